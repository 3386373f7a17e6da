#pragma once
// A wide BVH, collapsed from the binary one (core/bvh.h) as in Dammertz et al.,
// "Shallow Bounding Volume Hierarchies for Fast SIMD Ray Tracing of Incoherent Rays"
// (2008): a node holds the boxes of up to N children as the lanes of six SIMD
// vectors, and one slab test checks them all. Subtrees of at most four primitives
// become one leaf, which a mesh tests with one Triangle4. N is 16 where the build
// targets AVX-512, 8 under AVX, else 4 (kBvhWidth, core/simd.h): a shallower tree,
// fewer dependent node loads per ray.

#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "core/aabb.h"
#include "core/bvh.h"
#include "core/large_array.h"
#include "core/simd.h"

namespace rt {

namespace detail {
template <int N>
struct BoxRay;
}  // namespace detail

template <int N>
struct alignas(64) WideBvhNode {
    using Float = typename Lanes<N>::Float;

    Float bounds[6];         // lo x, y, z, hi x, y, z; lane = child; unused: lo +inf, hi -inf
    std::uint32_t child[N];  // interior child: node index; leaf: its first slot
    std::uint32_t count[N];  // leaf: primitives (up to the leaf size, more where the build
                             // stopped: depth limit, coincident centres); interior or unused: 0
};
static_assert(sizeof(WideBvhNode<4>) == 128, "whole cache lines");

template <int N>
class WideBvh {
  public:
    using Node = WideBvhNode<N>;
    static constexpr int kWidth = N;
    // Subtrees of at most leaf_size primitives become leaves: 4 for a mesh (one
    // Triangle4), 1 for a scene's objects, which are tested one by one.
    // On `threads` threads (0: all the hardware's), the same tree on any number.
    // split_above: as Bvh::build's.
    void build(std::span<const Aabb> prim_boxes, std::uint32_t leaf_size, int threads = 0,
               std::uint32_t split_above = 0);

    bool empty() const { return nodes_.empty(); }
    Aabb bounds() const { return bounds_; }
    std::size_t memory_bytes() const {
        return nodes_.size() * sizeof(Node) + prims_.size() * sizeof(std::uint32_t);
    }
    std::size_t node_count() const { return nodes_.size(); }
    std::span<const Node> nodes() const { return nodes_; }  // the root first
    std::span<const std::uint32_t> order() const { return prims_; }

    // As Bvh::traverse_leaves: `hit_leaf(first_slot, count, t_max)` for the leaves the
    // ray enters within (0, t_max), nearest first unless kAnyHit.
    template <bool kAnyHit, class HitLeaf>
    bool traverse_leaves(const Ray& ray, float& t_max, HitLeaf&& hit_leaf) const;
    template <bool kAnyHit, class HitPrim>
    bool traverse(const Ray& ray, float& t_max, HitPrim&& hit) const;
    // Up to kPacketWidth rays together (core/wide_bvh_packet.h): rays[lane] for each bit
    // of `active`, each with its own t_max[lane]. `hit_leaf(first_slot, count, lanes)`
    // tests the leaf for the rays in `lanes` (a bit each) and returns the bits of those
    // that hit it, having shortened their t_max; a ray that hits is done if kAnyHit. Every
    // ray gets the answer traverse_leaves gives it alone (of two hits at the very same t,
    // either). Rays whose directions differ in sign on some axis share no useful bounds:
    // they go to `alone(lanes)`, the caller's own single-ray code, one at a time (without
    // it, through traverse_leaves with hit_leaf).
    template <bool kAnyHit, class HitLeaf, class Alone>
    void traverse_packet(const Ray* rays, float* t_max, unsigned active, HitLeaf&& hit_leaf,
                         Alone&& alone) const;
    template <bool kAnyHit, class HitLeaf>
    void traverse_packet(const Ray* rays, float* t_max, unsigned active, HitLeaf&& hit_leaf) const;
    template <class F>
    void for_each_leaf(F&& f) const {
        for (const Node& n : nodes_)
            for (int lane = 0; lane < N; ++lane)
                if (n.count[lane] != 0) f(n.child[lane], n.count[lane]);
    }
    // Replaces each leaf's first slot by f(first_slot, count), which traverse_leaves then
    // hands out instead: a mesh names its leaves' triangle packs so, one load less per leaf.
    template <class F>
    void relabel_leaves(F&& f) {
        for (Node& n : nodes_)
            for (int lane = 0; lane < N; ++lane)
                if (n.count[lane] != 0) n.child[lane] = f(n.child[lane], n.count[lane]);
    }

