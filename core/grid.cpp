#include "core/grid.h"

#include <algorithm>
#include <cmath>

namespace rt {

void UniformGrid::build(std::span<const Aabb> boxes) {
    bounds_ = Aabb{};
    cell_start_.clear();
    cell_prims_.clear();
    for (const Aabb& b : boxes) bounds_.grow(b);
    if (boxes.empty() || bounds_.empty()) return;

    // About kCellsPerPrimitive cells per primitive, cubical where the bounds allow: a
    // flat axis gets one cell. Capped so that memory stays bounded.
    vec3 extent = bounds_.extent();
    const float largest = std::max({extent.x, extent.y, extent.z, 1e-30f});
    extent = glm::max(extent, vec3(largest * 1e-3f));
    bounds_.lo -= 1e-5f * extent;  // a little room: primitives on the far face fall inside
    bounds_.hi += 1e-5f * extent;
    extent = bounds_.extent();
    const float cells = kCellsPerPrimitive * static_cast<float>(boxes.size());
    const float per_unit = std::cbrt(cells / (extent.x * extent.y * extent.z));
    for (int a = 0; a < 3; ++a) {
        // Clamped as a float: primitives at one point make the volume underflow to 0 and
        // per_unit infinite (infinity or NaN cast to int is undefined).
        const float wanted = extent[a] * per_unit;
        res_[a] = wanted >= 512.0f ? 512 : wanted > 1.0f ? static_cast<int>(std::ceil(wanted)) : 1;
    }
    cell_size_ = extent / vec3(res_);

    const auto cell_range = [&](const Aabb& b, glm::ivec3& lo, glm::ivec3& hi) {
        for (int a = 0; a < 3; ++a) {
            lo[a] = cell_along(a, b.lo[a] - bounds_.lo[a]);
            hi[a] = cell_along(a, b.hi[a] - bounds_.lo[a]);
        }
    };
    // Two passes: count each cell's primitives, then place them (a compressed list).
    cell_start_.assign(static_cast<std::size_t>(res_.x) * res_.y * res_.z + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {
        std::vector<std::uint32_t> fill;
        if (pass == 1) {
            for (std::size_t c = 1; c < cell_start_.size(); ++c)
                cell_start_[c] += cell_start_[c - 1];
            cell_prims_.resize(cell_start_.back());
            fill.assign(cell_start_.begin(), cell_start_.end() - 1);
        }
        for (std::uint32_t p = 0; p < boxes.size(); ++p) {
            glm::ivec3 lo, hi;
            cell_range(boxes[p], lo, hi);
            for (int z = lo.z; z <= hi.z; ++z)
                for (int y = lo.y; y <= hi.y; ++y)
                    for (int x = lo.x; x <= hi.x; ++x) {
                        const std::size_t c = cell_index({x, y, z});
                        if (pass == 0)
                            ++cell_start_[c + 1];
                        else
                            cell_prims_[fill[c]++] = p;
                    }
        }
    }
}

}  // namespace rt
