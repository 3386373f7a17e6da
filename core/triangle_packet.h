#pragma once
// A pack's four triangles against a packet of rays, the rays as the lanes: for a leaf that
// several rays of a packet enter, one vector test per triangle instead of one Triangle4
// test per ray. The rays must share their permutation of the axes (ShearedRay's kx, ky,
// kz, which coherent rays do); each lane then does, operation for operation, what
// intersect(Triangle4, ShearedRay) does for that ray and that triangle, so every ray
// gets the very hit (t, triangle, barycentrics) it gets alone.

#include <cmath>
#include <cstdint>
#include <utility>

#include "core/ray_lanes.h"
#include "core/simd.h"
#include "core/triangle4.h"

namespace rt {

template <int N>
struct ShearedRays {
    using Float = typename Lanes<N>::Float;
    int kx = 0, ky = 1, kz = 2;
    Float sx{}, sy{}, sz{}, abs_sz{}, origin[3]{};

    // False where the rays (those of `lanes`) do not share one permutation.
    bool set(const ShearedRay* rays, unsigned lanes) {
        const int first = __builtin_ctz(lanes);
        kx = rays[first].kx;
        ky = rays[first].ky;
        kz = rays[first].kz;
        for (int lane = 0; lane < N; ++lane) {
            const ShearedRay& r = rays[(lanes >> lane) & 1u ? lane : first];
            if (r.kx != kx || r.ky != ky || r.kz != kz) return false;
            sx[lane] = r.sx;
            sy[lane] = r.sy;
            sz[lane] = r.sz;
            abs_sz[lane] = std::fabs(r.sz);
            for (int a = 0; a < 3; ++a) origin[a][lane] = r.origin[a];
        }
        return true;
    }

    // The same from the rays themselves, with vector arithmetic (lane by lane
    // ShearedRay's: the same comparisons choose the axes, the same IEEE divisions).
    bool set(const Ray* rays, unsigned lanes) {
        return set(RayLanes<N>::gather(rays, lanes), lanes);
    }
    // Only the lanes of `lanes` count (the others may hold any real rays).
    bool set(const RayLanes<N>& rays, unsigned lanes) {
        const Float* d = rays.dir;
        for (int a = 0; a < 3; ++a) origin[a] = rays.origin[a];
        const Float ax = vabs(d[0]), ay = vabs(d[1]), az = vabs(d[2]);
        const unsigned x_over_y = bits(ax > ay);
        const unsigned z_is_x = x_over_y & bits(ax > az) & lanes,
                       z_is_y = ~x_over_y & bits(ay > az) & lanes;
        if (z_is_x == lanes) {
            kz = 0;
        } else if (z_is_y == lanes) {
            kz = 1;
        } else if ((z_is_x | z_is_y) == 0) {
            kz = 2;
        } else {
            return false;
        }
        kx = (kz + 1) % 3;
        ky = (kx + 1) % 3;
        const unsigned negative = bits(d[kz] < 0.0f) & lanes;
        if (negative != 0 && negative != lanes) return false;
        if (negative != 0) std::swap(kx, ky);  // keep the winding
        sx = d[kx] / d[kz];
        sy = d[ky] / d[kz];
        sz = 1.0f / d[kz];
        abs_sz = vabs(sz);
        return true;
    }

    // Lane `lane` as the single ray's ShearedRay.
    ShearedRay lane_ray(int lane) const {
        ShearedRay r;
        r.kx = kx;
        r.ky = ky;
        r.kz = kz;
        r.sx = sx[lane];
        r.sy = sy[lane];
        r.sz = sz[lane];
        for (int a = 0; a < 3; ++a) r.origin[a] = origin[a][lane];
        return r;
    }
};

namespace detail {

// The watertight test of one triangle per ray, the rays as the lanes: corner(vertex, axis)
// gives each lane's vertex. Returns the rays of `lanes` that hit
// within their `limit` (their t in `t`); with kBarycentrics, b1 and b2 as well.
// `deferred`: as watertight_hits' (core/triangle4.h).
template <bool kBarycentrics, int N, class Corner>
[[gnu::always_inline]] inline unsigned watertight_lanes(
    const Corner& corner, const ShearedRays<N>& r, const typename Lanes<N>::Float& limit,
    unsigned lanes, typename Lanes<N>::Float& t, typename Lanes<N>::Float& b1,
    typename Lanes<N>::Float& b2, unsigned* deferred = nullptr) {
    using Float = typename Lanes<N>::Float;
    const auto o =
        watertight_values<Float>(relative_to_origin(corner, r), r.kx, r.ky, r.kz, r.sx, r.sy);
    const unsigned candidates = watertight_hits(o, corner, r, r.abs_sz, limit, lanes, t, deferred);
    if constexpr (kBarycentrics) {
        if (candidates != 0) {
            b1 = o.v / o.det;  // each lane's own IEEE division
            b2 = o.w / o.det;
        }
    }
    return candidates;
}

}  // namespace detail

// Per ray, the nearest hit of the pack's triangles within its own (0, t_max): fills
// t_max, lane (the triangle's lane in the pack), b1 and b2 of the rays that hit one and
// returns their bits. kAnyHit: returns the rays that hit any, nothing else written.
// `triangles`: the pack's lanes to test (the item buffer names one). `deferred`: where
// given, the rays a triangle left unsettled (watertight_hits) are added to it.
template <bool kAnyHit, int N>
[[gnu::always_inline]] inline unsigned intersect(const Triangle4& tri, const ShearedRays<N>& r,
                                                 unsigned lanes, float* t_max, int* lane_out,
                                                 float* b1, float* b2, unsigned triangles = 0xfu,
                                                 unsigned* deferred = nullptr) {
    using Float = typename Lanes<N>::Float;
    Float limit = select_bits(lanes, load<Float>(t_max), splat<Float>(0.0f));
    unsigned found = 0;
    for (int j = 0; j < 4; ++j) {
        if (((triangles >> j) & 1u) == 0) continue;
        const auto corner = [&](int vertex, int axis) {
            return splat<Float>(tri.v[vertex][axis][j]);
        };
        Float t, v, w;
        unsigned candidates =
            detail::watertight_lanes<!kAnyHit>(corner, r, limit, lanes, t, v, w, deferred);
        if constexpr (kAnyHit) {
            found |= candidates;
            lanes &= ~candidates;
            if (lanes == 0) return found;
            continue;
        }
        if (candidates == 0) continue;
        limit = select_bits(candidates, t, limit);  // each candidate is nearer than its limit
        found |= candidates;
        for (; candidates != 0; candidates &= candidates - 1) {
            const int ray = __builtin_ctz(candidates);
            t_max[ray] = t[ray];
            lane_out[ray] = j;
            b1[ray] = v[ray];
            b2[ray] = w[ray];
        }
    }
    return found;
}

}  // namespace rt
