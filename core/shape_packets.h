#pragma once
// The analytic shapes' tests (core/shapes.h) for several rays at once, the rays as the
// lanes (core/ray_lanes.h): each lane does, operation for operation and in the same order
// (glm::dot's and glm::cross's, std::min's and std::max's), what the shape's own test does
// for that ray, so every ray gets the very t (and barycentrics) it gets alone. Used where
// rays share a shape: a packet's planes, the item buffer's pixels that name one object.

#include "core/ray_lanes.h"
#include "core/shapes.h"

namespace rt {

// The rays of `lanes` whose hit lies in (0, t_max): returns their bits and sets their
// lanes of `t` (and of b1, b2 for a triangle: the weights of b and c).
template <int N>
struct LaneHits {
    using Float = typename Lanes<N>::Float;
    Float t_max;  // in: each ray's bound
    Float t, b1{}, b2{};  // out (a plane or sphere leaves b1 and b2 zero)
};

unsigned intersect_lanes(const Plane& p, const RayLanes<kPacketWidth>& r, unsigned lanes,
                         LaneHits<kPacketWidth>& out);
unsigned intersect_lanes(const Sphere& s, const RayLanes<kPacketWidth>& r, unsigned lanes,
                         LaneHits<kPacketWidth>& out);
unsigned intersect_lanes(const Triangle& tri, const RayLanes<kPacketWidth>& r, unsigned lanes,
                         LaneHits<kPacketWidth>& out);

}  // namespace rt
