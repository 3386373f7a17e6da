// The tutorial's camera, and its agreement with the raster matrices built from it.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "core/camera.h"
#include "core/scene.h"
#include "test_util.h"

namespace rt {
namespace {

TEST(Camera, RayFormulaByHand) {
    Camera cam;  // eye 0, u = x, v = y, n = z
    cam.W = 2.0f;
    cam.H = 1.0f;
    cam.N = 3.0f;
    cam.cols = 4;
    cam.rows = 2;
    // Pixel (0, 0): d = -3 n + 2 (2 (0.5)/4 - 1) u + 1 (2 (0.5)/2 - 1) v = (-1.5, -0.5, -3).
    const Ray r = cam.ray(0, 0);
    EXPECT_FLOAT_EQ(r.dir.x, -1.5f);
    EXPECT_FLOAT_EQ(r.dir.y, -0.5f);
    EXPECT_FLOAT_EQ(r.dir.z, -3.0f);
    // Pixel (3, 1), top right: (1.5, 0.5, -3).
    const Ray s = cam.ray(3, 1);
    EXPECT_FLOAT_EQ(s.dir.x, 1.5f);
    EXPECT_FLOAT_EQ(s.dir.y, 0.5f);
}

TEST(Camera, LookAtBuildsAnOrthonormalFrameLookingAlongMinusN) {
    const Camera cam = Camera::look_at({1, 2, 3}, {4, 0, -2}, {0, 1, 0}, 45.0f, 64, 32);
    EXPECT_NEAR(glm::dot(cam.u, cam.v), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(cam.u, cam.n), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(cam.n), 1.0f, 1e-6f);
    const vec3 forward = glm::normalize(vec3(4, 0, -2) - vec3(1, 2, 3));
    EXPECT_NEAR(glm::dot(-cam.n, forward), 1.0f, 1e-6f);
    EXPECT_FLOAT_EQ(cam.W / cam.H, 2.0f);  // square pixels
    EXPECT_NEAR(cam.H / cam.N, std::tan(glm::radians(22.5f)), 1e-6f);
}

// A traced hit point, projected by the raster matrices, lands in the pixel whose ray found it.
TEST(Camera, ProjectedHitLandsInItsPixel) {
    SceneDescription desc;
    desc.materials.push_back(Material{});
    desc.objects.push_back(Object{"floor", Plane{{0, 1, 0}, -1}, 0, {}});
    desc.objects.push_back(Object{"ball", Sphere{{0.3f, 0.2f, -2}, 1}, 0, {}});
    desc.camera = Camera::look_at({0.5f, 1.5f, 4}, {0, 0, -1}, {0.1f, 1, 0}, 50.0f, 97, 61);
    const Scene scene(std::move(desc));
    const glm::mat4 clip = scene.camera.projection(100.0f) * scene.camera.view();
    int checked = 0;
    for (int y = 0; y < scene.camera.rows; y += 3) {
        for (int x = 0; x < scene.camera.cols; x += 3) {
            const Ray ray = scene.camera.ray(x, y);
            Hit hit;
            if (!scene.intersect(ray, hit)) continue;
            const glm::vec4 c = clip * glm::vec4(ray.at(hit.t), 1.0f);
            const float px = (c.x / c.w * 0.5f + 0.5f) * static_cast<float>(scene.camera.cols);
            const float py = (c.y / c.w * 0.5f + 0.5f) * static_cast<float>(scene.camera.rows);
            EXPECT_NEAR(px, static_cast<float>(x) + 0.5f, 1e-3f) << x << "," << y;
            EXPECT_NEAR(py, static_cast<float>(y) + 0.5f, 1e-3f) << x << "," << y;
            EXPECT_GT(c.z / c.w, -1.0f);  // inside the depth range
            ++checked;
        }
    }
    EXPECT_GT(checked, 300);
}

TEST(Camera, ResizeKeepsTheVerticalViewAndSquarePixels) {
    const Camera cam = Camera::look_at({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 40.0f, 640, 480);
    const Camera wide = cam.resized(200, 100);
    EXPECT_FLOAT_EQ(wide.H, cam.H);
    EXPECT_FLOAT_EQ(wide.W, 2.0f * cam.H);
}

}  // namespace
}  // namespace rt
