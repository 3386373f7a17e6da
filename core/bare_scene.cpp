// Bare meshes (.obj, .ply, .stl) and glTF files as scenes: framed and lit by default
// where the file has no camera or lights of its own (core/scene_loader.h).
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "core/error.h"
#include "core/file_kind.h"
#include "core/gltf_loader.h"
#include "core/scene_loader.h"
#include "core/scene_loader_shared.h"

namespace rt {

using loader::append_textures;
using loader::kFarForItsSize;
using loader::kFarFromOrigin;
using loader::kMaxResolution;

void frame_bounds(SceneDescription& scene, const Aabb& bounds, int cols, int rows) {
    const vec3 centre = bounds.centre();
    // Never so close that float cannot tell the eye from the centre (a few float
    // spacings away at least): collapsed geometry would otherwise put the eye on the
    // target (a NaN camera). Anything larger keeps its own size on screen.
    const float magnitude =
        std::max({std::fabs(centre.x), std::fabs(centre.y), std::fabs(centre.z)});
    const float radius = std::max({0.5f * glm::length(bounds.extent()), 1e-6f, 2e-7f * magnitude});
    const float fov = 40.0f;
    const float distance = radius / std::sin(glm::radians(fov) * 0.5f) * 1.05f;
    const vec3 view_dir = glm::normalize(vec3(0.35f, 0.3f, 1.0f));
    scene.camera =
        Camera::look_at(centre + distance * view_dir, centre, vec3(0, 1, 0), fov, cols, rows);
    Light key{Light::Type::kPoint, centre + radius * vec3(2.0f, 4.0f, 3.0f), {}, vec3(0.8f)};
    Light fill{Light::Type::kPoint, centre + radius * vec3(-3.0f, 1.5f, 2.0f), {}, vec3(0.35f)};
    scene.lights = {key, fill};
}

namespace {

// The rotation that takes a bare mesh's `up` axis to +y (axis permutations with signs,
// so exact in float); throws on an unknown name.
glm::mat3 up_rotation(const std::filesystem::path& path, const std::string& up) {
    // Columns are the images of x, y and z.
    if (up == "y") return glm::mat3(1.0f);
    if (up == "-y") return {{1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
    if (up == "z") return {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}};
    if (up == "-z") return {{1, 0, 0}, {0, 0, 1}, {0, -1, 0}};
    if (up == "x") return {{0, 1, 0}, {-1, 0, 0}, {0, 0, 1}};
    if (up == "-x") return {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}};
    throw Error(path.string(), "--up",
                "unknown axis \"" + up + "\" (expected x, y, z, -x, -y or -z)");
}

}  // namespace

static LoadedScene bare_mesh_scene(const std::filesystem::path& path, MeshFile mesh);

LoadedScene load_obj_scene(const std::filesystem::path& path, const LoadOptions& options) {
    const glm::mat3 rotate = up_rotation(path, options.up);
    MeshFileOptions obj_options;
    obj_options.recentre_beyond = kFarFromOrigin;
    obj_options.recentre_beyond_sizes = kFarForItsSize;
    obj_options.rescale = true;
    MeshFile obj = load_mesh_file(path, obj_options);  // .obj, .ply or .stl
    for (vec3& p : obj.mesh.positions) p = rotate * p;
    for (vec3& n : obj.mesh.corner_normals) n = rotate * n;
    return bare_mesh_scene(path, std::move(obj));
}

// A bare mesh file's scene: the mesh with the preset materials before its own, the
// default background and ambient, framed and lit by frame_bounds.
static LoadedScene bare_mesh_scene(const std::filesystem::path& path, MeshFile mesh) {
    LoadedScene out;
    out.origin = mesh.origin;
    out.scale = mesh.scale;
    out.scene.origin = mesh.origin / mesh.scale;  // a checker's squares in the scene's units
    SceneDescription& scene = out.scene;
    scene.materials = material_presets();
    append_textures(mesh, scene);
    for (Material& m : mesh.materials) scene.materials.push_back(std::move(m));
    const auto presets = static_cast<std::uint32_t>(material_presets().size());
    for (std::uint32_t& m : mesh.mesh.materials) m = m < mesh.materials.size() ? presets + m : 0;
    const Aabb bounds = bounds_of(mesh.mesh);
    scene.meshes.push_back(std::move(mesh.mesh));
    scene.objects.push_back(Object{path.filename().string(), MeshRef{0, true}, 0, std::nullopt});
    scene.background = vec3(0.05f);
    scene.ambient = vec3(0.15f);
    frame_bounds(scene, bounds, 640, 480);
    out.warnings = std::move(mesh.warnings);
    return out;
}

LoadedScene load_gltf_scene(const std::filesystem::path& path, const LoadOptions& options) {
    MeshFileOptions mesh_options;
    mesh_options.recentre_beyond = kFarFromOrigin;
    mesh_options.recentre_beyond_sizes = kFarForItsSize;
    mesh_options.rescale = true;
    GltfScene gltf = load_gltf(path, mesh_options);
    std::vector<GltfCamera> cameras = std::move(gltf.cameras);
    std::vector<Light> lights = std::move(gltf.lights);
    LoadedScene out = bare_mesh_scene(path, std::move(gltf.geometry));
    if (!lights.empty()) out.scene.lights = std::move(lights);
    if (options.camera && *options.camera >= static_cast<int>(cameras.size()))
        throw Error(path.string(), "--camera",
                    "no camera " + std::to_string(*options.camera) + " (the file has " +
                        std::to_string(cameras.size()) + " perspective cameras)");
    if (cameras.empty()) return out;
    const GltfCamera& c = cameras[static_cast<std::size_t>(options.camera.value_or(0))];
    int cols = 640, rows = 480;
    if (c.aspect > 0.0f)
        cols = std::clamp(static_cast<int>(std::lround(480.0f * c.aspect)), 1, kMaxResolution);
    const vec3 up = glm::length(glm::cross(c.up, c.forward)) > 1e-4f ? c.up : vec3(0, 0, 1);
    out.scene.camera = Camera::look_at(c.eye, c.eye + c.forward, up, c.yfov_degrees, cols, rows);
    return out;
}

}  // namespace rt
