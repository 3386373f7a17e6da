#include "core/triangle_refs.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "core/parallel.h"

namespace rt {
namespace {

// The bounds of some points in double precision (not initialised: empty() is the empty one).
struct DoubleBox {
    glm::dvec3 lo, hi;
    static DoubleBox empty() { return {glm::dvec3(HUGE_VAL), glm::dvec3(-HUGE_VAL)}; }
    void grow(const glm::dvec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
};

// x as a float below (down) or above (up) x by a margin: x was computed in double
// precision, and rounding it to a float moves it by up to half a float's step; the
// margin, 2^-21 of it (four steps) and the least normal float, covers both and costs no
// branch (the library's nextafter, on every coordinate, took a third of the cut's time).
float round_down(double x) {
    const float f = static_cast<float>(x);
    return f - (std::abs(f) * 0x1p-21f + std::numeric_limits<float>::min());
}
float round_up(double x) {
    const float f = static_cast<float>(x);
    return f + (std::abs(f) * 0x1p-21f + std::numeric_limits<float>::min());
}

// Where the plane p[axis] = s meets the triangle's edges, added to the slabs on either
// side of it (a corner on the plane is met by its two edges).
void cut_edges(const glm::dvec3 (&v)[3], int axis, double s, DoubleBox& below, DoubleBox& above) {
    for (int i = 0; i < 3; ++i) {
        const glm::dvec3& p = v[i];
        const glm::dvec3& q = v[(i + 1) % 3];
        if ((p[axis] < s && q[axis] < s) || (p[axis] > s && q[axis] > s) || p[axis] == q[axis])
            continue;
        glm::dvec3 x = p + (q - p) * ((s - p[axis]) / (q[axis] - p[axis]));
        x[axis] = s;
        below.grow(x);
        above.grow(x);
    }
}

// The boxes of the triangle's parts in `pieces` slabs of its box along `axis`.
void cut_triangle(const vec3& a, const vec3& b, const vec3& c, const Aabb& box, int axis,
                  int pieces, Aabb* out) {
    const glm::dvec3 v[3] = {glm::dvec3(a), glm::dvec3(b), glm::dvec3(c)};
    // `pieces` slabs of equal width along the axis: each holds the corners inside it and
    // the points where its planes cut the edges, which bound the triangle's part in it.
    std::array<DoubleBox, kMostPieces> slab;  // (the first `pieces` set: the others unused)
    for (int i = 0; i < pieces; ++i) slab[i] = DoubleBox::empty();
    const double lo = box.lo[axis], width = (double{box.hi[axis]} - lo) / pieces;
    const auto plane = [&](int i) { return lo + width * i; };  // between slabs i - 1 and i
    for (const glm::dvec3& corner : v) {
        int i = 0;
        while (i + 1 < pieces && plane(i + 1) <= corner[axis]) ++i;
        slab[i].grow(corner);
    }
    for (int i = 1; i < pieces; ++i) cut_edges(v, axis, plane(i), slab[i - 1], slab[i]);
    for (int i = 0; i < pieces; ++i) {
        // (A slab the triangle spans always holds a point: it reaches across its box.)
        for (int k = 0; k < 3; ++k) {
            out[i].lo[k] = std::max(box.lo[k], round_down(slab[i].lo[k]));
            out[i].hi[k] = std::min(box.hi[k], round_up(slab[i].hi[k]));
        }
    }
}

}  // namespace

int cut_thin_triangle(const vec3& a, const vec3& b, const vec3& c, const Aabb& box,
                      const SplitLimits& limits, Aabb* piece) {
    const vec3 e = box.extent();
    const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
    const int most = std::clamp(limits.max_pieces, 1, kMostPieces);
    if (most == 1 || !(e[axis] > 0.0f)) return 1;
    // Both sides' area against the box's, in double: far from the origin or huge, floats'
    // products overflow. (Only the choice depends on it, not what a ray hits.)
    const glm::dvec3 u = glm::dvec3(b) - glm::dvec3(a), w = glm::dvec3(c) - glm::dvec3(a);
    const double both_sides = glm::length(glm::cross(u, w));
    const glm::dvec3 d(e);
    const double box_area = 2.0 * (d.x * d.y + d.y * d.z + d.z * d.x);
    const double ratio = box_area / both_sides;  // inf for a degenerate one: not cut
    if (!(ratio > limits.area_ratio) || !std::isfinite(ratio)) return 1;
    const int pieces =
        static_cast<int>(std::min<double>(most, std::ceil(ratio / limits.area_ratio)));
    // Cut only where the pieces' boxes are much smaller than the whole's: a sliver along
    // an axis fills as little of its box, but its pieces' boxes have as much area.
    cut_triangle(a, b, c, box, axis, pieces, piece);
    double pieces_area = 0.0;
    for (int i = 0; i < pieces; ++i) pieces_area += piece[i].half_area();
    return pieces_area <= limits.area_share * 0.5 * box_area ? pieces : 1;
}

TriangleRefs triangle_refs(std::span<const vec3> positions, std::span<const glm::uvec3> triangles,
                           const SplitLimits& limits, TaskPool* pool, int parts) {
    TriangleRefs refs;
    const std::size_t n = triangles.size();
    refs.boxes.resize(n);
    const auto each = [](int part) { return static_cast<std::size_t>(part); };
    std::vector<Aabb> part_bounds(each(parts));
    std::vector<double> part_area(each(parts)), part_largest(each(parts));
    // The boxes, the largest box's area, and the triangles' mean area, from every fourth
    // (all of them took the pass twice the time of the boxes alone).
    constexpr std::size_t kSampled = 4;
    parallel_parts(pool, 0, n, parts, [&](int part, std::size_t begin, std::size_t end) {
        Aabb all;
        float largest = 0.0f;
        for (std::size_t t = begin; t < end; ++t) {
            const glm::uvec3 tri = triangles[t];
            Aabb box;
            for (int k = 0; k < 3; ++k) box.grow(positions[tri[k]]);
            refs.boxes[t] = box;
            all.grow(box);
            largest = std::max(largest, box.half_area());
        }
        double area = 0.0;
        for (std::size_t t = begin; t < end; t += kSampled) {
            const glm::uvec3 tri = triangles[t];
            const vec3 &a = positions[tri[0]], &b = positions[tri[1]], &c = positions[tri[2]];
            area += double{glm::length(glm::cross(b - a, c - a))};
        }
        part_bounds[each(part)] = all;
        part_area[each(part)] = area;
        part_largest[each(part)] = 2.0 * double{largest};
    });
    for (const Aabb& b : part_bounds) refs.bounds.grow(b);
    if (limits.max_pieces <= 1 || n == 0) return refs;
    double area = 0.0, largest = 0.0;
    for (double a : part_area) area += a;
    for (double a : part_largest) largest = std::max(largest, a);
    // Which triangles are cut, those whose boxes are large against the mesh's triangles,
    // and into how many pieces; then the pieces: the first in the triangle's own place, the
    // others after every triangle, each part's in turn. (The cuts are made twice, which
    // costs less than arrays of unknown size: a fresh page costs a fault, 6-16 us on some
    // machines, docs/BENCHMARKS.md.)
    std::size_t sampled = 0;  // as the parts' loops count them
    for (int part = 0; part < parts; ++part) {
        const std::size_t begin = n * each(part) / each(parts),
                          end = n * each(part + 1) / each(parts);
        sampled += (end - begin + kSampled - 1) / kSampled;
    }
    const double large = limits.size_ratio * area / static_cast<double>(sampled);
    if (!(largest > large)) return refs;  // most meshes: none that large
    LargeArray<std::uint8_t> pieces(n);
    std::vector<std::size_t> first_extra(each(parts) + 1, 0);
    parallel_parts(pool, 0, n, parts, [&](int part, std::size_t begin, std::size_t end) {
        std::size_t extra = 0;
        std::array<Aabb, kMostPieces> piece;
        for (std::size_t t = begin; t < end; ++t) {
            int count = 1;
            if (2.0 * double{refs.boxes[t].half_area()} > large) {
                const glm::uvec3 tri = triangles[t];
                count = cut_thin_triangle(positions[tri[0]], positions[tri[1]], positions[tri[2]],
                                          refs.boxes[t], limits, piece.data());
            }
            pieces[t] = static_cast<std::uint8_t>(count);
            extra += static_cast<std::size_t>(count - 1);
        }
        first_extra[each(part) + 1] = extra;
    });
    for (std::size_t p = 1; p < first_extra.size(); ++p) first_extra[p] += first_extra[p - 1];
    if (first_extra.back() == 0) return refs;
    refs.boxes.resize(n + first_extra.back());
    refs.extra_triangles.resize(first_extra.back());
    parallel_parts(pool, 0, n, parts, [&](int part, std::size_t begin, std::size_t end) {
        std::size_t next = first_extra[each(part)];
        std::array<Aabb, kMostPieces> piece;
        for (std::size_t t = begin; t < end; ++t) {
            if (pieces[t] == 1) continue;
            const glm::uvec3 tri = triangles[t];
            const int count =
                cut_thin_triangle(positions[tri[0]], positions[tri[1]], positions[tri[2]],
                                  refs.boxes[t], limits, piece.data());
            refs.boxes[t] = piece[0];
            for (int i = 1; i < count; ++i, ++next) {
                refs.boxes[n + next] = piece[i];
                refs.extra_triangles[next] = static_cast<std::uint32_t>(t);
            }
        }
    });
    return refs;
}

}  // namespace rt
