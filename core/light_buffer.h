#pragma once
// The light buffer of Haines and Greenberg ("The Light Buffer: A Shadow-Testing
// Accelerator", IEEE CG&A, 1986), the item buffer's companion from the same group: a
// cube of directions around a point light, each face a grid of cells, each cell listing
// the objects that lie, at least in part, in its directions as seen from the light. A
// shadow feeler runs along one direction from the light, so only the objects of that
// direction's cell can block it: in an open scene most feelers find a cell with no
// object at all and are answered without a traversal.
//
// The lists are conservative: an object's box is projected onto each face in double
// precision and widened by a margin far above float's rounding, so every object a
// feeler's own test could hit is in its cell, and a feeler tested against its cell's
// objects gets the answer the traversal gives it.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "core/aabb.h"
#include "core/ray.h"

namespace rt {

class LightBuffer {
  public:
    static constexpr int kCells = 64;             // per side of a face
    static constexpr std::uint32_t kMaxList = 8;  // a cell with more: traverse the tree

    // Building visits each cell of each box: more visits than this (many large objects
    // near the light) and the light has no buffer (a build should not cost a frame).
    static constexpr std::size_t kMaxVisits = std::size_t{1} << 22;

    // The objects' boxes (index: the caller's slot) as seen from a point light at `light`.
    LightBuffer(const vec3& light, std::span<const Aabb> boxes);
    // The same, or none where building it would take more than kMaxVisits visits.
    static std::optional<LightBuffer> make(const vec3& light, std::span<const Aabb> boxes);

    // The slots a feeler from `origin` to the light may be blocked by, in ascending order.
    struct Cell {
        const std::uint32_t* begin = nullptr;
        const std::uint32_t* end = nullptr;
        bool crowded = true;  // or no direction (origin on the light): traverse instead
    };
    Cell cell(const vec3& origin) const;

    // For the docs and tests: how many cells hold no object, and how many are crowded.
    std::size_t empty_cells() const;
    std::size_t crowded_cells() const;

  private:
    static constexpr int kFaceCells = kCells * kCells;
    static constexpr std::uint32_t kCrowded = ~0u;
    struct Range {
        std::uint32_t begin = 0, end = 0;  // into slots_; begin kCrowded: crowded
    };

    vec3 light_;
    // Per cell (face f = 2 axis + (negative ? 1 : 0), row v, column u at
    // f * kFaceCells + v * kCells + u; u along axis + 1, v along axis + 2), its list.
    std::vector<Range> cells_;
    std::vector<std::uint32_t> slots_;
};

// Inline: a feeler asks once, and a call returns the cell through memory.
inline LightBuffer::Cell LightBuffer::cell(const vec3& origin) const {
    const float x = origin.x - light_.x, y = origin.y - light_.y, z = origin.z - light_.z;
    const float ax = std::fabs(x), ay = std::fabs(y), az = std::fabs(z);
    // The face of the largest component (a tie to the lower axis: a box that reaches the
    // direction is listed on both faces), and the other two, in the face's (u, v) order.
    float w, u, v;
    int face;
    if (ax >= ay && ax >= az) {
        w = ax, u = y, v = z, face = x < 0.0f ? 1 : 0;
    } else if (ay >= az) {
        w = ay, u = z, v = x, face = y < 0.0f ? 3 : 2;
    } else {
        w = az, u = x, v = y, face = z < 0.0f ? 5 : 4;
    }
    if (!(w > 0.0f) || !(w < kInfinity)) return {};  // on the light, or not finite
    const float scale = 0.5f * kCells / w;
    const auto index = [&](float t) {
        return std::clamp(static_cast<int>(t * scale + 0.5f * kCells), 0, kCells - 1);
    };
    const Range r =
        cells_[static_cast<std::size_t>(face * kFaceCells + index(v) * kCells + index(u))];
    if (r.begin == kCrowded) return {};
    return {slots_.data() + r.begin, slots_.data() + r.end, false};
}

}  // namespace rt
