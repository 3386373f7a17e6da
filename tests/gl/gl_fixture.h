#pragma once
// The GL tests' fixture: a headless context of each kind (EGL, OSMesa) per test, and no
// GL error reported through KHR_debug while the test ran (the tests run with
// RTVIEW_GL_DEBUG=1). Each test file instantiates it for both kinds.

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "../unit/test_util.h"
#include "app/gl/context.h"
#include "app/gl/debug.h"
#include "core/scene_loader.h"

namespace rt {

namespace gl {
inline void PrintTo(Backend b, std::ostream* os) {
    *os << (b == Backend::kEgl ? "EGL" : b == Backend::kOsmesa ? "OSMesa" : "auto");
}
}  // namespace gl

class GlTest : public ::testing::TestWithParam<gl::Backend> {
  protected:
    void SetUp() override { context_ = gl::create_headless_context(GetParam(), "rt_gl_tests"); }
    void TearDown() override {
        EXPECT_EQ(gl::debug_error_count(), errors_before_) << "KHR_debug reported GL errors";
    }

    static SceneDescription load(const std::string& name, int w, int h) {
        LoadedScene loaded = load_scene(test::scene_path(name));
        loaded.scene.camera = loaded.scene.camera.resized(w, h);
        return std::move(loaded.scene);
    }

    std::unique_ptr<gl::Context> context_;
    std::uint64_t errors_before_ = gl::debug_error_count();
};

// Each test suite runs on both kinds, its tests named .../egl and .../osmesa:
//   INSTANTIATE_TEST_SUITE_P(Headless, Suite, kBackends, backend_name);
inline const auto kBackends = ::testing::Values(gl::Backend::kEgl, gl::Backend::kOsmesa);
inline std::string backend_name(const ::testing::TestParamInfo<gl::Backend>& info) {
    return info.param == gl::Backend::kEgl ? "egl" : "osmesa";
}

// The shipped scenes every pass is checked on.
inline const char* const kScenes[] = {"tutorial.json", "whitted.json", "cornell.json",
                                      "many_spheres.json"};

}  // namespace rt
