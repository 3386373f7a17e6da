#include "core/assimp_loader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>
#include <glm/geometric.hpp>

#include "core/error.h"
#include "core/file_kind.h"
#include "core/ply_check.h"

namespace rt {
namespace {

struct Gathered {
    std::vector<glm::dvec3> positions;
    std::vector<glm::uvec3> triangles;
    std::vector<vec3> normals;  // per corner, zero where the mesh has none
    std::vector<vec3> colours;  // per corner, one where the mesh has none
    bool any_normals = false, any_colours = false;
};

void gather(const std::string& file, const aiMesh& m, Gathered& g) {
    const auto base = static_cast<std::uint32_t>(g.positions.size());
    for (unsigned v = 0; v < m.mNumVertices; ++v) {
        const aiVector3D& p = m.mVertices[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw Error(file, "vertex " + std::to_string(v), "a coordinate is not a finite number");
        g.positions.emplace_back(p.x, p.y, p.z);
    }
    const bool normals = m.HasNormals(), colours = m.HasVertexColors(0);
    g.any_normals = g.any_normals || normals;
    g.any_colours = g.any_colours || colours;
    for (unsigned f = 0; f < m.mNumFaces; ++f) {
        const aiFace& face = m.mFaces[f];
        if (face.mNumIndices != 3) continue;  // points and lines: the tracer renders surfaces
        glm::uvec3 tri;
        for (int k = 0; k < 3; ++k) {
            const unsigned i = face.mIndices[k];
            if (i >= m.mNumVertices)
                throw Error(file, "face " + std::to_string(f), "vertex index out of range");
            tri[k] = base + i;
            const vec3 n =
                normals ? vec3(m.mNormals[i].x, m.mNormals[i].y, m.mNormals[i].z) : vec3(0.0f);
            g.normals.push_back(
                std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z) ? n : vec3(0.0f));
            const aiColor4D c = colours ? m.mColors[0][i] : aiColor4D(1.0f, 1.0f, 1.0f, 1.0f);
            g.colours.push_back(glm::clamp(vec3(c.r, c.g, c.b), vec3(0.0f), vec3(1.0f)));
        }
        g.triangles.push_back(tri);
    }
}

// The file's bytes if it begins with a UTF-8 byte order mark, else nothing.
std::string utf8_bom_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    char mark[3] = {};
    if (!in.read(mark, 3) || mark[0] != '\xEF' || mark[1] != '\xBB' || mark[2] != '\xBF') return {};
    std::ostringstream all;
    all << in.rdbuf();
    return std::string(mark, 3) + all.str();
}

}  // namespace

MeshFile load_ply_stl(const std::filesystem::path& path, const MeshFileOptions& options) {
    const std::string file = path.string();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw Error(file, "open", "cannot open file (does it exist?)");
    const std::string bytes = utf8_bom_file(path);
    const std::string extension = lower_extension(path);  // ".ply" or ".stl"
    if (extension == ".ply") {
        std::ifstream in(path, std::ios::binary);
        if (!bytes.empty()) in.seekg(3);
        check_ply(file, in, std::filesystem::file_size(path, ec));
    }
    Assimp::Importer importer;
    // A text file saved with a UTF-8 byte order mark is still the file: Assimp's PLY
    // reader wants "ply" as its first bytes, so such a file is read from memory without
    // the mark (its format named by the extension).
    const aiScene* scene = bytes.empty()
                               ? importer.ReadFile(file, aiProcess_ValidateDataStructure)
                               : importer.ReadFileFromMemory(bytes.data() + 3, bytes.size() - 3,
                                                             aiProcess_ValidateDataStructure,
                                                             extension.substr(1).c_str());
    const auto parse_error = [&] {
        std::string what = importer.GetErrorString();
        std::replace(what.begin(), what.end(), '\n', ' ');
        return Error(file, "parse", what.empty() ? "not a readable PLY or STL file" : what);
    };
    if (!scene || !scene->mRootNode) throw parse_error();
    // A face without vertices (a PLY face list of length 0) passes Assimp's validation,
    // is counted a polygon, and stops the process in the triangulation (an assertion
    // that a mesh said to hold polygons holds one). Degenerate, not wrong: it becomes a
    // point at the first vertex, which gather() skips as it skips the file's own points,
    // and the mesh's primitive types are counted again from its faces.
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        aiMesh& mesh = *scene->mMeshes[m];
        unsigned types = 0;
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            aiFace& face = mesh.mFaces[f];
            if (face.mNumIndices == 0) {
                delete[] face.mIndices;
                face.mIndices = new unsigned[1]{0};
                face.mNumIndices = 1;
            }
            types |= face.mNumIndices == 1   ? aiPrimitiveType_POINT
                     : face.mNumIndices == 2 ? aiPrimitiveType_LINE
                     : face.mNumIndices == 3 ? aiPrimitiveType_TRIANGLE
                                             : aiPrimitiveType_POLYGON;
        }
        mesh.mPrimitiveTypes = types;
    }
    scene = importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_SortByPType);
    if (!scene) throw parse_error();
    Gathered g;
    for (unsigned i = 0; i < scene->mNumMeshes; ++i) gather(file, *scene->mMeshes[i], g);
    if (g.triangles.empty()) throw Error(file, "faces", "no triangles: nothing to render");

    MeshFile data;
    data.mesh.name = path.filename().string();
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::uvec3& t : g.triangles)
        for (int k = 0; k < 3; ++k) {
            lo = glm::min(lo, g.positions[t[k]]);
            hi = glm::max(hi, g.positions[t[k]]);
        }
    data.origin = mesh_origin(options, lo, hi);
    data.scale = mesh_scale(options, lo, hi);
    for (const glm::dvec3& p : g.positions)
        data.mesh.positions.push_back(vec3((p - data.origin) / data.scale));
    data.mesh.triangles = std::move(g.triangles);
    data.mesh.materials.assign(data.mesh.triangles.size(), kNoFileMaterial);
    if (g.any_colours) data.mesh.corner_colours = std::move(g.colours);
    if (g.any_normals) {
        for (std::size_t t = 0; t < data.mesh.triangles.size(); ++t) {
            const vec3 face = glm::normalize(data.mesh.face_normal(static_cast<std::uint32_t>(t)));
            for (int k = 0; k < 3; ++k) {
                const vec3 n = g.normals[3 * t + static_cast<std::size_t>(k)];
                data.mesh.corner_normals.push_back(glm::dot(n, n) > 0.0f ? glm::normalize(n)
                                                                         : face);
            }
        }
    }
    if (const std::size_t dropped = drop_duplicate_triangles(data.mesh))
        data.warnings.push_back(file + ": warning: " + std::to_string(dropped) +
                                " faces repeat an earlier face and were dropped");
    return data;
}

}  // namespace rt
