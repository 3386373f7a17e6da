#include "core/shapes.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace rt {

SphereRoots solve_sphere(const Sphere& s, const Ray& r) {
    const vec3 f = r.origin - s.centre;
    const float A = glm::dot(r.dir, r.dir);
    const float f_dot_d = glm::dot(f, r.dir);
    const float B = 2.0f * f_dot_d;
    const float C = glm::dot(f, f) - s.radius * s.radius;
    const vec3 closest = f - (f_dot_d / A) * r.dir;  // f minus its projection on d
    const float discriminant = 4.0f * A * (s.radius * s.radius - glm::dot(closest, closest));

    SphereRoots roots;
    if (!(discriminant > 0.0f)) {  // also catches NaN from a degenerate ray
        roots.kind = discriminant == 0.0f ? SphereCase::kGraze : SphereCase::kMiss;
        return roots;
    }
    // t = (-B +- sqrt(B^2 - 4AC)) / 2A, with the root of larger magnitude computed first
    // and the other from t1 t2 = C / A, so neither suffers cancellation.
    const float q = -0.5f * (B + std::copysign(std::sqrt(discriminant), B));
    const float ta = q / A;
    const float tb = q != 0.0f ? C / q : -ta;
    roots.kind = SphereCase::kTwoRoots;
    roots.t1 = std::min(ta, tb);
    roots.t2 = std::max(ta, tb);
    return roots;
}

std::optional<float> intersect(const Sphere& s, const Ray& r, float t_max) {
    const SphereRoots roots = solve_sphere(s, r);
    if (roots.kind != SphereCase::kTwoRoots) return std::nullopt;  // a graze counts as a miss
    if (roots.t1 > 0.0f && roots.t1 < t_max) return roots.t1;
    if (roots.t2 > 0.0f && roots.t2 < t_max) return roots.t2;  // origin inside the sphere
    return std::nullopt;
}

std::optional<TriangleHit> intersect_triangle(const vec3& a, const vec3& b, const vec3& c,
                                              const Ray& r, float t_max) {
    const vec3 n = glm::cross(b - a, c - a);
    const float d_dot_n = glm::dot(r.dir, n);
    if (d_dot_n == 0.0f) return std::nullopt;  // parallel, or a degenerate triangle
    const float t = glm::dot(a - r.origin, n) / d_dot_n;
    if (!(t > 0.0f && t < t_max)) return std::nullopt;

    const vec3 p = r.at(t);
    const float edge_ab = glm::dot(glm::cross(b - a, p - a), n);
    const float edge_bc = glm::dot(glm::cross(c - b, p - b), n);
    const float edge_ca = glm::dot(glm::cross(a - c, p - c), n);
    // All three share the sign of n.n > 0 when p is inside; zero (on an edge) counts.
    if (edge_ab < 0.0f || edge_bc < 0.0f || edge_ca < 0.0f) return std::nullopt;
    const float inv_nn = 1.0f / glm::dot(n, n);
    return TriangleHit{t, edge_ca * inv_nn, edge_ab * inv_nn};
}

// --- each shape's part of the scene's questions --------------------------------------
bool Sphere::intersect(const Ray& r, Hit& hit) const { return detail::replace_hit(*this, r, hit); }

bool Sphere::occluded(const Ray& r, float t_max) const {
    return rt::intersect(*this, r, t_max).has_value();
}

LocalSurface Sphere::surface(const Ray& r, const Hit& hit) const {
    // Projected back onto the sphere: the point is then as exact as floats allow, which
    // the ray offset relies on.
    const vec3 n = glm::normalize(r.at(hit.t) - centre);
    return LocalSurface{centre + radius * n, n, n, std::nullopt, glm::vec2(0.0f), vec3(1.0f)};
}

LocalSurface Plane::surface(const Ray& r, const Hit& hit) const {
    vec3 p = r.at(hit.t);
    p -= (glm::dot(p, normal) - offset) * normal;  // back onto the plane
    return LocalSurface{p, normal, normal, std::nullopt, glm::vec2(0.0f), vec3(1.0f)};
}

Aabb Triangle::bounds() const {
    Aabb box;
    box.grow(a);
    box.grow(b);
    box.grow(c);
    return box;
}

bool Triangle::intersect(const Ray& r, Hit& hit) const {
    const auto h = rt::intersect(*this, r, hit.t);
    if (h) hit = Hit{h->t, hit.object, 0, h->b1, h->b2};
    return h.has_value();
}

bool Triangle::occluded(const Ray& r, float t_max) const {
    return rt::intersect(*this, r, t_max).has_value();
}

LocalSurface Triangle::surface(const Ray&, const Hit& hit) const {
    const vec3 n = glm::cross(b - a, c - a);
    return LocalSurface{(1.0f - hit.b1 - hit.b2) * a + hit.b1 * b + hit.b2 * c, n, n, std::nullopt,
                        glm::vec2(0.0f)};
}

void tangent_frame(const vec3& n, vec3& t1, vec3& t2) {
    // Duff et al. build the frame around z; with y and z swapped it is built around y.
    const vec3 m{n.x, n.z, n.y};
    const float sign = std::copysign(1.0f, m.z);
    const float a = -1.0f / (sign + m.z);
    const float b = m.x * m.y * a;
    const vec3 s1{1.0f + sign * m.x * m.x * a, sign * b, -sign * m.x};
    const vec3 s2{b, sign + m.y * m.y * a, -m.y};
    t1 = {s1.x, s1.z, s1.y};
    t2 = {s2.x, s2.z, s2.y};
}

}  // namespace rt
