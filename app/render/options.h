#pragma once
// rtrender's command line, parsed.

#include <string>

#include "core/tracer.h"

namespace rtrender {

struct Options {
    std::string scene;
    std::string output;          // empty: out/SCENE.png
    std::string size;            // WxH, empty: the scene's
    std::string stats;           // JSON file, empty: none
    std::string mode = "trace";  // trace | raster | both | itembuffer
    std::string gl = "auto";     // egl | osmesa | auto
    std::string accel = "bvh";   // bvh (wide) | bvh2 (binary) | grid | brute
    std::string up = "y";        // a bare mesh's up axis (rt::LoadOptions)
    bool item_buffer = false;
    int threads = 0;
    rt::TraceOptions trace;
    bool quiet = false;
};

// Parses argv; on --help prints and returns the exit code in `exit_code`.
bool parse_command_line(int argc, char** argv, Options& options, int& exit_code);

int run(const Options& options);

}  // namespace rtrender
