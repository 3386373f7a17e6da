#pragma once
// The tutorial's analytic shapes, each with everything the scene asks of a shape, in
// one place and in the shape's own (object) space:
//   bounds()        its box (empty for the unbounded plane, which every ray tests);
//   intersect(r, h) the closest hit in (0, h.t): replaces h's record but h.object;
//   occluded(r, t)  any hit in (0, t): the shadow feeler's question;
//   surface(r, h)   the point and normals of a hit (LocalSurface);
//   pattern_point() where a checker is evaluated for a point of the surface;
//   triangle_count()
//   kConvex         a ray leaving its outside cannot meet it again: kFlat, either side
//                   (planes, triangles), kOutside (spheres, under any transform), or
//                   kNo (meshes); shadow feelers skip the shape they leave where they can.
// A mesh instance (core/mesh.h, MeshInstance) offers the same. The free intersect()
// functions below are the tutorial's formulas, each returning the smallest t in
// (0, t_max), or nothing. Adding a shape: docs/architecture.md.

#include <cstdint>
#include <optional>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/aabb.h"
#include "core/hit.h"
#include "core/ray.h"

namespace rt {

// An orthonormal tangent pair for a unit normal (Duff et al., JCGT 2017); for the
// y-up plane it gives +x and +z, so checker squares line up with the axes.
void tangent_frame(const vec3& n, vec3& t1, vec3& t2);

// A hit's surface in the shape's own space, before the object's transform. Normals
// need not be unit length nor face the ray; Scene::surface does both.
enum class Convex { kNo, kOutside, kFlat };

struct LocalSurface {
    vec3 p{0.0f};
    vec3 geometric_normal{0.0f, 1.0f, 0.0f};
    vec3 normal{0.0f, 1.0f, 0.0f};
    std::optional<std::uint32_t> material;  // a mesh's own material for the hit triangle
    glm::vec2 uv{0.0f};                     // texture coordinates (meshes that have them)
    vec3 colour{1.0f};                      // vertex colour (meshes that have them)
};

struct Sphere {
    static constexpr Convex kConvex = Convex::kOutside;
    vec3 centre{0.0f};
    float radius = 1.0f;

    Aabb bounds() const { return Aabb{centre - vec3(radius), centre + vec3(radius)}; }
    bool intersect(const Ray& r, Hit& hit) const;
    bool occluded(const Ray& r, float t_max) const;
    LocalSurface surface(const Ray& r, const Hit& hit) const;
    template <class V>
    V pattern_point(const V& p) const {
        return p;
    }
    std::size_t triangle_count() const { return 0; }
};

// The plane p . normal - offset = 0 (the tutorial's p . n - a = 0); normal is unit length.
struct Plane {
    static constexpr Convex kConvex = Convex::kFlat;
    vec3 normal{0.0f, 1.0f, 0.0f};
    float offset = 0.0f;

    Aabb bounds() const { return Aabb{}; }  // unbounded
    bool intersect(const Ray& r, Hit& hit) const;
    bool occluded(const Ray& r, float t_max) const;
    LocalSurface surface(const Ray& r, const Hit& hit) const;
    // A plane's checker lies in the plane, not across it: the point in the plane's frame.
    template <class V>
    V pattern_point(const V& p) const {
        vec3 t1, t2;
        tangent_frame(normal, t1, t2);
        return V(glm::dot(p, V(t1)), glm::dot(p, V(t2)), 0);
    }
    std::size_t triangle_count() const { return 0; }
};

struct Triangle {
    static constexpr Convex kConvex = Convex::kFlat;
    vec3 a, b, c;

    Aabb bounds() const;
    bool intersect(const Ray& r, Hit& hit) const;
    bool occluded(const Ray& r, float t_max) const;
    LocalSurface surface(const Ray& r, const Hit& hit) const;
    template <class V>
    V pattern_point(const V& p) const {
        return p;
    }
    std::size_t triangle_count() const { return 1; }
};

// The three cases of the sphere's discriminant B^2 - 4AC.
enum class SphereCase { kMiss, kGraze, kTwoRoots };

struct SphereRoots {
    SphereCase kind = SphereCase::kMiss;
    float t1 = kInfinity;  // entry (t1 <= t2)
    float t2 = kInfinity;  // exit
};

// Solves |o + d t - c|^2 = r^2 with A = d.d, B = 2 (o - c).d, C = |o - c|^2 - r^2.
// The discriminant is evaluated in the equivalent form 4A (r^2 - |f - (f.d/A) d|^2),
// f = o - c, which does not cancel catastrophically for distant spheres
// (Haines et al., "Precision Improvements for Ray/Sphere Intersection", RT Gems ch. 7).
SphereRoots solve_sphere(const Sphere& s, const Ray& r);
std::optional<float> intersect(const Sphere& s, const Ray& r, float t_max);

// Inline, as the plane's questions below: every ray of a scene with a floor asks them.
inline std::optional<float> intersect(const Plane& p, const Ray& r, float t_max) {
    // t = (a - eye.n) / (d.n); a ray parallel to the plane never meets it.
    const float d_dot_n = glm::dot(r.dir, p.normal);
    if (d_dot_n == 0.0f) return std::nullopt;
    const float t = (p.offset - glm::dot(r.origin, p.normal)) / d_dot_n;
    if (t > 0.0f && t < t_max) return t;
    return std::nullopt;
}

namespace detail {
// A sphere or plane has no triangle: the whole record is replaced, so no earlier mesh
// hit's triangle and barycentrics stay behind.
template <class Analytic>
bool replace_hit(const Analytic& shape, const Ray& r, Hit& hit) {
    const auto t = rt::intersect(shape, r, hit.t);
    if (t) hit = Hit{*t, hit.object, 0, 0.0f, 0.0f};
    return t.has_value();
}
}  // namespace detail

inline bool Plane::intersect(const Ray& r, Hit& hit) const {
    return detail::replace_hit(*this, r, hit);
}
inline bool Plane::occluded(const Ray& r, float t_max) const {
    return rt::intersect(*this, r, t_max).has_value();
}

struct TriangleHit {
    float t;
    float b1;  // barycentric weight of b
    float b2;  // barycentric weight of c
};

// The tutorial's test: the hit on the supporting plane, then three edge tests
// ((B-A) x (p-A)).n, ((C-B) x (p-B)).n, ((A-C) x (p-C)).n that must share a sign.
// The edge values, divided by n.n, are the barycentric coordinates.
std::optional<TriangleHit> intersect_triangle(const vec3& a, const vec3& b, const vec3& c,
                                              const Ray& r, float t_max);
inline std::optional<TriangleHit> intersect(const Triangle& tri, const Ray& r, float t_max) {
    return intersect_triangle(tri.a, tri.b, tri.c, r, t_max);
}

}  // namespace rt
