#include "app/viewer/trace_job.h"

#include <algorithm>

#include "core/stopwatch.h"

namespace rt::viewer {

TraceJob::TraceJob(std::function<void()> on_publish)
    : on_publish_(std::move(on_publish)), thread_([this](std::stop_token stop) { loop(stop); }) {}

TraceJob::~TraceJob() {
    thread_.request_stop();
    {
        std::lock_guard lock(mutex_);
        running_.request_stop();
    }
    wake_.notify_all();
}  // the jthread joins here

void TraceJob::submit(TraceRequest request) {
    {
        std::lock_guard lock(mutex_);
        pending_ = std::move(request);
        running_.request_stop();
        result_.reset();  // an untaken result of an older request is superseded: never shown
    }
    wake_.notify_all();
}

void TraceJob::cancel() {
    std::unique_lock lock(mutex_);
    pending_.reset();
    running_.request_stop();
    idle_.wait(lock, [&] { return !busy_.load(); });
}

void TraceJob::stop() {
    std::lock_guard lock(mutex_);
    pending_.reset();
    running_.request_stop();
}

std::optional<TraceResult> TraceJob::take() {
    std::lock_guard lock(mutex_);
    std::optional<TraceResult> out = std::move(result_);
    result_.reset();
    return out;
}

void TraceJob::loop(std::stop_token stop) {
    for (;;) {
        TraceRequest request;
        std::stop_token cancel;
        {
            std::unique_lock lock(mutex_);
            if (!wake_.wait(lock, stop, [&] { return pending_.has_value(); })) return;
            request = std::move(*pending_);
            pending_.reset();
            running_ = std::stop_source();
            cancel = running_.get_token();
            busy_ = true;
        }
        run(request, cancel);
        request.scene.reset();  // let go of the scene before saying we are idle
        request.item_buffer.reset();
        {
            std::lock_guard lock(mutex_);
            busy_ = false;
        }
        idle_.notify_all();
    }
}

void TraceJob::run(const TraceRequest& request, std::stop_token cancel) {
    const rt::Camera& full = request.camera;
    for (std::size_t i = 0; i < request.levels.size(); ++i) {
        const int level = request.levels[i];
        const rt::Camera camera =
            full.resized(std::max(1, full.cols / level), std::max(1, full.rows / level));
        const RasterFrame* raster = i < request.explain.size() ? request.explain[i].get() : nullptr;
        const bool use_ib = !raster && level == 1 && request.item_buffer &&
                            request.item_buffer->width == camera.cols &&
                            request.item_buffer->height == camera.rows;
        TraceResult result;
        result.id = request.id;
        result.level = level;
        progress_ = 0.0f;
        const auto on_progress = [&](int done, int total) {
            progress_ = static_cast<float>(done) / static_cast<float>(total);
        };
        if (raster) {
            if (!explain_level(request, camera, *raster, cancel, result)) return;
        } else {
            result.image =
                rt::render(*request.scene, camera, request.options, &result.stats, on_progress,
                           cancel, use_ib ? request.item_buffer.get() : nullptr);
            if (result.stats.cancelled) return;
        }
        if (use_ib) {
            rt::RenderStats plain_stats;
            const rt::Image plain =
                rt::render(*request.scene, camera, request.options, &plain_stats, {}, cancel);
            if (plain_stats.cancelled) return;
            result.without_item_buffer = plain_stats;
            result.item_buffer_disagreements = rt::item_buffer_disagreements(result.image, plain);
        }
        if (!publish(std::move(result), cancel)) return;
    }
    if (request.levels.empty() || request.levels.back() != 1) return;
    for (int spp : request.spp_passes) {
        TraceResult result;
        result.id = request.id;
        result.spp = spp;
        rt::RenderOptions options = request.options;
        options.spp = spp;
        // Refining only: leave a core to the window (llvmpipe draws it on the same cores;
        // with all of them tracing, frames at rest took 65-84 ms instead of 29-38).
        options.threads = std::max(1, rt::resolve_thread_count(options.threads) - 1);
        progress_ = 0.0f;
        const auto on_progress = [&](int done, int total) {
            progress_ = static_cast<float>(done) / static_cast<float>(total);
        };
        result.image =
            rt::render(*request.scene, full, options, &result.stats, on_progress, cancel);
        if (result.stats.cancelled || !publish(std::move(result), cancel)) return;
    }
}

bool TraceJob::publish(TraceResult result, std::stop_token cancel) {
    {
        std::lock_guard lock(mutex_);
        // A request submitted while this level rendered supersedes it (submit stops the
        // token under this lock, so the check cannot race).
        if (cancel.stop_requested()) return false;
        result_ = std::move(result);
    }
    if (on_publish_) on_publish_();
    return true;
}

bool TraceJob::explain_level(const TraceRequest& request, const rt::Camera& camera,
                             const RasterFrame& raster, std::stop_token cancel,
                             TraceResult& result) {
    if (raster.image.width != camera.cols || raster.image.height != camera.rows) return false;
    const rt::Stopwatch watch;
    auto explanation = std::make_shared<Explanation>();
    explanation->map = rt::explain(*request.scene, camera, request.options, raster.image,
                                   raster.ids, cancel, &raster.tricks);
    if (explanation->map.cancelled) return false;
    explanation->colours = rt::explain_colours(explanation->map);
    explanation->shares = rt::cause_shares(explanation->map);
    result.image = explanation->map.traced;
    result.stats.rays = explanation->map.rays;
    result.stats.threads = rt::resolve_thread_count(request.options.threads);
    result.stats.seconds = result.stats.secondary_seconds = watch.seconds();
    result.explanation = std::move(explanation);
    return true;
}

}  // namespace rt::viewer
