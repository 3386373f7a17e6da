#pragma once
// PLY (the Stanford format, ASCII and binary) and STL (ASCII and binary) through Assimp:
// every mesh of the file as one triangle mesh, with the file's per-vertex normals and
// colours where it has them (flat-shaded and uncoloured otherwise). OBJ stays with
// tinyobjloader and glTF with tinygltf (docs/scene-format.md says why).

#include <filesystem>

#include "core/mesh_file.h"

namespace rt {

// Throws rt::Error naming the file on anything it cannot use.
MeshFile load_ply_stl(const std::filesystem::path& path, const MeshFileOptions& options = {});

}  // namespace rt
