// Tracer::shade_found, the renderer's way to shade first hits eight at a time: the local
// term, the feelers and the bounces of each lane must be shade_hit's, bit for bit.
#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <vector>

#include <glm/geometric.hpp>

#include "core/tracer.h"
#include "test_util.h"

namespace rt {
namespace {

// Tracer::shade_found, the renderer's way to shade first hits, kPacketWidth at a time:
// each lane must be shade_hit's colour bit for bit, with the same rays counted, whether
// the lanes are neighbours (one material, mostly) or from all over the image.
void expect_lanes_as_alone(const Scene& scene, const TraceOptions& options) {
    std::vector<Ray> rays;
    std::vector<Hit> hits;
    for (int y = 0; y < scene.camera.rows; ++y) {
        for (int x = 0; x < scene.camera.cols; ++x) {
            Hit hit;
            const Ray r = scene.camera.ray(x, y);
            if (!scene.intersect(r, hit)) continue;
            rays.push_back(r);
            hits.push_back(hit);
        }
    }
    ASSERT_GT(hits.size(), 2u * kPacketWidth);
    const Tracer tracer(scene, options);
    RayCounts alone, together;
    int differing = 0;
    std::array<std::uint32_t, kPacketWidth> which;
    std::array<vec3, kPacketWidth> colours;
    for (std::size_t start = 0, n = 1, group = 0; start + kPacketWidth <= hits.size();
         start += n, n = n % kPacketWidth + 1, ++group) {
        for (std::size_t k = 0; k < n; ++k)
            which[k] =
                static_cast<std::uint32_t>(group % 2 ? (start + 97 * k) % hits.size() : start + k);
        tracer.shade_found(rays.data(), hits.data(), which.data(), static_cast<int>(n), together,
                           colours.data());
        for (std::size_t k = 0; k < n; ++k) {
            const vec3 c = tracer.shade_hit(rays[which[k]], hits[which[k]], alone);
            differing += std::memcmp(&c, &colours[k], sizeof(vec3)) != 0;
        }
    }
    EXPECT_EQ(differing, 0);
    EXPECT_EQ(together.shadow, alone.shadow);
    EXPECT_EQ(together.reflected, alone.reflected);
    EXPECT_EQ(together.refracted, alone.refracted);
}

TEST(ShadeFound, EachLaneIsShadeHitBitForBitOnTheShippedScenes) {
    for (const std::string& name : test::shipped_scene_names()) {
        SCOPED_TRACE(name);
        const Scene scene(test::shipped_scene(name, 48, 32));
        TraceOptions options;
        options.max_depth = 2;
        expect_lanes_as_alone(scene, options);
        options.shadows = false;
        options.max_depth = 0;
        expect_lanes_as_alone(scene, options);
    }
}

// What the shipped scenes lack: emission, a shininess that is no integer, a checker on
// vertex colours, a plane seen from behind, a light behind every surface, one so far
// away that its distance overflows, a directional light, and materials changing from one
// pixel to the next.
TEST(ShadeFound, EachLaneIsShadeHitBitForBitWhereLightsMisbehave) {
    SceneDescription desc;
    desc.camera = Camera::look_at({0, 3, 6}, {0, 0.5f, 0}, {0, 1, 0}, 50.0f, 40, 30);
    desc.ambient = vec3(0.15f, 0.2f, 0.25f);
    Material floor = test::plain(vec3(0.3f), vec3(0.7f, 0.6f, 0.5f), vec3(0.2f), 7.3f);
    floor.checker = Checker{vec3(1.0f, 0.2f, 0.1f), vec3(0.1f, 0.3f, 1.0f), 0.25f};
    Material glowing = test::plain(vec3(0.1f), vec3(0.4f), vec3(0.9f), 250.0f);
    glowing.emission = vec3(0.3f, 0.1f, 0.0f);
    glowing.reflectivity = 0.4f;
    desc.materials = {floor, glowing, test::plain(vec3(0.2f), vec3(0.1f, 0.8f, 0.3f))};
    desc.objects.push_back(Object{"floor", Plane{{0, 1, 0}, 0}, 0, {}});
    // A wall seen from behind (its normal faces away), tilted, off the origin.
    desc.objects.push_back(Object{"wall", Plane{{0.2f, -0.1f, -2.0f}, 6.0f}, 0, {}});
    desc.objects.push_back(Object{"ball", Sphere{{-0.8f, 0.7f, 0}, 0.7f}, 1, {}});
    desc.objects.push_back(Object{"ball 2", Sphere{{0.9f, 0.5f, 0.5f}, 0.5f}, 2, {}});
    TriangleMesh tinted;  // vertex colours under the floor's checker
    tinted.positions = {{-2.5f, 0.1f, -1.5f}, {-0.5f, 0.1f, -1.5f}, {-1.5f, 1.8f, -1.5f}};
    tinted.triangles = {{0, 1, 2}};
    tinted.corner_colours = {{1.0f, 0.2f, 0.2f}, {0.2f, 1.0f, 0.2f}, {0.2f, 0.2f, 1.0f}};
    desc.meshes.push_back(std::move(tinted));
    desc.objects.push_back(Object{"tinted", MeshRef{0, true}, 0, {}});
    desc.lights.push_back(Light{Light::Type::kPoint, {2, 5, 3}, {}, vec3(0.7f)});
    desc.lights.push_back(Light{Light::Type::kPoint, {0, -3, 0}, {}, vec3(0.5f)});  // below
    desc.lights.push_back(Light{Light::Type::kPoint, {3e38f, 3e38f, 0}, {}, vec3(0.5f)});
    desc.lights.push_back(
        Light{Light::Type::kDirectional, {}, glm::normalize(vec3(1, -2, -1)), vec3(0.3f)});
    for (bool shadows : {true, false}) {
        TraceOptions options;
        options.shadows = shadows;
        options.max_depth = 2;
        expect_lanes_as_alone(Scene(desc), options);
    }
    // Far from the file's zero: the checker is shifted by the origin (Scene::pattern_shift),
    // here by no whole number of its periods.
    desc.origin = glm::dvec3(1.0e5 + 0.3, 0.0, -2.0e5 + 0.7);
    expect_lanes_as_alone(Scene(std::move(desc)), TraceOptions{});
}

// Bounces many deep: two mirrors facing each other, a glass ball inside another (media
// nested), a glass block whose sides a ray inside meets past the critical angle (total
// internal reflection in the refracted ray's place: checked to happen), a weight limit
// that stops some paths early and none at all.
TEST(ShadeFound, EachLaneIsShadeHitBitForBitDepthAfterDepth) {
    SceneDescription desc;
    desc.camera = Camera::look_at({0.3f, 2.5f, 7}, {0, 1, 0}, {0, 1, 0}, 55.0f, 48, 36);
    desc.ambient = vec3(0.1f);
    Material floor = test::plain(vec3(0.3f), vec3(0.6f), vec3(0.2f), 12.0f);
    floor.checker = Checker{vec3(0.9f, 0.1f, 0.1f), vec3(0.9f, 0.9f, 0.2f), 0.5f};
    floor.reflectivity = 0.3f;
    Material mirror = test::plain(vec3(0.0f), vec3(0.05f), vec3(0.8f), 200.0f);
    mirror.reflectivity = 0.9f;
    Material glass = test::plain(vec3(0.0f), vec3(0.02f), vec3(0.9f), 300.0f);
    glass.reflectivity = 0.1f;
    glass.transparency = 0.85f;
    glass.ior = 1.5f;
    Material dense = glass;
    dense.ior = 2.4f;
    desc.materials = {floor, mirror, glass, dense};
    desc.objects.push_back(Object{"floor", Plane{{0, 1, 0}, 0}, 0, {}});
    desc.objects.push_back(Object{"left mirror", Plane{{1, 0, 0}, -3.0f}, 1, {}});
    desc.objects.push_back(Object{"right mirror", Plane{{-1, 0, 0}, -3.0f}, 1, {}});
    desc.objects.push_back(Object{"outer", Sphere{{0, 1.2f, 0}, 1.1f}, 2, {}});
    desc.objects.push_back(Object{"inner", Sphere{{0.1f, 1.2f, 0.1f}, 0.5f}, 3, {}});
    desc.objects.push_back(Object{"ball", Sphere{{-1.8f, 0.5f, -1}, 0.5f}, 1, {}});
    // A glass block: a ray that enters its top leaves through no side (a ball's symmetry
    // lets every ray out again; a cube's sides meet it past the critical angle).
    desc.meshes.push_back(
        test::box_mesh(vec3(1.2f, 0.0f, -0.5f), vec3(2.4f, 1.0f, 0.7f), test::Winding::kOutward));
    desc.objects.push_back(Object{"block", MeshRef{0, false}, 2, {}});
    desc.lights.push_back(Light{Light::Type::kPoint, {2, 6, 4}, {}, vec3(0.8f)});
    desc.lights.push_back(
        Light{Light::Type::kDirectional, {}, glm::normalize(vec3(-1, -2, -1)), vec3(0.3f)});
    const Scene scene(std::move(desc));
    // Some pixel's ray tree takes a total internal reflection, as the test means to.
    const auto internal = [](const RayNode& node, const auto& self) -> bool {
        if (node.total_internal_reflection) return true;
        for (const RayNode& child : node.children)
            if (self(child, self)) return true;
        return false;
    };
    int reflected_inside = 0;
    for (int y = 0; y < scene.camera.rows; y += 2)
        for (int x = 0; x < scene.camera.cols; x += 2)
            reflected_inside += internal(trace_ray_tree(scene, scene.camera, {}, x, y), internal);
    EXPECT_GT(reflected_inside, 10);
    for (const float min_weight : {0.0f, 0.05f}) {
        TraceOptions options;
        options.max_depth = 7;
        options.min_weight = min_weight;
        expect_lanes_as_alone(scene, options);
    }
    TraceOptions reflections_only;
    reflections_only.refractions = false;
    expect_lanes_as_alone(scene, reflections_only);
}

// A ball a thousand units across, its top seen from near by, lit by lights that graze
// it: a feeler leaving its surface cannot meet it again (it is convex), but tested
// against it, a quarter of them would, float's rounding giving hits at tiny t. Nothing
// else casts a shadow, so with feelers every colour is the colour without them, in the
// lanes (shade_found) and alone (shade_hit).
TEST(ShadeFound, FeelersDoNotMeetTheLargeBallTheyLeave) {
    SceneDescription desc;
    // Rows of whole packets, of 4, 8 or 16.
    desc.camera = Camera::look_at({0, 10, 5}, {0, 0, 0}, {0, 1, 0}, 60.0f, 48, 36);
    desc.materials = {test::plain(vec3(0.1f), vec3(0.8f), vec3(0.3f), 20.0f)};
    desc.objects.push_back(Object{"planet", Sphere{{0, -1000, 0}, 1000}, 0, {}});
    desc.lights.push_back(Light{Light::Type::kPoint, {50, 0.5f, 0}, {}, vec3(0.7f)});
    desc.lights.push_back(
        Light{Light::Type::kDirectional, {}, glm::normalize(vec3(-1, -0.01f, 0.2f)), vec3(0.5f)});
    const Scene scene(std::move(desc));
    TraceOptions with, without;
    with.max_depth = without.max_depth = 0;
    without.shadows = false;
    const Tracer feelers(scene, with), none(scene, without);
    RayCounts counts;
    int pixels = 0, differing = 0;
    for (int y = 0; y < scene.camera.rows; ++y) {
        std::array<Ray, kPacketWidth> rays;
        std::array<Hit, kPacketWidth> hits;
        std::array<std::uint32_t, kPacketWidth> which;
        std::array<vec3, kPacketWidth> lanes;
        for (int x0 = 0; x0 + kPacketWidth <= scene.camera.cols; x0 += kPacketWidth) {
            for (int k = 0; k < kPacketWidth; ++k) {
                rays[k] = scene.camera.ray(x0 + k, y);
                hits[k] = Hit{};
                ASSERT_TRUE(scene.intersect(rays[k], hits[k]));
                which[k] = static_cast<std::uint32_t>(k);
            }
            feelers.shade_found(rays.data(), hits.data(), which.data(), kPacketWidth, counts,
                                lanes.data());
            for (int k = 0; k < kPacketWidth; ++k) {
                const vec3 lit = none.shade_hit(rays[k], hits[k], counts);
                const vec3 alone = feelers.shade_hit(rays[k], hits[k], counts);
                differing += std::memcmp(&lit, &lanes[k], sizeof(vec3)) != 0;
                differing += std::memcmp(&lit, &alone, sizeof(vec3)) != 0;
                ++pixels;
            }
        }
    }
    EXPECT_GT(pixels, 1000);
    EXPECT_EQ(differing, 0);
}

}  // namespace
}  // namespace rt
