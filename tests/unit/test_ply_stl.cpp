// PLY and STL through Assimp (core/assimp_loader.h), on files tests/data/mesh/make.py
// wrote: one coloured octahedron as ASCII and binary PLY and as ASCII and binary STL.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "core/assimp_loader.h"
#include "core/error.h"
#include "core/scene_loader.h"
#include "test_util.h"

namespace rt {
namespace {

std::filesystem::path mesh(const std::string& name) {
    return test::source_dir() / "tests" / "data" / "mesh" / name;
}

// Both PLY encodings give the same octahedron, with the file's colour at each corner
// (red where the vertex is (1, 0, 0)) and its normals.
TEST(PlyStl, PlyAsciiAndBinaryWithColoursAndNormals) {
    const MeshFile ascii = load_ply_stl(mesh("octahedron_ascii.ply"));
    const MeshFile binary = load_ply_stl(mesh("octahedron_binary.ply"));
    for (const MeshFile* m : {&ascii, &binary}) {
        ASSERT_EQ(m->mesh.triangles.size(), 8u);
        ASSERT_EQ(m->mesh.corner_colours.size(), 24u);
        ASSERT_EQ(m->mesh.corner_normals.size(), 24u);
        for (std::size_t c = 0; c < 24; ++c) {
            const vec3 p = m->mesh.positions[m->mesh.triangles[c / 3][static_cast<int>(c % 3)]];
            EXPECT_NEAR(glm::dot(m->mesh.corner_normals[c], p), 1.0f, 1e-5f);  // the normal is p
            if (p.x > 0.5f) {
                EXPECT_EQ(m->mesh.corner_colours[c], vec3(1, 0, 0));
            }
        }
    }
    EXPECT_EQ(ascii.mesh.corner_colours, binary.mesh.corner_colours);
}

// Both STL encodings: the same eight facets, flat (each corner the facet's normal), no colour.
TEST(PlyStl, StlAsciiAndBinaryAreFlat) {
    const MeshFile ascii = load_ply_stl(mesh("octahedron_ascii.stl"));
    const MeshFile binary = load_ply_stl(mesh("octahedron_binary.stl"));
    for (const MeshFile* m : {&ascii, &binary}) {
        ASSERT_EQ(m->mesh.triangles.size(), 8u);
        EXPECT_TRUE(m->mesh.corner_colours.empty());
        for (std::uint32_t t = 0; t < 8; ++t)
            for (int k = 0; k < 3; ++k)
                EXPECT_NEAR(glm::dot(m->mesh.corner_normals[3 * t + static_cast<std::uint32_t>(k)],
                                     glm::normalize(m->mesh.face_normal(t))),
                            1.0f, 1e-5f);
    }
    for (std::uint32_t t = 0; t < 8; ++t)
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(ascii.mesh.positions[ascii.mesh.triangles[t][k]],
                      binary.mesh.positions[binary.mesh.triangles[t][k]]);
}

// A bare PLY is a scene (framed and lit like an OBJ); a JSON scene may name one as a mesh.
TEST(PlyStl, ScenesOfPlyAndStl) {
    const LoadedScene ply = load_scene(mesh("octahedron_binary.ply"));
    ASSERT_EQ(ply.scene.meshes.size(), 1u);
    EXPECT_EQ(ply.scene.lights.size(), 2u);
    const LoadedScene stl =
        load_scene(mesh("octahedron_ascii.stl"), LoadOptions{.up = "z", .camera = {}});
    EXPECT_EQ(stl.scene.meshes[0].triangles.size(), 8u);
    const auto bad = test::source_dir() / "tests" / "data" / "bad";
    for (const char* name : {"ply_truncated.ply", "stl_truncated.stl"}) {
        try {
            load_scene(bad / name);
            ADD_FAILURE() << name << " loaded";
        } catch (const Error& e) {
            EXPECT_EQ(e.where(), "parse") << e.what();
        }
    }
}

}  // namespace
}  // namespace rt
