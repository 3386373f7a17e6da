#pragma once
// One material feeds the tracer and, later, the GL uniforms: a single source of truth.

#include <cmath>
#include <cstdint>
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

    // Each cell's parity in float, f - 2 floor(f / 2), so it is defined at any coordinate
    // (past 2^24 every float is even) and phong.frag computes the very same.
    vec3 at(const vec3& p) const {
        const auto parity = [&](float x) {
            const float f = std::floor(x / scale);
            return f - 2.0f * std::floor(0.5f * f);
        };
        const float sum = parity(p.x) + parity(p.y) + parity(p.z);
        return sum == 0.0f || sum == 2.0f ? colour_a : colour_b;
    }
    // A shift of the pattern's point by `offset` (exact, in double), folded into one
    // period (2 scale) per axis so that float can add it to a small point without loss:
    // at(p + shift(o)) is at(p + o) computed exactly.
    vec3 shift(const glm::dvec3& offset) const {
        const double period = 2.0 * static_cast<double>(scale);
        return vec3(std::fmod(offset.x, period), std::fmod(offset.y, period),
                    std::fmod(offset.z, period));
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
    float ior = 1.5f;     // index of refraction (outside is air, 1.0)
    vec3 emission{0.0f};  // added as it is, lit or not (glTF's emissive)
    // The scene's texture (Scene::textures) that multiplies ka and kd, as a checker does.
    std::optional<std::uint32_t> texture;
    std::optional<Checker> checker;
};

}  // namespace rt
