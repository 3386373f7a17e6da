// The tutorial's intersection formulas against values computed by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "core/scene.h"
#include "core/scene_loader.h"
#include "core/shapes.h"
#include "core/triangle4.h"
#include "test_util.h"

namespace rt {
namespace {

TEST(Sphere, DiscriminantBelowZeroMisses) {
    // Passes 2 units from the centre of a unit sphere.
    const SphereRoots r = solve_sphere(Sphere{{0, 0, 0}, 1}, Ray{{-5, 2, 0}, {1, 0, 0}});
    EXPECT_EQ(r.kind, SphereCase::kMiss);
    EXPECT_FALSE(intersect(Sphere{{0, 0, 0}, 1}, Ray{{-5, 2, 0}, {1, 0, 0}}, kInfinity));
}

TEST(Sphere, DiscriminantZeroGrazesAndCountsAsMiss) {
    // Tangent at (0, 1, 0): B^2 - 4AC = 4A(r^2 - 1) = 0 exactly.
    const Ray ray{{-5, 1, 0}, {1, 0, 0}};
    EXPECT_EQ(solve_sphere(Sphere{{0, 0, 0}, 1}, ray).kind, SphereCase::kGraze);
    EXPECT_FALSE(intersect(Sphere{{0, 0, 0}, 1}, ray, kInfinity));
}

TEST(Sphere, DiscriminantAboveZeroGivesEntryAndExit) {
    // eye (0,0,5), d (0,0,-1), r = 1: A = 1, B = -10, C = 24, t = (10 +- 2) / 2.
    const Ray ray{{0, 0, 5}, {0, 0, -1}};
    const SphereRoots r = solve_sphere(Sphere{{0, 0, 0}, 1}, ray);
    ASSERT_EQ(r.kind, SphereCase::kTwoRoots);
    EXPECT_FLOAT_EQ(r.t1, 4.0f);
    EXPECT_FLOAT_EQ(r.t2, 6.0f);
    EXPECT_FLOAT_EQ(*intersect(Sphere{{0, 0, 0}, 1}, ray, kInfinity), 4.0f);
}

TEST(Sphere, OffCentreWithUnnormalisedDirection) {
    // Centre (1,2,3), r = 2, ray from (1,2,10) with d = (0,0,-2): hits z = 5 at t = 2.5.
    const auto t = intersect(Sphere{{1, 2, 3}, 2}, Ray{{1, 2, 10}, {0, 0, -2}}, kInfinity);
    ASSERT_TRUE(t);
    EXPECT_FLOAT_EQ(*t, 2.5f);
}

TEST(Sphere, FromInsideTakesTheExitAndBehindIsNoHit) {
    const Sphere s{{0, 0, 0}, 1};
    EXPECT_FLOAT_EQ(*intersect(s, Ray{{0, 0, 0}, {0, 0, 1}}, kInfinity), 1.0f);
    EXPECT_FALSE(intersect(s, Ray{{0, 0, 5}, {0, 0, 1}}, kInfinity));  // t < 0 only
    EXPECT_FALSE(intersect(s, Ray{{0, 0, 5}, {0, 0, -1}}, 3.9f));      // beyond t_max
}

TEST(Sphere, DistantSmallSphereStillHitsAtTheRightDistance) {
    // The naive B^2 - 4AC loses every digit here in float; the stable form does not.
    const auto t = intersect(Sphere{{0, 0, -1e4f}, 0.01f}, Ray{{0, 0, 0}, {0, 0, -1}}, kInfinity);
    ASSERT_TRUE(t);
    EXPECT_NEAR(*t, 1e4f - 0.01f, 1e-2f);
}

TEST(Plane, TutorialFormula) {
    // p.n = a with n = (0,1,0), a = -1; eye (0,3,0), d = (1,-2,0): t = (a - eye.n)/(d.n) = 2.
    const auto t = intersect(Plane{{0, 1, 0}, -1}, Ray{{0, 3, 0}, {1, -2, 0}}, kInfinity);
    ASSERT_TRUE(t);
    EXPECT_FLOAT_EQ(*t, 2.0f);
}

TEST(Plane, ParallelAndBehindMiss) {
    EXPECT_FALSE(intersect(Plane{{0, 1, 0}, 0}, Ray{{0, 1, 0}, {1, 0, 0}}, kInfinity));
    EXPECT_FALSE(intersect(Plane{{0, 1, 0}, 0}, Ray{{0, 1, 0}, {0, 1, 0}}, kInfinity));
}

TEST(Triangle, InsideHitWithBarycentrics) {
    const vec3 a{0, 0, 0}, b{4, 0, 0}, c{0, 4, 0};
    const auto h = intersect_triangle(a, b, c, Ray{{1, 2, 5}, {0, 0, -1}}, kInfinity);
    ASSERT_TRUE(h);
    EXPECT_FLOAT_EQ(h->t, 5.0f);
    EXPECT_FLOAT_EQ(h->b1, 0.25f);  // weight of b: x / 4
    EXPECT_FLOAT_EQ(h->b2, 0.5f);   // weight of c: y / 4
}

TEST(Triangle, EachEdgeTestRejectsItsSide) {
    const vec3 a{0, 0, 0}, b{4, 0, 0}, c{0, 4, 0};
    EXPECT_FALSE(intersect_triangle(a, b, c, Ray{{1, -1, 5}, {0, 0, -1}}, kInfinity));  // below AB
    EXPECT_FALSE(intersect_triangle(a, b, c, Ray{{3, 3, 5}, {0, 0, -1}}, kInfinity));   // past BC
    EXPECT_FALSE(
        intersect_triangle(a, b, c, Ray{{-1, 1, 5}, {0, 0, -1}}, kInfinity));  // left of CA
}

TEST(Triangle, BothWindingsAndBothSidesHit) {
    const vec3 a{0, 0, 0}, b{4, 0, 0}, c{0, 4, 0};
    EXPECT_TRUE(intersect_triangle(a, c, b, Ray{{1, 1, 5}, {0, 0, -1}}, kInfinity));
    EXPECT_TRUE(intersect_triangle(a, b, c, Ray{{1, 1, -5}, {0, 0, 1}}, kInfinity));
}

TEST(Triangle, EdgePointCountsAsInside) {
    const auto h =
        intersect_triangle({0, 0, 0}, {4, 0, 0}, {0, 4, 0}, Ray{{2, 0, 1}, {0, 0, -1}}, kInfinity);
    ASSERT_TRUE(h);
    EXPECT_FLOAT_EQ(h->b2, 0.0f);
}

TEST(Triangle, ParallelAndDegenerateMiss) {
    EXPECT_FALSE(
        intersect_triangle({0, 0, 0}, {4, 0, 0}, {0, 4, 0}, Ray{{1, 1, 1}, {1, 0, 0}}, kInfinity));
    EXPECT_FALSE(
        intersect_triangle({0, 0, 0}, {1, 1, 0}, {2, 2, 0}, Ray{{1, 1, 1}, {0, 0, -1}}, kInfinity));
}

TEST(TangentFrame, OrthonormalForManyNormals) {
    for (const vec3 n : {vec3(0, 1, 0), vec3(0, -1, 0), vec3(1, 0, 0), vec3(0, 0, -1),
                         glm::normalize(vec3(1, 2, 3)), glm::normalize(vec3(-0.3f, -0.1f, 0.9f))}) {
        vec3 t1, t2;
        tangent_frame(n, t1, t2);
        EXPECT_NEAR(glm::length(t1), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::length(t2), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(t1, n), 0.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(t2, n), 0.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(t1, t2), 0.0f, 1e-5f);
    }
}

TEST(RayOffset, MovesToTheRequestedSideAtEveryScale) {
    for (float scale : {1e-3f, 1.0f, 1e4f}) {
        const vec3 p{scale * 0.7f, scale * -1.3f, scale * 2.1f};
        const vec3 n = glm::normalize(vec3(1, 2, -1));
        const vec3 out = offset_ray_origin(p, n);
        EXPECT_GT(glm::dot(out - p, n), 0.0f) << scale;
        EXPECT_LT(glm::length(out - p), 1e-4f * scale + 1e-4f) << scale;  // small against the scale
        EXPECT_LT(glm::dot(offset_ray_origin(p, -n) - p, n), 0.0f) << scale;
    }
}

}  // namespace
}  // namespace rt

