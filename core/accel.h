#pragma once
// The acceleration structure behind a mesh's triangles and a scene's objects, chosen at
// build time: the wide BVH (the default; 4 or 8 lanes, core/simd.h), the binary BVH it is collapsed
// from, a uniform grid, or brute force, the last three kept as comparison points (rtrender
// --accel, rtbench).

#include <numeric>
#include <optional>
#include <string>
#include <variant>

#include "core/bvh.h"
#include "core/grid.h"
#include "core/names.h"
#include "core/wide_bvh.h"
#include "core/wide_bvh_packet.h"

namespace rt {

enum class AccelKind { kBvh, kBvh2, kGrid, kBrute };  // kBvh: wide; kBvh2: binary

inline constexpr Named<AccelKind> kAccelNames[] = {{"bvh", AccelKind::kBvh},
                                                   {"bvh2", AccelKind::kBvh2},
                                                   {"grid", AccelKind::kGrid},
                                                   {"brute", AccelKind::kBrute}};
inline const char* accel_name(AccelKind kind) { return name_of(kAccelNames, kind); }
inline std::optional<AccelKind> parse_accel(const std::string& name) {
    return parse_named(kAccelNames, name);
}

// Tests every primitive: the reference the others must agree with.
class BruteForce {
  public:
    void build(std::span<const Aabb> boxes) { count_ = static_cast<std::uint32_t>(boxes.size()); }
    template <bool kAnyHit, class HitPrim>
    bool traverse(const Ray&, float& t_max, HitPrim&& hit) const {
        bool found = false;
        for (std::uint32_t p = 0; p < count_; ++p) {
            if (hit(p, t_max)) {
                found = true;
                if constexpr (kAnyHit) return true;
            }
        }
        return found;
    }
    std::size_t memory_bytes() const { return 0; }

  private:
    std::uint32_t count_ = 0;
};

class Accel {
  public:
    // leaf_size: how many primitives the caller tests at once (a mesh: 8 in the wide BVH
    // under AVX, two Triangle4s in one test; else 4), so the BVHs stop splitting there;
    // above split_above only where a split would not pay (Bvh::build). The BVHs build on
    // `threads` threads (0: all the hardware's).
    void build(std::span<const Aabb> boxes, AccelKind kind, std::uint32_t leaf_size = 1,
               int threads = 0, std::uint32_t split_above = 0);
    AccelKind kind() const { return kind_; }
    std::size_t memory_bytes() const;
    // Slot s of the traversal is primitive order()[s]: callers may keep their data in
    // slot order (the BVH's leaf order) for locality.
    std::span<const std::uint32_t> order() const {
        if (const auto* wide = std::get_if<DefaultWideBvh>(&impl_)) return wide->order();
        if (const auto* bvh = std::get_if<Bvh>(&impl_)) return bvh->order();
        return order_;
    }

    // Visits candidate primitives for a ray in (0, t_max); `hit(slot, t_max)` tests one
    // and returns true on a hit, having shortened t_max. kAnyHit stops at the first hit.
    template <bool kAnyHit, class HitPrim>
    bool traverse(const Ray& ray, float& t_max, HitPrim&& hit) const {
        return std::visit(
            [&](const auto& impl) { return impl.template traverse<kAnyHit>(ray, t_max, hit); },
            impl_);
    }

    // The same a leaf at a time, `hit_leaf(first_slot, count, t_max)`: BVH leaves, or
    // single primitives for the other structures.
    template <bool kAnyHit, class HitLeaf>
    bool traverse_leaves(const Ray& ray, float& t_max, HitLeaf&& hit_leaf) const {
        if (const auto* wide = std::get_if<DefaultWideBvh>(&impl_))
            return wide->traverse_leaves<kAnyHit>(ray, t_max, hit_leaf);
        if (const auto* bvh = std::get_if<Bvh>(&impl_))
            return bvh->traverse_leaves<kAnyHit>(ray, t_max, hit_leaf);
        return traverse<kAnyHit>(ray, t_max, [&](std::uint32_t slot, float& limit) {
            return hit_leaf(slot, 1u, limit);
        });
    }
    // Up to kPacketWidth rays at once, as WideBvh::traverse_packet: `hit_leaf(first_slot,
    // count, lanes)` returns the lanes that hit. The wide BVH traces them as a packet; the
    // other structures a ray at a time.
    template <bool kAnyHit, class HitLeaf>
    void traverse_packet(const Ray* rays, float* t_max, unsigned active, HitLeaf&& hit_leaf) const {
        if (const auto* wide = std::get_if<DefaultWideBvh>(&impl_))
            return wide->traverse_packet<kAnyHit>(rays, t_max, active, hit_leaf);
        detail::one_by_one<kAnyHit>(*this, rays, t_max, active & ((1u << kPacketWidth) - 1u),
                                    hit_leaf);
    }
    // The same, the rays that make no packet handed to `alone(lanes)` (the caller's own
    // single-ray code); all of them where the structure has no packets.
    template <bool kAnyHit, class HitLeaf, class Alone>
    void traverse_packet(const Ray* rays, float* t_max, unsigned active, HitLeaf&& hit_leaf,
                         Alone&& alone) const {
        if (const auto* wide = std::get_if<DefaultWideBvh>(&impl_))
            return wide->traverse_packet<kAnyHit>(rays, t_max, active, hit_leaf, alone);
        alone(active & ((1u << kPacketWidth) - 1u));
    }
    // The leaves traverse_leaves() hands out, as `f(first_slot, count)`, in slot order.
    template <class F>
    void for_each_leaf(F&& f) const {
        if (const auto* wide = std::get_if<DefaultWideBvh>(&impl_)) return wide->for_each_leaf(f);
        if (const auto* bvh = std::get_if<Bvh>(&impl_)) return bvh->for_each_leaf(f);
        for (std::uint32_t s = 0; s < order_.size(); ++s) f(s, 1u);
    }

    // The wide BVH's leaves renamed, f(first_slot, count) -> what traverse_leaves hands
    // out in place of the first slot (WideBvh::relabel_leaves); false for the other
    // structures, which keep handing out slots.
    template <class F>
    bool relabel_leaves(F&& f) {
        auto* wide = std::get_if<DefaultWideBvh>(&impl_);
        if (wide) wide->relabel_leaves(f);
        return wide != nullptr;
    }

  private:
    AccelKind kind_ = AccelKind::kBvh;
    std::variant<DefaultWideBvh, Bvh, UniformGrid, BruteForce> impl_;
    std::vector<std::uint32_t> order_;  // the grid's and brute force's: the identity
};

}  // namespace rt
