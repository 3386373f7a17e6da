// Every acceleration structure must find exactly what testing every primitive with the
// tutorial's formula finds: the same primitive, at the same t (to rounding).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <random>
#include <span>

#include <glm/geometric.hpp>

#include "core/accel.h"
#include "core/bvh.h"
#include "core/mesh.h"
#include "core/scene.h"
#include "core/shapes.h"
#include "core/tessellate.h"
#include "core/triangle4.h"
#include "core/wide_bvh.h"
#include "test_util.h"

namespace rt {

void PrintTo(AccelKind k, std::ostream* os) { *os << accel_name(k); }

namespace {

using test::random_point;

TriangleMesh random_soup(std::mt19937& rng, int count, AccelKind kind) {
    TriangleMesh mesh;
    std::uniform_real_distribution<float> size(0.05f, 1.0f);
    for (int i = 0; i < count; ++i) {
        const vec3 centre = random_point(rng, 10.0f);
        const float s = size(rng);
        const auto base = static_cast<std::uint32_t>(mesh.positions.size());
        for (int k = 0; k < 3; ++k) mesh.positions.push_back(centre + s * random_point(rng, 1.0f));
        mesh.triangles.push_back({base, base + 1, base + 2});
    }
    mesh.build(kind);
    return mesh;
}

class AccelTest : public ::testing::TestWithParam<AccelKind> {};

TEST_P(AccelTest, MeshHitsMatchTheTutorialsTestOnEveryTriangle) {
    std::mt19937 rng(7);
    const TriangleMesh mesh = random_soup(rng, 3000, GetParam());
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
        EXPECT_NEAR(hit.t, best, 1e-5f * best + 1e-6f)
            << "ray " << i;  // relative, and to the scene size 10
        EXPECT_FALSE(mesh.occluded(ray, best * 0.999f))
            << "nothing is closer than the closest hit, ray " << i;
        EXPECT_TRUE(mesh.occluded(ray, hit.t * 1.0001f))
            << "the closest hit blocks a feeler that reaches just past it, ray " << i;
    }
    EXPECT_GT(hits, 500);  // the test means something only if many rays hit
}

// A mesh built again over fewer triangles reuses its arrays, which a build leaves
// unwritten until it fills them (core/large_array.h): the spare lanes of its triangle
// packs must be emptied, or the triangles of the earlier build would still be hit there.
TEST_P(AccelTest, ARebuildLeavesNoEarlierTriangleBehind) {
    TriangleMesh mesh;
    const auto build = [&](int copies, vec3 corner) {  // a half of the unit square, stacked
        mesh.positions = {{0, 0, 0}, corner, {1, 1, 0}};
        mesh.triangles.assign(static_cast<std::size_t>(copies), glm::uvec3{0, 1, 2});
        mesh.build(GetParam());
    };
    build(64, {1, 0, 0});  // the lower right half: every pack full of it
    build(5, {0, 1, 0});   // the upper left half: one leaf of five, packs with spare lanes
    Hit hit;
    const Ray lower_right{{0.8f, 0.2f, 5.0f}, {0, 0, -1}},
        upper_left{{0.2f, 0.8f, 5.0f}, {0, 0, -1}};
    EXPECT_FALSE(mesh.intersect(lower_right, hit)) << "hit triangle " << hit.prim;
    EXPECT_FALSE(mesh.occluded(lower_right, kInfinity));
    EXPECT_TRUE(mesh.intersect(upper_left, hit));
    EXPECT_LT(hit.prim, 5u);
}

TEST_P(AccelTest, SceneHitsMatchTestingEveryObject) {
    std::mt19937 rng(11);
    SceneDescription desc;
    desc.materials.push_back(Material{});
    std::uniform_real_distribution<float> radius(0.1f, 1.0f);
    for (int i = 0; i < 500; ++i)
        desc.objects.push_back(Object{"s", Sphere{random_point(rng, 12.0f), radius(rng)}, 0, {}});
    desc.objects.push_back(Object{"floor", Plane{{0, 1, 0}, -13}, 0, {}});
    const Scene scene(std::move(desc), GetParam());
    EXPECT_EQ(scene.accel_kind(), GetParam());
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

// Scenes of up to eight objects: the wide BVH over them is one node, whose leaves a
// shadow feeler visits without the stack (WideBvh::any_hit_in_root). Each object may
// block, and each may be the only one within the feeler's limit.
TEST_P(AccelTest, SmallScenesOccludeAsTestingEveryObject) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> radius(0.5f, 2.0f), limit(0.1f, 30.0f);
    for (int objects = 1; objects <= 9; ++objects) {
        SceneDescription desc;
        desc.materials.push_back(Material{});
        for (int i = 0; i < objects; ++i)
            desc.objects.push_back(
                Object{"s", Sphere{random_point(rng, 6.0f), radius(rng)}, 0, {}});
        const Scene scene(std::move(desc), GetParam());
        for (int i = 0; i < 2000; ++i) {
            const Ray ray{random_point(rng, 9.0f), random_point(rng, 1.0f)};
            const float t_max = i % 2 ? kInfinity : limit(rng);
            bool blocked = false;
            for (std::uint32_t o = 0; o < scene.objects.size(); ++o) {
                Hit h;
                h.t = t_max;
                blocked |= scene.intersect_object(o, ray, h);
            }
            ASSERT_EQ(scene.occluded(ray, t_max), blocked) << objects << " objects, ray " << i;
        }
    }
}

// Axis-aligned rays, rays from inside the bounds and flat scenes are where grids and
// slab tests go wrong.
TEST_P(AccelTest, FlatSceneAndAxisAlignedRays) {
    TriangleMesh mesh;
    for (int i = 0; i < 40; ++i)
        for (int j = 0; j < 40; ++j) {
            const auto base = static_cast<std::uint32_t>(mesh.positions.size());
            const float x = static_cast<float>(i), z = static_cast<float>(j);
            mesh.positions.insert(mesh.positions.end(), {{x, 0, z}, {x + 1, 0, z}, {x, 0, z + 1}});
            mesh.triangles.push_back({base, base + 1, base + 2});
        }
    mesh.build(GetParam());
    int hits = 0;
    for (int i = 0; i < 40; ++i) {
        const float x = static_cast<float>(i) + 0.25f;
        Hit down, up;
        hits += mesh.intersect(Ray{{x, 5, 7.25f}, {0, -1, 0}}, down);
        hits += mesh.intersect(Ray{{x, -5, 7.25f}, {0, 1, 0}}, up);
        EXPECT_FLOAT_EQ(down.t, 5.0f);
        Hit along;  // in the plane of the triangles: parallel, never a hit
        EXPECT_FALSE(mesh.intersect(Ray{{-1, 0, x}, {1, 0, 0}}, along));
        // In the plane x = i, where boxes have faces: (face - origin) / 0 is NaN in the
        // slab test, and the hit on the triangles' shared edge must not be lost.
        Hit on_face;
        hits += mesh.intersect(Ray{{static_cast<float>(i), 5, 7.25f}, {0, -1, 0}}, on_face);
        EXPECT_FLOAT_EQ(on_face.t, 5.0f);
    }
    EXPECT_EQ(hits, 120);
}

// A mesh collapsed to one point (every corner the same: no triangle has an area) is
// legal, degenerate input: it builds and no ray meets it. The grid sized its cells from
// the bounds' volume, which underflowed to 0, and cast the infinite cell count to int
// (undefined: the sanitizer build checks float-to-int casts, scripts/sanitize.sh).
TEST_P(AccelTest, AMeshCollapsedToOnePointBuildsAndIsNeverHit) {
    for (const float at : {0.0f, 1e-30f, 1.0f, 1e7f}) {
        TriangleMesh mesh;
        mesh.positions.assign(30, vec3(at));
        for (std::uint32_t k = 0; k < 30; k += 3) mesh.triangles.push_back({k, k + 1, k + 2});
        mesh.build(GetParam());
        Hit hit;
        EXPECT_FALSE(mesh.intersect(Ray{vec3(at) - vec3(1.0f), glm::normalize(vec3(1.0f))}, hit))
            << at;
        EXPECT_FALSE(mesh.occluded(Ray{vec3(at) - vec3(1.0f), glm::normalize(vec3(1.0f))}, 10.0f))
            << at;
    }
}

INSTANTIATE_TEST_SUITE_P(Structures, AccelTest,
                         ::testing::Values(AccelKind::kBvh, AccelKind::kBvh2, AccelKind::kGrid,
                                           AccelKind::kBrute),
                         [](const auto& param_info) {
                             return std::string(accel_name(param_info.param));
                         });

// One name per structure, and the names read back.
TEST(AccelNames, EveryKindHasOneNameThatParsesBack) {
    for (const auto& n : kAccelNames) {
        EXPECT_EQ(parse_accel(n.name), n.value);
        EXPECT_STREQ(accel_name(n.value), n.name);
    }
    EXPECT_FALSE(parse_accel("kd-tree").has_value());
    EXPECT_EQ(names_list(kAccelNames), "bvh, bvh2, grid or brute");
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

// The build runs on a pool of threads; the tree must not depend on how many. Boxes on a
// lattice give many equal centres (the ties the small nodes' sort must break the same
// way), and enough of them that the root is binned and partitioned in parts.
TEST(Bvh, TheTreeIsTheSameOnAnyNumberOfThreads) {
    std::mt19937 rng(23);
    std::uniform_int_distribution<int> cell(0, 40);
    std::vector<Aabb> boxes;
    for (int i = 0; i < 60000; ++i) {
        const vec3 lo(static_cast<float>(cell(rng)), static_cast<float>(cell(rng)),
                      static_cast<float>(cell(rng)));
        boxes.push_back({lo, lo + vec3(1.0f + static_cast<float>(i % 3))});
    }
    const auto same = [](const Bvh& a, const Bvh& b) {
        if (a.node_count() != b.node_count()) return false;
        for (std::size_t n = 0; n < a.node_count(); ++n) {
            const BvhNode &x = a.nodes()[n], &y = b.nodes()[n];
            if (x.lo != y.lo || x.hi != y.hi || x.first != y.first || x.count != y.count)
                return false;
        }
        return std::equal(a.order().begin(), a.order().end(), b.order().begin(), b.order().end());
    };
    Bvh one;
    one.build(boxes, 4, 1);
    for (int threads : {2, 3, 4, 7}) {
        Bvh many;
        many.build(boxes, 4, threads);
        EXPECT_TRUE(same(one, many)) << threads << " threads";
    }
}

// Leaves of up to eight where split_above is four: a subtree of five to eight is split
// only where its halves' boxes have much less area between them than it has (two far
// clusters of four), and kept whole where they overlap (eight boxes in one place).
TEST(Bvh, ALeafAboveSplitAboveIsSplitOnlyWhereThatPays) {
    const auto leaf_counts = [](const std::vector<Aabb>& boxes) {
        Bvh bvh;
        bvh.build(boxes, 8, 1, 4);
        std::vector<std::uint32_t> counts;
        for (const BvhNode& n : bvh.nodes())
            if (n.is_leaf()) counts.push_back(n.count);
        std::sort(counts.begin(), counts.end());
        return counts;
    };
    std::vector<Aabb> apart, together;
    for (int i = 0; i < 8; ++i) {
        const float x = i < 4 ? 0.0f : 100.0f, d = 0.1f * static_cast<float>(i % 4);
        apart.push_back({vec3(x + d, d, 0.0f), vec3(x + d + 1.0f, d + 1.0f, 1.0f)});
        together.push_back({vec3(d, 2.0f * d, 0.0f), vec3(d + 1.0f, 2.0f * d + 1.0f, 1.0f)});
    }
    EXPECT_EQ(leaf_counts(apart), (std::vector<std::uint32_t>{4, 4}));
    EXPECT_EQ(leaf_counts(together), (std::vector<std::uint32_t>{8}));
    // Without split_above, every subtree of up to eight is a leaf.
    Bvh whole;
    whole.build(apart, 8, 1);
    EXPECT_EQ(whole.node_count(), 1u);
}

// Nodes of up to a few thousand are binned along every axis, not only the one their
// centres spread most along: two layers of long boxes, the centres spread 20 along x and
// 10 along y, are best cut between the layers (each side a flat slab), not across x.
// Then every node below the root keeps to one layer, and leaves stay small.
TEST(Bvh, ANodeIsCutAlongTheAxisThatCostsLeastNotTheWidest) {
    std::vector<Aabb> boxes;
    for (int i = 0; i < 200; ++i) {
        const vec3 c(0.1f * static_cast<float>(i), i % 2 == 0 ? 0.0f : 10.0f, 0.0f);
        boxes.push_back({c - vec3(10.0f, 0.5f, 0.5f), c + vec3(10.0f, 0.5f, 0.5f)});
    }
    for (int threads : {1, 2}) {
        Bvh bvh;
        bvh.build(boxes, 4, threads);
        const auto nodes = bvh.nodes();
        ASSERT_FALSE(nodes[0].is_leaf());
        for (const std::uint32_t child : {1u, nodes[0].first})
            EXPECT_LE(nodes[child].hi.y - nodes[child].lo.y, 1.0f) << "child " << child;
        for (const BvhNode& n : nodes) EXPECT_LE(n.count, 4u);  // interior nodes: 0
    }
}

// A small node is split by sorting its centres (as integers made from their bits): the
// order must be the numbers' order across zero too. Three pairs along x, at -10/-9,
// -1/+1 (one each side of zero) and 9/10, and leaves of two: each leaf a pair.
TEST(Bvh, ASmallNodeSortsItsCentresAcrossZero) {
    std::vector<Aabb> boxes;
    for (float x : {9.0f, -1.0f, -10.0f, 10.0f, 1.0f, -9.0f})
        boxes.push_back({vec3(x - 0.25f, -0.25f, -0.25f), vec3(x + 0.25f, 0.25f, 0.25f)});
    Bvh bvh;
    bvh.build(boxes, 2, 1);
    int leaves = 0;
    for (const BvhNode& n : bvh.nodes()) {
        if (!n.is_leaf()) continue;
        ++leaves;
        EXPECT_EQ(n.count, 2u);
        EXPECT_LE(n.hi.x - n.lo.x, 2.5f) << "a leaf from " << n.lo.x << " to " << n.hi.x;
    }
    EXPECT_EQ(leaves, 3);
}

// Both widths of the wide BVH, whichever the build uses by default: every box a ray
// enters is visited, and closest-hit culling keeps the nearest, on boxes of every
// shape, flat ones included.
template <class Wide>
class WideBvhTest : public ::testing::Test {};
#if defined(__AVX512F__)
using WideWidths = ::testing::Types<WideBvh<4>, WideBvh<8>, WideBvh<16>>;
#elif defined(__AVX__)
using WideWidths = ::testing::Types<WideBvh<4>, WideBvh<8>>;
#else
using WideWidths = ::testing::Types<WideBvh<4>>;
#endif
TYPED_TEST_SUITE(WideBvhTest, WideWidths);

TYPED_TEST(WideBvhTest, VisitsExactlyTheBoxesTheRayEnters) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> size(0.0f, 2.0f);
    std::vector<Aabb> boxes;
    for (int i = 0; i < 5000; ++i) {
        const vec3 lo = random_point(rng, 20.0f);
        boxes.push_back({lo, lo + vec3(size(rng), size(rng), i % 7 == 0 ? 0.0f : size(rng))});
    }
    TypeParam wide;
    wide.build(boxes, 4);
    std::size_t leaf_prims = 0;
    wide.for_each_leaf([&](std::uint32_t, std::uint32_t count) {
        EXPECT_LE(count, 4u);
        leaf_prims += count;
    });
    EXPECT_EQ(leaf_prims, boxes.size());
    for (int i = 0; i < 2000; ++i) {
        const Ray ray{random_point(rng, 25.0f), random_point(rng, 1.0f)};
        const vec3 inv = 1.0f / ray.dir;
        std::vector<std::uint32_t> expected, visited;
        for (std::uint32_t p = 0; p < boxes.size(); ++p)
            if (slab_entry(boxes[p], ray.origin, inv, kInfinity) < kInfinity) expected.push_back(p);
        float t = kInfinity;
        wide.template traverse<false>(ray, t, [&](std::uint32_t slot, float&) {
            visited.push_back(wide.order()[slot]);
            return false;
        });
        std::sort(visited.begin(), visited.end());
        EXPECT_TRUE(std::adjacent_find(visited.begin(), visited.end()) == visited.end())
            << "ray " << i << " visits a primitive twice";
        // A leaf holds up to four: its other primitives come along, never one missing.
        EXPECT_TRUE(std::includes(visited.begin(), visited.end(), expected.begin(), expected.end()))
            << "ray " << i;

        // Closest hit with culling: treating each box's entry as a hit must end on the
        // nearest entry of all, though farther subtrees are skipped once it is found.
        float nearest = kInfinity;
        for (std::uint32_t p : expected)
            nearest = std::min(nearest, slab_entry(boxes[p], ray.origin, inv, kInfinity));
        float limit = kInfinity;
        wide.template traverse<false>(ray, limit, [&](std::uint32_t slot, float& t_max) {
            const float t_box = slab_entry(boxes[wide.order()[slot]], ray.origin, inv, t_max);
            if (!(t_box < t_max)) return false;
            t_max = t_box;
            return true;
        });
        EXPECT_EQ(limit, nearest) << "ray " << i;
    }
}

// What a ray's visits cost (core/wide_bvh.cpp): the wide nodes' areas, summed. A wide
// node's box is its lanes' boxes together.
template <class Wide>
double wide_cost(const Wide& wide) {
    double sum = 0.0;
    for (const auto& node : wide.nodes()) {
        Aabb box;
        for (int lane = 0; lane < Wide::kWidth; ++lane) {
            if (!(node.bounds[0][lane] <= node.bounds[3][lane])) continue;  // unused
            box.grow(vec3(node.bounds[0][lane], node.bounds[1][lane], node.bounds[2][lane]));
            box.grow(vec3(node.bounds[3][lane], node.bounds[4][lane], node.bounds[5][lane]));
        }
        sum += box.half_area();
    }
    return sum;
}

// The same for the greedy collapse of a binary tree (open the child of largest area
// until there are n lanes), the collapse the wide BVH used before, as a yardstick; with
// its node and lane counts.
struct Collapsed {
    double cost = 0.0;
    std::size_t nodes = 0, lanes = 0;
};
void greedy_collapse(std::span<const BvhNode> tree, std::uint32_t index, int n_max,
                     Collapsed& out) {
    const auto area = [&](std::uint32_t i) { return Aabb{tree[i].lo, tree[i].hi}.half_area(); };
    std::vector<std::uint32_t> lanes{index};
    while (static_cast<int>(lanes.size()) < n_max) {
        int widest = -1;
        for (int k = 0; k < static_cast<int>(lanes.size()); ++k)
            if (!tree[lanes[k]].is_leaf() && (widest < 0 || area(lanes[k]) > area(lanes[widest])))
                widest = k;
        if (widest < 0) break;
        const std::uint32_t parent = lanes[widest];
        lanes[widest] = parent + 1;
        lanes.push_back(tree[parent].first);
    }
    out.cost += area(index);
    ++out.nodes;
    out.lanes += lanes.size();
    for (std::uint32_t lane : lanes)
        if (!tree[lane].is_leaf()) greedy_collapse(tree, lane, n_max, out);
}

// The least cost of any collapse of a binary tree, found by trying every split plainly
// (the recursion of core/wide_bvh.cpp's Collapser, without its tables or its vectors):
// up_to(i, j) is the least cost of subtree i when it may take up to j lanes of its
// parent's node, as one lane (a leaf, or a node of its own) or as its children's.
struct LeastCollapse {
    std::span<const BvhNode> tree;
    int width;
    std::map<std::pair<std::uint32_t, int>, double> known;

