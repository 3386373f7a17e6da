// The item buffer on a real headless GL context (EGL and OSMesa, each test run on both):
// the object and triangle each pixel names, from its own pass and from the colour pass,
// read into fresh storage or into an earlier frame's, against the tracer's first hits.
#include <gtest/gtest.h>

#include <algorithm>
#include <utility>
#include <variant>

#include "../unit/test_util.h"
#include "app/gl/raster_renderer.h"
#include "core/compare.h"
#include "core/renderer.h"
#include "core/scene_loader.h"
#include "gl_fixture.h"

namespace rt {
namespace {

class GlItemBuffer : public GlTest {};

TEST_P(GlItemBuffer, ItemBufferNamesTheObjectAtEachPixel) {
    const Scene scene(load("tutorial.json", 120, 90));
    gl::RasterRenderer raster(scene);
    const ItemBuffer ib = raster.render_item_buffer(scene.camera);
    std::size_t checked = 0;
    for (int y = 0; y < ib.height; y += 2) {
        for (int x = 0; x < ib.width; x += 2) {
            if (!ib.interior(x, y)) continue;
            Hit hit;
            scene.intersect(scene.camera.ray(x, y), hit);
            const std::uint32_t expected = hit.found() ? hit.object + 1 : ItemBuffer::kEmpty;
            EXPECT_EQ(ib.object[ib.index(x, y)], expected) << x << "," << y;
            ++checked;
        }
    }
    EXPECT_GT(checked, 2000u);
}

// Both passes name a mesh's triangles (cornell: one mesh; whitted: the bunny among
// spheres and a plane). A scene without a mesh has no triangle ids drawn: 0 everywhere.
TEST_P(GlItemBuffer, ItemBufferNamesTheTriangleOfAMesh) {
    for (const char* name : {"cornell.json", "whitted.json"}) {
        const Scene scene(load(name, 96, 96));
        gl::RasterRenderer raster(scene);
        for (const bool shared : {false, true}) {
            const ItemBuffer ib = shared ? raster.render_with_item_buffer(scene.camera).ids
                                         : raster.render_item_buffer(scene.camera);
            int same = 0, interior = 0;
            for (int y = 0; y < ib.height; ++y) {
                for (int x = 0; x < ib.width; ++x) {
                    const std::uint32_t id = ib.object[ib.index(x, y)];
                    if (!ib.interior(x, y) || id == ItemBuffer::kEmpty ||
                        !std::holds_alternative<MeshRef>(scene.objects[id - 1].shape))
                        continue;
                    Hit hit;
                    scene.intersect(scene.camera.ray(x, y), hit);
                    ++interior;
                    same += hit.prim == ib.prim[ib.index(x, y)];
                }
            }
            // Within one object, neighbouring triangles share an edge the item buffer does
            // not mark; so a handful of pixels may name the neighbour (cornell: its quads;
            // whitted: 3 of 308, the bunny's triangles a pixel or two wide at 96 x 96).
            EXPECT_GT(interior, 200) << name;
            EXPECT_GE(same * 100, interior * 98) << name << (shared ? ", shared pass" : "");
        }
    }
    const Scene spheres(load("many_spheres.json", 96, 96));
    gl::RasterRenderer raster(spheres);
    for (const ItemBuffer& ib : {raster.render_item_buffer(spheres.camera),
                                 raster.render_with_item_buffer(spheres.camera).ids}) {
        EXPECT_EQ(std::count(ib.prim.begin(), ib.prim.end(), 0u),
                  static_cast<std::ptrdiff_t>(ib.prim.size()));
        EXPECT_GT(std::count(ib.object.begin(), ib.object.end(), ItemBuffer::kEmpty),
                  0);  // some background
        EXPECT_LT(std::count(ib.object.begin(), ib.object.end(), ItemBuffer::kEmpty),
                  static_cast<std::ptrdiff_t>(ib.object.size() / 2));
    }
}

TEST_P(GlItemBuffer, ItemBufferImagesAgreeWithFullTraversal) {
    for (const char* name : kScenes) {
        const Scene scene(load(name, 200, 150));
        gl::RasterRenderer raster(scene);
        const ItemBuffer ib = raster.render_item_buffer(scene.camera);
        RenderStats with, without;
        const Image a = render(scene, {}, &with, {}, {}, &ib);
        const Image b = render(scene, {}, &without);
        const ImageDiff d = compare_images(a, b, 1.5 / 255.0);
        EXPECT_LE(d.share_over, 0.001) << name << ": " << d.pixels_over << " pixels disagree";
        EXPECT_LT(with.item_buffer_fallbacks, a.pixels.size() / 2) << name;
        // Pixels where the named object misses (a tessellated silhouette, a background
        // pixel next to an object) fall back to a full traversal: every scene has some
        // (1,149 to 14,410 at 200 x 150), so the fallback path is exercised here.
        EXPECT_GT(with.item_buffer_fallbacks, 100u) << name;
    }
}

// The item buffer drawn by the colour pass itself (the shared pass) is the dedicated
// pass's, id for id, and drawing it changes no colour; with MSAA the ids take a pass of
// their own and are the same again. The last scene has lines in front of its surface:
// they are drawn in colour and leave the ids alone.
TEST_P(GlItemBuffer, TheColourPassDrawsTheSameItemBuffer) {
    const auto wires =
        test::write_file(test::temp_dir(std::string("shared_ids_") +
                                        (GetParam() == gl::Backend::kEgl ? "egl" : "osmesa")) /
                             "face_and_lines.obj",
                         "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0.5 0.2\nv 1 0.5 0.2\n"
                         "v 0 0.5 -0.2\nv 1 0.5 -0.2\nf 1 2 4\nf 1 4 3\nl 5 6\nl 7 8\n");
    std::vector<SceneDescription> scenes;
    for (const char* name : kScenes) scenes.push_back(load(name, 200, 150));
    LoadedScene loaded = load_scene(wires);
    loaded.scene.camera = loaded.scene.camera.resized(96, 72);
    scenes.push_back(std::move(loaded.scene));
    for (SceneDescription& description : scenes) {
        const Scene scene(std::move(description));
        gl::RasterRenderer raster(scene);
        const Image plain = raster.render(scene.camera);
        const ItemBuffer dedicated = raster.render_item_buffer(scene.camera);
        const gl::RasterRenderer::Frame frame = raster.render_with_item_buffer(scene.camera);
        EXPECT_TRUE(frame.shared);
        EXPECT_TRUE(frame.ids.object == dedicated.object) << scene.objects.size() << " objects";
        EXPECT_TRUE(frame.ids.prim == dedicated.prim) << scene.objects.size() << " objects";
        EXPECT_TRUE(frame.image.pixels == plain.pixels) << scene.objects.size() << " objects";
        std::size_t named = 0;
        for (std::uint32_t id : frame.ids.object) named += id != ItemBuffer::kEmpty;
        EXPECT_GT(named, frame.ids.object.size() / 20);  // not an empty buffer, equal by chance
        raster.set_msaa(4);
        const gl::RasterRenderer::Frame multisampled = raster.render_with_item_buffer(scene.camera);
        EXPECT_FALSE(multisampled.shared);
        EXPECT_TRUE(multisampled.ids.object == dedicated.object);
    }
}

// Frames read into an earlier frame's storage (as rtbench, rtrender and the viewer do),
// whether it was bigger, smaller or full of other ids, are the frames read fresh.
TEST_P(GlItemBuffer, AFrameReadIntoAnEarlierFramesStorageIsTheFreshFrame) {
    const Scene scene(load("whitted.json", 120, 90));
    gl::RasterRenderer raster(scene);
    gl::RasterRenderer::Frame reused;
    reused.ids.resize(160, 100);
    std::fill(reused.ids.object.begin(), reused.ids.object.end(), 0xdeadbeefu);
    std::fill(reused.ids.prim.begin(), reused.ids.prim.end(), 0xdeadbeefu);
    reused.image.resize(50, 50);
    for (const auto& [cols, rows] : {std::pair{120, 90}, {40, 30}, {160, 100}, {120, 90}}) {
        const Camera camera = scene.camera.resized(cols, rows);
        const Image plain = raster.render(camera);
        const ItemBuffer dedicated = raster.render_item_buffer(camera);
        raster.render_with_item_buffer(camera, reused);
        EXPECT_EQ(reused.ids.width, cols);
        EXPECT_EQ(reused.ids.height, rows);
        EXPECT_TRUE(reused.ids.object == dedicated.object) << cols << " x " << rows;
        EXPECT_TRUE(reused.ids.prim == dedicated.prim) << cols << " x " << rows;
        EXPECT_EQ(reused.image.width, cols);
        EXPECT_TRUE(reused.image.pixels == plain.pixels) << cols << " x " << rows;
        raster.render(camera, reused.image);
        EXPECT_TRUE(reused.image.pixels == plain.pixels) << cols << " x " << rows;
        raster.render_item_buffer(camera, reused.ids);
        EXPECT_TRUE(reused.ids.object == dedicated.object) << cols << " x " << rows;
        EXPECT_TRUE(reused.ids.prim == dedicated.prim) << cols << " x " << rows;
    }
}

INSTANTIATE_TEST_SUITE_P(Headless, GlItemBuffer,
                         ::testing::Values(gl::Backend::kEgl, gl::Backend::kOsmesa),
                         [](const auto& param_info) {
                             return param_info.param == gl::Backend::kEgl ? "egl" : "osmesa";
                         });

}  // namespace
}  // namespace rt
