#pragma once
// Ray tracing on a worker thread for the viewer, progressively: each request is a chain
// of levels (8 = one traced pixel per 8 x 8 screen pixels, ..., 1 = full resolution),
// each published as soon as it is done. A new request cancels the running one at its
// next tile, so the window never waits for the tracer.

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "core/explain.h"
#include "core/item_buffer.h"
#include "core/renderer.h"
#include "core/scene.h"

namespace rt::viewer {

// What the raster pipeline drew at one level's size, for the explain map (the "why" view).
struct RasterFrame {
    rt::Image image;
    rt::ItemBuffer ids;
    rt::RasterTricks tricks;  // what shadow and environment maps added, when on
};

struct TraceRequest {
    std::shared_ptr<const rt::Scene> scene;  // kept alive until the worker is done with it
    rt::Camera camera;                       // at the full trace resolution
    rt::RenderOptions options;
    std::vector<int> levels{8, 4, 2, 1};
    // For the full-resolution level: primary hits from the raster item buffer, and then
    // the same frame again without it, to measure what it saved and where it differs.
    std::shared_ptr<const rt::ItemBuffer> item_buffer;
    // For the why view: one raster frame per level, in the levels' order. Each level is
    // then traced in parts (rt::explain), giving the traced image and its explanation.
    std::vector<std::shared_ptr<const RasterFrame>> explain;
    // After full resolution: the same frame again with these many samples per pixel
    // (anti-aliased), each published as it is done.
    std::vector<int> spp_passes;
    std::uint64_t id = 0;
};

struct Explanation {
    rt::Image colours;  // rt::explain_colours
    std::array<rt::CauseShare, rt::kCauseCount> shares{};
    rt::ExplainMap map;  // per pixel, for the pixel inspector
};

struct TraceResult {
    std::uint64_t id = 0;
    int level = 1;
    int spp = 1;  // samples per pixel
    rt::Image image;
    rt::RenderStats stats;
    std::optional<rt::RenderStats> without_item_buffer;  // with an item buffer only
    std::uint64_t item_buffer_disagreements = 0;
    std::shared_ptr<const Explanation> explanation;  // when the request asked for one
};

class TraceJob {
  public:
    // `on_publish` is called on the worker thread after each level is published (the
    // viewer wakes its event loop with it); it must be thread-safe.
    explicit TraceJob(std::function<void()> on_publish = {});
    ~TraceJob();

    void submit(TraceRequest request);
    // Stops the running request and waits until the worker holds no scene.
    void cancel();
    // Stops the running request and returns at once.
    void stop();
    // The newest result not yet taken, always of the newest request: a submit drops any
    // result of an older one, taken or not yet published.
    std::optional<TraceResult> take();
    float progress() const { return progress_.load(); }  // of the running level
    bool busy() const { return busy_.load(); }

  private:
    void loop(std::stop_token stop);
    void run(const TraceRequest& request, std::stop_token cancel);
    bool publish(TraceResult result, std::stop_token cancel);  // false if superseded
    // One level traced in parts against its raster frame; false if cancelled.
    bool explain_level(const TraceRequest& request, const rt::Camera& camera,
                       const RasterFrame& raster, std::stop_token cancel, TraceResult& result);

    std::mutex mutex_;
    std::condition_variable_any wake_;
    std::condition_variable_any idle_;
    std::optional<TraceRequest> pending_;
    std::stop_source running_;
    std::optional<TraceResult> result_;
    std::atomic<float> progress_{0.0f};
    std::atomic<bool> busy_{false};
    std::function<void()> on_publish_;
    std::jthread thread_;  // last: starts after the members it uses
};

}  // namespace rt::viewer
