#include "core/obj_loader.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include <tiny_obj_loader.h>
#include <glm/geometric.hpp>

#include "core/error.h"

namespace rt {
namespace {

vec3 to_vec3(const tinyobj::real_t* v) { return {v[0], v[1], v[2]}; }

bool finite(const vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

Material from_mtl(const tinyobj::material_t& m) {
    Material out;
    out.name = m.name;
    out.ka = glm::max(to_vec3(m.ambient), vec3(0.0f));
    out.kd = glm::max(to_vec3(m.diffuse), vec3(0.0f));
    out.ks = glm::max(to_vec3(m.specular), vec3(0.0f));
    out.shininess = std::max(0.0f, static_cast<float>(m.shininess));
    out.ior = m.ior > 0.0f ? static_cast<float>(m.ior) : 1.5f;
    out.transparency = std::clamp(1.0f - static_cast<float>(m.dissolve), 0.0f, 1.0f);
    return out;
}

void add_warnings(const std::string& file, const std::string& text, std::vector<std::string>& out) {
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);)
        if (!line.empty()) out.push_back(file + ": warning: " + line);
}

void copy_positions(const std::string& file, const tinyobj::attrib_t& attrib, TriangleMesh& mesh) {
    mesh.positions.resize(attrib.vertices.size() / 3);
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        mesh.positions[i] = to_vec3(&attrib.vertices[3 * i]);
        if (!finite(mesh.positions[i]))
            throw Error(file, "vertex " + std::to_string(i + 1),
                        "coordinate is not a finite number");
    }
}

// Copies the triangles, checking every index; returns whether every corner had a usable normal.
bool copy_triangles(const std::string& file, const tinyobj::ObjReader& reader, TriangleMesh& mesh) {
    const tinyobj::attrib_t& attrib = reader.GetAttrib();
    const auto vertex_count = static_cast<long long>(mesh.positions.size());
    const auto normal_count = static_cast<long long>(attrib.normals.size() / 3);
    bool all_normals = true;
    std::vector<vec3> normals;
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        const auto& idx = shape.mesh.indices;
        for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
            const std::string where =
                (shape.name.empty() ? "" : "object \"" + shape.name + "\", ") + "face " +
                std::to_string(f + 1);
            if (shape.mesh.num_face_vertices[f] != 3)
                throw Error(file, where, "face was not triangulated");
            glm::uvec3 tri;
            for (int k = 0; k < 3; ++k) {
                const tinyobj::index_t& corner = idx[3 * f + k];
                if (corner.vertex_index < 0 || corner.vertex_index >= vertex_count)
                    throw Error(file, where,
                                "vertex index out of range (the file has " +
                                    std::to_string(vertex_count) + " vertices)");
                tri[k] = static_cast<std::uint32_t>(corner.vertex_index);
                const bool has_normal =
                    corner.normal_index >= 0 && corner.normal_index < normal_count;
                const vec3 n =
                    has_normal ? to_vec3(&attrib.normals[3 * corner.normal_index]) : vec3(0.0f);
                all_normals = all_normals && finite(n) && glm::dot(n, n) > 0.0f;
                normals.push_back(n);
            }
            mesh.triangles.push_back(tri);
            const int material = shape.mesh.material_ids.empty() ? -1 : shape.mesh.material_ids[f];
            mesh.materials.push_back(material >= 0 ? static_cast<std::uint32_t>(material)
                                                   : kNoObjMaterial);
        }
    }
    if (all_normals) {
        for (vec3& n : normals) n = glm::normalize(n);
        mesh.corner_normals = std::move(normals);
    }
    return all_normals;
}

// Before tinyobjloader reads it: not too large, and text (a NUL byte in the first 64 KiB
// means it is not an OBJ file), so garbage is refused at once rather than parsed.
void check_is_obj_text(const std::filesystem::path& path) {
    constexpr std::uintmax_t kMaxObjBytes = 2ull << 30;
    std::error_code ec;
    const std::uintmax_t bytes = std::filesystem::file_size(path, ec);
    if (!ec && bytes > kMaxObjBytes)
        throw Error(path.string(), "open",
                    "is " + std::to_string(bytes >> 20) + " MiB; OBJ files are limited to 2 GiB");
    std::ifstream in(path, std::ios::binary);
    std::string head(64 * 1024, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(in.gcount()));
    const auto nul = head.find('\0');
    if (nul != std::string::npos)
        throw Error(path.string(), "byte " + std::to_string(nul + 1),
                    "a NUL byte: this is not an OBJ text file");
}

// tinyobjloader reads "nan", "inf" or "1e999" as some number without a word, so the
// vertex lines are checked first: a coordinate must be a finite float.
void check_vertex_lines(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::string line;
    for (std::size_t number = 1; std::getline(in, line); ++number) {
        if (line.size() < 2 || line[0] != 'v' || (line[1] != ' ' && line[1] != '\t')) continue;
        std::istringstream tokens(line.substr(2));
        std::string token;
        for (int k = 0; k < 3 && tokens >> token; ++k) {
            float value = 0.0f;
            const auto [end, ec] =
                std::from_chars(token.data(), token.data() + token.size(), value);
            if (ec != std::errc{} || end != token.data() + token.size() || !std::isfinite(value))
                throw Error(path.string(), "line " + std::to_string(number),
                            "vertex coordinate \"" + token + "\" is not a finite number");
        }
    }
}

}  // namespace

ObjData load_obj(const std::filesystem::path& path, float crease_degrees) {
    const std::string file = path.string();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw Error(file, "open", "cannot open file (does it exist?)");

    check_is_obj_text(path);
    check_vertex_lines(path);
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    config.mtl_search_path = path.parent_path().string();
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(file, config)) {
        std::string message = reader.Error();
        while (!message.empty() && (message.back() == '\n' || message.back() == '\r'))
            message.pop_back();
        throw Error(file, "parse", message.empty() ? "not a readable OBJ file" : message);
    }

    ObjData data;
    data.mesh.name = path.filename().string();
    add_warnings(file, reader.Warning(), data.warnings);
    for (const auto& m : reader.GetMaterials()) data.materials.push_back(from_mtl(m));
    copy_positions(file, reader.GetAttrib(), data.mesh);
    if (!copy_triangles(file, reader, data.mesh)) compute_corner_normals(data.mesh, crease_degrees);
    if (data.mesh.triangles.empty())
        throw Error(file, "faces", "no triangles to render (only points or lines?)");
    return data;
}

}  // namespace rt
