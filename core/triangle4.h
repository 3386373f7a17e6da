#pragma once
// Four triangles tested against one ray at once: Moeller & Trumbore's test (as in
// shapes.h, the same operations in the same order, so the same answers) on lanes of
// four floats, with GCC/Clang vector extensions (SSE on x86-64, NEON on ARM).

#include <cstdint>

#include "core/shapes.h"

namespace rt {

using Float4 = float __attribute__((vector_size(16)));

struct Triangle4 {
    Float4 v0[3], e1[3], e2[3];  // x, y, z lanes; unused lanes are degenerate (never hit)

    void set(int lane, const PackedTriangle& t) {
        for (int a = 0; a < 3; ++a) {
            v0[a][lane] = t.v0[a];
            e1[a][lane] = t.e1[a];
            e2[a][lane] = t.e2[a];
        }
    }
};

struct Triangle4Hit {
    int lane = -1;  // -1: no hit
    float t = kInfinity, b1 = 0.0f, b2 = 0.0f;
};

// The nearest hit among the four in (0, t_max).
inline Triangle4Hit intersect(const Triangle4& tri, const Ray& r, float t_max) {
    const Float4 dx = Float4{} + r.dir.x, dy = Float4{} + r.dir.y, dz = Float4{} + r.dir.z;
    const Float4 px = dy * tri.e2[2] - dz * tri.e2[1];
    const Float4 py = dz * tri.e2[0] - dx * tri.e2[2];
    const Float4 pz = dx * tri.e2[1] - dy * tri.e2[0];
    const Float4 det = tri.e1[0] * px + tri.e1[1] * py + tri.e1[2] * pz;
    const Float4 inv_det = 1.0f / det;
    const Float4 sx = r.origin.x - tri.v0[0], sy = r.origin.y - tri.v0[1], sz = r.origin.z - tri.v0[2];
    const Float4 b1 = (sx * px + sy * py + sz * pz) * inv_det;
    const Float4 qx = sy * tri.e1[2] - sz * tri.e1[1];
    const Float4 qy = sz * tri.e1[0] - sx * tri.e1[2];
    const Float4 qz = sx * tri.e1[1] - sy * tri.e1[0];
    const Float4 b2 = (dx * qx + dy * qy + dz * qz) * inv_det;
    const Float4 t = (tri.e2[0] * qx + tri.e2[1] * qy + tri.e2[2] * qz) * inv_det;
    const auto ok = (det != 0.0f) & (b1 >= 0.0f) & (b1 <= 1.0f) & (b2 >= 0.0f) & (b1 + b2 <= 1.0f) & (t > 0.0f) &
                    (t < t_max);
    Triangle4Hit best;
    for (int lane = 0; lane < 4; ++lane) {
        if (ok[lane] && t[lane] < best.t) best = {lane, t[lane], b1[lane], b2[lane]};
    }
    return best;
}

}  // namespace rt
