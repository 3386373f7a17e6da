// The tutorial's transformation rules: M^-1 into object space, t unchanged, normals by M^-T.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "core/scene.h"
#include "test_util.h"

namespace rt {
namespace {

SceneDescription one_object(Shape shape, const glm::mat4& m) {
    SceneDescription desc;
    desc.materials.push_back(Material{});
    desc.objects.push_back(Object{"o", shape, 0, Transform::from_matrix(m)});
    return desc;
}

TEST(Transform, EllipsoidNormalsMatchTheAnalyticNormal) {
    // A unit sphere scaled by (3, 1, 1) is the ellipsoid x^2/9 + y^2 + z^2 = 1; its normal at
    // (3 cos a, sin a, 0) is the gradient (2x/9, 2y, 2z), i.e. along (cos a / 3, sin a, 0):
    // the tutorial's M^-T n with n = (cos a, sin a, 0).
    const Scene scene(one_object(Sphere{}, glm::scale(glm::mat4(1.0f), vec3(3, 1, 1))));
    for (float a = 0.1f; a < 3.0f; a += 0.2f) {
        const vec3 p{3.0f * std::cos(a), std::sin(a), 0.0f};
        const vec3 expected = glm::normalize(vec3(std::cos(a) / 3.0f, std::sin(a), 0.0f));
        const Ray ray{p + 2.0f * expected, -expected};  // shoot straight back along the normal
        Hit hit;
        ASSERT_TRUE(scene.intersect(ray, hit)) << a;
        EXPECT_NEAR(hit.t, 2.0f, 1e-4f);  // t is the world distance: unchanged by M^-1
        const SurfacePoint sp = scene.surface(ray, hit);
        EXPECT_NEAR(glm::length(sp.p - p), 0.0f, 1e-4f) << a;
        EXPECT_NEAR(glm::dot(sp.normal, expected), 1.0f, 1e-5f) << a;
    }
}

// A unit sphere scaled by (3, 1, 0.5) and then turned 30 degrees about z and 40 about y:
// M^-1 and M^-T differ there (they agree for a scale along the axes alone). The normal
// is checked against one worked out without M^-T: the cross product of the surface's two
// tangents at p = M u, which are M t1 and M t2 for tangents t1, t2 of the unit sphere at u.
TEST(Transform, RotatedNonUniformScaleNormalsMatchTheTangentsCrossProduct) {
    const glm::mat4 m = glm::rotate(glm::mat4(1.0f), glm::radians(40.0f), vec3(0, 1, 0)) *
                        glm::rotate(glm::mat4(1.0f), glm::radians(30.0f), vec3(0, 0, 1)) *
                        glm::scale(glm::mat4(1.0f), vec3(3.0f, 1.0f, 0.5f));
    const Scene scene(one_object(Sphere{}, m));
    const glm::mat3 l(m);
    for (float a = 0.3f; a < 6.0f; a += 0.7f) {
        for (float b = -1.2f; b < 1.3f; b += 0.6f) {
            const vec3 u{std::cos(b) * std::cos(a), std::sin(b), std::cos(b) * std::sin(a)};
            const vec3 t1{-std::sin(a), 0.0f, std::cos(a)};
            const vec3 t2 = glm::cross(u, t1);
            const vec3 p = l * u;
            vec3 expected = glm::normalize(glm::cross(l * t1, l * t2));
            if (glm::dot(expected, p) < 0.0f) expected = -expected;  // outward
            const Ray ray{p + 3.0f * expected, -expected};
            Hit hit;
            ASSERT_TRUE(scene.intersect(ray, hit)) << a << " " << b;
            EXPECT_NEAR(hit.t, 3.0f, 1e-3f);
            const SurfacePoint sp = scene.surface(ray, hit);
            EXPECT_NEAR(glm::dot(sp.normal, expected), 1.0f, 1e-4f) << a << " " << b;
            EXPECT_NEAR(glm::dot(sp.geometric_normal, expected), 1.0f, 1e-4f) << a << " " << b;
        }
    }
}

TEST(Transform, TStaysTheSameUnderScaleAndTranslation) {
    // Sphere scaled by 2 and moved to z = -10: a ray from the origin meets it at z = -8.
    const glm::mat4 m =
        glm::translate(glm::mat4(1.0f), vec3(0, 0, -10)) * glm::scale(glm::mat4(1.0f), vec3(2.0f));
    const Scene scene(one_object(Sphere{}, m));
    Hit hit;
    ASSERT_TRUE(scene.intersect(Ray{{0, 0, 0}, {0, 0, -1}}, hit));
    EXPECT_NEAR(hit.t, 8.0f, 1e-5f);
    Hit slow;  // the same ray with a longer direction: t halves
    ASSERT_TRUE(scene.intersect(Ray{{0, 0, 0}, {0, 0, -2}}, slow));
    EXPECT_NEAR(slow.t, 4.0f, 1e-5f);
}

TEST(Transform, TranslationLeavesNormalsAlone) {
    const Scene scene(one_object(Triangle{{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}},
                                 glm::translate(glm::mat4(1.0f), vec3(5, 7, -3))));
    const Ray ray{{5, 7, 10}, {0, 0, -1}};
    Hit hit;
    ASSERT_TRUE(scene.intersect(ray, hit));
    const SurfacePoint sp = scene.surface(ray, hit);
    EXPECT_NEAR(sp.normal.z, 1.0f, 1e-6f);
    EXPECT_NEAR(sp.p.z, -3.0f, 1e-6f);
}

TEST(Transform, RotationTurnsTheNormal) {
    // A y-up plane turned 90 degrees about z faces -x.
    const Scene scene(one_object(Plane{{0, 1, 0}, 0},
                                 glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), vec3(0, 0, 1))));
    const Ray ray{{-4, 0.3f, 0.2f}, {1, 0, 0}};
    Hit hit;
    ASSERT_TRUE(scene.intersect(ray, hit));
    EXPECT_NEAR(hit.t, 4.0f, 1e-5f);
    const SurfacePoint sp = scene.surface(ray, hit);
    EXPECT_NEAR(sp.normal.x, -1.0f, 1e-5f);
}

TEST(Transform, SingularAndProjectiveMatricesAreRefused) {
    EXPECT_FALSE(Transform::from_matrix(glm::scale(glm::mat4(1.0f), vec3(1, 0, 1))));
    glm::mat4 projective(1.0f);
    projective[2][3] = -1.0f;
    EXPECT_FALSE(Transform::from_matrix(projective));
    EXPECT_TRUE(
        Transform::from_matrix(glm::scale(glm::mat4(1.0f), vec3(1e-4f))));  // tiny, not singular
}

}  // namespace
}  // namespace rt
