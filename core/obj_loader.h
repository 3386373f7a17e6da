#pragma once
// Wavefront OBJ + MTL through tinyobjloader: polygons triangulated, missing normals
// computed, MTL Ka/Kd/Ks/Ns/Ni/d mapped onto rt::Material.

#include <filesystem>
#include <string>
#include <vector>

#include "core/material.h"
#include "core/mesh.h"

namespace rt {

struct ObjData {
    TriangleMesh mesh;  // mesh.materials index `materials`; kNoObjMaterial where none was named
    std::vector<Material> materials;
    std::vector<std::string> warnings;  // "FILE: WHERE: WHAT" lines for what was skipped
};

inline constexpr std::uint32_t kNoObjMaterial = 0xffffffffu;

// Throws rt::Error naming the OBJ file on anything it cannot use.
ObjData load_obj(const std::filesystem::path& path, float crease_degrees = 60.0f);

}  // namespace rt
