#pragma once
// Timing structures on ray sets, and checking their answers against a reference.

#include <nlohmann/json.hpp>

#include "app/bench/bench.h"
#include "app/bench/exact.h"

namespace rt::bench {

struct MeasureOptions {
    int threads = 2;
    int repeats = 5;
    int build_repeats = 5;
    double brute_budget = 4e8;  // triangle tests per pass: brute force traces a subset of rays
};

struct SetTiming {
    double mrays_per_s = 0.0;
    double seconds = 0.0;    // median pass
    std::size_t rays = 0;    // traced per pass
    std::size_t stride = 1;  // 1: every ray; k: every k-th (brute force)
};

// Where a structure and a reference answer rays differently. The exact test arbitrates
// up to kMaxArbitrated of the disagreements, spread evenly over them where there are
// more (a mesh on which Embree, whose test is not watertight, errs on a third of the
// feelers: its thousand slivers meeting at a point); the counts below are of those, and
// the verdict scales them up to all the disagreements.
struct Mismatches {
    static constexpr std::size_t kMaxArbitrated = 2000;
    std::size_t checked = 0;
    std::size_t disagreements = 0, arbitrated = 0;
    // Disagreements the exact test (app/bench/exact.h) decided against the structure:
    std::size_t hit_miss = 0;   // one found a hit, the other did not
    std::size_t wrong_hit = 0;  // another primitive at another t
    // Disagreements it did not: the ray grazes an edge (either answer is right), or the
    // reference itself was wrong.
    std::size_t ambiguous = 0;
    std::size_t reference_wrong = 0;
    std::size_t allowed() const { return std::max<std::size_t>(2, checked / 100000); }
    // The structure's wrong answers among all the disagreements: counted where all were
    // arbitrated, else estimated from those that were.
    double wrong() const {
        const auto found = static_cast<double>(hit_miss + wrong_hit);
        return arbitrated == disagreements
                   ? found
                   : found * static_cast<double>(disagreements) / static_cast<double>(arbitrated);
    }
    bool ok() const { return wrong() <= static_cast<double>(allowed()); }
};

// One pass of every ray of `set` (or every stride-th) through `s`, on `threads`: its
// seconds, and its answers in `answers`.
double trace_pass(const Structure& s, const RaySet& set, std::size_t stride, int threads,
                  std::vector<Result>& answers);
// Which rays `s` traces of a set of `rays` over `triangles`: every one (1), or for brute
// force every k-th, so that a pass stays within measure.brute_budget triangle tests.
std::size_t stride_for(const Structure& s, std::size_t rays, std::size_t triangles,
                       const MeasureOptions& measure);
// How many passes are timed: brute force, tracing a subset, takes half as many.
int repeats_for(std::size_t stride, int repeats);
// The median of a structure's passes, with the answers of its last pass.
SetTiming summarise(const Structure& s, std::vector<double> seconds, std::size_t stride,
                    std::vector<Result>& answers);
// Traces every ray of `set` (or every stride-th) through `s`, after a warm-up pass,
// `repeats` times; returns the median, and the answers of the last pass.
SetTiming time_set(const Structure& s, const RaySet& set, std::size_t stride,
                   const MeasureOptions& options, std::vector<Result>& answers);

// Compares answers[i] (for rays i * stride) with reference[i * ref_stride ...]; where
// they disagree, `exact` decides (up to 2000 rays; past that, a structure is plainly
// broken and the rest count against it).
Mismatches compare(const RaySet& set, const std::vector<Result>& answers, std::size_t stride,
                   const std::vector<Result>& reference, std::size_t ref_stride,
                   const ExactTracer& exact);

nlohmann::json to_json(const SetTiming& t);
nlohmann::json to_json(const Mismatches& m);

}  // namespace rt::bench
