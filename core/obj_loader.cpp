#include "core/obj_loader.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

#include <tiny_obj_loader.h>
#include <glm/geometric.hpp>

#include "core/error.h"

namespace rt {
namespace {

vec3 to_vec3(const tinyobj::real_t* v) {
    return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
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

// The centre of the box around the vertices that faces, lines and points use, in double.
// The box of the positions the faces, lines and points use (lo > hi: none).
std::pair<glm::dvec3, glm::dvec3> used_bounds(const tinyobj::attrib_t& attrib,
                                              const std::vector<tinyobj::shape_t>& shapes) {
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
    const auto vertex_count = static_cast<int>(attrib.vertices.size() / 3);
    for (const tinyobj::shape_t& shape : shapes)
        for (const auto* list : {&shape.mesh.indices, &shape.lines.indices, &shape.points.indices})
            for (const tinyobj::index_t& corner : *list) {
                if (corner.vertex_index < 0 || corner.vertex_index >= vertex_count) continue;
                const double* v =
                    &attrib.vertices[3 * static_cast<std::size_t>(corner.vertex_index)];
                lo = glm::min(lo, glm::dvec3(v[0], v[1], v[2]));
                hi = glm::max(hi, glm::dvec3(v[0], v[1], v[2]));
            }
    return {lo, hi};
}

// Positions relative to `origin` in units of `scale`, the arithmetic in double precision.
void copy_positions(const std::string& file, const tinyobj::attrib_t& attrib,
                    const glm::dvec3& origin, double scale, TriangleMesh& mesh) {
    mesh.positions.resize(attrib.vertices.size() / 3);
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const double* v = &attrib.vertices[3 * i];
        mesh.positions[i] = vec3((glm::dvec3(v[0], v[1], v[2]) - origin) / scale);
        if (!finite(mesh.positions[i]))
            throw Error(file, "vertex " + std::to_string(i + 1),
                        "coordinate is not a finite number in single precision");
    }
}

// Copies the triangles, checking every index; returns whether every corner had a usable normal.
bool copy_triangles(const std::string& file, const tinyobj::attrib_t& attrib,
                    const std::vector<tinyobj::shape_t>& shapes, TriangleMesh& mesh) {
    const auto vertex_count = static_cast<long long>(mesh.positions.size());
    const auto normal_count = static_cast<long long>(attrib.normals.size() / 3);
    const auto uv_count = static_cast<long long>(attrib.texcoords.size() / 2);
    bool all_normals = true, any_uv = false;
    std::vector<vec3> normals;
    std::vector<glm::vec2> uvs;
    for (const tinyobj::shape_t& shape : shapes) {
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
                // vt's v grows upwards; core/texture.h's downwards (glTF's, images' rows).
                const bool has_uv = corner.texcoord_index >= 0 && corner.texcoord_index < uv_count;
                const double* t = has_uv ? &attrib.texcoords[2 * corner.texcoord_index] : nullptr;
                uvs.push_back(
                    has_uv ? glm::vec2(static_cast<float>(t[0]), static_cast<float>(1.0 - t[1]))
                           : glm::vec2(0.0f));
                any_uv = any_uv || has_uv;
            }
            mesh.triangles.push_back(tri);
            const int material = shape.mesh.material_ids.empty() ? -1 : shape.mesh.material_ids[f];
            mesh.materials.push_back(material >= 0 ? static_cast<std::uint32_t>(material)
                                                   : kNoFileMaterial);
        }
    }
    if (all_normals) {
        for (vec3& n : normals) n = glm::normalize(n);
        mesh.corner_normals = std::move(normals);
    }
    if (any_uv) mesh.corner_uvs = std::move(uvs);
    return all_normals;
}

// Polylines (`l a b c`: segments a-b, b-c) and points (`p`), with indices in range.
void copy_lines_and_points(const tinyobj::attrib_t& attrib,
                           const std::vector<tinyobj::shape_t>& shapes, TriangleMesh& mesh) {
    const auto vertex_count = static_cast<int>(attrib.vertices.size() / 3);
    const auto valid = [&](const tinyobj::index_t& i) {
        return i.vertex_index >= 0 && i.vertex_index < vertex_count;
    };
    for (const tinyobj::shape_t& shape : shapes) {
        std::size_t at = 0;
        for (const int n : shape.lines.num_line_vertices) {
            for (int k = 0; k + 1 < n; ++k) {
                const auto& a = shape.lines.indices[at + k];
                const auto& b = shape.lines.indices[at + k + 1];
                if (valid(a) && valid(b))
                    mesh.segments.push_back({static_cast<std::uint32_t>(a.vertex_index),
                                             static_cast<std::uint32_t>(b.vertex_index)});
            }
            at += static_cast<std::size_t>(std::max(n, 0));
        }
        for (const auto& p : shape.points.indices)
            if (valid(p)) mesh.points.push_back(static_cast<std::uint32_t>(p.vertex_index));
    }
}