  private:
    // Always inlined: a function whose only effect is a prefetch is free of effects to the
    // compiler, which may drop its calls (GCC 12 did so with one, core/renderer.cpp).
    [[gnu::always_inline]] static void prefetch(const Node& node) {
        const char* at = reinterpret_cast<const char*>(&node);
        for (std::size_t line = 0; line < sizeof(Node); line += 64) __builtin_prefetch(at + line);
    }
    // A tree of one node (a scene of up to N objects): its leaves the ray enters, in lane
    // order, without the stack (any hit: the order does not change the answer).
    template <class HitLeaf>
    bool any_hit_in_root(const detail::BoxRay<N>& box_ray, float& t_max, HitLeaf& hit_leaf) const;

    LargeArray<Node> nodes_;  // written in full by build()
    std::vector<std::uint32_t> prims_;
    Aabb bounds_;
};

extern template class WideBvh<4>;
#if defined(__AVX__)
extern template class WideBvh<8>;
#endif
#if defined(__AVX512F__)
extern template class WideBvh<16>;
#endif

namespace detail {

// A ray set up for slab tests against N boxes: for each axis the near plane (lo if
// the direction is positive, hi if negative) and the far one, so no min/max per axis
// is needed and an unused lane (lo +inf, hi -inf) always misses. As in slab_entry
// (core/aabb.h), a plane the ray lies in gives NaN, which vmin/vmax drop: the order of
// their operands keeps the running bound, so the ray counts as inside that slab.
template <int N>
struct BoxRay {
    using Float = typename Lanes<N>::Float;
    Float inv[3], inv_far[3], origin[3];  // each splat over the lanes; inv_far: inv with
                                          // Ize's factor, so grazing rays are not lost
    int near[3], far[3];

