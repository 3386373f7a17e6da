#include "core/light_buffer.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "core/simd.h"

namespace rt {

using FaceSpan = LightBuffer::FaceSpan;

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

// A box widened by kMargin of its reach from `reference` (the light, or the origin), or
// of its coordinates where they are larger: float's step there is what a test's
// rounding is measured in. Empty where the box is not finite.
std::optional<std::pair<dvec3, dvec3>> padded(const Aabb& box, const dvec3& reference) {
    dvec3 lo = dvec3(box.lo) - reference, hi = dvec3(box.hi) - reference;
    if (!std::isfinite(lo.x + lo.y + lo.z + hi.x + hi.y + hi.z)) return std::nullopt;
    const auto largest = [](const dvec3& a, const dvec3& b) {
        return std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(a.z), std::fabs(b.x),
                         std::fabs(b.y), std::fabs(b.z)});
    };
    const dvec3 pad(kMargin * std::max(largest(lo, hi), largest(dvec3(box.lo), dvec3(box.hi))));
    return std::pair{lo - pad, hi + pad};
}

// The cells a box covers, face by face (face f: axis f / 2, negative if f is odd).
std::array<FaceSpan, 6> spans_of(const vec3& light, const Aabb& box) {
    std::array<FaceSpan, 6> spans{};
    if (box.empty()) return spans;
    const auto p = padded(box, dvec3(light));
    if (!p) {
        spans.fill(FaceSpan{true, {0, LightBuffer::kCells - 1}, {0, LightBuffer::kCells - 1}});
        return spans;
    }
    for (int face = 0; face < 6; ++face)
        spans[face] = project(p->first, p->second, face / 2, face % 2 ? -1.0 : 1.0);
    return spans;
}

