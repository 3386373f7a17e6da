#include "core/item_buffer_step.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <span>

namespace rt::detail {

namespace {

template <class V>
V least(V a, V b) {
    return a < b ? a : b;
}

template <class V>
V greatest(V a, V b) {
    return a < b ? b : a;
}

// op over all of v's lanes, in every lane: halvings, a lane against the one across.
template <class V, class Op>
V in_every_lane(V v, Op op) {
    constexpr int kWidth = sizeof(V) / sizeof(v[0]);
    if constexpr (kWidth == 16) {
        v = op(v,
               __builtin_shufflevector(v, v, 8, 9, 10, 11, 12, 13, 14, 15, 0, 1, 2, 3, 4, 5, 6, 7));
        v = op(v,
               __builtin_shufflevector(v, v, 4, 5, 6, 7, 0, 1, 2, 3, 12, 13, 14, 15, 8, 9, 10, 11));
        v = op(v,
               __builtin_shufflevector(v, v, 2, 3, 0, 1, 6, 7, 4, 5, 10, 11, 8, 9, 14, 15, 12, 13));
        return op(
            v, __builtin_shufflevector(v, v, 1, 0, 3, 2, 5, 4, 7, 6, 9, 8, 11, 10, 13, 12, 15, 14));
    } else if constexpr (kWidth == 8) {
        v = op(v, __builtin_shufflevector(v, v, 4, 5, 6, 7, 0, 1, 2, 3));
        v = op(v, __builtin_shufflevector(v, v, 2, 3, 0, 1, 6, 7, 4, 5));
        return op(v, __builtin_shufflevector(v, v, 1, 0, 3, 2, 5, 4, 7, 6));
    } else {
        static_assert(kWidth == 4, "four, eight or sixteen lanes (core/simd.h)");
        v = op(v, __builtin_shufflevector(v, v, 2, 3, 0, 1));
        return op(v, __builtin_shufflevector(v, v, 1, 0, 3, 2));
    }
}

// The objects named around pixels x0 .. x1 of row y (their 3 x 3 blocks), each once, in
// the order of their indices. The three rows' ids, at most kPacketWidth + 2 each, sit in
// two vectors a row, as indices (id - 1: the background, kEmpty, wraps to the largest);
// the least index left is found across all six vectors at once and then made the largest
// wherever it stands, so the work goes with the few objects there are, not with the thirty
// ids, and with one branch an object (many_spheres: 29 % of its runs have a pixel on an
// edge; finding the first id left, vector by vector, took a quarter of the primary step).
int objects_around(const ItemBuffer& ib, int x0, int x1, int y, std::uint32_t* out) {
    using Ids = ItemBuffer::Ids;
    constexpr int kRow = 2 * kPacketWidth;
    constexpr std::uint32_t kNone = ItemBuffer::kEmpty - 1u;  // the largest
    const int left = std::max(0, x0 - 1), right = std::min(ib.width - 1, x1 + 1);
    const int span = right - left + 1;  // at most kPacketWidth + 2 <= kRow
    // Rows y - 1, y and y + 1, two vectors each; kNone beyond the image.
    Ids ids[6];
    static const Ids kLane = [] {
        Ids lane{};
        for (int k = 0; k < kPacketWidth; ++k) lane[k] = static_cast<std::uint32_t>(k);
        return lane;
    }();
    const Ids in_span[2] = {Ids(kLane < Ids{} + static_cast<std::uint32_t>(span)),
                            Ids(kLane + kPacketWidth < Ids{} + static_cast<std::uint32_t>(span))};
    // Each row's two vectors at fixed places, so that they stay in registers (counted in
    // turn, they went through memory).
#pragma GCC unroll 3
    for (int d = 0; d < 3; ++d) {
        const int row = y - 1 + d;
        if (row < 0 || row >= ib.height) {
            ids[2 * d] = ids[2 * d + 1] = Ids{} + kNone;
            continue;
        }
        const std::size_t at = ib.index(left, row);
        if (left + kRow <= ib.width) {  // two whole vectors in the row: the span's lanes kept
            ids[2 * d] = (ib.object_ids(at) & in_span[0]) - 1u;
            ids[2 * d + 1] = (ib.object_ids(at + kPacketWidth) & in_span[1]) - 1u;
            continue;
        }
        std::uint32_t padded[kRow] = {};  // kEmpty beyond the span
        std::memcpy(padded, &ib.ids[at], static_cast<std::size_t>(span) * sizeof padded[0]);
        ids[2 * d] = (ItemBuffer::load(padded) >> ib.prim_bits) - 1u;
        ids[2 * d + 1] = (ItemBuffer::load(padded + kPacketWidth) >> ib.prim_bits) - 1u;
    }
    // Most runs on an edge name one or two objects: the least index and the greatest
    // (kNone, wrapped to 0 by adding one, left out) found side by side, not one after the
    // other, and where every id is one of them or kNone, they are the answer (many_spheres:
    // the step took 4 % less).
    const auto fold = [&](auto op, std::uint32_t add) {
        return in_every_lane(op(op(op(ids[0] + add, ids[1] + add), op(ids[2] + add, ids[3] + add)),
                                op(ids[4] + add, ids[5] + add)),
                             op)[0];
    };
    const std::uint32_t lo = fold(least<Ids>, 0u), hi = fold(greatest<Ids>, 1u) - 1u;
    if (lo == kNone) return 0;
    out[0] = lo;
    if (hi == lo) return 1;
    Ids others{};
    for (const Ids& v : ids) others |= Ids(v != lo) & Ids(v != hi) & Ids(v != kNone);
    if (bits(others != Ids{}) == 0) {
        out[1] = hi;
        return 2;
    }
    int count = 0;
    for (;;) {
        const std::uint32_t object = fold(least<Ids>, 0u);
        const Ids m = Ids{} + object;
        if (object == kNone) return count;
        out[count++] = object;
        for (Ids& v : ids) v |= Ids(v == m);  // m is the least in every lane
    }
}

// The objects too small for the raster, and the spheres cut by the image's edge along it
// (core/small_objects.h), that lie over pixels x .. x + n - 1 of row y: their pixels are
// not settled by the ids, but tested against them besides what is named around.
struct TinyOver {
    std::array<std::uint32_t, 4 * kPacketWidth> objects;
    int count = 0;
    unsigned lanes = 0;  // the pixels they lie over
    bool crowd = false;  // more than `objects` holds: the whole scene for those pixels
};

TinyOver tiny_over(const SmallObjects& small, int x, int y, int n, int width) {
    TinyOver tiny;
    const auto take = [&](std::span<const SmallObjects::Span> spans) {
        for (const SmallObjects::Span& s : spans) {
            const int lo = std::max(s.x0, x) - x, hi = std::min(s.x1, x + n - 1) - x;
            if (lo > hi) continue;
            tiny.lanes |= ((2u << hi) - 1u) & ~((1u << lo) - 1u);
            if (tiny.count < static_cast<int>(tiny.objects.size()))
                tiny.objects[tiny.count++] = s.object;
            else
                tiny.crowd = true;
        }
    };
    take(small.row(y));
    if (x == 0 || x + n == width) take(small.side(y));  // a run at the image's side
    return tiny;
}

bool is_mesh(const Scene& scene, std::uint32_t object) {
    return object < scene.objects.size() &&
           std::holds_alternative<MeshRef>(scene.objects[object].shape);
}

// The pixels of `lanes` (inside their object's region, ItemBuffer::interior_run) tested
// against the object (and triangle) each names, together with the others of the run that
// name the same one; a pixel inside the background is background. With `meshes_only`,
// the pixels naming a sphere, plane or triangle are left as they are (and added to
// `left`). Returns the pixels settled: a hit found, or the background.
unsigned own_ids(const Scene& scene, const ItemBuffer& ib, std::size_t at, int n,
                 const RayLanes<kPacketWidth>& lanes, Hit* hits, unsigned rest, bool meshes_only,
                 unsigned& left) {
    unsigned settled = 0;
    std::uint32_t triangles[kPacketWidth];
    bool have_triangles = false;
    while (rest != 0) {
        const std::uint32_t id = ib.object_id(at + __builtin_ctz(rest));
        const unsigned same = ib.same_object_run(at, n, id) & rest;
        rest &= ~same;
        if (id == ItemBuffer::kEmpty) {
            settled |= same;  // nothing here nor around it
            continue;
        }
        if (meshes_only && !is_mesh(scene, id - 1)) {
            left |= same;
            continue;
        }
        if (!have_triangles) ib.triangles(at, n, triangles), have_triangles = true;
        settled |= scene.intersect_primitive_packet(id - 1, triangles, lanes, hits, same, true);
    }
    return settled;
}

// The first hits of pixels x .. x + n - 1 of row y (n <= kPacketWidth) from the item
// buffer. Where the whole run lies inside objects' regions, each pixel is tested against
// what it names (own_ids). A pixel on an edge, or whose named primitive turns out to
// miss, is tested against every object named around it, not the whole scene: the raster
// and the tracer sample the same pixel centres, and where they disagree (the raster's
// tessellated spheres, rounding at an edge) the object the ray meets is named next to it
// (the planes too: the raster draws them to within a fraction of a pixel of their
// horizon, GpuScene::plane_extent). In a run with an edge, the spheres, planes and
// triangles around are tested once for all its pixels but those a mesh's triangle
// settles, not once for the pixels inside and again for those on the edge (many_spheres,
// where 29 % of the runs have an edge: the step took 18 % less); a mesh, a traversal of
// its own tree, only for the pixels on the edge and those still without a hit. Returns
// how many pixels were on an edge or missed.
// `interior`: ib.interior_run(x, y, n); `tiny`: tiny_over(small, x, y, n, ib.width).
[[gnu::always_inline]] inline int item_buffer_run(const Scene& scene, const ItemBuffer& ib,
                                                  const TileRays& rays, int x, int y, int n,
                                                  unsigned interior, const TinyOver& tiny,
                                                  Hit* hits) {
    const RayLanes<kPacketWidth> lanes = rays.lanes(x, y, n);
    const unsigned all = (1u << n) - 1u;
    reset_hits(hits, static_cast<std::size_t>(n));
    const std::size_t at = ib.index(x, y);
    const bool whole = interior == all;
    unsigned left = 0;  // inside the region of a sphere, plane or triangle, not yet tested
    const unsigned settled =
        own_ids(scene, ib, at, n, lanes, hits, interior, !whole, left) & ~tiny.lanes;
    const unsigned open = all & ~settled;
    if (open == 0) return 0;
    // The open pixels' records are as reset_hits left them (own_ids writes a miss as
    // Hit{}), but for those found under something small, tested again with it.
    for (unsigned k = open & tiny.lanes; k != 0; k &= k - 1) hits[__builtin_ctz(k)] = Hit{};
    const int on_edges = std::popcount(whole ? open : all & ~interior);
    if (tiny.crowd) {
        std::array<Ray, kPacketWidth> run;  // the Rays only here, where the scene's tree reads them
        rays.span(rays.index(x, y), static_cast<std::size_t>(n), run.data());
        scene.intersect_packet(run.data(), hits, open);
        return on_edges;
    }
    std::array<std::uint32_t, 3 * (kPacketWidth + 2)> around, meshes;
    int count =
        objects_around(ib, x + __builtin_ctz(open), x + 31 - __builtin_clz(open), y, around.data());
    int mesh_count = 0;
    if (!whole) {  // the meshes apart, in their order
        int kept = 0;
        for (int k = 0; k < count; ++k)
            (is_mesh(scene, around[k]) ? meshes[mesh_count++] : around[kept++]) = around[k];
        count = kept;
    }
    scene.intersect_among(around.data(), count, lanes, hits, open);
    if (tiny.count > 0) scene.intersect_among(tiny.objects.data(), tiny.count, lanes, hits, open);
    if (mesh_count == 0) return on_edges;
    unsigned trusted = 0;  // met what they name, inside its region: as own_ids leaves them
    for (unsigned k = left & open; k != 0; k &= k - 1) {
        const int lane = __builtin_ctz(k);
        if (hits[lane].found() && hits[lane].object + 1 == ib.object_id(at + lane))
            trusted |= k & -k;
    }
    scene.intersect_among(meshes.data(), mesh_count, lanes, hits, open & ~trusted);
    return on_edges;
}

// The ids of pixels x0 - 1 .. x1 of row y (a tile's row and its neighbours) asked for
// from memory ahead of their use. A tile's row is one cache line of a row of ids 5 KB
// long (1280 pixels): each row of the tile meets a line not read before, below it, and
// the hardware's prefetchers, which follow sequences of lines, do not see the step from
// row to row. Always inlined: a function that only prefetches is free of effects to the
// compiler, which drops the calls (GCC 12 did, and the prefetches with them).
[[gnu::always_inline]] inline void ask_for_ids(const ItemBuffer& ib, int x0, int x1, int y) {
    if (y >= ib.height) return;
    constexpr int kPerLine = 64 / sizeof(std::uint32_t);
    const std::uint32_t* row = &ib.ids[ib.index(0, y)];
    const int last = std::min(ib.width - 1, x1);
    for (int x = std::max(0, x0 - 1); x < last; x += kPerLine) __builtin_prefetch(row + x);
    __builtin_prefetch(row + last);
}

// A full run of pixels inside one object's region (none on an edge, nothing small over
// them), put aside to be tested with the others like it (InsideRuns).
struct InsideRun {
    int x, y;
    std::uint32_t object;  // its index
    std::size_t hit;       // its first pixel's index in the tile's hits
};

// The runs inside one object's region, each tested against that object alone (own_ids'
// test), one after another with nothing between them: each run's test is a chain of
// dependent divisions and a square root, and apart from the rest of the step, the
// processor overlaps one run's chain with the next's. A run that does not all hit its
// object (the raster and the tracer disagree there) goes through item_buffer_run.
class InsideRuns {
  public:
    bool full() const { return count_ == kMost; }
    void add(const InsideRun& run) { runs_[count_++] = run; }

