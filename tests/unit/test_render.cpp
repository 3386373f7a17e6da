// The tile renderer on the real scenes: determinism, progress, cancellation, sane pixels.
#include <gtest/gtest.h>

#include <cstring>
#include <type_traits>

#include "core/compare.h"
#include "core/renderer.h"
#include "core/scene_loader.h"
#include "core/tile_rays.h"
#include "test_util.h"

namespace rt {
namespace {

TEST(Render, SameBytesWhateverTheThreadCount) {
    const Scene scene(test::shipped_scene("whitted.json", 120, 90));
    RenderOptions options;
    options.threads = 1;
    const Image one = render(scene, options);
    for (int threads : {2, 3, 8}) {
        options.threads = threads;
        options.tile_size = threads == 3 ? 7 : 16;  // tile shape must not matter either
        const Image many = render(scene, options);
        ASSERT_EQ(one.pixels.size(), many.pixels.size());
        EXPECT_EQ(
            0, std::memcmp(one.pixels.data(), many.pixels.data(), one.pixels.size() * sizeof(vec3)))
            << threads << " threads";
    }
}

// Each pixel is the tutorial's ray through its centre (Camera::ray), traced alone: the
// renderer's per-tile rays (a column term plus a row term) and its tiles change nothing.
TEST(Render, EveryPixelIsItsCentresRayTracedAlone) {
    const Scene scene(test::shipped_scene("whitted.json", 61, 37));
    RenderOptions options;
    options.tile_size = 16;  // partial tiles at the right and the top
    options.trace.max_depth = 2;
    const Image image = render(scene, options);
    const Tracer tracer(scene, options.trace);
    int differing = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            RayCounts counts;
            const vec3 alone = tracer.trace_primary(scene.camera.ray(x, y), counts);
            differing += std::memcmp(&alone, &image.at(x, y), sizeof(vec3)) != 0;
        }
    }
    EXPECT_EQ(differing, 0);
}

// A tile's rays, made four at a time as blocks of floats (TileRays::span) or one by one
// (TileRays::ray), are the camera's rays through the pixel centres bit for bit, on tiles
// of every width from 1 to 19 (whole blocks and every remainder), in spans of every
// length from every start (running on into the next row), anywhere in the image, with an
// eye whose coordinates include -0 (kept by the block's -0 additions) and 0 in a
// direction's term. Jittered samples come back as pixel_sample made them.
TEST(Render, ATilesRaysAreTheCamerasRaysBitForBit) {
    Camera camera = Camera::look_at(vec3(-0.0f, 2.5f, -7.25f), vec3(0.0f, 2.5f, 0.0f),
                                    vec3(0.0f, 1.0f, 0.0f), 40.0f, 97, 31);
    camera.eye = vec3(-0.0f, 2.5f, -7.25f);
    const auto same = [](const Ray& a, const Ray& b) {
        return std::memcmp(&a, &b, sizeof(Ray)) == 0;
    };
    for (int width = 1; width <= 19; ++width) {
        for (const int x0 : {0, 5, 97 - width}) {
            const detail::Tile t{x0, 3, x0 + width, 9};
            const detail::CameraTerms terms(camera);
            detail::TileRays rays;
            for (const int spp : {1, 4}) {
                rays.make(terms, t, 2, spp);
                std::vector<Ray> expected;
                for (int y = t.y0; y < t.y1; ++y)
                    for (int x = t.x0; x < t.x1; ++x) {
                        expected.push_back(pixel_sample(camera, x, y, 2, spp));
                        ASSERT_TRUE(same(expected.back(), rays.ray(x, y)))
                            << "width " << width << ", pixel " << x << "," << y << ", spp " << spp;
                        ASSERT_EQ(rays.index(x, y), expected.size() - 1);
                    }
                for (std::size_t n = 1; n <= 13; ++n)
                    for (std::size_t i = 0; i + n <= expected.size(); ++i) {
                        std::vector<Ray> span(n);
                        rays.span(i, n, span.data());
                        for (std::size_t k = 0; k < n; ++k)
                            ASSERT_TRUE(same(expected[i + k], span[k]))
                                << "width " << width << ", span " << i << "+" << n << ", ray " << k
                                << ", spp " << spp;
                    }
            }
        }
    }
}

// A built Scene is read-only in its type: no member can be assigned, and it is never
// copied. Its description() builds again, with any structure, into the same picture.
static_assert(!std::is_copy_constructible_v<Scene> && !std::is_move_constructible_v<Scene>);
static_assert(!std::is_assignable_v<decltype((std::declval<Scene&>().lights)), std::vector<Light>>);
static_assert(!std::is_assignable_v<decltype((std::declval<Scene&>().camera)), Camera>);

