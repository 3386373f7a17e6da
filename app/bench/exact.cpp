#include "app/bench/exact.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace rt::bench {
namespace {

// Relative margins, far above double's rounding and far below float's: a ray this near
// an edge, a vertex or its end is one that float structures may legitimately see
// either way.
constexpr double kEdgeMargin = 1e-6;
constexpr double kTMargin = 1e-5;
// A float test's rounding, relative to the products it computes (16 float epsilons).
constexpr double kEdgeNoise = 1e-6;

struct DoubleHit {
    bool hit = false, grazing = false;
    double t = 0.0;
    // How far t may be off in a float test and still be right: t_rounding.
    double slack = 0.0;
};

// How far a float watertight test's t (Woop, Benthin and Wald; core/triangle4.h's) may
// lie from the exact t, the same whichever corner is called a. Each corner relative to
// the origin is sheared onto the ray's major axis (x, y across it, t_j along it): x and y
// are rounded by up to u (4 R + X) (u = 2^-24, R the corners' largest coordinate relative
// to the origin, X the largest |x| or |y|), so each edge function e_j, a difference of
// two products of them, by up to u (8 R X + 5 X^2) (PBR 3.9.6's delta_e), which moves
// t = sum(e_j t_j) / sum(e_j) by that times sum |t_j - t| / |sum e_j|; rounding t_j, the
// products, the sum and the division move it by up to about 7 u of sum |e_j t_j| / |sum
// e_j|. Taken as 8 u (R X + X^2) and 8 u: about the first-order worst case.
// A sliver long across the ray has X its length over sum e_j its area: on a twisted
// tube's slivers 6 units long and 2e-4 wide, hits 1e-4 to 2e-4 units from a feeler's
// start, which Embree met and our float test put at t <= 0, lie within this bound.
// Measured: a float t lies at most 0.58 of it from the exact one on the bunny, teapot,
// terrain and a soup (0.05-0.16 on slivers), 200,000 random rays each
// (docs/BENCHMARKS.md, forty-first session). Until then the slack was 1e-5 of the
// corners' distance times |e1| |e2| / |det|, which depends on which corner is a: on a
// sliver far above this with a at the apex, far below with a at a blunt corner (a false
// "WRONG" on twist.obj).
double t_rounding(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3 (&corner)[3],
                  double t) {
    constexpr double kEps = 0x1p-24, kEdgeUlps = 8.0, kAxisUlps = 8.0;
    const glm::dvec3 ad = glm::abs(d);
    const int kz = ad.x > ad.y ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2);
    const int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    double x[3], y[3], tj[3], r = 0.0, span = 0.0;
    for (int j = 0; j < 3; ++j) {
        const glm::dvec3 p = corner[j] - o;
        tj[j] = p[kz] / d[kz];
        x[j] = p[kx] - d[kx] * tj[j];
        y[j] = p[ky] - d[ky] * tj[j];
        r = std::max({r, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
        span = std::max({span, std::fabs(x[j]), std::fabs(y[j])});
    }
    double det = 0.0, moved = 0.0, along = 0.0;
    for (int j = 0; j < 3; ++j) {
        const int b = (j + 1) % 3, c = (j + 2) % 3;
        const double e = x[b] * y[c] - y[b] * x[c];
        det += e;
        moved += std::fabs(tj[j] - t);
        along += std::fabs(e * tj[j]);
    }
    if (det == 0.0) return std::numeric_limits<double>::infinity();
    return (kEdgeUlps * kEps * (r * span + span * span) * moved + kAxisUlps * kEps * along) /
           std::fabs(det);
}

// Moeller and Trumbore's test in double precision; `grazing` when the ray passes within
// kEdgeMargin (in barycentric terms) of the triangle's boundary, inside or out.
DoubleHit intersect(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& a,
                    const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 e1 = b - a, e2 = c - a, p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    DoubleHit h;
    if (det == 0.0) return h;  // parallel or degenerate: no area to hit
    const glm::dvec3 s = o - a;
    const double u = glm::dot(s, p) / det;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(d, q) / det;
    const double w = 1.0 - u - v;
    h.t = glm::dot(e2, q) / det;
    const double corners = std::max({glm::length(s), glm::length(b - o), glm::length(c - o)});
    // |e1| |e2|, not |e1 x e2|: a float test's t is e2 . (s x e1) / det rounded, off by
    // that product times the corners' distance, however thin the triangle (a needle's
    // cross product is small, its rounding is not).
    const glm::dvec3 corner[3] = {a, b, c};
    h.slack = t_rounding(o, d, corner, h.t);
    // Each weight's float noise: u * det = s . (d x e2) and v * det = d . (s x e1) are
    // products of the corners' distances and the edges, which a float test rounds to
    // kEdgeNoise of that (|d| = 1), whatever their difference: a needle of a straw seen
    // from 18 units, 0.004 across, is decided 1e-3 of its width from an edge either way.
    const double noise = kEdgeNoise * corners / std::fabs(det);
    const double mu = std::max(kEdgeMargin, noise * glm::length(e2)),
                 mv = std::max(kEdgeMargin, noise * glm::length(e1)), mw = mu + mv;
    h.hit = u >= 0.0 && v >= 0.0 && w >= 0.0 && h.t > 0.0;
    h.grazing = h.t > 0.0 && (std::fabs(u) <= mu || std::fabs(v) <= mv || std::fabs(w) <= mw) &&
                u >= -mu && v >= -mv && w >= -mw;
    return h;
}

}  // namespace

ExactAnswer ExactTracer::trace(const rt::Ray& ray, float t_max, bool any_hit) const {
    const glm::dvec3 o(ray.origin), d(ray.dir);
    const double limit = t_max;
    ExactAnswer best;
    best.t = limit;
    double second = limit;  // the next-nearest hit, for ties between triangles
    for (const glm::uvec3& tri : mesh_.triangles) {
        const DoubleHit h =
            intersect(o, d, glm::dvec3(mesh_.positions[tri[0]]),
                      glm::dvec3(mesh_.positions[tri[1]]), glm::dvec3(mesh_.positions[tri[2]]));
        if (!h.hit && !h.grazing) continue;
        // Within float's rounding of the ray's start (its own scale, or the triangle's:
        // a ray leaving a box's wall by the ground it stands on), or of its end.
        const bool near_end = std::fabs(h.t) <= std::max(kTMargin * std::max(1.0, h.t), h.slack) ||
                              (std::isfinite(limit) && std::fabs(h.t - limit) <= kTMargin * limit);
        if (h.t >= limit * (1.0 + kTMargin)) continue;
        if (h.grazing || near_end) {
            best.ambiguous = true;
            if (!h.hit) continue;
        }
        if (!h.hit || h.t >= limit) continue;
        if (h.t < best.t) {
            second = best.t;
            best.t = h.t;
            best.slack = h.slack;
            best.hit = true;
        } else {
            second = std::min(second, h.t);
        }
        if (any_hit && !best.ambiguous) return best;
    }
    // Two surfaces within rounding of each other along the ray: either is first.
    if (best.hit && second - best.t <= kTMargin * best.t) best.ambiguous = true;
    return best;
}

bool ExactTracer::agrees(const ExactAnswer& exact, const Result& answer, bool occlusion) const {
    if (exact.ambiguous) return true;
    if (exact.hit != answer.hit()) return false;
    if (!exact.hit || occlusion) return true;
    return std::fabs(answer.t - exact.t) <= 1e-4 * std::max(exact.t, 1e-3) + exact.slack;
}

}  // namespace rt::bench
