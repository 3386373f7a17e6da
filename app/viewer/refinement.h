#pragma once
// When the viewer's tracer starts again, and at which resolutions (GL-free, unit-tested).
// Any change of what the traced image depends on (a TraceKey) restarts it at once at the
// coarsest level, so the view follows the camera; once nothing has changed for
// kRestSeconds, the chain up to full resolution follows. The first image, and the first
// after reset() (a new scene), goes through every level at once. While no traced image
// is on screen (the raster view), changes are not followed: the tracer would only take
// cores from the rasteriser; the chain comes once the camera rests.

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace rt::viewer {

// What the traced image depends on. Display-only settings (the difference scale, the
// split divider, the view) are not in it: changing them never restarts the tracer.
struct TraceKey {
    std::uint64_t camera_version = 0;  // CameraController::version()
    int width = 0, height = 0;         // of the full-resolution traced image
    bool shadows = true, reflections = true, refractions = true;
    int max_depth = 5;
    bool item_buffer = false;
    int threads = 0;
    bool explain = false;  // traced in parts against the raster: the why view
    int max_spp = 1;       // anti-aliasing: samples per pixel refined to after full resolution

    bool operator==(const TraceKey&) const = default;
};

class RefinementSchedule {
  public:
    static constexpr double kRestSeconds = 0.2;  // the camera rests this long before refining
    static constexpr int kCoarsest = 8;          // a fraction of the full resolution per side

    // The levels to trace now (divisors of the full resolution, coarsest first: {8},
    // {4, 2, 1} or {8, 4, 2, 1}), or none. `now` is in seconds on any steady clock;
    // `on_screen`: whether the view shows a traced image.
    std::vector<int> update(const TraceKey& key, double now, bool on_screen = true);
    // Forget what was traced: the next update starts the full chain.
    void reset() { submitted_.reset(); }

  private:
    std::optional<TraceKey> submitted_;
    bool refine_pending_ = false;
    bool followed_ = false;  // the coarsest level of the pending change was traced
    double last_change_ = 0.0;
};

// Which trace the image on screen belongs to: the viewer says what it submitted and what
// arrived, and asks whether the image is stale (of a camera or settings other than the
// current ones), so that the view says "tracing..." rather than pass an old image off as
// the current one.
class ShownTrace {
  public:
    void submitted(std::uint64_t id, const TraceKey& key) { submitted_ = {id, key}; }
    // A level of request `id` went on screen (results of older requests never do).
    void arrived(std::uint64_t id, int level) {
        if (submitted_ && submitted_->first == id) {
            shown_ = submitted_->second;
            level_ = level;
        }
    }
    bool stale(const TraceKey& now) const { return !shown_ || !(*shown_ == now); }
    // The last request submitted is of `key`.
    bool asked_for(const TraceKey& key) const { return submitted_ && submitted_->second == key; }
    int level() const { return level_; }  // 0: nothing traced on screen yet
    // Full resolution, of the current camera and settings.
    bool complete(const TraceKey& now) const { return level_ == 1 && !stale(now); }
    void reset() { *this = ShownTrace{}; }

  private:
    std::optional<std::pair<std::uint64_t, TraceKey>> submitted_;
    std::optional<TraceKey> shown_;
    int level_ = 0;
};

}  // namespace rt::viewer
