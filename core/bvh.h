#pragma once
// A bounding volume hierarchy over anything with a bounding box: mesh triangles, or the
// objects of a scene. Built top-down with binned SAH, stored flat in depth-first order
// (a node's left child follows it), traversed near child first with a fixed stack.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/aabb.h"

namespace rt {

struct BvhNode {
    vec3 lo;
    std::uint32_t first;  // leaf: first index into prims; interior: right child
    vec3 hi;
    std::uint32_t count;  // leaf: number of prims; interior: 0

    bool is_leaf() const { return count != 0; }
};
static_assert(sizeof(BvhNode) == 32, "BVH nodes are meant to be 32 bytes");

class Bvh {
  public:
    static constexpr int kMaxDepth = 60;  // the traversal stack is sized from this

    void build(std::span<const Aabb> prim_boxes);

    bool empty() const { return nodes_.empty(); }
    Aabb bounds() const { return empty() ? Aabb{} : Aabb{nodes_[0].lo, nodes_[0].hi}; }
    std::size_t memory_bytes() const {
        return nodes_.size() * sizeof(BvhNode) + prims_.size() * sizeof(std::uint32_t);
    }
    std::size_t node_count() const { return nodes_.size(); }
    // The primitives in leaf order: slot s of the traversal is primitive order()[s].
    std::span<const std::uint32_t> order() const { return prims_; }

    // Visits the primitives whose boxes the ray enters within (0, t_max), nearest box
    // first. `hit(slot, t_max)` tests the primitive in that slot of order() and returns
    // true on a hit, having shortened t_max. With kAnyHit the walk stops at the first
    // hit (shadow feelers). Slots let a caller keep its primitives' data in leaf order.
    template <bool kAnyHit, class HitPrim>
    bool traverse(const Ray& ray, float& t_max, HitPrim&& hit) const;

  private:
    std::vector<BvhNode> nodes_;
    std::vector<std::uint32_t> prims_;
};

template <bool kAnyHit, class HitPrim>
bool Bvh::traverse(const Ray& ray, float& t_max, HitPrim&& hit) const {
    if (nodes_.empty()) return false;
    const vec3 inv_dir = 1.0f / ray.dir;
    if (slab_entry({nodes_[0].lo, nodes_[0].hi}, ray.origin, inv_dir, t_max) == kInfinity)
        return false;

    std::array<std::uint32_t, kMaxDepth + 2> stack;
    int top = 0;
    std::uint32_t index = 0;
    bool found = false;
    for (;;) {
        const BvhNode& node = nodes_[index];
        if (node.is_leaf()) {
            for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
                if (hit(i, t_max)) {
                    found = true;
                    if constexpr (kAnyHit) return true;
                }
            }
        } else {
            const std::uint32_t left = index + 1;
            const std::uint32_t right = node.first;
            const float t_left =
                slab_entry({nodes_[left].lo, nodes_[left].hi}, ray.origin, inv_dir, t_max);
            const float t_right =
                slab_entry({nodes_[right].lo, nodes_[right].hi}, ray.origin, inv_dir, t_max);
            const bool go_left = t_left != kInfinity;
            const bool go_right = t_right != kInfinity;
            if (go_left && go_right) {
                const bool left_first = t_left <= t_right;
                stack[top++] = left_first ? right : left;
                index = left_first ? left : right;
                continue;
            }
            if (go_left || go_right) {
                index = go_left ? left : right;
                continue;
            }
        }
        // A popped node may lie beyond a hit found since it was pushed; its children's
        // slab tests, made against the shortened t_max, reject it then.
        if (top == 0) break;
        index = stack[--top];
    }
    return found;
}

}  // namespace rt
