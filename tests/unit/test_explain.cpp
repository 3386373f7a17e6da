// The explain map (core/explain.h) without GL: a stand-in raster image (the tracer's own
// local Phong, or a flat colour) and an item buffer from the tracer's first hits, so that
// every term is known. tests/gl/test_gl.cpp checks the same against the real raster.
#include <gtest/gtest.h>

#include <algorithm>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/compare.h"
#include "core/explain.h"
#include "core/renderer.h"
#include "core/scene_loader.h"
#include "test_util.h"

namespace rt {
namespace {

// What the raster's item buffer would hold if it rasterized exactly what the tracer sees.
ItemBuffer traced_ids(const Scene& scene) {
    ItemBuffer ids(scene.camera.cols, scene.camera.rows);
    for (int y = 0; y < ids.height; ++y)
        for (int x = 0; x < ids.width; ++x) {
            Hit hit;
            if (scene.intersect(scene.camera.ray(x, y), hit))
                ids.ids[ids.index(x, y)] = hit.object + 1;
        }
    return ids;
}

RenderOptions local_only() {
    RenderOptions o;
    o.trace.shadows = o.trace.reflections = o.trace.refractions = false;
    return o;
}

const char* const kScenes[] = {"tutorial.json", "whitted.json", "cornell.json",
                               "many_spheres.json"};

// The terms add up to traced - raster at every pixel, and the traced colours are the
// renderer's, bit for bit; some item-buffer ids are wrong on purpose, so that geometry
// pixels are among them.
TEST(Explain, TermsSumToTracedMinusRasterAtEveryPixel) {
    for (const char* name : kScenes) {
        const Scene scene(test::shipped_scene(name, 64, 48));
        const Image raster = render(scene, local_only());
        ItemBuffer ids = traced_ids(scene);
        for (std::size_t i = 0; i < ids.ids.size(); i += 7) ids.ids[i] = (ids.ids[i] + 1) % 3;
        const ExplainMap map = explain(scene, scene.camera, {}, raster, ids);
        const Image traced = render(scene, {});
        ASSERT_FALSE(map.cancelled);
        std::size_t geometry = 0;
        for (std::size_t i = 0; i < traced.pixels.size(); ++i) {
            ASSERT_EQ(map.traced.pixels[i], traced.pixels[i]) << name << " pixel " << i;
            const vec3 want = traced.pixels[i] - raster.pixels[i];
            const vec3 got = map.terms[i].sum();
            for (int k = 0; k < 3; ++k)
                ASSERT_NEAR(got[k], want[k], 1e-4f) << name << " pixel " << i;
            geometry += map.cause[i] == Cause::kGeometry;
        }
        EXPECT_GT(geometry, 0u) << name;
    }
}

// Tracing only what the raster does, every difference is geometry or shading.
TEST(Explain, WithoutShadowsReflectionsAndRefractionsOnlyGeometryAndShadingRemain) {
    for (const char* name : kScenes) {
        const Scene scene(test::shipped_scene(name, 64, 48));
        const Image grey(64, 48);  // black: a raster image unlike the traced one
        ItemBuffer ids = traced_ids(scene);
        for (std::size_t i = 0; i < ids.ids.size(); i += 5) ids.ids[i] = 0;
        const ExplainMap map = explain(scene, scene.camera, local_only(), grey, ids);
        std::size_t shading = 0;
        for (std::size_t i = 0; i < map.cause.size(); ++i) {
            const Cause c = map.cause[i];
            EXPECT_TRUE(c == Cause::kGeometry || c == Cause::kShading || c == Cause::kNone)
                << name << " pixel " << i << ": " << name_of(kCauseNames, c);
            EXPECT_EQ(map.terms[i].shadow, vec3(0.0f));
            EXPECT_EQ(map.terms[i].reflection, vec3(0.0f));
            EXPECT_EQ(map.terms[i].refraction, vec3(0.0f));
            shading += c == Cause::kShading;
        }
        EXPECT_GT(shading, map.cause.size() / 4) << name;
    }
}

// Against a raster that computes the local term exactly (the tracer's, shadows off), the
// tutorial's shadows are the only cause on its floor: where the feelers darken a pixel
// visibly, the cause is shadow and the shadow term is that darkening.
TEST(Explain, TheTutorialsShadowPixelsAreShadow) {
    const Scene scene(test::shipped_scene("tutorial.json", 160, 120));
    const Image raster = render(scene, local_only());
    RenderOptions no_secondary;
    no_secondary.trace.reflections = no_secondary.trace.refractions = false;
    const Image shadowed = render(scene, no_secondary);
    const ExplainMap map = explain(scene, scene.camera, {}, raster, traced_ids(scene));
    std::size_t shadow_pixels = 0, called_shadow = 0;
    for (std::size_t i = 0; i < raster.pixels.size(); ++i) {
        const vec3 darkening = shadowed.pixels[i] - raster.pixels[i];
        if (glm::length(darkening) < 0.05f || !(glm::length(map.terms[i].reflection) < 1e-6f) ||
            !(glm::length(map.terms[i].refraction) < 1e-6f))
            continue;
        ++shadow_pixels;
        called_shadow += map.cause[i] == Cause::kShadow;
        EXPECT_NEAR(glm::length(map.terms[i].shadow - darkening), 0.0f, 1e-5f);
    }
    EXPECT_GT(shadow_pixels, 200u);
    EXPECT_EQ(called_shadow, shadow_pixels);
}

// The shares: each column sums to 1, and the pixels with no cause are exactly those the
// difference statistics count as not differing.
TEST(Explain, SharesSumToOneAndNoneIsWhatCompareCallsEqual) {
    const Scene scene(test::shipped_scene("whitted.json", 80, 60));
    const Image raster = render(scene, local_only());
    const ExplainMap map = explain(scene, scene.camera, {}, raster, traced_ids(scene));
    const auto shares = cause_shares(map);
    double pixels = 0.0, error = 0.0;
    for (const CauseShare& s : shares) pixels += s.pixels, error += s.error;
    EXPECT_NEAR(pixels, 1.0, 1e-9);
    EXPECT_NEAR(error, 1.0, 1e-9);
    const ImageDiff d = compare_images(raster, map.traced);
    const std::size_t none =
        static_cast<std::size_t>(std::count(map.cause.begin(), map.cause.end(), Cause::kNone));
    EXPECT_EQ(map.cause.size() - none, d.pixels_over);
    for (std::size_t k = 0; k < kCauseCount; ++k) {
        const Cause c = kCauseNames[k].value;
        if (c == Cause::kReflection || c == Cause::kRefraction) {
            EXPECT_GT(shares[k].pixels, 0.01) << kCauseNames[k].name;
        }
    }
}

// A pixel's cause is its largest term; below the threshold there is none.
TEST(Explain, ACauseIsTheLargestTerm) {
    ExplainTerms t;
    t.shading = vec3(0.01f, 0.0f, 0.0f);
    t.shadow = vec3(0.0f, -0.3f, 0.0f);
    t.reflection = vec3(0.2f);
    EXPECT_EQ(cause_of(t, 0.5f), Cause::kShadow);
    EXPECT_EQ(cause_of(t, 1.0f / 255.0f), Cause::kNone);
    PrimaryParts parts;
    parts.object = 3;
    parts.local = vec3(0.5f);
    // Item-buffer ids are object index + 1: 4 is the tracer's object, 5 another one.
    EXPECT_EQ(explain_terms(parts, vec3(0.1f), 4).geometry, vec3(0.0f));
    EXPECT_EQ(explain_terms(parts, vec3(0.1f), 4).shading, parts.unblocked - vec3(0.1f));
    EXPECT_EQ(explain_terms(parts, vec3(0.1f), 5).geometry, vec3(0.5f) - vec3(0.1f));
}

// The picture: each cause in its colour, the legend strip below naming them all.
TEST(Explain, TheImageColoursEachPixelByItsCause) {
    const Scene scene(test::shipped_scene("tutorial.json", 160, 120));
    const ExplainMap map =
        explain(scene, scene.camera, {}, render(scene, local_only()), traced_ids(scene));
    const Image colours = explain_colours(map);
    const Image picture = explain_image(map);
    EXPECT_EQ(picture.width, 160);
    EXPECT_GT(picture.height, 120);
    const int strip = picture.height - 120;
    for (std::size_t i = 0; i < map.cause.size(); ++i) {
        if (map.cause[i] != Cause::kShadow) continue;
        const vec3 c = colours.pixels[i], hue = cause_colour(Cause::kShadow);
        EXPECT_NEAR(glm::length(glm::normalize(c) - glm::normalize(hue)), 0.0f, 1e-4f);
    }
    for (int y = 0; y < 120; ++y)
        for (int x = 0; x < 160; ++x) ASSERT_EQ(picture.at(x, y + strip), colours.at(x, y));
    // Every cause's swatch is in the strip.
    for (const Named<Cause>& n : kCauseNames) {
        bool found = false;
        for (int y = 0; y < strip && !found; ++y)
            for (int x = 0; x < 160 && !found; ++x)
                found = picture.at(x, y) == cause_colour(n.value);
        EXPECT_TRUE(found) << n.name;
    }
    EXPECT_THROW(explain(scene, scene.camera, {}, Image(10, 10), traced_ids(scene)),
                 std::invalid_argument);
}

}  // namespace
}  // namespace rt