    double area(std::uint32_t i) const { return Aabb{tree[i].lo, tree[i].hi}.half_area(); }
    double children(std::uint32_t i, int j) {  // both children within j lanes
        double least = std::numeric_limits<double>::infinity();
        for (int k = 1; k < j; ++k)
            least = std::min(least, up_to(i + 1, k) + up_to(tree[i].first, j - k));
        return least;
    }
    double up_to(std::uint32_t i, int j) {
        if (tree[i].is_leaf()) return 0.0;
        const auto key = std::make_pair(i, j);
        if (const auto it = known.find(key); it != known.end()) return it->second;
        double least = area(i) + children(i, width);  // a node of its own
        for (int lanes = 2; lanes <= j; ++lanes) least = std::min(least, children(i, lanes));
        return known[key] = least;
    }
    double root() { return tree[0].is_leaf() ? 0.0 : area(0) + children(0, width); }
};

// The collapse's tree costs what the least collapse costs, on trees of every shape: the
// cost tables are found for all lane counts at once (a vector a node), and a split read
// from the wrong lane, or a cheaper one passed over, costs more.
TYPED_TEST(WideBvhTest, TheCollapseIsTheCheapest) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> size(0.0f, 1.0f);
    for (int count : {40, 300, 2500}) {
        std::vector<Aabb> boxes;
        for (int i = 0; i < count; ++i) {
            const vec3 lo = random_point(rng, 10.0f);
            const float s = size(rng);
            boxes.push_back({lo, lo + vec3(s * size(rng), s * size(rng), s * size(rng))});
        }
        TypeParam wide;
        wide.build(boxes, 4, 1);
        Bvh binary;
        binary.build(boxes, 4, 1);
        LeastCollapse least{binary.nodes(), TypeParam::kWidth, {}};
        const double expected = least.root();
        EXPECT_NEAR(wide_cost(wide), expected, 1e-5 * expected) << count << " boxes";
    }
}

