#include "core/transform.h"

#include <cmath>

#include <glm/matrix.hpp>

namespace rt {

std::optional<Transform> Transform::from_matrix(const glm::mat4& m) {
    const glm::mat3 linear(m);
    const float det = glm::determinant(linear);
    // Relative test: scale-invariant, so a tiny but valid scale is not called singular.
    float norm = 0.0f;
    for (int c = 0; c < 3; ++c) norm = std::max(norm, glm::length(linear[c]));
    if (!std::isfinite(det) || !(std::fabs(det) > 1e-7f * norm * norm * norm)) return std::nullopt;
    if (m[0][3] != 0.0f || m[1][3] != 0.0f || m[2][3] != 0.0f || m[3][3] != 1.0f)
        return std::nullopt;  // projective matrices do not keep t

    Transform t;
    t.m = m;
    t.inv = glm::inverse(m);
    t.normal = glm::transpose(glm::inverse(linear));
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(t.inv[c][r])) return std::nullopt;
    return t;
}

}  // namespace rt