namespace rt {
namespace {

// The BVH visits the mesh first (its box starts nearer: a sliver at z = 5 stretches it)
// and records a hit on its big back triangle, with its barycentrics; the sphere in front
// is nearer and replaces the record whole: no triangle index or barycentrics stay behind.
TEST(Scene, ASphereHitReplacesAnEarlierMeshHitWhole) {
    SceneDescription desc;
    desc.materials.push_back(Material{});
    TriangleMesh mesh;
    mesh.positions = {{3, 3, 5},       {3.1f, 3, 5},   {3, 3.1f, 5},
                      {-10, -10, -10}, {10, -10, -10}, {0, 10, -10}};
    mesh.triangles = {{0, 1, 2}, {3, 4, 5}};
    desc.meshes.push_back(std::move(mesh));
    desc.objects.push_back(Object{"mesh", MeshRef{0, false}, 0, {}});
    desc.objects.push_back(Object{"ball", Sphere{{0, 0, 0}, 1}, 0, {}});
    const Scene scene(std::move(desc));
    const Ray ray{{0.2f, 0.1f, 10}, {0, 0, -1}};
    Hit mesh_only;
    ASSERT_TRUE(scene.intersect_object(0, ray, mesh_only));
    ASSERT_EQ(mesh_only.prim, 1u);
    ASSERT_GT(mesh_only.b1 + mesh_only.b2, 0.0f);
    Hit hit;
    ASSERT_TRUE(scene.intersect(ray, hit));
    EXPECT_EQ(hit.object, 1u);
    EXPECT_EQ(hit.prim, 0u);
    EXPECT_EQ(hit.b1, 0.0f);
    EXPECT_EQ(hit.b2, 0.0f);
}

}  // namespace
}  // namespace rt

