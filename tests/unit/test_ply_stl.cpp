// PLY and STL through Assimp (core/assimp_loader.h), on files tests/data/mesh/make.py
// wrote: one coloured octahedron as ASCII and binary PLY and as ASCII and binary STL.
#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>

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
            EXPECT_EQ(e.where(),
                      name == std::string("ply_truncated.ply") ? "element face" : "parse")
                << e.what();
        }
    }
}

// A PLY saved with a UTF-8 byte order mark is the same file. Cut short, or promising
// more than it holds, it gets one located error: before, a header without its end_header
// line hung Assimp's reader, a hundred million vertices declared over a few bytes kept it
// busy for minutes, and a file ending where its faces begin aborted the process.
TEST(PlyStl, AByteOrderMarkIsReadAndCutFilesAreRefused) {
    const auto dir = test::temp_dir("ply_bom");
    std::ifstream in(mesh("octahedron_ascii.ply"), std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const MeshFile plain = load_ply_stl(mesh("octahedron_ascii.ply"));
    const MeshFile marked = load_ply_stl(test::write_file(dir / "bom.ply", "\xEF\xBB\xBF" + text));
    EXPECT_EQ(marked.mesh.triangles, plain.mesh.triangles);
    EXPECT_EQ(marked.mesh.positions, plain.mesh.positions);

    const auto header = [](const std::string& vertices, const std::string& faces) {
        return "ply\nformat ascii 1.0\nelement vertex " + vertices +
               "\nproperty float x\nproperty float y\nproperty float z\nelement face " + faces +
               "\nproperty list uchar int vertex_indices\n";
    };
    const std::string corners = "0 0 0\n1 0 0\n0 1 0\n";
    const std::pair<std::string, std::string> cut[] = {
        {header("3", "1"), "line 8"},                                   // no end_header
        {"\xEF\xBB\xBF" + header("3", "1").substr(0, 30), "line 3"},    // the same, marked
        {"\xEF\xBB\xBF", "header"},                                     // nothing but the mark
        {header("3", "1") + "end_header\n" + corners, "element face"},  // no face line
        {header("100000000", "1") + "end_header\n" + corners + "3 0 1 2\n", "element vertex"},
    };
    for (const auto& [bytes, where] : cut) {
        try {
            load_ply_stl(test::write_file(dir / "cut.ply", bytes));
            ADD_FAILURE() << where << ": loaded";
        } catch (const Error& e) {
            EXPECT_EQ(e.where(), where) << e.what();
        }
    }
    // A face of no vertices is degenerate, not wrong: the other faces are the mesh.
    const MeshFile empty_face = load_ply_stl(test::write_file(
        dir / "empty_face.ply", header("3", "2") + "end_header\n" + corners + "0\n3 0 1 2\n"));
    EXPECT_EQ(empty_face.mesh.triangles.size(), 1u);
}

// A body cut short, a value that is not one, or a face naming a vertex the file does not
// have is one error at its line (ASCII) or element (binary), before Assimp reads it: Assimp took a
// cut ASCII file's faces as fewer faces, or made up a cut face's last index (exit 0, a silently
// wrong mesh), and gave a binary one's out-of-range indices as its own message with no place.
TEST(PlyStl, ACutOrMalformedBodyIsOneLocatedError) {
    const auto dir = test::temp_dir("ply_body");
    const auto header = [](const std::string& format, const std::string& count_type) {
        return "ply\nformat " + format +
               " 1.0\nelement vertex 3\nproperty float x\n"
               "property float y\nproperty float z\nelement face 2\nproperty list " +
               count_type + " int vertex_indices\nend_header\n";
    };
    const std::string ascii = header("ascii", "uchar");  // 9 lines
    const std::string corners = "0 0 0\n1 0 0\n0 1 0\n";
    const std::pair<std::string, std::string> bad[] = {
        {ascii + corners + "3 0 1 2\n", "line 14"},         // one face of two
        {ascii + corners + "3 0 1 2\n3 0 2\n", "line 14"},  // the last face a value short
        {ascii + corners + "3 0 1 2\n3 0 x 2\n", "line 14"},
        {ascii + "0 0 0\n1 0\n0 1 0\n3 0 1 2\n3 0 2 1\n", "line 11"},
        {ascii + corners + "-1 0 1 2\n3 0 2 1\n", "line 13"},
        {ascii + corners + "2.5 0 1 2\n3 0 2 1\n", "line 13"},
        {ascii + corners + "3 0 1 3\n3 0 2 1\n", "line 13"},   // no vertex 3
        {ascii + corners + "3 0 1 2\n3 0 -1 1\n", "line 14"},  // nor vertex -1
    };
    for (const auto& [bytes, where] : bad) {
        try {
            load_ply_stl(test::write_file(dir / "bad.ply", bytes));
            ADD_FAILURE() << where << ": loaded";
        } catch (const Error& e) {
            EXPECT_EQ(e.where(), where) << e.what();
        }
    }
    // Binary, in either byte order, with a two-byte list length: whole, it loads; cut
    // anywhere in its faces, it is one error at the faces.
    for (const bool big : {false, true}) {
        SCOPED_TRACE(big ? "big-endian" : "little-endian");
        std::string body;
        const auto put = [&](std::uint32_t bits, int bytes) {
            for (int k = 0; k < bytes; ++k) {
                const int shift = 8 * (big ? bytes - 1 - k : k);
                body += static_cast<char>((bits >> shift) & 0xffu);
            }
        };
        for (const float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) {
            std::uint32_t bits = 0;
            std::memcpy(&bits, &v, 4);
            put(bits, 4);
        }
        for (const auto& face : {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{0, 2, 1}}) {
            put(3, 2);
            for (const int i : face) put(static_cast<std::uint32_t>(i), 4);
        }
        const std::string head =
            header(big ? "binary_big_endian" : "binary_little_endian", "ushort");
        const std::string whole = head + body;
        EXPECT_EQ(load_ply_stl(test::write_file(dir / "whole.ply", whole)).mesh.triangles.size(),
                  2u);
        for (std::size_t cut = 1; cut <= 2 * 14; ++cut) {
            try {
                load_ply_stl(
                    test::write_file(dir / "cut.ply", whole.substr(0, whole.size() - cut)));
                ADD_FAILURE() << cut << " bytes short: loaded";
            } catch (const Error& e) {
                EXPECT_EQ(e.where(), "element face") << e.what();
            }
        }
        // The last face's last index turned into 3: a vertex the file does not have.
        std::string past = whole;
        past[big ? past.size() - 1 : past.size() - 4] = 3;
        try {
            load_ply_stl(test::write_file(dir / "past.ply", past));
            ADD_FAILURE() << "a face naming vertex 3 of 3 loaded";
        } catch (const Error& e) {
            EXPECT_EQ(e.detail(),
                      "face 2 of the 2 names vertex 3, not one of the 3 (counted from 0)");
        }
    }
}

}  // namespace
}  // namespace rt
