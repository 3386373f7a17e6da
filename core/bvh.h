#pragma once
// A bounding volume hierarchy over anything with a bounding box: mesh triangles, or the
// objects of a scene. Built top-down with binned SAH, stored flat in depth-first order
// (a node's left child follows it), traversed near child first with a fixed stack.

#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "core/aabb.h"
#include "core/large_array.h"

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

    // Subtrees of at most max_leaf primitives become leaves (see Accel::build); of more
    // than split_above (if not 0) only where splitting them would not cut what a ray
    // enters: where the two halves' boxes have at least kKeepLeaf of the subtree's area
    // between them. On `threads` threads (0: all the hardware's); the tree is the same on
    // any number.
    // 0.4 since the thirty-sixth session (was 0.8, for the Cornell box's walls): leaves of
    // overlapping small triangles, a tree's or a soup's, took 3-7 % less time per shadow and
    // secondary ray; the shipped scenes' frames the same (docs/BENCHMARKS.md).
    static constexpr float kKeepLeaf = 0.4f;
    void build(std::span<const Aabb> prim_boxes, std::uint32_t max_leaf = 2, int threads = 0,
               std::uint32_t split_above = 0);

    bool empty() const { return nodes_.empty(); }
    Aabb bounds() const { return empty() ? Aabb{} : Aabb{nodes_[0].lo, nodes_[0].hi}; }
    std::size_t memory_bytes() const {
        return nodes_.size() * sizeof(BvhNode) + prims_.size() * sizeof(std::uint32_t);
    }
    std::size_t node_count() const { return nodes_.size(); }
    std::span<const BvhNode> nodes() const { return nodes_; }  // root first, depth-first
    // The primitives in leaf order: slot s of the traversal is primitive order()[s].
    std::span<const std::uint32_t> order() const { return prims_; }
    // The same, moved out (the tree is left without its slots: for a wide BVH's build).
    std::vector<std::uint32_t> take_order() { return std::move(prims_); }

    // Visits the primitives whose boxes the ray enters within (0, t_max), nearest box
    // first. `hit(slot, t_max)` tests the primitive in that slot of order() and returns
    // true on a hit, having shortened t_max. With kAnyHit the walk stops at the first
    // hit (shadow feelers). Slots let a caller keep its primitives' data in leaf order.
    template <bool kAnyHit, class HitPrim>
    bool traverse(const Ray& ray, float& t_max, HitPrim&& hit) const;
    // The same a leaf at a time: `hit_leaf(first_slot, count, t_max)`.
    template <bool kAnyHit, class HitLeaf>
    bool traverse_leaves(const Ray& ray, float& t_max, HitLeaf&& hit_leaf) const;
    // The leaves' slot ranges, for callers that lay their data out per leaf.
    template <class F>
    void for_each_leaf(F&& f) const {
        for (const BvhNode& n : nodes_)
            if (n.is_leaf()) f(n.first, n.count);
    }

  private:
    LargeArray<BvhNode> nodes_;
    std::vector<std::uint32_t> prims_;
};

template <bool kAnyHit, class HitLeaf>
bool Bvh::traverse_leaves(const Ray& ray, float& t_max, HitLeaf&& hit_leaf) const {
    if (nodes_.empty() || !finite_ray(ray)) return false;
    const vec3 inv_dir = 1.0f / ray.dir;
    const auto entry = [&](std::uint32_t n) {
        return slab_entry({nodes_[n].lo, nodes_[n].hi}, ray.origin, inv_dir, t_max);
    };
    if (entry(0) == kInfinity) return false;

    struct Pending {
        std::uint32_t node;
        float t_entry;  // a node that starts beyond a hit found since is skipped unvisited
    };
    std::array<Pending, kMaxDepth + 2> stack;
    int top = 0;
    std::uint32_t index = 0;
    bool found = false;
    for (;;) {
        const BvhNode& node = nodes_[index];
        if (node.is_leaf()) {
            if (hit_leaf(node.first, node.count, t_max)) {
                found = true;
                if constexpr (kAnyHit) return true;
            }
        } else {
            const std::uint32_t left = index + 1, right = node.first;
            const float t_left = entry(left), t_right = entry(right);
            if (t_left != kInfinity && t_right != kInfinity) {  // both: the nearer first
                const bool left_first = t_left <= t_right;
                stack[top++] = left_first ? Pending{right, t_right} : Pending{left, t_left};
                index = left_first ? left : right;
                continue;
            }
            if (t_left != kInfinity || t_right != kInfinity) {
                index = t_left != kInfinity ? left : right;
                continue;
            }
        }
        while (top > 0 && stack[top - 1].t_entry >= t_max) --top;
        if (top == 0) break;
        index = stack[--top].node;
    }
    return found;
}

// A primitive at a time: `hit(slot, t_max)` for each slot of a leaf, in order; with
// kAnyHit the leaf stops at its first hit. Both BVHs' traverse() use it.
template <bool kAnyHit, class HitPrim>
auto each_primitive(HitPrim& hit) {
    return [&hit](std::uint32_t first, std::uint32_t count, float& t_max) {
        bool found = false;
        for (std::uint32_t slot = first; slot < first + count; ++slot) {
            if (hit(slot, t_max)) {
                found = true;
                if constexpr (kAnyHit) return true;
            }
        }
        return found;
    };
}

template <bool kAnyHit, class HitPrim>
bool Bvh::traverse(const Ray& ray, float& t_max, HitPrim&& hit) const {
    return traverse_leaves<kAnyHit>(ray, t_max, each_primitive<kAnyHit>(hit));
}

}  // namespace rt
