#pragma once
// Everything one frame needs, in two types. A SceneDescription is plain data (camera,
// lights, materials, meshes and the objects that place shapes in the world): what a
// loader reads and a test assembles, edited freely. A Scene is a description built for
// tracing: its constructor makes the acceleration structures, and from then on it is
// read-only (its data is const) and safe to share between threads.

#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core/accel.h"
#include "core/camera.h"
#include "core/hit.h"
#include "core/light.h"
#include "core/light_buffer.h"
#include "core/material.h"
#include "core/mesh.h"
#include "core/shapes.h"
#include "core/texture.h"
#include "core/transform.h"

namespace rt {

struct MeshRef {
    std::uint32_t mesh = 0;     // index into Scene::meshes
    bool own_materials = true;  // use the mesh's per-triangle materials (else the object's)
};

using Shape = std::variant<Sphere, Plane, Triangle, MeshRef>;

struct Object {
    std::string name;
    Shape shape;
    std::uint32_t material = 0;  // for meshes: used where the mesh names no material
    std::optional<Transform> transform;
};

// The ray in o's own space: r itself where o has no transform, else r moved into `moved`
// (Transform::to_object's second form). Not a copy of r: a Ray copied whole is stored as
// 16 + 8 bytes, and the shapes read its direction's x and y back as 8 bytes across the
// two, which the store buffer cannot forward, so the load waited for both stores to
// retire (Plane::surface was 14 % of a Whitted frame).
inline const Ray& object_ray(const Object& o, const Ray& r, Ray& moved) {
    if (!o.transform) return r;
    o.transform->to_object(r, moved);
    return moved;
}

struct SceneDescription {
    Camera camera;
    vec3 background{0.0f};
    vec3 ambient{0.1f};  // the tutorial's I_a
    // Where the scene's zero lies in the file's world: a loader reads a far-away scene
    // relative to a point of its own (core/scene_loader.h). Everything here is relative
    // to it; checker patterns of shapes without a transform are laid in the file's world.
    glm::dvec3 origin{0.0};
    std::vector<Light> lights;
    std::vector<Material> materials;
    std::vector<TriangleMesh> meshes;  // the Scene builds them
    std::vector<Object> objects;
    std::vector<Texture> textures;  // Material::texture indexes them
};

struct ClosestLanes;  // core/shape_packets.h

class Scene {
  public:
    // Builds every mesh's structure and the one over the objects, with `kind`, and with
    // `light_buffers` each light's buffer (core/light_buffer.h; without, every feeler
    // walks the objects' tree: the same answers, slower).
    explicit Scene(SceneDescription description, AccelKind kind = AccelKind::kBvh,
                   bool light_buffers = true);
    // Built once and shared (by reference or shared_ptr), never copied or moved: the
    // const data below says "read-only" in the type.
    Scene(const Scene&) = delete;
    Scene& operator=(const Scene&) = delete;

    const Camera camera;
    const vec3 background;
    const vec3 ambient;
    const glm::dvec3 origin;
    const std::vector<Light> lights;
    const std::vector<Material> materials;
    const std::vector<TriangleMesh> meshes;  // built
    const std::vector<Object> objects;
    const std::vector<Texture> textures;

    AccelKind accel_kind() const { return top_.kind(); }
    // The description this scene was built from (a copy): to change a scene, change
    // its description and build a new one.
    SceneDescription description() const;

    // Closest hit in (0, hit.t); hit.t may be preset to limit the search.
    bool intersect(const Ray& r, Hit& hit) const;
    // The same for up to kPacketWidth neighbouring rays at once (rays[lane], hits[lane]
    // for each bit of `active`), traced together through the objects' and the meshes'
    // wide BVHs (core/wide_bvh_packet.h): each gets the hit intersect() gives it (of two
    // at the very same t, either). Returns the bits of the rays that hit.
    unsigned intersect_packet(const Ray* rays, Hit* hits, unsigned active) const;
    // Any hit in (0, t_max): the shadow feeler's question.
    bool occluded(const Ray& r, float t_max) const;
    // The same for a feeler to lights[light] (Light::feeler) from a surface point of
    // object `leaving` that the feeler cannot meet again (SurfacePoint::cannot_meet_again),
    // which is not tested. A point light's feelers test the objects of their light
    // buffer cell (core/light_buffer.h), not the tree.
    bool occluded(const Ray& feeler, float t_max, std::size_t light,
                  std::uint32_t leaving = kNoObject) const;
    // The same for up to kPacketWidth feelers to lights[light] at once (feelers[lane],
    // t_max[lane] and leaving[lane] for each bit of `active`): each gets the answer it
    // gets alone. Their light buffer cells are
    // found on SIMD lanes, and two or more feelers meeting a plane, sphere or triangle
    // test it on the lanes. Returns the bits of those blocked.
    unsigned occluded_packet(const RayLanes<kPacketWidth>& feelers, const float* t_max,
                             std::size_t light, const std::uint32_t* leaving,
                             unsigned active) const;
    // The closest hit among `count` objects (indices) for the rays of `lanes` (lanes of
    // `rays`, hits[lane], each within its hits[lane].t): where a ray's closest object is
    // among them, the hit intersect() gives. The item buffer's pixels on an edge test the
    // objects named around them so. Returns the bits of those that hit.
    unsigned intersect_among(const std::uint32_t* objects, int count,
                             const RayLanes<kPacketWidth>& rays, Hit* hits, unsigned lanes) const;
    // One object alone.
    bool intersect_object(std::uint32_t object, const Ray& r, Hit& hit) const;
    // One object, and of a mesh one triangle alone: what the item buffer names.
    bool intersect_primitive(std::uint32_t object, std::uint32_t prim, const Ray& r,
                             Hit& hit) const;
    // The same for the rays of `lanes` (lanes of `rays`, hits[lane], triangle
    // prims[lane]) at once, each with its own test's arithmetic (core/shape_packets.h):
    // the item buffer's pixels that name one object. Returns the bits of those that hit.
    // `fresh`: the hits of `lanes` are Hit{}, so a plane's, sphere's or triangle's test
    // takes infinity as their bound instead of gathering it from them (the item buffer's
    // interior pixels: primary rays with it 0.92-0.96x of the time on the analytic scenes).
    unsigned intersect_primitive_packet(std::uint32_t object, const std::uint32_t* prims,
                                        const RayLanes<kPacketWidth>& rays, Hit* hits,
                                        unsigned lanes, bool fresh = false) const;

