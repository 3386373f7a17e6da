// The item buffer's primary step (core/item_buffer_step.cpp) where the ids are wrong: a
// run of pixels whose named object its rays miss, a run that names one object but lies on
// an edge, a mesh named around a pixel. Each pixel must get the colour a trace from
// scratch gives it. The scene: a floor, a box (a mesh) standing on it, and a ball off to
// one side that the pixels checked here never see.
#include <gtest/gtest.h>

#include <utility>

#include "core/renderer.h"
#include "core/scene.h"
#include "test_util.h"

namespace rt {
namespace {

constexpr std::uint32_t kFloor = 1, kBox = 2, kBall = 3;  // object index + 1, as the ids hold them
// A run inside the box: kRunX .. kRunX + kPacketWidth - 1 (eight pixels under AVX, four
// with SSE alone: the tests below cover one run, whatever its width).
constexpr int kRunX = 24, kRunY = 24;
constexpr int kRunEnd = kRunX + kPacketWidth - 1;  // its last pixel

Scene box_scene() {
    SceneDescription d;
    d.materials.emplace_back();
    d.materials.emplace_back();
    d.materials.back().kd = vec3(0.1f, 0.9f, 0.2f);
    d.meshes.push_back(
        test::box_mesh(vec3(-1.5f, -2, -0.5f), vec3(1.5f, 1, 0.5f), test::Winding::kOutward));
    d.objects.push_back(Object{"floor", Plane{{0, 1, 0}, -2}, 0, {}});
    d.objects.push_back(Object{"box", MeshRef{0, true}, 1, {}});
    d.objects.push_back(Object{"ball", Sphere{{6, 4, -8}, 0.5f}, 0, {}});
    d.lights.push_back(Light{Light::Type::kPoint, {3, 6, 6}, {0, -1, 0}, vec3(1.0f)});
    d.camera = Camera::look_at({0, 3, 9}, {0, 0, 0}, {0, 1, 0}, 45.0f, 64, 48);
    return Scene(std::move(d));
}

// The pixels of row kRunY from x0 to x1 (inclusive) as a trace from scratch colours them.
void expect_row_as_traced(const Scene& scene, const ItemBuffer& ids, int x0, int x1) {
    RenderOptions options;
    options.threads = 1;
    const Image from_scratch = render(scene, options);
    const Image with = render(scene, options, nullptr, {}, {}, &ids);
    for (int x = x0; x <= x1; ++x) EXPECT_EQ(with.at(x, kRunY), from_scratch.at(x, kRunY)) << x;
}

// In a run with an edge, the spheres and planes around are tested once for all its
// pixels, a mesh only where what a pixel names did not meet it. Here a pixel inside a box
// (a mesh) and its four neighbours name a sphere that lies elsewhere, and a pixel of the
// run names the floor behind the box: the floor meets the pixel's ray, the sphere does
// not, so the pixel is not settled by what it names, and the box, named around it, is
// still tested (the floor alone would show through the box).
TEST(ItemBuffer, APixelWhoseNamedObjectMissesStillMeetsTheMeshAroundIt) {
    const Scene scene = box_scene();
    const ItemBuffer ib = test::traced_item_buffer(scene);
    // Inside runs 24 .. 31 and 32 .. 39 (of four: 28 .. 31 and 36 .. 39).
    for (const int x : {28, 36}) {
        ASSERT_EQ(ib.ids[ib.index(x, kRunY)], kBox);
        ItemBuffer named = ib;
        for (const auto& [dx, dy] : {std::pair{0, 0}, {-1, 0}, {1, 0}, {0, -1}, {0, 1}})
            named.ids[named.index(x + dx, kRunY + dy)] = kBall;
        named.ids[named.index(x + 3, kRunY)] = kFloor;
        Hit floor;
        ASSERT_TRUE(scene.intersect_object(0, scene.camera.ray(x, kRunY), floor));  // behind
        expect_row_as_traced(scene, named, x, x);
    }
}

// A whole run inside one object's region is tested against that object alone, with the
// other such runs (InsideRuns); where its rays miss it (here the run, its neighbours and
// the rows above and below name the ball, which no ray of theirs meets), the run goes the
// way of a run with an edge, and the box, named at one corner of the block around it, is
// found.
TEST(ItemBuffer, ARunInsideTheRegionOfAnObjectItsRaysMissIsTestedAgainstWhatIsAround) {
    const Scene scene = box_scene();
    ItemBuffer ib = test::traced_item_buffer(scene);
    for (int x = kRunX - 1; x <= kRunEnd + 1; ++x) {
        for (int y = kRunY - 1; y <= kRunY + 1; ++y) {
            ASSERT_EQ(ib.ids[ib.index(x, y)], kBox) << x << "," << y;
            Hit ball;
            ASSERT_FALSE(scene.intersect_object(2, scene.camera.ray(x, y), ball));
            ib.ids[ib.index(x, y)] = kBall;
        }
    }
    ib.ids[ib.index(kRunX - 1, kRunY - 1)] = kBox;  // a diagonal neighbour: the run stays whole
    for (int x = kRunX; x <= kRunEnd; ++x) ASSERT_TRUE(ib.interior(x, kRunY)) << x;
    expect_row_as_traced(scene, ib, kRunX, kRunEnd);
}

// A run whose pixels all name one object but whose neighbours above and below name
// another is on an edge: it is not taken as inside a region, and each pixel is tested
// against everything named around it. Here the run names the floor, seen behind the box
// that the rows above and below name: the box, nearer, is what its rays meet.
TEST(ItemBuffer, ARunThatNamesOneObjectOnAnEdgeIsTestedAgainstWhatIsAround) {
    const Scene scene = box_scene();
    ItemBuffer ib = test::traced_item_buffer(scene);
    for (int x = kRunX; x <= kRunEnd; ++x) {
        ASSERT_EQ(ib.ids[ib.index(x, kRunY)], kBox) << x;
        Hit floor;
        ASSERT_TRUE(scene.intersect_object(0, scene.camera.ray(x, kRunY), floor)) << x;
        ib.ids[ib.index(x, kRunY)] = kFloor;
    }
    expect_row_as_traced(scene, ib, kRunX, kRunEnd);
}

}  // namespace
}  // namespace rt
