#include "core/renderer.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "core/compare.h"
#include "core/small_objects.h"
#include "core/stopwatch.h"
#include "core/tile_rays.h"
#include "core/tile_runner.h"

namespace rt {

bool valid_spp(int n) {
    if (n < 1 || n > 1024) return false;
    const int m = static_cast<int>(std::lround(std::sqrt(static_cast<double>(n))));
    return m * m == n;
}

namespace {
// SplitMix64's finaliser: consecutive inputs give unrelated outputs.
std::uint64_t mix(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}
}  // namespace

Ray pixel_sample(const Camera& camera, int x, int y, int s, int spp) {
    if (spp <= 1) return camera.ray(x, y);
    const int m = static_cast<int>(std::lround(std::sqrt(static_cast<double>(spp))));
    const std::uint64_t h = mix((static_cast<std::uint64_t>(static_cast<std::uint32_t>(x)) << 40) ^
                                (static_cast<std::uint64_t>(static_cast<std::uint32_t>(y)) << 16) ^
                                static_cast<std::uint64_t>(s));
    constexpr float k24 = 1.0f / 16777216.0f;  // 24 random bits to [0, 1)
    const float jx = static_cast<float>(h >> 40) * k24,
                jy = static_cast<float>((h >> 16) & 0xffffff) * k24;
    const float cell = 1.0f / static_cast<float>(m);
    return camera.ray_at(static_cast<float>(x) + (static_cast<float>(s % m) + jx) * cell,
                         static_cast<float>(y) + (static_cast<float>(s / m) + jy) * cell);
}

int resolve_thread_count(int requested) {
    if (requested > 0) return requested;
    return std::max(1u, std::thread::hardware_concurrency());
}

namespace {

using detail::Tile;
using detail::tile_count;
using detail::TileRays;
using detail::TileRunner;

template <class V>
V least(V a, V b) {
    return a < b ? a : b;
}

// The least of v's lanes in every lane: halvings, a lane against the one across.
template <class V>
V least_in_every_lane(V v) {
    constexpr int kWidth = sizeof(V) / sizeof(v[0]);
    if constexpr (kWidth == 8) {
        v = least(v, __builtin_shufflevector(v, v, 4, 5, 6, 7, 0, 1, 2, 3));
        v = least(v, __builtin_shufflevector(v, v, 2, 3, 0, 1, 6, 7, 4, 5));
        return least(v, __builtin_shufflevector(v, v, 1, 0, 3, 2, 5, 4, 7, 6));
    } else {
        static_assert(kWidth == 4, "four or eight lanes (core/simd.h)");
        v = least(v, __builtin_shufflevector(v, v, 2, 3, 0, 1));
        return least(v, __builtin_shufflevector(v, v, 1, 0, 3, 2));
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
    Ids ids[6];
    for (Ids& v : ids) v = Ids{} + kNone;
    int vectors = 0;
    static const Ids kLane = [] {
        Ids lane{};
        for (int k = 0; k < kPacketWidth; ++k) lane[k] = static_cast<std::uint32_t>(k);
        return lane;
    }();
    const Ids in_span[2] = {Ids(kLane < Ids{} + static_cast<std::uint32_t>(span)),
                            Ids(kLane + kPacketWidth < Ids{} + static_cast<std::uint32_t>(span))};
    for (int row = std::max(0, y - 1); row <= std::min(ib.height - 1, y + 1); ++row) {
        const std::size_t at = ib.index(left, row);
        if (left + kRow <= ib.width) {  // two whole vectors in the row: the span's lanes kept
            ids[vectors++] = (ib.object_ids(at) & in_span[0]) - 1u;
            ids[vectors++] = (ib.object_ids(at + kPacketWidth) & in_span[1]) - 1u;
            continue;
        }
        std::uint32_t padded[kRow] = {};  // kEmpty beyond the span
        std::memcpy(padded, &ib.ids[at], static_cast<std::size_t>(span) * sizeof padded[0]);
        ids[vectors++] = (ItemBuffer::load(padded) >> ib.prim_bits) - 1u;
        ids[vectors++] = (ItemBuffer::load(padded + kPacketWidth) >> ib.prim_bits) - 1u;
    }
    int count = 0;
    for (;;) {
        const Ids m = least_in_every_lane(
            least(least(least(ids[0], ids[1]), least(ids[2], ids[3])), least(ids[4], ids[5])));
        const std::uint32_t object = m[0];
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
[[gnu::always_inline]] inline int item_buffer_run(const Scene& scene, const ItemBuffer& ib,
                                                  const SmallObjects& small, const TileRays& rays,
                                                  int x, int y, int n, Hit* hits) {
    const RayLanes<kPacketWidth> lanes = rays.lanes(x, y, n);
    const unsigned all = (1u << n) - 1u;
    reset_hits(hits, static_cast<std::size_t>(n));
    const std::size_t at = ib.index(x, y);
    const unsigned interior = ib.interior_run(x, y, n);
    const TinyOver tiny = tiny_over(small, x, y, n, ib.width);
    const bool whole = interior == all;
    unsigned left = 0;  // inside the region of a sphere, plane or triangle, not yet tested
    const unsigned settled =
        own_ids(scene, ib, at, n, lanes, hits, interior, !whole, left) & ~tiny.lanes;
    const unsigned open = all & ~settled;
    if (open == 0) return 0;
    for (unsigned k = open; k != 0; k &= k - 1) hits[__builtin_ctz(k)] = Hit{};
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
    scene.intersect_among(tiny.objects.data(), tiny.count, lanes, hits, open);
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

// The first hits of a tile's pixels from the item buffer, a row's run of kPacketWidth
// pixels at a time, the ids kRowsAhead rows below asked for as each row starts (the
// primary step took 4-15 % less on the five shipped scenes at 1 thread, tutorial's 25-28 %
// less at 2 threads; 1 row ahead gained nothing, 2 to 12 about the same; the tile's first
// rows asked for as it starts, or the rows of triangle ids, nothing more). Returns how
// many were traced through the scene.
std::uint64_t item_buffer_hits(const Scene& scene, const ItemBuffer& ib, const SmallObjects& small,
                               const Tile& t, const TileRays& rays, std::vector<Hit>& hits) {
    constexpr int kRowsAhead = 6;
    std::uint64_t fell = 0;
    std::size_t i = 0;
    for (int y = t.y0; y < t.y1; ++y) {
        ask_for_ids(ib, t.x0, t.x1, y + kRowsAhead);
        for (int x = t.x0; x < t.x1; x += kPacketWidth) {
            const int n = std::min(kPacketWidth, t.x1 - x);
            fell += static_cast<std::uint64_t>(
                item_buffer_run(scene, ib, small, rays, x, y, n, &hits[i]));
            i += static_cast<std::size_t>(n);
        }
    }
    return fell;
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

}  // namespace

Image render(const Scene& scene, const RenderOptions& options, RenderStats* stats,
             const ProgressFn& progress, std::stop_token stop, const ItemBuffer* item_buffer) {
    return render(scene, scene.camera, options, stats, progress, stop, item_buffer);
}

namespace {

// What both ways of rendering share.
struct Pass {
    const Scene& scene;
    const Camera& camera;
    const detail::CameraTerms& terms;  // the camera's rays' terms, once a frame
    const Tracer& tracer;
    int spp;
    const ItemBuffer* item_buffer;
    const SmallObjects& small;  // with the item buffer: what it cannot speak for
    Image& image;
    std::atomic<std::uint64_t>& nonfinite;
    std::atomic<std::uint64_t>& fallbacks;

    // A traced colour, or black (counted) if it is NaN or infinite.
    vec3 finite(vec3 c) const {
        if (std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z)) return c;
        nonfinite.fetch_add(1, std::memory_order_relaxed);
        return vec3(0.0f);
    }
};

// A sample's colour added to its pixel. The first sample's is written, not added to the
// image's zero: the sum is the same (0 + c is c + 0), but the pixel is not read, and a
// read waited on memory (the image, filled with zeros before the trace, has left the
// caches: whitted's frame spent 4 % on these loads, perf).
template <bool kFirst>
[[gnu::always_inline]] inline void add_sample(vec3& pixel, const vec3& colour) {
    if constexpr (kFirst)
        pixel = colour + vec3(0.0f);
    else
        pixel += colour;
}

// The colours of a tile's first hits, added to its pixels (written, for the first
// sample): the hits found go to the tracer kPacketWidth at a time, with their rays, their
// local terms computed across SIMD lanes.
template <bool kFirst>
void shade_tile(const Pass& p, const Tracer& tracer, const Tile& t, const TileRays& rays,
                const std::vector<Hit>& hits, RayCounts& counts) {
    static constexpr auto kEach = [] {
        std::array<std::uint32_t, kPacketWidth> each{};
        for (std::uint32_t k = 0; k < kPacketWidth; ++k) each[k] = k;
        return each;
    }();
    std::array<Ray, kPacketWidth> found_rays;
    std::array<Hit, kPacketWidth> found_hits;
    std::array<vec3*, kPacketWidth> pixels;
    std::array<vec3, kPacketWidth> colours;
    int n = 0;
    const auto shade = [&] {
        tracer.shade_found(found_rays.data(), found_hits.data(), kEach.data(), n, counts,
                           colours.data());
        for (int k = 0; k < n; ++k) add_sample<kFirst>(*pixels[k], p.finite(colours[k]));
        n = 0;
    };
    std::uint32_t i = 0;
    for (int y = t.y0; y < t.y1; ++y) {
        for (int x = t.x0; x < t.x1; ++x, ++i) {
            vec3& pixel = p.image.at(x, y);
            if (!hits[i].found()) {
                add_sample<kFirst>(pixel, p.finite(p.scene.background));
                continue;
            }
            found_rays[n] = rays.ray(x, y);
            found_hits[n] = hits[i];
            pixels[n++] = &pixel;
            if (n == kPacketWidth) shade();
        }
    }
    if (n > 0) shade();
}

struct TileArrays {
    TileRays rays;
    std::vector<Hit> hits;
    std::vector<Ray> tile_rays;
};

// Each tile takes all its samples before the next tile, in one pass over the image: per
// sample, the first hits of the tile's pixels (from the item buffer where there is one),
// then their shading. The rays and hits of a tile stay in the cache (a frame-sized buffer
// of hits written by one pass and read by a second cost the item buffer's primary pass
// as much time as its intersection tests), and no thread waits for the others between
// the passes or the samples (two passes per sample: --spp 16 cost 17.5-19.1 x --spp 1 on
// whitted). The sum per pixel runs over the samples in order. The wall time is split
// between first hits and shading in the proportion of the threads' time in each.
bool render_by_tile(const Pass& p, TileRunner& runner, std::stop_token stop, RayCounts& counts,
                    RenderStats& times) {
    std::atomic<std::int64_t> primary_ns{0}, shade_ns{0};
    const Stopwatch watch;
    const bool complete = runner.run(stop, counts, [&](const Tile& t, RayCounts& local) {
        // Each worker its own copy of the tracer (a few words): a shared one sat on the
        // calling thread's stack beside what that thread writes for every ray, and reading
        // it made the threads wait on each other's cache line (whitted at 1280 x 720 on
        // two threads, medians of 7 to 9 runs: 0.164 s shared, 0.134 s copied).
        const Tracer mine = p.tracer;
        const int w = t.x1 - t.x0;
        const std::size_t n = static_cast<std::size_t>(w) * (t.y1 - t.y0);
        // Each worker thread's arrays, kept from tile to tile (every step writes what it
        // reads: the rays made, the hits reset): made for each tile, their eight
        // allocations and fresh hits cost the frame 1-7 % (whitted 0.988x, tutorial 0.93x
        // reused, frames in turns).
        thread_local TileArrays arrays;
        TileRays& rays = arrays.rays;
        std::vector<Hit>& hits = arrays.hits;
        hits.resize(n);
        std::vector<Ray>& tile_rays = arrays.tile_rays;  // without the item buffer
        double primary = 0.0, shade = 0.0;
        std::uint64_t fell = 0;
        for (int s = 0; s < p.spp; ++s) {
            Stopwatch lap;
            rays.make(p.terms, t, s, p.spp);
            if (p.item_buffer)
                fell += item_buffer_hits(p.scene, *p.item_buffer, p.small, t, rays, hits);
            else
                primary_packets(p.scene, rays, tile_rays, hits);
            local.primary += n;
            primary += lap.lap();
            if (s == 0)
                shade_tile<true>(p, mine, t, rays, hits, local);
            else
                shade_tile<false>(p, mine, t, rays, hits, local);
            shade += lap.lap();
        }
        p.fallbacks.fetch_add(fell, std::memory_order_relaxed);
        primary_ns.fetch_add(static_cast<std::int64_t>(primary * 1e9), std::memory_order_relaxed);
        shade_ns.fetch_add(static_cast<std::int64_t>(shade * 1e9), std::memory_order_relaxed);
    });
    const double wall = watch.seconds();
    const double busy = static_cast<double>(primary_ns.load() + shade_ns.load());
    times.primary_seconds = busy > 0.0 ? wall * static_cast<double>(primary_ns.load()) / busy : 0.0;
    times.secondary_seconds = wall - times.primary_seconds;
    if (p.spp > 1) {
        const float scale = 1.0f / static_cast<float>(p.spp);
        for (vec3& c : p.image.pixels) c *= scale;
    }
    return complete;
}

}  // namespace

Image render(const Scene& scene, const Camera& camera, const RenderOptions& options,
             RenderStats* stats, const ProgressFn& progress, std::stop_token stop,
             const ItemBuffer* item_buffer) {
    const int width = camera.cols, height = camera.rows;
    if (item_buffer && (item_buffer->width != width || item_buffer->height != height))
        throw std::invalid_argument("render: the item buffer's size differs from the camera's");
    if (!valid_spp(options.spp))
        throw std::invalid_argument("render: samples per pixel must be a square number");
    const int spp = options.spp;
    if (spp > 1) item_buffer = nullptr;  // it knows the pixel centres only
    const int threads = resolve_thread_count(options.threads);
    Image image(width, height);
    std::atomic<std::uint64_t> fallbacks{0}, nonfinite{0};
    RayCounts counts;
    const int tile_size = std::max(1, options.tile_size);
    const int tiles = tile_count(width, height, tile_size);
    TileRunner runner(width, height, tile_size, threads, progress, tiles);
    const Tracer tracer(scene, options.trace);
    const Stopwatch watch;
    const SmallObjects small = item_buffer ? SmallObjects(scene, camera) : SmallObjects();
    const detail::CameraTerms terms(camera);
    const Pass pass{scene,       camera, terms, tracer,    spp,
                    item_buffer, small,  image, nonfinite, fallbacks};
    RenderStats times;
    const bool complete = render_by_tile(pass, runner, stop, counts, times);
    if (stats) {
        stats->rays = counts;
        stats->threads = std::min(threads, tiles);
        stats->primary_seconds = times.primary_seconds;
        stats->secondary_seconds = times.secondary_seconds;
        stats->seconds = watch.seconds();
        stats->nonfinite_pixels = nonfinite.load();
        stats->item_buffer_fallbacks = fallbacks.load();
        stats->cancelled = !complete;
    }
    return image;
}

std::uint64_t item_buffer_disagreements(const Image& with_item_buffer, const Image& from_scratch) {
    return compare_images(with_item_buffer, from_scratch, 1.5 / 255.0).pixels_over;
}

}  // namespace rt
