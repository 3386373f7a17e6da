// rtview --benchmark: the viewer's responsiveness, measured in the real window. For each
// scene: the UI thread's frame time (the frame's work, not the wait for events) while the
// first trace refines, at rest (nothing to do but composite), and while orbiting (a step
// every frame, as a drag's events would come); at rest with the cursor on another pixel
// each frame (the pixel inspector at work); and the delay from the last orbit step to
// the full-resolution traced image, with the event loop waiting as run() does. Medians.
#include <algorithm>
#include <cstdio>
#include <vector>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/viewer/viewer.h"
#include "app/viewer/views.h"
#include "core/stopwatch.h"

namespace rt::viewer {
namespace {

double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
    return v[v.size() / 2];
}

constexpr double kTimeout = 120.0;  // seconds a scene may take to reach full resolution
constexpr int kFrames = 40;         // frames at rest and while orbiting

}  // namespace

double Viewer::timed_frame(bool wait) {
    if (wait)
        wait_for_events();  // as run() does
    else
        glfwPollEvents();  // as when a drag's events keep coming
    const rt::Stopwatch watch;
    frame(1.0f / 60.0f);
    return watch.milliseconds();
}

// Frames until the full-resolution image of the current camera and settings is on
// screen; their times go to `frames`. False on timeout.
bool Viewer::frames_until_traced(std::vector<double>& frames) {
    const rt::Stopwatch watch;
    do {
        frames.push_back(timed_frame(true));
        if (watch.seconds() > kTimeout) return false;
    } while (!shown_.complete(trace_key()));
    return true;
}

int Viewer::benchmark(const std::vector<std::string>& scenes) {
    const glm::ivec2 fb = window_.framebuffer_size();
    std::printf(
        "rtview benchmark: %dx%d, view %s, raster %s, UI thread frame times in ms (median)\n", fb.x,
        fb.y, view_label(display_.view), raster_label().c_str());
    std::printf("%-22s %9s %7s %9s %9s %9s %9s %14s\n", "scene", "tracing", "frames", "at rest",
                "hovering", "orbiting", "(raster)", "release->full");
    int status = 0;
    for (const std::string& path : scenes) {
        if (!load(path)) {
            status = 1;
            continue;
        }
        std::vector<double> tracing, rest, hover, orbit, orbit_raster, release;
        bool ok = frames_until_traced(tracing);
        for (int i = 0; i < kFrames; ++i) rest.push_back(timed_frame(false));
        int w = 1, h = 1;
        glfwGetWindowSize(window_.handle(), &w, &h);
        for (int i = 0; i < kFrames; ++i) {  // right of the panel, a new pixel each frame
            drag_.cursor = {0.75 * w + 3.0 * i, 0.5 * h + 2.0 * i};
            hover.push_back(timed_frame(false));
        }
        for (int i = 0; i < kFrames; ++i) {
            controller_->orbit(6.0f, 0.0f);
            orbit.push_back(timed_frame(false));
            orbit_raster.push_back(stats_.raster_ms);
        }
        const rt::Stopwatch released;
        ok = ok && frames_until_traced(release);
        const double to_full = released.milliseconds();
        std::printf("%-22s %9.1f %7zu %9.1f %9.1f %9.1f %9.1f %14.0f%s\n",
                    std::filesystem::path(path).filename().string().c_str(), median(tracing),
                    tracing.size(), median(rest), median(hover), median(orbit),
                    median(orbit_raster), to_full, ok ? "" : "  (timed out)");
        std::fflush(stdout);
        if (!ok) status = 1;
    }
    return status;
}

}  // namespace rt::viewer
