// OBJ + MTL through tinyobjloader: triangulation, normals, materials, and located errors.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "core/obj_loader.h"
#include "core/scene_loader.h"
#include "test_util.h"

namespace rt {
namespace {

TEST(Obj, CornellBoxQuadsAreTriangulatedAndMtlIsMapped) {
    const MeshFile obj = load_obj(test::source_dir() / "assets/models/cornell_box.obj");
    EXPECT_EQ(obj.mesh.triangles.size(), 36u);  // 18 quads
    ASSERT_EQ(obj.materials.size(), 5u);
    const auto light = std::find_if(obj.materials.begin(), obj.materials.end(),
                                    [](const Material& m) { return m.name == "light"; });
    ASSERT_NE(light, obj.materials.end());
    EXPECT_FLOAT_EQ(light->ka.x, 20.0f);
    const auto red = std::find_if(obj.materials.begin(), obj.materials.end(),
                                  [](const Material& m) { return m.name == "red"; });
    EXPECT_FLOAT_EQ(red->kd.x, 1.0f);
    EXPECT_FLOAT_EQ(red->kd.y, 0.0f);
    for (std::uint32_t m : obj.mesh.materials) EXPECT_LT(m, obj.materials.size());
}

TEST(Obj, MissingNormalsAreComputedSmoothButCreased) {
    const auto dir = test::temp_dir("normals");
    // A unit cube, 6 quads, no normals: every corner normal must be its face's normal
    // (90 degree edges are creases), all unit length.
    const auto path =
        test::write_file(dir / "cube.obj",
                         "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                         "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n");
    const MeshFile obj = load_obj(path);
    ASSERT_EQ(obj.mesh.triangles.size(), 12u);
    ASSERT_EQ(obj.mesh.corner_normals.size(), 36u);
    for (std::uint32_t t = 0; t < 12; ++t) {
        const vec3 face = glm::normalize(obj.mesh.face_normal(t));
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(glm::dot(obj.mesh.corner_normals[3 * t + k], face), 1.0f, 1e-5f);
    }
}

// Around a cone's apex each corner's normal is the area-weighted sum of the faces there
// within the crease angle of its own, normalised: with a few faces (the directions
// searched) and with many (a hash map of them) alike. Half the slices are repeated
// (the same direction twice), so directions are merged.
TEST(Obj, ConeApexNormalsSumTheFacesWithinTheCrease) {
    for (int slices : {6, 20, 40, 100}) {
        TriangleMesh mesh;
        mesh.positions.push_back({0.0f, 3.0f, 0.0f});  // the apex of a tall cone
        for (int i = 0; i < slices; ++i) {
            const float a = 2.0f * std::numbers::pi_v<float> * static_cast<float>(i) /
                            static_cast<float>(slices);
            mesh.positions.push_back({std::cos(a), 0.0f, std::sin(a)});
        }
        for (int i = 0; i < slices; ++i) {
            const auto b = static_cast<std::uint32_t>(1 + i);
            const auto c = static_cast<std::uint32_t>(1 + (i + 1) % slices);
            mesh.triangles.push_back({0, c, b});
            if (i % 2 == 0) mesh.triangles.push_back({0, c, b});
        }
        compute_corner_normals(mesh, 60.0f);
        const float cos_crease = std::cos(60.0f * std::numbers::pi_v<float> / 180.0f);
        for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
            const vec3 own = glm::normalize(mesh.face_normal(t));
            vec3 sum(0.0f);
            for (std::uint32_t u = 0; u < mesh.triangles.size(); ++u)
                if (glm::dot(own, glm::normalize(mesh.face_normal(u))) >= cos_crease)
                    sum += mesh.face_normal(u);
            const vec3 expected = glm::normalize(sum), got = mesh.corner_normals[3 * t];
            EXPECT_NEAR(glm::distance(got, expected), 0.0f, 1e-5f)
                << slices << " slices, face " << t;
        }
    }
}

TEST(Obj, SmoothSurfacesGetAveragedNormals) {
    const MeshFile obj = load_obj(test::source_dir() / "assets/models/teapot.obj");
    ASSERT_EQ(obj.mesh.corner_normals.size(), 3 * obj.mesh.triangles.size());
    int smoothed = 0;
    for (std::uint32_t t = 0; t < obj.mesh.triangles.size(); ++t) {
        const vec3 face = glm::normalize(obj.mesh.face_normal(t));
        if (glm::dot(obj.mesh.corner_normals[3 * t], face) < 0.9999f) ++smoothed;
    }
    EXPECT_GT(smoothed, static_cast<int>(obj.mesh.triangles.size() / 2));
}

TEST(Obj, BareObjSceneIsFramedAndLit) {
    LoadedScene loaded = load_scene(test::source_dir() / "assets/models/teapot.obj");
    SceneDescription& desc = loaded.scene;
    const Scene s(std::move(desc));
    EXPECT_EQ(s.lights.size(), 2u);
    const Aabb b = s.bounds();
    const glm::mat4 clip = s.camera.projection(1e4f) * s.camera.view();
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec4 c = clip * glm::vec4(b.corner(corner), 1.0f);
        EXPECT_LT(std::fabs(c.x / c.w), 1.0f) << corner;
        EXPECT_LT(std::fabs(c.y / c.w), 1.0f) << corner;
    }
}

void expect_obj_error(const std::string& name, const std::string& text, const std::string& where,
                      const std::string& detail) {
    const auto path = test::write_file(test::temp_dir("obj_" + name) / (name + ".obj"), text);
    try {
        load_obj(path);
        FAIL() << name << " loaded";
    } catch (const Error& e) {
        EXPECT_EQ(e.file(), path.string());
        EXPECT_EQ(e.where(), where) << e.what();
        EXPECT_NE(e.detail().find(detail), std::string::npos) << e.what();
    }
}

TEST(Obj, BadFilesGiveLocatedErrors) {
    expect_obj_error("out_of_range", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n\nf 1 2 4\n", "line 6",
                     "face index 4 is out of range (the file has 3 vertices)");
    expect_obj_error("negative_out_of_range", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -7\n", "line 4",
                     "out of range");
    expect_obj_error("nan", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", "line 2",
                     "\"nan\" is not a finite");
    expect_obj_error("inf", "v 0 0 0\nv 1 0 0\nv 0 1e999 0\nf 1 2 3\n", "line 3",
                     "\"1e999\" is not a finite");
    expect_obj_error("zero_index", "# a comment\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 0 1 2\n",
                     "line 6", "face index 0 (OBJ indices start at 1)");
    expect_obj_error("two_corners", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n", "line 4",
                     "a face needs at least 3 vertices, this one has 2");
    expect_obj_error("garbage_index", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 x 3\n", "line 4",
                     "face vertex \"x\" is not an index");
    expect_obj_error("only_vertices", "v 0 0 0\nv 1 0 0\n", "faces", "no faces, lines or points");
    expect_obj_error("empty", "", "faces", "no faces, lines or points");
}

// The line check splits tokens as a stream's >> does: tabs, runs of spaces and the CR of
// CRLF lines separate them and are no part of them.
TEST(Obj, TabsRunsOfSpacesAndCrlfSeparateTokens) {
    const auto dir = test::temp_dir("obj_space");
    const auto path =
        test::write_file(dir / "ok.obj", "v\t0  0\t\t0\r\nv 1 0 0 \r\nv   0 1 0\r\nf 1\t2   3\r\n");
    EXPECT_EQ(load_obj(path).mesh.triangles.size(), 1u);
    expect_obj_error("crlf_nan", "v 0 0 0\r\nv 1\tnan\t0\r\nv 0 1 0\r\nf 1 2 3\r\n", "line 2",
                     "coordinate \"nan\" is not a finite");
    expect_obj_error("crlf_index", "v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 x\r\n", "line 4",
                     "face vertex \"x\" is not an index");
}

// A byte-order mark before the first line (some Windows editors write one) is skipped:
// the mtllib on that line still names the materials.
TEST(Obj, ByteOrderMarkIsSkippedInObjAndMtl) {
    const auto dir = test::temp_dir("obj_bom");
    test::write_file(dir / "bom.mtl", "\xEF\xBB\xBFnewmtl red\nKd 1 0 0\n");
    const auto path = test::write_file(
        dir / "bom.obj",
        "\xEF\xBB\xBFmtllib bom.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n");
    const MeshFile obj = load_obj(path);
    ASSERT_EQ(obj.materials.size(), 1u);
    EXPECT_EQ(obj.materials[0].name, "red");
    EXPECT_EQ(obj.materials[0].kd, vec3(1.0f, 0.0f, 0.0f));
    ASSERT_EQ(obj.mesh.materials.size(), 1u);
    EXPECT_EQ(obj.mesh.materials[0], 0u);
    EXPECT_TRUE(obj.warnings.empty());
}

// Found by fuzzing: "mtllib" with no name (or naming a directory) made the material
// reader read a directory, which threw from deep inside the stream library.
TEST(Obj, MtllibNamingADirectoryIsAWarning) {
    const auto dir = test::temp_dir("obj_mtldir");
    std::filesystem::create_directories(dir / "sub");
    for (const char* line : {"mtllib \n", "mtllib sub\n", "mtllib sub \n"}) {
        const auto path = test::write_file(
            dir / "m.obj", std::string(line) + "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        const MeshFile obj = load_obj(path);
        EXPECT_EQ(obj.mesh.triangles.size(), 1u) << line;
        EXPECT_FALSE(obj.warnings.empty()) << line;
    }
}

// Lines and points are the raster view's alone: a file of only them loads (polylines
// become segments), and one warning line says the tracer does not see them.
TEST(Obj, LinesAndPointsLoadWithOneWarning) {
    const auto path = test::write_file(test::temp_dir("obj_lines") / "l.obj",
                                       "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nl 1 2 3\np 1\nl 3 9\n");
    const MeshFile obj = load_obj(path);
    EXPECT_EQ(obj.mesh.triangles.size(), 1u);
    EXPECT_EQ(obj.mesh.segments, (std::vector<glm::uvec2>{{0, 1}, {1, 2}}));  // 3-9: out of range
    EXPECT_EQ(obj.mesh.points, (std::vector<std::uint32_t>{0}));
    ASSERT_EQ(obj.warnings.size(), 1u);
    EXPECT_NE(
        obj.warnings[0].find("2 line segments and 1 points are drawn by the raster view only"),
        std::string::npos);
    const auto only = test::write_file(test::temp_dir("obj_only_lines") / "o.obj",
                                       "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\n");
    const MeshFile lines = load_obj(only);
    EXPECT_TRUE(lines.mesh.triangles.empty());
    EXPECT_EQ(lines.mesh.segments.size(), 1u);
    EXPECT_EQ(bounds_of(lines.mesh).hi, vec3(1.0f, 0.0f, 0.0f));
}

TEST(Obj, RelativeIndicesWork) {
    const auto path = test::write_file(test::temp_dir("relative") / "r.obj",
                                       "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n");
    const MeshFile obj = load_obj(path);
    ASSERT_EQ(obj.mesh.triangles.size(), 1u);
    EXPECT_EQ(obj.mesh.triangles[0], glm::uvec3(0, 1, 2));
}

TEST(Obj, MissingMtlIsAWarningNotAnError) {
    const auto path = test::write_file(test::temp_dir("nomtl") / "m.obj",
                                       "mtllib gone.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const MeshFile obj = load_obj(path);
    EXPECT_EQ(obj.mesh.triangles.size(), 1u);
    EXPECT_FALSE(obj.warnings.empty());
}

}  // namespace
}  // namespace rt

namespace rt {
namespace {

// A million faces on the same three vertices, without normals: the smooth normals used
// to take time in the square of the faces around a vertex (80k faces: 27 s); now the
// repeats are dropped with one warning and the load is linear. A quadratic load would
// run into the test's time-out rather than pass.
TEST(Obj, MillionFacesOnOneTriangleLoadInLinearTime) {
    std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    for (int i = 0; i < 1000000; ++i) text += "f 1 2 3\n";
    const auto path = test::write_file(test::temp_dir("obj_valence") / "v.obj", text);
    const MeshFile obj = load_obj(path);
    EXPECT_EQ(obj.mesh.triangles.size(), 1u);
    ASSERT_EQ(obj.warnings.size(), 1u);
    EXPECT_NE(obj.warnings[0].find("999999 faces repeat"), std::string::npos);
}

// A cone of 200,000 slivers around one apex: 200,000 distinct face directions meet
// there. Past 256 directions the apex's corners take their own face normal (flat), so
// the work stays linear; the rim's corners are still smoothed.
TEST(Obj, HighValenceApexStaysLinearAndDefined) {
    constexpr int kSides = 200000;
    std::string text = "v 0 1 0\n";
    for (int i = 0; i < kSides; ++i) {
        const double a = 2.0 * 3.141592653589793 * i / kSides;
        text += "v " + std::to_string(std::cos(a)) + " 0 " + std::to_string(std::sin(a)) + "\n";
    }
    for (int i = 0; i < kSides; ++i)
        text += "f 1 " + std::to_string(2 + (i + 1) % kSides) + " " + std::to_string(2 + i) + "\n";
    const auto path = test::write_file(test::temp_dir("obj_apex") / "cone.obj", text);
    const MeshFile obj = load_obj(path);
    ASSERT_EQ(obj.mesh.corner_normals.size(), 3u * obj.mesh.triangles.size());
    for (std::size_t t = 0; t < obj.mesh.triangles.size(); t += 997) {
        const vec3 own = glm::normalize(obj.mesh.face_normal(static_cast<std::uint32_t>(t)));
        EXPECT_NEAR(glm::dot(obj.mesh.corner_normals[3 * t], own), 1.0f, 1e-5f);  // the apex
        EXPECT_NEAR(glm::length(obj.mesh.corner_normals[3 * t + 1]), 1.0f, 1e-5f);
    }
}

// Duplicates are recognised whichever corner a face starts from, and a face wound the
// other way (its back) is kept.
TEST(Obj, RepeatedFacesAreDroppedWindingKept) {
    TriangleMesh mesh;
    mesh.positions = {vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 0)};
    mesh.triangles = {{0, 1, 2}, {1, 2, 0}, {2, 1, 0}, {3, 1, 2}, {0, 1, 2}};
    mesh.materials = {5, 6, 7, 8, 9};
    EXPECT_EQ(drop_duplicate_triangles(mesh), 3u);  // {1,2,0}, {3,1,2} (welded), {0,1,2}
    ASSERT_EQ(mesh.triangles.size(), 2u);
    EXPECT_EQ(mesh.triangles[1], glm::uvec3(2, 1, 0));
    EXPECT_EQ(mesh.materials, (std::vector<std::uint32_t>{5, 7}));
}

// Positions weld by ==: -0 is 0, so a face over the negative zeros repeats one over the
// zeros; the first of equal positions in any order; a NaN position (no loader lets one
// through, but a mesh built in code may) welds to nothing and breaks nothing.
TEST(Obj, PositionsWeldAsEqualNumbers) {
    TriangleMesh mesh;
    mesh.positions = {vec3(1, 0, 0), vec3(0, 1, 0), vec3(-0.0f, 0, -0.0f),
                      vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0)};
    mesh.triangles = {{3, 0, 1}, {2, 4, 5}, {0, 5, 2}};
    EXPECT_EQ(drop_duplicate_triangles(mesh), 2u);
    ASSERT_EQ(mesh.triangles.size(), 1u);
    EXPECT_EQ(mesh.triangles[0], glm::uvec3(3, 0, 1));

    const float nan = std::numeric_limits<float>::quiet_NaN();
    mesh.positions = {vec3(0, 0, 0),   vec3(1, 0, 0), vec3(0, 1, 0),
                      vec3(nan, 0, 0), vec3(0, 0, 0), vec3(nan, 0, 0)};
    mesh.triangles = {{0, 1, 2}, {4, 1, 2}, {3, 1, 2}, {5, 1, 2}};
    EXPECT_EQ(drop_duplicate_triangles(mesh), 1u);  // {4,1,2}; the NaN faces are distinct
    EXPECT_EQ(mesh.triangles.size(), 3u);
}

}  // namespace
}  // namespace rt
