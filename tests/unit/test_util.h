#pragma once
// Small helpers shared by the unit tests: paths into the source tree, and scenes
// built in code where a test needs to know every value.

#include <filesystem>
#include <fstream>
#include <string>

#include "core/scene.h"

namespace rt::test {

inline std::filesystem::path source_dir() { return RTVIEW_SOURCE_DIR; }
inline std::filesystem::path scene_path(const std::string& name) {
    return source_dir() / "assets/scenes" / name;
}

// A fresh, empty temporary directory per test.
inline std::filesystem::path temp_dir(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / ("rtview_test_" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

inline std::filesystem::path write_file(const std::filesystem::path& path,
                                        const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

inline Material plain(vec3 ka, vec3 kd, vec3 ks = vec3(0.0f), float shininess = 1.0f) {
    Material m;
    m.ka = ka;
    m.kd = kd;
    m.ks = ks;
    m.shininess = shininess;
    return m;
}

// A camera at `eye` looking down -z with an odd resolution, so the centre pixel's ray
// is exactly the optical axis.
inline Camera axis_camera(vec3 eye, int size = 31) {
    return Camera::look_at(eye, eye - vec3(0, 0, 1), vec3(0, 1, 0), 30.0f, size, size);
}

}  // namespace rt::test
