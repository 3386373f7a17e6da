// The ray tree at a pixel (core/ray_tree.h), recorded by the real tracer, checked against
// the tutorial's formulas worked out here, and against the image the renderer makes.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "core/renderer.h"
#include "core/scene_loader.h"
#include "core/tracer.h"
#include "test_util.h"

namespace rt {
namespace {

RayNode tree_of(const Scene& scene, const Ray& ray, const TraceOptions& options = {}) {
    RayTreeRecorder recorder;
    RayCounts counts;
    Tracer(scene, options, &recorder).trace_primary(ray, counts);
    return recorder.root();
}

void expect_colour_near(const vec3& a, const vec3& b) {
    EXPECT_NEAR(glm::length(a - b), 0.0f, 1e-4f) << a.x << " " << a.y << " " << a.z;
}

const RayNode* child(const RayNode& n, RayKind kind) {
    for (const RayNode& c : n.children)
        if (c.kind == kind) return &c;
    return nullptr;
}

// The primary ray's t at a pixel: |eye + t d - c| = r solved by hand, the nearer root.
TEST(RayTree, PrimaryHitIsTheSpheresNearerRoot) {
    SceneDescription desc;
    desc.camera = Camera::look_at({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 40.0f, 41, 41);
    desc.materials.push_back(test::plain(vec3(0.2f), vec3(0.5f)));
    desc.objects.push_back(Object{"ball", Sphere{{0, 0, 0}, 1.0f}, 0, {}});
    desc.lights.push_back(Light{Light::Type::kPoint, {2, 3, 4}, {}, vec3(1.0f)});
    const Scene scene(std::move(desc));
    const Ray ray = scene.camera.ray(23, 25);
    const float a = glm::dot(ray.dir, ray.dir), b = 2.0f * glm::dot(ray.dir, ray.origin),
                c = glm::dot(ray.origin, ray.origin) - 1.0f;
    const float t = (-b - std::sqrt(b * b - 4.0f * a * c)) / (2.0f * a);
    const RayNode root = tree_of(scene, ray);
    EXPECT_EQ(root.kind, RayKind::kPrimary);
    ASSERT_TRUE(root.hit);
    EXPECT_EQ(root.hit->name, "ball");
    EXPECT_NEAR(root.hit->t, t, 1e-5f);
    EXPECT_NEAR(glm::length(root.hit->point - (ray.origin + t * ray.dir)), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::length(root.hit->normal - glm::normalize(root.hit->point)), 0.0f, 1e-5f);
    ASSERT_EQ(root.children.size(), 1u);  // one light: one feeler, clear
    EXPECT_EQ(root.children[0].kind, RayKind::kShadow);
    EXPECT_FALSE(root.children[0].blocked);
    // A miss returns the background and has no hit.
    const RayNode miss = tree_of(scene, scene.camera.ray(0, 0));
    EXPECT_FALSE(miss.hit);
    EXPECT_EQ(miss.colour, scene.background);
}

// A blocked feeler: p(t) = p + t (l - p), blocked for t in (0, 1), by the ball in the way.
TEST(RayTree, BlockedFeelerNamesItsBlockerWithinTheSegment) {
    SceneDescription desc;
    desc.camera = Camera::look_at({0, 4, 4}, {0, 0, 0}, {0, 1, 0}, 30.0f, 31, 31);
    desc.materials.push_back(test::plain(vec3(0.3f), vec3(0.7f)));
    desc.lights.push_back(Light{Light::Type::kPoint, {0, 10, 0}, {}, vec3(1.0f)});
    desc.objects.push_back(Object{"floor", Plane{{0, 1, 0}, 0}, 0, {}});
    desc.objects.push_back(Object{"blocker", Sphere{{0, 5, 0}, 1}, 0, {}});
    const Scene scene(std::move(desc));
    const RayNode root = tree_of(scene, scene.camera.ray(15, 15));
    ASSERT_TRUE(root.hit);
    EXPECT_EQ(root.hit->name, "floor");
    const RayNode* feeler = child(root, RayKind::kShadow);
    ASSERT_TRUE(feeler);
    EXPECT_EQ(feeler->light, 0);
    EXPECT_TRUE(feeler->blocked);
    ASSERT_TRUE(feeler->blocker);
    EXPECT_EQ(feeler->blocker->name, "blocker");
    EXPECT_GT(feeler->blocker->t, 0.0f);
    EXPECT_LT(feeler->blocker->t, 1.0f);
    // The sphere's bottom at y = 4, the light at y = 10, the floor point near y = 0.
    EXPECT_NEAR(feeler->blocker->t, 0.4f, 0.01f);
}

// A mirror: the reflected ray goes d - 2 (d . n) n from the hit, and the pixel is the
// local term plus the reflectivity times what it brought back.
TEST(RayTree, MirrorReflectsAboutTheNormal) {
    SceneDescription desc;
    desc.camera = Camera::look_at({0, 1, 5}, {0, 0, 0}, {0, 1, 0}, 40.0f, 41, 41);
    Material mirror = test::plain(vec3(0.05f), vec3(0.1f));
    mirror.reflectivity = 0.8f;
    desc.materials.push_back(mirror);
    desc.materials.push_back(test::plain(vec3(0.4f), vec3(0.6f)));
    desc.objects.push_back(Object{"mirror ball", Sphere{{0, 0, 0}, 1.0f}, 0, {}});
    desc.objects.push_back(Object{"floor", Plane{{0, 1, 0}, -1}, 1, {}});
    desc.lights.push_back(Light{Light::Type::kPoint, {2, 3, 4}, {}, vec3(1.0f)});
    const Scene scene(std::move(desc));
    const Ray ray = scene.camera.ray(20, 14);  // below the ball's centre: it sees the floor
    const RayNode root = tree_of(scene, ray);
    ASSERT_TRUE(root.hit);
    const RayNode* r = child(root, RayKind::kReflection);
    ASSERT_TRUE(r);
    const vec3 d = glm::normalize(ray.dir), n = root.hit->normal;
    const vec3 expected = d - 2.0f * glm::dot(d, n) * n;
    EXPECT_NEAR(glm::length(r->direction - expected), 0.0f, 1e-5f);
    EXPECT_NEAR(r->weight, 0.8f, 1e-6f);
    ASSERT_TRUE(r->hit);
    EXPECT_EQ(r->hit->name, "floor");
    EXPECT_NEAR(glm::length(root.colour - (root.local + 0.8f * r->colour)), 0.0f, 1e-5f);
}

// A glass ball: the ray refracts in, then out, and the tree says so in order.
TEST(RayTree, GlassBallRefractsInAndOut) {
    SceneDescription desc;
    desc.camera = Camera::look_at({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 40.0f, 41, 41);
    desc.materials.push_back(test::clear_glass(0.9f));
    desc.materials.push_back(test::plain(vec3(1.0f), vec3(0.0f)));
    desc.objects.push_back(Object{"glass ball", Sphere{{0, 0, 0}, 1.0f}, 0, {}});
    desc.objects.push_back(Object{"wall", Plane{{0, 0, 1}, -4}, 1, {}});
    const Scene scene(std::move(desc));
    const RayNode root = tree_of(scene, scene.camera.ray(22, 21));
    const RayNode* in = child(root, RayKind::kRefraction);
    ASSERT_TRUE(in);
    ASSERT_TRUE(in->hit);
    EXPECT_EQ(in->hit->name, "glass ball");  // the far side, from inside
    const RayNode* out = child(*in, RayKind::kRefraction);
    ASSERT_TRUE(out);
    ASSERT_TRUE(out->hit);
    EXPECT_EQ(out->hit->name, "wall");
    EXPECT_NEAR(out->weight, 0.81f, 1e-6f);
}

// Total internal reflection (the block of Refraction/GlassWinding, worked out there): in
// through the top at 60 degrees, the side x = 1 met at 54.74, past the critical 41.8: the
// tree shows a reflection marked as such where the refraction would be, meeting the bottom
// at x = 0.586, then the way out, down to the floor at 60 degrees again.
TEST(RayTree, TotalInternalReflectionIsAReflectionInThePlaceOfARefraction) {
    SceneDescription desc;
    desc.ambient = vec3(1.0f);
    desc.materials.push_back(test::clear_glass(0.9f));
    desc.materials.push_back(test::plain({1.0f, 0.0f, 0.0f}, vec3(0.0f)));
    desc.meshes.push_back(test::box_mesh({-10, -2, -10}, {1, 0, 10}, test::Winding::kOutward));
    desc.objects.push_back(Object{"block", MeshRef{0, false}, 0, {}});
    desc.objects.push_back(Object{"floor", Plane{{0, 1, 0}, -3}, 1, {}});
    const Scene scene(std::move(desc));
    const float a = glm::radians(60.0f);
    const RayNode root =
        tree_of(scene, Ray{{-std::sin(a), std::cos(a), 0.0f}, {std::sin(a), -std::cos(a), 0.0f}});
    const RayNode* in = child(root, RayKind::kRefraction);
    ASSERT_TRUE(in);
    const RayNode* mirrored = child(*in, RayKind::kReflection);
    ASSERT_TRUE(mirrored);
    EXPECT_TRUE(mirrored->total_internal_reflection);
    ASSERT_TRUE(mirrored->hit);
    EXPECT_NEAR(mirrored->hit->point.x, 0.586f, 0.01f);  // the bottom, from inside
    EXPECT_EQ(child(*in, RayKind::kRefraction), nullptr);
    const RayNode* out = child(*mirrored, RayKind::kRefraction);
    ASSERT_TRUE(out);
    ASSERT_TRUE(out->hit);
    EXPECT_EQ(out->hit->name, "floor");
    EXPECT_NEAR(out->hit->point.x, 0.586f - std::tan(a), 0.01f);  // out at 60 degrees again
    expect_colour_near(root.colour, {0.729f, 0.0f, 0.0f});
}

// Two facing mirrors: the tree is as deep as --max-depth allows, never deeper.
TEST(RayTree, DepthNeverExceedsTheMaximum) {
    SceneDescription desc;
    desc.camera = test::axis_camera({0, 0, 5});
    Material mirror = test::plain(vec3(0.1f), vec3(0.0f));
    mirror.reflectivity = 0.9f;
    desc.materials.push_back(mirror);
    desc.objects.push_back(Object{"front", Plane{{0, 0, 1}, 0}, 0, {}});
    desc.objects.push_back(Object{"back", Plane{{0, 0, 1}, 20}, 0, {}});
    const Scene scene(std::move(desc));
    for (int depth : {0, 1, 4}) {
        TraceOptions options;
        options.max_depth = depth;
        options.min_weight = 0.0f;
        EXPECT_EQ(bounce_depth(tree_of(scene, scene.camera.ray(15, 15), options)), depth);
    }
}

// Every node's colour is its local term plus its children's, weighted by the share each
// child carries of it; so the root's colour is the pixel's.
void expect_sums(const RayNode& n) {
    if (n.kind == RayKind::kShadow || !n.hit) return;
    vec3 sum = n.local;
    for (const RayNode& c : n.children) {
        if (c.kind == RayKind::kShadow) continue;
        sum += (c.weight / n.weight) * c.colour;
        expect_sums(c);
    }
    EXPECT_NEAR(glm::length(sum - n.colour), 0.0f, 1e-5f) << ray_kind_name(n.kind);
}

TEST(RayTree, TheTreeSumsToThePixelOfTheRenderedImage) {
    for (const char* name : {"whitted.json", "tutorial.json", "cornell.json"}) {
        LoadedScene loaded = load_scene(test::scene_path(name));
        loaded.scene.camera = loaded.scene.camera.resized(48, 36);
        const Scene scene(std::move(loaded.scene));
        const Image image = render(scene, {});
        for (int y = 0; y < 36; y += 5)
            for (int x = 0; x < 48; x += 5) {
                const RayNode root = tree_of(scene, scene.camera.ray(x, y));
                const vec3 pixel = image.pixels[static_cast<std::size_t>(y) * 48 + x];
                EXPECT_NEAR(glm::length(root.colour - pixel), 0.0f, 1e-5f)
                    << name << " " << x << "," << y;
                expect_sums(root);
            }
    }
}

}  // namespace
}  // namespace rt

namespace rt {
namespace {

std::size_t node_count(const RayNode& n) {
    std::size_t count = 1;
    for (const RayNode& c : n.children) count += node_count(c);
    return count;
}

// What the viewer draws: one segment a ray, in the tree's order; a hit ends at its point,
// a point light's feeler at the light, a miss after the fixed length.
TEST(RayTree, SegmentsEndAtHitsLightsOrAFixedLength) {
    LoadedScene loaded = load_scene(test::scene_path("whitted.json"));
    loaded.scene.camera = loaded.scene.camera.resized(160, 120);
    const Scene scene(std::move(loaded.scene));
    const RayNode root =
        trace_ray_tree(scene, scene.camera, {}, 100, 120 - 1 - 70);  // the glass ball
    const std::vector<RaySegment> segments = ray_segments(root, scene.lights, 7.0f);
    ASSERT_EQ(segments.size(), node_count(root));
    std::size_t i = 0, misses = 0, feelers = 0;
    const auto check = [&](const auto& self, const RayNode& n) -> void {
        const RaySegment& s = segments[i++];
        EXPECT_EQ(s.kind, n.kind);
        EXPECT_EQ(s.a, n.origin);
        if (n.kind == RayKind::kShadow) {
            ++feelers;
            EXPECT_EQ(s.blocked, n.blocked);
            EXPECT_NEAR(glm::length(s.b - scene.lights[static_cast<std::size_t>(n.light)].position),
                        0.0f, 1e-4f);
        } else if (n.hit) {
            EXPECT_EQ(s.b, n.hit->point);
        } else {
            ++misses;
            EXPECT_TRUE(s.miss);
            EXPECT_NEAR(glm::length(s.b - s.a), 7.0f, 1e-4f);
        }
        for (const RayNode& c : n.children) self(self, c);
    };
    check(check, root);
    EXPECT_GT(feelers, 0u);
    EXPECT_GT(misses, 0u);
}

}  // namespace
}  // namespace rt
