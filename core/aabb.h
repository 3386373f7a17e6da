#pragma once
// Axis-aligned bounding box: the tutorial's "object extents".

#include <algorithm>

#include <glm/common.hpp>
#include <glm/mat4x4.hpp>

#include "core/ray.h"

namespace rt {

struct Aabb {
    vec3 lo{kInfinity};
    vec3 hi{-kInfinity};

    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    void grow(const vec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    void grow(const Aabb& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    vec3 centre() const { return 0.5f * (lo + hi); }
    // Corner i (0 .. 7): bit 0 picks hi.x over lo.x, bit 1 hi.y, bit 2 hi.z.
    vec3 corner(int i) const {
        return {(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z};
    }
    vec3 extent() const { return hi - lo; }
    float half_area() const {
        const vec3 e = extent();
        return empty() ? 0.0f : e.x * e.y + e.y * e.z + e.z * e.x;
    }
    // The box that holds this box after the affine transform m.
    Aabb transformed(const glm::mat4& m) const;
};

inline Aabb Aabb::transformed(const glm::mat4& m) const {
    Aabb out;
    if (empty()) return out;
    for (int i = 0; i < 8; ++i) out.grow(vec3(m * glm::vec4(corner(i), 1.0f)));
    return out;
}

// A far plane's distance times this is conservative against rounding (Ize, "Robust BVH
// Ray Traversal", 2013): a ray that grazes a box edge is not lost. The wide BVH puts it
// into the far planes' inverse directions instead, a multiplication less per node.
inline constexpr float kSlabExitFactor = 1.00000024f;

// Slab test against a precomputed reciprocal direction; returns the entry distance or
// +inf when the ray misses the box within (0, t_max). A ray lying in a face's plane
// (direction 0 there, origin exactly on the face) gives 0 * inf = NaN for that plane;
// NaN fails both comparisons below, so that plane constrains nothing and the ray counts
// as inside the closed box, as it is.
inline float slab_entry(const Aabb& box, const vec3& origin, const vec3& inv_dir, float t_max) {
    float enter = 0.0f, leave = t_max;
    for (int a = 0; a < 3; ++a) {
        const float t_lo = (box.lo[a] - origin[a]) * inv_dir[a];
        const float t_hi = (box.hi[a] - origin[a]) * inv_dir[a];
        const bool negative = inv_dir[a] < 0.0f;
        const float near = negative ? t_hi : t_lo, far = negative ? t_lo : t_hi;
        if (near > enter) enter = near;
        if (far < leave) leave = far;
    }
    return enter <= leave * kSlabExitFactor ? enter : kInfinity;
}

}  // namespace rt
