#include "core/renderer.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>
#include <vector>

namespace rt {

int resolve_thread_count(int requested) {
    if (requested > 0) return requested;
    return std::max(1u, std::thread::hardware_concurrency());
}

namespace {

struct TileJob {
    TileJob(const Scene& s, const RenderOptions& o, Image& im, int tx, int total)
        : scene(s), tracer(s, o.trace), options(o), image(im), tiles_x(tx), tiles_total(total) {}

    const Scene& scene;
    const Tracer tracer;
    const RenderOptions& options;
    Image& image;
    int tiles_x, tiles_total;
    std::atomic<int> next_tile{0};
    std::atomic<std::uint64_t> nonfinite{0};
    std::mutex merge_mutex;  // guards counts, done and the progress callback
    RayCounts counts;
    int done = 0;

    void render_tile(int tile, RayCounts& local) {
        const int s = options.tile_size;
        const int x0 = (tile % tiles_x) * s, y0 = (tile / tiles_x) * s;
        const int x1 = std::min(x0 + s, image.width), y1 = std::min(y0 + s, image.height);
        for (int y = y0; y < y1; ++y) {
            for (int x = x0; x < x1; ++x) {
                vec3 c = tracer.trace_primary(scene.camera.ray(x, y), local);
                if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z)) {
                    nonfinite.fetch_add(1, std::memory_order_relaxed);
                    c = vec3(0.0f);
                }
                image.at(x, y) = c;
            }
        }
    }

    void work(std::stop_token stop, const ProgressFn& progress) {
        RayCounts local;
        for (int tile; !stop.stop_requested() && (tile = next_tile.fetch_add(1)) < tiles_total;) {
            render_tile(tile, local);
            std::lock_guard lock(merge_mutex);
            ++done;
            if (progress) progress(done, tiles_total);
        }
        std::lock_guard lock(merge_mutex);
        counts += local;
    }
};

}  // namespace

Image render(const Scene& scene, const RenderOptions& options, RenderStats* stats,
             const ProgressFn& progress, std::stop_token stop) {
    const auto start = std::chrono::steady_clock::now();
    Image image(scene.camera.cols, scene.camera.rows);
    const int s = std::max(1, options.tile_size);
    const int tiles_x = (image.width + s - 1) / s;
    const int tiles_y = (image.height + s - 1) / s;
    RenderOptions opts = options;
    opts.tile_size = s;
    TileJob job(scene, opts, image, tiles_x, tiles_x * tiles_y);

    const int thread_count = std::min(resolve_thread_count(options.threads), std::max(1, job.tiles_total));
    {
        std::vector<std::jthread> workers;
        for (int i = 1; i < thread_count; ++i)
            workers.emplace_back([&] { job.work(stop, progress); });
        job.work(stop, progress);  // the calling thread is a worker too
    }
    if (stats) {
        stats->rays = job.counts;
        stats->threads = thread_count;
        stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        stats->nonfinite_pixels = job.nonfinite.load();
        stats->cancelled = stop.stop_requested() && job.done < job.tiles_total;
    }
    return image;
}

}  // namespace rt
