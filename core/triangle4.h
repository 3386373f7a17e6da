#pragma once
// Four triangles against one ray at once, with the watertight test of Woop, Benthin and
// Wald ("Watertight Ray/Triangle Intersection", JCGT 2013): the ray is sheared to the
// z axis and the three 2D edge functions are evaluated from the original vertices, so a
// ray through a shared edge or vertex of a closed mesh hits at least one of the
// triangles: nothing leaks. It is the tutorial's test (a plane hit, then three edge
// values that must share a sign, divided by their sum for the barycentrics) done in the
// ray's own frame, four triangles a time (core/simd.h), or eight (two packs) under AVX.

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/ray.h"
#include "core/simd.h"

namespace rt {

// A ray prepared for the watertight test: the axes permuted so that z is the largest
// component of the direction, and the shear that maps the direction onto +z. Plain
// arrays, not glm vectors: glm (with GLM_FORCE_XYZW_ONLY) reads a vector's component by
// a run-time index through a switch, a branch per read in every triangle test.
struct ShearedRay {
    int kx = 0, ky = 1, kz = 2;
    float sx = 0.0f, sy = 0.0f, sz = 1.0f;
    float origin[3]{};

    ShearedRay() = default;
    // Always inlined: GCC's inliner weighs it against everything else in the calling file,
    // and when core/mesh.cpp's build() grew (thirty-eighth session) it became a call at
    // each ray's first leaf; on Zen 4 single shadow and secondary rays took 10-30 % longer
    // (docs/BENCHMARKS.md, forty-first session).
    [[gnu::always_inline]] explicit ShearedRay(const Ray& r)
        : origin{r.origin.x, r.origin.y, r.origin.z} {
        const float d[3] = {r.dir.x, r.dir.y, r.dir.z};
        const float ax = std::fabs(d[0]), ay = std::fabs(d[1]), az = std::fabs(d[2]);
        kz = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
        kx = (kz + 1) % 3;
        ky = (kx + 1) % 3;
        if (d[kz] < 0.0f) std::swap(kx, ky);  // keep the winding
        sx = d[kx] / d[kz];
        sy = d[ky] / d[kz];
        sz = 1.0f / d[kz];
    }
};

inline constexpr std::uint32_t kTriangle4Lanes = 4;

struct Triangle4 {
    Float4 v[3][3];  // v[vertex][axis] lanes; unused lanes zero (never hit): Triangle4{} or
                     // set_empty(), as a default-initialised pack is not written

