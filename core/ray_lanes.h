#pragma once
// Up to N rays as SIMD lanes (a structure of arrays): gathered once from the rays of a
// packet, then handed to every test across the rays (core/shape_packets.h, the item
// buffer's named triangle), which no longer read the rays one lane at a time.

#include <array>
#include <cstddef>

#include "core/hit.h"
#include "core/ray.h"
#include "core/simd.h"
#include "core/transform.h"

namespace rt {

namespace detail {

// Lane k of the result is base[(lane k of `lanes`, else the first of them) * stride]: a
// field of an array of records as lanes, the lanes not asked for repeating the first.
// `lanes` holds at least one bit (the first of none is undefined).
// Lane by lane: AVX2's gather instruction was slower here (the item buffer's primary
// step 5 to 10 %, and the same in the camera packets' plane test).
template <int N>
typename Lanes<N>::Float gather_field(const float* base, int stride, unsigned lanes) {
    using Mask = typename Lanes<N>::Mask;
    Mask index;
    const int first = __builtin_ctz(lanes);
    for (int k = 0; k < N; ++k) index[k] = ((lanes >> k) & 1u ? k : first) * stride;
    typename Lanes<N>::Float out;
    for (int k = 0; k < N; ++k) out[k] = base[index[k]];
    return out;
}

}  // namespace detail

template <int N>
struct RayLanes {
    using Float = typename Lanes<N>::Float;
    Float origin[3], dir[3];  // every lane written by whoever makes one

    // rays[lane] for each bit of `lanes` (one or more); the other lanes copy the first of
    // them (real numbers, so no lane computes a NaN or a trap).
    // Each ray is read as two rows of four floats, transposed (transpose_rows): its origin
    // and its direction's x, then its origin's z and its direction.
    static RayLanes gather(const Ray* rays, unsigned lanes) {
        static_assert(sizeof(Ray) == 6 * sizeof(float) && offsetof(Ray, dir) == 3 * sizeof(float));
        std::array<const float*, N> front, back;
        const int first = __builtin_ctz(lanes);
        for (int k = 0; k < N; ++k) {
            const Ray& r = rays[(lanes >> k) & 1u ? k : first];
            front[k] = &r.origin.x;
            back[k] = &r.origin.z;
        }
        RayLanes out;
        Float columns[4];
        transpose_rows<N>(front.data(), columns);
        for (int a = 0; a < 3; ++a) out.origin[a] = columns[a];
        transpose_rows<N>(back.data(), columns);
        for (int a = 0; a < 3; ++a) out.dir[a] = columns[a + 1];
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
// rays' bounds as lanes.
template <int N>
typename Lanes<N>::Float t_bounds(const Hit* hits, unsigned lanes) {
    static_assert(sizeof(Hit) == 5 * sizeof(float) && offsetof(Hit, t) == 0);
    return detail::gather_field<N>(&hits[0].t, 5, lanes);
}

}  // namespace rt
