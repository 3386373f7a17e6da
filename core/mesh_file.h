#pragma once
// A mesh read from a file (OBJ, glTF), as the scene loader takes it in: the triangles,
// their materials, what was skipped, and where the positions' zero lies.

#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/material.h"
#include "core/mesh.h"
#include "core/texture.h"

namespace rt {

struct MeshFileOptions {
    float crease_degrees = 60.0f;
    // Where the centre of the mesh's box lies beyond this distance from the origin (in
    // any coordinate), store positions relative to it (MeshFile::origin), taken off in
    // double precision: a model far from the origin keeps its shape in float.
    double recentre_beyond = std::numeric_limits<double>::infinity();
    // Or where it lies further out than this many times the box's largest side: a small
    // model at a moderate distance (1 mm at 1,000 units) is as short of float precision
    // there as a large one far out.
    double recentre_beyond_sizes = std::numeric_limits<double>::infinity();
    // Or store positions relative to this point (a scene's origin, core/scene_loader.h).
    std::optional<glm::dvec3> origin;
    // A model whose box's largest side lies outside [kSmallestSize, kLargestSize] is
    // scaled by a power of two (exact) to a side in [1, 2), MeshFile::scale (a bare
    // model's own scene only).
    bool rescale = false;
    // Or store positions in units of this (a scene's scale, core/scene_loader.h).
    std::optional<double> scale;
};

struct MeshFile {
    TriangleMesh mesh;  // mesh.materials index `materials`; kNoFileMaterial where none was named
    std::vector<Material> materials;  // Material::texture indexes `textures`
    std::vector<Texture> textures;
    std::vector<std::string> warnings;  // "FILE: WHERE: WHAT" lines for what was skipped
    glm::dvec3 origin{0.0};             // where the positions' zero is, in the file's coordinates
    double scale = 1.0;                 // file units per unit of the positions: a power of two
};

inline constexpr std::uint32_t kNoFileMaterial = 0xffffffffu;

// Where a mesh whose used positions span [lo, hi] (file coordinates; lo > hi: none) puts
// its zero: the origin asked for, else the box's centre if it lies beyond recentre_beyond
// or beyond recentre_beyond_sizes times the box's largest side, else the file's zero.
glm::dvec3 mesh_origin(const MeshFileOptions& options, const glm::dvec3& lo, const glm::dvec3& hi);

// Sizes a model keeps as they are (MeshFileOptions::rescale). Below, the ray offsets'
// absolute step near zero (offset_ray_origin) is large for it and squared lengths
// underflow; above, products of two coordinates (the triangle test's) and squared
// lengths overflow. A power of two keeps every float coordinate exact, and every
// computation's rounding the same relative to the model, so it looks as it would.
inline constexpr double kSmallestSize = 0x1p-4, kLargestSize = 0x1p24;

// The unit in which something `size` wide is stored: 1 where size lies within
// [kSmallestSize, kLargestSize] (or is 0 or not finite), else the power of two that
// brings it into [1, 2).
double power_of_two_unit(double size);

// File units per unit of the stored positions (MeshFile::scale): options.scale if given;
// else, where options.rescale asks, power_of_two_unit of the box's largest side; else 1.
double mesh_scale(const MeshFileOptions& options, const glm::dvec3& lo, const glm::dvec3& hi);

// By the file's extension: .obj (core/obj_loader.h), .gltf or .glb (core/gltf_loader.h),
// .ply or .stl (core/assimp_loader.h).
// Throws rt::Error naming the file on anything it cannot use.
MeshFile load_mesh_file(const std::filesystem::path& path, const MeshFileOptions& options = {});

}  // namespace rt
