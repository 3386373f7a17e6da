#include "core/scene.h"

#include <glm/geometric.hpp>

#include "core/triangle4.h"

namespace rt {
namespace {

template <class... F>
struct Overloaded : F... {
    using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;  // clang 14 does not deduce aggregates by itself

// Object-space hit test of one shape; updates hit.t (and prim, b1, b2) on a closer hit.
bool intersect_shape(const Scene& scene, const Shape& shape, const Ray& r, Hit& hit) {
    return std::visit(
        Overloaded{[&](const MeshRef& m) { return scene.meshes[m.mesh].intersect(r, hit); },
                   [&](const Triangle& tri) {
                       const auto h = intersect(tri, r, hit.t);
                       if (h) hit = Hit{h->t, hit.object, 0, h->b1, h->b2};
                       return h.has_value();
                   },
                   [&](const auto& analytic) {
                       // A sphere or plane has no triangle: the whole record is replaced,
                       // so no earlier mesh hit's triangle and barycentrics stay behind.
                       const auto t = intersect(analytic, r, hit.t);
                       if (t) hit = Hit{*t, hit.object, 0, 0.0f, 0.0f};
                       return t.has_value();
                   }},
        shape);
}

bool occluded_shape(const Scene& scene, const Shape& shape, const Ray& r, float t_max) {
    if (const auto* m = std::get_if<MeshRef>(&shape))
        return scene.meshes[m->mesh].occluded(r, t_max);
    Hit probe;
    probe.t = t_max;
    return intersect_shape(scene, shape, r, probe);
}

Ray object_ray(const Object& o, const Ray& r) {
    return o.transform ? o.transform->to_object(r) : r;
}

}  // namespace

Aabb Scene::object_bounds(const Object& o) const {
    Aabb box =
        std::visit(Overloaded{[&](const Sphere& s) {
                                  return Aabb{s.centre - vec3(s.radius), s.centre + vec3(s.radius)};
                              },
                              [&](const Triangle& t) {
                                  Aabb b;
                                  b.grow(t.a);
                                  b.grow(t.b);
                                  b.grow(t.c);
                                  return b;
                              },
                              [&](const MeshRef& m) { return meshes[m.mesh].bounds(); },
                              [&](const Plane&) { return Aabb{}; }},
                   o.shape);
    return o.transform ? box.transformed(o.transform->m) : box;
}

void Scene::build(AccelKind kind) {
    for (auto& mesh : meshes) mesh.build(kind);
    bounded_.clear();
    unbounded_.clear();
    std::vector<Aabb> boxes;
    for (std::uint32_t i = 0; i < objects.size(); ++i) {
        if (std::holds_alternative<Plane>(objects[i].shape)) {
            unbounded_.push_back(i);
            continue;
        }
        const Aabb box = object_bounds(objects[i]);
        if (box.empty()) continue;  // an empty mesh: nothing to hit
        bounded_.push_back(i);
        boxes.push_back(box);
    }
    top_.build(boxes, kind);
    std::vector<std::uint32_t> by_slot(bounded_.size());  // bounded_ is kept in slot order
    for (std::size_t slot = 0; slot < by_slot.size(); ++slot)
        by_slot[slot] = bounded_[top_.order()[slot]];
    bounded_ = std::move(by_slot);
}

bool Scene::intersect_object(std::uint32_t object, const Ray& r, Hit& hit) const {
    const Object& o = objects[object];
    if (!intersect_shape(*this, o.shape, object_ray(o, r), hit)) return false;
    hit.object = object;
    return true;
}

bool Scene::intersect_primitive(std::uint32_t object, std::uint32_t prim, const Ray& r,
                                Hit& hit) const {
    if (object >= objects.size()) return false;
    const Object& o = objects[object];
    const auto* m = std::get_if<MeshRef>(&o.shape);
    if (!m) return intersect_object(object, r, hit);
    const TriangleMesh& mesh = meshes[m->mesh];
    if (prim >= mesh.triangles.size()) return false;
    // The same watertight test (and t bound) that traversal uses, one lane of it: the
    // item buffer's pixels then get the very hit a full traversal would give.
    const glm::uvec3 idx = mesh.triangles[prim];
    Triangle4 pack{};
    pack.set(0, mesh.positions[idx[0]], mesh.positions[idx[1]], mesh.positions[idx[2]]);
    const Triangle4Hit h = rt::intersect(pack, ShearedRay(object_ray(o, r)), hit.t);
    if (h.lane != 0) return false;
    hit = Hit{h.t, object, prim, h.b1, h.b2};
    return true;
}

bool Scene::intersect(const Ray& r, Hit& hit) const {
    bool found = false;
    for (std::uint32_t i : unbounded_) found |= intersect_object(i, r, hit);
    found |= top_.traverse<false>(r, hit.t, [&](std::uint32_t slot, float&) {
        // hit.t is the traversal's t_max: intersect_object shortens it on a hit.
        return intersect_object(bounded_[slot], r, hit);
    });
    return found;
}

bool Scene::occluded(const Ray& r, float t_max) const {
    for (std::uint32_t i : unbounded_)
        if (occluded_shape(*this, objects[i].shape, object_ray(objects[i], r), t_max)) return true;
    return top_.traverse<true>(r, t_max, [&](std::uint32_t slot, float& t_limit) {
        const Object& o = objects[bounded_[slot]];
        return occluded_shape(*this, o.shape, object_ray(o, r), t_limit);
    });
}

SurfacePoint Scene::surface(const Ray& r, const Hit& hit) const {
    const Object& o = objects[hit.object];
    const Ray local = object_ray(o, r);
    SurfacePoint sp;
    sp.material = o.material;
    vec3 p = local.at(hit.t);
    vec3 ng, ns;
    std::visit(Overloaded{[&](const Sphere& s) {
                              // Project back onto the sphere: the point is then as exact as
                              // floats allow, which the ray offset relies on.
                              ng = glm::normalize(p - s.centre);
                              p = s.centre + s.radius * ng;
                              ns = ng;
                          },
                          [&](const Plane& pl) {
                              p -= (glm::dot(p, pl.normal) - pl.offset) * pl.normal;
                              ng = ns = pl.normal;
                          },
                          [&](const Triangle& tri) {
                              p = (1.0f - hit.b1 - hit.b2) * tri.a + hit.b1 * tri.b +
                                  hit.b2 * tri.c;
                              ng = ns = glm::cross(tri.b - tri.a, tri.c - tri.a);
                          },
                          [&](const MeshRef& m) {
                              const TriangleMesh& mesh = meshes[m.mesh];
                              p = mesh.point(hit);
                              ng = mesh.face_normal(hit.prim);
                              ns = mesh.shading_normal(hit);
                              if (m.own_materials && !mesh.materials.empty())
                                  sp.material = mesh.materials[hit.prim];
                          }},
               o.shape);

    sp.pattern_point = p;
    if (const auto* pl = std::get_if<Plane>(&o.shape)) {
        vec3 t1, t2;  // a plane's checker lies in the plane, not across it
        tangent_frame(pl->normal, t1, t2);
        sp.pattern_point = {glm::dot(p, t1), glm::dot(p, t2), 0.0f};
    }
    sp.pattern_point += pattern_shift(hit.object, sp.material);
    if (o.transform) {
        p = o.transform->point_to_world(p);
        ng = o.transform->normal_to_world(ng);
        ns = o.transform->normal_to_world(ns);
    } else {
        ng = glm::normalize(ng);
        ns = glm::normalize(ns);
    }
    sp.p = p;
    const bool front_face = glm::dot(r.dir, ng) < 0.0f;
    sp.geometric_normal = front_face ? ng : -ng;
    // An interpolated normal may lean past the silhouette; keep it on the viewer's side.
    ns = front_face ? ns : -ns;
    sp.normal = glm::dot(ns, sp.geometric_normal) > 0.0f ? ns : sp.geometric_normal;
    return sp;
}

vec3 Scene::pattern_shift(std::uint32_t object, std::uint32_t material) const {
    const Object& o = objects[object];
    const Material& m = materials[material];
    if (o.transform || !m.checker || origin == glm::dvec3(0.0)) return vec3(0.0f);
    if (const auto* pl = std::get_if<Plane>(&o.shape)) {
        vec3 t1, t2;
        tangent_frame(pl->normal, t1, t2);
        return m.checker->shift({glm::dot(origin, glm::dvec3(t1)), glm::dot(origin, glm::dvec3(t2)), 0.0});
    }
    return m.checker->shift(origin);
}

Aabb Scene::bounds() const {
    Aabb box;
    for (const Object& o : objects) box.grow(object_bounds(o));
    return box;
}

std::size_t Scene::triangle_count() const {
    std::size_t n = 0;
    for (const Object& o : objects) {
        if (std::holds_alternative<Triangle>(o.shape)) ++n;
        if (const auto* m = std::get_if<MeshRef>(&o.shape)) n += meshes[m->mesh].triangles.size();
    }
    return n;
}

std::size_t Scene::accel_memory_bytes() const {
    std::size_t bytes = top_.memory_bytes();
    for (const auto& mesh : meshes) bytes += mesh.memory_bytes();
    return bytes;
}

}  // namespace rt
