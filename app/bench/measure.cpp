#include "app/bench/measure.h"

#include <cmath>
#include <cstdlib>

#include "core/simd.h"
#include "core/stopwatch.h"

namespace rt::bench {

namespace {

// RTBENCH_FAULT=NAME makes structure NAME drop every 50th hit: the way to see that the
// answer check can fail (tests/cli/rtbench.sh uses it).
bool faulty(const Structure& s) {
    const char* name = std::getenv("RTBENCH_FAULT");
    return name && s.name() == name;
}

}  // namespace

SetTiming summarise(const Structure& s, std::vector<double> seconds, std::size_t stride,
                    std::vector<Result>& answers) {
    if (faulty(s))
        for (std::size_t i = 0; i < answers.size(); i += 50) answers[i] = Result{};
    SetTiming t;
    t.seconds = median(std::move(seconds));
    t.rays = answers.size();
    t.stride = stride;
    t.mrays_per_s = t.seconds > 0.0 ? static_cast<double>(t.rays) / t.seconds * 1e-6 : 0.0;
    return t;
}

double trace_pass(const Structure& s, const RaySet& set, std::size_t stride, int threads,
                  std::vector<Result>& answers) {
    const std::size_t count = (set.rays.size() + stride - 1) / stride;
    answers.resize(count);
    if (const auto seconds = s.trace_set(set, stride, answers))
        return *seconds;  // a batch structure: it times itself
    const rt::Stopwatch watch;
    parallel_for(count, threads, [&](std::size_t begin, std::size_t end) {
        if (s.packets() && stride == 1) {  // chunks are whole packets but the last
            for (std::size_t i = begin; i < end; i += rt::kPacketWidth) {
                const int n = static_cast<int>(std::min<std::size_t>(rt::kPacketWidth, end - i));
                if (set.occlusion) {
                    s.occluded_packet(&set.rays[i], &set.t_max[i], n, &answers[i]);
                } else {
                    s.intersect_packet(&set.rays[i], &set.t_max[i], n, &answers[i]);
                }
            }
            return;
        }
        for (std::size_t i = begin; i < end; ++i) {
            const std::size_t r = i * stride;
            if (set.occlusion) {
                answers[i].t = s.occluded(set.rays[r], set.t_max[r]) ? 0.0f : rt::kInfinity;
            } else {
                answers[i] = s.intersect(set.rays[r], set.t_max[r]);
            }
        }
    });
    return watch.seconds();
}

std::size_t stride_for(const Structure& s, std::size_t rays, std::size_t triangles,
                       const MeasureOptions& measure) {
    if (s.name() != "brute") return 1;
    const double tests = static_cast<double>(rays) * static_cast<double>(triangles);
    return std::max<std::size_t>(1, static_cast<std::size_t>(tests / measure.brute_budget));
}

int repeats_for(std::size_t stride, int repeats) {
    return stride > 1 ? std::max(1, repeats / 2) : repeats;
}

SetTiming time_set(const Structure& s, const RaySet& set, std::size_t stride,
                   const MeasureOptions& options, std::vector<Result>& answers) {
    answers.clear();
    trace_pass(s, set, stride, options.threads, answers);  // warm-up: caches, faults, threads
    std::vector<double> seconds;
    for (int k = 0; k < repeats_for(stride, options.repeats); ++k)
        seconds.push_back(trace_pass(s, set, stride, options.threads, answers));
    return summarise(s, std::move(seconds), stride, answers);
}

Mismatches compare(const RaySet& set, const std::vector<Result>& answers, std::size_t stride,
                   const std::vector<Result>& reference, std::size_t ref_stride,
                   const ExactTracer& exact) {
    Mismatches m;
    std::vector<std::size_t> differing;  // rays, each with the index of its answer
    std::vector<std::size_t> answer_of;
    for (std::size_t i = 0; i < answers.size(); ++i) {
        const std::size_t ray = i * stride;
        if (ray % ref_stride != 0) continue;
        const Result& a = answers[i];
        const Result& r = reference[ray / ref_stride];
        ++m.checked;
        bool differ = a.hit() != r.hit();
        if (!differ && a.hit() && !set.occlusion) {
            const float tolerance = 1e-4f * std::max(r.t, 1e-3f);
            const bool same_t = std::fabs(a.t - r.t) <= tolerance;
            // Two triangles may meet the ray at one t (a shared edge): either is right.
            differ = !same_t || (a.prim != r.prim && std::fabs(a.t - r.t) > 1e-6f * r.t);
        }
        if (differ) differing.push_back(ray), answer_of.push_back(i);
    }
    m.disagreements = differing.size();
    m.arbitrated = std::min(m.disagreements, Mismatches::kMaxArbitrated);
    for (std::size_t k = 0; k < m.arbitrated; ++k) {
        const std::size_t pick = k * m.disagreements / m.arbitrated;  // evenly spread
        const std::size_t ray = differing[pick];
        const Result& a = answers[answer_of[pick]];
        const Result& r = reference[ray / ref_stride];
        const ExactAnswer e = exact.trace(set.rays[ray], set.t_max[ray], set.occlusion);
        // Both within float's rounding of the exact hit: either is right.
        if (e.ambiguous ||
            (exact.agrees(e, a, set.occlusion) && exact.agrees(e, r, set.occlusion))) {
            ++m.ambiguous;
        } else if (exact.agrees(e, a, set.occlusion)) {
            ++m.reference_wrong;
        } else {
            ++(a.hit() != r.hit() ? m.hit_miss : m.wrong_hit);
        }
    }
    return m;
}

nlohmann::json to_json(const SetTiming& t) {
    return {{"mrays_per_s", t.mrays_per_s},
            {"seconds", t.seconds},
            {"rays", t.rays},
            {"stride", t.stride}};
}

nlohmann::json to_json(const Mismatches& m) {
    return {{"checked", m.checked},
            {"disagreements", m.disagreements},
            {"arbitrated", m.arbitrated},
            {"hit_miss", m.hit_miss},
            {"wrong_hit", m.wrong_hit},
            {"ambiguous", m.ambiguous},
            {"reference_wrong", m.reference_wrong},
            {"ok", m.ok()}};
}

}  // namespace rt::bench
