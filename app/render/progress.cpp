#include "app/render/progress.h"

#include <cstdio>
#include <string>

#include "core/stopwatch.h"

namespace rt::renderer {

ProgressBar::ProgressBar(bool enabled) : enabled_(enabled) {}

void ProgressBar::update(int done, int total) {
    if (!enabled_ || total <= 0) return;
    const double elapsed = watch_.seconds();
    if (!shown_ && elapsed < 1.0) return;
    const int percent = done * 100 / total;
    if (percent == last_percent_) return;
    last_percent_ = percent;
    shown_ = true;
    constexpr int kWidth = 40;
    const int filled = percent * kWidth / 100;
    const std::string bar = std::string(filled, '#') + std::string(kWidth - filled, '.');
    std::fprintf(stderr, "\r[%s] %3d%%  %.1fs", bar.c_str(), percent, elapsed);
    std::fflush(stderr);
}

void ProgressBar::finish() {
    if (shown_) std::fputc('\n', stderr);
    shown_ = false;
}

PhaseLine::PhaseLine(bool enabled, std::string what) : what_(std::move(what)) {
    if (!enabled) return;
    ticker_ = std::thread([this] {
        const rt::Stopwatch watch;
        std::unique_lock lock(mutex_);
        if (done_.wait_for(lock, std::chrono::seconds(1), [this] { return finished_; })) return;
        do {
            const double elapsed = watch.seconds();
            std::fprintf(stderr, "\r%s... %.1fs", what_.c_str(), elapsed);
            std::fflush(stderr);
            shown_ = true;
        } while (
            !done_.wait_for(lock, std::chrono::milliseconds(500), [this] { return finished_; }));
    });
}

PhaseLine::~PhaseLine() {
    if (!ticker_.joinable()) return;
    {
        std::lock_guard lock(mutex_);
        finished_ = true;
    }
    done_.notify_one();
    ticker_.join();
    if (shown_) std::fprintf(stderr, "\r\033[K");  // clear the line for what follows
}

}  // namespace rt::renderer
