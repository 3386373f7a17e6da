// Scene's shadow feelers: one at a time, and several to one light at once.
#include <array>
#include <bit>
#include <optional>

#include "core/scene.h"
#include "core/shape_packets.h"

namespace rt {

// Inlined into the feelers' paths: a plane's test is a few instructions, its call more.
[[gnu::always_inline]] inline bool Scene::occluded_by(std::uint32_t object, const Ray& r,
                                                      float t_max) const {
    const Object& o = objects[object];
    Ray moved;
    const Ray& local = object_ray(o, r, moved);
    return visit_shape(o, [&](const auto& shape) { return shape.occluded(local, t_max); });
}

bool Scene::occluded(const Ray& r, float t_max) const {
    for (std::uint32_t i : unbounded_)
        if (occluded_by(i, r, t_max)) return true;
    return top_.traverse<true>(r, t_max, [&](std::uint32_t slot, float& t_limit) {
        return occluded_by(bounded_[slot], r, t_limit);
    });
}

bool Scene::occluded_in_tree(const Ray& feeler, float t_max, std::uint32_t leaving) const {
    return top_.traverse<true>(feeler, t_max, [&](std::uint32_t slot, float& t_limit) {
        return bounded_[slot] != leaving && occluded_by(bounded_[slot], feeler, t_limit);
    });
}

bool Scene::occluded(const Ray& feeler, float t_max, std::size_t light,
                     std::uint32_t leaving) const {
    for (std::uint32_t i : unbounded_)
        if (i != leaving && occluded_by(i, feeler, t_max)) return true;
    const std::optional<LightBuffer>& buffer = light_buffers_[light];
    const LightBuffer::Cell cell = buffer ? buffer->cell(feeler.origin) : LightBuffer::Cell{};
    // A ray that is not finite meets no bounded object in the tree (it checks), nor so in
    // an empty cell (most cells: no check needed); in a listed one it goes to the tree.
    if (cell.crowded || (cell.begin != cell.end && !finite_ray(feeler)))
        return occluded_in_tree(feeler, t_max, leaving);
    for (const std::uint32_t* slot = cell.begin; slot != cell.end; ++slot)
        if (bounded_[*slot] != leaving && occluded_by(bounded_[*slot], feeler, t_max)) return true;
    return false;
}

namespace {

// The feelers in o's own space, as object_ray gives each alone: `world` itself where o
// has no transform, else `world` moved into `moved`.
const RayLanes<kPacketWidth>& object_lanes(const Object& o, const RayLanes<kPacketWidth>& world,
                                           RayLanes<kPacketWidth>& moved) {
    if (!o.transform) return world;
    moved = world.to_object(*o.transform);
    return moved;
}

// An analytic shape's test of the feelers of `lanes` (`world`, in the object's space
// where it has a transform) on the lanes: each lane's arithmetic is the shape's own
// (core/shape_packets.h), so each gets the answer it gets alone.
unsigned analytic_occluded(const Object& o, const RayLanes<kPacketWidth>& world, const float* t_max,
                           unsigned lanes) {
    LaneHits<kPacketWidth> out;
    out.t_max = splat<Lanes<kPacketWidth>::Float>(0.0f);
    for (unsigned rest = lanes; rest != 0; rest &= rest - 1)
        out.t_max[__builtin_ctz(rest)] = t_max[__builtin_ctz(rest)];
    RayLanes<kPacketWidth> moved;
    const RayLanes<kPacketWidth>& local = object_lanes(o, world, moved);
    return std::visit(
        Overloaded{[](const MeshRef&) { return 0u; },  // not asked
                   [&](const auto& shape) { return intersect_lanes(shape, local, lanes, out); }},
        o.shape);
}

// A mesh's test of the feelers of `lanes`, together through its tree (in the object's
// space where it has a transform: each lane the ray Transform::to_object gives).
unsigned mesh_occluded(const Object& o, const TriangleMesh& mesh,
                       const RayLanes<kPacketWidth>& world, const float* t_max, unsigned lanes) {
    RayLanes<kPacketWidth> moved;
    const RayLanes<kPacketWidth>& local = object_lanes(o, world, moved);
    std::array<Ray, kPacketWidth> rays;
    for (unsigned rest = lanes; rest != 0; rest &= rest - 1) {
        const int lane = __builtin_ctz(rest);
        rays[lane] = local.lane(lane);
    }
    return mesh.occluded_packet(rays.data(), t_max, lanes);
}

}  // namespace

// Two or more feelers meeting an object are tested together: a plane, sphere or triangle
// on the lanes, a mesh's as a packet through its tree. The mesh's packets were once
// slower than its feelers one by one (cornell, whose every feeler starts on its one mesh:
// 6 % of the frame, BENCHMARKS.md); since the leaves test a packet's rays across a
// triangle's lanes they are not (frames 0.94-0.96x whitted, 0.92x textured, 0.95x
// many_spheres, 0.99-1.00x cornell, BENCHMARKS.md "twenty-ninth session").
unsigned Scene::occluded_by_packet(std::uint32_t object, const RayLanes<kPacketWidth>& feelers,
                                   const float* t_max, unsigned lanes) const {
    const Object& o = objects[object];
    if (std::popcount(lanes) >= 2) {
        const auto* mesh = std::get_if<MeshRef>(&o.shape);
        return mesh ? mesh_occluded(o, meshes[mesh->mesh], feelers, t_max, lanes)
                    : analytic_occluded(o, feelers, t_max, lanes);
    }
    unsigned blocked = 0;
    for (; lanes != 0; lanes &= lanes - 1) {
        const unsigned lane = __builtin_ctz(lanes);
        if (occluded_by(object, feelers.lane(static_cast<int>(lane)), t_max[lane]))
            blocked |= 1u << lane;
    }
    return blocked;
}

unsigned Scene::occluded_packet(const RayLanes<kPacketWidth>& feelers, const float* t_max,
                                std::size_t light, const std::uint32_t* leaving,
                                unsigned active) const {
    unsigned blocked = 0;
    for (std::uint32_t i : unbounded_) {
        unsigned lanes = 0;
        for (unsigned open = active & ~blocked; open != 0; open &= open - 1)
            if (leaving[__builtin_ctz(open)] != i) lanes |= open & -open;
        blocked |= occluded_by_packet(i, feelers, t_max, lanes);
    }
    unsigned rest = active & ~blocked;
    const std::optional<LightBuffer>& buffer = light_buffers_[light];
    std::array<LightBuffer::Cell, kPacketWidth> cells;
    if (buffer) buffer->cells(feelers, rest, cells.data());
    // finite_ray on the lanes: x * 0 is NaN exactly where x is NaN or infinite.
    using Float = Lanes<kPacketWidth>::Float;
    Float sum = splat<Float>(0.0f);
    for (int a = 0; a < 3; ++a) sum += feelers.origin[a] * 0.0f + feelers.dir[a] * 0.0f;
    const unsigned finite = bits(sum == splat<Float>(0.0f));
    while (rest != 0) {
        const unsigned lane = __builtin_ctz(rest);
        const LightBuffer::Cell cell = cells[lane];
        if (!cell.crowded && cell.begin == cell.end) {  // an empty cell: nothing to meet
            rest &= rest - 1;
            continue;
        }
        if (cell.crowded || !((finite >> lane) & 1u)) {  // as occluded() does
            if (occluded_in_tree(feelers.lane(static_cast<int>(lane)), t_max[lane], leaving[lane]))
                blocked |= 1u << lane;
            rest &= rest - 1;
            continue;
        }
        // The feelers of this cell (its list is theirs too) test its objects together.
        unsigned same = 0;
        for (unsigned lanes = rest & finite; lanes != 0; lanes &= lanes - 1) {
            const unsigned k = __builtin_ctz(lanes);
            if (!cells[k].crowded && cells[k].begin == cell.begin && cells[k].end == cell.end)
                same |= 1u << k;
        }
        rest &= ~same;
        for (const std::uint32_t* slot = cell.begin; slot != cell.end && same != 0; ++slot) {
            const std::uint32_t object = bounded_[*slot];
            unsigned lanes = 0;
            for (unsigned open = same; open != 0; open &= open - 1)
                if (leaving[__builtin_ctz(open)] != object) lanes |= open & -open;
            const unsigned hit = occluded_by_packet(object, feelers, t_max, lanes);
            blocked |= hit;
            same &= ~hit;
        }
    }
    return blocked;
}

}  // namespace rt
