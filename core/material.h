#pragma once
// One material feeds the tracer and, later, the GL uniforms: a single source of truth.

#include <cmath>
#include <optional>
#include <string>

#include "core/ray.h"

namespace rt {

// A solid checker of two colours with squares `scale` wide, as on Whitted's floor.
// The pattern colour multiplies ka and kd, so shadowed squares keep the pattern.
struct Checker {
    vec3 colour_a{1.0f};
    vec3 colour_b{0.0f};
    float scale = 1.0f;

    vec3 at(const vec3& p) const {
        const auto cell = [&](float x) { return static_cast<long long>(std::floor(x / scale)); };
        return ((cell(p.x) + cell(p.y) + cell(p.z)) & 1) == 0 ? colour_a : colour_b;
    }
};

struct Material {
    std::string name = "default";
    vec3 ka{0.1f};            // ambient reflection
    vec3 kd{0.7f};            // diffuse reflection
    vec3 ks{0.0f};            // specular reflection
    float shininess = 32.0f;  // Phong exponent
    float reflectivity = 0.0f;
    float transparency = 0.0f;
    float ior = 1.5f;  // index of refraction (outside is air, 1.0)
    std::optional<Checker> checker;
};

}  // namespace rt
