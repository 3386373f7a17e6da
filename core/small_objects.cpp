#include "core/small_objects.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include <glm/geometric.hpp>

namespace rt {

namespace {

struct PixelBox {
    float x_lo, x_hi, y_lo, y_hi;  // in pixel units, (0, 0) the bottom-left image corner
};

// Where the box's corners fall on the image (Camera::ray_at inverted), or nothing if a
// corner is not in front of the eye.
std::optional<PixelBox> pixel_box(const Aabb& box, const Camera& c) {
    PixelBox b{INFINITY, -INFINITY, INFINITY, -INFINITY};
    for (int corner = 0; corner < 8; ++corner) {
        const vec3 d = box.corner(corner) - c.eye;
        const float depth = -glm::dot(d, c.n);
        if (!(depth > 0.0f)) return std::nullopt;
        const float a = glm::dot(d, c.u) * c.N / (depth * c.W);  // 2 px / cols - 1
        const float e = glm::dot(d, c.v) * c.N / (depth * c.H);
        const float px = (a + 1.0f) * 0.5f * static_cast<float>(c.cols);
        const float py = (e + 1.0f) * 0.5f * static_cast<float>(c.rows);
        b = {std::min(b.x_lo, px), std::max(b.x_hi, px), std::min(b.y_lo, py),
             std::max(b.y_hi, py)};
    }
    if (!std::isfinite(b.x_lo + b.x_hi + b.y_lo + b.y_hi)) return std::nullopt;
    return b;
}

// The pixels whose centres (pixel x's at x + 1/2) lie in [lo, hi], and one more each side,
// within 0 .. last: {first, last}, first > last where none. The bounds are clamped as
// floats first: a box seen from just in front of it projects past what an int holds.
std::pair<int, int> pixel_span(float lo, float hi, int last) {
    const float below = -2.0f, above = static_cast<float>(last) + 2.0f;
    const int first = static_cast<int>(std::ceil(std::clamp(lo - 0.5f, below, above))) - 1;
    const int end = static_cast<int>(std::floor(std::clamp(hi - 0.5f, below, above))) + 1;
    return {std::max(0, first), std::min(last, end)};
}

}  // namespace

namespace {

// Pixels x0 .. x1 of rows y0 .. y1 where the renderer tests `object` itself.
struct Patch {
    std::uint32_t object;
    int x0, x1, y0, y1;
};

// The pixels of the image's outermost rows (into `rows`) and columns (into `sides`)
// where a sphere cut by the image's edge may show, with a pixel more each way. `b` is its
// box on the image (none: it reaches across the eye's plane, and may show anywhere along
// the edge); where `exact` (its outline's own extents), only a side that the sphere
// reaches past by under two pixels needs it: where it reaches further, its outline is
// vertical (or level) only beyond the outermost pixels, so that a pixel there a quarter
// pixel inside the outline has a neighbour within the image at least 0.7 pixels further
// in, which the raster covers (ItemBuffer::interior's argument).
void edge_patches(std::uint32_t object, const std::optional<PixelBox>& b, bool exact,
                  const Camera& camera, std::vector<Patch>& rows, std::vector<Patch>& sides) {
    const int last_x = camera.cols - 1, last_y = camera.rows - 1;
    if (!b) {
        sides.push_back({object, 0, 0, 0, last_y});
        sides.push_back({object, last_x, last_x, 0, last_y});
        rows.push_back({object, 0, last_x, 0, 0});
        rows.push_back({object, 0, last_x, last_y, last_y});
        return;
    }
    const auto [x0, x1] = pixel_span(b->x_lo, b->x_hi, last_x);
    const auto [y0, y1] = pixel_span(b->y_lo, b->y_hi, last_y);
    if (x0 > x1 || y0 > y1) return;  // off the image
    const float cols = static_cast<float>(camera.cols), height = static_cast<float>(camera.rows);
    const float reach = exact ? 2.0f : INFINITY;  // how far in a sphere may reach
    if (b->x_lo < 0.0f && b->x_hi < reach) sides.push_back({object, 0, 0, y0, y1});
    if (b->x_hi > cols && b->x_lo > cols - reach) sides.push_back({object, last_x, last_x, y0, y1});
    if (b->y_lo < 0.0f && b->y_hi < reach) rows.push_back({object, x0, x1, 0, 0});
    if (b->y_hi > height && b->y_lo > height - reach)
        rows.push_back({object, x0, x1, last_y, last_y});
}

// Where a sphere without a transform falls on the image, exactly: its outline's extents,
// between the planes through the eye that touch it and hold the camera's v axis (for x;
// u for y), a little more each way against rounding; nothing where it reaches across the
// eye's plane. In the plane of u and the view axis, the sphere is a disc of radius r about
// (a, z), and the line x = t z through the eye touches it where (a - t z)^2 = r^2 (1 + t^2).
std::optional<PixelBox> sphere_box(const Sphere& s, const Camera& c) {
    const glm::dvec3 w = glm::dvec3(s.centre) - glm::dvec3(c.eye);
    const double a = glm::dot(w, glm::dvec3(c.u)), b = glm::dot(w, glm::dvec3(c.v));
    const double z = -glm::dot(w, glm::dvec3(c.n)), r = s.radius;
    const double k = z * z - r * r;
    if (!(z > r) || !(k > 0.0)) return std::nullopt;
    const auto extent = [&](double across, double half, double scale, float& lo, float& hi) {
        const double root = r * std::sqrt(across * across + k);
        const double t_lo = (across * z - root) / k, t_hi = (across * z + root) / k;
        constexpr double kMargin = 0.01;  // pixels
        lo = static_cast<float>(half * (1.0 + scale * t_lo) - kMargin);
        hi = static_cast<float>(half * (1.0 + scale * t_hi) + kMargin);
    };
    PixelBox box{};
    extent(a, 0.5 * c.cols, double(c.N) / c.W, box.x_lo, box.x_hi);
    extent(b, 0.5 * c.rows, double(c.N) / c.H, box.y_lo, box.y_hi);
    if (!std::isfinite(box.x_lo + box.x_hi + box.y_lo + box.y_hi)) return std::nullopt;
    return box;
}

// True when every corner of the box is behind the eye (or on its plane).
bool behind(const Aabb& box, const Camera& camera) {
    for (int corner = 0; corner < 8; ++corner)
        if (glm::dot(camera.eye - box.corner(corner), camera.n) > 0.0f) return false;
    return true;
}

// Patches as spans by row: row y's are spans[start[y]] .. spans[start[y + 1] - 1].
void by_row(const std::vector<Patch>& patches, int rows, std::vector<std::uint32_t>& start,
            std::vector<SmallObjects::Span>& spans) {
    if (patches.empty()) return;
    start.assign(static_cast<std::size_t>(rows) + 1, 0);
    for (const Patch& f : patches)
        for (int y = f.y0; y <= f.y1; ++y) ++start[static_cast<std::size_t>(y) + 1];
    for (std::size_t y = 1; y < start.size(); ++y) start[y] += start[y - 1];
    spans.resize(start.back());
    std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
    for (const Patch& f : patches)
        for (int y = f.y0; y <= f.y1; ++y)
            spans[next[static_cast<std::size_t>(y)]++] = {f.object, f.x0, f.x1};
}

}  // namespace

SmallObjects::SmallObjects(const Scene& scene, const Camera& camera) {
    std::vector<Patch> patches, sides;
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        const Aabb box = scene.object_bounds(o);
        if (box.empty()) continue;  // a plane
        const std::optional<PixelBox> b = pixel_box(box, camera);
        if (!b || b->x_hi - b->x_lo >= kPixels || b->y_hi - b->y_lo >= kPixels) {
            if (const Sphere* sphere = std::get_if<Sphere>(&o.shape);
                sphere && !behind(box, camera)) {
                const std::optional<PixelBox> exact =
                    o.transform ? std::nullopt : sphere_box(*sphere, camera);
                edge_patches(i, exact ? exact : b, exact.has_value(), camera, patches, sides);
            }
            continue;
        }
        const auto [x0, x1] = pixel_span(b->x_lo, b->x_hi, camera.cols - 1);
        const auto [y0, y1] = pixel_span(b->y_lo, b->y_hi, camera.rows - 1);
        if (x0 > x1 || y0 > y1) continue;  // off the image
        patches.push_back({i, x0, x1, y0, y1});
        ++objects_;
    }
    by_row(patches, camera.rows, row_start_, spans_);
    by_row(sides, camera.rows, side_start_, side_spans_);
}

}  // namespace rt
