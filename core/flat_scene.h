#pragma once
// A Scene as flat arrays of 16-byte rows, ready to be copied into GPU buffers as they are
// (GLSL's std430 layout: every struct below is a whole number of vec4s). No GL here: the
// GPU tracer (app/gl/gpu_tracer.h, shaders/gputrace.comp) uploads them; docs/gpu-tracer.md
// describes each layout.
//
// The hierarchy is core's binary BVH (core/bvh.h, the same builder the CPU side uses),
// two levels in one node array: the objects' tree first (root at node 0), then each
// mesh's tree. An interior node's `first` is its right child (the left one follows it);
// a leaf's `first` indexes `object_order` (top level) or `triangle_order` (a mesh).

#include <cstdint>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "core/bvh.h"
#include "core/scene.h"

namespace rt {

struct FlatObject {
    glm::mat4 to_object{1.0f};  // M^-1 (identity without a transform)
    glm::mat4 to_world{1.0f};   // M
    glm::mat4 normal{1.0f};     // (M^-1)^T, upper 3x3
    glm::vec4 shape[3]{};       // sphere: centre, radius; plane: normal, offset; triangle: a, b, c
    glm::vec4 pattern_hi{0.0f}, pattern_lo{0.0f};  // the scene origin's pattern point, hi + lo
    std::uint32_t kind = 0;                        // FlatObject::kSphere...
    std::uint32_t material = 0;
    std::uint32_t mesh = 0;   // meshes: index into FlatScene::meshes
    std::uint32_t flags = 0;  // kTransformed | kOwnMaterials

    static constexpr std::uint32_t kSphere = 0, kPlane = 1, kTriangle = 2, kMesh = 3;
    static constexpr std::uint32_t kTransformed = 1, kOwnMaterials = 2;
};
static_assert(sizeof(FlatObject) == 16 * 18);

struct FlatMesh {
    std::uint32_t root = 0;           // its tree's root in FlatScene::nodes
    std::uint32_t triangles = 0;      // its first triangle in the per-triangle arrays
    std::uint32_t normals = kNone;    // its first in corner_normals (3 per triangle), or kNone
    std::uint32_t uvs = kNone;        // in corner_uvs (two rows per triangle), or kNone
    std::uint32_t colours = kNone;    // in corner_colours (3 per triangle), or kNone
    std::uint32_t materials = kNone;  // in triangle_materials, or kNone
    std::uint32_t pad[2]{};
    static constexpr std::uint32_t kNone = ~0u;
};
static_assert(sizeof(FlatMesh) == 32);

struct FlatMaterial {
    glm::vec4 ka_shininess;
    glm::vec4 kd_reflectivity;
    glm::vec4 ks_transparency;
    glm::vec4 emission_ior;
    glm::vec4 checker_a_scale;  // scale 0: no checker
    glm::vec4 checker_b;
    std::int32_t texture[4];  // index into FlatScene::textures or -1, then wrap u, wrap v
};
static_assert(sizeof(FlatMaterial) == 16 * 7);

struct FlatTexture {
    std::int32_t first = 0;  // its top-left texel in FlatScene::texels
    std::int32_t width = 0, height = 0;
    std::int32_t pad = 0;
};

struct FlatLight {
    glm::vec4 position_type;  // w: 0 point, 1 directional
    glm::vec4 direction;
    glm::vec4 colour;
};

struct FlatScene {
    std::vector<BvhNode> nodes;
    std::vector<std::uint32_t> object_order;    // top-level leaf slots -> object
    std::vector<std::uint32_t> triangle_order;  // mesh leaf slots -> triangle (within its mesh)
    std::vector<std::uint32_t> unbounded;       // the planes: tested by every ray
    std::vector<FlatObject> objects;
    std::vector<FlatMesh> meshes;
    std::vector<glm::vec4> vertices;        // 3 per triangle, all meshes
    std::vector<glm::vec4> corner_normals;  // 3 per triangle, meshes that have them
    std::vector<glm::vec4> corner_uvs;      // (u0, v0, u1, v1), (u2, v2, 0, 0) per triangle
    std::vector<glm::vec4> corner_colours;  // 3 per triangle
    std::vector<std::uint32_t> triangle_materials;
    std::vector<FlatMaterial> materials;
    std::vector<FlatTexture> textures;
    std::vector<glm::vec4> texels;
    std::vector<FlatLight> lights;

    std::size_t bytes() const;  // everything above, as uploaded
};

// Leaves of at most `max_leaf` triangles in the meshes' trees (a GPU thread tests them
// one by one, so small leaves pay).
FlatScene flatten(const Scene& scene, std::uint32_t max_leaf = 2);

}  // namespace rt