// The whole file, refused at once if it is too large or not text (a NUL byte in the
// first 64 KiB), so garbage is not parsed.
std::string read_obj_text(const std::filesystem::path& path) {
    constexpr std::uintmax_t kMaxObjBytes = 2ull << 30;
    std::error_code ec;
    const std::uintmax_t bytes = std::filesystem::file_size(path, ec);
    if (!ec && bytes > kMaxObjBytes)
        throw Error(path.string(), "open",
                    "is " + std::to_string(bytes >> 20) + " MiB; OBJ files are limited to 2 GiB");
    std::ifstream in(path, std::ios::binary);
    std::ostringstream whole;  // in blocks, not a character at a time through an iterator
    whole << in.rdbuf();
    std::string text = std::move(whole).str();
    const auto nul = text.find('\0');
    if (nul != std::string::npos && nul < 64 * 1024)
        throw Error(path.string(), "byte " + std::to_string(nul + 1),
                    "a NUL byte: this is not an OBJ text file");
    return text;
}

// What the line-by-line check counted.
struct ObjCounts {
    long long vertices = 0;
};

bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r';
}

// The next whitespace-separated token of `rest` (as `>>` would read it), which is left
// after it; empty at the end. Without a stream per line: with one, checking the bunny's
// 200k lines cost more than tinyobjloader's parse of them (callgrind: 443 M against
// 251 M instructions). A character at a time: find_first_of with the set of six spaces
// looked each character up in the set (a memchr each: 50 M of the check's 139 M).
std::string_view next_token(std::string_view& rest) {
    std::size_t begin = 0;
    while (begin < rest.size() && is_space(rest[begin])) ++begin;
    std::size_t end = begin;
    while (end < rest.size() && !is_space(rest[end])) ++end;
    const std::string_view token = rest.substr(begin, end - begin);
    rest.remove_prefix(end);
    return token;
}

bool is_element(std::string_view line, char kind) {
    return line.size() >= 2 && line[0] == kind && (line[1] == ' ' || line[1] == '\t');
}

// Before tinyobjloader reads the file, whose messages carry no usable location: every
// vertex coordinate a finite number ("nan", "inf" and "1e999" would become some number
// without a word), and every face of at least three vertices whose indices name a vertex.
ObjCounts check_obj_lines(const std::string& file, std::string_view text) {
    ObjCounts counts;
    long long max_index = 0, max_index_line = 0;
    std::size_t number = 0;
    for (std::size_t at = 0; at < text.size();) {
        const std::size_t eol = std::min(text.find('\n', at), text.size());
        const std::string_view line = text.substr(at, eol - at);
        at = eol + 1;
        ++number;
        const auto fail = [&](const std::string& what) {
            throw Error(file, "line " + std::to_string(number), what);
        };
        std::string_view tokens = line.size() >= 2 ? line.substr(2) : std::string_view{};
        std::string_view token;
        if (is_element(line, 'v')) {
            ++counts.vertices;
            for (int k = 0; k < 3 && !(token = next_token(tokens)).empty(); ++k) {
                double value = 0.0;
                const auto [end, ec] =
                    std::from_chars(token.data(), token.data() + token.size(), value);
                if (ec != std::errc{} || end != token.data() + token.size() ||
                    !std::isfinite(value))
                    fail("vertex coordinate \"" + std::string(token) + "\" is not a finite number");
            }
        } else if (is_element(line, 'f')) {
            int corners = 0;
            for (; !(token = next_token(tokens)).empty(); ++corners) {
                long long index = 0;
                const char* end = token.data() + token.size();
                const auto [stop, ec] = std::from_chars(token.data(), end, index);
                if (ec != std::errc{} || (stop != end && *stop != '/'))
                    fail("face vertex \"" + std::string(token) + "\" is not an index");
                if (index == 0) fail("face index 0 (OBJ indices start at 1)");
                if (index < 0 && -index > counts.vertices)
                    fail("relative face index " + std::to_string(index) + " is out of range (" +
                         std::to_string(counts.vertices) + " vertices defined before it)");
                if (index > max_index) {
                    max_index = index;
                    max_index_line = static_cast<long long>(number);
                }
            }
            if (corners < 3)
                fail("a face needs at least 3 vertices, this one has " + std::to_string(corners));
        }
    }
    if (max_index > counts.vertices)
        throw Error(file, "line " + std::to_string(max_index_line),
                    "face index " + std::to_string(max_index) + " is out of range (the file has " +
                        std::to_string(counts.vertices) + " vertices)");
    return counts;
}

