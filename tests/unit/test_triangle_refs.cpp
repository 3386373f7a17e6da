// Long thin triangles cut into pieces for the wide BVH (core/triangle_refs.h): the pieces
// cover their triangle, only thin and large triangles are cut, and a mesh of them
// answers every ray as brute force does.

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <random>

#include <glm/geometric.hpp>

#include "core/mesh.h"
#include "core/tessellate.h"
#include "core/triangle_refs.h"

namespace rt {
namespace {

// A needle: from p along a random direction for `length`, `width` across.
std::array<vec3, 3> needle(std::mt19937& rng, const glm::dvec3& p, double length, double width) {
    std::normal_distribution<double> g;
    const glm::dvec3 d = glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
    const glm::dvec3 side = glm::normalize(glm::cross(d, glm::dvec3(g(rng), g(rng), g(rng))));
    return {vec3(p), vec3(p + length * d + width * side), vec3(p + length * d - width * side)};
}

// `count` needles 3 units long and 0.01 across, crossing in a 4-unit cube (hay, straws).
TriangleMesh straws(int count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    TriangleMesh m;
    for (int i = 0; i < count; ++i) {
        for (const vec3& v : needle(rng, glm::dvec3(u(rng), u(rng), u(rng)), 3.0, 0.005))
            m.positions.push_back(v);
        const auto k = static_cast<std::uint32_t>(3 * i);
        m.triangles.push_back({k, k + 1, k + 2});
    }
    return m;
}

bool inside(const Aabb& box, const glm::dvec3& p) {
    for (int a = 0; a < 3; ++a)
        if (!(double{box.lo[a]} <= p[a] && p[a] <= double{box.hi[a]})) return false;
    return true;
}

// Points of the triangle in double precision (its corners, its edges, its inside) each
// lie in one of its pieces' boxes, and the pieces in the triangle's box: near the origin,
// far from it, huge and tiny, in two to five pieces.
TEST(TriangleRefs, EveryPointOfACutTriangleLiesInOneOfItsPieces) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int cut = 0, outside = 0, pieces_outside = 0;
    for (const double scale : {1.0, 1e6, 1e-6})
        for (const double offset : {0.0, 1e5}) {
            for (int pieces = 2; pieces <= 5; ++pieces) {
                SplitLimits limits;
                limits.max_pieces = pieces;
                for (int i = 0; i < 200; ++i) {
                    const auto v =
                        needle(rng, glm::dvec3(offset * scale), 3.0 * scale, 0.005 * scale);
                    Aabb box;
                    for (const vec3& c : v) box.grow(c);
                    std::array<Aabb, kMostPieces> piece;
                    const int count =
                        cut_thin_triangle(v[0], v[1], v[2], box, limits, piece.data());
                    if (count == 1) continue;
                    ++cut;
                    for (int k = 0; k < count; ++k)
                        pieces_outside += !(inside(box, glm::dvec3(piece[k].lo)) &&
                                            inside(box, glm::dvec3(piece[k].hi)));
                    const glm::dvec3 a(v[0]), b(v[1]), c(v[2]);
                    const auto covered = [&](const glm::dvec3& p) {
                        for (int k = 0; k < count; ++k)
                            if (inside(piece[k], p)) return true;
                        return false;
                    };
                    // Where the cuts (equal slabs along the box's longest axis) cross
                    // the edges: the pieces' bounds, rounded outwards.
                    const vec3 e = box.extent();
                    const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
                    const double lo = box.lo[axis], width = (double{box.hi[axis]} - lo) / count;
                    for (int cut_at = 1; cut_at < count; ++cut_at) {
                        const double plane = lo + width * cut_at;
                        for (int edge = 0; edge < 3; ++edge) {
                            const glm::dvec3 p(v[edge]), q(v[(edge + 1) % 3]);
                            if ((p[axis] - plane) * (q[axis] - plane) > 0.0 || p[axis] == q[axis])
                                continue;
                            glm::dvec3 x = p + (q - p) * ((plane - p[axis]) / (q[axis] - p[axis]));
                            x[axis] = plane;
                            outside += !covered(x);
                        }
                    }
                    for (int s = 0; s < 300; ++s) {
                        double b1 = u(rng), b2 = u(rng);
                        if (b1 + b2 > 1.0) b1 = 1.0 - b1, b2 = 1.0 - b2;
                        if (s < 3) b1 = s == 1, b2 = s == 2;  // the corners
                        if (s >= 3 && s < 60) b2 = 0.0;       // an edge
                        outside += !covered(a + b1 * (b - a) + b2 * (c - a));
                    }
                }
            }
        }
    EXPECT_GT(cut, 4000);  // a needle's box is hundreds of times its area
    EXPECT_EQ(outside, 0);
    EXPECT_EQ(pieces_outside, 0);
}

// Compact triangles are not cut, however placed; nor a sliver along an axis (its halves'
// boxes have its box's area), a degenerate one, or any where max_pieces is 1.
TEST(TriangleRefs, OnlyThinTrianglesWhosePiecesAreSmallerAreCut) {
    std::array<Aabb, kMostPieces> piece;
    const auto count = [&](vec3 a, vec3 b, vec3 c, SplitLimits limits = {}) {
        Aabb box;
        box.grow(a);
        box.grow(b);
        box.grow(c);
        return cut_thin_triangle(a, b, c, box, limits, piece.data());
    };
    EXPECT_EQ(count({0, 0, 0}, {1, 0, 0}, {0, 1, 1}), 1);
    EXPECT_EQ(count({0, 0, 0}, {0.002f, 0, 0}, {0, 3, 0}), 1);       // along y
    EXPECT_EQ(count({0, 0, 0}, {1, 1, 1}, {2, 2, 2}), 1);            // no area
    EXPECT_EQ(count({0, 0, 0}, {1, 1, 1.001f}, {1, 1.001f, 1}), 2);  // a diagonal needle
    SplitLimits none;
    none.max_pieces = 1;
    EXPECT_EQ(count({0, 0, 0}, {1, 1, 1.001f}, {1, 1.001f, 1}, none), 1);
}

// A mesh's references: a tessellated sphere has none but its triangles; needles have
// more, each naming its triangle.
TEST(TriangleRefs, NeedlesGetPiecesAndACompactMeshNone) {
    const TriangleMesh sphere = tessellate_unit_sphere(64);
    const TriangleRefs round = triangle_refs(sphere.positions, sphere.triangles, {}, nullptr, 1);
    EXPECT_EQ(round.boxes.size(), sphere.triangles.size());
    const TriangleMesh hay = straws(3000, 5);
    const TriangleRefs refs = triangle_refs(hay.positions, hay.triangles, {}, nullptr, 1);
    EXPECT_GT(refs.boxes.size(), 2 * hay.triangles.size() * 9 / 10);
    ASSERT_EQ(refs.boxes.size(), hay.triangles.size() + refs.extra_triangles.size());
    for (std::uint32_t ref = 0; ref < refs.boxes.size(); ++ref) {
        const std::uint32_t t = refs.triangle(ref);
        ASSERT_LT(t, hay.triangles.size());
        Aabb box;
        for (int k = 0; k < 3; ++k) box.grow(hay.positions[hay.triangles[t][k]]);
        EXPECT_TRUE(box.lo.x <= refs.boxes[ref].lo.x && refs.boxes[ref].hi.x <= box.hi.x);
    }
}

// Rays through a mesh of needles, whose triangles sit in several leaves: the wide BVH
// finds what brute force finds, single rays and packets, nearest hits and feelers; and
// each triangle alone (the item buffer's test) is found where a ray aims at it.
TEST(TriangleRefs, AMeshOfNeedlesAnswersAsBruteForce) {
    TriangleMesh bvh = straws(4000, 9), brute = bvh;
    bvh.build(AccelKind::kBvh, 2);
    brute.build(AccelKind::kBrute, 1);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(-3.0f, 3.0f);
    std::normal_distribution<float> g;
    int hits = 0, differ = 0, packet_differ = 0, feelers_differ = 0;
    for (int i = 0; i < 1000; ++i) {
        std::array<Ray, kPacketWidth> rays;
        std::array<Hit, kPacketWidth> packet;
        const vec3 origin(u(rng), u(rng), u(rng));
        const vec3 aim = glm::normalize(vec3(g(rng), g(rng), g(rng)));
        std::array<float, kPacketWidth> t_max;
        unsigned expected_blocked = 0;
        for (int k = 0; k < kPacketWidth; ++k) {
            const auto lane = static_cast<std::size_t>(k);
            rays[lane] = Ray{origin, glm::normalize(aim + 0.05f * vec3(g(rng), g(rng), g(rng)))};
            Hit a, b;
            const bool found = bvh.intersect(rays[lane], a);
            hits += found;
            differ += found != brute.intersect(rays[lane], b) || (found && a.t != b.t);
            t_max[lane] = 2.0f;
            const bool blocked = brute.occluded(rays[lane], t_max[lane]);
            differ += blocked != bvh.occluded(rays[lane], t_max[lane]);
            expected_blocked |= unsigned{blocked} << k;
            packet[lane] = Hit{};
            if (found) packet[lane].t = kInfinity;
        }
        const unsigned all = (1u << kPacketWidth) - 1u;
        const unsigned found = bvh.intersect_packet(rays.data(), packet.data(), all);
        for (int k = 0; k < kPacketWidth; ++k) {
            const auto lane = static_cast<std::size_t>(k);
            Hit alone;
            const bool hit = brute.intersect(rays[lane], alone);
            packet_differ +=
                hit != (((found >> k) & 1u) != 0) || (hit && packet[lane].t != alone.t);
        }
        feelers_differ +=
            std::popcount(bvh.occluded_packet(rays.data(), t_max.data(), all) ^ expected_blocked);
    }
    EXPECT_GT(hits, 1000);
    EXPECT_EQ(differ, 0);
    EXPECT_EQ(packet_differ, 0);
    EXPECT_EQ(feelers_differ, 0);
    int missed = 0;
    for (std::uint32_t t = 0; t < bvh.triangles.size(); ++t) {
        const glm::uvec3 tri = bvh.triangles[t];
        const vec3 centre =
            (bvh.positions[tri[0]] + bvh.positions[tri[1]] + bvh.positions[tri[2]]) / 3.0f;
        const vec3 n = glm::normalize(bvh.face_normal(t));
        Hit hit;
        missed += !bvh.intersect_triangle(t, Ray{centre + n, -n}, hit) || hit.prim != t;
    }
    EXPECT_EQ(missed, 0);
}

}  // namespace
}  // namespace rt
