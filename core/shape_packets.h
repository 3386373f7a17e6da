#pragma once
// The analytic shapes' tests (core/shapes.h) for several rays at once, the rays as the
// lanes (core/ray_lanes.h): each lane does, operation for operation and in the same order
// (glm::dot's and glm::cross's, std::min's and std::max's), what the shape's own test does
// for that ray, so every ray gets the very t (and barycentrics) it gets alone. Used where
// rays share a shape: a packet's planes, the item buffer's pixels that name one object.

#include <bit>
#include <cstdint>
#include <limits>

#include "core/ray_lanes.h"
#include "core/shapes.h"

namespace rt {

// The rays of `lanes` whose hit lies in (0, t_max): returns their bits and sets their
// lanes of `t` (and of b1, b2 for a triangle: the weights of b and c).
template <int N>
struct LaneHits {
    using Float = typename Lanes<N>::Float;
    Float t_max;          // in: each ray's bound
    Float t, b1{}, b2{};  // out (a plane or sphere leaves b1 and b2 zero)
};

// The closest hit so far of each ray of a packet, as lanes, over the tests of one or
// more shapes in turn: the rays' bounds are read from their records once and the records
// of those that hit written once, not once a shape (the item buffer's pixels on an edge,
// which test every object named around them: Scene::intersect_among). The object's index
// is kept as the bits of a float lane.
struct ClosestLanes {
    using Float = Lanes<kPacketWidth>::Float;
    Float t, b1{}, b2{}, object;
    unsigned found = 0;  // the lanes whose hit is here and not yet in their records

    // The rays of `lanes` (one or more) within hits[lane].t.
    static ClosestLanes within(const Hit* hits, unsigned lanes) {
        ClosestLanes c;
        c.t = t_bounds<kPacketWidth>(hits, lanes);
        return c;
    }

    // The lanes of `hit` take out's hit on object `id`; returns `hit`.
    unsigned take(unsigned hit, const LaneHits<kPacketWidth>& out, std::uint32_t id) {
        t = select_bits(hit, out.t, t);
        b1 = select_bits(hit, out.b1, b1);
        b2 = select_bits(hit, out.b2, b2);
        object = select_bits(hit, splat<Float>(std::bit_cast<float>(id)), object);
        found |= hit;
        return hit;
    }

