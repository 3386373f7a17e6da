// glTF 2.0 through core/gltf_loader.h: Khronos' sample models (tests/data/gltf/khronos,
// licences in its README) and hand-made files (tests/data/gltf/make.py writes them).
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "core/compare.h"
#include "core/error.h"
#include "core/gltf_loader.h"
#include "core/renderer.h"
#include "core/scene.h"
#include "core/scene_loader.h"
#include "test_util.h"

namespace rt {
namespace {

std::filesystem::path gltf(const std::string& name) {
    return test::source_dir() / "tests" / "data" / "gltf" / name;
}

std::string error_of(const std::filesystem::path& path) {
    try {
        load_scene(path);
    } catch (const Error& e) {
        return e.where();
    }
    return "no error";
}

// A node hierarchy with a rotation, a non-uniform scale, a translation and a matrix,
// against the same triangles placed by the JSON format's own transforms (with the
// material mapping's Phong terms written out): the traced images agree.
TEST(Gltf, HierarchyRendersAsTheSameSceneWrittenAsJson) {
    const auto image = [](const char* name) {
        LoadedScene loaded = load_scene(gltf(name));
        EXPECT_TRUE(loaded.warnings.empty()) << loaded.warnings.front();
        return render(Scene(std::move(loaded.scene)), RenderOptions{});
    };
    const Image written = image("hierarchy_written.json");
    const Image referenced = image("hierarchy_referenced.json");
    const ImageDiff d = compare_images(written, referenced, 1.0 / 255.0);
    EXPECT_EQ(d.pixels_over, 0u) << "max " << d.max_error;
    // Not two empty pictures: both objects cover pixels.
    std::size_t lit = 0;
    for (const vec3& p : written.pixels) lit += p.x > 0.1f;
    EXPECT_GT(lit, 300u);
}

TEST(Gltf, BinaryAndTextFilesHoldTheSameScene) {
    for (const auto& [text, binary] : {std::pair{gltf("hierarchy.gltf"), gltf("hierarchy.glb")},
                                       std::pair{gltf("khronos/BoxTextured/BoxTextured.gltf"),
                                                 gltf("khronos/BoxTextured.glb")}}) {
        const GltfScene a = load_gltf(text), b = load_gltf(binary);
        ASSERT_GT(a.geometry.mesh.triangles.size(), 0u) << text;
        EXPECT_EQ(a.geometry.mesh.positions, b.geometry.mesh.positions) << text;
        EXPECT_EQ(a.geometry.mesh.triangles, b.geometry.mesh.triangles) << text;
        EXPECT_EQ(a.geometry.mesh.corner_normals, b.geometry.mesh.corner_normals) << text;
        EXPECT_EQ(a.geometry.materials.size(), b.geometry.materials.size()) << text;
    }
}

// Khronos' cube: 12 triangles with the file's normals, one material. BoxTextured's node
// matrix turns its box (y up becomes z): its bounds are those of a unit cube either way.
TEST(Gltf, SampleModelsLoad) {
    const GltfScene cube = load_gltf(gltf("khronos/Cube/Cube.gltf"));
    EXPECT_EQ(cube.geometry.mesh.triangles.size(), 12u);
    EXPECT_EQ(cube.geometry.mesh.corner_normals.size(), 36u);
    ASSERT_EQ(cube.geometry.materials.size(), 1u);
    EXPECT_EQ(cube.geometry.materials[0].name, "Cube");
    for (const vec3& n : cube.geometry.mesh.corner_normals)
        EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
    const GltfScene box = load_gltf(gltf("khronos/BoxTextured/BoxTextured.gltf"));
    EXPECT_EQ(box.geometry.mesh.triangles.size(), 12u);
    const Aabb b = bounds_of(box.geometry.mesh);
    EXPECT_NEAR(b.extent().x, 1.0f, 1e-5f);
    EXPECT_NEAR(b.extent().y, 1.0f, 1e-5f);
    EXPECT_NEAR(b.extent().z, 1.0f, 1e-5f);
}

// Cameras.gltf has a perspective and an orthographic camera: the first is looked
// through (its node's place, looking down its -z), the second is named in a warning.
TEST(Gltf, TheFilesCameraIsLookedThrough) {
    const GltfScene g = load_gltf(gltf("khronos/Cameras/Cameras.gltf"));
    ASSERT_EQ(g.cameras.size(), 1u);
    EXPECT_NEAR(g.cameras[0].eye.z, 3.0f, 1e-5f);  // nodes/1: translation (0.5, 0.5, 3)
    EXPECT_NEAR(g.cameras[0].forward.z, -1.0f, 1e-5f);
    EXPECT_NEAR(g.cameras[0].yfov_degrees, 40.107f, 1e-3f);  // 0.7 radians
    ASSERT_EQ(g.geometry.warnings.size(), 1u);
    EXPECT_NE(g.geometry.warnings[0].find("orthographic"), std::string::npos);
    const LoadedScene s = load_scene(gltf("khronos/Cameras/Cameras.gltf"));
    EXPECT_EQ(s.scene.camera.eye, g.cameras[0].eye);
    EXPECT_NEAR(glm::dot(-s.scene.camera.n, g.cameras[0].forward), 1.0f, 1e-6f);
    EXPECT_NEAR(static_cast<float>(s.scene.camera.cols) / static_cast<float>(s.scene.camera.rows),
                1.0f, 1e-3f);  // its aspectRatio
    try {
        load_scene(gltf("khronos/Cameras/Cameras.gltf"), LoadOptions{.up = "y", .camera = 1});
        FAIL() << "no camera 1";
    } catch (const Error& e) {
        EXPECT_EQ(e.where(), "--camera");
    }
}

// docs/scene-format.md's table: a dielectric is its base colour with a 4 % highlight; a
// metal mirrors (1 - roughness) of the light and scatters the rest in its colour.
TEST(Gltf, MaterialsMapOntoPhongAsDocumented) {
    const GltfScene g = load_gltf(gltf("hierarchy.gltf"));
    ASSERT_EQ(g.geometry.materials.size(), 2u);
    const Material& plastic = g.geometry.materials[0];
    EXPECT_EQ(plastic.name, "red plastic");
    EXPECT_NEAR(plastic.kd.x, 0.8f, 1e-6f);
    EXPECT_NEAR(plastic.ks.x, 0.04f, 1e-6f);
    EXPECT_NEAR(plastic.shininess, 30.0f, 1e-3f);  // alpha = 0.5^2: 2 / alpha^2 - 2
    EXPECT_EQ(plastic.reflectivity, 0.0f);
    const Material& gold = g.geometry.materials[1];
    EXPECT_NEAR(gold.reflectivity, 0.6f, 1e-6f);
    EXPECT_NEAR(gold.kd.y, 0.8f * 0.4f, 1e-6f);
    EXPECT_NEAR(gold.ks.z, 0.3f, 1e-6f);
    // The square has normals, the tetrahedron none: its corners take the face's normal.
    const TriangleMesh& m = g.geometry.mesh;
    ASSERT_EQ(m.triangles.size(), 6u);
    for (std::uint32_t t = 2; t < 6; ++t)
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(glm::dot(m.corner_normals[3 * t + static_cast<std::uint32_t>(k)],
                                 glm::normalize(m.face_normal(t))),
                        1.0f, 1e-5f);
}

// Point, directional and spot (as a point) lights at their nodes; their colours keep the
// relative strengths seen from the mesh, the brightest at its own colour.
TEST(Gltf, PunctualLightsBecomeTheScenesLights) {
    const LoadedScene s = load_scene(gltf("lights.gltf"));
    ASSERT_EQ(s.scene.lights.size(), 3u);
    const Light& point = s.scene.lights[0];
    const Light& sun = s.scene.lights[1];
    EXPECT_EQ(point.type, Light::Type::kPoint);
    EXPECT_NEAR(point.position.y, 10.0f, 1e-5f);
    EXPECT_EQ(sun.type, Light::Type::kDirectional);
    EXPECT_NEAR(sun.direction.y, -1.0f, 1e-5f);  // -z turned 90 degrees about x
    const float brightest = std::max({point.colour.x, sun.colour.x, s.scene.lights[2].colour.x});
    EXPECT_NEAR(brightest, 1.0f, 1e-6f);
    EXPECT_NEAR(point.colour.y / point.colour.x, 0.5f, 1e-6f);  // its colour's hue kept
    ASSERT_EQ(s.warnings.size(), 2u);  // the unknown extension, the spot light
    EXPECT_NE(s.warnings[0].find("EXT_unknown_for_the_test"), std::string::npos);
}

// COLOR_0 (normalised RGBA bytes here) becomes each corner's colour; a primitive without
// it is white.
TEST(Gltf, VertexColoursAreReadPerCorner) {
    const GltfScene g = load_gltf(gltf("colours.gltf"));
    const TriangleMesh& m = g.geometry.mesh;
    ASSERT_EQ(m.corner_colours.size(), 3 * m.triangles.size());
    // The square's first triangle is vertices 0, 1, 2: red, green, blue.
    EXPECT_EQ(m.corner_colours[0], vec3(1, 0, 0));
    EXPECT_EQ(m.corner_colours[1], vec3(0, 1, 0));
    EXPECT_EQ(m.corner_colours[2], vec3(0, 0, 1));
    for (std::size_t c = 6; c < m.corner_colours.size(); ++c)
        EXPECT_EQ(m.corner_colours[c], vec3(1.0f)) << c;  // the tetrahedron has none
    EXPECT_TRUE(load_gltf(gltf("hierarchy.gltf")).geometry.mesh.corner_colours.empty());
}

// Broken files: one located error each (tests/cli/bad_input.sh checks the programs say so).
TEST(Gltf, BrokenFilesAreLocatedErrors) {
    const auto bad = test::source_dir() / "tests" / "data" / "bad";
    EXPECT_EQ(error_of(bad / "gltf_accessor_out_of_range.gltf").rfind("/accessors/0", 0), 0u);
    EXPECT_EQ(error_of(bad / "gltf_index_out_of_range.gltf").rfind("/accessors/4", 0), 0u);
    EXPECT_EQ(error_of(bad / "gltf_node_cycle.gltf").rfind("/nodes/", 0), 0u);
    EXPECT_EQ(error_of(bad / "gltf_required_extension.gltf").rfind("/extensionsRequired", 0), 0u);
    EXPECT_EQ(error_of(bad / "gltf_missing_buffer.gltf").rfind("load", 0), 0u);
    EXPECT_EQ(error_of(bad / "gltf_truncated.glb").rfind("load", 0), 0u);
}

}  // namespace
}  // namespace rt
