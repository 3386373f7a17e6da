#include "core/renderer.h"

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <vector>

#include "core/compare.h"
#include "core/stopwatch.h"
#include "core/tile_runner.h"

namespace rt {

int resolve_thread_count(int requested) {
    if (requested > 0) return requested;
    return std::max(1u, std::thread::hardware_concurrency());
}

namespace {

using detail::Tile;
using detail::tile_count;
using detail::TileRunner;

// The first hit along a camera ray, from the item buffer where it can be trusted.
Hit primary_hit(const Scene& scene, const Ray& ray, const ItemBuffer* ib, int x, int y,
                bool& fell_back) {
    Hit hit;
    if (ib) {
        const std::size_t i = ib->index(x, y);
        const std::uint32_t id = ib->object[i];
        if (ib->interior(x, y)) {
            if (id == ItemBuffer::kEmpty) return hit;  // nothing here nor around it
            if (scene.intersect_primitive(id - 1, ib->prim[i], ray, hit)) return hit;
        }
        fell_back = true;
        hit = Hit{};
    }
    scene.intersect(ray, hit);
    return hit;
}

}  // namespace

Image render(const Scene& scene, const RenderOptions& options, RenderStats* stats,
             const ProgressFn& progress, std::stop_token stop, const ItemBuffer* item_buffer) {
    return render(scene, scene.camera, options, stats, progress, stop, item_buffer);
}

Image render(const Scene& scene, const Camera& camera, const RenderOptions& options,
             RenderStats* stats, const ProgressFn& progress, std::stop_token stop,
             const ItemBuffer* item_buffer) {
    const int width = camera.cols, height = camera.rows;
    if (item_buffer && (item_buffer->width != width || item_buffer->height != height))
        throw std::invalid_argument("render: the item buffer's size differs from the camera's");
    const int threads = resolve_thread_count(options.threads);
    Image image(width, height);
    std::vector<Hit> hits(image.pixels.size());
    std::atomic<std::uint64_t> fallbacks{0}, nonfinite{0};
    RayCounts counts;
    const int tile_size = std::max(1, options.tile_size);
    const int tiles = tile_count(width, height, tile_size);
    TileRunner runner(width, height, tile_size, threads, progress, 2 * tiles);

    const Stopwatch watch;
    bool complete = runner.run(stop, counts, [&](const Tile& t, RayCounts& local) {
        std::uint64_t fell = 0;
        for (int y = t.y0; y < t.y1; ++y) {
            for (int x = t.x0; x < t.x1; ++x) {
                bool fell_back = false;
                hits[static_cast<std::size_t>(y) * width + x] =
                    primary_hit(scene, camera.ray(x, y), item_buffer, x, y, fell_back);
                fell += fell_back;
                ++local.primary;
            }
        }
        fallbacks.fetch_add(fell, std::memory_order_relaxed);
    });
    const double primary_seconds = watch.seconds();

    const Tracer tracer(scene, options.trace);
    const Stopwatch shade_watch;
    complete = complete && runner.run(stop, counts, [&](const Tile& t, RayCounts& local) {
        // Each worker its own copy (a few words): the shared one sat on the calling
        // thread's stack beside what that thread writes for every ray, and reading it made
        // the two threads wait on each other's cache line (whitted at 1280 x 720 on two
        // threads, medians of 7 to 9 runs: 0.164 s with the shared tracer, 0.134 s with copies).
        const Tracer mine = tracer;
        for (int y = t.y0; y < t.y1; ++y) {
            for (int x = t.x0; x < t.x1; ++x) {
                vec3 c = mine.shade_hit(camera.ray(x, y),
                                        hits[static_cast<std::size_t>(y) * width + x], local);
                if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z)) {
                    nonfinite.fetch_add(1, std::memory_order_relaxed);
                    c = vec3(0.0f);
                }
                image.at(x, y) = c;
            }
        }
    });

    if (stats) {
        stats->rays = counts;
        stats->threads = std::min(threads, tiles);
        stats->primary_seconds = primary_seconds;
        stats->secondary_seconds = shade_watch.seconds();
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