    void set_empty(int lane) {
        for (auto& vertex : v)
            for (Float4& axis : vertex) axis[lane] = 0.0f;
    }
    void set(int lane, const vec3& a, const vec3& b, const vec3& c) {
        for (int axis = 0; axis < 3; ++axis) {
            v[0][axis][lane] = a[axis];
            v[1][axis][lane] = b[axis];
            v[2][axis][lane] = c[axis];
        }
    }
};

struct Triangle4Hit {
    int lane = -1;                              // -1: no hit
    float t = kInfinity, b1 = 0.0f, b2 = 0.0f;  // b1, b2: weights of the second and third vertex
};

namespace detail {

// The values of one watertight test, each lane a triangle (Triangle4) or a ray (the
// packets' test, core/triangle_packet.h), computed by the same expressions for both so
// that both give the very same answer. rel(vertex, axis): a vertex's coordinate relative
// to the ray's origin; sx, sy: the shear (a float, or a vector of the rays').
template <class V>
struct WatertightValues {
    V az, bz, cz, ax, ay, bx, by, cx, cy;
    V u, v, w;  // the edge functions: each is the weight of the opposite vertex, times their sum
    V det;      // their sum
};

template <class V, class Rel, class S>
[[gnu::always_inline]] inline WatertightValues<V> watertight_values(const Rel& rel, int kx, int ky,
                                                                    int kz, S sx, S sy) {
    WatertightValues<V> o;
    o.az = rel(0, kz), o.bz = rel(1, kz), o.cz = rel(2, kz);
    o.ax = rel(0, kx) - sx * o.az, o.ay = rel(0, ky) - sy * o.az;
    o.bx = rel(1, kx) - sx * o.bz, o.by = rel(1, ky) - sy * o.bz;
    o.cx = rel(2, kx) - sx * o.cz, o.cy = rel(2, ky) - sy * o.cz;
    o.u = o.cx * o.by - o.cy * o.bx, o.v = o.ax * o.cy - o.ay * o.cx,
    o.w = o.bx * o.ay - o.by * o.ax;
    o.det = o.u + o.v + o.w;
    return o;
}

// Not only t > 0 but t beyond its own rounding error (Pharr, Jakob and Humphreys, PBR 3rd
// ed., 3.9.6): the error grows with the triangle's size, so a ray leaving a large
// triangle, offset from it by a little (offset_ray_origin), could otherwise hit the
// triangle itself just in front of its origin: acne on big walls. The bound on |t * det|,
// compared with it without a division; abs_sz: |sz|.
template <class V>
[[gnu::always_inline]] inline V t_det_error(const WatertightValues<V>& o, V abs_sz) {
    const auto gamma = [](float n) { return n * 0x1p-24f / (1.0f - n * 0x1p-24f); };
    const auto max3 = [](V a, V b, V c) { return vmax(vmax(vabs(a), vabs(b)), vabs(c)); };
    const V x_max = max3(o.ax, o.bx, o.cx), y_max = max3(o.ay, o.by, o.cy);
    const V z_max = max3(o.az, o.bz, o.cz) * abs_sz;
    const V delta_x = gamma(5) * (x_max + z_max), delta_y = gamma(5) * (y_max + z_max);
    const V delta_e = 2.0f * (gamma(2) * x_max * y_max + delta_y * x_max + delta_x * y_max);
    const V e_max = max3(o.u, o.v, o.w);
    return 3.0f * (gamma(3) * e_max * z_max + delta_e * z_max + gamma(3) * z_max * e_max);
}

inline float lane_of(float x, int) { return x; }
template <class V>
inline float lane_of(const V& x, int lane) {
    return x[lane];
}

// Of the lanes in `doubt` (the ray meets each one's triangle, at a t > 0 within the edge
// form's bound on its rounding), those whose plane certainly lies ahead of the ray's
// origin along it, before `limit`, with their t: in double precision, the plane's normal n from the
// corners relative to the origin (axes permuted as the shear's), the origin's side n . A and the
// direction's n . (sx, sy, 1), each beyond a bound on its rounding (forward error
// analysis; sx and sy were rounded to floats; the bounds doubled for their own rounding).
// The edge form's bound (t_det_error) is loose on a sliver that spans the origin's plane:
// there |t * det| is as small as det (a sliver of a twisted tube 0.2 units ahead was
// dropped), while here n is as long as the sliver is. The rare path: a lane at a time.
template <class V>
struct PlaneHits {
    unsigned lanes = 0;
    V t;  // in `lanes`
};

template <class V, class Corner, class R>
[[gnu::noinline, gnu::cold]] PlaneHits<V> plane_hits(const Corner& corner, const R& r,
                                                     const V& limit, unsigned doubt) {
    const auto gamma = [](double n) { return n * 0x1p-53 / (1.0 - n * 0x1p-53); };
    const int axis[3] = {r.kx, r.ky, r.kz};
    V c[3][3];
    for (int vertex = 0; vertex < 3; ++vertex)
        for (int a = 0; a < 3; ++a) c[vertex][a] = corner(vertex, axis[a]);
    PlaneHits<V> ahead;
    for (unsigned rest = doubt; rest != 0; rest &= rest - 1) {
        const int lane = __builtin_ctz(rest);
        double p[3][3];  // the corners relative to the origin, each rounded at most once
        double m = 0.0;
        for (int vertex = 0; vertex < 3; ++vertex)
            for (int a = 0; a < 3; ++a) {
                p[vertex][a] =
                    double(c[vertex][a][lane]) - double(lane_of(r.origin[axis[a]], lane));
                m = std::max(m, std::fabs(p[vertex][a]));
            }
        double e1[3], e2[3], e = 0.0;
        for (int a = 0; a < 3; ++a) {
            e1[a] = p[1][a] - p[0][a], e2[a] = p[2][a] - p[0][a];
            e = std::max({e, std::fabs(e1[a]), std::fabs(e2[a])});
        }
        const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                             e1[0] * e2[1] - e1[1] * e2[0]};
        const double n_max = std::max({std::fabs(n[0]), std::fabs(n[1]), std::fabs(n[2])});
        const double sx = lane_of(r.sx, lane), sy = lane_of(r.sy, lane);       // |sx|, |sy| <= 1
        const double side = n[0] * p[0][0] + n[1] * p[0][1] + n[2] * p[0][2];  // n . A
        const double toward = n[0] * sx + n[1] * sy + n[2];                    // n . d / d[kz]
        const double delta_e = gamma(1) * e + gamma(2) * 2.0 * m;
        const double delta_n = gamma(2) * 2.0 * e * e + 4.0 * e * delta_e + 2.0 * delta_e * delta_e;
        const double side_error =
            2.0 * (gamma(3) * 3.0 * n_max * m + 3.0 * m * (gamma(1) * n_max + delta_n));
        const double toward_error =
            2.0 * (gamma(3) * 3.0 * n_max + 0x1p-23 * 2.0 * n_max + 3.0 * delta_n);
        if (std::fabs(side) <= side_error || std::fabs(toward) <= toward_error) continue;
        const double t_exact = side * lane_of(r.sz, lane) / toward;  // n . A / n . d
        const auto t_float = float(t_exact);
        if (!(t_float > 0.0f) || t_exact >= double(limit[lane])) continue;
        ahead.t[lane] = t_float;
        ahead.lanes |= 1u << lane;
    }
    return ahead;
}

// The lanes of `asked` whose triangle the ray hits: the edge functions of one sign and
// det != 0 (the hit is inside), t in (0, limit) and beyond its rounding error. Writes
// each lane's t (meaningful in the lanes returned). corner(vertex, axis): a coordinate,
// as lanes; r: the shear (ShearedRay, or the packets' ShearedRays); abs_sz: its |sz|.
// The one test of both the single ray's leaves and the packets' (core/triangle_packet.h).
// `deferred`: where given, the lanes that only the plane test could settle are added to
// it and left out, not settled here: a packet's walk traces those rays alone afterwards
// (core/mesh_packet.cpp), which keeps the rare call out of its loops (2-5 % of the hall's
// feeler packets with it in; docs/BENCHMARKS.md, fortieth session).
template <class V, class Corner, class R>
[[gnu::always_inline]] inline unsigned watertight_hits(const WatertightValues<V>& o,
                                                       const Corner& corner, const R& r,
                                                       const V& abs_sz, const V& limit,
                                                       unsigned asked, V& t,
                                                       unsigned* deferred = nullptr) {
    const auto sz = r.sz;
    using enum Compare;
    const V zero = splat<V>(0.0f);
    const unsigned same_sign =
        (lanes<kGe>(o.u, zero) & lanes<kGe>(o.v, zero) & lanes<kGe>(o.w, zero)) |
        (lanes<kLe>(o.u, zero) & lanes<kLe>(o.v, zero) & lanes<kLe>(o.w, zero));
    const unsigned inside = same_sign & lanes<kNe>(o.det, zero) & asked;
    if (inside == 0) return 0;  // most leaf tests end here, before any division
    const V t_scaled = sz * (o.u * o.az + o.v * o.bz + o.w * o.cz);  // t * det
    t = t_scaled / o.det;
    const unsigned candidates = inside & lanes<kGt>(t, zero) & lanes<kLt>(t, limit);
    if (candidates == 0) return 0;
    // A triangle wholly in front of the origin is met at t > 0 wherever the ray meets it:
    // t is its corners' distances along the ray (each az * sz, its sign exact: a rounded
    // difference is 0 only where the two are equal), weighted by the barycentrics. One
    // that spans the origin's plane is met ahead where |t * det| passes the bound on its
    // rounding, or else where the plane test in double precision says so: the bound is
    // loose on a sliver (its edge functions cancel, and |t * det| is as small as det
    // whatever t is: a fan of thousands met at its centre had holes, a twisted tube of
    // slivers lost hits 0.2 units ahead).
    const unsigned in_front =
        lanes<kGt>(sz * o.az, zero) & lanes<kGt>(sz * o.bz, zero) & lanes<kGt>(sz * o.cz, zero);
    const unsigned sure =
        candidates & (in_front | lanes<kGt>(vabs(t_scaled), t_det_error(o, abs_sz)));
    const unsigned doubt = candidates & ~sure;
    if (doubt == 0) [[likely]]
        return sure;
    if (deferred != nullptr) {
        *deferred |= doubt;
        return sure;
    }
    const PlaneHits<V> plane = plane_hits<V>(corner, r, limit, doubt);
    t = select_bits(plane.lanes, plane.t, t);
    return sure | plane.lanes;
}

// A corner's coordinate relative to the ray's origin, as lanes (rounded once): the
// watertight test's input. corner(vertex, axis): the coordinate itself.
template <class Corner, class R>
[[gnu::always_inline]] inline auto relative_to_origin(const Corner& corner, const R& r) {
    return [&corner, &r](int vertex, int axis) { return corner(vertex, axis) - r.origin[axis]; };
}

// The closest of the triangles in V's lanes (corner(vertex, axis): a coordinate, as
// lanes) within (0, t_max), among `lanes`.
template <class V, class Corner>
[[gnu::always_inline]] inline Triangle4Hit closest_in_lanes(const Corner& corner,
                                                            const ShearedRay& r, float t_max,
                                                            unsigned lanes,
                                                            unsigned* deferred = nullptr) {
    const auto o =
        watertight_values<V>(relative_to_origin(corner, r), r.kx, r.ky, r.kz, r.sx, r.sy);
    V t;
    unsigned candidates = watertight_hits(o, corner, r, splat<V>(std::fabs(r.sz)), splat<V>(t_max),
                                          lanes, t, deferred);
    Triangle4Hit best;
    for (; candidates != 0; candidates &= candidates - 1) {
        const int lane = __builtin_ctz(candidates);
        if (t[lane] < best.t) best = {lane, t[lane], 0.0f, 0.0f};
    }
    if (best.lane >= 0) {
        best.b1 = o.v[best.lane] / o.det[best.lane];
        best.b2 = o.w[best.lane] / o.det[best.lane];
    }
    return best;
}

// Whether the ray hits any of the lanes' triangles within (0, t_max): the same test, no
// nearest sought (a shadow feeler's question).
template <class V, class Corner>
[[gnu::always_inline]] inline bool any_in_lanes(const Corner& corner, const ShearedRay& r,
                                                float t_max, unsigned lanes,
                                                unsigned* deferred = nullptr) {
    const auto o =
        watertight_values<V>(relative_to_origin(corner, r), r.kx, r.ky, r.kz, r.sx, r.sy);
    V t;
    return watertight_hits(o, corner, r, splat<V>(std::fabs(r.sz)), splat<V>(t_max), lanes, t,
                           deferred) != 0;
}

}  // namespace detail

