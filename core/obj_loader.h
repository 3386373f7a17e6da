#pragma once
// Wavefront OBJ + MTL through tinyobjloader (its double-precision build): polygons
// triangulated, missing normals computed, MTL Ka/Kd/Ks/Ns/Ni/d mapped onto rt::Material.

#include <filesystem>
#include <string>
#include <vector>

#include "core/mesh_file.h"

namespace rt {

// Throws rt::Error naming the OBJ file on anything it cannot use.
MeshFile load_obj(const std::filesystem::path& path, const MeshFileOptions& options = {});

// The byte-order mark U+FEFF in UTF-8, which some editors put first in a text file.
inline std::string_view skip_utf8_bom(std::string_view text) {
    return text.starts_with("\xEF\xBB\xBF") ? text.substr(3) : text;
}

}  // namespace rt
