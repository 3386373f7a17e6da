// The item buffer's pixels, eight at a time: the shapes' tests across rays
// (core/shape_packets.h) against each ray's own test, the transform of ray lanes, the
// named primitives of a packet against Scene::intersect_primitive, the 3 x 3 check of a
// run of pixels against the pixel's own, and a frame rendered from a perfect item buffer
// against the frame traced from scratch. Every comparison is bit for bit.
#include <gtest/gtest.h>
#include <bit>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <memory>
#include <random>
#include <span>

#include <glm/gtc/matrix_transform.hpp>

#include "core/renderer.h"
#include "core/scene.h"
#include "core/shape_packets.h"
#include "core/small_objects.h"
#include "core/tessellate.h"
#include "test_util.h"

namespace rt {
namespace {

constexpr int kW = kPacketWidth;
constexpr unsigned kAll = (1u << kW) - 1u;

vec3 random_in(std::mt19937& rng, float extent) {
    std::uniform_real_distribution<float> u(-extent, extent);
    return {u(rng), u(rng), u(rng)};
}

// Rays at a shape from near and far, from inside it, grazing, parallel, with no direction,
// and with a NaN: lane k of packet i.
Ray test_ray(std::mt19937& rng, int i, int k, const vec3& target) {
    const vec3 origin = random_in(rng, i % 4 == 0 ? 1.0f : 12.0f);
    vec3 dir = target + random_in(rng, 1.5f) - origin;
    if (i % 7 == 1 && k == 2) dir = vec3(0.0f);
    if (i % 7 == 2 && k == 5 % kW) dir.y = 0.0f;
    if (i % 11 == 3 && k == 1) dir.x = std::nanf("");
    if (i % 13 == 4) dir *= 1e-3f;  // short, unnormalised directions keep t
    return Ray{origin, dir};
}

template <class Shape>
void expect_lanes_match(const Shape& shape, const vec3& target, bool barycentrics) {
    std::mt19937 rng(41);
    std::uniform_real_distribution<float> limit(0.5f, 30.0f);
    int hits = 0;
    for (int i = 0; i < 3000; ++i) {
        std::array<Ray, kW> rays;
        std::array<float, kW> t_max;
        for (int k = 0; k < kW; ++k) {
            rays[k] = test_ray(rng, i, k, target);
            t_max[k] = i % 3 == 0 ? limit(rng) : kInfinity;
        }
        const unsigned lanes = i % 5 == 0 ? ((static_cast<unsigned>(rng()) | 1u) & kAll) : kAll;
        LaneHits<kW> out;
        for (int k = 0; k < kW; ++k) out.t_max[k] = t_max[k];
        const unsigned found =
            intersect_lanes(shape, RayLanes<kW>::gather(rays.data(), lanes), lanes, out);
        EXPECT_EQ(found & ~lanes, 0u);
        for (int k = 0; k < kW; ++k) {
            if (!((lanes >> k) & 1u)) continue;
            Hit alone;
            alone.t = t_max[k];
            const bool hit = shape.intersect(rays[k], alone);
            ASSERT_EQ(((found >> k) & 1u) != 0, hit) << "packet " << i << " lane " << k;
            if (!hit) continue;
            ++hits;
            ASSERT_EQ(out.t[k], alone.t) << "packet " << i << " lane " << k;
            if (!barycentrics) continue;
            ASSERT_EQ(out.b1[k], alone.b1) << "packet " << i << " lane " << k;
            ASSERT_EQ(out.b2[k], alone.b2) << "packet " << i << " lane " << k;
        }
    }
    EXPECT_GT(hits, 3000);
}

TEST(ShapeLanes, PlaneGivesEachRayItsOwnT) {
    expect_lanes_match(Plane{glm::normalize(vec3(0.2f, 1.0f, -0.3f)), -0.5f}, vec3(0, -1, 0),
                       false);
}

TEST(ShapeLanes, SphereGivesEachRayItsOwnT) {
    expect_lanes_match(Sphere{{0.5f, -0.25f, 0.75f}, 1.5f}, vec3(0.5f, -0.25f, 0.75f), false);
}

TEST(ShapeLanes, TriangleGivesEachRayItsOwnTAndBarycentrics) {
    const Triangle tri{{-2, -1, 0.5f}, {2, -1.5f, -0.5f}, {0.25f, 2, 0}};
    expect_lanes_match(tri, vec3(0.1f, 0.0f, 0.0f), true);
}

TEST(RayLanes, ToObjectIsEachRaysOwnTransform) {
    const auto t = Transform::from_matrix(
        glm::scale(glm::rotate(glm::translate(glm::mat4(1.0f), vec3(2.7f, 0.75f, -1.2f)), 0.6f,
                               glm::normalize(vec3(0.2f, 1.0f, 0.4f))),
                   vec3(0.9f, 0.35f, 0.35f)));
    ASSERT_TRUE(t);
    std::mt19937 rng(43);
    for (int i = 0; i < 500; ++i) {
        std::array<Ray, kW> rays;
        for (Ray& r : rays) r = Ray{random_in(rng, 100.0f), random_in(rng, 1.0f)};
        const RayLanes<kW> local = RayLanes<kW>::gather(rays.data(), kAll).to_object(*t);
        for (int k = 0; k < kW; ++k) {
            const Ray alone = t->to_object(rays[k]);
            const Ray lane = local.lane(k);
            for (int a = 0; a < 3; ++a) {
                ASSERT_EQ(lane.origin[a], alone.origin[a]) << i;
                ASSERT_EQ(lane.dir[a], alone.dir[a]) << i;
            }
        }
    }
}

// A scene of every kind of object, some under a transform, the mesh instanced twice.
Scene every_kind_scene() {
    SceneDescription d;
    d.materials.emplace_back();
    TriangleMesh ball = tessellate_unit_sphere(16);
    d.meshes.push_back(std::move(ball));
    const auto moved = [](const vec3& by, float scale) {
        return Transform::from_matrix(glm::scale(
            glm::rotate(glm::translate(glm::mat4(1.0f), by), 0.4f, vec3(0, 1, 0)), vec3(scale)));
    };
    d.objects.push_back(Object{"floor", Plane{{0, 1, 0}, -2}, 0, {}});
    d.objects.push_back(Object{"ball", Sphere{{-2, 0, 0}, 1.0f}, 0, {}});
    d.objects.push_back(Object{"egg", Sphere{{0, 0, 0}, 1.0f}, 0, moved({2, 0, 0}, 0.8f)});
    d.objects.push_back(Object{"tri", Triangle{{-1, 2, -1}, {1, 2, -1}, {0, 3.5f, -1}}, 0, {}});
    d.objects.push_back(Object{"mesh", MeshRef{0, true}, 0, {}});
    d.objects.push_back(Object{"moved mesh", MeshRef{0, true}, 0, moved({0, -1, 2}, 0.7f)});
    d.camera = Camera::look_at({0, 1, 9}, {0, 0, 0}, {0, 1, 0}, 45.0f, 64, 48);
    return Scene(std::move(d));
}

// Rays a packet sends at one object, the triangles named as the item buffer names them:
// for a mesh, runs of the same triangle (tested across the rays) beside single ones. On
// fresh records (as the item buffer's packets are), a ray that misses keeps a fresh one.
TEST(ScenePackets, NamedPrimitivesGiveEachRayItsOwnHit) {
    const Scene scene = every_kind_scene();
    std::mt19937 rng(47);
    int hits = 0;
    for (std::uint32_t object = 0; object < scene.objects.size(); ++object) {
        const Aabb box = scene.object_bounds(scene.objects[object]);
        const vec3 centre = box.empty() ? vec3(0, -2, 0) : 0.5f * (box.lo + box.hi);
        const bool mesh = std::holds_alternative<MeshRef>(scene.objects[object].shape);
        const auto triangles =
            mesh ? static_cast<std::uint32_t>(scene.meshes[0].triangles.size()) : 1u;
        for (int i = 0; i < 400; ++i) {
            std::array<Ray, kW> rays;
            std::array<std::uint32_t, kW> prims;
            const vec3 eye = vec3(0, 1, 9) + random_in(rng, 1.0f);
            const std::uint32_t shared = static_cast<std::uint32_t>(rng()) % triangles;
            for (int k = 0; k < kW; ++k) {
                rays[k] = Ray{eye, centre + random_in(rng, 0.6f) - eye};
                prims[k] = k % 3 == 2 ? static_cast<std::uint32_t>(rng()) % triangles : shared;
            }
            const unsigned lanes = i % 4 == 0 ? ((static_cast<unsigned>(rng()) | 2u) & kAll) : kAll;
            const bool fresh = i % 2 == 1;
            std::array<Hit, kW> together;
            const unsigned found = scene.intersect_primitive_packet(
                object, prims.data(), RayLanes<kW>::gather(rays.data(), kAll), together.data(),
                lanes, fresh);
            EXPECT_EQ(found & ~lanes, 0u);
            for (int k = 0; k < kW; ++k) {
                if (!((lanes >> k) & 1u)) continue;
                Hit alone;
                const bool hit = scene.intersect_primitive(object, prims[k], rays[k], alone);
                ASSERT_EQ(((found >> k) & 1u) != 0, hit) << object << " " << i << " " << k;
                if (!hit) {
                    const Hit none;
                    if (fresh) {
                        ASSERT_EQ(0, std::memcmp(&together[k], &none, sizeof(Hit))) << k;
                    }
                    continue;
                }
                ++hits;
                ASSERT_EQ(together[k].t, alone.t) << object << " " << i << " " << k;
                ASSERT_EQ(together[k].object, object);
                ASSERT_EQ(together[k].prim, alone.prim);
                ASSERT_EQ(together[k].b1, alone.b1);
                ASSERT_EQ(together[k].b2, alone.b2);
            }
        }
    }
    EXPECT_GT(hits, 750 * kW);  // kW rays a packet: 8, or 4 under SSE2
}

// An edge's pixels test a list of objects (Scene::intersect_among): any kinds, in any
// order, some rays already holding a hit nearer or farther than the objects'. Each ray
// gets what testing the objects one by one, alone, gives it (the triangle's weights and a
// mesh's triangle where they belong to the hit), and the rays not asked keep their record.
TEST(ScenePackets, AListOfObjectsGivesEachRayTheClosestHitAmongThem) {
    const Scene scene = every_kind_scene();
    const auto count = static_cast<std::uint32_t>(scene.objects.size());
    std::mt19937 rng(53);
    int hits = 0, kept = 0;
    for (int i = 0; i < 3000; ++i) {
        std::array<std::uint32_t, 8> among;
        const int n = 1 + static_cast<int>(rng() % among.size());
        for (int k = 0; k < n; ++k) among[k] = static_cast<std::uint32_t>(rng()) % count;
        std::array<Ray, kW> rays;
        std::array<Hit, kW> before;
        const vec3 eye = vec3(0, 1, 9) + random_in(rng, 1.0f);
        for (int k = 0; k < kW; ++k) {
            const Aabb box = scene.object_bounds(scene.objects[among[rng() % n]]);
            const vec3 centre = box.empty() ? vec3(0, -2, 0) : 0.5f * (box.lo + box.hi);
            rays[k] = Ray{eye, centre + random_in(rng, 1.2f) - eye};
            if (rng() % 3 == 0)  // an earlier hit, somewhere along the ray
                before[k] = Hit{std::uniform_real_distribution<float>(4.0f, 14.0f)(rng), count + 1,
                                7, 0.25f, 0.5f};
        }
        const unsigned lanes = (static_cast<unsigned>(rng()) & kAll) | 1u;
        std::array<Hit, kW> together = before;
        const unsigned found = scene.intersect_among(
            among.data(), n, RayLanes<kW>::gather(rays.data(), kAll), together.data(), lanes);
        for (int k = 0; k < kW; ++k) {
            if (!((lanes >> k) & 1u)) {
                ASSERT_EQ(0, std::memcmp(&together[k], &before[k], sizeof(Hit))) << i << " " << k;
                continue;
            }
            Hit alone = before[k];
            bool hit = false;
            for (int j = 0; j < n; ++j) hit |= scene.intersect_object(among[j], rays[k], alone);
            ASSERT_EQ(((found >> k) & 1u) != 0, hit) << i << " " << k;
            ASSERT_EQ(together[k].t, alone.t) << i << " " << k;
            ASSERT_EQ(together[k].object, alone.object) << i << " " << k;
            if (!hit) {
                ++kept;
                continue;
            }
            ++hits;
            const auto& shape = scene.objects[alone.object].shape;
            if (std::holds_alternative<MeshRef>(shape)) {
                ASSERT_EQ(together[k].prim, alone.prim) << i << " " << k;
            }
            if (std::holds_alternative<MeshRef>(shape) || std::holds_alternative<Triangle>(shape)) {
                ASSERT_EQ(together[k].b1, alone.b1) << i << " " << k;
                ASSERT_EQ(together[k].b2, alone.b2) << i << " " << k;
            }
        }
    }
    EXPECT_GT(hits, 1000 * kW);
    EXPECT_GT(kept, 100 * kW);
}

// `ib` (ids and triangles apart) with its triangles packed below the object ids, as the
// raster's one target holds them where they fit, or with the objects alone (`bits` 0: the
// triangles dropped, as for a scene without a mesh).
ItemBuffer packed(const ItemBuffer& ib, int bits) {
    ItemBuffer out = ib;
    out.resize(ib.width, ib.height, bits, false);
    for (std::size_t i = 0; i < ib.ids.size(); ++i) {
        EXPECT_LT(static_cast<std::uint64_t>(ib.prim[i]), std::uint64_t{1} << bits);
        out.ids[i] = ib.ids[i] << bits | (bits > 0 ? ib.prim[i] : 0u);
    }
    return out;
}

// Small regions of ids, runs of every length from every column, the image's edges too;
// the same with triangles of their own packed below the ids (neighbours that name one
// object but not one triangle are inside the object's region).
TEST(ItemBuffer, ARunsCheckIsEachPixelsOwn) {
    ItemBuffer ib(37, 11);
    std::mt19937 rng(53);
    for (int round = 0; round < 20; ++round) {
        for (std::uint32_t& id : ib.ids) id = 0;
        for (int blob = 0; blob < 6; ++blob) {
            const int x0 = static_cast<int>(rng() % 37), y0 = static_cast<int>(rng() % 11);
            const int w = 1 + static_cast<int>(rng() % 12), h = 1 + static_cast<int>(rng() % 6);
            const std::uint32_t id = 1 + static_cast<std::uint32_t>(rng() % 3);
            for (int y = y0; y < std::min(11, y0 + h); ++y)
                for (int x = x0; x < std::min(37, x0 + w); ++x) ib.ids[ib.index(x, y)] = id;
        }
        for (std::uint32_t& t : ib.prim) t = static_cast<std::uint32_t>(rng() % 256);
        const ItemBuffer with_triangles = packed(ib, 8);
        for (int y = 0; y < ib.height; ++y) {
            for (int x = 0; x < ib.width; ++x) {
                for (int n = 1; n <= 20 && x + n <= ib.width; ++n) {
                    unsigned own = 0, same = 0;
                    const std::uint32_t id = ib.ids[ib.index(x, y)];
                    for (int k = 0; k < n; ++k) {
                        own |= static_cast<unsigned>(ib.interior(x + k, y)) << k;
                        same |= static_cast<unsigned>(ib.ids[ib.index(x + k, y)] == id) << k;
                    }
                    ASSERT_EQ(ib.interior_run(x, y, n), own) << x << "," << y << " n " << n;
                    ASSERT_EQ(ib.same_object_run(ib.index(x, y), n, id), same);
                    ASSERT_EQ(with_triangles.interior_run(x, y, n), own) << x << "," << y;
                    ASSERT_EQ(with_triangles.same_object_run(ib.index(x, y), n, id), same);
                }
            }
        }
    }
}

// A frame from a perfect item buffer is the frame from scratch, bit for bit (at a size
// that leaves short runs at the tiles' right ends): the pixels on edges tested against
// the objects named around them, the others against what they name.
TEST(ItemBuffer, AFrameFromAPerfectItemBufferIsTheFrameFromScratch) {
    for (const std::string& name : test::shipped_scene_names()) {
        const Scene scene(test::shipped_scene(name, 101, 57));
        const Camera& camera = scene.camera;
        const ItemBuffer ib = test::traced_item_buffer(scene);
        RenderOptions options;
        options.threads = 2;
        RenderStats with_stats;
        const Image from_scratch = render(scene, options);
        const Image with = render(scene, options, &with_stats, {}, {}, &ib);
        EXPECT_EQ(with.pixels, from_scratch.pixels) << name;
        // The layouts the raster reads back (gl::IdLayout): the triangles packed below the
        // ids, in the bits the ids leave, where the scene has a mesh; the objects alone
        // where it has none.
        bool meshes = false;
        for (const Object& o : scene.objects) meshes |= std::holds_alternative<MeshRef>(o.shape);
        const int bits = meshes ? 32 - static_cast<int>(std::bit_width(scene.objects.size())) : 0;
        const ItemBuffer as_read = packed(ib, bits);
        RenderStats packed_stats;
        const Image from_packed = render(scene, options, &packed_stats, {}, {}, &as_read);
        EXPECT_EQ(from_packed.pixels, from_scratch.pixels) << name << " packed";
        // The same pixels settled by what they name (a wrong triangle would miss, and its
        // pixel would still be found, through the objects around it).
        EXPECT_EQ(packed_stats.item_buffer_fallbacks, with_stats.item_buffer_fallbacks) << name;
        EXPECT_LT(with_stats.item_buffer_fallbacks, camera.cols * camera.rows * 3 / 4) << name;
        EXPECT_GT(with_stats.item_buffer_fallbacks, 0u) << name;
    }
}

// Where the raster and the tracer disagree on an edge (the raster's spheres are
// tessellated, an edge is rounded its own way), the pixel's own id is wrong but the
// object its ray meets is named next to it: a pixel on an edge is tested against every
// object named around it. Here every edge pixel of a perfect item buffer names nothing;
// each pixel still on an edge (one of the four beside it names another object) whose
// object is still named in its 3 x 3 block gets its colour from scratch.
TEST(ItemBuffer, AnEdgePixelFindsTheObjectNamedNextToIt) {
    for (const char* name : {"whitted.json", "cornell.json", "tutorial.json"}) {
        const Scene scene(test::shipped_scene(name, 160, 90));
        const Camera& camera = scene.camera;
        const ItemBuffer perfect = test::traced_item_buffer(scene);
        ItemBuffer blanked = perfect;
        for (int y = 0; y < camera.rows; ++y)
            for (int x = 0; x < camera.cols; ++x)
                if (!perfect.interior(x, y)) blanked.ids[blanked.index(x, y)] = ItemBuffer::kEmpty;
        RenderOptions options;
        options.threads = 2;
        const Image from_scratch = render(scene, options);
        const Image with = render(scene, options, nullptr, {}, {}, &blanked);
        int edges = 0;
        for (int y = 0; y < camera.rows; ++y) {
            for (int x = 0; x < camera.cols; ++x) {
                const std::uint32_t id = perfect.object_id(perfect.index(x, y));
                if (perfect.interior(x, y) || blanked.interior(x, y) || id == ItemBuffer::kEmpty)
                    continue;
                bool named = false;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx)
                        if (x + dx >= 0 && y + dy >= 0 && x + dx < camera.cols &&
                            y + dy < camera.rows)
                            named |= blanked.ids[blanked.index(x + dx, y + dy)] == id;
                if (!named) continue;
                ++edges;
                ASSERT_EQ(with.at(x, y), from_scratch.at(x, y)) << name << " " << x << "," << y;
            }
        }
        EXPECT_GT(edges, 100) << name;
    }
}

// A sphere under a couple of pixels across may cover pixel centres the raster's
// tessellation does not (many_spheres far off), and then nothing around names it: the
// renderer tests such objects itself where their screen boxes lie (core/small_objects.h).
// Here the item buffer is a perfect one of the scene without its small spheres, as if the
// raster had missed every one: the frame must still be the frame from scratch.
TEST(ItemBuffer, AnObjectTooSmallForTheRasterIsFoundWhereItLies) {
    SceneDescription d;
    d.materials.emplace_back();
    d.objects.push_back(Object{"floor", Plane{{0, 1, 0}, -2}, 0, {}});
    d.objects.push_back(Object{"ball", Sphere{{-2, 0, -1}, 1.0f}, 0, {}});
    d.lights.push_back(Light{Light::Type::kPoint, {3, 6, 6}, {0, -1, 0}, vec3(1.0f)});
    d.camera = Camera::look_at({0, 1, 9}, {0, 0, 0}, {0, 1, 0}, 45.0f, 64, 48);
    SceneDescription without_small = d;
    for (int i = 0; i < 6; ++i)  // about 1.4 pixels across, some in front of the ball
        for (int j = 0; j < 4; ++j)
            d.objects.push_back(Object{"speck",
                                       Sphere{{-3.1f + 1.07f * static_cast<float>(i),
                                               -1.3f + 0.83f * static_cast<float>(j), 1.0f},
                                              0.1f},
                                       0,
                                       {}});
    const Scene scene(std::move(d)), missed(std::move(without_small));
    const SmallObjects small(scene, scene.camera);
    EXPECT_EQ(small.size(), 24u);  // the specks, not the ball, nor the floor
    ItemBuffer ib = test::traced_item_buffer(missed);
    const ItemBuffer perfect = test::traced_item_buffer(scene);
    int speck_pixels = 0;
    for (std::size_t i = 0; i < perfect.ids.size(); ++i) speck_pixels += perfect.ids[i] > 2;
    EXPECT_GT(speck_pixels, 10);
    RenderOptions options;
    options.threads = 2;
    const Image from_scratch = render(scene, options);
    const Image with = render(scene, options, nullptr, {}, {}, &ib);
    int differ = 0;
    for (std::size_t i = 0; i < with.pixels.size(); ++i)
        differ += with.pixels[i] != from_scratch.pixels[i];
    EXPECT_EQ(differ, 0);
}

// A sphere cut by the image's edge may reach into the outermost column or row by less than
// the raster's quarter pixel: no pixel of the image names it, and the pixels it covers
// there have no neighbour beyond the edge to put them on an edge (many_spheres: two pixels
// of its right-hand column). Here, on each side in turn, the sphere comes in from afar
// until it covers pixels of the outermost column or row but none of the next, and the
// item buffer is a perfect one of the scene without it, as if the raster had missed it:
// the frame must still be the frame from scratch.
TEST(ItemBuffer, ASphereCutByTheImagesEdgeIsFoundAlongIt) {
    const auto scene_with = [](vec3 centre, bool with_sphere) {
        SceneDescription d;
        d.materials.emplace_back();
        d.objects.push_back(Object{"floor", Plane{{0, 1, 0}, -4}, 0, {}});
        if (with_sphere) d.objects.push_back(Object{"ball", Sphere{centre, 1.0f}, 0, {}});
        d.lights.push_back(Light{Light::Type::kPoint, {3, 6, 6}, {0, -1, 0}, vec3(1.0f)});
        d.camera = Camera::look_at({0, 0, 9}, {0, 0, 0}, {0, 1, 0}, 45.0f, 64, 48);
        return std::make_unique<Scene>(std::move(d));
    };
    // The ball's pixels in column (or row) `at` of the image.
    const auto ball_pixels = [](const ItemBuffer& ib, bool column, int at) {
        int n = 0;
        for (int k = 0; k < (column ? ib.height : ib.width); ++k)
            n += ib.object_id(column ? ib.index(at, k) : ib.index(k, at)) == 2;
        return n;
    };
    struct Side {
        const char* name;
        // Far out, beyond the side (and off the horizon, where the floor's pixels and the
        // sky's would put the ball's on an edge).
        vec3 from;
        bool column;  // a side column, or the top or bottom row
        int outermost, next;
    };
    const Side sides[] = {{"right", {8, 1.5f, 0}, true, 63, 62},  // above the horizon
                          {"left", {-8, 1.5f, 0}, true, 0, 1},
                          {"top", {0, 6, 0}, false, 47, 46},
                          {"bottom", {0, -6, 0}, false, 0, 1}};
    RenderOptions options;
    options.threads = 2;
    for (const Side& side : sides) {
        vec3 centre = side.from;
        const vec3 step = -0.002f * glm::normalize(side.from);
        std::unique_ptr<Scene> scene;
        for (int k = 0; k < 2000; ++k, centre += step) {
            scene = scene_with(centre, true);
            if (ball_pixels(test::traced_item_buffer(*scene), side.column, side.outermost) > 0)
                break;
        }
        const ItemBuffer perfect = test::traced_item_buffer(*scene);
        const int pixels = ball_pixels(perfect, side.column, side.outermost);
        ASSERT_GT(pixels, 0) << side.name << ": the ball never reaches the image";
        ASSERT_EQ(ball_pixels(perfect, side.column, side.next), 0) << side.name;
        ItemBuffer ib = test::traced_item_buffer(*scene_with(centre, false));  // named nowhere
        const Image from_scratch = render(*scene, options);
        const Image with = render(*scene, options, nullptr, {}, {}, &ib);
        int differ = 0;
        for (std::size_t i = 0; i < with.pixels.size(); ++i)
            differ += with.pixels[i] != from_scratch.pixels[i];
        EXPECT_EQ(differ, 0) << side.name << ": of " << pixels << " pixels of the ball";
    }
}

// A box seen from just in front of it (a corner 1e-30 before the eye's plane) projects
// some 1e33 pixels out: past what an int holds. A sphere under a transform (listed by its
// box) across the whole image so must be listed along every side, its span clamped, not
// cast from such a float (undefined; on x86 it wrapped to no pixels at all).
TEST(ItemBuffer, ASphereSeenFromJustInFrontOfItsBoxIsListedAlongTheEdges) {
    SceneDescription d;
    d.materials.emplace_back();
    // Its box spans x -1.5 .. 0.5, y -1 .. 1, z -2 .. 0; the eye sits 1e-30 in front of z 0.
    d.objects.push_back(Object{"ball", Sphere{{-0.5f, 0.0f, -1.0f}, 1.0f}, 0,
                               Transform::from_matrix(glm::mat4(1.0f))});
    d.camera = Camera::look_at({0, 0, 1e-30f}, {0, 0, -1}, {0, 1, 0}, 45.0f, 64, 48);
    const Scene scene(std::move(d));
    const SmallObjects small(scene, scene.camera);
    const auto lists_ball = [](std::span<const SmallObjects::Span> spans) {
        return std::any_of(spans.begin(), spans.end(),
                           [](const SmallObjects::Span& s) { return s.object == 0; });
    };
    for (int y = 0; y < 48; ++y) EXPECT_TRUE(lists_ball(small.side(y))) << "row " << y;
    EXPECT_TRUE(lists_ball(small.row(0)));
    EXPECT_TRUE(lists_ball(small.row(47)));
}

}  // namespace
}  // namespace rt
