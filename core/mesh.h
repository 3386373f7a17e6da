#pragma once
// A triangle mesh with its own BVH; objects refer to it by index, so one mesh can be
// instanced many times under different transforms.

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/accel.h"
#include "core/hit.h"
#include "core/large_array.h"
#include "core/ray_lanes.h"
#include "core/shapes.h"
#include "core/triangle4.h"

namespace rt {

struct TriangleMesh {
    std::string name;
    std::vector<vec3> positions;
    std::vector<glm::uvec3> triangles;     // indices into positions
    std::vector<vec3> corner_normals;      // 3 per triangle (smooth shading); empty: flat
    std::vector<std::uint32_t> materials;  // per triangle, scene material index; may be empty
    std::vector<glm::vec2> corner_uvs;     // 3 per triangle (core/texture.h's convention), or empty
    std::vector<vec3> corner_colours;      // 3 per triangle (a PLY's vertex colours), or empty
    // Line segments and points (OBJ `l` and `p`), indices into positions: the raster view
    // draws them; the tracer, which renders surfaces, does not see them.
    std::vector<glm::uvec2> segments;
    std::vector<std::uint32_t> points;

    // Bounds and acceleration structure; call after filling the arrays.
    void build(AccelKind kind = AccelKind::kBvh, int threads = 0);  // 0: every hardware thread
    const Aabb& bounds() const { return bounds_; }
    std::size_t memory_bytes() const;
    std::size_t accel_memory_bytes() const;  // the structure and its packed triangles only

    // Closest hit in (0, hit.t): fills t, prim, b1, b2 and returns true.
    bool intersect(const Ray& r, Hit& hit) const;
    bool occluded(const Ray& r, float t_max) const;
    // The same for up to kPacketWidth rays at once (rays[lane], hits[lane] for each bit
    // of `active`), traced together: each gets the answer it gets alone (of two hits at
    // the very same t, either). Return the bits of the rays that hit.
    unsigned intersect_packet(const Ray* rays, Hit* hits, unsigned active) const;
    unsigned occluded_packet(const Ray* rays, const float* t_max, unsigned active) const;
    // Triangle `prim` alone, with the very test (and pack) a traversal uses, so the hit is
    // the one a traversal would find there: what the item buffer names.
    bool intersect_triangle(std::uint32_t prim, const Ray& r, Hit& hit) const;
    // The same for the rays of `lanes` (rays[lane], hits[lane]), tested together where
    // they are several and share ShearedRay's axes: returns the bits of those that hit.
    unsigned intersect_triangle_packet(std::uint32_t prim, const RayLanes<kPacketWidth>& rays,
                                       Hit* hits, unsigned lanes) const;
    // Each ray of `lanes` against its own triangle prims[lane], the same way.
    unsigned intersect_triangles_packet(const std::uint32_t* prims,
                                        const RayLanes<kPacketWidth>& rays, Hit* hits,
                                        unsigned lanes) const;

    // The hit's shading normal (interpolated, or the face normal) and face normal, unnormalised.
    vec3 face_normal(std::uint32_t tri) const;
    vec3 shading_normal(const Hit& hit) const;
    vec3 point(const Hit& hit) const;    // rebuilt from barycentrics: more exact than o + d t
    glm::vec2 uv(const Hit& hit) const;  // interpolated; (0, 0) where the mesh has none
    vec3 colour(const Hit& hit) const;   // interpolated; white where the mesh has none

  private:
    Aabb bounds_;
    Accel accel_;
    // The triangles in the structure's slot order, four to a Triangle4, each leaf
    // starting a new one (leaf_pack_[first slot] is its first). The grid's and brute
    // force's leaves are single triangles: slot s is lane 0 of packs_[s]. The wide BVH
    // hands out the first pack itself (leaves_are_packs_), no lookup on the way.
    LargeArray<Triangle4> packs_;           // written in full by build(), in parallel
    LargeArray<std::uint32_t> pack_prims_;  // the triangle in lane l of pack p: [4 p + l]
    LargeArray<std::uint32_t> prim_lane_;   // its inverse: triangle -> 4 p + l (a cut
                                            // one's first copy, core/triangle_refs.h)
    LargeArray<std::uint32_t> leaf_pack_;   // read at leaves' first slots only
    bool leaves_are_packs_ = false;