TEST(Render, ADescriptionBuildsTheSamePictureWithAnyStructure) {
    const Scene scene(test::shipped_scene("cornell.json", 64, 64));
    const Image bvh = render(scene, {});
    for (AccelKind kind : {AccelKind::kBrute, AccelKind::kGrid, AccelKind::kBvh2}) {
        const Scene again(scene.description(), kind);
        EXPECT_EQ(again.accel_kind(), kind);
        EXPECT_EQ(again.objects.size(), scene.objects.size());
        EXPECT_EQ(compare_images(bvh, render(again, {})).pixels_over, 0u) << accel_name(kind);
    }
}

TEST(Render, ProgressCountsEveryTileOnce) {
    const Scene scene(test::shipped_scene("tutorial.json", 100, 50));
    RenderOptions options;
    options.tile_size = 16;  // 7 x 4 tiles
    int calls = 0, last = 0, total_seen = 0;
    RenderStats stats;
    render(scene, options, &stats, [&](int done, int total) {
        ++calls;
        EXPECT_EQ(done, last + 1);
        last = done;
        total_seen = total;
    });
    EXPECT_EQ(total_seen, 28);  // each tile finds its first hits and shades them in one go
    EXPECT_EQ(calls, 28);
    EXPECT_FALSE(stats.cancelled);
    EXPECT_EQ(stats.rays.primary, 5000u);
}

TEST(Render, CancellationStopsTheWorkers) {
    const Scene scene(test::shipped_scene("whitted.json", 320, 240));
    std::stop_source stop;
    RenderOptions options;
    options.tile_size = 8;
    RenderStats stats;
    int done_when_stopped = 0;
    render(
        scene, options, &stats,
        [&](int done, int) {
            if (done == 3) stop.request_stop();
            done_when_stopped = done;
        },
        stop.get_token());
    EXPECT_TRUE(stats.cancelled);
    EXPECT_LT(done_when_stopped, 3 + 2);  // each worker finishes at most its current tile
    EXPECT_LT(stats.rays.primary, 320u * 240u / 10u);
}

// Every scene in assets/scenes renders with no NaN or Inf, and is a picture, not a
// flat or black image.
TEST(Render, EveryAssetSceneGivesASanePicture) {
    const std::vector<std::string> names = test::shipped_scene_names();
    for (const std::string& name : names) {
        const Scene scene(test::shipped_scene(name, 64, 48));
        RenderStats stats;
        const Image image = render(scene, {}, &stats);
        EXPECT_EQ(stats.nonfinite_pixels, 0u) << name;
        double sum = 0.0, sum_sq = 0.0;
        for (const vec3& c : image.pixels) {
            const double luma = 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
            sum += luma;
            sum_sq += luma * luma;
        }
        const double n = static_cast<double>(image.pixels.size());
        const double mean = sum / n, variance = sum_sq / n - mean * mean;
        EXPECT_GT(mean, 0.05) << name << " is nearly black";
        EXPECT_GT(variance, 1e-3) << name << " is flat";
    }
    EXPECT_GE(names.size(), 4u);
}

// The light buffers change how a feeler is answered, not the answer: every shipped
// scene, byte for byte, with them and without. (Skipping the convex surface a feeler
// leaves is held to testing every object in ShadowFeelers.AnswerAsTestingEveryObject.)
TEST(Render, TheLightBufferChangesNoPixel) {
    const std::vector<std::string> names = test::shipped_scene_names();
    for (const std::string& name : names) {
        const Scene with(test::shipped_scene(name, 160, 90)),
            without(test::shipped_scene(name, 160, 90), AccelKind::kBvh, false);
        RenderStats stats;
        const Image a = render(with, {}, &stats), b = render(without, {});
        EXPECT_GT(stats.rays.shadow, 1000u) << name;
        EXPECT_TRUE(a.pixels == b.pixels) << name;
    }
    EXPECT_GE(names.size(), 4u);
}

TEST(Render, DefaultSceneShowsShadowsReflectionAndRefraction) {
    const Scene scene(test::shipped_scene("whitted.json", 160, 120));
    RenderStats stats;
    render(scene, {}, &stats);
    EXPECT_GT(stats.rays.shadow, 0u);
    EXPECT_GT(stats.rays.reflected, 1000u);
    EXPECT_GT(stats.rays.refracted, 1000u);

    // Switched off, each kind of secondary ray disappears and the image changes.
    RenderOptions plain;
    plain.trace.shadows = plain.trace.reflections = plain.trace.refractions = false;
    RenderStats plain_stats;
    const Image a = render(scene, {}, nullptr);
    const Image b = render(scene, plain, &plain_stats);
    EXPECT_EQ(plain_stats.rays.total(), plain_stats.rays.primary);
    int differing = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) differing += a.pixels[i] != b.pixels[i];
    EXPECT_GT(differing, static_cast<int>(a.pixels.size() / 10));
}

}  // namespace
}  // namespace rt
