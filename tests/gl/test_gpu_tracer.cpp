// The GPU tracer (shaders/gputrace.comp) against the CPU tracer it ports, on real
// headless contexts (EGL and OSMesa): every shipped scene, the test scenes that reach the
// corners of the tracer (total internal reflection, glTF hierarchies, vertex colours,
// PLY, far from the origin), and each effect switched off. The criterion is the issue's:
// PSNR at least 40 dB and at most 0.1 % of pixels differing by more than 2/255, and a
// path broken on one side only must fail it.
#include <gtest/gtest.h>

#include <filesystem>

#include "../unit/far_scene.h"
#include "../unit/test_util.h"
#include "app/gl/context.h"
#include "app/gl/debug.h"
#include "app/gl/gpu_tracer.h"
#include "core/compare.h"
#include "core/error.h"
#include "core/renderer.h"
#include "core/scene_loader.h"
#include "gl_fixture.h"

namespace rt {
namespace {

class GpuTrace : public ::testing::TestWithParam<gl::Backend> {
  protected:
    void SetUp() override {
        context_ = gl::create_headless_context(GetParam(), "rt_gl_tests");
        if (const std::string why = gl::compute_unavailable_reason(); !why.empty())
            GTEST_SKIP() << why;
    }
    void TearDown() override {
        EXPECT_EQ(gl::debug_error_count(), errors_before_) << "KHR_debug reported GL errors";
    }

