// The raster pipeline on a real headless GL context (EGL and OSMesa, each test run on
// both): it agrees with the tracer where it should, its item buffer is right and saves
// nothing it should not, and GL never reports an error.
#include <gtest/gtest.h>

#include <cstdlib>

#include "../unit/far_scene.h"
#include "../unit/test_util.h"
#include "app/gl/compositor.h"
#include "app/gl/context.h"
#include "app/gl/debug.h"
#include "app/gl/framebuffer.h"
#include "app/gl/gl.h"
#include "app/gl/program.h"
#include "app/gl/raster_renderer.h"
#include "app/gl/texture.h"
#include "core/compare.h"
#include "core/error.h"
#include "core/explain.h"
#include "core/renderer.h"
#include "core/scene_loader.h"
#include "gl_fixture.h"

namespace rt {
namespace {

class Gl : public GlTest {};

// The context is what the shaders ask for (3.3 core, no compatibility profile), and the
// KHR_debug callback that every "no GL error" check relies on is really listening: a
// deliberate error must reach it.
TEST_P(Gl, ContextIsCoreProfile33OrLater) {
    GLint major = 0, minor = 0, mask = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
    EXPECT_GE(major * 10 + minor, 33) << context_->description();
    EXPECT_TRUE(mask & GL_CONTEXT_CORE_PROFILE_BIT) << "profile mask " << mask;
    EXPECT_FALSE(mask & GL_CONTEXT_COMPATIBILITY_PROFILE_BIT) << "profile mask " << mask;
    ASSERT_TRUE(gl::debug_output_requested()) << "the tests run with RTVIEW_GL_DEBUG=1";
    ASSERT_TRUE(gl::debug_output_installed()) << "KHR_debug was asked for but is not installed";
    const std::uint64_t before = gl::debug_error_count();
    glBindBuffer(GL_ARRAY_BUFFER, 987654u);  // never generated: GL_INVALID_OPERATION in core
    EXPECT_NE(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    EXPECT_GT(gl::debug_error_count(), before) << "the debug callback missed a GL error";
    errors_before_ = gl::debug_error_count();  // that error was ours
}

// Whether two linear colours differ on screen: by more than 2/255 in a channel, sRGB encoded.
bool differ_on_screen(const vec3& a, const vec3& b) {
    float d = 0.0f;
    for (int k = 0; k < 3; ++k) d = std::max(d, std::fabs(srgb_encode(a[k]) - srgb_encode(b[k])));
    return d > 2.0f / 255.0f;
}

// The raster image against local-only tracing (no shadows, reflections or refractions),
// counted over the pixels away from any edge in the item buffer (`objects_only`: and not
// the background).
struct LocalAgreement {
    std::size_t inside = 0, off = 0;
    ImageDiff all;
};
LocalAgreement raster_against_local_trace(const Scene& scene, bool objects_only) {
    gl::RasterRenderer raster(scene);
    const Image r = raster.render(scene.camera);
    const ItemBuffer ib = raster.render_item_buffer(scene.camera);
    RenderOptions options;
    options.trace.shadows = options.trace.reflections = options.trace.refractions = false;
    const Image t = render(scene, options);
    LocalAgreement out;
    for (int y = 0; y < r.height; ++y) {
        for (int x = 0; x < r.width; ++x) {
            if (!ib.interior(x, y)) continue;
            if (objects_only && ib.object_id(ib.index(x, y)) == ItemBuffer::kEmpty) continue;
            ++out.inside;
            out.off += differ_on_screen(r.at(x, y), t.at(x, y));
        }
    }
    out.all = compare_images(r, t);
    return out;
}

// With shadows, reflection and refraction off, the tracer computes exactly what the
// raster pipeline computes. Inside objects (away from any edge in the item buffer) the
// two must agree to a rounding; only silhouettes, where a tessellated sphere and the
// true sphere cover different pixels, may differ.
TEST_P(Gl, RasterEqualsLocalTracingAwayFromSilhouettes) {
    for (const char* name : kScenes) {
        const Scene scene(load(name, 200, 150));
        const LocalAgreement a = raster_against_local_trace(scene, false);
        const std::size_t pixels = static_cast<std::size_t>(scene.camera.cols) * scene.camera.rows;
        EXPECT_GT(a.inside, pixels / 2) << name;
        // A few checker cells flip where the floor meets the horizon, at float precision.
        EXPECT_LE(static_cast<double>(a.off), 1e-3 * static_cast<double>(a.inside)) << name;
        EXPECT_LT(a.all.share_over, 0.03) << name << ": silhouettes only";
        EXPECT_GT(a.all.psnr_db, 25.0) << name;
    }
}

// Model files (Khronos' glTF samples, a hand-made glTF hierarchy with lights, a PLY with
// vertex colours, an STL) pass the same cross-validation as the JSON scenes: with the
// effects off, the raster and the tracer agree inside every object, and the objects are
// in the picture.
TEST_P(Gl, ModelFilesAgreeInBothPipelines) {
    const auto dir = test::source_dir() / "tests" / "data" / "gltf";
    for (const auto& file :
         {dir / "khronos" / "Cube" / "Cube.gltf", dir / "khronos" / "BoxTextured.glb",
          dir / "khronos" / "Cameras" / "Cameras.gltf", dir / "lights.gltf",
          dir / ".." / "mesh" / "octahedron_binary.ply",
          dir / ".." / "mesh" / "octahedron_ascii.stl", dir / "colours.gltf"}) {
        LoadedScene loaded = load_scene(file);
        loaded.scene.camera = loaded.scene.camera.resized(200, 150);
        const Scene scene(std::move(loaded.scene));
        const LocalAgreement a = raster_against_local_trace(scene, true);
        EXPECT_GT(a.inside, std::size_t{200 * 150 / 50}) << file;  // objects in the picture
        EXPECT_LE(static_cast<double>(a.off), 1e-3 * static_cast<double>(a.inside)) << file;
        EXPECT_LT(a.all.share_over, 0.03) << file << ": silhouettes only";
    }
}

// Textures show in both pipelines, and alike: a textured OBJ (the shipped textured
// scene) and Khronos' textured box; with effects off the two agree inside objects, and
// without their textures both pictures change over most of the textured surface.
TEST_P(Gl, TexturesShowAlikeInBothPipelines) {
    const auto dir = test::source_dir() / "tests" / "data" / "gltf" / "khronos";
    for (const auto& file : {test::scene_path("textured.json"), dir / "BoxTextured.glb"}) {
        LoadedScene loaded = load_scene(file);
        loaded.scene.camera = loaded.scene.camera.resized(200, 150);
        SceneDescription plain = loaded.scene;
        for (Material& m : plain.materials) m.texture.reset();
        const auto pictures = [&](SceneDescription d) {
            const Scene scene(std::move(d));
            gl::RasterRenderer raster(scene);
            RenderOptions options;
            options.trace.shadows = options.trace.reflections = options.trace.refractions = false;
            return std::tuple{raster.render(scene.camera), render(scene, options),
                              raster.render_item_buffer(scene.camera)};
        };
        const auto [r, t, ib] = pictures(loaded.scene);
        const auto [r_plain, t_plain, ib_plain] = pictures(plain);
        std::size_t textured = 0, off = 0, raster_changed = 0, traced_changed = 0;
        for (int y = 0; y < r.height; ++y) {
            for (int x = 0; x < r.width; ++x) {
                const std::uint32_t id = ib.object_id(ib.index(x, y));
                if (!ib.interior(x, y) || id == ItemBuffer::kEmpty) continue;
                const Object& o = loaded.scene.objects[id - 1];
                if (!std::holds_alternative<MeshRef>(o.shape)) continue;  // the floor, the mirror
                ++textured;
                off += differ_on_screen(r.at(x, y), t.at(x, y));
                raster_changed += differ_on_screen(r.at(x, y), r_plain.at(x, y));
                traced_changed += differ_on_screen(t.at(x, y), t_plain.at(x, y));
            }
        }
        ASSERT_GT(textured, r.pixels.size() / 50) << file;
        EXPECT_LE(static_cast<double>(off), 2e-3 * static_cast<double>(textured)) << file;
        EXPECT_GT(raster_changed, textured / 2) << file << ": the raster shows no texture";
        EXPECT_GT(traced_changed, textured / 2) << file << ": the tracer shows no texture";
    }
}

// The explain map against the real raster image and item buffer, every shipped scene: the
// terms add up to traced - raster at every pixel (1e-4 per channel), the traced colours
// are the renderer's, and where the raster saw the tracer's object and the feelers
// visibly darkened a pixel with no reflection or refraction (a shadow the raster does not
// draw), the cause is shadow.
TEST_P(Gl, ExplainTermsSumToTheDifferenceOfTheRealImages) {
    for (const char* name : kScenes) {
        const Scene scene(load(name, 160, 120));
        gl::RasterRenderer raster(scene);
        const Image r = raster.render(scene.camera);
        const ItemBuffer ib = raster.render_item_buffer(scene.camera);
        const ExplainMap map = explain(scene, scene.camera, {}, r, ib);
        const Image traced = render(scene, {});
        RenderOptions no_shadows;
        no_shadows.trace.shadows = false;
        const Image unshadowed = render(scene, no_shadows);
        std::size_t shadowed = 0, called_shadow = 0;
        for (std::size_t i = 0; i < r.pixels.size(); ++i) {
            ASSERT_EQ(map.traced.pixels[i], traced.pixels[i]) << name << " pixel " << i;
            const vec3 want = traced.pixels[i] - r.pixels[i], got = map.terms[i].sum();
            for (int k = 0; k < 3; ++k)
                ASSERT_NEAR(got[k], want[k], 1e-4f) << name << " pixel " << i << " channel " << k;
            const vec3 darkening = unshadowed.pixels[i] - traced.pixels[i];
            // Off mirrors and glass (whose reflections hold shadows of their own).
            const ExplainTerms& t = map.terms[i];
            const bool local_only = t.reflection == vec3(0.0f) && t.refraction == vec3(0.0f);
            if (t.geometry == vec3(0.0f) && local_only &&
                std::min({darkening.x, darkening.y, darkening.z}) > 0.1f) {
                ++shadowed;
                called_shadow += map.cause[i] == Cause::kShadow;
            }
        }
        EXPECT_GT(shadowed, 100u) << name;
        EXPECT_GE(static_cast<double>(called_shadow), 0.95 * static_cast<double>(shadowed)) << name;
    }
}

// MSAA smooths edges and nothing else: with 4 samples, every pixel that changes lies where
// the item buffer has an edge, of an object or of a triangle (shading runs once a pixel,
// at its centre, so the inside of a triangle is the same image: the checker is not
// smoothed), some of them do change, and the mean colour stays. 8 samples, beyond what llvmpipe
// offers, is a located error, not a black image.
bool inside_one_triangle(const ItemBuffer& ib, int x, int y) {
    if (!ib.interior(x, y)) return false;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int nx = std::clamp(x + dx, 0, ib.width - 1),
                      ny = std::clamp(y + dy, 0, ib.height - 1);
            if (ib.triangle(ib.index(nx, ny)) != ib.triangle(ib.index(x, y))) return false;
        }
    return true;
}

TEST_P(Gl, MsaaChangesEdgesOnly) {
    for (const char* name : kScenes) {
        const Scene scene(load(name, 160, 120));
        gl::RasterRenderer raster(scene);
        const Image one = raster.render(scene.camera);
        const ItemBuffer ib = raster.render_item_buffer(scene.camera);
        raster.set_msaa(4);
        const Image four = raster.render(scene.camera);
        std::size_t changed = 0, inside = 0;
        double mean_one = 0.0, mean_four = 0.0;
        for (int y = 0; y < one.height; ++y)
            for (int x = 0; x < one.width; ++x) {
                const vec3 a = one.at(x, y), b = four.at(x, y);
                mean_one += static_cast<double>(a.x + a.y + a.z);
                mean_four += static_cast<double>(b.x + b.y + b.z);
                if (glm::length(a - b) < 2.0f / 255.0f) continue;
                ++changed;
                inside += inside_one_triangle(ib, x, y);
            }
        EXPECT_GT(changed, 20u) << name;
        // A sphere's proxy mesh has no triangle ids, so a few pixels on its inner edges
        // (ray-cast once per fragment on each side) may change too.
        EXPECT_LE(inside, one.pixels.size() / 1000) << name;
        EXPECT_NEAR(mean_four, mean_one, 0.02 * mean_one) << name;
    }
    gl::RasterRenderer raster(Scene(load("tutorial.json", 32, 24)));
    GLint most = 1;
    glGetIntegerv(GL_MAX_SAMPLES, &most);
    raster.set_msaa(2 * most);
    EXPECT_THROW(raster.render(Camera::look_at({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 40.0f, 32, 24)),
                 std::runtime_error);
}

// The pixels a pipeline's shadows darken: lit minus shadowed, by more than 0.02 in a channel.
std::vector<bool> darkened(const Image& lit, const Image& shadowed) {
    std::vector<bool> out(lit.pixels.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
        const vec3 d = lit.pixels[i] - shadowed.pixels[i];
        out[i] = std::max({d.x, d.y, d.z}) > 0.02f;
    }
    return out;
}

// Shadow maps against the tracer's shadow feelers: of the pixels either pipeline puts in
// shadow, at least 90 % are in shadow in both (intersection over union), at 640 x 480.
// Each pipeline's shadow is what switching its shadows on takes away from the same image.
TEST_P(Gl, ShadowMapsAgreeWithShadowFeelers) {
    for (const char* name : {"tutorial.json", "cornell.json"}) {
        const Scene scene(load(name, 640, 480));
        gl::RasterRenderer raster(scene);
        const Image plain = raster.render(scene.camera);
        raster.set_shadow_maps(true);
        const Image mapped = raster.render(scene.camera);
        RenderOptions local;
        local.trace.reflections = local.trace.refractions = local.trace.shadows = false;
        const Image unshadowed = render(scene, local);
        local.trace.shadows = true;
        const Image shadowed = render(scene, local);
        const std::vector<bool> a = darkened(plain, mapped), b = darkened(unshadowed, shadowed);
        std::size_t both = 0, either = 0;
        for (std::size_t i = 0; i < a.size(); ++i) {
            both += a[i] && b[i];
            either += a[i] || b[i];
        }
        ASSERT_GT(either, 1000u) << name;
        const double iou = static_cast<double>(both) / static_cast<double>(either);
        EXPECT_GE(iou, 0.9) << name << ": " << both << " of " << either << " shadowed pixels agree";
        std::printf("%s: shadow maps and feelers agree on %.3f of the shadowed pixels\n", name,
                    iou);
    }
}

// PSNR (dB, displayed values) of `a` against `b` over the pixels the item buffer gives to
// `object`.
double psnr_on(const Image& a, const Image& b, const ItemBuffer& ib, std::uint32_t object) {
    double sum = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        if (ib.object_id(i) != object + 1 ||
            !ib.interior(static_cast<int>(i % ib.width), static_cast<int>(i / ib.width)))
            continue;
        for (int k = 0; k < 3; ++k) {
            const double d = srgb_encode(a.pixels[i][k]) - srgb_encode(b.pixels[i][k]);
            sum += d * d;
        }
        n += 3;
    }
    EXPECT_GT(n, 300u) << "too few pixels of object " << object;
    return 10.0 * std::log10(1.0 / std::max(sum / static_cast<double>(std::max<std::size_t>(n, 1)),
                                            1e-12));
}

// The traced image with reflections only (no shadows, no refraction): what environment
// maps stand in for.
Image traced_reflections(const Scene& scene) {
    RenderOptions o;
    o.trace.shadows = o.trace.refractions = false;
    return render(scene, o);
}

// Environment maps on the whitted scene's mirror ball, against the traced reflections:
// much closer than the classic pipeline's dark ball (5.3 dB), and at least the floor
// measured here (15.6 dB at 320 x 240 on Mesa, floor 14 dB). What is left: parallax (the
// bunny is close to the ball), the map's resolution against a checker seen at grazing
// angles, and the glass ball, which the maps show refracted once where the tracer (here
// without refraction) shows it plain.
TEST_P(Gl, EnvironmentMapsShowTheMirrorsReflection) {
    const Scene scene(load("whitted.json", 320, 240));
    std::uint32_t mirror = 0;
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i) {
        const Material& m = scene.materials[scene.objects[i].material];
        if (m.reflectivity > 0.5f && m.transparency == 0.0f) mirror = i;
    }
    gl::RasterRenderer raster(scene);
    const ItemBuffer ib = raster.render_item_buffer(scene.camera);
    const Image plain = raster.render(scene.camera);
    raster.set_environment_maps(true);
    const Image mapped = raster.render(scene.camera);
    const Image traced = traced_reflections(scene);
    const double with = psnr_on(mapped, traced, ib, mirror),
                 without = psnr_on(plain, traced, ib, mirror);
    std::printf(
        "mirror ball against the traced reflections: %.1f dB with environment maps, %.1f "
        "dB without\n",
        with, without);
    EXPECT_GE(with, 14.0);
    EXPECT_GE(with, without + 8.0);
}

// The known failure: an environment map is seen from the object's centre and looked up as
// if the scene were infinitely far, so an object near the mirror shows in the wrong place
// in it (parallax). A red ball beside the mirror ball, then the same ball three times as
// far and three times as big (the same size seen from the mirror's centre): the near one's
// reflection is much further from the tracer's.
TEST_P(Gl, EnvironmentMapsMisplaceNearObjectsParallax) {
    const auto scene_with_ball = [](float distance) {
        SceneDescription d;
        d.camera = Camera::look_at({0, 0, 6}, {0, 0, 0}, {0, 1, 0}, 35.0f, 320, 240);
        d.background = vec3(0.1f, 0.1f, 0.2f);
        Material mirror = test::plain(vec3(0.0f), vec3(0.0f));
        mirror.reflectivity = 1.0f;
        d.materials = {mirror, test::plain(vec3(0.3f, 0.05f, 0.05f), vec3(0.8f, 0.1f, 0.1f))};
        d.objects.push_back(Object{"mirror", Sphere{{0, 0, 0}, 1.0f}, 0, {}});
        const float s = distance / 1.6f;
        d.objects.push_back(Object{"red", Sphere{vec3(1.2f, 0.4f, 0.9f) * s, 0.35f * s}, 1, {}});
        d.lights.push_back(Light{Light::Type::kPoint, {3, 5, 8}, {}, vec3(1.0f)});
        return Scene(std::move(d));
    };
    double psnr[2] = {};
    for (int far = 0; far < 2; ++far) {
        const Scene scene = scene_with_ball(far ? 4.8f : 1.6f);
        gl::RasterRenderer raster(scene);
        raster.set_environment_maps(true);
        psnr[far] = psnr_on(raster.render(scene.camera), traced_reflections(scene),
                            raster.render_item_buffer(scene.camera), 0);
    }
    std::printf("parallax: the mirror against the tracer, red ball near %.1f dB, far %.1f dB\n",
                psnr[0], psnr[1]);
    EXPECT_LT(psnr[0], psnr[1] - 3.0);
}

// Anti-aliasing on both sides converges to the same limit: against a 64-sample traced
// reference of the tutorial scene with every effect off (what the raster computes), the
// error on the edge pixels (where the item buffer changes) falls as samples rise: the
// tracer at 1, 4 and 16 samples per pixel, the raster at 1, 2 and 4 MSAA samples.
TEST_P(Gl, AntiAliasingConvergesOnBothSides) {
    const Scene scene(load("tutorial.json", 160, 120));
    RenderOptions local;
    local.trace.shadows = local.trace.reflections = local.trace.refractions = false;
    local.spp = 64;
    const Image reference = render(scene, local);
    gl::RasterRenderer raster(scene);
    const ItemBuffer ib = raster.render_item_buffer(scene.camera);
    const auto edge_error = [&](const Image& image) {
        double sum = 0.0;
        std::size_t n = 0;
        for (int y = 0; y < ib.height; ++y)
            for (int x = 0; x < ib.width; ++x) {
                if (ib.interior(x, y)) continue;
                for (int k = 0; k < 3; ++k)
                    sum += std::abs(srgb_encode(image.at(x, y)[k]) -
                                    srgb_encode(reference.at(x, y)[k]));
                ++n;
            }
        EXPECT_GT(n, 200u);
        return sum / static_cast<double>(std::max<std::size_t>(n, 1));
    };
    double traced[3] = {}, rasterised[3] = {};
    const int spp[3] = {1, 4, 16}, msaa[3] = {1, 2, 4};
    for (int i = 0; i < 3; ++i) {
        local.spp = spp[i];
        traced[i] = edge_error(render(scene, local));
        raster.set_msaa(msaa[i]);
        rasterised[i] = edge_error(raster.render(scene.camera));
    }
    std::printf(
        "edge error against 64 spp: traced %.4f %.4f %.4f (1, 4, 16 spp), raster %.4f "
        "%.4f %.4f (1, 2, 4x MSAA)\n",
        traced[0], traced[1], traced[2], rasterised[0], rasterised[1], rasterised[2]);
    // A GL may give more samples than asked (llvmpipe gives 4 for 2): the raster's error
    // must not rise, and 4x must cut it clearly.
    for (int i = 1; i < 3; ++i) {
        EXPECT_LT(traced[i], traced[i - 1]) << spp[i] << " spp";
        EXPECT_LE(rasterised[i], rasterised[i - 1]) << msaa[i] << "x MSAA";
    }
    EXPECT_LT(rasterised[2], 0.8 * rasterised[0]);
}

// With the tricks on, the explain map compares like with like: the terms still add up to
// traced - raster, and where both pipelines shadow a pixel its shadow term is about 0
// (the feelers against the map), where the map fails it is not; on the mirror ball the
// reflection term is the traced reflection against the environment map's, far smaller
// than against nothing.
TEST_P(Gl, ExplainSetsEachTrickAgainstItsTracedTerm) {
    const Scene scene(load("whitted.json", 320, 240));
    gl::RasterRenderer raster(scene);
    raster.set_shadow_maps(true);
    raster.set_environment_maps(true);
    const gl::RasterRenderer::ForExplain r = raster.render_for_explain(scene.camera);
    ASSERT_FALSE(r.tricks.shadow.pixels.empty());
    ASSERT_FALSE(r.tricks.reflection.pixels.empty());
    const ExplainMap like = explain(scene, scene.camera, {}, r.image, r.ids, {}, &r.tricks);
    const ExplainMap whole = explain(scene, scene.camera, {}, r.image, r.ids);
    const Image traced = render(scene, {});
    std::size_t both_shadowed = 0, small_shadow_term = 0;
    double reflection_like = 0.0, reflection_whole = 0.0;
    for (std::size_t i = 0; i < traced.pixels.size(); ++i) {
        const vec3 want = traced.pixels[i] - r.image.pixels[i], got = like.terms[i].sum();
        for (int k = 0; k < 3; ++k) ASSERT_NEAR(got[k], want[k], 1e-4f) << "pixel " << i;
        const float feelers = glm::length(whole.terms[i].shadow);  // the tracer's darkening
        const float map = glm::length(r.tricks.shadow.pixels[i]);  // the map's
        if (feelers > 0.1f && map > 0.1f && like.terms[i].reflection == vec3(0.0f) &&
            like.terms[i].refraction == vec3(0.0f)) {
            ++both_shadowed;
            small_shadow_term += glm::length(like.terms[i].shadow) < 0.05f;
        }
        reflection_like += glm::length(like.terms[i].reflection);
        reflection_whole += glm::length(whole.terms[i].reflection);
    }
    EXPECT_GT(both_shadowed, 500u);
    EXPECT_GE(static_cast<double>(small_shadow_term), 0.9 * static_cast<double>(both_shadowed));
    EXPECT_LT(reflection_like, 0.5 * reflection_whole);
}

// A camera skimming the floor, just above it or just under it (an orbit can take it
// there): the floor is nearer than any object, and the raster must not clip it at the
// near plane while the tracer draws it. With the near plane chosen from the objects alone,
// the lower rows of the raster image were background.
TEST_P(Gl, ACameraSkimmingTheFloorSeesItInBothPipelines) {
    for (const float height : {0.05f, -0.05f}) {
        SceneDescription desc = load("whitted.json", 160, 120);
        desc.camera = Camera::look_at({0.3f, height, 4.5f}, {0.0f, height - 0.4f, 0.0f}, {0, 1, 0},
                                      38.0f, 160, 120);
        const Scene scene(std::move(desc));
        gl::RasterRenderer raster(scene);
        const Image r = raster.render(scene.camera);
        RenderOptions options;
        options.trace.shadows = options.trace.reflections = options.trace.refractions = false;
        const Image t = render(scene, options);
        const ImageDiff d = compare_images(r, t);
        EXPECT_LT(d.share_over, 0.03) << "camera at height " << height << ": silhouettes only";
    }
}

TEST_P(Gl, BrokenShaderIsALocatedError) {
    const auto dir = test::temp_dir(std::string("shaders_") +
                                    (GetParam() == gl::Backend::kEgl ? "egl" : "osmesa"));
    for (const char* f : {"raster.vert", "itembuffer.frag", "wire.frag", "shadow.frag"})
        std::filesystem::copy_file(gl::shader_dir() / f, dir / f);
    test::write_file(dir / "phong.frag",
                     "#version 330 core\nout vec4 c;\nvoid main() {\n  c = vec4(1.0) +;\n}\n");
    const Scene scene(load("tutorial.json", 32, 32));
    try {
        gl::RasterRenderer raster(scene, dir);
        FAIL() << "compiled";
    } catch (const Error& e) {
        EXPECT_NE(e.file().find("phong.frag"), std::string::npos) << e.what();
        EXPECT_EQ(e.where(), "line 4") << e.what();
    }
    std::filesystem::remove(dir / "phong.frag");
    EXPECT_THROW(gl::RasterRenderer(scene, dir), Error);  // missing
}

// Shaders are compiled once per feature set (app/gl/program.h): every set compiles, and
// a set's error is reported at the file's own line, as it is without definitions.
TEST_P(Gl, EveryShaderVariantCompilesAndErrorsKeepTheirLines) {
    const Scene scene(load("tutorial.json", 32, 32));
    gl::RasterRenderer raster(scene);
    for (bool shadows : {false, true})
        for (bool env : {false, true}) EXPECT_NO_THROW(raster.phong(shadows, env));
    gl::Compositor compositor;
    using gl::DiffMode;
    using gl::View;
    for (View v :
         {View::kRaster, View::kTrace, View::kSplit, View::kDiff, View::kItemBuffer, View::kWhy})
        for (DiffMode m : {DiffMode::kHeat, DiffMode::kSigned, DiffMode::kChannels})
            for (bool overlay : {false, true}) EXPECT_NO_THROW(compositor.program(v, m, overlay));

    const auto dir = test::temp_dir(std::string("variants_") +
                                    (GetParam() == gl::Backend::kEgl ? "egl" : "osmesa"));
    for (const char* f : {"raster.vert", "itembuffer.frag", "wire.frag", "shadow.frag"})
        std::filesystem::copy_file(gl::shader_dir() / f, dir / f);
    test::write_file(dir / "phong.frag",
                     "#version 330 core\nout vec4 c;\nvoid main() {\n#if SHADOW_MAPS == 1\n"
                     "  c = vec4(1.0) +;\n#else\n  c = vec4(1.0);\n#endif\n}\n");
    gl::RasterRenderer broken(scene, dir);  // without shadow maps it compiles
    try {
        broken.phong(true, false);
        FAIL() << "compiled";
    } catch (const Error& e) {
        EXPECT_NE(e.file().find("phong.frag"), std::string::npos) << e.what();
        EXPECT_EQ(e.where(), "line 5") << e.what();
    }
}

// GL names are held by self-deleting handles (app/gl/handle.h): constructions that throw
// half-way (a shader that does not compile after one that did, a program that does not
// link, a framebuffer that is incomplete) and moved-from objects leave no name behind.
TEST_P(Gl, FailedConstructionsLeakNoGlNames) {
    const auto live_names = [] {
        int n = 0;
        for (GLuint id = 1; id < 4096; ++id)
            n += glIsShader(id) + glIsProgram(id) + glIsTexture(id) + glIsFramebuffer(id) +
                 glIsRenderbuffer(id) + glIsBuffer(id) + glIsVertexArray(id);
        return n;
    };
    const auto dir =
        test::temp_dir(std::string("leak_") + (GetParam() == gl::Backend::kEgl ? "egl" : "osmesa"));
    std::filesystem::copy_file(gl::shader_dir() / "raster.vert", dir / "raster.vert",
                               std::filesystem::copy_options::overwrite_existing);
    test::write_file(dir / "broken.frag", "#version 330 core\nvoid main() { syntax error }\n");
    test::write_file(
        dir / "unlinked.frag",  // compiles, but calls what nothing defines
        "#version 330 core\nout vec4 c;\nvec4 nowhere();\nvoid main() { c = nowhere(); }\n");
    const int before = live_names();
    for (int i = 0; i < 3; ++i) {
        EXPECT_THROW(gl::Program(dir / "raster.vert", dir / "broken.frag"), Error);
        EXPECT_THROW(gl::Program(dir / "raster.vert", dir / "unlinked.frag"), Error);
        // A zero-sized attachment makes a framebuffer incomplete (GL 3.3, 4.4.4.2): it
        // throws after its texture, renderbuffer and framebuffer names were made.
        EXPECT_THROW(gl::Framebuffer(gl::Framebuffer::Kind::kItemBuffer, 0, 0), std::runtime_error);
        gl::Texture moved_from;
        gl::Texture texture = std::move(moved_from);
        texture.upload(Image(2, 2));
    }
    EXPECT_EQ(live_names(), before);
    gl::check("FailedConstructionsLeakNoGlNames");
}

// A bare model far smaller or larger than float handles well is scaled by a power of two
// (core/mesh_file.h): the raster draws it as at its own size (the bunny 1e15 times its
// size was an empty raster: every depth rounded to the far plane's). And the bunny 1e6
// out written with 9 digits, which collapses many of its triangles onto lines: the raster
// draws none of those (rounding in the projection gave some a few fragments without a
// normal: NaN pixels).
TEST_P(Gl, ABareModelRastersAtAnyScaleAndTrianglesWithoutAreaDrawNothing) {
    const auto dir = test::temp_dir(std::string("scale_") +
                                    (GetParam() == gl::Backend::kEgl ? "egl" : "osmesa"));
    const auto raster = [&](const std::string& name, const std::string& text, int cols = 160) {
        LoadedScene loaded = load_scene(test::write_file(dir / name, text));
        loaded.scene.camera = loaded.scene.camera.resized(cols, cols * 3 / 4);
        const Scene scene(std::move(loaded.scene));
        return gl::RasterRenderer(scene).render(scene.camera);
    };
    const Image near = raster("near.obj", test::bunny_obj(1.0, 0.0));
    for (const double s : {1e-12, 1e15})
        EXPECT_LE(compare_images(near, raster("scaled.obj", test::bunny_obj(s, 0.0))).share_over,
                  0.001)
            << s;
    const Image far = raster("far.obj", test::bunny_obj(1.0, 1e6, 9), 480);
    std::size_t non_finite = 0;
    for (const vec3& p : far.pixels) non_finite += !std::isfinite(p.x + p.y + p.z);
    EXPECT_EQ(non_finite, 0u);
}

// An OBJ of lines and points: the raster view draws them (in the material's diffuse
// colour), the item buffer and the tracer see nothing there.
TEST_P(Gl, LinesAndPointsAreDrawnByTheRasterOnly) {
    const auto path =
        test::write_file(test::temp_dir(std::string("wire_") +
                                        (GetParam() == gl::Backend::kEgl ? "egl" : "osmesa")) /
                             "wire.obj",
                         "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nl 1 2 4 3 1\np 1 4\n");
    LoadedScene loaded = load_scene(path);
    SceneDescription& desc = loaded.scene;
    desc.camera = desc.camera.resized(96, 72);
    const Scene scene(std::move(desc));
    gl::RasterRenderer raster(scene);
    const Image image = raster.render(scene.camera);
    int drawn = 0;
    for (const vec3& p : image.pixels) drawn += p != scene.background;
    EXPECT_GT(drawn, 96);           // four edges across a good part of the frame
    EXPECT_LT(drawn, 96 * 72 / 4);  // lines, not a filled square
    const ItemBuffer ib = raster.render_item_buffer(scene.camera);
    for (std::size_t i = 0; i < ib.ids.size(); ++i) EXPECT_EQ(ib.object_id(i), ItemBuffer::kEmpty);
    const Image traced = render(scene, {});
    for (const vec3& p : traced.pixels) EXPECT_EQ(p, scene.background);
}

// Two EGL contexts share the process's one EGL display: destroying the first must leave
// the second working (eglTerminate on the shared display used to end both).
TEST(GlContexts, DestroyingOneEglContextLeavesTheOtherWorking) {
    auto first = gl::create_headless_context(gl::Backend::kEgl, "rt_gl_tests");
    auto second = gl::create_headless_context(gl::Backend::kEgl, "rt_gl_tests");
    LoadedScene loaded = load_scene(test::scene_path("tutorial.json"));
    loaded.scene.camera = loaded.scene.camera.resized(64, 48);
    const Scene scene(std::move(loaded.scene));
    first->make_current();
    const Image before = gl::RasterRenderer(scene).render(scene.camera);
    first.reset();
    second->make_current();
    const Image after = gl::RasterRenderer(scene).render(scene.camera);
    EXPECT_EQ(compare_images(before, after).pixels_over, 0u);
    int lit = 0;
    for (const vec3& p : after.pixels) lit += p != scene.background;
    EXPECT_GT(lit, 64 * 48 / 4);
}

INSTANTIATE_TEST_SUITE_P(Headless, Gl, kBackends, backend_name);

}  // namespace
}  // namespace rt
