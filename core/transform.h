#pragma once
// An instance transform as the tutorial applies it: the ray goes into object space by
// M^-1 (points with w = 1, directions with w = 0), t stays the same, and normals come
// back by M^-T without translation, normalised.

#include <optional>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include "core/ray.h"

namespace rt {

struct Transform {
    glm::mat4 m{1.0f};
    glm::mat4 inv{1.0f};
    glm::mat3 normal{1.0f};  // (M^-1)^T of the upper 3x3

    // Nothing when m is singular or not finite.
    static std::optional<Transform> from_matrix(const glm::mat4& m);

    Ray to_object(const Ray& r) const {
        return Ray{vec3(inv * glm::vec4(r.origin, 1.0f)), vec3(inv * glm::vec4(r.dir, 0.0f))};
    }
    vec3 point_to_world(const vec3& p) const { return vec3(m * glm::vec4(p, 1.0f)); }
    vec3 normal_to_world(const vec3& n) const { return glm::normalize(normal * n); }
};

}  // namespace rt