// The collapse of least cost costs no more than the greedy one on the same binary tree
// (it is the least), and its nodes are fuller (on these, by a third of a lane or more):
// on a tessellated sphere, a height field and a soup of boxes.
TYPED_TEST(WideBvhTest, TheCollapseCostsNoMoreThanTheGreedyOne) {
    std::vector<std::pair<const char*, std::vector<Aabb>>> inputs;
    const auto triangle_boxes = [](const TriangleMesh& mesh) {
        std::vector<Aabb> boxes;
        for (const auto& t : mesh.triangles) {
            Aabb b;
            for (int k = 0; k < 3; ++k) b.grow(mesh.positions[t[k]]);
            boxes.push_back(b);
        }
        return boxes;
    };
    inputs.emplace_back("sphere", triangle_boxes(tessellate_unit_sphere(96)));
    TriangleMesh field;
    const int n = 90;
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) {
            const float x = static_cast<float>(i), z = static_cast<float>(j);
            field.positions.push_back(
                {0.1f * x, std::sin(0.3f * x) * std::cos(0.2f * z), 0.1f * z});
        }
    }
    for (std::uint32_t j = 0; j < n; ++j) {
        for (std::uint32_t i = 0; i < n; ++i) {
            const std::uint32_t a = j * (n + 1) + i, c = a + n + 1;
            field.triangles.push_back({a, c, a + 1});
            field.triangles.push_back({a + 1, c, c + 1});
        }
    }
    inputs.emplace_back("height field", triangle_boxes(field));
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> size(0.0f, 1.0f);
    std::vector<Aabb> soup;
    for (int i = 0; i < 6000; ++i) {
        const vec3 lo = random_point(rng, 20.0f);
        soup.push_back({lo, lo + vec3(size(rng), size(rng), size(rng))});
    }
    inputs.emplace_back("soup", std::move(soup));

    for (const auto& [name, boxes] : inputs) {
        TypeParam wide;
        wide.build(boxes, 4, 1);
        Bvh binary;
        binary.build(boxes, 4, 1);
        Collapsed greedy;
        greedy_collapse(binary.nodes(), 0, TypeParam::kWidth, greedy);
        EXPECT_LE(wide_cost(wide), greedy.cost * (1.0 + 1e-6)) << name;
        std::size_t leaves = 0;
        wide.for_each_leaf([&](std::uint32_t, std::uint32_t) { ++leaves; });
        // Lanes in use per node (every node but the root is a lane of another).
        const auto per_node = [](std::size_t lanes, std::size_t nodes) {
            return static_cast<double>(lanes) / static_cast<double>(nodes);
        };
        EXPECT_GE(per_node(leaves + wide.node_count() - 1, wide.node_count()),
                  per_node(greedy.lanes, greedy.nodes) + 0.3)
            << name;
    }
}

