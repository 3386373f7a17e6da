#include "core/mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <numeric>
#include <optional>
#include <unordered_map>
#include <unordered_set>

#include <glm/geometric.hpp>

#include "core/parallel.h"
#include "core/shapes.h"
#include "core/triangle_refs.h"

namespace rt {
namespace {
// A wide BVH's leaves: up to one test of the SIMD width. Under AVX, two packs tested as
// one of eight lanes (core/triangle4.h): a leaf of eight costs what a leaf of four did, and
// the tree has fewer nodes (docs/BENCHMARKS.md, "Leaves of eight"). A subtree of more than
// four is split where that cuts the area rays enter (Bvh::build). Four under SSE2. (Not
// the nodes' width, kBvhWidth: sixteen under AVX-512, where leaves stay at eight.)
#if defined(__AVX__)
constexpr std::uint32_t kWideLeaf = 2 * kTriangle4Lanes;
#else
constexpr std::uint32_t kWideLeaf = kTriangle4Lanes;
#endif

// A ray set up for the watertight test at the first leaf it reaches: its three divisions
// are not paid by the rays that miss every leaf (a scene's feelers and bounces that pass
// a mesh's box by).
class LazySheared {
  public:
    explicit LazySheared(const Ray& r) : ray_(r) {}
    [[gnu::always_inline]] const ShearedRay& get() {
        if (!ready_) sheared_ = ShearedRay(ray_), ready_ = true;
        return sheared_;
    }