    // Both always inlined, as ShearedRay's constructor (core/triangle4.h): GCC weighs an
    // inline function against its calling file's growth, and a call here would cost every
    // node (docs/BENCHMARKS.md, forty-first session).
    [[gnu::always_inline]] explicit BoxRay(const Ray& ray) {
        // Plain arrays: glm reads a component by a run-time index through a switch.
        const float dir[3] = {ray.dir.x, ray.dir.y, ray.dir.z};
        const float from[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
        for (int a = 0; a < 3; ++a) {
            const float inv_a = 1.0f / dir[a];
            inv[a] = splat<Float>(inv_a);
            inv_far[a] = splat<Float>(inv_a * kSlabExitFactor);
            origin[a] = splat<Float>(from[a]);
            near[a] = inv_a < 0.0f ? a + 3 : a;
            far[a] = inv_a < 0.0f ? a : a + 3;
        }
    }
    // Entry distances of the children, and a bit per child the ray enters in (0, t_max).
    [[gnu::always_inline]] unsigned test(const WideBvhNode<N>& n, float t_max,
                                         Float& t_enter) const {
        // (plane - origin) * inv, not plane * inv - origin * inv: one rounding, as Ize's
        // bound assumes; the second form loses rays at shared box faces.
        const auto plane = [&](int index, int a) { return (n.bounds[index] - origin[a]) * inv[a]; };
        const auto far_plane = [&](int index, int a) {
            return (n.bounds[index] - origin[a]) * inv_far[a];
        };
        t_enter = vmax(vmax(plane(near[0], 0), plane(near[1], 1)),
                       vmax(plane(near[2], 2), splat<Float>(0.0f)));
        const Float t_leave = vmin(vmin(far_plane(far[0], 0), far_plane(far[1], 1)),
                                   vmin(far_plane(far[2], 2), splat<Float>(t_max)));
        return lanes<Compare::kLe>(t_enter, t_leave);
    }
};

// Puts `other` on the stack to wait, the nearer of it and `current` going on as
// `current`; the entries pushed since `first` stay sorted, the nearest on top (a shadow
// feeler takes any hit: its order does not matter and is not kept).
template <bool kAnyHit, class Pending, std::size_t K>
[[gnu::always_inline]] inline void wait(std::array<Pending, K>& stack, int& top, int first,
                                        Pending& current, Pending other) {
    if (!kAnyHit && other.t_enter < current.t_enter) std::swap(other, current);
    int i = top++;
    if constexpr (!kAnyHit)
        for (; i > first && stack[i - 1].t_enter < other.t_enter; --i) stack[i] = stack[i - 1];
    stack[i] = other;
}

}  // namespace detail

template <int N>
template <bool kAnyHit, class HitLeaf>
bool WideBvh<N>::traverse_leaves(const Ray& ray, float& t_max, HitLeaf&& hit_leaf) const {
    if (nodes_.empty() || !finite_ray(ray)) return false;
    const detail::BoxRay<N> box_ray(ray);
    if constexpr (kAnyHit) {
        if (nodes_.size() == 1) return any_hit_in_root(box_ray, t_max, hit_leaf);
    }
    struct Pending {
        std::uint32_t child, count;  // count 0: a node
        float t_enter;               // skipped unvisited if a hit since is nearer
    };
    std::array<Pending, (N - 1) * Bvh::kMaxDepth + N> stack;  // a node adds at most N - 1
    int top = 0;
    const auto pop = [&](Pending& next) {
        do {
            if (top == 0) return false;
            next = stack[--top];
        } while (next.t_enter >= t_max);
        return true;
    };
    Pending current{0, 0, 0.0f};
    bool found = false;
    for (;;) {
        // Down the nearest child entered until a leaf; the others wait on the stack,
        // sorted so that the nearest is popped first (a shadow feeler takes any hit, so
        // its order does not matter).
        bool missed = false;
        while (current.count == 0) {
            const Node& node = nodes_[current.child];
            typename Lanes<N>::Float t_enter;
            unsigned mask = box_ray.test(node, t_max, t_enter);
            if (mask == 0) {
                missed = true;
                break;
            }
            int lane = __builtin_ctz(mask);
            current = {node.child[lane], node.count[lane], t_enter[lane]};
            const int first = top;
            for (mask &= mask - 1; mask != 0; mask &= mask - 1) {
                lane = __builtin_ctz(mask);
                detail::wait<kAnyHit>(stack, top, first, current,
                                      Pending{node.child[lane], node.count[lane], t_enter[lane]});
            }
        }
        if (!missed) {
            // The node to be taken next is fetched while the leaf is tested: incoherent rays
            // wait on their nodes' loads more than on anything else (docs/BENCHMARKS.md,
            // ninth session).
            if (top > 0 && stack[top - 1].count == 0) prefetch(nodes_[stack[top - 1].child]);
            if (hit_leaf(current.child, current.count, t_max)) {
                found = true;
                if constexpr (kAnyHit) return true;
            }
        }
        if (!pop(current)) return found;
    }
}

template <int N>
template <class HitLeaf>
bool WideBvh<N>::any_hit_in_root(const detail::BoxRay<N>& box_ray, float& t_max,
                                 HitLeaf& hit_leaf) const {
    const Node& root = nodes_[0];
    typename Lanes<N>::Float t_enter;
    for (unsigned mask = box_ray.test(root, t_max, t_enter); mask != 0; mask &= mask - 1) {
        const int lane = __builtin_ctz(mask);
        if (hit_leaf(root.child[lane], root.count[lane], t_max)) return true;
    }
    return false;
}

template <int N>
template <bool kAnyHit, class HitPrim>
bool WideBvh<N>::traverse(const Ray& ray, float& t_max, HitPrim&& hit) const {
    return traverse_leaves<kAnyHit>(ray, t_max, each_primitive<kAnyHit>(hit));
}

// The width the build's SIMD runs best.
using DefaultWideBvh = WideBvh<kBvhWidth>;

}  // namespace rt
