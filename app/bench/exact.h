#pragma once
// The arbiter of disagreements: when two structures answer one ray differently, the
// ray is traced again against every triangle in double precision. Rays that graze an
// edge or a vertex, or end on a triangle, are ambiguous even then: no answer is wrong.

#include <cstdint>

#include "app/bench/bench.h"

namespace rt::bench {

struct ExactAnswer {
    bool hit = false;
    double t = 0.0;
    bool ambiguous = false;  // within rounding of an edge, a vertex, t_max, or a second hit
    double slack = 0.0;      // how far a float test's t may be from t and still be right
};

class ExactTracer {
  public:
    explicit ExactTracer(const rt::TriangleMesh& mesh) : mesh_(mesh) {}
    ExactAnswer trace(const rt::Ray& ray, float t_max, bool any_hit) const;
    // Whether `answer` is right for the ray by the exact test: an ambiguous ray admits
    // either answer (and is counted as such by the caller).
    bool agrees(const ExactAnswer& exact, const Result& answer, bool occlusion) const;

  private:
    const rt::TriangleMesh& mesh_;
};

}  // namespace rt::bench
