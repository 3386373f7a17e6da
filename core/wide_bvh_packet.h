#pragma once
// Coherent rays through the wide BVH together (Wald, Slusallek, Benthin and Wagner,
// "Interactive Rendering with Coherent Ray Tracing", 2001; the interval test of Boulos
// et al., "Geometric and Arithmetic Culling Methods for Entire Ray Packets", 2006).
// A node is tested once for the whole packet: one slab test over its N children with
// interval arithmetic on the rays' origins and inverse directions, which bounds every
// ray's own entry and exit from below and above. Each child it admits is then tested
// against each ray's own box test (the rays as the lanes: kPacketWidth of them, eight
// under AVX also where the nodes have sixteen children), and the child is walked for
// the rays that enter it only: its triangles are tested by exactly the rays that would
// test them alone. At a node that at most kFewRays of them reach, each of those tests all
// the children itself, as it would alone, and the walk goes on together. Each ray ends
// with the hit it would find alone. (Where the rays share
// their origin, a camera's, the interval is tight: a leaf it admits skips the rays' own
// box test, and the triangle tests decide.)
//
// Rays whose direction signs differ on some axis, or with a zero component, make no
// useful interval: such a packet is traced a ray at a time, by the caller's own
// single-ray code where it gives one (a mesh: its intersect and occluded, whose leaf
// tests need none of the packet's set-up), else WideBvh::traverse_leaves.

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

#include "core/ray_lanes.h"
#include "core/wide_bvh.h"

namespace rt {
namespace detail {

// The rays of a packet, as lanes: at most kPacketWidth, however wide the nodes.
template <int N>
inline constexpr int kRayLanes = N < kPacketWidth ? N : kPacketWidth;

template <int N>
struct PacketBoxes {
    using Float = typename Lanes<N>::Float;                // a lane per child
    using RayFloat = typename Lanes<kRayLanes<N>>::Float;  // a lane per ray
    // The interval over the rays, each splat over the children: the origin a near plane
    // is measured from (the largest coordinate where the rays go up the axis, else the
    // smallest), the one a far plane is, and the inverse directions' range.
    // exit_inv_lo, exit_inv_hi: the same range of the far planes' inverses (Ize's factor in
    // them, as in BoxRay).
    Float entry_origin[3], exit_origin[3], inv_lo[3], inv_hi[3], exit_inv_lo[3], exit_inv_hi[3];
    // The rays themselves, a lane each, for each ray's own test.
    RayFloat inv[3], inv_far[3], origin[3];
    int near[3], far[3];
    bool one_origin = true;  // the rays share their origin (a camera's): the interval is tight

    // False where the interval says nothing useful: then trace the rays alone. The
    // rays' origins are finite (traverse_packet leaves the others out); lanes outside
    // `active` repeat its first ray, so they widen nothing.
    bool set(const Ray* rays, unsigned active) {
        constexpr unsigned kAll = (1u << kRayLanes<N>)-1u;
        const auto gathered = RayLanes<kRayLanes<N>>::gather(rays, active);
        const RayFloat* d = gathered.dir;
        for (int a = 0; a < 3; ++a) origin[a] = gathered.origin[a];
        one_origin = true;
        for (int a = 0; a < 3; ++a) {
            inv[a] = 1.0f / d[a];  // lane by lane the single ray's 1.0f / dir (IEEE division)
            inv_far[a] = inv[a] * kSlabExitFactor;
            const unsigned up = bits(d[a] > 0.0f), down = bits(d[a] < 0.0f);
            if ((up != kAll && down != kAll) ||
                bits(vabs(inv[a]) < splat<RayFloat>(kInfinity)) != kAll)
                return false;
            const float o_lo = hmin(origin[a]), o_hi = hmax(origin[a]);
            one_origin = one_origin && o_lo == o_hi;
            const bool positive = up == kAll;
            entry_origin[a] = splat<Float>(positive ? o_hi : o_lo);
            exit_origin[a] = splat<Float>(positive ? o_lo : o_hi);
            const float i_lo = hmin(inv[a]), i_hi = hmax(inv[a]);
            inv_lo[a] = splat<Float>(i_lo);
            inv_hi[a] = splat<Float>(i_hi);
            // Multiplying by the factor keeps the order, so these bound every ray's inv_far.
            exit_inv_lo[a] = splat<Float>(i_lo * kSlabExitFactor);
            exit_inv_hi[a] = splat<Float>(i_hi * kSlabExitFactor);
            near[a] = positive ? a : a + 3;
            far[a] = positive ? a + 3 : a;
        }
        return true;
    }

