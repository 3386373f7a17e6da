#pragma once
// Three-component vectors across SIMD lanes, one point or direction per lane (a
// structure of arrays): the local Phong term of several pixels at once
// (Tracer::shade_found). Each operation is glm's, lane by lane and in glm's order (a dot
// product is (x x' + y y') + z z'; a normalisation multiplies by 1 / sqrt), and the build
// does not fuse a * b + c, so every lane's result is bit for bit what glm computes.

#include <array>
#include <bit>

#include "core/ray.h"
#include "core/simd.h"

namespace rt {

template <int N>
struct Vec3Lanes {
    using Float = typename Lanes<N>::Float;
    using Mask = typename Lanes<N>::Mask;
    Float x, y, z;

    static Vec3Lanes splat(const vec3& v) {
        return {rt::splat<Float>(v.x), rt::splat<Float>(v.y), rt::splat<Float>(v.z)};
    }
    void set(int lane, const vec3& v) {
        x[lane] = v.x;
        y[lane] = v.y;
        z[lane] = v.z;
    }
    vec3 get(int lane) const { return vec3(x[lane], y[lane], z[lane]); }

    // Lane k: the three floats at rows[k] + first (first 0 or 1), as set(k, ...) of each
    // would make them. Each rows[k] must point at four readable floats (a vec3 and the
    // field after it, or the one before it and the vec3): they are read whole and
    // transposed (transpose_rows), where setting a lane at a time stores the floats one
    // by one and then loads the vector over them, a store-forwarding stall per vector.
    static Vec3Lanes transpose(const std::array<const float*, N>& rows, int first) {
        Float c[4];
        transpose_rows<N>(rows.data(), c);
        return {c[first], c[first + 1], c[first + 2]};
    }

    friend Vec3Lanes operator+(const Vec3Lanes& a, const Vec3Lanes& b) {
        return {a.x + b.x, a.y + b.y, a.z + b.z};
    }
    friend Vec3Lanes operator-(const Vec3Lanes& a, const Vec3Lanes& b) {
        return {a.x - b.x, a.y - b.y, a.z - b.z};
    }
    friend Vec3Lanes operator-(const Vec3Lanes& a) { return {-a.x, -a.y, -a.z}; }
    friend Vec3Lanes operator*(const Vec3Lanes& a, const Vec3Lanes& b) {
        return {a.x * b.x, a.y * b.y, a.z * b.z};
    }
    friend Vec3Lanes operator*(const Vec3Lanes& a, Float s) { return {a.x * s, a.y * s, a.z * s}; }
    friend Vec3Lanes operator/(const Vec3Lanes& a, Float s) { return {a.x / s, a.y / s, a.z / s}; }
    friend Float dot(const Vec3Lanes& a, const Vec3Lanes& b) {
        const Vec3Lanes p = a * b;
        return p.x + p.y + p.z;
    }
    // glm::normalize: v * (1 / sqrt(v . v)).
    friend Vec3Lanes normalize(const Vec3Lanes& v) {
        return v * (rt::splat<Float>(1.0f) / vsqrt(dot(v, v)));
    }
    // The mask of the lanes whose bits (lane 0 lowest) are set.
    static Mask mask(unsigned lanes) {
        Mask bit;
        for (int k = 0; k < N; ++k) bit[k] = 1 << k;
        return ((Mask{} + static_cast<int>(lanes)) & bit) != 0;
    }
    // Lane by lane, `a` where `m` is set, else `b`.
    friend Vec3Lanes select(Mask m, const Vec3Lanes& a, const Vec3Lanes& b) {
        return {m ? a.x : b.x, m ? a.y : b.y, m ? a.z : b.z};
    }
};

// offset_ray_origin (core/ray.h), lane by lane.
template <int N>
Vec3Lanes<N> offset_ray_origin(const Vec3Lanes<N>& p, const Vec3Lanes<N>& normal) {
    using Float = typename Lanes<N>::Float;
    using Int = typename Lanes<N>::Mask;
    using namespace origin_offset;
    const auto step = [](Float x, Float n) {
        const Int ulps = __builtin_convertvector(splat<Float>(kIntScale) * n, Int);
        const Int bits = std::bit_cast<Int>(x);
        const Float stepped = std::bit_cast<Float>(bits + (x < splat<Float>(0.0f) ? -ulps : ulps));
        return vabs(x) < splat<Float>(kOriginBand) ? x + splat<Float>(kFloatScale) * n : stepped;
    };
    return {step(p.x, normal.x), step(p.y, normal.y), step(p.z, normal.z)};
}

}  // namespace rt