// The collapse runs on the pool too (the parts of the binary tree, then the top): the
// wide tree must not depend on how many threads, and each part's nodes must land where
// its parent points: every node reached once from the root, every slot in one leaf.
TYPED_TEST(WideBvhTest, TheTreeIsTheSameOnAnyNumberOfThreadsAndWhole) {
    // Clusters of boxes on lattices (equal centres: ties), small ones beside large ones,
    // so that small subtrees come before large ones in the tree.
    std::mt19937 rng(29);
    std::vector<Aabb> boxes;
    for (const auto& [x, count] : {std::pair{0, 3000}, {100, 60000}, {300, 2000}, {400, 30000}}) {
        const int side = static_cast<int>(std::cbrt(static_cast<float>(count))) + 4;
        std::uniform_int_distribution<int> cell(0, side);
        for (int i = 0; i < count; ++i) {
            const vec3 lo(static_cast<float>(x + cell(rng)), static_cast<float>(cell(rng)),
                          static_cast<float>(cell(rng)));
            boxes.push_back({lo, lo + vec3(0.5f + static_cast<float>(i % 4))});
        }
    }
    TypeParam one;
    one.build(boxes, 4, 1);
    std::vector<int> reached(one.node_count(), 0), slots(boxes.size(), 0);
    std::vector<std::uint32_t> pending{0};
    while (!pending.empty()) {
        const std::uint32_t at = pending.back();
        pending.pop_back();
        ASSERT_LT(at, one.node_count());
        ++reached[at];
        const auto& node = one.nodes()[at];
        for (int lane = 0; lane < TypeParam::kWidth; ++lane) {
            if (node.count[lane] != 0) {
                for (std::uint32_t s = 0; s < node.count[lane]; ++s) ++slots[node.child[lane] + s];
            } else if (node.bounds[0][lane] <= node.bounds[3][lane]) {
                pending.push_back(node.child[lane]);
            }
        }
    }
    EXPECT_EQ(std::count(reached.begin(), reached.end(), 1), static_cast<long>(reached.size()));
    EXPECT_EQ(std::count(slots.begin(), slots.end(), 1), static_cast<long>(slots.size()));
    for (int threads : {2, 3, 7}) {
        TypeParam many;
        many.build(boxes, 4, threads);
        ASSERT_EQ(many.node_count(), one.node_count()) << threads << " threads";
        EXPECT_EQ(std::memcmp(many.nodes().data(), one.nodes().data(),
                              one.node_count() * sizeof(one.nodes()[0])),
                  0)
            << threads << " threads";
        EXPECT_TRUE(std::equal(one.order().begin(), one.order().end(), many.order().begin(),
                               many.order().end()))
            << threads << " threads";
    }
}

