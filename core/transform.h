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
        Ray out;
        to_object(r, out);
        return out;
    }
    // The same into `out`, origin and direction written apart. A returned Ray assigned
    // whole was stored as 16 + 8 bytes, and the shapes read the direction's x and y as
    // 8 bytes across the two stores, which the CPU cannot forward from its store buffer:
    // each such read waited for the stores to retire (whitted's frame 0.96-0.98x with
    // this form, interleaved runs; core/scene.cpp's object_ray).
    void to_object(const Ray& r, Ray& out) const {
        out.origin = vec3(inv * glm::vec4(r.origin, 1.0f));
        out.dir = vec3(inv * glm::vec4(r.dir, 0.0f));
    }
    vec3 point_to_world(const vec3& p) const { return vec3(m * glm::vec4(p, 1.0f)); }
    vec3 normal_to_world(const vec3& n) const { return glm::normalize(normal * n); }
};

}  // namespace rt
