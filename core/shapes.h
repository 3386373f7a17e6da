#pragma once
// The tutorial's analytic shapes and their ray intersections, in object space.
// Each intersect() returns the smallest t in (0, t_max), or nothing.

#include <optional>

#include "core/ray.h"

namespace rt {

struct Sphere {
    vec3 centre{0.0f};
    float radius = 1.0f;
};

// The plane p . normal - offset = 0 (the tutorial's p . n - a = 0); normal is unit length.
struct Plane {
    vec3 normal{0.0f, 1.0f, 0.0f};
    float offset = 0.0f;
};

struct Triangle {
    vec3 a, b, c;
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

std::optional<float> intersect(const Plane& p, const Ray& r, float t_max);

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

// An orthonormal tangent pair for a unit normal (Duff et al., JCGT 2017); for the
// y-up plane it gives +x and +z, so checker squares line up with the axes.
void tangent_frame(const vec3& n, vec3& t1, vec3& t2);

}  // namespace rt