TYPED_TEST(WideBvhTest, DegenerateInputsBuild) {
    TypeParam wide;
    wide.build({}, 4);
    EXPECT_TRUE(wide.empty());
    float t = kInfinity;
    EXPECT_FALSE(wide.template traverse<false>(Ray{{0, 0, -5}, {0, 0, 1}}, t,
                                               [](std::uint32_t, float&) { return true; }));
    std::vector<Aabb> same(1000, Aabb{vec3(0.0f), vec3(1.0f)});  // one leaf of 1000
    wide.build(same, 4);
    int visited = 0;
    wide.template traverse<false>(Ray{{0.5f, 0.5f, -5}, {0, 0, 1}}, t, [&](std::uint32_t, float&) {
        ++visited;
        return false;
    });
    EXPECT_EQ(visited, 1000);
}

TEST(Bvh, ParallelBuildGivesAValidTree) {
    // Large enough for the build to hand subtrees to another thread.
    std::mt19937 rng(3);
    const TriangleMesh mesh = random_soup(rng, 60000, AccelKind::kBvh);
    const TriangleMesh brute = [&] {
        TriangleMesh m = mesh;
        m.build(AccelKind::kBrute);
        return m;
    }();
    for (int i = 0; i < 300; ++i) {
        const Ray ray{random_point(rng, 15.0f), random_point(rng, 1.0f)};
        Hit a, b;
        ASSERT_EQ(mesh.intersect(ray, a), brute.intersect(ray, b));
        EXPECT_EQ(a.prim, b.prim);
        EXPECT_EQ(a.t, b.t);
    }
}

