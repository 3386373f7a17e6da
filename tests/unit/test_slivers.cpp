// Slivers against the triangle test's rounding: long thin triangles whose edge functions
// cancel, where a bound on t's rounding computed from them (t_det_error) is far looser
// than the hit is near, and real hits were dropped.

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <random>

#include <glm/geometric.hpp>

#include "core/mesh.h"
#include "core/triangle4.h"

namespace rt {
namespace {

// One sliver of a tube of 60,000 twisted a quarter turn over 6 units (make_bench_meshes'
// twist.obj): from (cos a, -3, sin a) and its neighbour 2 pi / 30,000 on to the point a
// quarter turn round at y = 3. Six units long, 2e-4 across.
TriangleMesh twisted_sliver(int i) {
    const double step = 2.0 * M_PI / 30000.0, a = step * i;
    TriangleMesh m;
    m.positions = {vec3(float(std::cos(a)), -3.0f, float(std::sin(a))),
                   vec3(float(std::cos(a + step)), -3.0f, float(std::sin(a + step))),
                   vec3(float(std::cos(a + M_PI / 2)), 3.0f, float(std::sin(a + M_PI / 2)))};
    m.triangles = {{0, 1, 2}};
    m.build();
    return m;
}

// Rays from points a little off a sliver (0.02-0.3 units), their main axis along its
// length (so the sliver spans the plane through the origin across that axis), aimed at
// points well inside it: every one hits, at its distance (checked in double precision).
// The edge functions' bound alone rejected most hits nearer than ~0.3 units; the plane
// test in double precision (plane_hits) settles them. Single rays, and packets of rays
// from one origin, nearest hits and feelers: the whole packet (its leaves test the
// triangle across the rays) and two of its rays (each tests the leaf alone); the packets
// leave such hits to a trace of the ray alone after their walk (core/mesh_packet.cpp).
TEST(Watertight, NoRayMissesASliverAheadThatSpansItsOriginsPlane) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int misses = 0, far_off = 0, rays = 0;
    int packet_misses = 0, feeler_misses = 0, pair_misses = 0, pair_feeler_misses = 0;
    for (int s = 0; s < 2000; ++s) {
        const TriangleMesh m = twisted_sliver(static_cast<int>(rng() % 30000));
        const glm::dvec3 a(m.positions[0]), b(m.positions[1]), c(m.positions[2]);
        const glm::dvec3 n = glm::normalize(glm::cross(b - a, c - a));
        // the origin: off a point of the sliver's middle third, along its normal
        const double along = 0.35 + 0.3 * u(rng), away = (0.02 + 0.28 * u(rng)) * (s % 2 ? 1 : -1);
        const glm::dvec3 base = a + along * (c - a) + 0.5 * (b - a) * (1.0 - along);
        const vec3 origin(base + away * n);
        std::array<Ray, kPacketWidth> packet;
        for (int k = 0; k < kPacketWidth; ++k) {
            // a point inside, within 0.3 units of the origin's foot along the sliver, its
            // barycentrics at least 0.2 of the width there
            const double lambda = along + 0.1 * (u(rng) - 0.5);
            const double mu = (0.2 + 0.6 * u(rng)) * (1.0 - lambda);
            const glm::dvec3 aim = a + lambda * (c - a) + mu * (b - a);
            const glm::dvec3 d = aim - glm::dvec3(origin);
            const auto lane = static_cast<std::size_t>(k);
            packet[lane] = Ray{origin, vec3(d / glm::length(d))};
            const double expected = glm::length(d);
            Hit hit;
            ++rays;
            if (!m.intersect(packet[lane], hit)) {
                ++misses;
            } else {
                // a sliver's t from its edge functions is good to ~1e-4 of it
                far_off += std::fabs(hit.t - expected) > 1e-2 * expected;
            }
        }
        const unsigned all = (1u << kPacketWidth) - 1u, pair = 0x5u;
        const auto packet_hits = [&](unsigned lanes) {
            std::array<Hit, kPacketWidth> hits{};
            return std::popcount(lanes & ~m.intersect_packet(packet.data(), hits.data(), lanes));
        };
        std::array<float, kPacketWidth> far;
        far.fill(kInfinity);
        const auto feelers = [&](unsigned lanes) {
            return std::popcount(lanes & ~m.occluded_packet(packet.data(), far.data(), lanes));
        };
        packet_misses += packet_hits(all);
        feeler_misses += feelers(all);
        pair_misses += packet_hits(pair);
        pair_feeler_misses += feelers(pair);
    }
    EXPECT_EQ(misses, 0) << "of " << rays;
    EXPECT_EQ(packet_misses, 0) << "of " << rays;
    EXPECT_EQ(feeler_misses, 0) << "of " << rays;
    EXPECT_EQ(pair_misses, 0) << "of " << rays / kPacketWidth * 2;
    EXPECT_EQ(pair_feeler_misses, 0) << "of " << rays / kPacketWidth * 2;
    EXPECT_EQ(far_off, 0);
}

// The other side: a ray leaving a sliver's surface (offset_ray_origin) away from it never
// meets the sliver itself, however near its plane the origin lies.
TEST(Watertight, ARayLeavingASliverDoesNotMeetIt) {
    std::mt19937 rng(8);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int self_hits = 0;
    for (int s = 0; s < 2000; ++s) {
        const TriangleMesh m = twisted_sliver(static_cast<int>(rng() % 30000));
        const glm::dvec3 a(m.positions[0]), b(m.positions[1]), c(m.positions[2]);
        const glm::dvec3 n = glm::normalize(glm::cross(b - a, c - a));
        const double along = 0.1 + 0.8 * u(rng);
        const vec3 p(a + along * (c - a) + 0.5 * (b - a) * (1.0 - along));
        const double side = s % 2 ? 1.0 : -1.0;
        // a direction on the normal's side, its main axis often along the sliver
        const glm::dvec3 t = glm::normalize(c - a);
        const glm::dvec3 d = glm::normalize(side * (0.05 + u(rng)) * n + (u(rng) - 0.5) * 4.0 * t);
        Hit hit;
        self_hits += m.intersect(Ray{offset_ray_origin(p, vec3(side * n)), vec3(d)}, hit);
    }
    EXPECT_EQ(self_hits, 0);
}

}  // namespace
}  // namespace rt