    Hit lane(int k) const {
        return Hit{t[k], std::bit_cast<std::uint32_t>(object[k]), 0, b1[k], b2[k]};
    }
    // The records of the lanes found, each written whole.
    void write(Hit* hits) const {
        for (unsigned rest = found; rest != 0; rest &= rest - 1) {
            const int k = __builtin_ctz(rest);
            hits[k] = lane(k);
        }
    }
};

namespace detail {

using LaneFloat = Lanes<kPacketWidth>::Float;
using LaneMask = Lanes<kPacketWidth>::Mask;

// glm::dot's order, (x + y) + z.
inline LaneFloat dot(const LaneFloat* u, const LaneFloat* v) {
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}
inline LaneFloat dot(const LaneFloat* u, const vec3& v) {
    return u[0] * v.x + u[1] * v.y + u[2] * v.z;
}

// glm::cross(x, y) of a fixed x and lanes y.
inline void cross(const vec3& x, const LaneFloat* y, LaneFloat* out) {
    out[0] = x.y * y[2] - y[1] * x.z;
    out[1] = x.z * y[0] - y[2] * x.x;
    out[2] = x.x * y[1] - y[0] * x.y;
}

inline LaneFloat copysign(LaneFloat magnitude, LaneFloat sign) {
    const LaneMask s = std::bit_cast<LaneMask>(sign) & std::numeric_limits<std::int32_t>::min();
    return std::bit_cast<LaneFloat>((std::bit_cast<LaneMask>(magnitude) & 0x7fffffff) | s);
}

}  // namespace detail

inline unsigned intersect_lanes(const Plane& p, const RayLanes<kPacketWidth>& r, unsigned lanes,
                                LaneHits<kPacketWidth>& out) {
    using Float = detail::LaneFloat;
    using detail::dot;
    const Float d_dot_n = dot(r.dir, p.normal), o_dot_n = dot(r.origin, p.normal);
    const Float zero = splat<Float>(0.0f);
    out.t = (splat<Float>(p.offset) - o_dot_n) / d_dot_n;
    return bits((d_dot_n != zero) & (out.t > zero) & (out.t < out.t_max)) & lanes;
}

inline unsigned intersect_lanes(const Sphere& s, const RayLanes<kPacketWidth>& r, unsigned lanes,
                                LaneHits<kPacketWidth>& out) {
    using Float = detail::LaneFloat;
    using Mask = detail::LaneMask;
    using detail::copysign, detail::dot;
    const Float f[3] = {r.origin[0] - s.centre.x, r.origin[1] - s.centre.y,
                        r.origin[2] - s.centre.z};
    const Float* d = r.dir;
    const Float A = dot(d, d), f_dot_d = dot(f, d);
    const Float B = 2.0f * f_dot_d;
    const float r2 = s.radius * s.radius;
    const Float C = dot(f, f) - r2;
    const Float along = f_dot_d / A;
    const Float closest[3] = {f[0] - along * d[0], f[1] - along * d[1], f[2] - along * d[2]};
    const Float discriminant = 4.0f * A * (r2 - dot(closest, closest));
    const Float zero = splat<Float>(0.0f);
    unsigned hit = bits(discriminant > zero) & lanes;  // a graze is a miss
    if (hit == 0) return 0;
    const Float q = -0.5f * (B + copysign(vsqrt(discriminant), B));
    const Float ta = q / A;
    const Float tb = q != zero ? C / q : -ta;
    const Float t1 = tb < ta ? tb : ta, t2 = ta < tb ? tb : ta;  // std::min, std::max
    const Mask near = (t1 > zero) & (t1 < out.t_max);
    out.t = near ? t1 : t2;  // the far root where the origin is inside
    return hit & bits(near | ((t2 > zero) & (t2 < out.t_max)));
}

inline unsigned intersect_lanes(const Triangle& tri, const RayLanes<kPacketWidth>& r,
                                unsigned lanes, LaneHits<kPacketWidth>& out) {
    using Float = detail::LaneFloat;
    using detail::cross, detail::dot;
    const vec3 ab = tri.b - tri.a, ac = tri.c - tri.a, bc = tri.c - tri.b, ca = tri.a - tri.c;
    const vec3 n = glm::cross(ab, ac);
    const Float zero = splat<Float>(0.0f);
    const Float d_dot_n = dot(r.dir, n);
    const Float to_a[3] = {tri.a.x - r.origin[0], tri.a.y - r.origin[1], tri.a.z - r.origin[2]};
    const Float t = dot(to_a, n) / d_dot_n;
    unsigned hit = bits((d_dot_n != zero) & (t > zero) & (t < out.t_max)) & lanes;
    if (hit == 0) return 0;
    const Float p[3] = {r.origin[0] + r.dir[0] * t, r.origin[1] + r.dir[1] * t,
                        r.origin[2] + r.dir[2] * t};
    const auto edge = [&](const vec3& from, const vec3& along) {
        const Float rel[3] = {p[0] - from.x, p[1] - from.y, p[2] - from.z};
        Float c[3];
        cross(along, rel, c);
        return dot(c, n);
    };
    const Float edge_ab = edge(tri.a, ab), edge_bc = edge(tri.b, bc), edge_ca = edge(tri.c, ca);
    hit &=
        ~bits((edge_ab < zero) | (edge_bc < zero) | (edge_ca < zero));  // as the test: NaN passes
    const float inv_nn = 1.0f / glm::dot(n, n);
    out.t = t;
    out.b1 = edge_ca * inv_nn;
    out.b2 = edge_ab * inv_nn;
    return hit;
}

}  // namespace rt
