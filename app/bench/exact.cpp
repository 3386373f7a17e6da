#include "app/bench/exact.h"

#include <algorithm>
#include <cmath>

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
    // How far t may be off in a float test and still be right: the triangle's corners are
    // rounded to floats relative to the ray's origin, so the plane a float test meets may
    // lie kTMargin of their distance from the origin away from the exact one, which moves
    // t by that over the ray's speed towards the plane (a ground 120 units wide met 1e-3
    // from a ray's start: 4e-6 apart, 1e-4 of t).
    double slack = 0.0;
};

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
    h.slack = kTMargin * corners * glm::length(e1) * glm::length(e2) / std::fabs(det);
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