// The watertight 4-wide test against the tutorial's, on triangles seen from anywhere.
// A ray leaving a large triangle from a point offset just off it (as every shadow,
// reflected and refracted ray does) must not hit the triangle itself: the rounding error
// of t grows with the triangle's size, and near a coordinate of 0 the offset is tiny.
// This was acne on the Cornell box's walls with the grid and brute force.
TEST(Triangle4, RaysLeavingALargeTriangleDoNotHitIt) {
    const vec3 a{0, 0, 0}, b{0, 548.8f, 0}, c{0, 548.8f, 559.2f};  // the Cornell box's left wall
    Triangle4 pack{};  // zeroed: the three unused lanes must never hit
    pack.set(0, a, b, c);
    std::mt19937 rng(23);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    int self_hits = 0;
    for (int i = 0; i < 100000; ++i) {
        float w1 = u(rng), w2 = u(rng);
        if (w1 + w2 > 1.0f) w1 = 1.0f - w1, w2 = 1.0f - w2;
        const vec3 p = (1.0f - w1 - w2) * a + w1 * b + w2 * c;
        const vec3 origin = offset_ray_origin(p, {1, 0, 0});
        const vec3 dir{u(rng) * 300.0f + 1e-3f, (u(rng) - 0.5f) * 800.0f, (u(rng) - 0.5f) * 800.0f};
        self_hits += intersect(pack, ShearedRay(Ray{origin, dir}), 1.0f).lane >= 0;
    }
    EXPECT_EQ(self_hits, 0);
}

