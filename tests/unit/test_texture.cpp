// Textures (core/texture.h): the one sampling rule both pipelines follow, and the loaders
// that give meshes their texture coordinates and materials their images.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "core/error.h"
#include "core/gltf_loader.h"
#include "core/image.h"
#include "core/obj_loader.h"
#include "core/scene_loader.h"
#include "test_util.h"

namespace rt {
namespace {

// 2 x 2 texels: red, green (top row), blue, white (bottom row).
Texture four_texels(Wrap wrap) {
    Texture t;
    t.width = t.height = 2;
    t.texels = {vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1), vec3(1, 1, 1)};
    t.wrap_u = t.wrap_v = wrap;
    return t;
}

void expect_near(const vec3& a, const vec3& b) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], 1e-5f) << k;
}

// Texel centres sit at (i + 1/2) / size and return their texel; between them the four
// neighbours blend bilinearly; v = 0 is the top row.
TEST(Texture, BilinearBetweenTexelCentres) {
    const Texture t = four_texels(Wrap::kClamp);
    expect_near(t.sample({0.25f, 0.25f}), vec3(1, 0, 0));
    expect_near(t.sample({0.75f, 0.25f}), vec3(0, 1, 0));
    expect_near(t.sample({0.25f, 0.75f}), vec3(0, 0, 1));
    expect_near(t.sample({0.5f, 0.25f}), vec3(0.5f, 0.5f, 0));
    expect_near(t.sample({0.5f, 0.5f}), vec3(0.5f, 0.5f, 0.5f));
    expect_near(t.sample({0.375f, 0.25f}), vec3(0.75f, 0.25f, 0));  // a quarter of the way
}

// GL's wrap modes: clamp holds the edge texel, repeat comes round to the other side,
// mirror reflects at each edge; far outside [0, 1] each still gives a texel's colour.
TEST(Texture, WrapModesAsInGl) {
    expect_near(four_texels(Wrap::kClamp).sample({-3.0f, 0.25f}), vec3(1, 0, 0));
    expect_near(four_texels(Wrap::kClamp).sample({0.0f, 0.25f}), vec3(1, 0, 0));
    // At u = 0 repeat blends the first column with the last.
    expect_near(four_texels(Wrap::kRepeat).sample({0.0f, 0.25f}), vec3(0.5f, 0.5f, 0));
    expect_near(four_texels(Wrap::kRepeat).sample({1.25f, 0.25f}), vec3(1, 0, 0));
    expect_near(four_texels(Wrap::kMirror).sample({1.25f, 0.25f}), vec3(0, 1, 0));
    expect_near(four_texels(Wrap::kMirror).sample({-0.25f, 0.25f}), vec3(1, 0, 0));
    expect_near(four_texels(Wrap::kRepeat).sample({1e6f + 0.25f, 0.25f}), vec3(1, 0, 0));
    EXPECT_EQ(wrap_texel(-1, 4, Wrap::kRepeat), 3);
    EXPECT_EQ(wrap_texel(-1, 4, Wrap::kMirror), 0);
    EXPECT_EQ(wrap_texel(5, 4, Wrap::kMirror), 2);
    EXPECT_EQ(wrap_texel(9, 4, Wrap::kClamp), 3);
}

// The shipped textured OBJ: map_Kd read (sRGB decoded: the grid's white lines are
// 235/255 encoded), a coordinate per corner, vt's v turned to the image's downward rows.
TEST(Texture, ObjMapKdAndCoordinates) {
    const MeshFile spot = load_obj(test::source_dir() / "assets" / "models" / "spot.obj");
    ASSERT_EQ(spot.textures.size(), 1u);
    EXPECT_EQ(spot.textures[0].width, 256);
    EXPECT_NEAR(spot.textures[0].at(0, 0).x, srgb_decode(235.0f / 255.0f), 1e-6f);
    ASSERT_EQ(spot.materials.size(), 1u);
    EXPECT_EQ(spot.materials[0].texture, 0u);
    EXPECT_EQ(spot.mesh.corner_uvs.size(), 3 * spot.mesh.triangles.size());
    // spot.obj's first face is 739/1 735/2 736/3; vt 1 is its first vt line.
    std::ifstream in(test::source_dir() / "assets" / "models" / "spot.obj");
    std::string line;
    while (std::getline(in, line) && line.rfind("vt ", 0) != 0) {
    }
    std::istringstream vt(line.substr(3));
    float u = 0, v = 0;
    vt >> u >> v;
    EXPECT_NEAR(spot.mesh.corner_uvs[0].x, u, 1e-6f);
    EXPECT_NEAR(spot.mesh.corner_uvs[0].y, 1.0f - v, 1e-6f);
}

// glTF: the base colour texture decoded from its file (and from a .glb's buffer), its
// sampler's wrap modes, TEXCOORD_0 per corner; a scene joins the textures of its meshes.
TEST(Texture, GltfBaseColourTextures) {
    const auto dir = test::source_dir() / "tests" / "data" / "gltf" / "khronos";
    for (const auto& file : {dir / "BoxTextured" / "BoxTextured.gltf", dir / "BoxTextured.glb"}) {
        const GltfScene box = load_gltf(file);
        ASSERT_EQ(box.geometry.textures.size(), 1u) << file;
        EXPECT_GT(box.geometry.textures[0].width, 1) << file;
        EXPECT_EQ(box.geometry.materials[0].texture, 0u) << file;
        EXPECT_EQ(box.geometry.mesh.corner_uvs.size(), 36u) << file;
    }
    const LoadedScene scene = load_scene(test::scene_path("textured.json"));
    ASSERT_EQ(scene.scene.textures.size(), 1u);
    std::size_t textured = 0;
    for (const Material& m : scene.scene.materials) textured += m.texture == 0u;
    EXPECT_EQ(textured, 1u);
}

}  // namespace
}  // namespace rt
