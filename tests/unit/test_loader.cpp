// The JSON scene format: what loads, and one located error for each kind of mistake.
#include <gtest/gtest.h>

#include "core/error.h"
#include "core/scene_loader.h"
#include "test_util.h"

namespace rt {
namespace {

TEST(Loader, AssetScenesLoadWithoutWarnings) {
    for (const char* name :
         {"tutorial.json", "whitted.json", "cornell.json", "many_spheres.json"}) {
        const LoadedScene loaded = load_scene(test::scene_path(name));
        EXPECT_TRUE(loaded.warnings.empty()) << name;
        EXPECT_FALSE(loaded.scene.objects.empty()) << name;
        EXPECT_FALSE(loaded.scene.lights.empty()) << name;
    }
    EXPECT_GE(load_scene(test::scene_path("many_spheres.json")).scene.objects.size(), 1000u);
}

TEST(Loader, ReadsEveryFieldOfTheDefaultScene) {
    const Scene s(load_scene(test::scene_path("whitted.json")).scene);
    EXPECT_EQ(s.camera.cols, 640);
    EXPECT_EQ(s.lights.size(), 2u);
    const auto& floor = s.materials[s.objects[0].material];
    EXPECT_EQ(floor.name, "floor");
    ASSERT_TRUE(floor.checker);
    EXPECT_FLOAT_EQ(floor.checker->scale, 1.0f);
    const auto& glass = s.materials[s.objects[2].material];
    EXPECT_FLOAT_EQ(glass.ior, 1.5f);
    EXPECT_FLOAT_EQ(glass.transparency, 0.9f);
    EXPECT_TRUE(s.objects[3].transform.has_value());  // the ellipsoid
    EXPECT_TRUE(std::holds_alternative<MeshRef>(s.objects[4].shape));
}

TEST(Loader, TransformListsApplyInOrder) {
    const auto dir = test::temp_dir("order");
    const auto path = test::write_file(dir / "s.json", R"({
      "camera": {"eye": [0,0,5], "look_at": [0,0,0]},
      "objects": [{"type": "sphere", "transform": [{"translate": [1,0,0]}, {"scale": 2}]}]})");
    const Scene s(load_scene(path).scene);
    const glm::vec4 centre = s.objects[0].transform->m * glm::vec4(0, 0, 0, 1);
    EXPECT_FLOAT_EQ(centre.x, 2.0f);  // translated first, then scaled
}

struct BadCase {
    std::string name;
    std::string json;
    std::string where;   // expected WHERE part
    std::string detail;  // expected in the WHAT part
};

void PrintTo(const BadCase& c, std::ostream* os) { *os << c.name; }

class BadScene : public ::testing::TestWithParam<BadCase> {};

constexpr const char* kCamera = R"("camera": {"eye": [0,0,5], "look_at": [0,0,0]})";

std::string with_camera(const char* rest) { return std::string("{") + kCamera + ", " + rest + "}"; }

TEST_P(BadScene, NamesTheFileThePlaceAndTheProblem) {
    const BadCase& c = GetParam();
    const auto dir = test::temp_dir("bad_" + c.name);
    test::write_file(dir / "box.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
    const auto path = test::write_file(dir / "scene.json", c.json);
    try {
        load_scene(path);
        FAIL() << "loaded without error";
    } catch (const Error& e) {
        EXPECT_NE(e.file().find(".json"), std::string::npos) << e.what();
        EXPECT_EQ(e.where().rfind(c.where, 0), 0u)
            << "where should start with " << c.where << ": " << e.what();
        EXPECT_NE(e.detail().find(c.detail), std::string::npos) << e.what();
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line";
    }
}

const std::vector<BadCase> kBadCases = {
    {"syntax", "{\n  \"camera\": {\n    \"eye\": [0, 0 5]\n", "line 3, column 18", "syntax error"},
    {"empty", "  \n", "line 1", "empty"},
    {"unknown_top_key", R"({"camera": {}, "objets": []})", "/objets", "did you mean \"objects\""},
    {"misspelt_material_key",
     with_camera(R"("materials": {"m": {"reflectivty": 0.5}}, "objects": [])"),
     "/materials/m/reflectivty", "did you mean \"reflectivity\""},
    {"unknown_object", with_camera(R"("objects": [{"type": "cube"}])"), "/objects/0/type",
     "unknown object type"},
    {"negative_radius", with_camera(R"("objects": [{"type": "sphere", "radius": -1}])"),
     "/objects/0/radius", "must be > 0"},
    {"radius_string", with_camera(R"("objects": [{"type": "sphere", "radius": "big"}])"),
     "/objects/0/radius", "expected a number"},
    {"zero_up", R"({"camera": {"eye": [0,0,5], "look_at": [0,0,0], "up": [0,0,0]}, "objects": []})",
     "/camera/up", "non-zero"},
    {"up_parallel",
     R"({"camera": {"eye": [0,0,5], "look_at": [0,0,0], "up": [0,0,2]}, "objects": []})",
     "/camera/up", "parallel"},
    {"singular",
     with_camera(R"("objects": [{"type": "sphere", "transform": {"scale": [1, 0, 1]}}])"),
     "/objects/0/transform", "singular"},
    {"huge_number", with_camera(R"("objects": [{"type": "sphere", "center": [1e999, 0, 0]}])"),
     "line 1, column 92", "number overflow"},
    // The same characters earlier in a name are not the number.
    {"huge_number_after_name",
     "{\"camera\": {\"eye\": [0,0,5], \"look_at\": [0,0,0]},\n \"objects\": [\n"
     "  {\"type\": \"sphere\", \"name\": \"1e999\"},\n  {\"type\": \"sphere\", \"radius\": "
     "1e999}]}",
     "line 4, column 32", "number overflow"},
    {"float_overflow", with_camera(R"("objects": [{"type": "sphere", "radius": 1e300}])"),
     "/objects/0/radius", "too large"},
    {"unknown_material", with_camera(R"("objects": [{"type": "sphere", "material": "gold"}])"),
     "/objects/0/material", "unknown material \"gold\""},
    {"missing_objects", R"({"camera": {"eye": [0,0,5], "look_at": [0,0,0]}})", "(top level)",
     "missing required key \"objects\""},
    {"short_vector", with_camera(R"("objects": [{"type": "sphere", "center": [1, 2]}])"),
     "/objects/0/center", "expected 3 elements"},
    {"missing_mesh", with_camera(R"("objects": [{"type": "mesh", "file": "nope.obj"}])"),
     "/objects/0/file", "cannot open mesh"},
    {"bad_resolution", with_camera(R"("resolution": [0, 10], "objects": [])"), "/resolution/0",
     "between 1 and"},
    {"reflectivity_range",
     with_camera(R"("materials": {"m": {"reflectivity": 1.5}}, "objects": [])"),
     "/materials/m/reflectivity", "between 0 and 1"},
    {"collinear_triangle",
     with_camera(R"("objects": [{"type": "triangle", "vertices": [[0,0,0],[1,1,1],[2,2,2]]}])"),
     "/objects/0/vertices", "collinear"},
    {"light_type", with_camera(R"("lights": [{"type": "spot"}], "objects": [])"), "/lights/0/type",
     "unknown light type"},
    {"too_deep", (std::string(200, '[') + std::string(200, ']')), "(document)", "nested"},
    {"not_object", "[1, 2, 3]", "(top level)", "expected an object"},
};

INSTANTIATE_TEST_SUITE_P(Json, BadScene, ::testing::ValuesIn(kBadCases),
                         [](const auto& param_info) { return param_info.param.name; });

TEST(Loader, MissingFileAndUnknownExtension) {
    try {
        load_scene("/nonexistent/scene.json");
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(e.file(), "/nonexistent/scene.json");
        EXPECT_NE(e.detail().find("cannot open"), std::string::npos);
    }
    EXPECT_THROW(load_scene(test::write_file(test::temp_dir("ext") / "s.txt", "{}")), Error);
}

TEST(Loader, ErrorsInsideAMeshNameTheMeshFile) {
    const auto dir = test::temp_dir("mesh_error");
    test::write_file(dir / "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
    const auto path = test::write_file(
        dir / "s.json", with_camera(R"("objects": [{"type": "mesh", "file": "bad.obj"}])"));
    try {
        load_scene(path);
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(e.file().find("bad.obj"), std::string::npos) << e.what();
        EXPECT_NE(e.detail().find("out of range"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace rt

namespace rt {
namespace {

// A byte-order mark before a JSON scene is skipped like any whitespace.
TEST(Loader, JsonWithAByteOrderMarkLoads) {
    const auto path =
        test::write_file(test::temp_dir("json_bom") / "bom.json",
                         "\xEF\xBB\xBF{\"camera\": {\"eye\": [0, 0, 5], \"look_at\": [0, 0, 0]},"
                         " \"objects\": [{\"type\": \"sphere\"}]}");
    const LoadedScene loaded = load_scene(path);
    EXPECT_EQ(loaded.scene.objects.size(), 1u);
}

// --up turns a bare mesh so that the named axis points up (+y), keeping handedness:
// a proper rotation, so the triangle's winding (its front) is kept too.
TEST(Loader, UpAxisTurnsABareMesh) {
    const auto path =
        test::write_file(test::temp_dir("up") / "z_up.obj", "v 0 0 0\nv 1 0 0\nv 0 0 2\nf 1 2 3\n");
    // The vertex (0, 0, 2), and the face normal x cross z = (0, -2, 0), turned: a rotation
    // carries the normal along (a reflection would flip it, and the face's front).
    const vec3 want_top[] = {{0, 2, 0}, {0, 0, 2}, {0, -2, 0}, {0, 0, -2}};
    const vec3 want_normal[] = {{0, 0, 2}, {0, -2, 0}, {0, 0, -2}, {0, 2, 0}};
    const char* axes[] = {"z", "y", "-z", "-y"};
    for (int i = 0; i < 4; ++i) {
        const LoadedScene loaded = load_scene(path, LoadOptions{.up = axes[i], .camera = {}});
        const TriangleMesh& mesh = loaded.scene.meshes[0];
        EXPECT_EQ(mesh.positions[2], want_top[i]) << axes[i];
        EXPECT_EQ(mesh.face_normal(0), want_normal[i]) << axes[i];
    }
    const LoadedScene x_up = load_scene(path, LoadOptions{.up = "x", .camera = {}});
    EXPECT_EQ(x_up.scene.meshes[0].positions[1], vec3(0, 1, 0));  // x became y
    try {
        load_scene(path, LoadOptions{.up = "w", .camera = {}});
        FAIL() << "loaded";
    } catch (const Error& e) {
        EXPECT_EQ(e.where(), "--up");
    }
}

}  // namespace
}  // namespace rt