namespace rt {
namespace {

// Scene::surface keeps a plane's checker axes (tangent_frame of its normal) from the
// build, and normalises a plane's or sphere's one normal once: the surface must still be
// what the shape itself gives, bit for bit, on tilted planes too.
TEST(Scene, APlanesCheckerPointAndNormalsAreTheShapesOwn) {
    SceneDescription desc;
    desc.materials.push_back(test::plain(vec3(0.1f), vec3(0.7f)));
    const Plane tilted{{0.3f, 2.0f, -0.7f}, -1.5f}, wall{{-1.0f, 0.0f, 0.2f}, -9.0f};
    const Sphere ball{{0.5f, 0.0f, -4.0f}, 1.25f};
    desc.objects.push_back(Object{"tilted", tilted, 0, {}});
    desc.objects.push_back(Object{"wall", wall, 0, {}});
    desc.objects.push_back(Object{"ball", ball, 0, {}});
    const Scene scene(std::move(desc));
    const auto same = [](const vec3& a, const vec3& b) {
        return std::memcmp(&a, &b, sizeof a) == 0;
    };
    int planes = 0, balls = 0;
    for (int i = 0; i < 400; ++i) {
        const float a = 0.05f * static_cast<float>(i), b = 0.37f * static_cast<float>(i);
        const Ray r{{0.0f, 0.5f, 2.0f}, {std::sin(a), 0.4f * std::cos(b), -1.0f}};
        Hit hit;
        if (!scene.intersect(r, hit)) continue;
        const SurfacePoint sp = scene.surface(r, hit);
        const vec3 facing = glm::dot(r.dir, sp.geometric_normal) < 0.0f ? vec3(1.0f) : vec3(-1.0f);
        if (hit.object == 2) {
            const LocalSurface ls = ball.surface(r, hit);
            EXPECT_TRUE(same(sp.normal, glm::normalize(ls.normal) * facing)) << i;
            ++balls;
            continue;
        }
        const Plane& plane = hit.object == 0 ? tilted : wall;
        const LocalSurface ls = plane.surface(r, hit);
        EXPECT_TRUE(same(sp.pattern_point, plane.pattern_point(ls.p))) << i;
        EXPECT_TRUE(same(sp.geometric_normal, glm::normalize(plane.normal) * facing)) << i;
        EXPECT_TRUE(same(sp.normal, sp.geometric_normal)) << i;
        ++planes;
    }
    EXPECT_GT(planes, 100);
    EXPECT_GT(balls, 10);
}

// Scene::surface written into a SurfacePoint that held something else (shade_found's
// keep what the last run of pixels left) gives, field by field and bit for bit, what the
// returned one is: every field is written, none left to its default. Every kind of
// shape: the shipped scenes' planes, spheres (one scaled), meshes and triangles, and
// rays from inside the glass.
TEST(Scene, ASurfacePointIsWrittenWholeOverWhatItHeld) {
    int hits = 0, leaving = 0, staying = 0;
    for (const char* name : {"whitted.json", "textured.json", "cornell.json"}) {
        const Scene scene(test::shipped_scene(name, 64, 36));
        for (int y = 0; y < scene.camera.rows; ++y) {
            for (int x = 0; x < scene.camera.cols; ++x) {
                Ray r = scene.camera.ray(x, y);
                Hit hit;
                if (!scene.intersect(r, hit)) continue;
                for (int bounce = 0; bounce < 2; ++bounce) {  // the camera's, then inside
                    const SurfacePoint returned = scene.surface(r, hit);
                    SurfacePoint written;
                    std::memset(static_cast<void*>(&written), 0x7f, sizeof written);
                    scene.surface(r, hit, written);
                    const auto same = [](const auto& a, const auto& b) {
                        return std::memcmp(&a, &b, sizeof a) == 0;
                    };
                    ASSERT_TRUE(same(written.p, returned.p) &&
                                same(written.geometric_normal, returned.geometric_normal) &&
                                same(written.normal, returned.normal) &&
                                written.material == returned.material &&
                                same(written.pattern_point, returned.pattern_point) &&
                                same(written.uv, returned.uv) &&
                                same(written.colour, returned.colour) &&
                                written.cannot_meet_again == returned.cannot_meet_again)
                        << name << " pixel " << x << "," << y << " bounce " << bounce;
                    ++hits;
                    (returned.cannot_meet_again == kNoObject ? staying : leaving) += 1;
                    // On through the surface: a sphere's or a mesh's far side, from inside.
                    r = Ray{r.at(hit.t) + 1e-3f * r.dir, r.dir};
                    hit = Hit{};
                    if (!scene.intersect(r, hit)) break;
                }
            }
        }
    }
    EXPECT_GT(hits, 3000);
    EXPECT_GT(leaving, 100);
    EXPECT_GT(staying, 100);
}

// A mesh's two normals differ: the shading normal is its corners' interpolated, each
// normalised on its own, with or without a transform.
TEST(Scene, AMeshHitIsShadedWithItsInterpolatedNormal) {
    SceneDescription desc;
    desc.materials.push_back(test::plain(vec3(0.1f), vec3(0.7f)));
    TriangleMesh mesh;
    mesh.positions = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
    mesh.triangles = {{0, 1, 2}};
    mesh.corner_normals = {{-0.5f, 0, 1}, {0.5f, 0, 1}, {0, 0.8f, 1}};
    desc.meshes.push_back(std::move(mesh));
    const std::optional<Transform> moved = Transform::from_matrix(
        glm::scale(glm::translate(glm::mat4(1.0f), vec3(5, 0, 0)), vec3(2.0f, 1.0f, 1.0f)));
    ASSERT_TRUE(moved);
    desc.objects.push_back(Object{"mesh", MeshRef{0, true}, 0, {}});
    desc.objects.push_back(Object{"moved mesh", MeshRef{0, true}, 0, moved});
    const Scene scene(std::move(desc));
    for (const float x : {0.0f, 5.0f}) {
        const Ray r{{x + 0.3f, -0.2f, 4.0f}, {0.0f, 0.0f, -1.0f}};
        Hit hit;
        ASSERT_TRUE(scene.intersect(r, hit));
        const SurfacePoint sp = scene.surface(r, hit);
        const vec3 local = scene.meshes[0].shading_normal(hit);
        const vec3 want = x == 0.0f ? glm::normalize(local) : moved->normal_to_world(local);
        EXPECT_EQ(sp.normal, want) << x;
        EXPECT_GT(glm::length(sp.normal - sp.geometric_normal), 0.05f) << x;
    }
}

// The item buffer names a mesh triangle per pixel and the tracer tests that triangle
// alone (Scene::intersect_primitive); a full traversal finds the closest hit among all.
// For rays through the interior of the triangle that the traversal hits, both must give
// the same hit, bit for bit: the same watertight test, the same t bound.
TEST(Triangle, ItemBufferTestAgreesWithTraversalBitForBit) {
    LoadedScene loaded = load_scene(test::source_dir() / "assets/models/stanford-bunny.obj");
    SceneDescription& desc = loaded.scene;
    const Scene scene(std::move(desc));
    const TriangleMesh& mesh = scene.meshes[0];
    std::uint32_t state = 12345;
    const auto uniform = [&] {
        state = state * 1664525u + 1013904223u;
        return static_cast<float>(state >> 8) / 16777216.0f;
    };
    int compared = 0;
    for (int i = 0; i < 20000; ++i) {
        const auto prim =
            static_cast<std::uint32_t>(uniform() * static_cast<float>(mesh.triangles.size()));
        const glm::uvec3 idx = mesh.triangles[prim];
        float u = 0.05f + 0.45f * uniform(), v = 0.05f + 0.45f * uniform();
        const vec3 target = (1.0f - u - v) * mesh.positions[idx[0]] + u * mesh.positions[idx[1]] +
                            v * mesh.positions[idx[2]];
        const Ray ray{scene.camera.eye, target - scene.camera.eye};
        Hit full;
        if (!scene.intersect(ray, full) || full.prim != prim) continue;  // hidden behind another
        Hit named;
        ASSERT_TRUE(scene.intersect_primitive(0, prim, ray, named)) << i;
        EXPECT_EQ(named.t, full.t) << i;
        EXPECT_EQ(named.b1, full.b1) << i;
        EXPECT_EQ(named.b2, full.b2) << i;
        ++compared;
    }
    EXPECT_GT(compared, 5000);
}

// The named triangle is tested in its own pack of four, the others masked off: where the
// item buffer names one that lies behind a neighbour of the same pack (the raster and the
// tracer may disagree at a pixel), the hit is the named triangle's, never the neighbour's
// t with the named triangle's index.
TEST(Triangle, ANamedTriangleIsHitItselfNotItsPackNeighbour) {
    SceneDescription d;
    TriangleMesh mesh;
    mesh.positions = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}, {-1, -1, 1}, {1, -1, 1}, {0, 1, 1}};
    mesh.triangles = {{0, 1, 2}, {3, 4, 5}};
    d.meshes.push_back(std::move(mesh));
    d.objects.push_back(Object{"two", MeshRef{0, true}, 0, std::nullopt});
    d.materials.emplace_back();
    const Scene scene(std::move(d));
    const Ray ray{{0.0f, -0.2f, -5.0f}, {0.0f, 0.0f, 1.0f}};
    for (std::uint32_t prim : {0u, 1u}) {
        Hit hit;
        ASSERT_TRUE(scene.intersect_primitive(0, prim, ray, hit)) << prim;
        EXPECT_EQ(hit.prim, prim);
        EXPECT_FLOAT_EQ(hit.t, prim == 0 ? 5.0f : 6.0f);
    }
}

}  // namespace
}  // namespace rt
