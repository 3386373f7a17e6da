#pragma once
// Scene files: the native JSON format (docs/scene-format.md), a bare .obj, framed by a
// default camera and lit by a default light rig, or a glTF 2.0 file (.gltf, .glb), with
// its own camera and lights where it has them.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/scene.h"

namespace rt {

struct LoadedScene {
    SceneDescription scene;  // Scene(std::move(scene), kind) builds it
    std::vector<std::string> warnings;
    // Where the scene's zero lies in the file's coordinates: a bare mesh is moved next to
    // the origin (in double precision) so that float keeps its shape and its lighting.
    glm::dvec3 origin{0.0};
    // File units per scene unit: a scene far smaller or larger than float's arithmetic
    // handles well is read in a power-of-two unit (power_of_two_unit, core/mesh_file.h);
    // else 1. A point p of the scene is origin + scale * p in the file.
    double scale = 1.0;
};

// Which of a bare mesh's axes points up: "y" (the default), "z", "x", "-y", "-z", "-x".
// Z-up is common for scans and CAD models.
struct LoadOptions {
    std::string up = "y";
    // Which of a glTF file's perspective cameras to look through (none: the first, or
    // the default framing if it has none).
    std::optional<int> camera;
};

// Throws rt::Error "FILE: WHERE: WHAT" on anything it cannot use.
LoadedScene load_scene(const std::filesystem::path& path, const LoadOptions& options = {});
LoadedScene load_json_scene(const std::filesystem::path& path);
// A bare mesh (.obj, .ply or .stl), framed and lit by default.
LoadedScene load_obj_scene(const std::filesystem::path& path, const LoadOptions& options = {});
LoadedScene load_gltf_scene(const std::filesystem::path& path, const LoadOptions& options = {});

// What load_scene reads, by extension (case-insensitive): a scene file of any kind, and
// of those the bare meshes that --up turns.
bool is_scene_file(const std::filesystem::path& path);
bool is_bare_mesh(const std::filesystem::path& path);
inline constexpr const char* kSceneFormats = ".json, .obj, .gltf, .glb, .ply or .stl";

// The accepted --up names, for the programs' checks.
inline constexpr const char* kUpAxes[] = {"y", "z", "x", "-y", "-z", "-x"};

// Looks at the bounds from the front and a little above, with a key and a fill light.
void frame_bounds(SceneDescription& scene, const Aabb& bounds, int cols, int rows);

// Materials every scene can name without defining them: default, matte, mirror, glass.
std::vector<Material> material_presets();

}  // namespace rt
