// Whitted shading on scenes whose right answer can be worked out by hand.
#include <gtest/gtest.h>

#include <vector>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "core/renderer.h"
#include "core/tracer.h"
#include "test_util.h"

namespace rt {
namespace {

void expect_colour(const vec3& got, const vec3& want, float tol = 1e-5f) {
    EXPECT_NEAR(got.x, want.x, tol);
    EXPECT_NEAR(got.y, want.y, tol);
    EXPECT_NEAR(got.z, want.z, tol);
}

vec3 centre_pixel(const Scene& scene, const TraceOptions& options = {}) {
    RayCounts counts;
    return Tracer(scene, options)
        .trace_primary(scene.camera.ray(scene.camera.cols / 2, scene.camera.rows / 2), counts);
}

TEST(Reflect, MirrorDirectionByHand) {
    const vec3 d = reflect_dir({1, -1, 0}, {0, 1, 0});
    expect_colour(d, {1, 1, 0});
}

TEST(Refract, SnellAtFortyFiveDegreesIntoGlass) {
    const vec3 d = glm::normalize(vec3(1, -1, 0));
    const Refraction r = refract_dir(d, {0, 1, 0}, 1.0f, 1.5f);
    ASSERT_FALSE(r.total_internal_reflection);
    const float sin_t = std::sin(glm::radians(45.0f)) / 1.5f;  // n1 sin i = n2 sin t
    EXPECT_NEAR(r.dir.x, sin_t, 1e-6f);
    EXPECT_NEAR(r.dir.y, -std::sqrt(1.0f - sin_t * sin_t), 1e-6f);
    EXPECT_NEAR(glm::length(r.dir), 1.0f, 1e-6f);
}

TEST(Refract, NormalIncidenceGoesStraightThrough) {
    const Refraction r = refract_dir({0, -1, 0}, {0, 1, 0}, 1.0f, 1.33f);
    ASSERT_FALSE(r.total_internal_reflection);
    expect_colour(r.dir, {0, -1, 0});
}

TEST(Refract, TotalInternalReflectionPastTheCriticalAngle) {
    // Glass to air: critical angle asin(1/1.5) = 41.8 degrees.
    const vec3 at45 = glm::normalize(vec3(1, -1, 0));
    EXPECT_TRUE(refract_dir(at45, {0, 1, 0}, 1.5f, 1.0f).total_internal_reflection);
    const vec3 at30{std::sin(glm::radians(30.0f)), -std::cos(glm::radians(30.0f)), 0};
    const Refraction r = refract_dir(at30, {0, 1, 0}, 1.5f, 1.0f);
    ASSERT_FALSE(r.total_internal_reflection);
    EXPECT_NEAR(r.dir.x, 0.75f, 1e-6f);  // sin t = 1.5 sin 30
}

// A sphere lit from the eye: at the centre pixel n = l = v, so n.l = 1 and r.v = 1 and
// I = ka Ia + (kd + ks) I_l.
TEST(Phong, LitSphereCentreEqualsHandValue) {
    SceneDescription desc;
    desc.camera = test::axis_camera({0, 0, 5});
    desc.ambient = vec3(0.2f, 0.3f, 0.4f);
    desc.materials.push_back(
        test::plain({0.5f, 0.4f, 0.3f}, {0.6f, 0.2f, 0.1f}, vec3(0.25f), 20.0f));
    desc.lights.push_back(Light{Light::Type::kPoint, {0, 0, 5}, {}, {0.9f, 0.8f, 0.7f}});
    desc.objects.push_back(Object{"ball", Sphere{{0, 0, 0}, 1}, 0, {}});
    const Scene scene(std::move(desc));
    const vec3 expected = vec3(0.5f, 0.4f, 0.3f) * scene.ambient +
                          (vec3(0.6f, 0.2f, 0.1f) + vec3(0.25f)) * vec3(0.9f, 0.8f, 0.7f);
    expect_colour(centre_pixel(scene), expected);
}

TEST(Phong, DiffuseFollowsTheCosineOfTheLight) {
    // Light at 60 degrees from the normal, no specular: I = kd cos 60 I_l.
    SceneDescription desc;
    desc.camera = test::axis_camera({0, 0, 5});
    desc.ambient = vec3(0.0f);
    desc.materials.push_back(test::plain(vec3(0.0f), vec3(0.8f)));
    desc.lights.push_back(Light{
        Light::Type::kDirectional, {}, glm::normalize(vec3(-std::sqrt(3.0f), 0, -1)), vec3(1.0f)});
    desc.objects.push_back(Object{"wall", Plane{{0, 0, 1}, 0}, 0, {}});
    const Scene scene(std::move(desc));
    expect_colour(centre_pixel(scene), vec3(0.4f));
}

// A ball hangs between a light and the floor: the floor point under it gets ka Ia only.
SceneDescription shadow_scene() {
    SceneDescription desc;
    desc.camera = Camera::look_at({0, 4, 4}, {0, 0, 0}, {0, 1, 0}, 30.0f, 31, 31);
    desc.ambient = vec3(0.3f);
    desc.materials.push_back(test::plain(vec3(0.5f), vec3(0.7f)));
    desc.lights.push_back(Light{Light::Type::kPoint, {0, 10, 0}, {}, vec3(1.0f)});
    desc.objects.push_back(Object{"floor", Plane{{0, 1, 0}, 0}, 0, {}});
    desc.objects.push_back(Object{"blocker", Sphere{{0, 5, 0}, 1}, 0, {}});
    return desc;
}

TEST(Shadows, PointInShadowGetsAmbientOnly) {
    const Scene scene(shadow_scene());
    expect_colour(centre_pixel(scene), vec3(0.5f * 0.3f));
    TraceOptions no_shadows;
    no_shadows.shadows = false;  // the same point, lit: ambient plus kd n.l I_l with n.l = 1
    expect_colour(centre_pixel(scene, no_shadows), vec3(0.5f * 0.3f + 0.7f));
}

TEST(Shadows, FeelerStopsAtThePointLight) {
    // An occluder beyond the light casts no shadow: the feeler covers t in (0, 1) only.
    SceneDescription desc = shadow_scene();
    std::get<Sphere>(desc.objects[1].shape).centre = {0, 12, 0};
    const Scene scene(std::move(desc));
    expect_colour(centre_pixel(scene), vec3(0.5f * 0.3f + 0.7f));
}

// A mirror facing the camera shows exactly what is behind the camera: a wall lit by
// ambient light only, of colour ka Ia.
SceneDescription mirror_scene(float reflectivity) {
    SceneDescription desc;
    desc.camera = test::axis_camera({0, 0, 5});
    desc.ambient = vec3(1.0f);
    Material mirror = test::plain(vec3(0.0f), vec3(0.0f));
    mirror.reflectivity = reflectivity;
    desc.materials.push_back(mirror);
    desc.materials.push_back(test::plain({0.2f, 0.5f, 0.7f}, vec3(0.0f)));
    desc.objects.push_back(Object{"mirror", Plane{{0, 0, 1}, 0}, 0, {}});
    desc.objects.push_back(Object{"wall", Plane{{0, 0, 1}, 20}, 1, {}});
    return desc;
}

TEST(Reflection, MirrorShowsExactlyTheColourItFaces) {
    expect_colour(centre_pixel(Scene(mirror_scene(1.0f))), {0.2f, 0.5f, 0.7f});
    expect_colour(centre_pixel(Scene(mirror_scene(0.5f))), {0.1f, 0.25f, 0.35f});
}

TEST(Reflection, StopsAtMaxDepthBetweenTwoMirrors) {
    SceneDescription desc = mirror_scene(0.9f);
    desc.materials[1] = desc.materials[0];  // two facing mirrors: an endless corridor
    const Scene scene(std::move(desc));
    for (int depth : {0, 1, 3, 7}) {
        TraceOptions options;
        options.max_depth = depth;
        options.min_weight = 0.0f;
        RayCounts counts;
        Tracer(scene, options).trace_primary(scene.camera.ray(15, 15), counts);
        EXPECT_EQ(counts.reflected, static_cast<std::uint64_t>(depth)) << depth;
    }
}

TEST(Reflection, StopsWhenTheWeightFallsUnderTheThreshold) {
    SceneDescription desc = mirror_scene(0.5f);
    desc.materials[1] = desc.materials[0];
    const Scene scene(std::move(desc));
    TraceOptions options;
    options.max_depth = 50;
    options.min_weight = 0.1f;  // 0.5^n >= 0.1 for n = 1..3
    RayCounts counts;
    Tracer(scene, options).trace_primary(scene.camera.ray(15, 15), counts);
    EXPECT_EQ(counts.reflected, 3u);
}

TEST(Refraction, RayThroughAGlassBallCentreComesOutStraight) {
    // Through the centre the ray meets both surfaces head-on and is not bent: the pixel
    // shows the wall behind, weighted by the transparency at each of the two crossings.
    SceneDescription desc;
    desc.camera = test::axis_camera({0, 0, 5});
    desc.ambient = vec3(1.0f);
    desc.materials.push_back(test::clear_glass(0.8f));
    desc.materials.push_back(test::plain({0.9f, 0.6f, 0.3f}, vec3(0.0f)));
    desc.objects.push_back(Object{"ball", Sphere{{0, 0, 0}, 1}, 0, {}});
    desc.objects.push_back(Object{"wall", Plane{{0, 0, 1}, -10}, 1, {}});
    const Scene scene(std::move(desc));
    RayCounts counts;
    const vec3 c = Tracer(scene, {}).trace_primary(scene.camera.ray(15, 15), counts);
    expect_colour(c, 0.64f * vec3(0.9f, 0.6f, 0.3f));
    EXPECT_EQ(counts.refracted, 2u);
}

using test::clear_glass;

// The specular term away from the mirror direction, where r.v < 1 and the exponent
// shows: a plane at y = 0 seen from straight above, lit from 45 degrees. r.v = cos 45,
// so I = ks (1/sqrt 2)^10 I_l = ks I_l / 32 (without the power it would be ks I_l 0.707).
TEST(Phong, SpecularIsRaisedToTheShininess) {
    SceneDescription desc;
    desc.materials.push_back(test::plain(vec3(0.0f), vec3(0.0f), vec3(0.8f), 10.0f));
    desc.lights.push_back(Light{Light::Type::kPoint, {1, 1, 0}, {}, vec3(1.0f)});
    desc.objects.push_back(Object{"floor", Plane{{0, 1, 0}, 0}, 0, {}});
    const Scene scene(std::move(desc));
    const Ray down{{0, 1, 0}, {0, -1, 0}};
    Hit hit;
    ASSERT_TRUE(scene.intersect(down, hit));
    RayCounts counts;
    const vec3 c = Tracer(scene, {}).phong(down, scene.surface(down, hit), counts);
    expect_colour(c, vec3(0.8f / 32.0f), 1e-5f);
}

using test::box_mesh;
using test::Winding;

class GlassWinding : public ::testing::TestWithParam<Winding> {};
INSTANTIATE_TEST_SUITE_P(Refraction, GlassWinding,
                         ::testing::Values(Winding::kOutward, Winding::kInward),
                         [](const auto& param_info) {
                             return param_info.param == Winding::kOutward ? "outward" : "inward";
                         });

// A glass slab between y = 0 and y = -1, and under it at y = -3 a floor that is red only
// in a band around where Snell's law puts the ray, worked out by hand: entering at 50
// degrees, sin t = sin 50 / 1.5 gives t = 30.71 degrees across the slab (tan t =
// 0.5937), out again at 50 degrees for 2 units (2 tan 50 = 2.3835): x = 2.9772. Unbent,
// the ray would land at 3 tan 50 = 3.575; with the indices swapped (leaving where it
// enters, as a tracer that trusts the winding does with an inward slab) it could not
// enter at all (sin t > 1).
TEST_P(GlassWinding, ObliqueRayFollowsSnellThroughASlab) {
    SceneDescription desc;
    desc.ambient = vec3(1.0f);
    desc.materials.push_back(clear_glass(1.0f));
    desc.materials.push_back(test::plain({1.0f, 0.0f, 0.0f}, vec3(0.0f)));  // red band
    desc.materials.push_back(test::plain({0.0f, 0.0f, 1.0f}, vec3(0.0f)));  // blue elsewhere
    desc.meshes.push_back(box_mesh({-50, -1, -50}, {50, 0, 50}, GetParam()));
    desc.objects.push_back(Object{"slab", MeshRef{0, false}, 0, {}});
    const float x = 2.9772f, half = 0.03f;
    desc.objects.push_back(
        Object{"band",
               Triangle{{x - half, -2.999f, -50}, {x + half, -2.999f, -50}, {x, -2.999f, 50}},
               1,
               {}});
    desc.objects.push_back(Object{"floor", Plane{{0, 1, 0}, -3}, 2, {}});
    const Scene scene(std::move(desc));
    const float a = glm::radians(50.0f);
    const Ray ray{{-std::sin(a), std::cos(a), 0.0f}, {std::sin(a), -std::cos(a), 0.0f}};
    RayCounts counts;
    const vec3 c = Tracer(scene, {}).trace_primary(ray, counts);
    expect_colour(c, {1.0f, 0.0f, 0.0f}, 1e-4f);
    EXPECT_EQ(counts.refracted, 2u);
    EXPECT_EQ(counts.reflected, 0u);
}

// Total internal reflection: a ray enters the top of a glass block (x <= 1, -2 <= y <= 0)
// at 60 degrees, crosses at t = 35.26 degrees (sin t = sin 60 / 1.5) and meets the side
// x = 1 at 54.74 degrees, past the critical angle of 41.8: no light crosses, what would
// have been transmitted is reflected, and the ray leaves through the bottom at x = 0.586
// to a red floor. Each of the three crossings keeps kt of it: kt^3 red. Going black, or
// out through the side, would be a bug.
TEST_P(GlassWinding, TotalInternalReflectionReflectsInsteadOfGoingBlack) {
    SceneDescription desc;
    desc.ambient = vec3(1.0f);
    desc.materials.push_back(clear_glass(0.9f));
    desc.materials.push_back(test::plain({1.0f, 0.0f, 0.0f}, vec3(0.0f)));
    desc.meshes.push_back(box_mesh({-10, -2, -10}, {1, 0, 10}, GetParam()));
    desc.objects.push_back(Object{"block", MeshRef{0, false}, 0, {}});
    desc.objects.push_back(Object{"floor", Plane{{0, 1, 0}, -3}, 1, {}});
    const Scene scene(std::move(desc));
    const float a = glm::radians(60.0f);
    const Ray ray{{-std::sin(a), std::cos(a), 0.0f}, {std::sin(a), -std::cos(a), 0.0f}};
    RayCounts counts;
    const vec3 c = Tracer(scene, {}).trace_primary(ray, counts);
    expect_colour(c, {0.729f, 0.0f, 0.0f}, 1e-4f);
    EXPECT_EQ(counts.reflected, 1u);
    EXPECT_EQ(counts.refracted, 2u);
}

// Glass in glass: a ball of index 1.5 inside another of 1.5 is no boundary at all, so
// every ray through the pair must come out as through the outer ball alone (to float's
// rounding: the wall behind is lit smoothly, so a ray moved by an offset changes its
// colour by far less than 1e-3). A tracer that takes every entry as from air bends the
// rays at the inner ball.
TEST(Refraction, GlassInGlassOfTheSameIndexIsInvisible) {
    const auto scene_with = [](bool inner) {
        SceneDescription desc;
        desc.camera = test::axis_camera({0, 0, 6}, 41);
        desc.ambient = vec3(1.0f);
        desc.materials.push_back(clear_glass(1.0f));
        desc.materials.push_back(test::plain(vec3(0.0f), vec3(1.0f)));
        desc.lights.push_back(Light{Light::Type::kPoint, {0.5f, 0.5f, -3.0f}, {}, vec3(1.0f)});
        desc.objects.push_back(Object{"outer", Sphere{{0, 0, 0}, 1.0f}, 0, {}});
        if (inner) desc.objects.push_back(Object{"inner", Sphere{{0.3f, 0.2f, 0.1f}, 0.5f}, 0, {}});
        desc.objects.push_back(Object{"wall", Plane{{0, 0, 1}, -4}, 1, {}});
        return desc;
    };
    const Scene alone(scene_with(false)), nested(scene_with(true));
    TraceOptions options;
    options.max_depth = 8;
    int bent_by_the_inner_ball = 0;
    for (int y = 0; y < 41; ++y)
        for (int x = 0; x < 41; ++x) {
            RayCounts counts;
            const vec3 a = Tracer(alone, options).trace_primary(alone.camera.ray(x, y), counts);
            const vec3 b = Tracer(nested, options).trace_primary(nested.camera.ray(x, y), counts);
            bent_by_the_inner_ball += glm::length(a - b) > 1e-3f;
        }
    EXPECT_EQ(bent_by_the_inner_ball, 0);
}

TEST(MediumStack, EntersLeavesAndNests) {
    const MediumStack air;
    EXPECT_EQ(air.ior(), 1.0f);
    const auto into_a = air.cross(7, 1.5f);  // air -> A
    EXPECT_EQ(into_a.eta_from, 1.0f);
    EXPECT_EQ(into_a.eta_to, 1.5f);
    const auto into_b = into_a.after.cross(9, 2.0f);  // A -> B inside it
    EXPECT_EQ(into_b.eta_from, 1.5f);
    EXPECT_EQ(into_b.eta_to, 2.0f);
    const auto out_of_b = into_b.after.cross(9, 2.0f);  // B -> back into A
    EXPECT_EQ(out_of_b.eta_from, 2.0f);
    EXPECT_EQ(out_of_b.eta_to, 1.5f);
    const auto out_of_a = out_of_b.after.cross(7, 1.5f);  // A -> air
    EXPECT_EQ(out_of_a.eta_to, 1.0f);
    EXPECT_TRUE(out_of_a.after.empty());
    // Overlapping glass: leaving A while still inside B passes straight on, in B.
    const auto overlap = into_b.after.cross(7, 1.5f);
    EXPECT_EQ(overlap.eta_from, overlap.eta_to);
    EXPECT_EQ(overlap.after.size(), 1);
    EXPECT_EQ(overlap.after.ior(), 2.0f);
    // Deeper than the capacity: the outermost is forgotten, the innermost stays right.
    MediumStack deep;
    for (std::uint32_t i = 0; i < MediumStack::kCapacity + 3; ++i)
        deep = deep.cross(i, 1.0f + 0.1f * static_cast<float>(i)).after;
    EXPECT_EQ(deep.size(), MediumStack::kCapacity);
    EXPECT_FLOAT_EQ(deep.ior(), 1.0f + 0.1f * (MediumStack::kCapacity + 2));
}

// The checker's cells by hand: the parity of floor(x / s) + floor(y / s) + floor(z / s),
// negative coordinates included, and defined far past where integers would overflow.
TEST(Checker, CellsAlternateByTheSumOfTheirIndices) {
    const Checker c{vec3(1.0f), vec3(0.0f), 2.0f};
    EXPECT_EQ(c.at({1, 1, 1}), c.colour_a);      // cell (0, 0, 0)
    EXPECT_EQ(c.at({3, 1, 1}), c.colour_b);      // (1, 0, 0)
    EXPECT_EQ(c.at({3, 3, 1}), c.colour_a);      // (1, 1, 0)
    EXPECT_EQ(c.at({3, 3, 3}), c.colour_b);      // (1, 1, 1)
    EXPECT_EQ(c.at({-1, 1, 1}), c.colour_b);     // (-1, 0, 0)
    EXPECT_EQ(c.at({-1, -1, 1}), c.colour_a);    // (-1, -1, 0)
    EXPECT_EQ(c.at({-3, 1, 1}), c.colour_a);     // (-2, 0, 0)
    EXPECT_EQ(c.at({6e30f, 1, 1}), c.colour_a);  // an even cell index: float holds no odd one there
    // A shift by whole periods (Checker::shift folds the origin into one) changes nothing.
    const vec3 shift = c.shift({4.0e7 + 3.0, 0.0, 0.0});
    EXPECT_NEAR(shift.x, 3.0f, 1e-6f);
    EXPECT_EQ(c.at(vec3(0.5f, 1, 1) + shift), c.at({3.5f, 1, 1}));
}

// A point light exactly at the surface point gives that point ambient light only, not
// NaN (normalising the zero vector to the light).
TEST(Phong, LightOnTheSurfaceGivesAmbientNotNaN) {
    SceneDescription desc;
    desc.ambient = vec3(0.25f);
    desc.materials.push_back(test::plain(vec3(1.0f), vec3(0.8f), vec3(0.5f), 8.0f));
    desc.lights.push_back(Light{Light::Type::kPoint, {0, 0, 0}, {}, vec3(1.0f)});
    desc.objects.push_back(Object{"floor", Plane{{0, 1, 0}, 0}, 0, {}});
    const Scene scene(std::move(desc));
    for (bool shadows : {true, false}) {  // with feelers, and with no feeler to stop it
        TraceOptions options;
        options.shadows = shadows;
        RayCounts counts;
        const vec3 c = Tracer(scene, options).trace_primary(Ray{{0, 1, 0}, {0, -1, 0}}, counts);
        expect_colour(c, vec3(0.25f));
    }
}

// A light above the surface but nearer to it than the feeler's offset (here 1000 units
// out, 256 float steps are 0.016 units; the light is 0.005 above the floor): the feeler
// from the offset point would run away from the light, so the true surface point decides,
// and the light is in front of it: lit, as with no feelers.
TEST(Shadows, ALightNearerThanTheFeelersOffsetStillLights) {
    SceneDescription desc;
    desc.ambient = vec3(0.0f);
    desc.materials.push_back(test::plain(vec3(0.0f), vec3(0.8f)));
    desc.lights.push_back(Light{Light::Type::kPoint, {0, 1000.005f, 0}, {}, vec3(1.0f)});
    desc.objects.push_back(Object{"floor", Plane{{0, 1, 0}, 1000}, 0, {}});
    const Scene scene(std::move(desc));
    for (bool shadows : {true, false}) {
        TraceOptions options;
        options.shadows = shadows;
        RayCounts counts;
        const vec3 c = Tracer(scene, options).trace_primary(Ray{{0, 1001, 0}, {0, -1, 0}}, counts);
        expect_colour(c, vec3(0.8f), 1e-3f);
    }
}

}  // namespace
}  // namespace rt
