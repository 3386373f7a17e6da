#include "core/small_objects.h"

#include <algorithm>
#include <cmath>
#include <optional>

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
        const vec3 p{corner & 1 ? box.hi.x : box.lo.x, corner & 2 ? box.hi.y : box.lo.y,
                     corner & 4 ? box.hi.z : box.lo.z};
        const vec3 d = p - c.eye;
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

}  // namespace

SmallObjects::SmallObjects(const Scene& scene, const Camera& camera) {
    struct Found {
        std::uint32_t object;
        int x0, x1, y0, y1;
    };
    std::vector<Found> found;
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i) {
        const Aabb box = scene.object_bounds(scene.objects[i]);
        if (box.empty()) continue;  // a plane
        const std::optional<PixelBox> b = pixel_box(box, camera);
        if (!b || b->x_hi - b->x_lo >= kPixels || b->y_hi - b->y_lo >= kPixels) continue;
        // Pixel x's centre is at x + 1/2: the columns whose centres the box holds, and one
        // more each side.
        const int x0 = std::max(0, static_cast<int>(std::ceil(b->x_lo - 0.5f)) - 1);
        const int x1 = std::min(camera.cols - 1, static_cast<int>(std::floor(b->x_hi - 0.5f)) + 1);
        const int y0 = std::max(0, static_cast<int>(std::ceil(b->y_lo - 0.5f)) - 1);
        const int y1 = std::min(camera.rows - 1, static_cast<int>(std::floor(b->y_hi - 0.5f)) + 1);
        if (x0 > x1 || y0 > y1) continue;  // off the image
        found.push_back({i, x0, x1, y0, y1});
    }
    objects_ = found.size();
    if (found.empty()) return;
    row_start_.assign(static_cast<std::size_t>(camera.rows) + 1, 0);
    for (const Found& f : found)
        for (int y = f.y0; y <= f.y1; ++y) ++row_start_[static_cast<std::size_t>(y) + 1];
    for (std::size_t y = 1; y < row_start_.size(); ++y) row_start_[y] += row_start_[y - 1];
    spans_.resize(row_start_.back());
    std::vector<std::uint32_t> next(row_start_.begin(), row_start_.end() - 1);
    for (const Found& f : found)
        for (int y = f.y0; y <= f.y1; ++y)
            spans_[next[static_cast<std::size_t>(y)]++] = {f.object, f.x0, f.x1};
}

}  // namespace rt
