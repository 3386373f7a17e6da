#pragma once
// Small helpers shared by the unit tests: paths into the source tree, and scenes
// built in code where a test needs to know every value.

#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "core/item_buffer.h"
#include "core/scene.h"
#include "core/scene_loader.h"

namespace rt::test {

// A point with each coordinate uniform in [-extent, extent].
inline vec3 random_point(std::mt19937& rng, float extent) {
    std::uniform_real_distribution<float> u(-extent, extent);
    return {u(rng), u(rng), u(rng)};
}

inline std::filesystem::path source_dir() { return RTVIEW_SOURCE_DIR; }
inline std::filesystem::path scene_path(const std::string& name) {
    return source_dir() / "assets/scenes" / name;
}

// The file names of the shipped scenes (assets/scenes/*.json).
inline std::vector<std::string> shipped_scene_names() {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(source_dir() / "assets/scenes"))
        if (entry.path().extension() == ".json") names.push_back(entry.path().filename().string());
    return names;
}

// The item buffer a perfect rasteriser would give: each pixel centre's first hit, traced.
inline ItemBuffer traced_item_buffer(const Scene& scene) {
    const Camera& camera = scene.camera;
    ItemBuffer ib(camera.cols, camera.rows);
    for (int y = 0; y < camera.rows; ++y) {
        for (int x = 0; x < camera.cols; ++x) {
            Hit hit;
            if (!scene.intersect(camera.ray(x, y), hit)) continue;
            ib.ids[ib.index(x, y)] = hit.object + 1;
            ib.prim[ib.index(x, y)] = hit.prim;
        }
    }
    return ib;
}

// A shipped scene (assets/scenes/NAME) at another resolution, as a description to build.
inline SceneDescription shipped_scene(const std::string& name, int w, int h) {
    LoadedScene loaded = load_scene(scene_path(name));
    loaded.scene.camera = loaded.scene.camera.resized(w, h);
    return std::move(loaded.scene);
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

// Glass with no colour of its own: only what it lets through (index 1.5 unless given).
inline Material clear_glass(float transparency, float ior = 1.5f) {
    Material glass = plain(vec3(0.0f), vec3(0.0f));
    glass.transparency = transparency;
    glass.ior = ior;
    return glass;
}

// A camera at `eye` looking down -z with an odd resolution, so the centre pixel's ray
// is exactly the optical axis.
inline Camera axis_camera(vec3 eye, int size = 31) {
    return Camera::look_at(eye, eye - vec3(0, 0, 1), vec3(0, 1, 0), 30.0f, size, size);
}

// A closed box from lo to hi, its faces wound outward (counter-clockwise seen from
// outside) or, as some exporters and every mirrored model do, inward.
enum class Winding { kOutward, kInward };
inline TriangleMesh box_mesh(vec3 lo, vec3 hi, Winding winding) {
    TriangleMesh box;
    for (int i = 0; i < 8; ++i)
        box.positions.push_back({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
    box.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6},   // z = lo, z = hi
                     {0, 1, 5}, {0, 5, 4}, {2, 6, 7}, {2, 7, 3},   // y = lo, y = hi
                     {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};  // x = lo, x = hi
    if (winding == Winding::kInward)
        for (auto& t : box.triangles) std::swap(t.y, t.z);
    return box;
}

}  // namespace rt::test
