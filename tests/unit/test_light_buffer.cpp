// The light buffer (core/light_buffer.h) and the shadow feelers that use it: a feeler's
// cell must list every object its segment to the light passes through, so that a
// feeler answered from its cell gets exactly the traversal's answer; and a feeler
// skips the surface it leaves only where it cannot meet it again.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <limits>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "core/light_buffer.h"
#include "core/scene.h"
#include "core/tracer.h"
#include "test_util.h"

namespace rt {
namespace {

using dvec3 = glm::dvec3;

// Does the segment from `a` to `b` meet the closed box? In double, the exact question
// the buffer must answer conservatively.
bool segment_meets(const dvec3& a, const dvec3& b, const Aabb& box) {
    double enter = 0.0, leave = 1.0;
    for (int k = 0; k < 3; ++k) {
        const double d = b[k] - a[k], lo = box.lo[k], hi = box.hi[k];
        if (d == 0.0) {
            if (a[k] < lo || a[k] > hi) return false;
            continue;
        }
        double t0 = (lo - a[k]) / d, t1 = (hi - a[k]) / d;
        if (t0 > t1) std::swap(t0, t1);
        enter = std::max(enter, t0);
        leave = std::min(leave, t1);
    }
    return enter <= leave;
}

bool listed(const LightBuffer::Cell& cell, std::uint32_t slot) {
    return std::find(cell.begin, cell.end, slot) != cell.end;
}

using test::random_point;

// Boxes of every kind around a light at `l`: small and far, thin, flat, reaching across
// the light's own planes (so a face sees them to its edge), holding the light.
std::vector<Aabb> awkward_boxes(std::mt19937& rng, const vec3& l) {
    std::uniform_real_distribution<float> size(0.01f, 3.0f);
    std::vector<Aabb> boxes;
    for (int i = 0; i < 5; ++i) {
        const vec3 c = l + random_point(rng, 8.0f), h{size(rng), size(rng), size(rng)};
        boxes.push_back(Aabb{c - h, c + h});
    }
    boxes.push_back(Aabb{l + vec3(-4, 0.5f, -0.2f), l + vec3(4, 0.6f, 0.3f)});  // across x = l.x
    boxes.push_back(Aabb{l + vec3(1, -2, -3), l + vec3(1, 2, 3)});              // flat, x = l.x + 1
    boxes.push_back(Aabb{l - vec3(0.5f), l + vec3(0.5f)});                      // holds the light
    return boxes;
}

TEST(LightBuffer, EverySegmentThroughABoxFindsItInItsCell) {
    std::mt19937 rng(3);
    int met = 0;
    for (int scene = 0; scene < 40; ++scene) {
        const vec3 light = scene % 4 == 0 ? vec3(0.0f) : random_point(rng, 50.0f);
        const std::vector<Aabb> boxes = awkward_boxes(rng, light);
        const LightBuffer buffer(light, boxes);
        for (int i = 0; i < 3000; ++i) {
            // Origins all around, and on the cube's edges and diagonals (|q_a| = |q_b|).
            vec3 o = light + random_point(rng, 12.0f);
            if (i % 5 == 0) o.y = light.y + (o.x - light.x);
            if (i % 7 == 0) o.z = light.z - (o.x - light.x);
            const LightBuffer::Cell cell = buffer.cell(o);
            ASSERT_FALSE(cell.crowded) << "at most kMaxList boxes";
            for (std::uint32_t slot = 0; slot < boxes.size(); ++slot) {
                if (!segment_meets(dvec3(o), dvec3(light), boxes[slot])) continue;
                ++met;
                ASSERT_TRUE(listed(cell, slot))
                    << "scene " << scene << ", origin " << i << ", box " << slot;
            }
        }
    }
    EXPECT_GT(met, 20000);
}

// Box faces on the cells' own boundaries, and feelers through the boxes' corners: the
// rounding of a feeler's direction must not carry it into the neighbouring cell.
TEST(LightBuffer, FeelersThroughCornersOnCellBoundariesFindTheBox) {
    std::mt19937 rng(8);
    std::uniform_real_distribution<float> beyond(1.01f, 9.0f);
    std::uniform_int_distribution<int> cell(-LightBuffer::kCells / 2, LightBuffer::kCells / 2);
    const float step = 2.0f / LightBuffer::kCells;  // a cell's width on a face at distance 1
    int met = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        const vec3 light = trial % 2 ? vec3(0.0f) : random_point(rng, 100.0f);
        const float u = static_cast<float>(cell(rng)) * step,
                    v = static_cast<float>(cell(rng)) * step;
        // A box whose near corner lies at (1, u, v) from the light, on face +x, -y or +z.
        vec3 corner{1.0f, u, v};
        if (trial % 3 == 1) corner = {u, -1.0f, v};
        if (trial % 3 == 2) corner = {u, v, 1.0f};
        const vec3 lo = light + corner, far = lo + vec3(0.5f);
        const Aabb box{glm::min(lo, far), glm::max(lo, far)};
        const std::vector<Aabb> boxes{box};
        const LightBuffer buffer(light, boxes);
        const vec3 o = light + beyond(rng) * (box.lo - light);  // through the corner
        if (!segment_meets(dvec3(o), dvec3(light), box)) continue;
        ++met;
        ASSERT_TRUE(listed(buffer.cell(o), 0)) << "trial " << trial;
    }
    EXPECT_GT(met, 1000);
}

// A directional light's grid: a feeler runs from its origin against the light's
// direction, without end; every box on that half-line must be in its cell.
TEST(LightBuffer, DirectionalFeelersFindEveryBoxUpstream) {
    std::mt19937 rng(13);
    int met = 0, outside = 0;
    const vec3 directions[] = {{0, -1, 0},
                               {1, 0, 0},
                               {0, 0, -1},
                               {0.5f, -0.8f, 0.3f},
                               {-0.5f, 0.2f, 0.84f}};  // axes, and |x| about the frame's switch
    for (int scene = 0; scene < 30; ++scene) {
        const vec3 d = scene < 5 ? directions[scene] : random_point(rng, 1.0f);
        const Light light{Light::Type::kDirectional, {}, glm::normalize(d), vec3(1.0f)};
        const vec3 centre = scene % 3 == 0 ? vec3(2000, -500, 800) : vec3(0.0f);
        std::vector<Aabb> boxes = awkward_boxes(rng, centre);
        const auto buffer = LightBuffer::make(light, boxes);
        ASSERT_TRUE(buffer.has_value());
        for (int i = 0; i < 3000; ++i) {
            const vec3 o = centre + random_point(rng, i % 10 == 0 ? 200.0f : 12.0f);
            const dvec3 far = dvec3(o) - 1e5 * dvec3(light.direction);  // beyond every box
            const LightBuffer::Cell cell = buffer->cell(o);
            ASSERT_FALSE(cell.crowded);
            outside += cell.begin == cell.end;
            for (std::uint32_t slot = 0; slot < boxes.size(); ++slot) {
                if (!segment_meets(dvec3(o), far, boxes[slot])) continue;
                ++met;
                ASSERT_TRUE(listed(cell, slot))
                    << "scene " << scene << ", origin " << i << ", box " << slot;
            }
        }
    }
    EXPECT_GT(met, 5000);
    EXPECT_GT(outside, 1000);  // origins whose feelers no box shadows: empty cells
    const std::vector<Aabb> unbounded{Aabb{vec3(0.0f), vec3(kInfinity, 1, 1)}};
    EXPECT_FALSE(
        LightBuffer::make(Light{Light::Type::kDirectional, {}, {0, -1, 0}, vec3(1.0f)}, unbounded)
            .has_value())
        << "a box beyond float's reach: no grid";
}

TEST(LightBuffer, CrowdedAndEmptyCells) {
    std::vector<Aabb> boxes;
    for (std::uint32_t i = 0; i <= LightBuffer::kMaxList; ++i)  // one more than a cell lists
        boxes.push_back(Aabb{vec3(5.0f + static_cast<float>(i), -0.1f, -0.1f),
                             vec3(5.5f + static_cast<float>(i), 0.1f, 0.1f)});
    const LightBuffer buffer(vec3(0.0f), boxes);
    EXPECT_TRUE(buffer.cell(vec3(20, 0, 0)).crowded);
    const LightBuffer::Cell empty = buffer.cell(vec3(-20, 0, 0));
    EXPECT_FALSE(empty.crowded);
    EXPECT_EQ(empty.begin, empty.end);
    EXPECT_GT(buffer.crowded_cells(), 0u);
    EXPECT_GT(buffer.empty_cells(), buffer.crowded_cells());
    EXPECT_TRUE(buffer.cell(vec3(0.0f)).crowded) << "on the light: no direction, traverse";
    const float inf = kInfinity;
    EXPECT_TRUE(buffer.cell(vec3(inf, 0, 0)).crowded);
}

TEST(LightBuffer, OneTooCostlyToBuildIsNotBuilt) {
    // Boxes around the light cover every cell of every face: 6 x 64 x 64 visits each.
    const auto around = [](int n) { return std::vector<Aabb>(n, Aabb{vec3(-1.0f), vec3(1.0f)}); };
    const std::size_t per_box = 6 * LightBuffer::kCells * LightBuffer::kCells;
    const int fits = static_cast<int>(LightBuffer::kMaxVisits / per_box);
    const Light light{Light::Type::kPoint, vec3(0.0f), {}, vec3(1.0f)};
    EXPECT_TRUE(LightBuffer::make(light, around(fits)).has_value());
    EXPECT_FALSE(LightBuffer::make(light, around(fits + 1)).has_value());
}

TEST(LightBuffer, ABoxBeyondFloatsReachIsInEveryCell) {
    const std::vector<Aabb> boxes{Aabb{vec3(1, 1, 1), vec3(kInfinity, 2, 2)}};
    const LightBuffer buffer(vec3(0.0f), boxes);
    std::mt19937 rng(1);
    for (int i = 0; i < 1000; ++i) EXPECT_TRUE(listed(buffer.cell(random_point(rng, 10.0f)), 0));
}

// A scene with a bit of everything that casts shadows: spheres (some transformed), a
// triangle, a transformed mesh, planes, and more objects in some directions than a cell
// lists; two point lights (one among the objects) and a directional one; all of it
// moved by `shift` (far from the origin, float's steps are coarse).
SceneDescription shadow_casters(std::mt19937& rng, vec3 shift) {
    SceneDescription desc;
    desc.materials.push_back(Material{});
    std::uniform_real_distribution<float> radius(0.3f, 1.5f);
    for (int i = 0; i < 14; ++i) {
        Object o{"s", Sphere{random_point(rng, 6.0f), radius(rng)}, 0, {}};
        if (i % 3 == 0)
            o.transform = Transform::from_matrix(
                glm::mat4(glm::mat3(vec3(1.5f, 0.2f, 0), vec3(0, 0.5f, 0.1f), vec3(0.3f, 0, 1))));
        desc.objects.push_back(o);
    }
    // Columns of small spheres along a feeler's way to each light: more than a cell lists
    // (crowded cells, where feelers traverse the tree).
    const vec3 towards_sun = -glm::normalize(vec3(-1, -2, -1));
    for (int i = 1; i <= 10; ++i) {
        const auto k = static_cast<float>(i);
        desc.objects.push_back(Object{"column", Sphere{vec3(4, 12 - 1.6f * k, 5), 0.3f}, 0, {}});
        desc.objects.push_back(
            Object{"column", Sphere{vec3(-3, -4, 2) + 1.5f * k * towards_sun, 0.3f}, 0, {}});
        desc.objects.push_back(Object{
            "column", Sphere{vec3(0.5f) + (0.8f + 0.7f * k) * vec3(0.6f, -0.8f, 0), 0.2f}, 0, {}});
    }
    desc.objects.push_back(Object{"tri", Triangle{{-3, -2, 1}, {3, -2, 2}, {0, 3, 0}}, 0, {}});
    desc.meshes.push_back(test::box_mesh(vec3(-1), vec3(1), test::Winding::kOutward));
    Object box{"box", MeshRef{0, true}, 0, {}};
    box.transform = Transform::from_matrix(glm::translate(glm::mat4(1.0f), vec3(2, 1, -3)));
    desc.objects.push_back(box);
    desc.objects.push_back(Object{"floor", Plane{{0, 1, 0}, -7}, 0, {}});
    desc.objects.push_back(Object{"wall", Plane{glm::normalize(vec3(1, 0, 1)), -9}, 0, {}});
    desc.lights.push_back(Light{Light::Type::kPoint, {4, 12, 5}, {}, vec3(1.0f)});
    desc.lights.push_back(Light{Light::Type::kPoint, {0.5f, 0.5f, 0.5f}, {}, vec3(1.0f)});
    desc.lights.push_back(
        Light{Light::Type::kDirectional, {}, glm::normalize(vec3(-1, -2, -1)), vec3(1.0f)});
    const glm::mat4 move = glm::translate(glm::mat4(1.0f), shift);
    for (Object& o : desc.objects) {
        if (auto* plane = std::get_if<Plane>(&o.shape)) {
            plane->offset += glm::dot(plane->normal, shift);
            continue;
        }
        o.transform =
            Transform::from_matrix(move * (o.transform ? o.transform->m : glm::mat4(1.0f)));
    }
    for (Light& l : desc.lights) l.position += shift;
    return desc;
}

// Any hit in (0, t_max) on any object, each tested alone: the answer without a buffer,
// a tree or a skipped surface.
bool blocked_by_any(const Scene& scene, const Ray& feeler, float t_max) {
    for (std::uint32_t o = 0; o < scene.objects.size(); ++o) {
        Hit h;
        h.t = t_max;
        if (scene.intersect_object(o, feeler, h)) return true;
    }
    return false;
}

TEST(ShadowFeelers, AnswerAsTestingEveryObject) {
    std::mt19937 rng(21);
    int blocked = 0, feelers = 0;
    for (int variant = 0; variant < 4; ++variant) {
        const vec3 shift = variant == 3 ? vec3(3000, -2000, 5000) : vec3(0.0f);
        const Scene scene(shadow_casters(rng, shift));
        for (int i = 0; i < 4000; ++i) {
            // Feelers from surface points, as the tracer sends them (the surface it leaves
            // skipped where it may be), and from points anywhere.
            const Ray ray{shift + random_point(rng, 12.0f), random_point(rng, 1.0f)};
            Hit hit;
            if (!scene.intersect(ray, hit)) continue;
            const SurfacePoint sp = scene.surface(ray, hit);
            const vec3 from_surface = offset_ray_origin(sp.p, sp.geometric_normal);
            for (std::size_t l = 0; l < scene.lights.size(); ++l) {
                for (const bool on_surface : {true, false}) {
                    const vec3 p = on_surface ? from_surface : shift + random_point(rng, 10.0f);
                    vec3 dir;
                    const float t_max = scene.lights[l].feeler(p, dir);
                    if (on_surface && glm::dot(dir, sp.geometric_normal) <= 0.0f) continue;
                    const Ray feeler{p, dir};
                    const bool expected = blocked_by_any(scene, feeler, t_max);
                    const std::uint32_t leaving = on_surface ? sp.cannot_meet_again : kNoObject;
                    ASSERT_EQ(scene.occluded(feeler, t_max, l, leaving), expected)
                        << "variant " << variant << ", ray " << i << ", light " << l
                        << (on_surface ? ", from the surface" : ", from anywhere");
                    blocked += expected;
                    ++feelers;
                }
            }
        }
    }
    // Rays that are not finite: what the tree answers (nothing bounded meets them).
    const Scene scene(shadow_casters(rng, vec3(0.0f)));
    const float inf = kInfinity, nan = std::numeric_limits<float>::quiet_NaN();
    for (const Ray& r : {Ray{{nan, 0, 0}, {0, 1, 0}}, Ray{{0, -6, 0}, {inf, 1, 0}},
                         Ray{{0, -6, 0}, {0, nan, 0}}, Ray{{inf, 0, 0}, {-1, 0, 0}},
                         Ray{{-inf, 2, 1}, {1, 0, 0}}, Ray{{3e38f, 0, 0}, {-3e38f, 1, 0}}})
        for (std::size_t l = 0; l < scene.lights.size(); ++l)
            EXPECT_EQ(scene.occluded(r, 1.0f, l), scene.occluded(r, 1.0f)) << "light " << l;
    EXPECT_GT(feelers, 10000);
    EXPECT_GT(blocked, feelers / 10);
    EXPECT_LT(blocked, feelers - feelers / 10);
}

// A sphere seen from inside (a ray in a glass ball) is not convex from there: the
// feeler to a light outside leaves through the sphere, which blocks it.
TEST(ShadowFeelers, InsideASphereTheSphereStillBlocks) {
    SceneDescription desc;
    desc.materials.push_back(Material{});
    desc.objects.push_back(Object{"ball", Sphere{vec3(0.0f), 1.0f}, 0, {}});
    desc.objects.push_back(Object{"floor", Plane{{0, 1, 0}, -3}, 0, {}});
    desc.lights.push_back(Light{Light::Type::kPoint, {0, 5, 0}, {}, vec3(1.0f)});
    const Scene scene(std::move(desc));
    const auto feeler_blocked = [&](const Ray& ray, std::uint32_t expect_skip) {
        Hit hit;
        EXPECT_TRUE(scene.intersect(ray, hit));
        const SurfacePoint sp = scene.surface(ray, hit);
        EXPECT_EQ(sp.cannot_meet_again, expect_skip);
        vec3 dir;
        const vec3 p = offset_ray_origin(sp.p, sp.geometric_normal);
        const float t_max = scene.lights[0].feeler(p, dir);
        return scene.occluded(Ray{p, dir}, t_max, 0, sp.cannot_meet_again);
    };
    EXPECT_TRUE(feeler_blocked(Ray{vec3(0.0f), {0, -1, 0}}, kNoObject)) << "from inside";
    EXPECT_FALSE(feeler_blocked(Ray{{0, 3, 0}, {0, -1, 0}}, 0)) << "the ball's top, outside";
    EXPECT_TRUE(feeler_blocked(Ray{{0.2f, -1, 0}, {0, -1, 0}}, 1)) << "the floor, under the ball";
    // The whole shading: the ball's inside lit by nothing but ambient; its top lit.
    const Tracer tracer(scene, TraceOptions{});
    RayCounts counts;
    Hit inside;
    scene.intersect(Ray{vec3(0.0f), {0, -1, 0}}, inside);
    const vec3 dark = tracer.phong(Ray{vec3(0.0f), {0, -1, 0}},
                                   scene.surface(Ray{vec3(0.0f), {0, -1, 0}}, inside), counts);
    EXPECT_FLOAT_EQ(dark.x, Material{}.ka.x * scene.ambient.x);
}

// LightBuffer::cells: each lane's cell is the one cell() gives its origin, for origins
// anywhere, on the light, on the faces' diagonals (ties), not finite, and for any lanes.
TEST(LightBuffer, CellsAcrossLanesAreEachOriginsOwn) {
    std::mt19937 rng(8);
    const vec3 l(1.5f, -2.0f, 0.25f);
    const std::vector<Aabb> boxes = awkward_boxes(rng, l);
    const LightBuffer point(l, boxes);
    const std::optional<LightBuffer> directional = LightBuffer::make(
        Light{Light::Type::kDirectional, {}, glm::normalize(vec3(-1, -2, -1)), vec3(1.0f)}, boxes);
    ASSERT_TRUE(directional.has_value());
    const float inf = kInfinity, nan = std::numeric_limits<float>::quiet_NaN();
    std::vector<vec3> origins{l,
                              l + vec3(1, 1, 0),
                              l + vec3(-2, 2, 2),
                              l + vec3(0, -3, 3),
                              l + vec3(1e-30f, 0, 0),
                              vec3(nan, 0, 0),
                              vec3(0, inf, 0),
                              vec3(3e38f, -3e38f, 1),
                              l + vec3(4, 0.5f, -7)};
    while (origins.size() < 64 * kPacketWidth) origins.push_back(l + random_point(rng, 12.0f));
    std::shuffle(origins.begin(), origins.end(), rng);
    const auto same = [](const LightBuffer::Cell& a, const LightBuffer::Cell& b) {
        return a.crowded == b.crowded && (a.crowded || (a.begin == b.begin && a.end == b.end));
    };
    int empty = 0, listed_cells = 0;
    for (std::size_t first = 0; first < origins.size(); first += kPacketWidth) {
        std::array<Ray, kPacketWidth> feelers;
        for (int k = 0; k < kPacketWidth; ++k) feelers[k].origin = origins[first + k];
        const unsigned all = (1u << kPacketWidth) - 1u;
        for (const unsigned lanes :
             {all, 0x55u & all, 1u << (first / kPacketWidth % kPacketWidth)}) {
            for (const LightBuffer* buffer : {&point, &*directional}) {
                std::array<LightBuffer::Cell, kPacketWidth> cells;
                buffer->cells(RayLanes<kPacketWidth>::gather(feelers.data(), lanes), lanes,
                              cells.data());
                for (unsigned rest = lanes; rest != 0; rest &= rest - 1) {
                    const unsigned k = static_cast<unsigned>(__builtin_ctz(rest));
                    const LightBuffer::Cell alone = buffer->cell(feelers[k].origin);
                    ASSERT_TRUE(same(cells[k], alone))
                        << "origin " << feelers[k].origin.x << ", " << feelers[k].origin.y << ", "
                        << feelers[k].origin.z << (buffer == &point ? " (point)" : "");
                    empty += !alone.crowded && alone.begin == alone.end;
                    listed_cells += !alone.crowded && alone.begin != alone.end;
                }
            }
        }
    }
    EXPECT_GT(empty, 100);
    EXPECT_GT(listed_cells, 100);
}

// Scene::occluded_packet: each feeler's bit is occluded()'s answer for it alone. The
// feelers of a group leave neighbouring surface points (they share cells, whose planes,
// spheres, moved spheres and triangle they test on the lanes) or points anywhere in the
// scene; some are not finite.
TEST(ShadowFeelers, APacketAnswersAsEachFeelerAlone) {
    std::mt19937 rng(34);
    std::uniform_real_distribution<float> jitter(-0.02f, 0.02f);
    int blocked = 0, feelers = 0, shared = 0;
    for (int variant = 0; variant < 3; ++variant) {
        const vec3 shift = variant == 2 ? vec3(3000, -2000, 5000) : vec3(0.0f);
        const Scene scene(shadow_casters(rng, shift));
        for (int group = 0; group < 600; ++group) {
            const bool neighbours = group % 3 != 2;
            // Neighbours look at the box mesh (group % 3 == 0) or anywhere.
            const vec3 eye = shift + random_point(rng, 12.0f);
            const vec3 aim = group % 3 == 0 ? shift + vec3(2, 1, -3) + random_point(rng, 0.8f)
                                            : shift + random_point(rng, 8.0f);
            std::array<SurfacePoint, kPacketWidth> sps;
            unsigned found = 0;
            for (int k = 0; k < kPacketWidth; ++k) {
                const Ray ray =
                    neighbours ? Ray{eye, aim - eye + vec3(jitter(rng), jitter(rng), jitter(rng))}
                               : Ray{shift + random_point(rng, 12.0f), random_point(rng, 1.0f)};
                Hit hit;
                if (!scene.intersect(ray, hit)) continue;
                sps[k] = scene.surface(ray, hit);
                found |= 1u << k;
            }
            for (std::size_t l = 0; l < scene.lights.size(); ++l) {
                std::array<Ray, kPacketWidth> rays;
                std::array<float, kPacketWidth> t_max{};
                std::array<std::uint32_t, kPacketWidth> leaving{};
                unsigned active = 0;
                for (unsigned rest = found; rest != 0; rest &= rest - 1) {
                    const unsigned k = static_cast<unsigned>(__builtin_ctz(rest));
                    rays[k].origin = offset_ray_origin(sps[k].p, sps[k].geometric_normal);
                    t_max[k] = scene.lights[l].feeler(rays[k].origin, rays[k].dir);
                    leaving[k] = sps[k].cannot_meet_again;
                    if (group % 17 == 5 && k == 1) rays[k].dir.x = kInfinity;  // not finite
                    active |= 1u << k;
                }
                if (active == 0) continue;  // no feeler: occluded_packet asks for one or more
                const unsigned packet =
                    scene.occluded_packet(RayLanes<kPacketWidth>::gather(rays.data(), active),
                                          t_max.data(), l, leaving.data(), active);
                EXPECT_EQ(packet & ~active, 0u) << "a bit of a lane not asked about";
                for (unsigned rest = active; rest != 0; rest &= rest - 1) {
                    const unsigned k = static_cast<unsigned>(__builtin_ctz(rest));
                    const bool alone = scene.occluded(rays[k], t_max[k], l, leaving[k]);
                    ASSERT_EQ(((packet >> k) & 1u) != 0, alone)
                        << "variant " << variant << ", group " << group << ", light " << l
                        << ", lane " << k;
                    blocked += alone;
                    ++feelers;
                }
                shared += neighbours && std::popcount(packet) >= 2;
            }
        }
    }
    EXPECT_GT(feelers, 2500 * kPacketWidth);  // packets of 8, or 4 under SSE2
    EXPECT_GT(blocked, feelers / 10);
    EXPECT_LT(blocked, feelers - feelers / 10);
    EXPECT_GT(shared, 200) << "groups blocked together";
}

}  // namespace
}  // namespace rt
