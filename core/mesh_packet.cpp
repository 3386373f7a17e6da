// The mesh's packet tests: up to kPacketWidth rays through its BVH together, and the
// item buffer's rays against one named triangle together (core/triangle_packet.h).
#include "core/mesh.h"

#include <array>
#include <bit>

#include "core/triangle_packet.h"

namespace rt {

namespace {

// A leaf that at least kRaysAcross rays of a packet enter, and at least kRaysPerTriangle
// rays for each of its triangles, tests its triangles across the rays, a triangle at a time
// (core/triangle_packet.h); otherwise each ray tests the whole leaf at once (up to eight
// triangles in one test, intersect(Triangle4, Triangle4, ...)). A triangle across the rays
// costs about what a ray against the leaf does, so the rays must outnumber the triangles
// for it to pay, and by two to one in practice: with the rays at least as many as the
// triangles, packets of shadow feelers took 1.00-1.01x Embree's rtcOccluded8 time on the
// bunny and 0.92x at two to one (primary packets 0.77-0.78x and 0.68-0.69x; teapot shadows
// 1.05-1.06x and 1.00x; docs/BENCHMARKS.md, nineteenth session).
constexpr int kRaysAcross = 3;
constexpr std::uint32_t kRaysPerTriangle = 2;

// The packet's rays set up for the watertight test, each alone and, where they share
// their permutation, together.
struct PacketShear {
    std::array<ShearedRay, kPacketWidth> each;
    ShearedRays<kPacketWidth> together;
    bool shared = false;

    // Set up at the first leaf a packet reaches (most of a camera's packets miss a mesh).
    const Ray* rays;
    unsigned active;
    bool ready = false;

