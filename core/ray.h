#pragma once
// A ray p(t) = origin + dir * t (the tutorial's p(t) = p0 + d t). `dir` need not be
// unit length: transformed rays keep t, so their directions are not normalised.

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include <glm/vec3.hpp>

namespace rt {

using glm::vec3;

inline constexpr float kInfinity = std::numeric_limits<float>::infinity();

// Whether all three components are finite numbers (no NaN, no infinity).
inline bool finite(const vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

struct Ray {
    vec3 origin{0.0f};
    vec3 dir{0.0f, 0.0f, -1.0f};

    vec3 at(float t) const { return origin + dir * t; }
};

// Whether origin and direction are finite numbers. A NaN or infinite ray (a camera
// framed on collapsed geometry, a degenerate transform) hits nothing: the box tests'
// NaN handling would otherwise count it as inside every box, unused wide-BVH lanes too.
inline bool finite_ray(const Ray& r) {
    float sum = 0.0f;
    for (int a = 0; a < 3; ++a) sum += r.origin[a] * 0.0f + r.dir[a] * 0.0f;
    return sum == 0.0f;  // x * 0 is NaN exactly when x is NaN or infinite
}

// Moves a surface point off the surface along `normal` (pointing to the side the new ray
// leaves from) by an amount that scales with the point's floating-point precision:
// a fixed number of ULPs far from the origin, a small absolute step near it
// (Waechter & Binder, "A Fast and Robust Method for Avoiding Self-Intersection",
// Ray Tracing Gems, ch. 6). This replaces the magic epsilon of t > 0.001.
namespace origin_offset {
inline constexpr float kOriginBand = 1.0f / 32.0f;     // below this |x|, step absolutely
inline constexpr float kFloatScale = 1.0f / 65536.0f;  // absolute step near the origin
inline constexpr float kIntScale = 256.0f;             // ULPs to step elsewhere
}  // namespace origin_offset

inline vec3 offset_ray_origin(const vec3& p, const vec3& normal) {
    using namespace origin_offset;
    vec3 out;
    for (int i = 0; i < 3; ++i) {
        const auto ulps = static_cast<std::int32_t>(kIntScale * normal[i]);
        const auto bits = std::bit_cast<std::int32_t>(p[i]);
        const float stepped = std::bit_cast<float>(bits + (p[i] < 0.0f ? -ulps : ulps));
        out[i] = std::fabs(p[i]) < kOriginBand ? p[i] + kFloatScale * normal[i] : stepped;
    }
    return out;
}

}  // namespace rt