// A box's extent across a directional light: along e1 and e2, over its corners.
std::array<std::pair<double, double>, 2> across(const std::pair<dvec3, dvec3>& box, const dvec3& e1,
                                                const dvec3& e2) {
    std::array<std::pair<double, double>, 2> r{std::pair{HUGE_VAL, -HUGE_VAL},
                                               std::pair{HUGE_VAL, -HUGE_VAL}};
    for (int corner = 0; corner < 8; ++corner) {
        const dvec3 c{corner & 1 ? box.second.x : box.first.x,
                      corner & 2 ? box.second.y : box.first.y,
                      corner & 4 ? box.second.z : box.first.z};
        const double s = glm::dot(c, e1), t = glm::dot(c, e2);
        r[0] = {std::min(r[0].first, s), std::max(r[0].second, s)};
        r[1] = {std::min(r[1].first, t), std::max(r[1].second, t)};
    }
    return r;
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

std::optional<LightBuffer> LightBuffer::make(const Light& light, std::span<const Aabb> boxes) {
    std::size_t visits = 0;
    if (light.type == Light::Type::kPoint) {
        for (const Aabb& box : boxes) visits += cells_covered(spans_of(light.position, box));
        if (visits > kMaxVisits) return std::nullopt;
        return LightBuffer(light.position, boxes);
    }
    LightBuffer buffer;
    if (!buffer.set_up_grid(light.direction, boxes)) return std::nullopt;
    for (const Aabb& box : boxes) visits += cells_covered(buffer.grid_spans(box));
    if (visits > kMaxVisits) return std::nullopt;
    buffer.fill(boxes, [&](const Aabb& box) { return buffer.grid_spans(box); });
    return buffer;
}

LightBuffer::LightBuffer(const vec3& light, std::span<const Aabb> boxes) : light_(light) {
    fill(boxes, [&](const Aabb& box) { return spans_of(light, box); });
}

bool LightBuffer::set_up_grid(const vec3& direction, std::span<const Aabb> boxes) {
    directional_ = true;
    side_ = kGrid;
    faces_ = 1;
    const dvec3 d = glm::normalize(dvec3(direction));
    if (!std::isfinite(d.x + d.y + d.z)) return false;
    // Any two unit vectors across the light (core/shapes.h's frame, in double).
    const dvec3 helper = std::fabs(d.x) < 0.5 ? dvec3(1, 0, 0) : dvec3(0, 1, 0);
    const dvec3 across_1 = glm::normalize(glm::cross(d, helper));
    e1_ = vec3(across_1);
    e2_ = vec3(glm::cross(d, across_1));
    // The vectors as the lookup has them (float), for the grid's bounds and the boxes.
    const dvec3 e1(e1_), e2(e2_);
    std::pair<double, double> u{HUGE_VAL, -HUGE_VAL}, v{HUGE_VAL, -HUGE_VAL};
    for (const Aabb& box : boxes) {
        if (box.empty()) continue;
        const auto p = padded(box, dvec3(0.0));
        if (!p) return false;  // a box beyond float's reach: no grid holds it
        const auto r = across(*p, e1, e2);
        u = {std::min(u.first, r[0].first), std::max(u.second, r[0].second)};
        v = {std::min(v.first, r[1].first), std::max(v.second, r[1].second)};
    }
    if (!(u.first <= u.second)) u = v = {0.0, 1.0};  // no box: every cell empty
    grid_lo_ = {u.first, v.first};
    const auto step = [](std::pair<double, double> r) {
        const double s = (r.second - r.first) / kGrid;
        return s > 0.0 ? s : 1.0;
    };
    grid_step_ = {step(u), step(v)};
    grid_lo_f_ = glm::vec2(grid_lo_);
    grid_inv_f_ = glm::vec2(1.0 / grid_step_.x, 1.0 / grid_step_.y);
    return true;
}

std::array<FaceSpan, 6> LightBuffer::grid_spans(const Aabb& box) const {
    std::array<FaceSpan, 6> spans{};
    if (box.empty()) return spans;
    const auto p = padded(box, dvec3(0.0));
    const auto r = across(*p, dvec3(e1_), dvec3(e2_));
    const auto index = [&](double x, int axis) {
        const double i = std::floor((x - grid_lo_[axis]) / grid_step_[axis]);
        return static_cast<int>(std::clamp(i, 0.0, kGrid - 1.0));
    };
    spans[0] = {true,
                {index(r[0].first, 0), index(r[0].second, 0)},
                {index(r[1].first, 1), index(r[1].second, 1)}};
    return spans;
}

template <class Spans>
void LightBuffer::fill(std::span<const Aabb> boxes, Spans&& spans_of_box) {
    const int face_cells = side_ * side_, cells = faces_ * face_cells;
    // Each box's cells, visited twice: to count each cell's objects, then to list them.
    const auto for_each_cell = [&](const Aabb& box, auto&& visit) {
        const std::array<FaceSpan, 6> spans = spans_of_box(box);
        for (int face = 0; face < faces_; ++face) {
            const FaceSpan& span = spans[static_cast<std::size_t>(face)];
            if (!span.covered) continue;
            for (int v = span.v.first; v <= span.v.second; ++v)
                for (int u = span.u.first; u <= span.u.second; ++u)
                    visit(face * face_cells + v * side_ + u);
        }
    };
    std::vector<std::uint32_t> count(static_cast<std::size_t>(cells), 0);
    for (const Aabb& box : boxes)
        for_each_cell(box, [&](int c) { count[c] = std::min(count[c] + 1, kMaxList + 1); });
    cells_.resize(static_cast<std::size_t>(cells));
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

LightBuffer::Cell LightBuffer::grid_cell(const vec3& origin) const {
    const float u = (glm::dot(origin, e1_) - grid_lo_f_.x) * grid_inv_f_.x,
                v = (glm::dot(origin, e2_) - grid_lo_f_.y) * grid_inv_f_.y;
    if (!(u < kInfinity) || !(v < kInfinity)) return {};  // not finite
    // Beyond the grid no box casts a shadow: an empty cell, not a crowded one.
    if (u < 0.0f || v < 0.0f || u >= kGrid || v >= kGrid) return {nullptr, nullptr, false};
    const Range r =
        cells_[static_cast<std::size_t>(static_cast<int>(v) * kGrid + static_cast<int>(u))];
    if (r.begin == kCrowded) return {};
    return {slots_.data() + r.begin, slots_.data() + r.end, false};
}

void LightBuffer::cells(const RayLanes<kPacketWidth>& feelers, unsigned lanes, Cell* out) const {
    using Float = Lanes<kPacketWidth>::Float;
    if (directional_) {
        for (; lanes != 0; lanes &= lanes - 1)
            out[__builtin_ctz(lanes)] = grid_cell(feelers.lane(__builtin_ctz(lanes)).origin);
        return;
    }
    // cell's steps, lane by lane: the face of the largest component (ties to the lower
    // axis), its other two in the face's (u, v) order, and the same rounding.
    const Float x = feelers.origin[0] - splat<Float>(light_.x),
                y = feelers.origin[1] - splat<Float>(light_.y),
                z = feelers.origin[2] - splat<Float>(light_.z);
    const Float ax = vabs(x), ay = vabs(y), az = vabs(z);
    const auto on_x = (ax >= ay) & (ax >= az);
    const auto on_y = ~on_x & (ay >= az);
    const Float w = on_x ? ax : (on_y ? ay : az);
    const Float u = on_x ? y : (on_y ? z : x);
    const Float v = on_x ? z : (on_y ? x : y);
    const Float along = on_x ? x : (on_y ? y : z);
    const Float face =
        (on_x ? splat<Float>(0.0f) : (on_y ? splat<Float>(2.0f) : splat<Float>(4.0f))) +
        (along < splat<Float>(0.0f) ? splat<Float>(1.0f) : splat<Float>(0.0f));
    const auto valid = (w > splat<Float>(0.0f)) & (w < splat<Float>(kInfinity));
    const Float scale = splat<Float>(0.5f * kCells) / w;
    // clamp(int(t), 0, kCells - 1) as floats: floor and truncation agree once clamped
    // below at 0, and a NaN (max takes its second operand then) becomes 0, as in cell().
    const auto index = [&](Float t) {
        const Float i = vfloor(t * scale + splat<Float>(0.5f * kCells));
        return vmin(vmax(i, splat<Float>(0.0f)), splat<Float>(kCells - 1.0f));
    };
    const Float at = (face * splat<Float>(kCells) + index(v)) * splat<Float>(kCells) + index(u);
    for (; lanes != 0; lanes &= lanes - 1) {
        const unsigned lane = __builtin_ctz(lanes);
        if (!valid[lane]) {  // on the light, or not finite
            out[lane] = Cell{};
            continue;
        }
        const Range r = cells_[static_cast<std::size_t>(at[lane])];
        out[lane] = r.begin == kCrowded
                        ? Cell{}
                        : Cell{slots_.data() + r.begin, slots_.data() + r.end, false};
    }
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
