// Legal input far from the origin: the same small scene placed at offsets up to 1e7
// must give the same picture (lit, shadowed, with its checker where the file put it),
// and collapsed geometry must neither crash a traversal nor hang a build.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

#include "core/compare.h"
#include "core/renderer.h"
#include "core/scene_loader.h"
#include "core/tessellate.h"
#include "core/wide_bvh.h"
#include "far_scene.h"
#include "test_util.h"

namespace rt {
namespace {

constexpr double kOffsets[] = {0.0, 1e3, 1e5, 1e6, 1e7};
using test::far_json;
using test::number;
using test::point;
using test::tetra_obj;

// A 4-unit cube as a bare OBJ, every coordinate offset by o.
std::string far_cube_obj(double o) {
    std::string text;
    for (int i = 0; i < 8; ++i)
        text += "v " + number((i & 4 ? 2 : -2) + o) + " " + number((i & 2 ? 2 : -2) + o) + " " +
                number((i & 1 ? 2 : -2) + o) + "\n";
    for (const char* f : {"1 2 4 3", "5 7 8 6", "1 5 6 2", "3 4 8 7", "1 3 7 5", "2 6 8 4"})
        text += std::string("f ") + f + "\n";
    return text;
}

Image render_file(const std::filesystem::path& path, RenderStats* stats) {
    LoadedScene loaded = load_scene(path);
    loaded.scene.camera = loaded.scene.camera.resized(160, 120);
    const Scene scene(std::move(loaded.scene));
    return render(scene, {}, stats);
}

// The tolerance: at most 0.5 % of pixels differ by more than 2/255 from the scene at the
// origin. Scenes nearer than 4096 units are read as they are, so float rounding moves a
// few edge pixels (0.3 % at 1e3); farther ones are read relative to their eye or centre
// and come out identical.
void expect_same_at_every_offset(const std::string& name, std::string (*make)(double),
                                 const std::string& extension) {
    const auto dir = test::temp_dir("far_" + name);
    Image reference;
    for (double o : kOffsets) {
        test::write_file(dir / ("tetra" + number(o) + ".obj"), tetra_obj(o));
        test::write_file(dir / "tetra0.obj", tetra_obj(0.0));
        const auto path = test::write_file(dir / (name + number(o) + extension), make(o));
        RenderStats stats;
        const Image image = render_file(path, &stats);
        EXPECT_GT(stats.rays.shadow, 10000u) << name << " at " << o << ": the light is lost";
        if (o == 0.0) {
            reference = image;
            continue;
        }
        const ImageDiff diff = compare_images(reference, image);
        EXPECT_LE(diff.share_over, 0.005) << name << " at offset " << o;
        if (o >= 1e5) {
            EXPECT_EQ(diff.pixels_over, 0u) << name << " at offset " << o;
        }
    }
}

TEST(Far, JsonSceneLooksTheSameAtAnyOffset) {
    expect_same_at_every_offset(
        "json", [](double o) { return far_json(o); }, ".json");
}

TEST(Far, BareObjLooksTheSameAtAnyOffset) {
    expect_same_at_every_offset("cube", far_cube_obj, ".obj");
}

// The every-shape scene 64 times its size (740 units across) 2^17 units out: nearer than
// 256 of its sizes, so only the rule of 4096 units reads it relative to its eye. Read as
// it is, float's step there (1/64) and the ray offsets (256 steps, 4 units) moved its
// shadows' and reflections' edges (138 pixels of 19,200 unlike); relative to its eye it
// is the scene at the origin (both in powers of two: every coordinate the same in float).
TEST(Far, ALargeSceneFarOutIsReadRelativeToItsEye) {
    const auto dir = test::temp_dir("far_large");
    const double s = 64.0;
    Image near;
    for (const double o : {0.0, 0x1p17}) {
        test::write_file(dir / ("tetra" + number(o) + ".obj"), tetra_obj(o, s));
        test::write_file(dir / "tetra0.obj", tetra_obj(0.0, s));
        const auto path = test::write_file(dir / "scene.json", far_json(o, s));
        EXPECT_EQ(load_scene(path).origin,
                  o == 0.0 ? glm::dvec3(0.0) : glm::dvec3(o, o + 2 * s, o + 10 * s));
        const Image image = render_file(path, nullptr);
        if (o == 0.0)
            near = image;
        else
            EXPECT_EQ(compare_images(near, image).pixels_over, 0u);
    }
}

// A 1 mm cube 1000 units out is framed and lit as at the origin: the camera's minimum
// distance follows float's spacing there (a larger share of the coordinates framed it
// far too small: 31 % of pixels differed), and a light nearer than the shadow feeler's
// offset still lights it (it went dark). Read as float (it is nearer than 4096), its
// corners move by up to half a float step (6e-5, 2.4 % of its size): 3.2 % of pixels
// differ along its edges; 5 % is allowed.
TEST(Far, TinyModelAwayFromTheOriginKeepsItsSizeOnScreen) {
    const auto dir = test::temp_dir("far_tiny");
    const auto tiny = [](double o) {
        std::string text;
        for (int i = 0; i < 8; ++i)
            text += "v " + number((i & 4 ? 5e-4 : -5e-4) + o) + " " +
                    number((i & 2 ? 5e-4 : -5e-4) + o) + " " + number((i & 1 ? 5e-4 : -5e-4) + o) +
                    "\n";
        for (const char* f : {"1 2 4 3", "5 7 8 6", "1 5 6 2", "3 4 8 7", "1 3 7 5", "2 6 8 4"})
            text += std::string("f ") + f + "\n";
        return text;
    };
    const Image near = render_file(test::write_file(dir / "tiny0.obj", tiny(0.0)), nullptr);
    const Image far = render_file(test::write_file(dir / "tiny1000.obj", tiny(1e3)), nullptr);
    EXPECT_LE(compare_images(near, far).share_over, 0.05);
}

// The every-shape scene a thousand times smaller (balls of 1.5 mm) and 1000 units out:
// nearer than 4096, but 1.7e5 times as far as the camera looks, so it is read relative to
// its eye. Read as it is, the ray offsets (256 float steps, 1.6 cm there) went past the
// balls: no shadows, broken reflections, 19 % of pixels unlike the same scene at the
// origin. Relative to its eye it differs from that one where the checker's edges lie:
// its squares are float(1e-3) wide, so 1000 units out they are shifted by 5 % of a square
// (the file's pattern, rightly drawn), and 4.7 % of pixels differ, all on edges.
TEST(Far, ASmallSceneIsReadRelativeToItsEyeWhereFloatIsCoarseForIt) {
    const auto dir = test::temp_dir("far_small");
    test::write_file(dir / "tetra0.obj", tetra_obj(0.0, 1e-3));
    test::write_file(dir / "tetra1000.obj", tetra_obj(1e3, 1e-3));
    const auto near_path = test::write_file(dir / "near.json", far_json(0.0, 1e-3));
    const auto far_path = test::write_file(dir / "far.json", far_json(1e3, 1e-3));
    EXPECT_EQ(load_scene(near_path).origin, glm::dvec3(0.0));
    EXPECT_EQ(load_scene(far_path).origin, glm::dvec3(1e3, 1e3 + 2e-3, 1e3 + 1e-2));
    RenderStats near_stats, far_stats;
    const Image near = render_file(near_path, &near_stats);
    const Image far = render_file(far_path, &far_stats);
    EXPECT_LE(compare_images(near, far).share_over, 0.06);
    // The ball's shadow and reflections: as many feelers blocked, as many reflected rays.
    EXPECT_EQ(far_stats.rays.reflected, near_stats.rays.reflected);
}

// The Stanford bunny 1e7 units out: in float its vertices would collapse onto a few
// points; read relative to its centre in double it is the bunny at the origin.
TEST(Far, BunnyFarAwayIsTheBunny) {
    const auto dir = test::temp_dir("far_bunny");
    const auto path = test::write_file(dir / "far.obj", test::bunny_obj(1.0, 1e7));
    const Image near =
        render_file(test::source_dir() / "assets/models/stanford-bunny.obj", nullptr);
    const Image image = render_file(path, nullptr);
    EXPECT_LE(compare_images(near, image).share_over, 0.005);
}

// A scene read in a unit of its own (LoadedScene::scale, a power of two) must look as
// `near`, the same at size 1, does: the same pixels but 0.1 %, as many shadow feelers
// (0.1 %) and reflected rays, no NaN.
void expect_like_size_one(const std::filesystem::path& path, double s, const Image& near,
                          const RenderStats& near_stats) {
    const LoadedScene loaded = load_scene(path);
    int exponent = 0;
    EXPECT_EQ(std::frexp(loaded.scale, &exponent), 0.5) << s << ": a power of two";
    EXPECT_NE(loaded.scale, 1.0) << s;
    RenderStats stats;
    const Image image = render_file(path, &stats);
    EXPECT_LE(compare_images(near, image).share_over, 0.001) << "scale " << s;
    EXPECT_EQ(stats.nonfinite_pixels, 0u) << s;
    EXPECT_EQ(stats.rays.reflected, near_stats.rays.reflected) << s;
    EXPECT_NEAR(static_cast<double>(stats.rays.shadow), static_cast<double>(near_stats.rays.shadow),
                0.001 * static_cast<double>(near_stats.rays.shadow))
        << s << ": lit as at its own size";
}

// The bunny 1e-12, 1e15 and 2^-70 times its size, and 1e-4 times it 1,000 units
// out, looks as it does. Read as they were, the tiny ones came out empty (the framing's
// least distance, the ray offsets' absolute step near zero) and the huge ones unlit (each
// face's cross product squared overflowed: no normals). A bare model that far from a
// size float handles well is scaled by a power of two.
TEST(Far, ABareModelLooksTheSameAtAnyScale) {
    const auto dir = test::temp_dir("far_scale");
    const auto bunny = test::source_dir() / "assets/models/stanford-bunny.obj";
    RenderStats near_stats;
    const Image near = render_file(bunny, &near_stats);
    EXPECT_EQ(load_scene(bunny).scale, 1.0);
    for (const auto& [s, o] : {std::pair{1e-12, 0.0}, {1e-4, 1e3}, {1e15, 0.0}, {0x1p-70, 0.0}})
        expect_like_size_one(
            test::write_file(dir / ("bunny" + number(s) + ".obj"), test::bunny_obj(s, o)), s, near,
            near_stats);
}

// The every-shape scene (a checker, a mirror, transformed shapes, meshes from files)
// 1e-9, 1e12 and 1e15 times its size looks as it does: tiny, its feelers started a float
// offset's absolute step (1/65536) away and its shadows went (8.6 % of pixels unlike);
// at 1e15 the raster had NaN pixels. A scene whose camera looks that far (or that near)
// is read in a power-of-two unit, every length divided by it.
TEST(Far, AJsonSceneLooksTheSameAtAnyScale) {
    const auto dir = test::temp_dir("far_json_scale");
    const auto scene_at = [&](double s) {
        test::write_file(dir / "tetra0.obj", tetra_obj(0.0, s));
        return test::write_file(dir / "scene.json", far_json(0.0, s));
    };
    RenderStats near_stats;
    const Image near = render_file(scene_at(1.0), &near_stats);
    for (const double s : {1e-9, 1e12, 1e15})
        expect_like_size_one(scene_at(s), s, near, near_stats);
}

// The same with a camera given by u, v and n, which says nothing of the scene's size:
// the size of what the file holds decides (read once more in its unit). Before, the tiny
// scene lost its shadows, and one 2^-13 its size 1,024 units out was not rebased (sizes
// and offsets of powers of two: the checker's squares line up there as at the origin).
TEST(Far, AJsonSceneWithoutLookAtLooksTheSameAtAnyScale) {
    const auto dir = test::temp_dir("far_json_uvn");
    const auto scene_at = [&](double o, double s) {
        test::write_file(dir / ("tetra" + number(o) + ".obj"), tetra_obj(o, s));
        test::write_file(dir / "tetra0.obj", tetra_obj(0.0, s));
        return test::write_file(dir / "scene.json", far_json(o, s, /*uvn=*/true));
    };
    RenderStats near_stats;
    const Image near = render_file(scene_at(0.0, 1.0), &near_stats);
    EXPECT_EQ(load_scene(dir / "scene.json").scale, 1.0);
    for (const auto& [s, o] : {std::pair{1e-9, 0.0}, {1e15, 0.0}, {0x1p-13, 1024.0}})
        expect_like_size_one(scene_at(o, s), s, near, near_stats);
}

// A NaN or infinite ray enters no box: before the guard, a NaN ray counted as inside
// every lane, unused ones too, whose child 0 is the root: the stack overflowed.
template <class Tree>
void expect_non_finite_rays_miss() {
    std::vector<Aabb> boxes;
    for (int i = 0; i < 100; ++i) boxes.push_back({vec3(float(i)), vec3(float(i) + 0.5f)});
    Tree tree;
    tree.build(boxes, 1);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (const Ray& r : {Ray{vec3(nan), vec3(0, 0, 1)}, Ray{vec3(0.0f), vec3(nan, 1, 1)},
                         Ray{vec3(kInfinity, 0, 0), vec3(1, 1, 1)}}) {
        float t_max = kInfinity;
        int visits = 0;
        EXPECT_FALSE(tree.template traverse<false>(r, t_max, [&](std::uint32_t, float&) {
            ++visits;
            return false;
        }));
        EXPECT_EQ(visits, 0);
    }
}

// The raster's sphere is finer the larger it looks, up to 256 segments. A sphere that
// looks some 1e7 pixels or more across (a planet through a telephoto lens) has its
// quarter-pixel arc's angle round to 0 and the count to infinity: it must still get the
// finest mesh (the cast of infinity to int was undefined and gave x86's INT_MIN, clamped
// to the coarsest, 12 segments: a polygon hundreds of metres inside the surface).
TEST(Far, ASphereThatLooksMillionsOfPixelsWideGetsTheFinestMesh) {
    int previous = 0;
    for (const float pixels : {0.0f, 0.3f, 1.0f, 10.0f, 100.0f, 1e3f, 1e4f, 1e6f, 1e7f, 1e8f, 1e12f,
                               1e30f, std::numeric_limits<float>::infinity()}) {
        const int segments = sphere_segments_for(pixels);
        EXPECT_GE(segments, previous) << pixels;  // never coarser for a larger sphere
        EXPECT_GE(segments, 12) << pixels;
        EXPECT_LE(segments, 256) << pixels;
        previous = segments;
    }
    EXPECT_EQ(sphere_segments_for(1e8f), 256);
    // A 10 km ball 150 m away through a lens of 0.1 degrees: 2.7e7 pixels.
    const Camera camera = Camera::look_at({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 0.1f, 1280, 720);
    const float pixels = projected_radius_pixels(camera, {0, 0, -10150.0f}, 1e4f);
    EXPECT_GT(pixels, 1e7f);
    EXPECT_EQ(sphere_segments_for(pixels), 256);
}

TEST(Far, NonFiniteRaysEnterNoBox) {
    expect_non_finite_rays_miss<WideBvh<4>>();
    expect_non_finite_rays_miss<Bvh>();
#if defined(__AVX__)
    expect_non_finite_rays_miss<WideBvh<8>>();
#endif
#if defined(__AVX512F__)
    expect_non_finite_rays_miss<WideBvh<16>>();
#endif
}

// Every triangle's box the same point (a mesh collapsed by float far from the origin):
// the build makes one leaf, and a traversal visits it once.
TEST(Far, CollapsedGeometryBuildsOneLeaf) {
    std::vector<Aabb> boxes(5000, Aabb{vec3(1e7f), vec3(1e7f)});
    DefaultWideBvh tree;
    tree.build(boxes, 4);
    EXPECT_EQ(tree.node_count(), 1u);
    float t_max = kInfinity;
    int visits = 0;
    tree.traverse<false>(Ray{vec3(1e7f - 10.0f), vec3(1.0f)}, t_max, [&](std::uint32_t, float&) {
        ++visits;
        return false;
    });
    EXPECT_EQ(visits, 5000);
}

// Two clusters so far apart that the box around both has an area beyond float (the
// collapse's cost for the root is infinite): the tree still holds every box, and a ray
// visits each box it enters.
TEST(Far, ClustersWhoseJointAreaOverflowsStillBuildAWholeTree) {
    std::vector<Aabb> boxes;
    for (int i = 0; i < 3000; ++i) {
        const float side = i % 2 == 0 ? -1.0f : 1.0f;
        const vec3 at(side * 1e19f + 1e15f * static_cast<float>(i % 41),
                      side * 1e19f + 1e15f * static_cast<float>(i % 37),
                      1e15f * static_cast<float>(i % 7));
        boxes.push_back({at, at + vec3(2e15f)});
    }
    DefaultWideBvh tree;
    tree.build(boxes, 4);
    EXPECT_GT(tree.node_count(), 1u);
    std::size_t leaf_prims = 0;
    tree.for_each_leaf([&](std::uint32_t, std::uint32_t count) { leaf_prims += count; });
    EXPECT_EQ(leaf_prims, boxes.size());
    for (const float side : {-1.0f, 1.0f}) {
        const Ray ray{vec3(side * 1e19f + 1.6e16f, side * 1e19f + 1.6e16f, -1e18f), vec3(0, 0, 1)};
        const vec3 inv = 1.0f / ray.dir;
        std::size_t expected = 0;
        for (const Aabb& b : boxes)
            expected += slab_entry(b, ray.origin, inv, kInfinity) < kInfinity;
        ASSERT_GT(expected, 0u);
        std::size_t visited = 0;
        float t_max = kInfinity;
        tree.traverse<false>(ray, t_max, [&](std::uint32_t slot, float&) {
            visited +=
                slab_entry(boxes[tree.order()[slot]], ray.origin, inv, kInfinity) < kInfinity;
            return false;
        });
        EXPECT_EQ(visited, expected) << side;
    }
}

}  // namespace
}  // namespace rt
