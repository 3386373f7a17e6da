#pragma once
// Wavefront OBJ + MTL through tinyobjloader (its double-precision build): polygons
// triangulated, missing normals computed, MTL Ka/Kd/Ks/Ns/Ni/d mapped onto rt::Material.

#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/material.h"
#include "core/mesh.h"

namespace rt {

struct ObjOptions {
    float crease_degrees = 60.0f;
    // Where the centre of the mesh's box lies beyond this distance from the origin (in
    // any coordinate), store positions relative to it (ObjData::origin), taken off in
    // double precision: a model far from the origin keeps its shape in float.
    double recentre_beyond = std::numeric_limits<double>::infinity();
    // Or store positions relative to this point (a scene's origin, core/scene_loader.h).
    std::optional<glm::dvec3> origin;
};

struct ObjData {
    TriangleMesh mesh;  // mesh.materials index `materials`; kNoObjMaterial where none was named
    std::vector<Material> materials;
    std::vector<std::string> warnings;  // "FILE: WHERE: WHAT" lines for what was skipped
    glm::dvec3 origin{0.0};             // where the positions' zero is, in the file's coordinates
};

inline constexpr std::uint32_t kNoObjMaterial = 0xffffffffu;

// Throws rt::Error naming the OBJ file on anything it cannot use.
ObjData load_obj(const std::filesystem::path& path, const ObjOptions& options = {});

// The byte-order mark U+FEFF in UTF-8, which some editors put first in a text file.
inline std::string_view skip_utf8_bom(std::string_view text) {
    return text.starts_with("\xEF\xBB\xBF") ? text.substr(3) : text;
}

}  // namespace rt
