// Rays traced as packets (core/wide_bvh_packet.h) must get what each gets alone: the same
// hit or miss, at the very same t, on the same triangle (or on one met at that very t).
#include <gtest/gtest.h>

#include <array>
#include <limits>
#include <map>
#include <random>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "core/mesh.h"
#include "core/scene.h"
#include "core/tessellate.h"
#include "core/transform.h"
#include "core/triangle_packet.h"
#include "core/vec3_lanes.h"
#include "core/wide_bvh_packet.h"
#include "test_util.h"

namespace rt {
namespace {

constexpr int kW = kPacketWidth;
using Packet = std::array<Ray, kW>;

vec3 random_in(std::mt19937& rng, float extent) {
    std::uniform_real_distribution<float> u(-extent, extent);
    return {u(rng), u(rng), u(rng)};
}

// Closed surfaces (shared edges: ties) and a soup of loose triangles (deep overlaps).
TriangleMesh test_mesh(int which, AccelKind kind) {
    TriangleMesh mesh;
    if (which == 0) {
        mesh = tessellate_unit_sphere(64);
        for (vec3& p : mesh.positions) p = 3.0f * p + vec3(0.5f, -0.25f, 0.0f);
    } else {
        std::mt19937 rng(11);
        for (int i = 0; i < 2000; ++i) {
            const vec3 centre = random_in(rng, 4.0f);
            const auto base = static_cast<std::uint32_t>(mesh.positions.size());
            for (int k = 0; k < 3; ++k)
                mesh.positions.push_back(centre + 0.4f * random_in(rng, 1.0f));
            mesh.triangles.push_back({base, base + 1, base + 2});
        }
    }
    mesh.build(kind);
    return mesh;
}

// Packets of every kind a renderer makes, and some it should not: a camera's neighbouring
// pixels (one origin), feelers from scattered points to one light (one end), rays whose
// signs differ (traced one at a time), rays along an axis (a zero component), and rays
// with no direction at all.
Packet make_packet(std::mt19937& rng, int kind) {
    Packet p;
    const vec3 eye = vec3(0.0f, 0.0f, 9.0f) + random_in(rng, 2.0f);
    const vec3 aim = random_in(rng, 2.0f) - eye;
    const vec3 light = random_in(rng, 9.0f);
    for (int lane = 0; lane < kW; ++lane) {
        const vec3 jitter = random_in(rng, kind == 1 ? 2.0f : 0.02f);
        switch (kind) {
            case 0:
                p[lane] = {eye, aim + jitter};
                break;
            case 1:
                p[lane] = {light + jitter * 2.0f, -light + jitter};
                break;
            case 2:
                p[lane] = {random_in(rng, 8.0f), random_in(rng, 1.0f)};
                break;
            case 3:
                p[lane] = {eye + jitter * 50.0f, vec3(0.0f, 0.0f, -1.0f)};
                break;
            default:
                p[lane] = {eye, lane == 3 ? vec3(0.0f) : aim + jitter};
                break;
        }
    }
    return p;
}

class PacketTest : public ::testing::TestWithParam<AccelKind> {};

// The lane reductions a packet's interval is made of: whichever lane holds the extreme.
TEST(Simd, TheSmallestAndLargestLaneAreFoundInAnyLane) {
    using Float = Lanes<kPacketWidth>::Float;
    for (int at = 0; at < kPacketWidth; ++at) {
        Float v;
        for (int lane = 0; lane < kPacketWidth; ++lane)
            v[lane] = 1.0f + 0.25f * static_cast<float>(lane);
        v[at] = -3.5f;
        EXPECT_EQ(hmin(v), -3.5f) << "lane " << at;
        v[at] = 7.25f;
        EXPECT_EQ(hmax(v), 7.25f) << "lane " << at;
    }
}

// The comparisons as bits (core/simd.h): at every width the build has, each lane the
// scalar operator's answer, NaN (false, but true for !=), signed zeros and infinities
// included. A wrong predicate (an ordered != or an unordered <) fails on the NaN pairs.
template <class V>
void expect_lanes_compare_as_scalars() {
    constexpr int kN = static_cast<int>(sizeof(V) / sizeof(float));
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const std::array<float, 7> values{-kInfinity, -1.5f, -0.0f, 0.0f, 2.0f, kInfinity, nan};
    int pair = 0;
    for (float x : values)
        for (float y : values) {
            const int lane = pair++ % kN;
            V a = splat<V>(1.0f), b = splat<V>(1.0f);  // the other lanes equal: <=, >= only
            a[lane] = x;
            b[lane] = y;
            const unsigned others = ((1u << kN) - 1u) & ~(1u << lane);
            const auto expect = [&](unsigned got, bool want, unsigned rest, const char* op) {
                EXPECT_EQ((got >> lane) & 1u, want ? 1u : 0u) << x << " " << op << " " << y;
                EXPECT_EQ(got & others, rest) << op << ": the other lanes";
            };
            expect(lanes<Compare::kLt>(a, b), x < y, 0u, "<");
            expect(lanes<Compare::kLe>(a, b), x <= y, others, "<=");
            expect(lanes<Compare::kGt>(a, b), x > y, 0u, ">");
            expect(lanes<Compare::kGe>(a, b), x >= y, others, ">=");
            expect(lanes<Compare::kNe>(a, b), x != y, 0u, "!=");
        }
}

TEST(Simd, ComparisonsAsBitsAreTheScalarOperatorsLaneByLane) {
    expect_lanes_compare_as_scalars<Float4>();
#if defined(__AVX__)
    expect_lanes_compare_as_scalars<Float8>();
#endif
#if defined(__AVX512F__)
    expect_lanes_compare_as_scalars<Float16>();
#endif
}

// Rows of four floats from anywhere (here one array, in a shuffled order, rows
// overlapping), transposed: lane k of column c is row k's float c; then rows of three.
template <int N>
void expect_rows_transposed() {
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> any(-100.0f, 100.0f);
    std::array<float, 64> floats;
    for (float& f : floats) f = any(rng);
    for (int round = 0; round < 50; ++round) {
        std::array<const float*, N> rows;
        for (int k = 0; k < N; ++k) rows[k] = floats.data() + rng() % (floats.size() - 3);
        typename Lanes<N>::Float columns[4];
        transpose_rows<N>(rows.data(), columns);
        for (int k = 0; k < N; ++k)
            for (int c = 0; c < 4; ++c) ASSERT_EQ(columns[c][k], rows[k][c]) << k << ", " << c;
        for (int first = 0; first < 2; ++first) {
            const Vec3Lanes<N> v = Vec3Lanes<N>::transpose(rows, first);
            for (int k = 0; k < N; ++k)
                ASSERT_EQ(v.get(k), vec3(rows[k][first], rows[k][first + 1], rows[k][first + 2]));
        }
    }
    // Rows of three (a mesh's vertices), the last at the very end of its array (under
    // the sanitizers, a fourth float read would be caught): the fourth column is zero.
    const std::vector<vec3> points = {{1, 2, 3}, {4, 5, 6}, {-7, 8.5f, -9}};
    for (int round = 0; round < 20; ++round) {
        std::array<const float*, N> rows;
        for (int k = 0; k < N; ++k) rows[k] = &points[rng() % points.size()].x;
        rows[round % N] = &points.back().x;
        typename Lanes<N>::Float columns[4];
        transpose_rows<N, 3>(rows.data(), columns);
        for (int k = 0; k < N; ++k) {
            for (int c = 0; c < 3; ++c) ASSERT_EQ(columns[c][k], rows[k][c]) << k << ", " << c;
            ASSERT_EQ(columns[3][k], 0.0f) << k;
        }
    }
}

// select_bits against each lane's bit, for every mask of N lanes; load reads any address.
template <class V>
void expect_selected_by_bits() {
    constexpr int kN = sizeof(V) / sizeof(float);
    std::array<float, kN + 3> floats;
    for (int k = 0; k < kN + 3; ++k) floats[k] = 1.5f * static_cast<float>(k) - 7.0f;
    for (int offset = 0; offset < 4; ++offset) {
        const V a = load<V>(floats.data() + offset);
        for (int k = 0; k < kN; ++k) ASSERT_EQ(a[k], floats[k + offset]);
    }
    const V a = load<V>(floats.data()), b = splat<V>(-kInfinity);
    for (unsigned mask = 0; mask < (1u << kN); mask += kN == 16 ? 37u : 1u) {
        const V chosen = select_bits(mask, a, b);
        for (int k = 0; k < kN; ++k)
            ASSERT_EQ(chosen[k], (mask >> k) & 1u ? a[k] : b[k])
                << "mask " << mask << " lane " << k;
    }
}

TEST(Simd, LanesAreChosenByTheirBits) {
    expect_selected_by_bits<Float4>();
#if defined(__AVX__)
    expect_selected_by_bits<Float8>();
#endif
#if defined(__AVX512F__)
    expect_selected_by_bits<Float16>();
#endif
}

TEST(Simd, RowsOfFourFloatsAreTransposedIntoLanes) {
    expect_rows_transposed<4>();
#if defined(__AVX__)
    expect_rows_transposed<8>();
#endif
}

TEST_P(PacketTest, EveryRayGetsTheHitItGetsAlone) {
    std::mt19937 rng(3);
    int hits = 0, packed = 0;
    for (int which = 0; which < 2; ++which) {
        const TriangleMesh mesh = test_mesh(which, GetParam());
        for (int n = 0; n < 1500; ++n) {
            const Packet rays = make_packet(rng, n % 5);
            const unsigned active = n % 7 == 0 ? (rng() & ((1u << kW) - 1u)) : (1u << kW) - 1u;
            std::array<Hit, kW> alone, together;
            for (int lane = 0; lane < kW; ++lane) {
                const float limit = n % 3 == 0 ? 4.0f + static_cast<float>(lane) : kInfinity;
                alone[lane].t = together[lane].t = limit;
                together[lane].prim = 12345;  // left as it is where the ray misses
            }
            const unsigned found = mesh.intersect_packet(rays.data(), together.data(), active);
            ++packed;
            for (int lane = 0; lane < kW; ++lane) {
                const bool on = (active >> lane) & 1u;
                const bool hit_alone = on && mesh.intersect(rays[lane], alone[lane]);
                ASSERT_EQ(((found >> lane) & 1u) != 0, hit_alone)
                    << "packet " << n << " lane " << lane;
                if (!hit_alone) {
                    EXPECT_EQ(together[lane].prim, 12345u);
                    EXPECT_EQ(together[lane].t, alone[lane].t);
                    continue;
                }
                ++hits;
                ASSERT_EQ(together[lane].t, alone[lane].t) << "packet " << n << " lane " << lane;
                if (together[lane].prim != alone[lane].prim) {  // only a tie may differ
                    Hit other;
                    ASSERT_TRUE(mesh.intersect_triangle(together[lane].prim, rays[lane], other));
                    EXPECT_EQ(other.t, alone[lane].t) << "packet " << n << " lane " << lane;
                } else {
                    EXPECT_EQ(together[lane].b1, alone[lane].b1);
                    EXPECT_EQ(together[lane].b2, alone[lane].b2);
                }
            }
        }
    }
    EXPECT_GT(hits, packed * kW / 4);  // the test means something only if many rays hit
}

TEST_P(PacketTest, EveryFeelerIsBlockedExactlyWhenItIsAlone) {
    std::mt19937 rng(5);
    int blocked = 0, total = 0;
    for (int which = 0; which < 2; ++which) {
        const TriangleMesh mesh = test_mesh(which, GetParam());
        for (int n = 0; n < 1500; ++n) {
            const Packet rays = make_packet(rng, n % 5);
            const unsigned active = n % 7 == 0 ? (rng() & ((1u << kW) - 1u)) : (1u << kW) - 1u;
            std::array<float, kW> t_max;
            for (int lane = 0; lane < kW; ++lane)
                t_max[lane] = n % 2 ? 0.5f + static_cast<float>(lane) : kInfinity;
            const unsigned result = mesh.occluded_packet(rays.data(), t_max.data(), active);
            for (int lane = 0; lane < kW; ++lane) {
                const bool on = (active >> lane) & 1u;
                const bool alone = on && mesh.occluded(rays[lane], t_max[lane]);
                ASSERT_EQ(((result >> lane) & 1u) != 0, alone)
                    << "packet " << n << " lane " << lane;
                blocked += alone;
                total += on;
            }
        }
    }
    EXPECT_GT(blocked, total / 5);
    EXPECT_LT(blocked, total * 4 / 5);
}

// A whole scene's packets (planes, spheres, triangles, meshes under transforms, through
// the objects' BVH and each mesh's): each camera ray in a packet of its row's neighbours
// finds what Scene::intersect finds for it alone.
// Planes (tested for every ray, across the packet where untransformed) give each ray the
// record it gets alone: several planes one after the other, each within the limit the
// ones before left; a ray's own starting limit; a transformed plane (ray by ray);
// partial packets; rays parallel to a plane.
TEST(ScenePackets, PlanesGiveEachRayItsOwnHit) {
    SceneDescription desc;
    desc.materials.push_back(Material{});
    desc.objects.push_back(Object{"floor", Plane{{0, 1, 0}, -1}, 0, {}});
    desc.objects.push_back(Object{"ceiling", Plane{{0, -1, 0}, -4}, 0, {}});
    desc.objects.push_back(Object{"wall", Plane{glm::normalize(vec3(1, 0, 1)), -3}, 0, {}});
    desc.objects.push_back(
        Object{"tilted", Plane{{0, 0, 1}, 0}, 0,
               Transform::from_matrix(glm::rotate(glm::translate(glm::mat4(1.0f), vec3(0, 0, -5)),
                                                  0.3f, vec3(1, 0, 0)))});
    desc.objects.push_back(Object{"ball", Sphere{{0.5f, 0, -2}, 0.7f}, 0, {}});
    const Scene scene(std::move(desc));
    std::mt19937 rng(23);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f), limit(0.5f, 20.0f);
    int hits = 0;
    for (int i = 0; i < 4000; ++i) {
        Packet rays;
        std::array<Hit, kW> together, alone;
        for (int k = 0; k < kW; ++k) {
            vec3 dir(u(rng), u(rng), u(rng));
            if (k == 3) dir.y = 0.0f;  // parallel to floor and ceiling
            rays[k] = Ray{vec3(u(rng), u(rng), u(rng)), dir};
            together[k] = alone[k] = Hit{};
            if (i % 3 == 0) together[k].t = alone[k].t = limit(rng);
        }
        const unsigned active = i % 5 == 0 ? (rng() & ((1u << kW) - 1u)) : (1u << kW) - 1u;
        const unsigned found = scene.intersect_packet(rays.data(), together.data(), active);
        for (int k = 0; k < kW; ++k) {
            if (!((active >> k) & 1u)) continue;
            const bool hit = scene.intersect(rays[k], alone[k]);
            ASSERT_EQ(((found >> k) & 1u) != 0, hit) << "packet " << i << " lane " << k;
            ASSERT_EQ(together[k].t, alone[k].t) << "packet " << i << " lane " << k;
            if (!hit) continue;
            ++hits;
            ASSERT_EQ(together[k].object, alone[k].object) << "packet " << i << " lane " << k;
        }
    }
    EXPECT_GT(hits, 10000);
}

TEST(ScenePackets, EveryPixelGetsTheHitItGetsAlone) {
    for (const char* name :
         {"whitted.json", "cornell.json", "textured.json", "many_spheres.json", "tutorial.json"}) {
        const Scene scene(test::shipped_scene(name, 160, 90));
        const Camera& camera = scene.camera;
        int hits = 0;
        for (int y = 0; y < camera.rows; ++y) {
            for (int x0 = 0; x0 < camera.cols; x0 += kW) {
                std::array<Ray, kW> rays;
                std::array<Hit, kW> together;
                const int n = std::min(kW, camera.cols - x0);
                for (int k = 0; k < n; ++k) rays[k] = camera.ray(x0 + k, y);
                const unsigned active = (1u << n) - 1u;
                const unsigned found = scene.intersect_packet(rays.data(), together.data(), active);
                for (int k = 0; k < n; ++k) {
                    Hit alone;
                    const bool hit = scene.intersect(rays[k], alone);
                    const std::string where = std::string(name) + " pixel " +
                                              std::to_string(x0 + k) + "," + std::to_string(y);
                    ASSERT_EQ(((found >> k) & 1u) != 0, hit) << where;
                    ASSERT_EQ(together[k].t, alone.t) << where;
                    if (!hit) continue;
                    ++hits;
                    ASSERT_EQ(together[k].object, alone.object) << where;
                    if (together[k].prim != alone.prim) {
                        Hit other;
                        ASSERT_TRUE(scene.intersect_primitive(together[k].object, together[k].prim,
                                                              rays[k], other));
                        EXPECT_EQ(other.t, alone.t) << where;
                    }
                }
            }
        }
        EXPECT_GT(hits, camera.rows * camera.cols / 4) << name;
    }
}

// The test across rays (core/triangle_packet.h) against Triangle4's for each ray alone, bit
// for bit: random packs, and rays leaving a large triangle's surface (where the t bound
// of the rounding error decides: a wrong bound lets them hit the triangle they leave).
TEST(TrianglePacket, EachRayGetsWhatItsOwnTestGives) {
    std::mt19937 rng(29);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const vec3 a{0, 0, 0}, b{0, 548.8f, 0}, c{0, 548.8f, 559.2f};  // the Cornell box's left wall
    std::map<std::array<int, 3>, std::vector<Ray>> by_axes;        // rays sharing a permutation
    int compared = 0, hits = 0, self_hits = 0;
    for (int round = 0; round < 400; ++round) {
        Triangle4 pack{};
        const bool wall = round % 2 == 0;
        for (int lane = 0; lane < 4; ++lane) {
            if (wall && lane == 1) {
                pack.set(lane, a, b, c);
            } else if (lane < 3) {
                const vec3 centre = random_in(rng, 40.0f);
                pack.set(lane, centre + random_in(rng, 30.0f), centre + random_in(rng, 30.0f),
                         centre + random_in(rng, 30.0f));
            }
        }
        by_axes.clear();
        for (int i = 0; i < 64 * kW; ++i) {
            Ray r;
            if (wall) {
                float w1 = u(rng), w2 = u(rng);
                if (w1 + w2 > 1.0f) w1 = 1.0f - w1, w2 = 1.0f - w2;
                r.origin = offset_ray_origin((1.0f - w1 - w2) * a + w1 * b + w2 * c, {1, 0, 0});
                r.dir = {u(rng) * 300.0f + 1e-3f, (u(rng) - 0.5f) * 800.0f,
                         (u(rng) - 0.5f) * 800.0f};
            } else {
                r.origin = random_in(rng, 80.0f);
                r.dir = random_in(rng, 40.0f) - r.origin;  // towards the triangles
            }
            const ShearedRay sheared(r);
            by_axes[{sheared.kx, sheared.ky, sheared.kz}].push_back(r);
        }
        for (const auto& [axes, rays] : by_axes) {
            for (std::size_t first = 0; first + kW <= rays.size(); first += kW) {
                const unsigned lanes =
                    round % 3 == 0 ? (rng() | 1u) & ((1u << kW) - 1u) : (1u << kW) - 1u;
                std::array<ShearedRay, kW> each;
                for (int k = 0; k < kW; ++k) each[k] = ShearedRay(rays[first + k]);
                ShearedRays<kW> together, from_rays;
                ASSERT_TRUE(together.set(each.data(), lanes));
                ASSERT_TRUE(from_rays.set(&rays[first], lanes));  // the vector set-up: the same
                for (int k = 0; k < kW; ++k) {
                    if (!((lanes >> k) & 1u)) continue;
                    const ShearedRay lane_ray = from_rays.lane_ray(k);
                    ASSERT_EQ(lane_ray.kx, each[k].kx);
                    ASSERT_EQ(lane_ray.ky, each[k].ky);
                    ASSERT_EQ(lane_ray.kz, each[k].kz);
                    ASSERT_EQ(lane_ray.sx, each[k].sx);
                    ASSERT_EQ(lane_ray.sy, each[k].sy);
                    ASSERT_EQ(lane_ray.sz, each[k].sz);
                    for (int axis = 0; axis < 3; ++axis)
                        ASSERT_EQ(lane_ray.origin[axis], each[k].origin[axis]);
                }
                std::array<float, kW> t_max, limits;
                std::array<int, kW> lane;
                std::array<float, kW> b1, b2;
                for (int k = 0; k < kW; ++k) t_max[k] = limits[k] = wall ? 1.0f : 200.0f;
                const unsigned found = intersect<false>(pack, together, lanes, t_max.data(),
                                                        lane.data(), b1.data(), b2.data());
                const unsigned any = intersect<true>(pack, together, lanes, limits.data(), nullptr,
                                                     nullptr, nullptr);
                EXPECT_EQ(any, found);
                for (int k = 0; k < kW; ++k) {
                    if (!((lanes >> k) & 1u)) continue;
                    ++compared;
                    const Triangle4Hit alone = intersect(pack, each[k], wall ? 1.0f : 200.0f);
                    ASSERT_EQ(((found >> k) & 1u) != 0, alone.lane >= 0) << "round " << round;
                    if (alone.lane < 0) continue;
                    ++hits;
                    self_hits += wall && alone.lane == 1;
                    EXPECT_EQ(lane[k], alone.lane);
                    EXPECT_EQ(t_max[k], alone.t);
                    EXPECT_EQ(b1[k], alone.b1);
                    EXPECT_EQ(b2[k], alone.b2);
                }
            }
        }
    }
    EXPECT_GT(compared, 50000);
    EXPECT_GT(hits, compared / 50);
    EXPECT_EQ(self_hits, 0);
}

// A packet's walk drops a waiting child only where none of the rays that enter it can
// still find something nearer there, also where the rays part ways and a node is tested
// by each of the few that reach it (kFewRays): each ray ends with what it finds alone.
// The primitives are overlapping boxes, each "hit" halfway through the ray's span in it,
// so that which child waits behind which, and with which bound, decides the answers.
TEST(PacketWalk, EveryRayFindsTheNearestAmongOverlappingBoxes) {
    std::mt19937 rng(7);
    std::vector<Aabb> boxes;
    for (int i = 0; i < 96; ++i) {
        const vec3 centre = random_in(rng, 4.0f),
                   half = 0.1f + 1.2f * glm::abs(random_in(rng, 1.0f));
        boxes.push_back({centre - half, centre + half});
    }
    WideBvh<kBvhWidth> bvh;
    bvh.build(boxes, 1);
    const auto midway = [&](const Ray& r, std::uint32_t slot) {  // +inf: no hit
        const Aabb& b = boxes[bvh.order()[slot]];
        double enter = 0.0, leave = kInfinity;
        for (int a = 0; a < 3; ++a) {
            const double lo = (double{b.lo[a]} - r.origin[a]) / r.dir[a];
            const double hi = (double{b.hi[a]} - r.origin[a]) / r.dir[a];
            enter = std::max(enter, std::min(lo, hi));
            leave = std::min(leave, std::max(lo, hi));
        }
        return enter < leave ? static_cast<float>(0.5 * (enter + leave)) : kInfinity;
    };
    int compared = 0, hits = 0;
    for (int n = 0; n < 4000; ++n) {
        // Rays from scattered points, their directions of one sign on each axis (as
        // feelers towards a light): two of them (the few that test nodes each), or all.
        std::array<Ray, kPacketWidth> rays;
        const vec3 towards = vec3(0.2f) + glm::abs(random_in(rng, 1.0f));
        for (Ray& r : rays)
            r = {random_in(rng, 6.0f), towards + 0.3f * glm::abs(random_in(rng, 1.0f))};
        unsigned active = (1u << kPacketWidth) - 1u;
        if (n % 2 == 0) active = (1u << (rng() % kPacketWidth)) | (1u << (rng() % kPacketWidth));
        std::array<float, kPacketWidth> t_max;
        t_max.fill(kInfinity);
        bvh.traverse_packet<false>(rays.data(), t_max.data(), active,
                                   [&](std::uint32_t first, std::uint32_t count, unsigned lanes) {
                                       unsigned found = 0;
                                       for (; lanes != 0; lanes &= lanes - 1) {
                                           const int r = __builtin_ctz(lanes);
                                           for (std::uint32_t k = 0; k < count; ++k) {
                                               const float t = midway(rays[r], first + k);
                                               if (t < t_max[r]) t_max[r] = t, found |= 1u << r;
                                           }
                                       }
                                       return found;
                                   });
        for (unsigned m = active; m != 0; m &= m - 1) {
            const int r = __builtin_ctz(m);
            float alone = kInfinity;
            bvh.traverse_leaves<false>(rays[r], alone,
                                       [&](std::uint32_t first, std::uint32_t count, float& limit) {
                                           bool found = false;
                                           for (std::uint32_t k = 0; k < count; ++k) {
                                               const float t = midway(rays[r], first + k);
                                               if (t < limit) limit = t, found = true;
                                           }
                                           return found;
                                       });
            ASSERT_EQ(t_max[r], alone) << "packet " << n << " ray " << r;
            ++compared;
            hits += alone < kInfinity;
        }
    }
    EXPECT_GT(hits, compared / 4);
    EXPECT_LT(hits, compared * 3 / 4);
}

INSTANTIATE_TEST_SUITE_P(EveryKind, PacketTest,
                         ::testing::Values(AccelKind::kBvh, AccelKind::kBvh2, AccelKind::kGrid,
                                           AccelKind::kBrute),
                         [](const auto& param_info) {
                             return std::string(accel_name(param_info.param));
                         });

}  // namespace
}  // namespace rt