    std::uint32_t first_pack(std::uint32_t leaf) const {
        return leaves_are_packs_ ? leaf : leaf_pack_[leaf];
    }
    // The nearest of a leaf's `count` triangles, from pack `start` on, that the ray hits
    // within t_max; its lane counts on from the first pack's (lanes 4-7: the second pack).
    // Five to eight under AVX: the two packs in one test of eight lanes. `deferred`: as
    // rt::intersect's (nonzero where the leaf left a triangle unsettled).
    [[gnu::always_inline]] Triangle4Hit leaf_hit(std::uint32_t start, std::uint32_t count,
                                                 const ShearedRay& r, float t_max,
                                                 unsigned* deferred = nullptr) const {
#if defined(__AVX__)
        if (count > kTriangle4Lanes && count <= 2 * kTriangle4Lanes)
            return rt::intersect(packs_[start], packs_[start + 1], r, t_max, deferred);
#endif
        Triangle4Hit best;
        for (std::uint32_t k = 0; kTriangle4Lanes * k < count; ++k) {
            Triangle4Hit h = rt::intersect(packs_[start + k], r, t_max, 0xfu, deferred);
            if (h.lane < 0) continue;
            t_max = h.t;
            h.lane += static_cast<int>(kTriangle4Lanes * k);
            best = h;
        }
        return best;
    }
    // Whether the ray hits any of the leaf's triangles within t_max (leaf_hit's lane >= 0).
    [[gnu::always_inline]] bool leaf_blocks(std::uint32_t start, std::uint32_t count,
                                            const ShearedRay& r, float t_max,
                                            unsigned* deferred = nullptr) const {
#if defined(__AVX__)
        if (count > kTriangle4Lanes && count <= 2 * kTriangle4Lanes)
            return rt::occludes(packs_[start], packs_[start + 1], r, t_max, deferred);
#endif
        for (std::uint32_t k = 0; kTriangle4Lanes * k < count; ++k)
            if (rt::occludes(packs_[start + k], r, t_max, deferred)) return true;
        return false;
    }
};

// A mesh as one object of a scene sees it: the shape interface of core/shapes.h over a
// shared TriangleMesh (Scene::visit_shape makes one from an object's MeshRef).
struct MeshInstance {
    static constexpr Convex kConvex = Convex::kNo;
    const TriangleMesh& mesh;
    bool own_materials = true;  // the mesh's per-triangle materials, else the object's

    const Aabb& bounds() const { return mesh.bounds(); }
    bool intersect(const Ray& r, Hit& hit) const { return mesh.intersect(r, hit); }
    bool occluded(const Ray& r, float t_max) const { return mesh.occluded(r, t_max); }
    LocalSurface surface(const Ray&, const Hit& hit) const {
        LocalSurface s{mesh.point(hit),
                       mesh.face_normal(hit.prim),
                       mesh.shading_normal(hit),
                       std::nullopt,
                       mesh.uv(hit),
                       mesh.colour(hit)};
        if (own_materials && !mesh.materials.empty()) s.material = mesh.materials[hit.prim];
        return s;
    }
    template <class V>
    V pattern_point(const V& p) const {
        return p;
    }
    std::size_t triangle_count() const { return mesh.triangles.size(); }
};

// The box around the triangles, segments and points (unused vertices left out).
Aabb bounds_of(const TriangleMesh& mesh);

// Drops triangles that repeat an earlier one: the same three positions in the same
// winding (a file that lists one face a million times would make every ray test them
// all). Corner normals and materials follow. Returns how many were dropped.
std::size_t drop_duplicate_triangles(TriangleMesh& mesh);

// Fills corner_normals by averaging, at each vertex, the area-weighted normals of the
// faces that meet there within `crease_degrees` of each other: smooth curved surfaces,
// sharp box corners.
void compute_corner_normals(TriangleMesh& mesh, float crease_degrees = 60.0f);

}  // namespace rt
