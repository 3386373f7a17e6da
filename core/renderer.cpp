#include "core/renderer.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "core/compare.h"
#include "core/item_buffer_step.h"
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

using detail::item_buffer_hits;
using detail::primary_packets;
using detail::Tile;
using detail::tile_count;
using detail::TileRays;
using detail::TileRunner;

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
