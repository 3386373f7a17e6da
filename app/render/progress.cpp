#include "app/render/progress.h"

#include <cstdio>
#include <string>

namespace rtrender {

ProgressBar::ProgressBar(bool enabled)
    : enabled_(enabled), start_(std::chrono::steady_clock::now()) {}

void ProgressBar::update(int done, int total) {
    if (!enabled_ || total <= 0) return;
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
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

}  // namespace rtrender
