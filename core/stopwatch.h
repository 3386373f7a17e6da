#pragma once
// Wall-clock time since a start (Nori's Timer): every timing the programs print or
// write comes from one of these.
//   const Stopwatch watch;  work();  stats["seconds"] = watch.seconds();

#include <chrono>

namespace rt {

class Stopwatch {
  public:
    using Clock = std::chrono::steady_clock;

    Stopwatch() : start_(Clock::now()) {}
    void restart() { start_ = Clock::now(); }
    double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
    double milliseconds() const { return 1e3 * seconds(); }
    // Seconds since the start, and start again: successive phases, one watch.
    double lap() {
        const double s = seconds();
        restart();
        return s;
    }

  private:
    Clock::time_point start_;
};

}  // namespace rt