    // A bit per child that some ray may enter in (0, t_max), t_max the largest of the
    // rays', and a lower bound on where each child is entered. Of the interval product
    // (plane - origin) * inverse, the smallest for a near plane is the smallest
    // difference times the smallest inverse if that difference is positive, else times
    // the largest; the largest for a far plane, the other way round. Rounding to nearest
    // is monotonic, so the bounds hold for every ray's own rounded slab test.
    [[gnu::always_inline]] unsigned test(const WideBvhNode<N>& n, float t_max,
                                         Float& t_enter) const {
        const Float zero = splat<Float>(0.0f);
        const auto entry = [&](int a) {
            const Float d = n.bounds[near[a]] - entry_origin[a];
            return d * (d >= zero ? inv_lo[a] : inv_hi[a]);
        };
        const auto exit = [&](int a) {
            const Float d = n.bounds[far[a]] - exit_origin[a];
            return d * (d >= zero ? exit_inv_hi[a] : exit_inv_lo[a]);
        };
        t_enter = vmax(vmax(entry(0), entry(1)), vmax(entry(2), zero));
        const Float t_leave = vmin(vmin(exit(0), exit(1)), vmin(exit(2), splat<Float>(t_max)));
        return bits(t_enter <= t_leave);
    }

    // A bit per ray that enters child `lane` of `n` within its own (0, t_max): the single
    // ray's test (BoxRay::test), with the rays as the lanes.
    [[gnu::always_inline]] unsigned rays_entering(const WideBvhNode<N>& n, int lane,
                                                  const RayFloat& t_max) const {
        const auto plane = [&](int index, int a, const RayFloat* inverse) {
            return (splat<RayFloat>(n.bounds[index][lane]) - origin[a]) * inverse[a];
        };
        const RayFloat t_enter = vmax(vmax(plane(near[0], 0, inv), plane(near[1], 1, inv)),
                                      vmax(plane(near[2], 2, inv), splat<RayFloat>(0.0f)));
        const RayFloat t_leave = vmin(vmin(plane(far[0], 0, inv_far), plane(far[1], 1, inv_far)),
                                      vmin(plane(far[2], 2, inv_far), t_max));
        return bits(t_enter <= t_leave);
    }

    // The children of `n` that ray `r` (a lane) enters within (0, t_max), and where: the
    // single ray's own test (BoxRay::test), with the children as the lanes.
    [[gnu::always_inline]] unsigned ray_enters(const WideBvhNode<N>& n, int r, float t_max,
                                               Float& t_enter) const {
        const auto plane = [&](int index, int a, const RayFloat* inverse) {
            return (n.bounds[index] - splat<Float>(origin[a][r])) * splat<Float>(inverse[a][r]);
        };
        t_enter = vmax(vmax(plane(near[0], 0, inv), plane(near[1], 1, inv)),
                       vmax(plane(near[2], 2, inv), splat<Float>(0.0f)));
        const Float t_leave = vmin(vmin(plane(far[0], 0, inv_far), plane(far[1], 1, inv_far)),
                                   vmin(plane(far[2], 2, inv_far), splat<Float>(t_max)));
        return bits(t_enter <= t_leave);
    }
};

// The rays' t_max as lanes (inactive ones -inf, so no box is entered) and the largest.
template <int N>
struct PacketLimits {
    typename Lanes<kRayLanes<N>>::Float lanes;
    float largest = -kInfinity;

