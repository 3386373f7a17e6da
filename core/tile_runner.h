#pragma once
// Work over an image in square tiles on worker threads (the calling thread one of them):
// the renderer's two passes and the explain map share it. Tiles are handed out in order
// from an atomic counter, so a slow tile never holds the others up.

#include <algorithm>
#include <atomic>
#include <mutex>
#include <stop_token>
#include <thread>
#include <vector>

#include "core/renderer.h"

namespace rt::detail {

struct Tile {
    int x0, y0, x1, y1;
};

inline int tile_count(int width, int height, int size) {
    return ((width + size - 1) / size) * ((height + size - 1) / size);
}

// Runs `work(tile, counts)` over every tile on `threads` threads; returns false if
// stopped before the end.
class TileRunner {
  public:
    // Progress is reported as part of `progress_total` tiles over all runs.
    TileRunner(int width, int height, int tile_size, int threads, const ProgressFn& progress,
               int progress_total)
        : width_(width),
          height_(height),
          size_(tile_size),
          threads_(threads),
          progress_(progress),
          progress_total_(progress_total) {
        tiles_x_ = (width + size_ - 1) / size_;
        tiles_ = tile_count(width, height, size_);
    }

    template <class Work>
    bool run(std::stop_token stop, RayCounts& counts, Work&& work) {
        std::atomic<int> next{0};
        int done = 0;
        const auto worker = [&] {
            RayCounts local;
            for (int t; !stop.stop_requested() && (t = next.fetch_add(1)) < tiles_;) {
                work(tile(t), local);
                std::lock_guard lock(mutex_);
                ++done;
                ++progress_done_;  // across runs
                if (progress_) progress_(progress_done_, progress_total_);
            }
            std::lock_guard lock(mutex_);
            counts += local;
        };
        {
            std::vector<std::jthread> pool;
            for (int i = 1; i < std::min(threads_, tiles_); ++i) pool.emplace_back(worker);
            worker();  // the calling thread is a worker too
        }
        return done == tiles_;
    }

  private:
    Tile tile(int t) const {
        const int x0 = (t % tiles_x_) * size_, y0 = (t / tiles_x_) * size_;
        return {x0, y0, std::min(x0 + size_, width_), std::min(y0 + size_, height_)};
    }

    int width_, height_, size_, threads_;
    const ProgressFn& progress_;
    int progress_total_;
    int progress_done_ = 0;
    int tiles_x_ = 0, tiles_ = 0;
    std::mutex mutex_;
};

}  // namespace rt::detail