    // The surface point of a hit (r's, of hits[..] from intersect), written into `sp`,
    // every field: where the caller keeps it (a SurfacePoint returned and copied out was
    // read back whole over the callee's smaller stores, which the store buffer cannot
    // forward: 12 % of Tracer::shade_found's samples).
    void surface(const Ray& r, const Hit& hit, SurfacePoint& sp) const;
    SurfacePoint surface(const Ray& r, const Hit& hit) const {
        SurfacePoint sp;
        surface(r, hit, sp);
        return sp;
    }
    // surface for rays[which[k]] and hits[which[k]], k < n (1 to kPacketWidth), where every
    // hit is on one plane without a transform (a floor's run of pixels), across SIMD
    // lanes: bit for bit what surface gives. False, and nothing written, for other hits.
    bool plane_surfaces(const Ray* rays, const Hit* hits, const std::uint32_t* which, int n,
                        SurfacePoint* out) const;
    // What a checker of `material` on object `object` adds to its pattern point so that
    // the pattern lies where the file put it (Checker::shift of the origin); zero for
    // objects with a transform, whose pattern lies in their own coordinates.
    vec3 pattern_shift(std::uint32_t object, std::uint32_t material) const;

    Aabb bounds() const;  // of the bounded objects (planes are left out)
    std::size_t triangle_count() const;
    std::size_t accel_memory_bytes() const;

    // Calls f with the object's shape, a mesh reference resolved to its MeshInstance, so
    // that f sees the one interface every shape has (core/shapes.h).
    template <class F>
    decltype(auto) visit_shape(const Object& o, F&& f) const;
    // The object's box in the scene (empty for planes).
    Aabb object_bounds(const Object& o) const;

  private:
    // A plane's, sphere's or triangle's test (object `object`) for the rays of `lanes`,
    // its hits taken into `best`; returns their bits.
    unsigned analytic_lanes(std::uint32_t object, const RayLanes<kPacketWidth>& world,
                            unsigned lanes, ClosestLanes& best) const;
    unsigned intersect_unbounded_packet(const Ray* rays, Hit* hits, unsigned active) const;
    unsigned mesh_among(std::uint32_t object, const RayLanes<kPacketWidth>& rays, Hit* hits,
                        unsigned lanes) const;
    unsigned intersect_object_packet(std::uint32_t object, const Ray* rays, Hit* hits,
                                     unsigned lanes) const;

    bool occluded_by(std::uint32_t object, const Ray& r, float t_max) const;
    unsigned occluded_by_packet(std::uint32_t object, const RayLanes<kPacketWidth>& feelers,
                                const float* t_max, unsigned lanes) const;
    bool occluded_in_tree(const Ray& feeler, float t_max, std::uint32_t leaving) const;

    Accel top_;                             // over the bounded objects
    std::vector<std::uint32_t> bounded_;    // traversal slot -> object
    std::vector<std::uint32_t> unbounded_;  // planes: tested for every ray
    bool few_shapes_ = false;  // few bounded objects, no mesh: packets test each (intersect_packet)
    std::vector<std::optional<LightBuffer>> light_buffers_;  // per light, where it has one
    struct PlaneFrame {
        vec3 t1{0.0f}, t2{0.0f};  // tangent_frame of a plane's normal: its checker's axes
    };
    std::vector<PlaneFrame> plane_frames_;  // per object (planes only)
};

template <class... F>
struct Overloaded : F... {
    using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;  // clang 14 does not deduce aggregates by itself

// Calls f with the object's shape, a mesh reference resolved (in `meshes`) to its
// MeshInstance: the one interface every shape has (core/shapes.h). For descriptions and
// built scenes alike.
template <class F>
decltype(auto) visit_shape(const std::vector<TriangleMesh>& meshes, const Object& o, F&& f) {
    return std::visit(Overloaded{[&](const MeshRef& m) {
                                     return f(MeshInstance{meshes[m.mesh], m.own_materials});
                                 },
                                 [&](const auto& shape) { return f(shape); }},
                      o.shape);
}

template <class F>
decltype(auto) Scene::visit_shape(const Object& o, F&& f) const {
    return rt::visit_shape(meshes, o, std::forward<F>(f));
}

}  // namespace rt