// Reads the MTL files an OBJ names, beside it, skipping a byte-order mark.
class MtlReader : public tinyobj::MaterialReader {
  public:
    MtlReader(std::filesystem::path dir, std::string obj_file)
        : dir_(std::move(dir)), obj_file_(std::move(obj_file)) {}
    bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* names, std::string* warn, std::string*) override {
        const std::filesystem::path path = dir_ / name;
        std::error_code ec;
        std::ifstream in;
        if (std::filesystem::is_regular_file(path, ec)) in.open(path, std::ios::binary);
        if (!in.is_open()) {  // missing, or a directory ("mtllib" with no name), or unreadable
            *warn += "material library \"" + name + "\" not found beside the OBJ file\n";
            return false;
        }
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        std::istringstream stream{std::string(skip_utf8_bom(text))};
        tinyobj::LoadMtl(names, materials, &stream, warn, warn);
        return true;
    }

  private:
    std::filesystem::path dir_;
    std::string obj_file_;
};

}  // namespace

MeshFile load_obj(const std::filesystem::path& path, const MeshFileOptions& options) {
    const std::string file = path.string();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw Error(file, "open", "cannot open file (does it exist?)");

    const std::string text = read_obj_text(path);
    const std::string_view body = skip_utf8_bom(text);
    check_obj_lines(file, body);
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warn, err;
    {
        std::istringstream stream{std::string(body)};
        MtlReader mtl(path.parent_path(), file);
        if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, &stream, &mtl, true,
                              false)) {
            while (!err.empty() && (err.back() == '\n' || err.back() == '\r')) err.pop_back();
            throw Error(file, "parse", err.empty() ? "not a readable OBJ file" : err);
        }
    }

    MeshFile data;
    data.mesh.name = path.filename().string();
    add_warnings(file, warn, data.warnings);
    std::map<std::string, std::uint32_t> textures;  // map_Kd file -> data.textures
    for (const auto& m : materials) {
        data.materials.push_back(from_mtl(m));
        if (m.diffuse_texname.empty()) continue;
        auto [it, added] = textures.try_emplace(m.diffuse_texname,
                                                static_cast<std::uint32_t>(data.textures.size()));
        if (added) {
            data.textures.push_back(read_texture(path.parent_path() / m.diffuse_texname, file,
                                                 "material \"" + m.name + "\" map_Kd"));
            if (m.diffuse_texopt.clamp)
                data.textures.back().wrap_u = data.textures.back().wrap_v = Wrap::kClamp;
        }
        data.materials.back().texture = it->second;
    }
    const auto [lo, hi] = used_bounds(attrib, shapes);
    data.origin = mesh_origin(options, lo, hi);
    data.scale = mesh_scale(options, lo, hi);
    copy_positions(file, attrib, data.origin, data.scale, data.mesh);
    const bool has_normals = copy_triangles(file, attrib, shapes, data.mesh);
    if (const std::size_t dropped = drop_duplicate_triangles(data.mesh))
        data.warnings.push_back(file + ": warning: " + std::to_string(dropped) +
                                " faces repeat an earlier face and were dropped");
    if (!has_normals) compute_corner_normals(data.mesh, options.crease_degrees);
    copy_lines_and_points(attrib, shapes, data.mesh);
    if (!data.mesh.segments.empty() || !data.mesh.points.empty())
        data.warnings.push_back(
            file + ": warning: " + std::to_string(data.mesh.segments.size()) +
            " line segments and " + std::to_string(data.mesh.points.size()) +
            " points are drawn by the raster view only (the tracer renders surfaces)");
    if (data.mesh.triangles.empty() && data.mesh.segments.empty() && data.mesh.points.empty())
        throw Error(file, "faces", "no faces, lines or points: nothing to render");
    return data;
}

}  // namespace rt
