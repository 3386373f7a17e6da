// The item buffer on a real headless GL context (EGL and OSMesa, each test run on both):
// the object and triangle each pixel names, from its own pass and from the colour pass,
// read into fresh storage or into an earlier frame's, against the tracer's first hits.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <glm/geometric.hpp>

#include "../unit/test_util.h"
#include "app/gl/compositor.h"
#include "app/gl/raster_renderer.h"
#include "core/compare.h"
#include "core/image.h"
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
            EXPECT_EQ(ib.object_id(ib.index(x, y)), expected) << x << "," << y;
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
                    const std::uint32_t id = ib.object_id(ib.index(x, y));
                    if (!ib.interior(x, y) || id == ItemBuffer::kEmpty ||
                        !std::holds_alternative<MeshRef>(scene.objects[id - 1].shape))
                        continue;
                    Hit hit;
                    scene.intersect(scene.camera.ray(x, y), hit);
                    ++interior;
                    same += hit.prim == ib.triangle(ib.index(x, y));
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
        EXPECT_TRUE(ib.prim.empty());  // the objects alone, read as they were drawn
        std::size_t background = 0, triangles = 0;
        for (std::size_t i = 0; i < ib.ids.size(); ++i) {
            background += ib.object_id(i) == ItemBuffer::kEmpty;
            triangles += ib.triangle(i) != 0;
        }
        EXPECT_EQ(triangles, 0u);
        EXPECT_GT(background, 0u);  // some background
        EXPECT_LT(background, ib.ids.size() / 2);
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
        EXPECT_TRUE(frame.ids.same_objects(dedicated)) << scene.objects.size() << " objects";
        EXPECT_TRUE(frame.image.pixels == plain.pixels) << scene.objects.size() << " objects";
        std::size_t named = 0;
        for (std::size_t i = 0; i < frame.ids.ids.size(); ++i)
            named += frame.ids.object_id(i) != ItemBuffer::kEmpty;
        EXPECT_GT(named, frame.ids.ids.size() / 20);  // not an empty buffer, equal by chance
        raster.set_msaa(4);
        const gl::RasterRenderer::Frame multisampled = raster.render_with_item_buffer(scene.camera);
        EXPECT_FALSE(multisampled.shared);
        EXPECT_TRUE(multisampled.ids.same_objects(dedicated));
    }
}

// Frames read into an earlier frame's storage (as rtbench, rtrender and the viewer do),
// whether it was bigger, smaller or full of other ids, are the frames read fresh.
TEST_P(GlItemBuffer, AFrameReadIntoAnEarlierFramesStorageIsTheFreshFrame) {
    const Scene scene(load("whitted.json", 120, 90));
    gl::RasterRenderer raster(scene);
    gl::RasterRenderer::Frame reused;
    reused.ids.resize(160, 100, 0, true);
    std::fill(reused.ids.ids.begin(), reused.ids.ids.end(), 0xdeadbeefu);
    std::fill(reused.ids.prim.begin(), reused.ids.prim.end(), 0xdeadbeefu);
    reused.image.resize(50, 50);
    for (const auto& [cols, rows] : {std::pair{120, 90}, {40, 30}, {160, 100}, {120, 90}}) {
        const Camera camera = scene.camera.resized(cols, rows);
        const Image plain = raster.render(camera);
        const ItemBuffer dedicated = raster.render_item_buffer(camera);
        raster.render_with_item_buffer(camera, reused);
        EXPECT_EQ(reused.ids.width, cols);
        EXPECT_EQ(reused.ids.height, rows);
        EXPECT_TRUE(reused.ids.same_objects(dedicated)) << cols << " x " << rows;
        EXPECT_EQ(reused.image.width, cols);
        EXPECT_TRUE(reused.image.pixels == plain.pixels) << cols << " x " << rows;
        raster.render(camera, reused.image);
        EXPECT_TRUE(reused.image.pixels == plain.pixels) << cols << " x " << rows;
        raster.render_item_buffer(camera, reused.ids);
        EXPECT_TRUE(reused.ids.same_objects(dedicated)) << cols << " x " << rows;
    }
}

