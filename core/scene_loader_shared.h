#pragma once
// What the scene loaders share (core/scene_loader.cpp reads JSON scenes,
// core/bare_scene.cpp bare meshes and glTF files): their limits, and how a mesh file's
// textures join a scene.

#include <cstdint>
#include <utility>

#include "core/mesh_file.h"
#include "core/scene.h"

namespace rt::loader {

constexpr int kMaxResolution = 16384;

// A mesh file's textures join the scene's; its materials' texture indices follow them.
inline void append_textures(MeshFile& mesh, SceneDescription& scene) {
    const auto first = static_cast<std::uint32_t>(scene.textures.size());
    for (Texture& t : mesh.textures) scene.textures.push_back(std::move(t));
    for (Material& m : mesh.materials)
        if (m.texture) *m.texture += first;
}

// Beyond this distance from the origin (in any coordinate) a scene is read relative to
// a point of its own: its eye (JSON) or its centre (a bare mesh). Nearer, float's
// precision is ample and the scene is read as it is, bit for bit.
constexpr double kFarFromOrigin = 4096.0;
// Or beyond this many times its own size (a bare mesh's box, the distance a JSON camera
// looks across): there the ray offsets (256 float steps, 3e-5 of the distance) would be a
// visible share of the scene (a 1 mm model 1,000 units out lost its shadows and
// reflections), and float's step a larger one.
constexpr double kFarForItsSize = 256.0;

}  // namespace rt::loader