  private:
    const Ray& ray_;
    ShearedRay sheared_;
    bool ready_ = false;
};
}  // namespace

void TriangleMesh::build(AccelKind kind, int threads) {
    threads = build_threads(threads);
    TaskPool* const pool = threads > 1 ? &TaskPool::shared(threads) : nullptr;
    // The triangles' boxes in parts, long thin ones cut in pieces (core/triangle_refs.h)
    // for the wide BVH, the structure rays are traced with (a cut triangle is copied into
    // the packs of each leaf its pieces reach). (On one thread until the
    // thirty-eighth session: two threads touching a fresh array's small pages at once were
    // slower, eighth session; a large array's pages are huge ones now, or kept from the
    // last build.)
    SplitLimits limits;
    if (kind != AccelKind::kBvh) limits.max_pieces = 1;
    const TriangleRefs refs =
        triangle_refs(positions, triangles, limits, pool,
                      pool ? part_count(triangles.size(), threads, 16384) : 1);
    bounds_ = refs.bounds;
    accel_.build(refs.boxes, kind, kind == AccelKind::kBvh ? kWideLeaf : kTriangle4Lanes, threads,
                 kTriangle4Lanes);
    // Each leaf's first pack (a pass over the leaves), then the packs filled in parallel.
    const auto order = accel_.order();
    struct Leaf {
        std::uint32_t first, count;
    };
    std::vector<Leaf> leaves;
    leaf_pack_.clear();
    leaf_pack_.resize(order.size());
    std::uint32_t pack_total = 0;
    accel_.for_each_leaf([&](std::uint32_t first, std::uint32_t count) {
        leaves.push_back({first, count});
        leaf_pack_[first] = pack_total;
        pack_total += (count + kTriangle4Lanes - 1) / kTriangle4Lanes;
    });
    packs_.clear();  // then every lane written below, the spare ones zero (never hit)
    packs_.resize(pack_total);
    pack_prims_.clear();
    pack_prims_.resize(std::size_t{pack_total} * kTriangle4Lanes);
    // (Two loops: where no triangle is cut, slot s holds triangle order()[s] and no
    // lookup is made, which took the loop 0.5 ms longer on a 122,402-triangle mesh.)
    const std::size_t n = triangles.size();  // references past these are extra pieces
    const std::uint32_t* const extra = refs.extra_triangles.data();
    const auto fill = [&]<bool kCut>(std::size_t begin, std::size_t end) {
        for (std::size_t l = begin; l < end; ++l) {
            const Leaf leaf = leaves[l];
            const std::uint32_t start = leaf_pack_[leaf.first];
            for (std::uint32_t i = 0; i < leaf.count; ++i) {
                const std::uint32_t ref = order[leaf.first + i];
                const std::uint32_t prim = !kCut || ref < n ? ref : extra[ref - n];
                const glm::uvec3 idx = triangles[prim];
                packs_[start + i / kTriangle4Lanes].set(static_cast<int>(i % kTriangle4Lanes),
                                                        positions[idx[0]], positions[idx[1]],
                                                        positions[idx[2]]);
                pack_prims_[std::size_t{start} * kTriangle4Lanes + i] = prim;
                if (!kCut || ref == prim)  // its first copy
                    prim_lane_[prim] = start * kTriangle4Lanes + i;
            }
            for (std::uint32_t i = leaf.count; i % kTriangle4Lanes != 0; ++i) {
                packs_[start + i / kTriangle4Lanes].set_empty(
                    static_cast<int>(i % kTriangle4Lanes));
                pack_prims_[std::size_t{start} * kTriangle4Lanes + i] = ~0u;
            }
        }
    };
    prim_lane_.clear();  // every triangle's first reference is in one leaf: written by fill
    prim_lane_.resize(triangles.size());
    parallel_parts(pool, 0, leaves.size(), pool ? part_count(leaves.size(), threads, 4096) : 1,
                   [&](int, std::size_t begin, std::size_t end) {
                       if (refs.extra_triangles.empty())
                           fill.template operator()<false>(begin, end);
                       else
                           fill.template operator()<true>(begin, end);
                   });
    leaves_are_packs_ = accel_.relabel_leaves(
        [&](std::uint32_t first, std::uint32_t) { return leaf_pack_[first]; });
}

Aabb bounds_of(const TriangleMesh& mesh) {
    Aabb box;
    for (const glm::uvec3& tri : mesh.triangles)
        for (int k = 0; k < 3; ++k) box.grow(mesh.positions[tri[k]]);
    for (const glm::uvec2& segment : mesh.segments)
        for (int k = 0; k < 2; ++k) box.grow(mesh.positions[segment[k]]);
    for (std::uint32_t point : mesh.points) box.grow(mesh.positions[point]);
    return box;
}

std::size_t TriangleMesh::accel_memory_bytes() const {
    return accel_.memory_bytes() + packs_.size() * sizeof(Triangle4) +
           (pack_prims_.size() + prim_lane_.size() + leaf_pack_.size()) * sizeof(std::uint32_t);
}

std::size_t TriangleMesh::memory_bytes() const {
    return positions.size() * sizeof(vec3) + triangles.size() * sizeof(glm::uvec3) +
           corner_normals.size() * sizeof(vec3) + materials.size() * sizeof(std::uint32_t) +
           corner_uvs.size() * sizeof(glm::vec2) + corner_colours.size() * sizeof(vec3) +
           accel_memory_bytes();
}

bool TriangleMesh::intersect(const Ray& r, Hit& hit) const {
    LazySheared sheared(r);
    return accel_.traverse_leaves<false>(
        r, hit.t, [&](std::uint32_t leaf, std::uint32_t count, float& t_max) RT_FORCE_INLINE {
            const std::uint32_t start = first_pack(leaf);
            const Triangle4Hit h = leaf_hit(start, count, sheared.get(), t_max);
            if (h.lane < 0) return false;
            t_max = h.t;
            hit.prim = pack_prims_[kTriangle4Lanes * start + static_cast<std::uint32_t>(h.lane)];
            hit.b1 = h.b1;
            hit.b2 = h.b2;
            return true;
        });
}

bool TriangleMesh::intersect_triangle(std::uint32_t prim, const Ray& r, Hit& hit) const {
    if (prim >= prim_lane_.size()) return false;
    const std::uint32_t at = prim_lane_[prim];
    const Triangle4Hit h = rt::intersect(packs_[at / kTriangle4Lanes], ShearedRay(r), hit.t,
                                         1u << (at % kTriangle4Lanes));
    if (h.lane < 0) return false;
    hit.t = h.t;
    hit.prim = prim;
    hit.b1 = h.b1;
    hit.b2 = h.b2;
    return true;
}

bool TriangleMesh::occluded(const Ray& r, float t_max) const {
    LazySheared sheared(r);
    return accel_.traverse_leaves<true>(
        r, t_max, [&](std::uint32_t leaf, std::uint32_t count, float& t_limit) RT_FORCE_INLINE {
            return leaf_blocks(first_pack(leaf), count, sheared.get(), t_limit);
        });
}

vec3 TriangleMesh::face_normal(std::uint32_t tri) const {
    const glm::uvec3 idx = triangles[tri];
    return glm::cross(positions[idx[1]] - positions[idx[0]], positions[idx[2]] - positions[idx[0]]);
}

vec3 TriangleMesh::shading_normal(const Hit& hit) const {
    if (corner_normals.empty()) return face_normal(hit.prim);
    const vec3* n = &corner_normals[3 * std::size_t{hit.prim}];
    return (1.0f - hit.b1 - hit.b2) * n[0] + hit.b1 * n[1] + hit.b2 * n[2];
}

glm::vec2 TriangleMesh::uv(const Hit& hit) const {
    if (corner_uvs.empty()) return glm::vec2(0.0f);
    const glm::vec2* t = &corner_uvs[3 * std::size_t{hit.prim}];
    return (1.0f - hit.b1 - hit.b2) * t[0] + hit.b1 * t[1] + hit.b2 * t[2];
}

vec3 TriangleMesh::colour(const Hit& hit) const {
    if (corner_colours.empty()) return vec3(1.0f);
    const vec3* c = &corner_colours[3 * std::size_t{hit.prim}];
    return (1.0f - hit.b1 - hit.b2) * c[0] + hit.b1 * c[1] + hit.b2 * c[2];
}

vec3 TriangleMesh::point(const Hit& hit) const {
    const glm::uvec3 idx = triangles[hit.prim];
    return (1.0f - hit.b1 - hit.b2) * positions[idx[0]] + hit.b1 * positions[idx[1]] +
           hit.b2 * positions[idx[2]];
}

namespace {

// For each vertex, the first vertex with exactly the same position.
struct Vec3Hash {
    std::size_t operator()(const vec3& p) const {
        std::size_t h = 0;
        for (int i = 0; i < 3; ++i) h = h * 1000003u ^ std::hash<float>{}(p[i]);
        return h;
    }
};

// Each position's first index among the positions equal to it (==: +0 and -0 alike, a
// NaN equal to nothing). By sorting the indices by position, ties by index, so each run of
// equal positions starts with its first; a hash map of positions cost a node allocation
// each (callgrind, the bunny: 27.7 M instructions a call against 12.2 M). With a NaN, which
// sorts nowhere, the map.
std::vector<std::uint32_t> weld_positions(const std::vector<vec3>& positions) {
    std::vector<std::uint32_t> weld(positions.size());
    const auto nan = [](const vec3& p) { return std::isnan(p.x + p.y + p.z); };
    if (std::any_of(positions.begin(), positions.end(), nan)) {
        std::unordered_map<vec3, std::uint32_t, Vec3Hash> first;
        for (std::uint32_t i = 0; i < positions.size(); ++i)
            weld[i] = first.try_emplace(positions[i], i).first->second;
        return weld;
    }
    std::vector<std::uint32_t> order(positions.size());
    std::iota(order.begin(), order.end(), 0u);
    const auto less = [&](std::uint32_t a, std::uint32_t b) {
        const vec3 &p = positions[a], &q = positions[b];
        if (p.x != q.x) return p.x < q.x;
        if (p.y != q.y) return p.y < q.y;
        if (p.z != q.z) return p.z < q.z;
        return a < b;
    };
    std::sort(order.begin(), order.end(), less);
    for (std::size_t k = 0, run = 0; k < order.size(); ++k) {
        if (positions[order[k]] != positions[order[run]]) run = k;
        weld[order[k]] = order[run];
    }
    return weld;
}

}  // namespace

std::size_t drop_duplicate_triangles(TriangleMesh& mesh) {
    const std::vector<std::uint32_t> weld = weld_positions(mesh.positions);
    struct Key {
        std::uint32_t a, b, c;
        bool operator==(const Key&) const = default;
    };
    struct KeyHash {
        std::size_t operator()(const Key& k) const {
            return (std::size_t{k.a} * 1000003u ^ k.b) * 1000003u ^ k.c;
        }
    };
    std::unordered_set<Key, KeyHash> seen;
    std::size_t kept = 0;
    const bool normals = !mesh.corner_normals.empty(), materials = !mesh.materials.empty();
    const bool uvs = !mesh.corner_uvs.empty(), colours = !mesh.corner_colours.empty();
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        std::uint32_t v[3] = {weld[mesh.triangles[t][0]], weld[mesh.triangles[t][1]],
                              weld[mesh.triangles[t][2]]};
        // The same cycle whichever corner the file starts from; the winding is kept.
        const int first = v[0] <= v[1] && v[0] <= v[2] ? 0 : (v[1] <= v[2] ? 1 : 2);
        if (!seen.insert({v[first], v[(first + 1) % 3], v[(first + 2) % 3]}).second) continue;
        mesh.triangles[kept] = mesh.triangles[t];
        if (normals)
            for (int k = 0; k < 3; ++k)
                mesh.corner_normals[3 * kept + k] = mesh.corner_normals[3 * t + k];
        if (materials) mesh.materials[kept] = mesh.materials[t];
        if (uvs)
            for (int k = 0; k < 3; ++k) mesh.corner_uvs[3 * kept + k] = mesh.corner_uvs[3 * t + k];
        if (colours)
            for (int k = 0; k < 3; ++k)
                mesh.corner_colours[3 * kept + k] = mesh.corner_colours[3 * t + k];
        ++kept;
    }
    const std::size_t dropped = mesh.triangles.size() - kept;
    mesh.triangles.resize(kept);
    if (normals) mesh.corner_normals.resize(3 * kept);
    if (materials) mesh.materials.resize(kept);
    if (uvs) mesh.corner_uvs.resize(3 * kept);
    if (colours) mesh.corner_colours.resize(3 * kept);
    return dropped;
}

