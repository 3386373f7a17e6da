#pragma once
// What a mesh's BVH is built over: a reference per triangle, and more for long thin ones.
//
// Long thin triangles at an angle to the axes (hay, hair, grass, the slivers of a lathed
// or twisted surface) fill almost none of their boxes: a needle 3 units long along a
// diagonal has a box 1.7 units on a side, and every ray through that box tests it. Its
// halves have boxes of an eighth of that volume each. Early split clipping (Ernst and
// Greiner, "Early Split Clipping for Bounding Volume Hierarchies", 2007) hands the build
// such pieces as references of their own to the one triangle, each with the box of the
// triangle's part in a slab of space. A triangle then sits in several leaves; a ray that
// reaches two of them tests it twice and gets the same answer from both.

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "core/aabb.h"
#include "core/large_array.h"

namespace rt {

class TaskPool;

inline constexpr int kMostPieces = 16;

// Which triangles are cut, and into how many pieces.
struct SplitLimits {
    // A triangle is cut only where its box's area is more than this many times the
    // mesh's mean triangle's (both sides): larger by far than a leaf's worth of compact
    // triangles would have. (A lathed surface's slivers are long and thin too, but their
    // neighbours fill their boxes, and a leaf's box is no smaller for cutting them: on the
    // bench's vase, 120,000 of them, the cut pieces built in twice the time and traced no
    // faster; its slivers' boxes are at most 128 times its mean, straws' and a fan's
    // mostly above 256 times.)
    float size_ratio = 128.0f;
    // It is cut where its box's area is more than this many times its own (both sides):
    // into ceil(ratio / area_ratio) slabs along its box's longest axis ...
    float area_ratio = 16.0f;
    // ... and at most this many (1: none cut; up to kMostPieces) ...
    int max_pieces = 2;
    // ... where the pieces' boxes have at most this share of the whole box's area.
    float area_share = 0.75f;
};

struct TriangleRefs {
    // The first triangles.size() are the triangles' boxes (a cut one's first piece), then
    // the other pieces', whose triangles extra_triangles holds in the same order.
    LargeArray<Aabb> boxes;
    LargeArray<std::uint32_t> extra_triangles;
    Aabb bounds;  // of all the triangles

    std::uint32_t triangle(std::uint32_t ref) const {
        const std::size_t n = boxes.size() - extra_triangles.size();
        return ref < n ? ref : extra_triangles[ref - n];
    }
};

// On `parts` parts of the triangles on `pool` (null: here). Every point of a triangle
// lies in one of its pieces' boxes: they are computed in double precision and rounded
// outwards.
TriangleRefs triangle_refs(std::span<const vec3> positions, std::span<const glm::uvec3> triangles,
                           const SplitLimits& limits, TaskPool* pool, int parts);

// Triangle (a, b, c), whose box is `box`, cut into pieces if it is thin as `limits` say:
// their boxes, piece[0 .. count), and the count (1: not cut, piece[0] not written). Its
// pieces are slabs of its box along the box's longest axis.
int cut_thin_triangle(const vec3& a, const vec3& b, const vec3& c, const Aabb& box,
                      const SplitLimits& limits, Aabb* piece);

}  // namespace rt