    std::unique_ptr<gl::Context> context_;
    std::uint64_t errors_before_ = gl::debug_error_count();
};

struct Agreement {
    ImageDiff diff;
    bool ok() const {
        return (diff.identical() || diff.psnr_db >= 40.0) && diff.share_over <= 0.001;
    }
};

std::ostream& operator<<(std::ostream& os, const Agreement& a) {
    return os << "PSNR " << (a.diff.identical() ? 999.0 : a.diff.psnr_db) << " dB, "
              << 100.0 * a.diff.share_over << " % of pixels over 2/255";
}

// The scene traced on both sides at w x h, the GPU with `gpu_options` (default: the same).
Agreement agreement(const std::filesystem::path& file, int w, int h, const TraceOptions& options,
                    const std::optional<TraceOptions>& gpu_options = std::nullopt) {
    LoadedScene loaded = load_scene(file);
    loaded.scene.camera = loaded.scene.camera.resized(w, h);
    const Scene scene(std::move(loaded.scene));
    RenderOptions cpu;
    cpu.trace = options;
    const Image reference = render(scene, cpu);
    gl::GpuTracer gpu;
    gpu.upload(scene);
    return {compare_images(reference, gpu.render(scene.camera, gpu_options.value_or(options)))};
}

std::vector<std::filesystem::path> shipped_scenes() {
    std::vector<std::filesystem::path> scenes;
    for (const auto& entry :
         std::filesystem::directory_iterator(test::source_dir() / "assets/scenes"))
        if (entry.path().extension() == ".json") scenes.push_back(entry.path());
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

TEST_P(GpuTrace, AgreesWithTheCpuTracerOnEveryShippedScene) {
    const auto scenes = shipped_scenes();
    ASSERT_GE(scenes.size(), 5u);
    for (const auto& file : scenes)
        for (const auto& [w, h] : {std::pair{160, 120}, std::pair{640, 480}}) {
            const Agreement a = agreement(file, w, h, TraceOptions{});
            EXPECT_TRUE(a.ok()) << file.filename() << " at " << w << "x" << h << ": " << a;
        }
}

TEST_P(GpuTrace, AgreesOnTheCornersOfTheTracer) {
    const auto data = test::source_dir() / "tests/data";
    for (const char* file : {"tir/tir.json", "gltf/hierarchy.gltf", "gltf/colours.gltf",
                             "gltf/lights.gltf", "mesh/octahedron_binary.ply"}) {
        const Agreement a = agreement(data / file, 160, 120, TraceOptions{});
        EXPECT_TRUE(a.ok()) << file << ": " << a;
    }
    // Every kind of shape, with and without transforms, at the origin and far from it
    // (the checker's shift of the scene's origin, the ray offsets at large coordinates).
    // A folder per backend: ctest runs the EGL and OSMesa instances side by side.
    const auto dir = test::temp_dir(std::string("gpu_far_") +
                                    (GetParam() == gl::Backend::kEgl ? "egl" : "osmesa"));
    for (double o : {0.0, 1e6}) {
        test::write_file(dir / ("tetra" + test::number(o) + ".obj"), test::tetra_obj(o));
        test::write_file(dir / "tetra0.obj", test::tetra_obj(0.0));
        const auto path =
            test::write_file(dir / ("far" + test::number(o) + ".json"), test::far_json(o));
        const Agreement a = agreement(path, 160, 120, TraceOptions{});
        EXPECT_TRUE(a.ok()) << "far scene at offset " << o << ": " << a;
    }
    // The same scene a thousand times smaller (balls of 1.5 mm), at the origin and a
    // thousand units out: the offsets and the feelers' ends at small sizes.
    for (double o : {0.0, 1e3}) {
        const auto tiny = dir / ("tiny" + test::number(o));
        std::filesystem::create_directories(tiny);
        test::write_file(tiny / ("tetra" + test::number(o) + ".obj"), test::tetra_obj(o, 1e-3));
        test::write_file(tiny / "tetra0.obj", test::tetra_obj(0.0, 1e-3));
        const auto path = test::write_file(tiny / "tiny.json", test::far_json(o, 1e-3));
        const Agreement a = agreement(path, 160, 120, TraceOptions{});
        EXPECT_TRUE(a.ok()) << "tiny scene at offset " << o << ": " << a;
    }
}

TEST_P(GpuTrace, AgreesWithEachEffectOff) {
    const auto whitted = test::scene_path("whitted.json");
    TraceOptions plain;
    plain.shadows = plain.reflections = plain.refractions = false;
    // Deep, but with the default minimum weight: llvmpipe stops a shader's loops after
    // 65535 iterations in all (LP_MAX_TGSI_LOOP_ITERATIONS), which every ray down to
    // weight 0 at depth 12 would pass (docs/gpu-tracer.md).
    TraceOptions deep;
    deep.max_depth = 12;
    TraceOptions one_bounce;
    one_bounce.max_depth = 1;
    for (const TraceOptions& options : {plain, deep, one_bounce}) {
        const Agreement a = agreement(whitted, 160, 120, options);
        EXPECT_TRUE(a.ok()) << "max depth " << options.max_depth << ": " << a;
    }
}

// The criterion can fail: one effect switched off on the GPU side only.
TEST_P(GpuTrace, APathBrokenOnOneSideFailsTheComparison) {
    const auto whitted = test::scene_path("whitted.json");
    TraceOptions no_refraction, no_reflection, no_shadows;
    no_refraction.refractions = false;
    no_reflection.reflections = false;
    no_shadows.shadows = false;
    for (const TraceOptions& broken : {no_refraction, no_reflection, no_shadows}) {
        const Agreement a = agreement(whitted, 160, 120, TraceOptions{}, broken);
        EXPECT_FALSE(a.ok()) << a;
    }
}

TEST_P(GpuTrace, ASceneWithoutObjectsIsBackground) {
    SceneDescription d;
    d.camera = d.camera.resized(16, 12);
    d.background = vec3(0.25f, 0.5f, 0.75f);
    const Scene scene(std::move(d));
    gl::GpuTracer gpu;
    gpu.upload(scene);
    const Image image = gpu.render(scene.camera, TraceOptions{});
    for (const vec3& p : image.pixels) EXPECT_EQ(p, scene.background);
}

INSTANTIATE_TEST_SUITE_P(Headless, GpuTrace, kBackends, backend_name);

}  // namespace
}  // namespace rt
