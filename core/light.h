#pragma once

#include <glm/geometric.hpp>

#include "core/ray.h"

namespace rt {

struct Light {
    enum class Type { kPoint, kDirectional };
    Type type = Type::kPoint;
    vec3 position{0.0f};                // point lights
    vec3 direction{0.0f, -1.0f, 0.0f};  // directional lights: the way the light travels (unit)
    vec3 colour{1.0f};                  // the tutorial's I_l

    // The shadow feeler from p: sf(t) = p + (l - p) t with t in (0, 1) for a point light;
    // towards the light, unbounded, for a directional one. Returns the t limit.
    float feeler(const vec3& p, vec3& dir) const {
        if (type == Type::kPoint) {
            dir = position - p;
            return 1.0f;
        }
        dir = -direction;
        return kInfinity;
    }
};

}  // namespace rt