    void update(const float* t_max, unsigned active) {  // (the inactive lanes' t_max may be unset)
        using Float = typename Lanes<kRayLanes<N>>::Float;
        lanes = select_bits(active, load<Float>(t_max), splat<Float>(-kInfinity));
        largest = hmax(lanes);
    }
};

// At most this many rays at a node are tested each on its own, against all the children
// at once: the interval test and a test over the rays for each child it admits cost more
// for so few. Feelers from scattered hits (a soup of small triangles, foliage) part ways
// high in the tree and walk most of it one or two together: their packets took 1.28x
// Embree's rtcOccluded8 time on a soup, and 0.98x with this (a tree's leaves 0.96 ->
// 0.86x); the city, the teapot and the bunny 1-4 % faster, primary rays within the noise
// (docs/BENCHMARKS.md, thirty-seventh session).
inline constexpr int kFewRays = 2;

// The children of `n` that some of `rays` enter, a few rays each testing all of them
// (kFewRays): as children_entered.
template <int N>
[[gnu::always_inline]] inline unsigned children_entered_by_each(const PacketBoxes<N>& boxes,
                                                                const WideBvhNode<N>& n,
                                                                unsigned rays,
                                                                const PacketLimits<N>& limits,
                                                                typename Lanes<N>::Float& t_enter,
                                                                std::array<unsigned, N>& entering) {
    using Float = typename Lanes<N>::Float;
    using Mask = typename Lanes<N>::Mask;
    Mask child_bit, rays_in = {};  // lane k: 1 << k; the rays that enter child k
    for (int k = 0; k < N; ++k) child_bit[k] = 1 << k;
    unsigned mask = 0;
    t_enter = splat<Float>(kInfinity);
    for (unsigned m = rays; m != 0; m &= m - 1) {
        const int r = __builtin_ctz(m);
        Float t;
        const unsigned enters = boxes.ray_enters(n, r, limits.lanes[r], t);
        t_enter = select_bits(enters, vmin(t_enter, t), t_enter);
        rays_in |= ((static_cast<int>(enters) & child_bit) != 0) & (1 << r);
        mask |= enters;
    }
    __builtin_memcpy(entering.data(), &rays_in, sizeof rays_in);
    return mask;
}

// The children of `n` that some of `rays` enter: a bit each, with which rays
// (`entering`) and a lower bound on where (`t_enter`). The interval test picks the
// children some ray may enter; each ray's own test then says which do, so a subtree is
// walked for its rays only (near the rays' origins, where feelers start among small
// boxes, the interval alone admits many that none enters). Rays from one origin leave
// the rays' own test of a leaf to the leaf.
template <int N>
[[gnu::always_inline]] inline unsigned children_entered(const PacketBoxes<N>& boxes,
                                                        const WideBvhNode<N>& n, unsigned rays,
                                                        const PacketLimits<N>& limits,
                                                        typename Lanes<N>::Float& t_enter,
                                                        std::array<unsigned, N>& entering) {
    if (std::popcount(rays) <= kFewRays)
        return children_entered_by_each<N>(boxes, n, rays, limits, t_enter, entering);
    unsigned mask = 0;
    for (unsigned m = boxes.test(n, limits.largest, t_enter); m != 0; m &= m - 1) {
        const int lane = __builtin_ctz(m);
        entering[lane] = n.count[lane] == 0 && boxes.one_origin
                             ? rays
                             : boxes.rays_entering(n, lane, limits.lanes) & rays;
        if (entering[lane] != 0) mask |= 1u << lane;
    }
    return mask;
}

// The rays of `active` one at a time, through `s.traverse_leaves` (a packet whose rays
// make no useful interval, or a structure without packets).
template <bool kAnyHit, class S, class HitLeaf>
void one_by_one(const S& s, const Ray* rays, float* t_max, unsigned active, HitLeaf& hit_leaf) {
    for (; active != 0; active &= active - 1) {
        const unsigned lane = __builtin_ctz(active);
        s.template traverse_leaves<kAnyHit>(rays[lane], t_max[lane],
                                            [&](std::uint32_t first, std::uint32_t count, float&) {
                                                return hit_leaf(first, count, 1u << lane) != 0;
                                            });
    }
}

}  // namespace detail

template <int N>
template <bool kAnyHit, class HitLeaf>
void WideBvh<N>::traverse_packet(const Ray* rays, float* t_max, unsigned active,
                                 HitLeaf&& hit_leaf) const {
    traverse_packet<kAnyHit>(rays, t_max, active, hit_leaf, [&](unsigned lanes) {
        detail::one_by_one<kAnyHit>(*this, rays, t_max, lanes, hit_leaf);
    });
}

template <int N>
template <bool kAnyHit, class HitLeaf, class Alone>
void WideBvh<N>::traverse_packet(const Ray* rays, float* t_max, unsigned active, HitLeaf&& hit_leaf,
                                 Alone&& alone) const {
    active &= (1u << detail::kRayLanes<N>)-1u;
    for (unsigned m = active; m != 0; m &= m - 1) {
        const int lane = __builtin_ctz(m);
        if (!finite_ray(rays[lane])) active &= ~(1u << lane);
    }
    if (nodes_.empty() || active == 0) return;
    detail::PacketBoxes<N> boxes;
    if (!boxes.set(rays, active)) return alone(active);
    detail::PacketLimits<N> limits;
    limits.update(t_max, active);
    struct Pending {
        std::uint32_t child, count;  // count 0: a node
        unsigned rays;               // the rays that enter it, each by its own test
        float t_enter;               // a lower bound for each of them
    };
    std::array<Pending, (N - 1) * Bvh::kMaxDepth + N> stack;
    int top = 0;
    Pending current{0, 0, active, 0.0f};
    for (;;) {
        // Down the nearest child entered until a leaf, as a single ray goes (traverse_leaves).
        bool missed = false;
        while (current.count == 0) {
            const Node& node = nodes_[current.child];
            typename Lanes<N>::Float t_enter;
            std::array<unsigned, N> entering;
            unsigned mask =
                detail::children_entered<N>(boxes, node, current.rays, limits, t_enter, entering);
            if (mask == 0) {
                missed = true;
                break;
            }
            int lane = __builtin_ctz(mask);
            current = {node.child[lane], node.count[lane], entering[lane], t_enter[lane]};
            const int first = top;
            for (mask &= mask - 1; mask != 0; mask &= mask - 1) {
                lane = __builtin_ctz(mask);
                detail::wait<kAnyHit>(
                    stack, top, first, current,
                    Pending{node.child[lane], node.count[lane], entering[lane], t_enter[lane]});
            }
        }
        if (!missed) {
            const unsigned hit = hit_leaf(current.child, current.count, current.rays);
            if (hit != 0) {
                if constexpr (kAnyHit) {
                    active &= ~hit;
                    if (active == 0) return;
                }
                limits.update(t_max, active);
            }
        }
        do {
            if (top == 0) return;
            current = stack[--top];
            current.rays &= active;
        } while (current.rays == 0 || current.t_enter >= limits.largest);
    }
}

}  // namespace rt
