#pragma once
// A one-line progress bar on stderr, shown only on a terminal and only once the
// render has taken more than a second (short renders stay quiet).

#include <chrono>

namespace rtrender {

class ProgressBar {
  public:
    explicit ProgressBar(bool enabled);
    void update(int done, int total);  // called with the render's progress
    void finish();

  private:
    bool enabled_;
    bool shown_ = false;
    int last_percent_ = -1;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace rtrender
