#pragma once
// A one-line progress bar on stderr, shown only on a terminal and only once the
// render has taken more than a second (short renders stay quiet).

#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

#include "core/stopwatch.h"

namespace rt::renderer {

class ProgressBar {
  public:
    explicit ProgressBar(bool enabled);
    void update(int done, int total);  // called with the render's progress
    void finish();

  private:
    bool enabled_;
    bool shown_ = false;
    int last_percent_ = -1;
    rt::Stopwatch watch_;
};

// A phase with no progress to count (loading a file, building the structures): past a
// second, the same line shows what is being done and for how long, every half second,
// so that slow can be told from stuck. The line is cleared when the phase ends.
class PhaseLine {
  public:
    PhaseLine(bool enabled, std::string what);
    ~PhaseLine();
    PhaseLine(const PhaseLine&) = delete;
    PhaseLine& operator=(const PhaseLine&) = delete;

  private:
    std::string what_;
    bool shown_ = false;
    std::mutex mutex_;
    std::condition_variable done_;
    bool finished_ = false;
    std::thread ticker_;
};

}  // namespace rt::renderer
