#include "core/light_buffer.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/vec3.hpp>

namespace rt {
namespace {

using dvec3 = glm::dvec3;

// A box is widened by this much of its farthest reach from the light before it is
// projected: its directions then include, with room to spare, those of every feeler
// that meets it or that a box test in float could let through (a few float ulps, about
// 1e-7 of a face's width or of the coordinates).
constexpr double kMargin = 1e-5;

// The cells' columns (or rows) a face range [lo, hi] covers.
std::pair<int, int> cell_span(double lo, double hi) {
    const auto index = [](double u) {
        const double i = std::floor((u + 1.0) * 0.5 * LightBuffer::kCells);
        return static_cast<int>(std::clamp(i, 0.0, LightBuffer::kCells - 1.0));
    };
    return {index(lo), index(hi)};
}

// The cells of face (axis m, sign s) that a box (relative to the light) covers, as
// column and row spans, or none. A direction q lies on the face at
// (q[m + 1] / |q[m]|, q[m + 2] / |q[m]|); over a box's points in front of the face
// (s q[m] > 0) each ratio is extreme at a corner, the nearest distance along m clipped
// to just above zero: a box that reaches the light's plane covers the face to its edge.
struct FaceSpan {
    bool covered = false;
    std::pair<int, int> u, v;
};
FaceSpan project(const dvec3& lo, const dvec3& hi, int m, double s) {
    const double w_far = s > 0.0 ? hi[m] : -lo[m];
    if (w_far <= 0.0) return {};
    const double w_near = std::max(s > 0.0 ? lo[m] : -hi[m], 1e-300);
    const auto range = [&](int a) {
        double r_lo = HUGE_VAL, r_hi = -HUGE_VAL;
        for (const double x : {lo[a], hi[a]}) {
            for (const double w : {w_near, w_far}) {
                r_lo = std::min(r_lo, x / w);
                r_hi = std::max(r_hi, x / w);
            }
        }
        return cell_span(r_lo, r_hi);
    };
    return {true, range((m + 1) % 3), range((m + 2) % 3)};
}

// The cells a box covers, face by face (face f: axis f / 2, negative if f is odd).
std::array<FaceSpan, 6> spans_of(const vec3& light, const Aabb& box) {
    std::array<FaceSpan, 6> spans{};
    if (box.empty()) return spans;
    const dvec3 l(light);
    dvec3 lo = dvec3(box.lo) - l, hi = dvec3(box.hi) - l;
    if (!std::isfinite(lo.x + lo.y + lo.z + hi.x + hi.y + hi.z)) {
        spans.fill(FaceSpan{true, {0, LightBuffer::kCells - 1}, {0, LightBuffer::kCells - 1}});
        return spans;
    }
    // Of the box's reach from the light, or of the coordinates themselves where they are
    // larger: float's step there is what a test's rounding is measured in.
    const auto largest = [](const dvec3& a, const dvec3& b) {
        return std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(a.z), std::fabs(b.x),
                         std::fabs(b.y), std::fabs(b.z)});
    };
    const dvec3 pad(kMargin * std::max(largest(lo, hi), largest(dvec3(box.lo), dvec3(box.hi))));
    lo -= pad;
    hi += pad;
    for (int face = 0; face < 6; ++face)
        spans[face] = project(lo, hi, face / 2, face % 2 ? -1.0 : 1.0);
    return spans;
}

std::size_t cells_covered(const std::array<FaceSpan, 6>& spans) {
    std::size_t n = 0;
    for (const FaceSpan& f : spans)
        if (f.covered)
            n += static_cast<std::size_t>(f.u.second - f.u.first + 1) *
                 static_cast<std::size_t>(f.v.second - f.v.first + 1);
    return n;
}

}  // namespace

std::optional<LightBuffer> LightBuffer::make(const vec3& light, std::span<const Aabb> boxes) {
    std::size_t visits = 0;
    for (const Aabb& box : boxes) visits += cells_covered(spans_of(light, box));
    if (visits > kMaxVisits) return std::nullopt;
    return LightBuffer(light, boxes);
}

LightBuffer::LightBuffer(const vec3& light, std::span<const Aabb> boxes) : light_(light) {
    const int cells = 6 * kFaceCells;
    // Each box's cells, visited twice: to count each cell's objects, then to list them.
    const auto for_each_cell = [&](const Aabb& box, auto&& visit) {
        const std::array<FaceSpan, 6> spans = spans_of(light, box);
        for (int face = 0; face < 6; ++face) {
            const FaceSpan& span = spans[face];
            if (!span.covered) continue;
            for (int v = span.v.first; v <= span.v.second; ++v)
                for (int u = span.u.first; u <= span.u.second; ++u)
                    visit(face * kFaceCells + v * kCells + u);
        }
    };
    std::vector<std::uint32_t> count(cells, 0);
    for (const Aabb& box : boxes)
        for_each_cell(box, [&](int c) { count[c] = std::min(count[c] + 1, kMaxList + 1); });
    cells_.resize(cells);
    std::uint32_t listed = 0;
    for (int c = 0; c < cells; ++c) {
        if (count[c] > kMaxList) {
            cells_[c] = {kCrowded, kCrowded};
            continue;
        }
        cells_[c] = {listed, listed};
        listed += count[c];
    }
    slots_.resize(listed);
    for (std::uint32_t slot = 0; slot < boxes.size(); ++slot)
        for_each_cell(boxes[slot], [&](int c) {
            if (cells_[c].begin != kCrowded) slots_[cells_[c].end++] = slot;
        });
}

std::size_t LightBuffer::empty_cells() const {
    return static_cast<std::size_t>(std::count_if(cells_.begin(), cells_.end(), [](Range r) {
        return r.begin == r.end && r.begin != kCrowded;
    }));
}

std::size_t LightBuffer::crowded_cells() const {
    return static_cast<std::size_t>(
        std::count_if(cells_.begin(), cells_.end(), [](Range r) { return r.begin == kCrowded; }));
}

}  // namespace rt
