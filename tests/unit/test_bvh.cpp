// The BVH must find exactly what testing every primitive finds.
#include <gtest/gtest.h>

#include <random>

#include "core/mesh.h"
#include "core/scene.h"
#include "core/shapes.h"

namespace rt {
namespace {

vec3 random_point(std::mt19937& rng, float extent) {
    std::uniform_real_distribution<float> u(-extent, extent);
    return {u(rng), u(rng), u(rng)};
}

TriangleMesh random_soup(std::mt19937& rng, int count) {
    TriangleMesh mesh;
    std::uniform_real_distribution<float> size(0.05f, 1.0f);
    for (int i = 0; i < count; ++i) {
        const vec3 centre = random_point(rng, 10.0f);
        const float s = size(rng);
        const auto base = static_cast<std::uint32_t>(mesh.positions.size());
        for (int k = 0; k < 3; ++k) mesh.positions.push_back(centre + s * random_point(rng, 1.0f));
        mesh.triangles.push_back({base, base + 1, base + 2});
    }
    mesh.build();
    return mesh;
}

TEST(Bvh, MeshHitsMatchBruteForce) {
    std::mt19937 rng(7);
    const TriangleMesh mesh = random_soup(rng, 3000);
    int hits = 0;
    for (int i = 0; i < 4000; ++i) {
        const Ray ray{random_point(rng, 15.0f), random_point(rng, 1.0f)};
        float best = kInfinity;
        std::uint32_t best_tri = 0;
        for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
            const auto& tri = mesh.triangles[t];
            if (auto h = intersect_triangle(mesh.positions[tri[0]], mesh.positions[tri[1]],
                                            mesh.positions[tri[2]], ray, best)) {
                best = h->t;
                best_tri = t;
            }
        }
        Hit hit;
        const bool found = mesh.intersect(ray, hit);
        ASSERT_EQ(found, best < kInfinity) << "ray " << i;
        EXPECT_EQ(mesh.occluded(ray, kInfinity), found) << "ray " << i;
        if (!found) continue;
        ++hits;
        EXPECT_EQ(hit.prim, best_tri) << "ray " << i;
        EXPECT_FLOAT_EQ(hit.t, best) << "ray " << i;
        EXPECT_FALSE(mesh.occluded(ray, best * 0.999f))
            << "nothing is closer than the closest hit, ray " << i;
    }
    EXPECT_GT(hits, 500);  // the test means something only if many rays hit
}

TEST(Bvh, SceneHitsMatchTestingEveryObject) {
    std::mt19937 rng(11);
    Scene scene;
    scene.materials.push_back(Material{});
    std::uniform_real_distribution<float> radius(0.1f, 1.0f);
    for (int i = 0; i < 500; ++i)
        scene.objects.push_back(Object{"s", Sphere{random_point(rng, 12.0f), radius(rng)}, 0, {}});
    scene.objects.push_back(Object{"floor", Plane{{0, 1, 0}, -13}, 0, {}});
    scene.build();
    for (int i = 0; i < 3000; ++i) {
        const Ray ray{random_point(rng, 15.0f), random_point(rng, 1.0f)};
        Hit brute;
        for (std::uint32_t o = 0; o < scene.objects.size(); ++o)
            scene.intersect_object(o, ray, brute);
        Hit hit;
        ASSERT_EQ(scene.intersect(ray, hit), brute.found()) << "ray " << i;
        EXPECT_EQ(hit.object, brute.object) << "ray " << i;
        EXPECT_FLOAT_EQ(hit.t, brute.t) << "ray " << i;
        EXPECT_EQ(scene.occluded(ray, kInfinity), brute.found()) << "ray " << i;
    }
}

TEST(Bvh, DegenerateInputsBuild) {
    Bvh bvh;
    bvh.build({});
    EXPECT_TRUE(bvh.empty());
    // Many identical boxes: no split separates them; the build must still finish.
    std::vector<Aabb> same(1000, Aabb{vec3(0.0f), vec3(1.0f)});
    bvh.build(same);
    float t = kInfinity;
    int visited = 0;
    bvh.traverse<false>(Ray{{0.5f, 0.5f, -5}, {0, 0, 1}}, t, [&](std::uint32_t, float&) {
        ++visited;
        return false;
    });
    EXPECT_EQ(visited, 1000);
}

}  // namespace
}  // namespace rt