    PacketShear(const Ray* r, unsigned a) : rays(r), active(a) {}
    const PacketShear& get() {
        if (ready) return *this;
        ready = true;
        shared = active != 0 && together.set(rays, active);
        for (unsigned m = active; m != 0; m &= m - 1) {
            const unsigned lane = __builtin_ctz(m);
            each[lane] =
                shared ? together.lane_ray(static_cast<int>(lane)) : ShearedRay(rays[lane]);
        }
        return *this;
    }
    bool across(unsigned lanes, std::uint32_t triangles) const {
        const int entering = std::popcount(lanes);
        return shared && entering >= kRaysAcross &&
               static_cast<std::uint32_t>(entering) >= kRaysPerTriangle * triangles;
    }
};

}  // namespace

unsigned TriangleMesh::intersect_packet(const Ray* rays, Hit* hits, unsigned active) const {
    std::array<float, kPacketWidth> t_max;
    for (unsigned m = active; m != 0; m &= m - 1)
        t_max[__builtin_ctz(m)] = hits[__builtin_ctz(m)].t;
    PacketShear lazy_shear(rays, active);
    unsigned found = 0, alone = 0;  // hits in the packet's leaves, and of rays traced alone
    unsigned unsure = 0;            // rays a leaf's test left unsettled: traced alone after
    accel_.traverse_packet<false>(
        rays, t_max.data(), active,
        [&](std::uint32_t leaf, std::uint32_t count, unsigned lanes) RT_FORCE_INLINE {
            unsigned hit = 0;
            const std::uint32_t start = first_pack(leaf);
            const PacketShear& shear = lazy_shear.get();
            const auto record = [&](unsigned ray, std::uint32_t pack, int lane, float b1,
                                    float b2) {
                Hit& out = hits[ray];
                out.prim = pack_prims_[kTriangle4Lanes * pack + static_cast<std::uint32_t>(lane)];
                out.b1 = b1;
                out.b2 = b2;
                hit |= 1u << ray;
            };
            if (shear.across(lanes, count)) {
                std::array<int, kPacketWidth> lane;
                std::array<float, kPacketWidth> b1, b2;
                for (std::uint32_t k = 0; kTriangle4Lanes * k < count; ++k) {
                    unsigned h =
                        rt::intersect<false>(packs_[start + k], shear.together, lanes, t_max.data(),
                                             lane.data(), b1.data(), b2.data(), 0xfu, &unsure);
                    for (; h != 0; h &= h - 1) {
                        const unsigned ray = __builtin_ctz(h);
                        record(ray, start + k, lane[ray], b1[ray], b2[ray]);
                    }
                }
            } else {
                for (; lanes != 0; lanes &= lanes - 1) {
                    const unsigned ray = __builtin_ctz(lanes);
                    unsigned doubt = 0;
                    const Triangle4Hit h =
                        leaf_hit(start, count, shear.each[ray], t_max[ray], &doubt);
                    unsure |= unsigned{doubt != 0} << ray;
                    if (h.lane < 0) continue;
                    t_max[ray] = h.t;
                    record(ray, start, h.lane, h.b1, h.b2);
                }
            }
            found |= hit;
            return hit;
        },
        [&](unsigned lanes) {
            for (; lanes != 0; lanes &= lanes - 1) {
                const unsigned lane = __builtin_ctz(lanes);
                if (intersect(rays[lane], hits[lane])) alone |= 1u << lane;
            }
        });
    for (unsigned m = found; m != 0; m &= m - 1) {
        const unsigned lane = __builtin_ctz(m);
        hits[lane].t = t_max[lane];
    }
    // A ray with a hit that only the plane test settles (a sliver spanning its origin's
    // plane, core/triangle4.h: a handful a frame) is traced again alone, within the hit
    // it has: it gets the very hit it gets alone, and the call stays out of the loops.
    for (unsigned m = unsure; m != 0; m &= m - 1) {
        const unsigned lane = __builtin_ctz(m);
        if (intersect(rays[lane], hits[lane])) alone |= 1u << lane;
    }
    return found | alone;
}

unsigned TriangleMesh::occluded_packet(const Ray* rays, const float* t_max, unsigned active) const {
    std::array<float, kPacketWidth> limits;
    for (unsigned m = active; m != 0; m &= m - 1)
        limits[__builtin_ctz(m)] = t_max[__builtin_ctz(m)];
    PacketShear lazy_shear(rays, active);
    unsigned blocked = 0, unsure = 0;  // unsure: as intersect_packet's
    accel_.traverse_packet<true>(
        rays, limits.data(), active,
        [&](std::uint32_t leaf, std::uint32_t count, unsigned lanes) RT_FORCE_INLINE {
            unsigned hit = 0;
            const std::uint32_t start = first_pack(leaf);
            const PacketShear& shear = lazy_shear.get();
            if (shear.across(lanes, count)) {
                for (std::uint32_t k = 0; kTriangle4Lanes * k < count && lanes != 0; ++k) {
                    const unsigned h =
                        rt::intersect<true>(packs_[start + k], shear.together, lanes, limits.data(),
                                            nullptr, nullptr, nullptr, 0xfu, &unsure);
                    hit |= h;
                    lanes &= ~h;
                }
            } else {
                for (; lanes != 0; lanes &= lanes - 1) {
                    const unsigned ray = __builtin_ctz(lanes);
                    unsigned doubt = 0;
                    if (leaf_blocks(start, count, shear.each[ray], limits[ray], &doubt))
                        hit |= 1u << ray;
                    unsure |= unsigned{doubt != 0} << ray;
                }
            }
            blocked |= hit;
            return hit;
        },
        [&](unsigned lanes) {
            for (; lanes != 0; lanes &= lanes - 1) {
                const unsigned lane = __builtin_ctz(lanes);
                if (occluded(rays[lane], t_max[lane])) blocked |= 1u << lane;
            }
        });
    for (unsigned m = unsure & ~blocked; m != 0; m &= m - 1) {
        const unsigned lane = __builtin_ctz(m);
        if (occluded(rays[lane], t_max[lane])) blocked |= 1u << lane;
    }
    return blocked;
}

unsigned TriangleMesh::intersect_triangle_packet(std::uint32_t prim,
                                                 const RayLanes<kPacketWidth>& rays, Hit* hits,
                                                 unsigned lanes) const {
    if (prim >= prim_lane_.size() || lanes == 0) return 0;
    const std::uint32_t at = prim_lane_[prim];
    ShearedRays<kPacketWidth> together;
    if (std::popcount(lanes) < kRaysAcross || !together.set(rays, lanes)) {
        unsigned found = 0;
        for (; lanes != 0; lanes &= lanes - 1) {
            const unsigned ray = __builtin_ctz(lanes);
            if (intersect_triangle(prim, rays.lane(static_cast<int>(ray)), hits[ray]))
                found |= 1u << ray;
        }
        return found;
    }
    std::array<float, kPacketWidth> t_max;
    std::array<int, kPacketWidth> lane;
    std::array<float, kPacketWidth> b1, b2;
    for (unsigned m = lanes; m != 0; m &= m - 1) t_max[__builtin_ctz(m)] = hits[__builtin_ctz(m)].t;
    const unsigned found =
        rt::intersect<false>(packs_[at / kTriangle4Lanes], together, lanes, t_max.data(),
                             lane.data(), b1.data(), b2.data(), 1u << (at % kTriangle4Lanes));
    for (unsigned m = found; m != 0; m &= m - 1) {
        const unsigned ray = __builtin_ctz(m);
        hits[ray].t = t_max[ray];
        hits[ray].prim = prim;
        hits[ray].b1 = b1[ray];
        hits[ray].b2 = b2[ray];
    }
    return found;
}

unsigned TriangleMesh::intersect_triangles_packet(const std::uint32_t* prims,
                                                  const RayLanes<kPacketWidth>& rays, Hit* hits,
                                                  unsigned lanes) const {
    using Float = Lanes<kPacketWidth>::Float;
    for (unsigned m = lanes; m != 0; m &= m - 1)
        if (prims[__builtin_ctz(m)] >= prim_lane_.size()) lanes &= ~(1u << __builtin_ctz(m));
    if (lanes == 0) return 0;
    const std::uint32_t first = prims[__builtin_ctz(lanes)];
    bool one = true;
    for (unsigned m = lanes; m != 0; m &= m - 1) one &= prims[__builtin_ctz(m)] == first;
    if (one) return intersect_triangle_packet(first, rays, hits, lanes);
    ShearedRays<kPacketWidth> together;
    if (std::popcount(lanes) < kRaysAcross || !together.set(rays, lanes)) {
        unsigned found = 0;
        for (; lanes != 0; lanes &= lanes - 1) {
            const unsigned ray = __builtin_ctz(lanes);
            if (intersect_triangle(prims[ray], rays.lane(static_cast<int>(ray)), hits[ray]))
                found |= 1u << ray;
        }
        return found;
    }
    // Each ray's own triangle as the lanes: its corners (the very floats its pack holds)
    // read as rows of three from the positions and transposed, not a float at a time into
    // lanes that are then read as vectors (each vector's load waited on eight stores).
    static_assert(sizeof(vec3) == 3 * sizeof(float));
    std::array<const float*, kPacketWidth> corners[3];
    for (int lane = 0; lane < kPacketWidth; ++lane) {
        const glm::uvec3& corner = triangles[((lanes >> lane) & 1u) != 0 ? prims[lane] : first];
        for (int vertex = 0; vertex < 3; ++vertex)
            corners[vertex][lane] = &positions[corner[vertex]].x;
    }
    Float v[3][4];
    for (int vertex = 0; vertex < 3; ++vertex)
        transpose_rows<kPacketWidth, 3>(corners[vertex].data(), v[vertex]);
    const Float limit = t_bounds<kPacketWidth>(hits, lanes);
    const auto corner = [&](int vertex, int axis) { return v[vertex][axis]; };
    Float t, b1, b2;
    const unsigned found =
        detail::watertight_lanes<true>(corner, together, limit, lanes, t, b1, b2);
    for (unsigned m = found; m != 0; m &= m - 1) {
        const unsigned ray = __builtin_ctz(m);
        hits[ray].t = t[ray];
        hits[ray].prim = prims[ray];
        hits[ray].b1 = b1[ray];
        hits[ray].b2 = b2[ray];
    }
    return found;
}

}  // namespace rt