TEST(Triangle4, AgreesWithTheTutorialsTest) {
    std::mt19937 rng(5);
    int hits = 0;
    for (int i = 0; i < 20000; ++i) {
        const vec3 a = random_point(rng, 2.0f), b = random_point(rng, 2.0f),
                   c = random_point(rng, 2.0f);
        // Aimed at the triangle or just beside it.
        std::uniform_real_distribution<float> w(-0.1f, 0.7f);
        const float w1 = w(rng), w2 = w(rng);
        const vec3 origin = random_point(rng, 6.0f);
        const Ray ray{origin, a + w1 * (b - a) + w2 * (c - a) - origin};
        Triangle4 four{};
        const int lane = i % 4;  // any lane; the others stay empty
        four.set(lane, a, b, c);
        const auto ref = intersect_triangle(a, b, c, ray, kInfinity);
        const Triangle4Hit fast = intersect(four, ShearedRay(ray), kInfinity);
        if (ref && fast.lane >= 0) {
            ++hits;
            EXPECT_EQ(fast.lane, lane);
            // Rounding in t grows as the ray grazes the plane: allow for 1 / cos.
            const float cos_angle = std::fabs(
                glm::dot(glm::normalize(ray.dir), glm::normalize(glm::cross(b - a, c - a))));
            EXPECT_NEAR(fast.t, ref->t, 2e-5f * ref->t / std::max(cos_angle, 1e-3f));
            EXPECT_NEAR(fast.b1, ref->b1, 1e-3f);
            EXPECT_NEAR(fast.b2, ref->b2, 1e-3f);
        } else if (ref.has_value() != (fast.lane >= 0)) {
            // Only a ray through an edge may be decided differently by rounding.
            const float b1 = ref ? ref->b1 : fast.b1, b2 = ref ? ref->b2 : fast.b2;
            EXPECT_LT(std::min({b1, b2, 1.0f - b1 - b2}), 1e-4f) << i;
        }
    }
    EXPECT_GT(hits, 5000);
}

#if defined(__AVX__)
// Two packs tested as one of eight lanes give, lane for lane, what the two tests give one
// after the other: the same lane (the second pack's as 4-7), t and weights, bit for bit.
TEST(Triangle4, APairOfPacksIsTheirTwoTestsInOne) {
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> w(-0.1f, 0.6f);
    int hits = 0;
    for (int i = 0; i < 5000; ++i) {
        Triangle4 packs[2]{};
        std::array<std::array<vec3, 3>, 8> corners;
        for (int lane = 0; lane < 8; ++lane) {
            const vec3 centre = random_point(rng, 1.0f);
            for (vec3& c : corners[lane]) c = centre + random_point(rng, 0.8f);
            if (lane == i % 9) continue;  // an empty lane here and there
            packs[lane / 4].set(lane % 4, corners[lane][0], corners[lane][1], corners[lane][2]);
        }
        // Aimed at one of them (or just beside it), from anywhere around.
        const auto& aim = corners[static_cast<std::size_t>(i % 8)];
        const vec3 target = aim[0] + w(rng) * (aim[1] - aim[0]) + w(rng) * (aim[2] - aim[0]);
        const vec3 origin = random_point(rng, 5.0f);
        const Ray ray{origin, target - origin};
        const ShearedRay sheared(ray);
        const float t_max = i % 3 == 0 ? 4.0f : kInfinity;
        Triangle4Hit one_by_one = intersect(packs[0], sheared, t_max);
        Triangle4Hit second =
            intersect(packs[1], sheared, one_by_one.lane >= 0 ? one_by_one.t : t_max);
        if (second.lane >= 0) one_by_one = second, one_by_one.lane += 4;
        const Triangle4Hit pair = intersect(packs[0], packs[1], sheared, t_max);
        ASSERT_EQ(pair.lane, one_by_one.lane) << i;
        if (pair.lane < 0) continue;
        ++hits;
        EXPECT_EQ(pair.t, one_by_one.t) << i;
        EXPECT_EQ(pair.b1, one_by_one.b1) << i;
        EXPECT_EQ(pair.b2, one_by_one.b2) << i;
    }
    EXPECT_GT(hits, 1000);
}
#endif

// A leaf of more than eight (triangles whose boxes are one cube: nothing splits them) is
// tested four at a time, each hit named by its own lane: the mesh gives every ray the
// triangle and t that testing each triangle alone gives.
TEST(Triangle4, ALeafOfMoreThanEightNamesEachTriangle) {
    TriangleMesh mesh;
    for (int corner = 0; corner < 8; ++corner)
        mesh.positions.push_back(
            {corner & 1 ? 1.0f : -1.0f, corner & 2 ? 1.0f : -1.0f, corner & 4 ? 1.0f : -1.0f});
    // Every triangle of the cube's corners that spans the cube on all three axes.
    for (std::uint32_t a = 0; a < 8; ++a)
        for (std::uint32_t b = a + 1; b < 8; ++b)
            for (std::uint32_t c = b + 1; c < 8; ++c)
                if (((a & b & c) | (~a & ~b & ~c)) % 8 == 0 && mesh.triangles.size() < 20)
                    mesh.triangles.push_back({a, b, c});
    std::vector<Aabb> boxes(mesh.triangles.size(), Aabb{vec3(-1.0f), vec3(1.0f)});
    Bvh one_leaf;
    one_leaf.build(boxes, 8, 1, 4);
    ASSERT_EQ(one_leaf.node_count(), 1u);
    ASSERT_GT(mesh.triangles.size(), 8u);
    mesh.build();
    std::mt19937 rng(4);
    std::uniform_real_distribution<float> w(0.0f, 0.5f);
    int hits = 0;
    for (int i = 0; i < 3000; ++i) {  // each aimed at a point of one of them
        const glm::uvec3 tri = mesh.triangles[static_cast<std::size_t>(i) % mesh.triangles.size()];
        const vec3 a = mesh.positions[tri[0]], b = mesh.positions[tri[1]],
                   c = mesh.positions[tri[2]];
        const vec3 origin = random_point(rng, 3.0f);
        const Ray ray{origin, a + w(rng) * (b - a) + w(rng) * (c - a) - origin};
        Hit expected;
        for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
            Hit h = expected;
            if (mesh.intersect_triangle(t, ray, h)) expected = h;
        }
        Hit got;
        const bool found = mesh.intersect(ray, got);
        ASSERT_EQ(found, expected.t < kInfinity) << i;
        if (!found) continue;
        ++hits;
        EXPECT_EQ(got.prim, expected.prim) << i;
        EXPECT_EQ(got.t, expected.t) << i;
        EXPECT_EQ(mesh.occluded(ray, kInfinity), true) << i;
    }
    EXPECT_GT(hits, 500);
}

