// Numerical robustness: no shadow acne or self-intersection at any scene scale.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "core/renderer.h"
#include "core/shapes.h"
#include "test_util.h"

namespace rt {
namespace {

// A sphere lit by a point light, rendered with shadow feelers on, at scales from 1e-3
// to 1e4. Every pixel on the sphere must have the Phong value computed here in double
// precision from the exact hit: a feeler that hits its own sphere (acne) would leave
// ambient only where n.l > 0.
TEST(Robustness, NoShadowAcneAtAnyScale) {
    for (double scale : {1e-3, 1.0, 1e4}) {
        const auto s = static_cast<float>(scale);
        SceneDescription desc;
        desc.camera =
            Camera::look_at(vec3(0.3f, 0.2f, 5.0f) * s, vec3(0.0f), {0, 1, 0}, 30.0f, 61, 61);
        desc.ambient = vec3(0.1f);
        desc.materials.push_back(test::plain(vec3(1.0f), vec3(0.8f)));
        const glm::dvec3 light = glm::dvec3(2.0, 3.0, 5.0) * scale;
        desc.lights.push_back(Light{Light::Type::kPoint, vec3(light), {}, vec3(1.0f)});
        desc.objects.push_back(Object{"ball", Sphere{vec3(0.0f), s}, 0, {}});
        const Scene scene(std::move(desc));
        const Image image = render(scene, {});
        int on_sphere = 0, lit = 0;
        for (int y = 0; y < 61; ++y) {
            for (int x = 0; x < 61; ++x) {
                const Ray r = scene.camera.ray(x, y);
                // The exact hit, in double precision.
                const glm::dvec3 o(r.origin), d = glm::normalize(glm::dvec3(r.dir));
                const double b = glm::dot(o, d), c = glm::dot(o, o) - scale * scale,
                             disc = b * b - c;
                if (disc <= 1e-6 * scale * scale) continue;  // misses, or grazes: skip the rim
                const glm::dvec3 p = o + (-b - std::sqrt(disc)) * d;
                const glm::dvec3 n = p / scale;
                const double n_dot_l = glm::dot(n, glm::normalize(light - p));
                if (std::fabs(n_dot_l) < 0.02)
                    continue;  // the terminator, where rounding may go either way
                const double expected = 0.1 + 0.8 * std::max(0.0, n_dot_l);
                ++on_sphere;
                lit += n_dot_l > 0.0;
                EXPECT_NEAR(image.at(x, y).x, expected, 2e-3)
                    << "scale " << scale << " pixel " << x << "," << y;
            }
        }
        EXPECT_GT(on_sphere, 1000) << scale;
        EXPECT_GT(lit, 300) << scale;
    }
}

// A mirror at a large scale facing a wall: the reflected ray must leave the mirror,
// not hit it again (self-intersection), at every scale.
TEST(Robustness, ReflectionsLeaveTheirSurfaceAtAnyScale) {
    for (float scale : {1e-3f, 1.0f, 1e4f}) {
        SceneDescription desc;
        desc.camera =
            Camera::look_at(vec3(0.1f, 0.2f, 5.0f) * scale, vec3(0.0f), {0, 1, 0}, 20.0f, 21, 21);
        desc.ambient = vec3(1.0f);
        Material mirror = test::plain(vec3(0.0f), vec3(0.0f));
        mirror.reflectivity = 1.0f;
        desc.materials.push_back(mirror);
        desc.materials.push_back(test::plain({0.2f, 0.5f, 0.7f}, vec3(0.0f)));
        desc.objects.push_back(Object{"mirror", Sphere{vec3(0.0f), scale}, 0, {}});
        desc.objects.push_back(Object{"sky", Sphere{vec3(0.0f), 100.0f * scale}, 1, {}});
        const Scene scene(std::move(desc));
        const Image image = render(scene, {});
        const vec3 centre = image.at(10, 10);  // the mirror shows the inside of the big sphere
        EXPECT_NEAR(centre.x, 0.2f, 1e-4f) << scale;
        EXPECT_NEAR(centre.z, 0.7f, 1e-4f) << scale;
    }
}

// Degenerate triangles in a mesh (collinear, or with a repeated vertex), a zero-radius
// sphere and rays parallel to a plane: never hit, never a NaN in a normal or a pixel.
TEST(Robustness, DegenerateGeometryIsHarmless) {
    TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    mesh.triangles = {{0, 1, 2}, {0, 0, 3}, {0, 1, 3}, {1, 4, 3}};  // two degenerate, two real
    compute_corner_normals(mesh);
    for (const vec3& n : mesh.corner_normals)
        EXPECT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
    mesh.build();
    Hit hit;
    EXPECT_FALSE(mesh.intersect(Ray{{1.5f, 0.0f, 1.0f}, {0, 0, -1}},
                                hit));  // through the collinear one only
    Hit edge;  // through the zero-area one's edge, which the real one shares
    EXPECT_TRUE(mesh.intersect(Ray{{0.0f, 0.5f, 1.0f}, {0, 0, -1}}, edge));
    EXPECT_EQ(edge.prim, 2u);
    EXPECT_TRUE(mesh.intersect(Ray{{0.25f, 0.25f, 1.0f}, {0, 0, -1}}, hit));
    EXPECT_EQ(hit.prim, 2u);

    EXPECT_FALSE(intersect(Sphere{vec3(0.0f), 0.0f}, Ray{{0, 0, 5}, {0, 0, -1}}, kInfinity));
    EXPECT_FALSE(
        intersect(Plane{{0, 1, 0}, 0}, Ray{{0, 0, 5}, {0, 0, -1}}, kInfinity));  // in the plane

    SceneDescription desc;
    desc.camera = test::axis_camera({0.5f, 0.5f, 3.0f});
    desc.materials.push_back(Material{});
    desc.meshes.push_back(mesh);
    desc.objects.push_back(Object{"mesh", MeshRef{0, true}, 0, {}});
    desc.objects.push_back(Object{"dot", Sphere{vec3(0.0f), 0.0f}, 0, {}});
    desc.objects.push_back(
        Object{"floor", Plane{{0, 1, 0}, 0.5f}, 0, {}});  // the camera is level with it
    desc.lights.push_back(Light{Light::Type::kPoint, {0.5f, 0.5f, 3.0f}, {}, vec3(1.0f)});
    const Scene scene(std::move(desc));
    RenderStats stats;
    render(scene, {}, &stats);
    EXPECT_EQ(stats.nonfinite_pixels, 0u);
}

}  // namespace
}  // namespace rt
