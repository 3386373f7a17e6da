#pragma once
// The light buffer of Haines and Greenberg ("The Light Buffer: A Shadow-Testing
// Accelerator", IEEE CG&A, 1986), the item buffer's companion from the same group: a
// cube of directions around a point light, each face a grid of cells, each cell listing
// the objects that lie, at least in part, in its directions as seen from the light. A
// shadow feeler runs along one direction from the light, so only the objects of that
// direction's cell can block it: in an open scene most feelers find a cell with no
// object at all and are answered without a traversal. A directional light's feelers are
// parallel, so its buffer is one grid across the light's direction instead.
//
// The lists are conservative: an object's box is projected onto each face in double
// precision and widened by a margin far above float's rounding, so every object a
// feeler's own test could hit is in its cell, and a feeler tested against its cell's
// objects gets the answer the traversal gives it.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "core/aabb.h"
#include "core/light.h"
#include "core/ray.h"
#include "core/ray_lanes.h"

namespace rt {

class LightBuffer {
  public:
    static constexpr int kCells = 64;             // per side of a cube face (point lights)
    static constexpr int kGrid = 128;             // per side of the grid (directional lights)
    static constexpr std::uint32_t kMaxList = 8;  // a cell with more: traverse the tree

    // Building visits each cell of each box: more visits than this (many large objects
    // near the light) and the light has no buffer (a build should not cost a frame).
    static constexpr std::size_t kMaxVisits = std::size_t{1} << 22;

    // The objects' boxes (index: the caller's slot) as seen from a point light at `light`.
    LightBuffer(const vec3& light, std::span<const Aabb> boxes);
    // A point light's buffer, or a directional light's: a grid across the light's
    // direction over the boxes' shadows (a feeler runs along the direction, so only the
    // objects over its origin's cell can block it). None where building it would take
    // more than kMaxVisits visits, or a box is beyond float's reach (directional).
    static std::optional<LightBuffer> make(const Light& light, std::span<const Aabb> boxes);

    // The slots a feeler from `origin` to the light may be blocked by, in ascending order.
    struct Cell {
        const std::uint32_t* begin = nullptr;
        const std::uint32_t* end = nullptr;
        bool crowded = true;  // or no direction (origin on the light): traverse instead
    };
    Cell cell(const vec3& origin) const;
    // cell for the origins of the feelers' lanes of `lanes`, across SIMD lanes
    // (out[lane]): the same cells, without a division and the face's branches each.
    void cells(const RayLanes<kPacketWidth>& feelers, unsigned lanes, Cell* out) const;

    // For the docs and tests: how many cells hold no object, and how many are crowded.
    std::size_t empty_cells() const;
    std::size_t crowded_cells() const;

    // The cells a box covers on one face (of the cube, or the one grid): the build's.
    struct FaceSpan {
        bool covered = false;
        std::pair<int, int> u, v;  // first and last column, first and last row
    };

  private:
    static constexpr std::uint32_t kCrowded = ~0u;
    struct Range {
        std::uint32_t begin = 0, end = 0;  // into slots_; begin kCrowded: crowded
    };

    LightBuffer() = default;
    Cell grid_cell(const vec3& origin) const;
    bool set_up_grid(const vec3& direction, std::span<const Aabb> boxes);
    std::array<FaceSpan, 6> grid_spans(const Aabb& box) const;
    template <class Spans>
    void fill(std::span<const Aabb> boxes, Spans&& spans_of_box);

    bool directional_ = false;
    int side_ = kCells, faces_ = 6;
    vec3 light_{0.0f};  // point lights
    // Directional lights: the grid's axes across the light, its corner and cell sizes.
    vec3 e1_{0.0f}, e2_{0.0f};
    glm::dvec2 grid_lo_{0.0}, grid_step_{1.0};
    glm::vec2 grid_lo_f_{0.0f}, grid_inv_f_{1.0f};
    // Per cell (face f = 2 axis + (negative ? 1 : 0), row v, column u at
    // f side^2 + v side + u; u along axis + 1, v along axis + 2; the grid: face 0, u
    // along e1, v along e2), its list.
    std::vector<Range> cells_;
    std::vector<std::uint32_t> slots_;
};

// Inline: a feeler asks once, and a call returns the cell through memory.
inline LightBuffer::Cell LightBuffer::cell(const vec3& origin) const {
    if (directional_) return grid_cell(origin);  // out of line: point lights are the many
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
    // As cells() does it: clamped as floats, a NaN (a component not finite, no comparison
    // holds for it) to 0, before the cast (a NaN or a float past an int's range cast to
    // int is undefined).
    const auto index = [&](float t) {
        const float i = std::floor(t * scale + 0.5f * kCells);
        const float low = i > 0.0f ? i : 0.0f;
        return static_cast<int>(low < kCells - 1.0f ? low : kCells - 1.0f);
    };
    const Range r =
        cells_[static_cast<std::size_t>(face * kCells * kCells + index(v) * kCells + index(u))];
    if (r.begin == kCrowded) return {};
    return {slots_.data() + r.begin, slots_.data() + r.end, false};
}

}  // namespace rt