// Rays aimed exactly at the shared edges and vertices of a closed mesh, from inside it,
// must all hit it: a test that is not watertight lets some through (a Moeller-Trumbore
// test here let 10 % of these million rays leak, nearly all those aimed at vertices).
TEST(Watertight, NoRayLeaksThroughEdgesOrVertices) {
    TriangleMesh sphere = tessellate_unit_sphere(64);
    sphere.build();
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    int leaks = 0;
    for (int i = 0; i < 1000000; ++i) {
        const glm::uvec3 tri = sphere.triangles[rng() % sphere.triangles.size()];
        const int e = static_cast<int>(rng() % 3);
        const vec3 a = sphere.positions[tri[e]], b = sphere.positions[tri[(e + 1) % 3]];
        const float s = i % 10 == 0 ? 0.0f : u(rng);  // every tenth exactly at a vertex
        const vec3 origin = 0.2f * vec3(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f);
        Hit hit;
        leaks += !sphere.intersect(Ray{origin, a + s * (b - a) - origin}, hit);
    }
    EXPECT_EQ(leaks, 0);
}

// A fan of 60,000 slivers met near its centre, where they are thinner than float can
// tell apart, by rays from one eye (unit directions, as a camera's) aimed at a grid of
// points around the centre: every ray hits the fan. The bound on t's rounding
// (t_det_error) is loose where a sliver's edge functions cancel, and alone it dropped
// such hits: a line of holes through the centre of the fan (the cap of a finely
// tessellated cylinder, a sphere's pole).
TEST(Watertight, NoRayLeaksThroughTheCentreOfAFanOfSlivers) {
    TriangleMesh fan;
    const int n = 60000;
    fan.positions.push_back(vec3(0.0f));
    for (int i = 0; i < n; ++i) {
        const float a = 6.2831853f * static_cast<float>(i) / static_cast<float>(n);
        fan.positions.push_back(
            {4.0f * std::cos(a), 0.3f * std::sin(5.0f * a), 4.0f * std::sin(a)});
    }
    for (std::uint32_t i = 0; i < n; ++i) fan.triangles.push_back({0, 1 + i, 1 + (i + 1) % n});
    fan.build();
    const vec3 eye(5.53f, 4.74f, 15.79f);
    int leaks = 0;
    for (int i = -100; i <= 100; ++i) {
        for (int j = -100; j <= 100; ++j) {
            const vec3 aim(0.004f * static_cast<float>(i), 0.0f, 0.004f * static_cast<float>(j));
            Hit hit;
            leaks += !fan.intersect(Ray{eye, glm::normalize(aim - eye)}, hit);
        }
    }
    EXPECT_EQ(leaks, 0);
}

// The same through the packet traversal (core/wide_bvh_packet.h), whose interval test
// bounds every ray's exit with Ize's factor as a single ray's does: a ray alone in its
// packet (the interval is then its own test), and eight rays from one point aimed along
// one edge. Without the factor in the interval's exit bounds, rays alone leaked.
TEST(Watertight, NoPacketRayLeaksThroughEdgesOrVertices) {
    TriangleMesh sphere = tessellate_unit_sphere(64);
    sphere.build();
    std::mt19937 rng(2);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    int alone_leaks = 0, together_leaks = 0;
    for (int i = 0; i < 100000; ++i) {
        const glm::uvec3 tri = sphere.triangles[rng() % sphere.triangles.size()];
        const int e = static_cast<int>(rng() % 3);
        const vec3 a = sphere.positions[tri[e]], b = sphere.positions[tri[(e + 1) % 3]];
        const vec3 origin = 0.2f * vec3(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f);
        std::array<Ray, kPacketWidth> rays;
        for (int lane = 0; lane < kPacketWidth; ++lane) {
            const float s = lane == 0 ? 0.0f : u(rng);  // lane 0 exactly at a vertex
            rays[static_cast<std::size_t>(lane)] = Ray{origin, a + s * (b - a) - origin};
        }
        std::array<Hit, kPacketWidth> hits{};
        const unsigned lane = static_cast<unsigned>(i) % kPacketWidth, alone = 1u << lane;
        alone_leaks += sphere.intersect_packet(rays.data(), hits.data(), alone) != alone;
        hits = {};
        const unsigned all = (1u << kPacketWidth) - 1u;
        together_leaks +=
            std::popcount(all & ~sphere.intersect_packet(rays.data(), hits.data(), all));
    }
    EXPECT_EQ(alone_leaks, 0);
    EXPECT_EQ(together_leaks, 0);
}

}  // namespace
}  // namespace rt
