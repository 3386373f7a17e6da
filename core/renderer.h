#pragma once
// Renders a scene in tiles on worker threads, each tile in two steps: the primary hits of
// its pixels (from a full traversal, or from the item buffer), then their shading with
// shadow feelers and secondary rays. Each pixel depends on nothing but the scene, so the
// image is the same, byte for byte, whatever the thread count.

#include <functional>
#include <stop_token>

#include "core/image.h"
#include "core/item_buffer.h"
#include "core/tracer.h"

namespace rt {

struct RenderOptions {
    TraceOptions trace;
    int threads = 0;  // 0: every hardware thread
    int tile_size = 16;
    // Samples per pixel, a square number (1, 4, 9, 16, ...): stratified and jittered,
    // averaged (a box filter). 1 is the pixel centre: the image of the tutorial.
    int spp = 1;
};

// Whether n samples per pixel can be laid out as a square grid of strata.
bool valid_spp(int n);
// Sample `s` of `spp` in pixel (x, y) (y = 0 the bottom row): the centre for one sample;
// otherwise stratum (s mod m, s div m) of the m x m grid (m = sqrt spp), at a point within
// it drawn from a hash of (x, y, s), so the image is the same every run, on any number of
// threads.
Ray pixel_sample(const Camera& camera, int x, int y, int s, int spp);

struct RenderStats {
    RayCounts rays;
    int threads = 0;
    double seconds = 0.0;                     // the whole image
    double primary_seconds = 0.0;             // finding the first hits (the wall time
                                              // split as the threads' time was)
    double secondary_seconds = 0.0;           // shading: shadow feelers, reflection, refraction
    std::uint64_t nonfinite_pixels = 0;       // replaced by black; should stay 0
    std::uint64_t item_buffer_fallbacks = 0;  // pixels the item buffer could not settle
    bool cancelled = false;

    double mrays_per_s() const {
        return seconds > 0.0 ? static_cast<double>(rays.total()) / seconds * 1e-6 : 0.0;
    }
};

// Called after each finished tile of either pass with (tiles done, tiles in all), from
// a worker thread but never from two at once.
using ProgressFn = std::function<void(int done, int total)>;

// Renders scene.camera's view (or `camera`'s). With an item buffer (of the camera's size), and
// one sample per pixel (it knows the pixel centres only), the primary hits come from it: only the
// named object or triangle is tested, and pixels on an object's border, or where that test misses,
// are tested against the objects named around them (item_buffer_fallbacks counts them). When `stop`
// is requested the workers finish their current tile and return; the image is then partly black and
// stats.cancelled is set.
Image render(const Scene& scene, const RenderOptions& options, RenderStats* stats = nullptr,
             const ProgressFn& progress = {}, std::stop_token stop = {},
             const ItemBuffer* item_buffer = nullptr);
// The same from another camera (the scene is shared read-only, e.g. with a viewer).
Image render(const Scene& scene, const Camera& camera, const RenderOptions& options,
             RenderStats* stats = nullptr, const ProgressFn& progress = {},
             std::stop_token stop = {}, const ItemBuffer* item_buffer = nullptr);

int resolve_thread_count(int requested);

// The item buffer's check, the same in rtrender, rtview and rtbench: the pixels of a
// frame traced from the item buffer's first hits that differ, by more than 1.5/255 in a
// channel, from the same frame traced from scratch. None should.
std::uint64_t item_buffer_disagreements(const Image& with_item_buffer, const Image& from_scratch);

}  // namespace rt