    // Returns how many of their pixels were traced through the scene.
    std::uint64_t test(const Scene& scene, const ItemBuffer& ib, const TileRays& rays, Hit* hits) {
        constexpr unsigned kAll = (1u << kPacketWidth) - 1u;
        std::uint64_t fell = 0;
        std::uint32_t triangles[kPacketWidth];
        for (int k = 0; k < count_; ++k) {
            const InsideRun& run = runs_[k];
            Hit* at = &hits[run.hit];
            reset_hits(at, kPacketWidth);
            ib.triangles(ib.index(run.x, run.y), kPacketWidth, triangles);
            const unsigned found = scene.intersect_primitive_packet(
                run.object, triangles, rays.lanes(run.x, run.y, kPacketWidth), at, kAll, true);
            if (found != kAll)
                fell += static_cast<std::uint64_t>(item_buffer_run(
                    scene, ib, rays, run.x, run.y, kPacketWidth, kAll, TinyOver{}, at));
        }
        count_ = 0;
        return fell;
    }

  private:
    static constexpr int kMost = 64;
    std::array<InsideRun, kMost> runs_;
    int count_ = 0;
};

}  // namespace

// A row's run of kPacketWidth pixels at a time, the ids kRowsAhead rows below asked for as
// each row starts (the primary step took 4-15 % less on the five shipped scenes at 1
// thread, tutorial's 25-28 % less at 2 threads; 1 row ahead gained nothing, 2 to 12 about
// the same; the tile's first rows asked for as it starts, or the rows of triangle ids,
// nothing more). Full runs inside one object's region wait in `inside` and are tested
// together (InsideRuns); full runs inside the background's are misses, with no test and
// no ray made (tutorial, half of it sky: the step took 13 % less on one thread, whitted,
// cornell and many_spheres 2-4 %).

std::uint64_t item_buffer_hits(const Scene& scene, const ItemBuffer& ib, const SmallObjects& small,
                               const Tile& t, const TileRays& rays, std::vector<Hit>& hits) {
    constexpr int kRowsAhead = 6;
    constexpr unsigned kAll = (1u << kPacketWidth) - 1u;
    std::uint64_t fell = 0;
    std::size_t i = 0;
    InsideRuns inside;
    for (int y = t.y0; y < t.y1; ++y) {
        ask_for_ids(ib, t.x0, t.x1, y + kRowsAhead);
        for (int x = t.x0; x < t.x1; x += kPacketWidth) {
            const int n = std::min(kPacketWidth, t.x1 - x);
            const unsigned interior = ib.interior_run(x, y, n);
            const TinyOver tiny = tiny_over(small, x, y, n, ib.width);
            if (interior == kAll && n == kPacketWidth && tiny.lanes == 0) {
                // Each pixel names what the pixels beside it name: the run, one object.
                const std::uint32_t id = ib.object_id(ib.index(x, y));
                if (id == ItemBuffer::kEmpty) {
                    reset_hits(&hits[i], kPacketWidth);  // the background, and only it around
                } else {
                    if (inside.full()) fell += inside.test(scene, ib, rays, hits.data());
                    inside.add({x, y, id - 1, i});
                }
            } else {
                fell += static_cast<std::uint64_t>(
                    item_buffer_run(scene, ib, rays, x, y, n, interior, tiny, &hits[i]));
            }
            i += static_cast<std::size_t>(n);
        }
    }
    return fell + inside.test(scene, ib, rays, hits.data());
}

// The first hits of a tile's rays, kPacketWidth neighbours at a time (a row's run of
// pixels, rows running on where the tile is narrower): the hits Scene::intersect gives,
// the boxes tested once for a packet (core/wide_bvh_packet.h). The tile's Rays are made
// first, all together, into `tile` (made packet by packet, next to the traversal that
// reads them, the step took 2-4 % longer: tutorial, many_spheres).
void primary_packets(const Scene& scene, const TileRays& rays, std::vector<Ray>& tile,
                     std::vector<Hit>& hits) {
    tile.resize(hits.size());
    rays.span(0, hits.size(), tile.data());
    for (std::size_t i = 0; i < hits.size(); i += kPacketWidth) {
        const std::size_t n = std::min<std::size_t>(kPacketWidth, hits.size() - i);
        reset_hits(&hits[i], n);
        scene.intersect_packet(&tile[i], &hits[i], (1u << n) - 1u);
    }
}

}  // namespace rt::detail
