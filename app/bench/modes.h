#pragma once
// rtbench's three modes.

#include <string>

#include "app/bench/measure.h"
#include "app/gl/context.h"
#include "core/tracer.h"

namespace rt::bench {

struct SceneBenchOptions {
    std::string scene;
    std::vector<std::string>
        only;          // structures to run (empty: all); bvh is always built, for the rays
    std::string json;  // empty: no JSON
    int width = 1280, height = 720;
    MeasureOptions measure;
    bool gpu = false;            // also the GPU tracer's traversal, on a `gl` context, and a frame
    rt::TraceOptions gpu_frame;  // of the whole scene traced so
    rt::gl::Backend gl = rt::gl::Backend::kAuto;
    // Not empty: instead of the table, our wide BVH and Embree built and traced on each of
    // these thread counts (the same rays), a row each.
    std::vector<int> threads_sweep;
};

// Every structure on the scene's triangles; exit status 1 on a wrong answer.
int run_scene(const SceneBenchOptions& options);

struct SweepOptions {
    std::string csv = "sweep.csv";
    std::string png = "sweep.png";
    int width = 320, height = 180;
    std::vector<int> triangle_counts{1000, 10000, 100000, 1000000};
    MeasureOptions measure;
};
int run_sweep(const SweepOptions& options);

struct ItemBufferBenchOptions {
    std::string scene;
    std::string json;
    int width = 1280, height = 720;
    int threads = 2;
    int repeats = 5;
    rt::gl::Backend gl = rt::gl::Backend::kAuto;
};
int run_item_buffer(const ItemBufferBenchOptions& options);

}  // namespace rt::bench
