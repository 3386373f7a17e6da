#include "core/scene.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstring>
#include <optional>
#include <type_traits>

#include <glm/geometric.hpp>

#include "core/shape_packets.h"
#include "core/triangle4.h"
#include "core/vec3_lanes.h"

namespace rt {

namespace {
// Up to this many bounded objects, none of them a mesh (tutorial's 2 spheres), a packet
// tests each of them on the lanes (intersect_among), not the objects' tree: frames 0.91x
// tutorial (probe, 20 frames a side). With a mesh among them it cost more than the tree
// saved (whitted 1.10x, textured 1.07x: the mesh's own tree walked for every packet).
// Not tuned: scenes of 3 to 100 spheres were not measured.
constexpr std::size_t kFewObjects = 6;

std::vector<TriangleMesh> built(std::vector<TriangleMesh> meshes, AccelKind kind) {
    for (auto& mesh : meshes) mesh.build(kind);
    return meshes;
}

}  // namespace

Aabb Scene::object_bounds(const Object& o) const {
    const Aabb box = visit_shape(o, [](const auto& shape) { return Aabb(shape.bounds()); });
    return o.transform ? box.transformed(o.transform->m) : box;
}

Scene::Scene(SceneDescription d, AccelKind kind, bool light_buffers)
    : camera(d.camera),
      background(d.background),
      ambient(d.ambient),
      origin(d.origin),
      lights(std::move(d.lights)),
      materials(std::move(d.materials)),
      meshes(built(std::move(d.meshes), kind)),
      objects(std::move(d.objects)),
      textures(std::move(d.textures)) {
    for (const Material& m : materials)
        if (m.texture && *m.texture >= textures.size())
            throw std::invalid_argument("Scene: material \"" + m.name + "\" names texture " +
                                        std::to_string(*m.texture) + " of " +
                                        std::to_string(textures.size()));
    std::vector<Aabb> boxes;
    plane_frames_.resize(objects.size());
    for (std::uint32_t i = 0; i < objects.size(); ++i) {
        if (const Plane* plane = std::get_if<Plane>(&objects[i].shape)) {
            tangent_frame(plane->normal, plane_frames_[i].t1, plane_frames_[i].t2);
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
    few_shapes_ = bounded_.size() <= kFewObjects &&
                  std::none_of(bounded_.begin(), bounded_.end(), [&](std::uint32_t object) {
                      return std::holds_alternative<MeshRef>(objects[object].shape);
                  });
    std::vector<Aabb> slot_boxes;
    for (const std::uint32_t object : bounded_)
        slot_boxes.push_back(object_bounds(objects[object]));
    // A buffer is 6 x 64 x 64 cells (200 kB) for a point light, 128 x 128 for a
    // directional one: the first kBufferedLights lights have one, the others' feelers
    // traverse the tree.
    constexpr std::size_t kBufferedLights = 64;
    std::size_t buffered = 0;
    for (const Light& light : lights) {
        if (light_buffers && buffered < kBufferedLights) {
            light_buffers_.push_back(LightBuffer::make(light, slot_boxes));
            ++buffered;
        } else {
            light_buffers_.emplace_back();
        }
    }
}

SceneDescription Scene::description() const {
    return {camera, background, ambient, origin, lights, materials, meshes, objects, textures};
}

bool Scene::intersect_object(std::uint32_t object, const Ray& r, Hit& hit) const {
    const Object& o = objects[object];
    Ray moved;
    const Ray& local = object_ray(o, r, moved);
    if (!visit_shape(o, [&](const auto& shape) { return shape.intersect(local, hit); }))
        return false;
    hit.object = object;
    return true;
}

bool Scene::intersect_primitive(std::uint32_t object, std::uint32_t prim, const Ray& r,
                                Hit& hit) const {
    if (object >= objects.size()) return false;
    const Object& o = objects[object];
    const auto* m = std::get_if<MeshRef>(&o.shape);
    if (!m) return intersect_object(object, r, hit);
    // The same watertight test (and t bound) that traversal uses, on the triangle's own
    // pack: the item buffer's pixels then get the very hit a full traversal would give.
    Ray moved;
    if (!meshes[m->mesh].intersect_triangle(prim, object_ray(o, r, moved), hit)) return false;
    hit.object = object;
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

unsigned Scene::intersect_object_packet(std::uint32_t object, const Ray* rays, Hit* hits,
                                        unsigned lanes) const {
    const Object& o = objects[object];
    const auto* m = std::get_if<MeshRef>(&o.shape);
    unsigned found = 0;
    if (m) {
        std::array<Ray, kPacketWidth> local;
        for (unsigned rest = lanes; rest != 0; rest &= rest - 1) {
            const unsigned lane = __builtin_ctz(rest);
            local[lane] = o.transform ? o.transform->to_object(rays[lane]) : rays[lane];
        }
        found = meshes[m->mesh].intersect_packet(local.data(), hits, lanes);
        for (unsigned rest = found; rest != 0; rest &= rest - 1)
            hits[__builtin_ctz(rest)].object = object;
        return found;
    }
    for (; lanes != 0; lanes &= lanes - 1) {
        const unsigned lane = __builtin_ctz(lanes);
        if (intersect_object(object, rays[lane], hits[lane])) found |= 1u << lane;
    }
    return found;
}

namespace {

// A shape's test across the rays of `lanes` (core/shape_packets.h), its hits taken into
// `best`; returns their bits.
template <class Shape>
unsigned shape_lanes(const Shape& shape, std::uint32_t object, const RayLanes<kPacketWidth>& r,
                     unsigned lanes, ClosestLanes& best) {
    LaneHits<kPacketWidth> out;
    out.t_max = best.t;
    const unsigned hit = intersect_lanes(shape, r, lanes, out);
    return hit != 0 ? best.take(hit, out, object) : 0;
}

// A shape's test across the rays of `lanes` (core/shape_packets.h); the hits replace
// the rays' records. Returns their bits.
template <class Shape>
unsigned shape_packet(const Shape& shape, std::uint32_t object, const RayLanes<kPacketWidth>& r,
                      Hit* hits, unsigned lanes, bool fresh) {
    LaneHits<kPacketWidth> out;
    out.t_max =
        fresh ? splat<Lanes<kPacketWidth>::Float>(kInfinity) : t_bounds<kPacketWidth>(hits, lanes);
    const unsigned hit = intersect_lanes(shape, r, lanes, out);
    if (fresh && lanes == (1u << kPacketWidth) - 1u) {
        // The whole packet is this object's: every record written, without a branch (a
        // loop over the hits' bits, its exit mispredicted, took 15-17 % of the item
        // buffer's primary step: tutorial, whitted at 1 thread).
#pragma GCC unroll 8
        for (int lane = 0; lane < kPacketWidth; ++lane) {
            const bool on = (hit >> lane) & 1u;
            hits[lane].t = on ? out.t[lane] : kInfinity;
            hits[lane].object = on ? object : kNoObject;
            if constexpr (std::is_same_v<Shape, Triangle>) {
                hits[lane].b1 = on ? out.b1[lane] : 0.0f;
                hits[lane].b2 = on ? out.b2[lane] : 0.0f;
            }
        }
        return hit;
    }
    for (unsigned rest = hit; rest != 0; rest &= rest - 1) {
        const unsigned lane = __builtin_ctz(rest);
        if constexpr (std::is_same_v<Shape, Triangle>) {
            hits[lane] = Hit{out.t[lane], object, 0, out.b1[lane], out.b2[lane]};
        } else if (fresh) {  // the rest of a fresh hit is already what it should be
            hits[lane].t = out.t[lane];
            hits[lane].object = object;
        } else {
            hits[lane] = Hit{out.t[lane], object, 0, 0.0f, 0.0f};  // no barycentrics
        }
    }
    return hit;
}

// The plane's test for the rays of `lanes` (intersect_lanes' arithmetic): in every camera
// packet of a scene with a floor. (A RayLanes gathered by gather instructions or through
// memory cost the primary step 4 to 10 %, tutorial, interleaved runs; it is now read as
// rows and transposed.)
unsigned plane_packet(const Plane& p, std::uint32_t object, const Ray* rays, Hit* hits,
                      unsigned lanes) {
    using Float = Lanes<kPacketWidth>::Float;
    const RayLanes<kPacketWidth> r = RayLanes<kPacketWidth>::gather(rays, lanes);
    const auto dot_n = [&](const Float* v) {  // glm::dot's order: (x + y) + z
        return (v[0] * p.normal[0] + v[1] * p.normal[1]) + v[2] * p.normal[2];
    };
    const Float d_dot_n = dot_n(r.dir), o_dot_n = dot_n(r.origin);
    const Float t_max = t_bounds<kPacketWidth>(hits, lanes);
    const Float zero = splat<Float>(0.0f);
    const Float t = (splat<Float>(p.offset) - o_dot_n) / d_dot_n;
    const unsigned hit = bits((d_dot_n != zero) & (t > zero) & (t < t_max)) & lanes;
    for (unsigned rest = hit; rest != 0; rest &= rest - 1) {
        const unsigned lane = __builtin_ctz(rest);
        hits[lane] = Hit{t[lane], object, 0, 0.0f, 0.0f};
    }
    return hit;
}

}  // namespace

unsigned Scene::analytic_lanes(std::uint32_t object, const RayLanes<kPacketWidth>& world,
                               unsigned lanes, ClosestLanes& best) const {
    const Object& o = objects[object];
    RayLanes<kPacketWidth> local;
    if (o.transform) local = world.to_object(*o.transform);
    const RayLanes<kPacketWidth>& rays = o.transform ? local : world;
    if (const auto* plane = std::get_if<Plane>(&o.shape))
        return shape_lanes(*plane, object, rays, lanes, best);
    if (const auto* sphere = std::get_if<Sphere>(&o.shape))
        return shape_lanes(*sphere, object, rays, lanes, best);
    return shape_lanes(std::get<Triangle>(o.shape), object, rays, lanes, best);
}

unsigned Scene::intersect_primitive_packet(std::uint32_t object, const std::uint32_t* prims,
                                           const RayLanes<kPacketWidth>& world, Hit* hits,
                                           unsigned lanes, bool fresh) const {
    if (object >= objects.size() || lanes == 0) return 0;
    const Object& o = objects[object];
    RayLanes<kPacketWidth> local;
    if (o.transform) local = world.to_object(*o.transform);
    const RayLanes<kPacketWidth>& rays = o.transform ? local : world;
    if (const auto* plane = std::get_if<Plane>(&o.shape))
        return shape_packet(*plane, object, rays, hits, lanes, fresh);
    if (const auto* sphere = std::get_if<Sphere>(&o.shape))
        return shape_packet(*sphere, object, rays, hits, lanes, fresh);
    if (const auto* triangle = std::get_if<Triangle>(&o.shape))
        return shape_packet(*triangle, object, rays, hits, lanes, fresh);
    const auto& mesh = meshes[std::get<MeshRef>(o.shape).mesh];
    const unsigned found = mesh.intersect_triangles_packet(prims, rays, hits, lanes);
    for (unsigned rest = found; rest != 0; rest &= rest - 1)
        hits[__builtin_ctz(rest)].object = object;
    return found;
}

// Inlined into intersect_packet: every camera packet of a scene with a floor calls it.
[[gnu::always_inline]] inline unsigned Scene::intersect_unbounded_packet(const Ray* rays, Hit* hits,
                                                                         unsigned active) const {
    unsigned found = 0;
    for (std::uint32_t i : unbounded_) {
        const Object& o = objects[i];
        if (const auto* plane = std::get_if<Plane>(&o.shape); plane && !o.transform && active) {
            found |= plane_packet(*plane, i, rays, hits, active);
            continue;
        }
        for (unsigned rest = active; rest != 0; rest &= rest - 1) {
            const unsigned lane = __builtin_ctz(rest);
            if (intersect_object(i, rays[lane], hits[lane])) found |= 1u << lane;
        }
    }
    return found;
}

unsigned Scene::intersect_among(const std::uint32_t* among, int count,
                                const RayLanes<kPacketWidth>& rays, Hit* hits,
                                unsigned lanes) const {
    lanes &= (1u << kPacketWidth) - 1u;
    if (lanes == 0) return 0;
    unsigned found = 0;
    // The rays' closest hits as lanes while planes, spheres and triangles are tested; in
    // their records while a mesh's tree is walked, with the rays as Rays (made for each
    // mesh met, mesh_among: made, or even default-constructed, in every call, they and an
    // optional ClosestLanes were most of the 6 % of the item buffer's step's instructions
    // that this saved on many_spheres, whose edges call this for two or three spheres).
    ClosestLanes best;
    bool open = false;  // best holds hits not yet written to their records
    for (int k = 0; k < count; ++k) {
        const std::uint32_t object = among[k];
        if (object >= objects.size()) continue;
        if (!std::holds_alternative<MeshRef>(objects[object].shape)) {
            if (!open) best = ClosestLanes::within(hits, lanes), open = true;
            found |= analytic_lanes(object, rays, lanes, best);
            continue;
        }
        if (open) best.write(hits), open = false;
        found |= mesh_among(object, rays, hits, lanes);
    }
    if (open) best.write(hits);
    return found;
}

// A mesh's tree walked for the rays of `lanes` (Scene::intersect_among's), as Rays.
unsigned Scene::mesh_among(std::uint32_t object, const RayLanes<kPacketWidth>& rays, Hit* hits,
                           unsigned lanes) const {
    std::array<Ray, kPacketWidth> as_rays;
    for (unsigned rest = lanes; rest != 0; rest &= rest - 1)
        as_rays[__builtin_ctz(rest)] = rays.lane(__builtin_ctz(rest));
    return intersect_object_packet(object, as_rays.data(), hits, lanes);  // its own tree
}

unsigned Scene::intersect_packet(const Ray* rays, Hit* hits, unsigned active) const {
    active &= (1u << kPacketWidth) - 1u;
    unsigned found = intersect_unbounded_packet(rays, hits, active);
    if (few_shapes_) {
        unsigned finite = 0;  // as the tree: a ray that is not finite meets no bounded object
        for (unsigned rest = active; rest != 0; rest &= rest - 1)
            if (finite_ray(rays[__builtin_ctz(rest)])) finite |= rest & -rest;
        if (finite == 0) return found;
        return found | intersect_among(bounded_.data(), static_cast<int>(bounded_.size()),
                                       RayLanes<kPacketWidth>::gather(rays, finite), hits, finite);
    }
    std::array<float, kPacketWidth> t_max;
    for (unsigned rest = active; rest != 0; rest &= rest - 1) {
        const unsigned lane = __builtin_ctz(rest);
        t_max[lane] = hits[lane].t;
    }
    // A plane, sphere or triangle that two or more of the rays meet tests them on the
    // lanes (the rays gathered into lanes at the first such object), not one by one.
    std::optional<RayLanes<kPacketWidth>> as_lanes;
    top_.traverse_packet<false>(
        rays, t_max.data(), active, [&](std::uint32_t first, std::uint32_t count, unsigned lanes) {
            unsigned hit = 0;
            for (std::uint32_t slot = first; slot < first + count; ++slot) {
                const std::uint32_t object = bounded_[slot];
                if (std::popcount(lanes) < 2 ||
                    std::holds_alternative<MeshRef>(objects[object].shape)) {
                    hit |= intersect_object_packet(object, rays, hits, lanes);
                    continue;
                }
                if (!as_lanes) as_lanes = RayLanes<kPacketWidth>::gather(rays, active);
                hit |= intersect_primitive_packet(object, nullptr, *as_lanes, hits, lanes);
            }
            for (unsigned rest = hit; rest != 0; rest &= rest - 1) {
                const unsigned lane = __builtin_ctz(rest);
                t_max[lane] = hits[lane].t;  // the traversal's bound follows each hit
            }
            found |= hit;
            return hit;
        });
    return found;
}

void Scene::surface(const Ray& r, const Hit& hit, SurfacePoint& sp) const {
    const Object& o = objects[hit.object];
    Ray moved;
    const Ray& local = object_ray(o, r, moved);
    Convex convex = Convex::kNo;
    const LocalSurface ls = visit_shape(o, [&](const auto& shape) {
        using Kind = std::decay_t<decltype(shape)>;
        convex = Kind::kConvex;
        const LocalSurface s = shape.surface(local, hit);
        // A checker lies in the shape's own frame (a plane's), before the transform.
        if constexpr (std::is_same_v<Kind, Plane>) {
            const PlaneFrame& f = plane_frames_[hit.object];  // Plane::pattern_point's
            sp.pattern_point = vec3(glm::dot(s.p, f.t1), glm::dot(s.p, f.t2), 0.0f);
        } else {
            sp.pattern_point = shape.pattern_point(s.p);
        }
        return s;
    });
    sp.material = ls.material.value_or(o.material);
    sp.uv = ls.uv;
    sp.colour = ls.colour;
    if (origin != glm::dvec3(0.0))  // the usual case skips the call: 2 % of a Whitted frame
        sp.pattern_point += pattern_shift(hit.object, sp.material);
    // A plane's and a sphere's two normals are one: normalised once.
    const bool one_normal = std::memcmp(&ls.normal, &ls.geometric_normal, sizeof(vec3)) == 0;
    vec3 p = ls.p, ng = ls.geometric_normal, ns = ls.normal;
    if (o.transform) {
        p = o.transform->point_to_world(p);
        ng = o.transform->normal_to_world(ng);
        ns = one_normal ? ng : o.transform->normal_to_world(ns);
    } else {
        ng = glm::normalize(ng);
        ns = one_normal ? ng : glm::normalize(ns);
    }
    sp.p = p;
    const bool front_face = glm::dot(r.dir, ng) < 0.0f;
    sp.geometric_normal = front_face ? ng : -ng;
    const bool leaves = convex == Convex::kFlat || (convex == Convex::kOutside && front_face);
    sp.cannot_meet_again = leaves ? hit.object : kNoObject;
    // An interpolated normal may lean past the silhouette; keep it on the viewer's side.
    ns = front_face ? ns : -ns;
    sp.normal = glm::dot(ns, sp.geometric_normal) > 0.0f ? ns : sp.geometric_normal;
}

bool Scene::plane_surfaces(const Ray* rays, const Hit* hits, const std::uint32_t* which, int n,
                           SurfacePoint* out) const {
    using Lanes3 = Vec3Lanes<kPacketWidth>;
    using Float = Lanes3::Float;
    const std::uint32_t object = hits[which[0]].object;
    const Object& o = objects[object];
    const Plane* plane = std::get_if<Plane>(&o.shape);
    if (!plane || o.transform) return false;
    for (int k = 1; k < n; ++k)
        if (hits[which[k]].object != object) return false;
    // A ray's origin and direction as rows of four floats: the origin and the direction's
    // x; the origin's z and the direction.
    static_assert(offsetof(Ray, dir) == 3 * sizeof(float));
    std::array<const float*, kPacketWidth> origins, dirs;
    Float t;
    for (int lane = 0; lane < kPacketWidth; ++lane) {
        const std::uint32_t i = which[lane < n ? lane : 0];
        origins[lane] = &rays[i].origin.x;
        dirs[lane] = &rays[i].origin.z;
        t[lane] = hits[i].t;
    }
    const Lanes3 from = Lanes3::transpose(origins, 0), dir = Lanes3::transpose(dirs, 1);
    // Plane::surface, then Scene::surface's steps for a plane.
    const Lanes3 normal = Lanes3::splat(plane->normal);
    Lanes3 p = from + dir * t;
    p = p - normal * (dot(p, normal) - splat<Float>(plane->offset));
    const PlaneFrame& f = plane_frames_[object];
    Lanes3 pattern{dot(p, Lanes3::splat(f.t1)), dot(p, Lanes3::splat(f.t2)), splat<Float>(0.0f)};
    if (origin != glm::dvec3(0.0))
        pattern = pattern + Lanes3::splat(pattern_shift(object, o.material));
    const vec3 unit = glm::normalize(plane->normal);
    const unsigned front = bits(dot(dir, Lanes3::splat(unit)) < splat<Float>(0.0f));
    for (int k = 0; k < n; ++k) {
        SurfacePoint& sp = out[k];
        sp = SurfacePoint{};
        sp.p = p.get(k);
        sp.geometric_normal = sp.normal = (front >> k) & 1u ? unit : -unit;
        sp.material = o.material;
        sp.pattern_point = pattern.get(k);
        sp.cannot_meet_again = object;
    }
    return true;
}

vec3 Scene::pattern_shift(std::uint32_t object, std::uint32_t material) const {
    const Object& o = objects[object];
    const Material& m = materials[material];
    if (o.transform || !m.checker || origin == glm::dvec3(0.0)) return vec3(0.0f);
    return m.checker->shift(
        visit_shape(o, [&](const auto& shape) { return shape.pattern_point(origin); }));
}

Aabb Scene::bounds() const {
    Aabb box;
    for (const Object& o : objects) box.grow(object_bounds(o));
    return box;
}

std::size_t Scene::triangle_count() const {
    std::size_t n = 0;
    for (const Object& o : objects)
        n += visit_shape(o, [](const auto& shape) { return shape.triangle_count(); });
    return n;
}

std::size_t Scene::accel_memory_bytes() const {
    std::size_t bytes = top_.memory_bytes();
    for (const auto& mesh : meshes) bytes += mesh.memory_bytes();
    return bytes;
}

}  // namespace rt
