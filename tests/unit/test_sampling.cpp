// Anti-aliasing in the tracer (RenderOptions::spp): where the samples fall, that one sample
// is the tutorial's image, that the image is the same on any number of threads, and that
// more samples converge.
#include <gtest/gtest.h>

#include <set>

#include <glm/geometric.hpp>

#include "core/compare.h"
#include "core/renderer.h"
#include "core/scene_loader.h"
#include "test_util.h"

namespace rt {
namespace {

// Where a ray crosses the view plane, in pixel units (the inverse of Camera::ray_at).
glm::vec2 on_grid(const Camera& c, const Ray& r) {
    const vec3 d = r.dir * (c.N / -glm::dot(r.dir, c.n));
    return {(glm::dot(d, c.u) / c.W + 1.0f) * 0.5f * static_cast<float>(c.cols),
            (glm::dot(d, c.v) / c.H + 1.0f) * 0.5f * static_cast<float>(c.rows)};
}

TEST(Sampling, OnlySquareCountsAreValid) {
    for (int n : {1, 4, 9, 16, 64, 1024}) EXPECT_TRUE(valid_spp(n)) << n;
    for (int n : {0, -4, 2, 3, 8, 15, 1025}) EXPECT_FALSE(valid_spp(n)) << n;
}

// Each sample in its own stratum of the m x m grid, all inside the pixel; one sample is
// the centre.
TEST(Sampling, EachSampleLiesInItsOwnStratum) {
    const Camera camera = Camera::look_at({1, 2, 3}, {0, 0, 0}, {0, 1, 0}, 50.0f, 64, 48);
    const glm::vec2 centre = on_grid(camera, pixel_sample(camera, 10, 20, 0, 1));
    EXPECT_NEAR(centre.x, 10.5f, 1e-3f);
    EXPECT_NEAR(centre.y, 20.5f, 1e-3f);
    for (int spp : {4, 16, 64}) {
        const int m = spp == 4 ? 2 : spp == 16 ? 4 : 8;
        std::set<std::pair<int, int>> strata;
        for (int s = 0; s < spp; ++s) {
            const glm::vec2 p = on_grid(camera, pixel_sample(camera, 10, 20, s, spp));
            ASSERT_GE(p.x, 10.0f - 1e-3f);
            ASSERT_LT(p.x, 11.0f + 1e-3f);
            ASSERT_GE(p.y, 20.0f - 1e-3f);
            ASSERT_LT(p.y, 21.0f + 1e-3f);
            const int i = static_cast<int>((p.x - 10.0f) * static_cast<float>(m));
            const int j = static_cast<int>((p.y - 20.0f) * static_cast<float>(m));
            EXPECT_EQ(i, s % m) << spp << " sample " << s;
            EXPECT_EQ(j, s / m) << spp << " sample " << s;
            strata.insert({i, j});
        }
        EXPECT_EQ(strata.size(), static_cast<std::size_t>(spp));
    }
    // Jittered, not at the strata's centres; the same point every time.
    const glm::vec2 a = on_grid(camera, pixel_sample(camera, 3, 4, 5, 16));
    const glm::vec2 b = on_grid(camera, pixel_sample(camera, 3, 4, 5, 16));
    EXPECT_EQ(a, b);
    EXPECT_GT(glm::length(a - glm::vec2(3.0f + 1.5f / 4.0f, 4.0f + 1.5f / 4.0f)), 1e-3f);
}

// One sample per pixel is today's image bit for bit; any spp gives the same image on one
// thread or three, and casts spp primary rays a pixel.
TEST(Sampling, OneSampleIsThePixelCentreAndThreadsChangeNothing) {
    const Scene scene(test::shipped_scene("whitted.json", 48, 36));
    RenderOptions one;
    one.spp = 1;
    EXPECT_EQ(render(scene, one).pixels, render(scene, RenderOptions{}).pixels);
    RenderOptions a;
    a.spp = 16;
    a.threads = 1;
    RenderOptions b = a;
    b.threads = 3;
    b.tile_size = 7;
    RenderStats stats;
    const Image ia = render(scene, a, &stats);
    EXPECT_EQ(ia.pixels, render(scene, b).pixels);
    EXPECT_EQ(stats.rays.primary, 48u * 36u * 16u);
    EXPECT_NE(ia.pixels, render(scene, one).pixels);
}

// More samples, closer to the limit: against 256 samples per pixel, the error falls as
// the count rises, and the mean brightness stays (a box filter neither adds nor loses light).
TEST(Sampling, MoreSamplesConvergeAndKeepTheMean) {
    const Scene scene(test::shipped_scene("whitted.json", 40, 30));
    const auto at = [&](int spp) {
        RenderOptions o;
        o.spp = spp;
        return render(scene, o);
    };
    const Image reference = at(256);
    double previous = 1e9;
    for (int spp : {1, 4, 16, 64}) {
        const double rms = compare_images(at(spp), reference).rms;
        EXPECT_LT(rms, previous) << spp;
        previous = rms;
    }
    EXPECT_LT(previous, 0.01);
    const auto mean = [](const Image& im) {
        double s = 0.0;
        for (const vec3& p : im.pixels) s += static_cast<double>(p.x + p.y + p.z);
        return s / static_cast<double>(im.pixels.size());
    };
    EXPECT_NEAR(mean(at(16)), mean(reference), 0.01 * mean(reference));
}

}  // namespace
}  // namespace rt
