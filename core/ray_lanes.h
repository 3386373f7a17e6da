#pragma once
// Up to N rays as SIMD lanes (a structure of arrays): gathered once from the rays of a
// packet, then handed to every test across the rays (core/shape_packets.h, the item
// buffer's named triangle), which no longer read the rays one lane at a time.

#include <cstring>

#include "core/hit.h"
#include "core/ray.h"
#include "core/simd.h"
#include "core/transform.h"

namespace rt {

template <int N>
struct RayLanes {
    using Float = typename Lanes<N>::Float;
    Float origin[3], dir[3];  // every lane written by whoever makes one

    // rays[lane] for each bit of `lanes`; the other lanes copy the first of them (real
    // numbers, so no lane computes a NaN or a trap).
    static RayLanes gather(const Ray* rays, unsigned lanes) {
        RayLanes out;
        const int first = __builtin_ctz(lanes);
        for (int lane = 0; lane < N; ++lane) {
            const Ray& r = rays[(lanes >> lane) & 1u ? lane : first];
            for (int a = 0; a < 3; ++a) {
                out.origin[a][lane] = r.origin[a];
                out.dir[a][lane] = r.dir[a];
            }
        }
        return out;
    }

    Ray lane(int k) const {
        return Ray{vec3(origin[0][k], origin[1][k], origin[2][k]),
                   vec3(dir[0][k], dir[1][k], dir[2][k])};
    }

    // Transform::to_object for every lane, in glm's order for a matrix times a vector,
    // (m0 v0 + m1 v1) + (m2 v2 + m3 v3), so each lane is the ray to_object gives.
    RayLanes to_object(const Transform& t) const {
        RayLanes out;
        const glm::mat4& m = t.inv;
        for (int row = 0; row < 3; ++row) {
            const auto apply = [&](const Float* v, float w) {
                return (m[0][row] * v[0] + m[1][row] * v[1]) + (m[2][row] * v[2] + m[3][row] * w);
            };
            out.origin[row] = apply(origin, 1.0f);
            out.dir[row] = apply(dir, 0.0f);
        }
        return out;
    }
};

// hits[lane].t for each bit of `lanes` (the other lanes repeat the first of them): the
// rays' bounds as lanes. Written to memory and read as one vector, not inserted lane by
// lane, and chosen by index, not by a branch per lane.
template <int N>
typename Lanes<N>::Float t_bounds(const Hit* hits, unsigned lanes) {
    alignas(4 * N) float t[N];
    const unsigned first = static_cast<unsigned>(__builtin_ctz(lanes));
    for (unsigned lane = 0; lane < N; ++lane) t[lane] = hits[(lanes >> lane) & 1u ? lane : first].t;
    typename Lanes<N>::Float out;
    std::memcpy(&out, t, sizeof out);
    return out;
}

}  // namespace rt
