// core/flat_scene.h: the arrays the GPU tracer uploads. Walking the flat trees the way
// the shader does reaches every object and every triangle exactly once, each inside its
// leaf's box, and the per-triangle arrays line up with the meshes.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>

#include "core/flat_scene.h"
#include "test_util.h"

namespace rt {
namespace {

// The slots of the leaves under `root`, walked as the shader walks (left child follows
// its parent, `first` is the right child), checking each node's box holds its children's.
std::vector<std::uint32_t> leaf_slots(const FlatScene& flat, std::uint32_t root,
                                      const std::function<Aabb(std::uint32_t)>& slot_box) {
    std::vector<std::uint32_t> slots;
    std::vector<std::uint32_t> pending{root};
    while (!pending.empty()) {
        const std::uint32_t index = pending.back();
        pending.pop_back();
        const BvhNode& node = flat.nodes.at(index);
        const Aabb box{node.lo, node.hi};
        if (node.is_leaf()) {
            for (std::uint32_t s = node.first; s < node.first + node.count; ++s) {
                slots.push_back(s);
                const Aabb inner = slot_box(s);
                for (int a = 0; a < 3; ++a) {
                    EXPECT_LE(box.lo[a], inner.lo[a]) << "slot " << s;
                    EXPECT_GE(box.hi[a], inner.hi[a]) << "slot " << s;
                }
            }
            continue;
        }
        pending.push_back(index + 1);
        pending.push_back(node.first);
    }
    return slots;
}

TEST(FlatScene, EveryObjectAndTriangleIsReachedOnceInsideItsBoxes) {
    for (const char* name : {"whitted.json", "cornell.json", "many_spheres.json"}) {
        const Scene scene(test::shipped_scene(name, 64, 48));
        const FlatScene flat = flatten(scene);
        ASSERT_EQ(flat.objects.size(), scene.objects.size());
        ASSERT_EQ(flat.meshes.size(), scene.meshes.size());
        ASSERT_EQ(flat.materials.size(), scene.materials.size());
        // Top level: the planes apart, every other object once.
        std::vector<std::uint32_t> objects;
        for (std::uint32_t slot : leaf_slots(flat, 0, [&](std::uint32_t s) {
                 return scene.object_bounds(scene.objects[flat.object_order.at(s)]);
             }))
            objects.push_back(flat.object_order.at(slot));
        objects.insert(objects.end(), flat.unbounded.begin(), flat.unbounded.end());
        std::sort(objects.begin(), objects.end());
        for (std::uint32_t i = 0; i < scene.objects.size(); ++i)
            EXPECT_EQ(objects.at(i), i) << name << ": object " << i;
        // Each mesh's tree: every triangle once, its corners in the vertex rows.
        std::size_t triangles = 0;
        for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
            const TriangleMesh& mesh = scene.meshes[m];
            const FlatMesh& fm = flat.meshes[m];
            const auto corner = [&](std::uint32_t tri, int k) {
                return vec3(flat.vertices.at(3 * (fm.triangles + tri) + k));
            };
            std::vector<std::uint32_t> tris;
            for (std::uint32_t slot : leaf_slots(flat, fm.root, [&](std::uint32_t s) {
                     Aabb box;
                     for (int k = 0; k < 3; ++k) box.grow(corner(flat.triangle_order.at(s), k));
                     return box;
                 }))
                tris.push_back(flat.triangle_order.at(slot));
            std::sort(tris.begin(), tris.end());
            ASSERT_EQ(tris.size(), mesh.triangles.size()) << name << ": mesh " << m;
            for (std::uint32_t t = 0; t < tris.size(); ++t) {
                ASSERT_EQ(tris[t], t) << name << ": mesh " << m;
                for (int k = 0; k < 3; ++k)
                    EXPECT_EQ(corner(t, k), mesh.positions[mesh.triangles[t][k]]);
            }
            triangles += mesh.triangles.size();
        }
        EXPECT_EQ(flat.vertices.size(), 3 * triangles) << name;
    }
}

TEST(FlatScene, RowsAreWholeVec4sForStd430) {
    static_assert(sizeof(FlatObject) % 16 == 0 && sizeof(FlatMaterial) % 16 == 0 &&
                  sizeof(FlatMesh) % 16 == 0 && sizeof(FlatLight) % 16 == 0 &&
                  sizeof(BvhNode) == 32);
    const Scene scene(test::shipped_scene("textured.json", 32, 24));
    const FlatScene flat = flatten(scene);
    ASSERT_FALSE(flat.textures.empty());
    std::size_t texels = 0;
    for (const Texture& t : scene.textures) texels += t.texels.size();
    EXPECT_EQ(flat.texels.size(), texels);
    EXPECT_EQ(flat.lights.size(), scene.lights.size());
    EXPECT_GT(flat.bytes(), flat.vertices.size() * sizeof(glm::vec4));
}

}  // namespace
}  // namespace rt
