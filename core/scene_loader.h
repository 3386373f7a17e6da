#pragma once
// Scene files: the native JSON format (docs/scene-format.md) or a bare .obj, which is
// framed by a default camera and lit by a default light rig.

#include <filesystem>
#include <string>
#include <vector>

#include "core/scene.h"

namespace rt {

struct LoadedScene {
    Scene scene;  // not yet built (Scene::build)
    std::vector<std::string> warnings;
};

// Throws rt::Error "FILE: WHERE: WHAT" on anything it cannot use.
LoadedScene load_scene(const std::filesystem::path& path);
LoadedScene load_json_scene(const std::filesystem::path& path);
LoadedScene load_obj_scene(const std::filesystem::path& path);

// Looks at the bounds from the front and a little above, with a key and a fill light.
void frame_bounds(Scene& scene, const Aabb& bounds, int cols, int rows);

// Materials every scene can name without defining them: default, matte, mirror, glass.
std::vector<Material> material_presets();

}  // namespace rt
