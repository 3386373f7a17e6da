#pragma once
// Four triangles against one ray at once, with the watertight test of Woop, Benthin and
// Wald ("Watertight Ray/Triangle Intersection", JCGT 2013): the ray is sheared to the
// z axis and the three 2D edge functions are evaluated from the original vertices, so a
// ray through a shared edge or vertex of a closed mesh hits at least one of the
// triangles: nothing leaks. It is the tutorial's test (a plane hit, then three edge
// values that must share a sign, divided by their sum for the barycentrics) done in the
// ray's own frame, four triangles a time (core/simd.h).

#include <cmath>
#include <cstdint>

#include "core/ray.h"
#include "core/simd.h"

namespace rt {

// A ray prepared for the watertight test: the axes permuted so that z is the largest
// component of the direction, and the shear that maps the direction onto +z.
struct ShearedRay {
    int kx = 0, ky = 1, kz = 2;
    float sx = 0.0f, sy = 0.0f, sz = 1.0f;
    vec3 origin{0.0f};

    ShearedRay() = default;
    explicit ShearedRay(const Ray& r) : origin(r.origin) {
        const vec3 a{std::fabs(r.dir.x), std::fabs(r.dir.y), std::fabs(r.dir.z)};
        kz = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
        kx = (kz + 1) % 3;
        ky = (kx + 1) % 3;
        if (r.dir[kz] < 0.0f) std::swap(kx, ky);  // keep the winding
        sx = r.dir[kx] / r.dir[kz];
        sy = r.dir[ky] / r.dir[kz];
        sz = 1.0f / r.dir[kz];
    }
};

inline constexpr std::uint32_t kTriangle4Lanes = 4;

struct Triangle4 {
    Float4 v[3][3]{};  // v[vertex][axis] lanes; unused lanes stay zero (never hit)

    void set(int lane, const vec3& a, const vec3& b, const vec3& c) {
        for (int axis = 0; axis < 3; ++axis) {
            v[0][axis][lane] = a[axis];
            v[1][axis][lane] = b[axis];
            v[2][axis][lane] = c[axis];
        }
    }
};

struct Triangle4Hit {
    int lane = -1;                              // -1: no hit
    float t = kInfinity, b1 = 0.0f, b2 = 0.0f;  // b1, b2: weights of the second and third vertex
};

// `lanes`: the lanes that may hit (a bit each); the others are computed and ignored, so a
// lane's answer is the same whichever others are asked for.
[[gnu::always_inline]] inline Triangle4Hit intersect(const Triangle4& tri, const ShearedRay& r,
                                                     float t_max, unsigned lanes = 0xfu) {
    const auto rel = [&](int vertex, int axis) { return tri.v[vertex][axis] - r.origin[axis]; };
    const Float4 az = rel(0, r.kz), bz = rel(1, r.kz), cz = rel(2, r.kz);
    const Float4 ax = rel(0, r.kx) - r.sx * az, ay = rel(0, r.ky) - r.sy * az;
    const Float4 bx = rel(1, r.kx) - r.sx * bz, by = rel(1, r.ky) - r.sy * bz;
    const Float4 cx = rel(2, r.kx) - r.sx * cz, cy = rel(2, r.ky) - r.sy * cz;
    // The edge functions: each is the weight of the opposite vertex, times their sum.
    const Float4 u = cx * by - cy * bx, v = ax * cy - ay * cx, w = bx * ay - by * ax;
    const Mask4 same_sign =
        ((u >= 0.0f) & (v >= 0.0f) & (w >= 0.0f)) | ((u <= 0.0f) & (v <= 0.0f) & (w <= 0.0f));
    const Float4 det = u + v + w;
    const Mask4 inside = same_sign & (det != 0.0f);
    Triangle4Hit best;
    if (bits(inside) == 0) return best;  // most leaf tests end here, before any division
    const Float4 t_scaled = r.sz * (u * az + v * bz + w * cz);  // t * det
    const Float4 t = t_scaled / det;
    unsigned candidates = bits(inside & (t > 0.0f) & (t < t_max)) & lanes;
    if (candidates == 0) return best;
    // Not only t > 0 but t beyond its own rounding error (Pharr, Jakob and Humphreys,
    // PBR 3rd ed., 3.9.6): the error grows with the triangle's size, so a ray leaving a
    // large triangle, offset from it by a little (offset_ray_origin), could otherwise hit
    // the triangle itself just in front of its origin: acne on big walls. Compared as
    // |t * det| against the bound times |det|, so without a division.
    const auto gamma = [](float n) { return n * 0x1p-24f / (1.0f - n * 0x1p-24f); };
    const auto max3 = [](Float4 a, Float4 b, Float4 c) {
        return vmax(vmax(vabs(a), vabs(b)), vabs(c));
    };
    const Float4 x_max = max3(ax, bx, cx), y_max = max3(ay, by, cy);
    const Float4 z_max = max3(az, bz, cz) * std::fabs(r.sz);
    const Float4 delta_x = gamma(5) * (x_max + z_max), delta_y = gamma(5) * (y_max + z_max);
    const Float4 delta_e = 2.0f * (gamma(2) * x_max * y_max + delta_y * x_max + delta_x * y_max);
    const Float4 e_max = max3(u, v, w);
    const Float4 delta_t_det =
        3.0f * (gamma(3) * e_max * z_max + delta_e * z_max + gamma(3) * z_max * e_max);
    candidates &= bits(vabs(t_scaled) > delta_t_det);
    for (; candidates != 0; candidates &= candidates - 1) {
        const int lane = __builtin_ctz(candidates);
        if (t[lane] < best.t) best = {lane, t[lane], 0.0f, 0.0f};
    }
    if (best.lane >= 0) {
        best.b1 = v[best.lane] / det[best.lane];
        best.b2 = w[best.lane] / det[best.lane];
    }
    return best;
}

}  // namespace rt