// `lanes`: the lanes that may hit (a bit each); the others are computed and ignored, so a
// lane's answer is the same whichever others are asked for. `deferred`: as watertight_hits'
// (its bits, where given: the lanes left unsettled).
[[gnu::always_inline]] inline Triangle4Hit intersect(const Triangle4& tri, const ShearedRay& r,
                                                     float t_max, unsigned lanes = 0xfu,
                                                     unsigned* deferred = nullptr) {
    const auto corner = [&](int vertex, int axis) { return tri.v[vertex][axis]; };
    return detail::closest_in_lanes<Float4>(corner, r, t_max, lanes, deferred);
}

[[gnu::always_inline]] inline bool occludes(const Triangle4& tri, const ShearedRay& r, float t_max,
                                            unsigned* deferred = nullptr) {
    const auto corner = [&](int vertex, int axis) { return tri.v[vertex][axis]; };
    return detail::any_in_lanes<Float4>(corner, r, t_max, 0xfu, deferred);
}

#if defined(__AVX__)
// Two packs in one test of eight lanes, each lane the very arithmetic of the test above:
// a wide BVH's leaf of five to eight triangles costs one test, as a leaf of four does.
// The hit's lane: 0-3 in `a`, 4-7 in `b`.
[[gnu::always_inline]] inline Triangle4Hit intersect(const Triangle4& a, const Triangle4& b,
                                                     const ShearedRay& r, float t_max,
                                                     unsigned* deferred = nullptr) {
    const auto corner = [&](int vertex, int axis) {
        return Float8(_mm256_set_m128(b.v[vertex][axis], a.v[vertex][axis]));
    };
    return detail::closest_in_lanes<Float8>(corner, r, t_max, 0xffu, deferred);
}
[[gnu::always_inline]] inline bool occludes(const Triangle4& a, const Triangle4& b,
                                            const ShearedRay& r, float t_max,
                                            unsigned* deferred = nullptr) {
    const auto corner = [&](int vertex, int axis) {
        return Float8(_mm256_set_m128(b.v[vertex][axis], a.v[vertex][axis]));
    };
    return detail::any_in_lanes<Float8>(corner, r, t_max, 0xffu, deferred);
}
#endif

}  // namespace rt