void compute_corner_normals(TriangleMesh& mesh, float crease_degrees) {
    const std::size_t tri_count = mesh.triangles.size();
    std::vector<vec3> face(tri_count);
    for (std::size_t t = 0; t < tri_count; ++t)
        face[t] = mesh.face_normal(static_cast<std::uint32_t>(t));

    // Vertices at the same position count as one (patch seams repeat them), so
    // normals are smooth across seams; then the faces around each such vertex, as a
    // compressed adjacency list.
    const std::vector<std::uint32_t> weld = weld_positions(mesh.positions);
    std::vector<std::uint32_t> start(mesh.positions.size() + 1, 0);
    for (const auto& tri : mesh.triangles)
        for (int k = 0; k < 3; ++k) ++start[weld[tri[k]] + 1];
    for (std::size_t v = 1; v < start.size(); ++v) start[v] += start[v - 1];
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    std::vector<std::uint32_t> faces_at(start.back());
    for (std::uint32_t t = 0; t < tri_count; ++t)
        for (int k = 0; k < 3; ++k) faces_at[fill[weld[mesh.triangles[t][k]]]++] = t;

    const float cos_crease = std::cos(crease_degrees * std::numbers::pi_v<float> / 180.0f);
    mesh.corner_normals.assign(3 * tri_count, vec3(0.0f));
    std::vector<vec3> unit(tri_count);
    for (std::size_t t = 0; t < tri_count; ++t) {
        const float len = glm::length(face[t]);
        unit[t] = len > 0.0f ? face[t] / len : vec3(0.0f);
    }
    // Around each vertex, faces that point the same way (a fan of coplanar triangles, a
    // face repeated) are merged into one direction carrying their summed normals, and
    // each direction is compared with the others once: the work is the number of faces
    // times the number of distinct directions there, not the faces squared. A vertex
    // with more than kMaxDirections directions (a cone's apex of thousands of slivers)
    // gives each corner its own face normal: flat there, and still linear.
    constexpr std::size_t kMaxDirections = 256;
    struct Direction {
        vec3 unit, sum, result;
    };
    std::vector<Direction> dirs;
    std::unordered_map<vec3, std::uint32_t, Vec3Hash> dir_of;
    std::vector<std::uint32_t> corner_dir;
    // A direction's index, a new one for a unit normal not seen at this vertex. Most
    // vertices have a handful of faces: a search of the few directions beats a hash map,
    // whose node a face cost an allocation (the map, for the rest, finds the same: its
    // keys compare with ==, and +0 and -0 hash alike).
    constexpr std::uint32_t kSearchedFaces = 32;
    const auto direction_of = [&](const vec3& u, bool searched) {
        const auto next = static_cast<std::uint32_t>(dirs.size());
        if (searched) {
            for (std::uint32_t d = 0; d < next; ++d)
                if (dirs[d].unit == u) return d;
        } else if (const auto [it, added] = dir_of.try_emplace(u, next); !added) {
            return it->second;
        }
        dirs.push_back({u, vec3(0.0f), vec3(0.0f)});
        return next;
    };
    for (std::uint32_t v = 0; v + 1 < start.size(); ++v) {
        if (start[v] == start[v + 1]) continue;
        const bool searched = start[v + 1] - start[v] <= kSearchedFaces;
        dirs.clear();
        if (!searched) dir_of.clear();
        corner_dir.clear();
        for (std::uint32_t i = start[v]; i < start[v + 1]; ++i) {
            const std::uint32_t t = faces_at[i];
            const std::uint32_t d = direction_of(unit[t], searched);
            dirs[d].sum += face[t];  // length = 2 x area: area weighting
            corner_dir.push_back(d);
        }
        const bool flat = dirs.size() > kMaxDirections;
        for (Direction& own : dirs) {
            vec3 sum(0.0f);
            for (const Direction& other : dirs)
                if (!flat && other.unit != vec3(0.0f) &&
                    glm::dot(own.unit, other.unit) >= cos_crease)
                    sum += other.sum;
            const float sum_len = glm::length(sum);
            own.result = sum_len > 0.0f ? sum / sum_len : own.unit;
        }
        // Each face's corner at this vertex (a face can touch a welded vertex twice).
        for (std::uint32_t i = start[v]; i < start[v + 1]; ++i) {
            const std::uint32_t t = faces_at[i];
            for (int k = 0; k < 3; ++k)
                if (weld[mesh.triangles[t][k]] == v)
                    mesh.corner_normals[3 * t + k] = dirs[corner_dir[i - start[v]]].result;
        }
    }
}

}  // namespace rt