// The ids read straight into the caller's storage (llvmpipe's default) are the ids read
// through the pixel buffer (a GPU's), in every layout, from either pass, into storage
// that held another layout before.
TEST_P(GlItemBuffer, IdsReadStraightAreTheIdsReadThroughThePixelBuffer) {
    using Reads = gl::Framebuffer::IdReads;
    for (const char* name : {"tutorial.json", "whitted.json", "cornell.json"}) {
        const Scene scene(load(name, 120, 90));
        gl::RasterRenderer raster(scene);
        for (const gl::IdLayout layout :
             {raster.id_layout(), gl::IdLayout{gl::IdLayout::Kind::kSeparate, 0}}) {
            raster.set_id_layout(layout);
            for (const bool shared : {false, true}) {
                ItemBuffer ids[2];
                for (const Reads how : {Reads::kPixelBuffer, Reads::kDirect}) {
                    raster.set_id_reads(how);
                    ItemBuffer& into = ids[how == Reads::kDirect];
                    into.resize(7, 3, 5, layout.kind != gl::IdLayout::Kind::kSeparate);
                    std::fill(into.ids.begin(), into.ids.end(), 0xdeadbeefu);
                    if (shared) {
                        gl::RasterRenderer::Frame frame;
                        frame.ids = std::move(into);
                        raster.render_with_item_buffer(scene.camera, frame);
                        into = std::move(frame.ids);
                    } else {
                        raster.render_item_buffer(scene.camera, into);
                    }
                }
                const std::string what = std::string(name) + (shared ? ", shared" : "") +
                                         ", layout " +
                                         std::to_string(static_cast<int>(layout.kind));
                EXPECT_EQ(ids[1].prim_bits, ids[0].prim_bits) << what;
                EXPECT_TRUE(ids[1].ids == ids[0].ids && ids[1].prim == ids[0].prim) << what;
                std::size_t named = 0;
                for (std::size_t i = 0; i < ids[1].ids.size(); ++i)
                    named += ids[1].object_id(i) != ItemBuffer::kEmpty;
                EXPECT_GT(named, ids[1].ids.size() / 4) << what;  // not two empty buffers
            }
        }
    }
}

// The ids' layout: packed wherever the object ids and the largest mesh's triangles fit
// in 32 bits together, objects alone without a mesh, two targets otherwise.
TEST(IdLayout, PacksWhereObjectsAndTrianglesFitInOneWord) {
    using Kind = gl::IdLayout::Kind;
    EXPECT_EQ(gl::IdLayout::for_scene(5, 0).kind, Kind::kObjectsOnly);
    const gl::IdLayout whitted = gl::IdLayout::for_scene(5, 69451);  // ids 1-5: 3 bits
    EXPECT_EQ(whitted.kind, Kind::kPacked);
    EXPECT_EQ(whitted.prim_bits, 29);
    EXPECT_EQ(whitted.shader_prim_bits(), 29u);
    EXPECT_FALSE(whitted.second_target());
    const std::size_t two21 = std::size_t{1} << 21;
    EXPECT_EQ(gl::IdLayout::for_scene(1601, two21).prim_bits, 21);  // ids to 1601: 11 bits
    EXPECT_EQ(gl::IdLayout::for_scene(1601, two21 + 1).kind, Kind::kSeparate);
    EXPECT_EQ(gl::IdLayout::for_scene(2047, two21).prim_bits, 21);
    EXPECT_EQ(gl::IdLayout::for_scene(2048, two21).kind, Kind::kSeparate);  // 12 bits
    EXPECT_EQ(gl::IdLayout::for_scene(1, std::size_t{1} << 31).prim_bits, 31);
    EXPECT_EQ(gl::IdLayout::for_scene(1, (std::size_t{1} << 31) + 1).kind, Kind::kSeparate);
    EXPECT_EQ(gl::IdLayout::for_scene(std::size_t{1} << 32, 1).kind, Kind::kSeparate);
    const gl::IdLayout separate = gl::IdLayout::for_scene(3, std::size_t{1} << 31);
    EXPECT_TRUE(separate.second_target());
    EXPECT_EQ(separate.shader_prim_bits(), 0u);
}

