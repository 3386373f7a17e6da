#pragma once
// A uniform grid, from the tutorial's "subdivision" speed-ups, kept as a comparison point
// for the BVH. Cells hold the primitives whose boxes overlap them; rays walk the cells
// in order with a 3D DDA (Amanatides & Woo, "A Fast Voxel Traversal Algorithm", 1987).

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "core/aabb.h"

namespace rt {

class UniformGrid {
  public:
    static constexpr float kCellsPerPrimitive = 2.0f;

    void build(std::span<const Aabb> boxes);
    std::size_t memory_bytes() const {
        return (cell_start_.size() + cell_prims_.size()) * sizeof(std::uint32_t);
    }
    glm::ivec3 resolution() const { return res_; }

    // As Bvh::traverse; slots are primitive indices.
    template <bool kAnyHit, class HitPrim>
    bool traverse(const Ray& ray, float& t_max, HitPrim&& hit) const;

  private:
    std::size_t cell_index(const glm::ivec3& c) const {
        return (static_cast<std::size_t>(c.z) * res_.y + c.y) * res_.x + c.x;
    }
    // The cell along axis a of a point `offset` past the bounds' low corner, clamped to
    // the grid as a float: a cell size of 0 (primitives at one point, far out) makes NaN,
    // and a cast of NaN or of a float past an int's range is undefined. NaN: cell 0.
    int cell_along(int a, float offset) const {
        const float at = offset / cell_size_[a];
        const int last = res_[a] - 1;
        return at >= static_cast<float>(last) ? last : at > 0.0f ? static_cast<int>(at) : 0;
    }

    Aabb bounds_;
    glm::ivec3 res_{0};
    vec3 cell_size_{1.0f};
    std::vector<std::uint32_t> cell_start_;  // res.x * res.y * res.z + 1 offsets into cell_prims_
    std::vector<std::uint32_t> cell_prims_;
};

template <bool kAnyHit, class HitPrim>
bool UniformGrid::traverse(const Ray& ray, float& t_max, HitPrim&& hit) const {
    if (cell_start_.empty()) return false;
    const vec3 inv_dir = 1.0f / ray.dir;
    const float t_enter = slab_entry(bounds_, ray.origin, inv_dir, t_max);
    if (t_enter == kInfinity) return false;

    const vec3 start = ray.at(t_enter);
    glm::ivec3 cell, step;
    vec3 t_next, t_delta;
    for (int a = 0; a < 3; ++a) {
        cell[a] = cell_along(a, start[a] - bounds_.lo[a]);
        if (ray.dir[a] > 0.0f) {
            step[a] = 1;
            t_next[a] =
                (bounds_.lo[a] + static_cast<float>(cell[a] + 1) * cell_size_[a] - ray.origin[a]) *
                inv_dir[a];
            t_delta[a] = cell_size_[a] * inv_dir[a];
        } else if (ray.dir[a] < 0.0f) {
            step[a] = -1;
            t_next[a] =
                (bounds_.lo[a] + static_cast<float>(cell[a]) * cell_size_[a] - ray.origin[a]) *
                inv_dir[a];
            t_delta[a] = -cell_size_[a] * inv_dir[a];
        } else {
            step[a] = 0;
            t_next[a] = kInfinity;
            t_delta[a] = kInfinity;
        }
    }
    bool found = false;
    for (;;) {
        const std::size_t c = cell_index(cell);
        for (std::uint32_t i = cell_start_[c]; i < cell_start_[c + 1]; ++i) {
            if (hit(cell_prims_[i], t_max)) {
                found = true;
                if constexpr (kAnyHit) return true;
            }
        }
        // The next cell is the one whose boundary the ray crosses first.
        const int axis =
            t_next.x < t_next.y ? (t_next.x < t_next.z ? 0 : 2) : (t_next.y < t_next.z ? 1 : 2);
        // A hit at or before this cell's exit cannot be beaten by a later cell.
        if (t_max <= t_next[axis]) break;
        cell[axis] += step[axis];
        if (cell[axis] < 0 || cell[axis] >= res_[axis]) break;
        t_next[axis] += t_delta[axis];
    }
    return found;
}

}  // namespace rt
