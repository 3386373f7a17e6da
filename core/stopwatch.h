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
    // Seconds since the start, and start again: successive phases, one watch. One read of
    // the clock ends a phase and starts the next (two left a gap between them, and the
    // renderer takes two laps a tile: a read is about 24 ns here).
    double lap() {
        const Clock::time_point now = Clock::now();
        const double s = std::chrono::duration<double>(now - start_).count();
        start_ = now;
        return s;
    }

  private:
    Clock::time_point start_;
};

}  // namespace rt