// Packed ids read back as the two targets' ids, pixel for pixel, from both passes, and
// so do the packed ids cut to the fewest bits the mesh needs (every mask and shift at
// its edge; a sphere's tessellation, whose triangles nothing reads, is cut then, so
// triangles are compared on the mesh's pixels: the last scene's two-triangle quad leaves
// one bit, far fewer than its sphere's tessellation has). One pixel read alone is
// unpacked too.
TEST_P(GlItemBuffer, PackedIdsReadBackAsTwoTargets) {
    const auto dir = test::temp_dir(std::string("packed_ids_") +
                                    (GetParam() == gl::Backend::kEgl ? "egl" : "osmesa"));
    test::write_file(dir / "quad.obj",
                     "v -0.2 -1 0\nv 1.8 -1 0\nv -0.2 1 0\nv 1.8 1 0\nf 1 2 4\nf 1 4 3\n");
    const auto quad_and_ball = test::write_file(
        dir / "quad_and_ball.json",
        R"({"camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov": 40},
            "lights": [{"type": "point", "position": [0, 3, 5], "color": 1}],
            "objects": [{"type": "sphere", "center": [-1, 0, 0], "radius": 0.8},
                        {"type": "mesh", "file": "quad.obj"}]})");
    std::vector<std::pair<std::string, SceneDescription>> scenes;
    for (const char* name : {"cornell.json", "whitted.json"})
        scenes.emplace_back(name, load(name, 120, 90));
    SceneDescription small = load_scene(quad_and_ball).scene;
    small.camera = small.camera.resized(120, 90);
    scenes.emplace_back("quad_and_ball.json", std::move(small));
    for (auto& [name, description] : scenes) {
        const Scene scene(std::move(description));
        gl::RasterRenderer raster(scene);
        ASSERT_EQ(raster.id_layout().kind, gl::IdLayout::Kind::kPacked) << name;
        std::size_t mesh_triangles = 0;
        for (const TriangleMesh& m : scene.meshes)
            mesh_triangles = std::max(mesh_triangles, m.triangles.size());
        const int fewest = static_cast<int>(std::bit_width(mesh_triangles - 1));
        const gl::IdLayout packed = raster.id_layout();
        raster.set_id_layout({gl::IdLayout::Kind::kSeparate, 0});
        const ItemBuffer two = raster.render_item_buffer(scene.camera);
        const ItemBuffer two_shared = raster.render_with_item_buffer(scene.camera).ids;
        EXPECT_TRUE(two.ids == two_shared.ids && two.prim == two_shared.prim) << name;
        EXPECT_EQ(two.prim.size(), two.ids.size()) << name;  // the triangles apart
        for (const gl::IdLayout layout :
             {packed, gl::IdLayout{gl::IdLayout::Kind::kPacked, fewest}}) {
            raster.set_id_layout(layout);
            for (const bool shared : {false, true}) {
                const ItemBuffer one = shared ? raster.render_with_item_buffer(scene.camera).ids
                                              : raster.render_item_buffer(scene.camera);
                const std::string what = std::string(name) + ", " +
                                         std::to_string(layout.prim_bits) + " bits" +
                                         (shared ? ", shared pass" : "");
                EXPECT_TRUE(one.prim.empty()) << what;  // read back packed, as drawn
                EXPECT_EQ(one.prim_bits, layout.prim_bits) << what;
                std::size_t mesh_pixels = 0, unlike = 0, objects_unlike = 0;
                for (std::size_t i = 0; i < one.ids.size(); ++i) {
                    const std::uint32_t id = one.object_id(i);
                    objects_unlike += id != two.object_id(i);
                    if (id == ItemBuffer::kEmpty ||
                        !std::holds_alternative<MeshRef>(scene.objects[id - 1].shape))
                        continue;
                    ++mesh_pixels;
                    unlike += one.triangle(i) != two.triangle(i);
                }
                EXPECT_EQ(objects_unlike, 0u) << what;
                EXPECT_GT(mesh_pixels, 200u) << what;
                EXPECT_EQ(unlike, 0u) << what;
                if (layout.prim_bits == packed.prim_bits) {
                    EXPECT_TRUE(one.same_objects(two)) << what;
                }
            }
            const gl::Framebuffer& fb = raster.render_item_buffer_to_texture(scene.camera);
            for (const auto& [x, y] : {std::pair{60, 45}, {10, 80}, {100, 20}})
                EXPECT_EQ(fb.read_id(x, y), two.object_id(two.index(x, y)))
                    << name << " " << x << "," << y;
        }
    }
}

// The viewer's item-buffer view samples the packed target itself: each pixel shows the
// palette colour of its object, the triangle bits shifted away.
TEST_P(GlItemBuffer, TheItemViewShowsPackedIdsAsTheirObjects) {
    const Scene scene(load("whitted.json", 120, 90));
    gl::RasterRenderer raster(scene);
    ASSERT_EQ(raster.id_layout().kind, gl::IdLayout::Kind::kPacked);
    const ItemBuffer ids = raster.render_item_buffer(scene.camera);
    const gl::Framebuffer& packed = raster.render_item_buffer_to_texture(scene.camera);
    gl::Compositor compositor;
    compositor.set_item_palette(scene.objects.size());
    gl::CompositeInputs in;
    in.view = gl::View::kItemBuffer;
    in.item_buffer = packed.texture();
    in.item_buffer_shift = packed.ids().shader_prim_bits();
    const gl::Framebuffer screen(gl::Framebuffer::Kind::kColour, ids.width, ids.height);
    screen.bind();
    compositor.draw(in, ids.width, ids.height);
    const Image shown = screen.read_colour();
    std::vector<vec3> palette;
    for (std::uint32_t id = 0; id <= scene.objects.size(); ++id) {
        const vec3 c = item_colour(id);
        palette.push_back({srgb_encode(c.x), srgb_encode(c.y), srgb_encode(c.z)});
    }
    std::size_t wrong = 0, objects = 0;
    for (std::size_t i = 0; i < ids.ids.size(); ++i) {
        const auto nearest = std::min_element(palette.begin(), palette.end(), [&](vec3 a, vec3 b) {
            return glm::length(a - shown.pixels[i]) < glm::length(b - shown.pixels[i]);
        });
        wrong += static_cast<std::uint32_t>(nearest - palette.begin()) != ids.object_id(i);
        objects += ids.object_id(i) != ItemBuffer::kEmpty;
    }
    EXPECT_EQ(wrong, 0u);
    EXPECT_GT(objects, ids.ids.size() / 4);
}

INSTANTIATE_TEST_SUITE_P(Headless, GlItemBuffer, kBackends, backend_name);

}  // namespace
}  // namespace rt
