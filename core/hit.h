#pragma once
// What traversal records about the closest hit; the full surface record is built once,
// after the search ("find the closest hit first, then build the hit record").

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>

#include <glm/vec2.hpp>

#include "core/ray.h"

namespace rt {

inline constexpr std::uint32_t kNoObject = std::numeric_limits<std::uint32_t>::max();

struct Hit {
    float t = kInfinity;
    std::uint32_t object = kNoObject;
    std::uint32_t prim = 0;  // triangle index within a mesh
    float b1 = 0.0f;         // barycentrics of a triangle hit
    float b2 = 0.0f;

    bool found() const { return object != kNoObject; }
};

// hits[0 .. n) made fresh (Hit{}); a full packet (eight, or sixteen) as one copy of fresh
// records (five or ten vector stores), not field by field.
inline void reset_hits(Hit* hits, std::size_t n) {
    static constexpr Hit kFresh[16]{};
    if (n == 8) {
        std::memcpy(hits, kFresh, 8 * sizeof(Hit));
        return;
    }
    if (n == 16) {
        std::memcpy(hits, kFresh, sizeof kFresh);
        return;
    }
    for (std::size_t k = 0; k < n; ++k) hits[k] = Hit{};
}

// The surface at a hit, in world space. Both normals face the incoming ray, whichever
// way the surface is wound (refraction asks the ray's media, not the winding, whether it
// enters or leaves: core/medium.h).
struct SurfacePoint {
    vec3 p{0.0f};
    vec3 geometric_normal{0.0f, 1.0f, 0.0f};
    vec3 normal{0.0f, 1.0f, 0.0f};  // shading normal
    std::uint32_t material = 0;
    vec3 pattern_point{0.0f};  // where a checker is evaluated (object space)
    glm::vec2 uv{0.0f};        // where a texture is sampled (core/texture.h)
    vec3 colour{1.0f};         // a mesh's vertex colour, multiplying ka and kd
    // The object hit, where a ray leaving the point on the normal's side cannot meet it
    // again (a plane or triangle, or a sphere's outside: convex, Shape::kConvex), so a
    // shadow feeler need not test it; kNoObject for meshes and a sphere's inside.
    std::uint32_t cannot_meet_again = kNoObject;
};

}  // namespace rt
