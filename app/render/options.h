#pragma once
// rtrender's command line, parsed.

#include <optional>
#include <string>

#include "app/gl/context.h"
#include "core/accel.h"
#include "core/names.h"
#include "core/tracer.h"

namespace rt::renderer {

enum class Mode { kTrace, kRaster, kBoth, kItemBuffer, kExplain, kGpuTrace };
inline constexpr rt::Named<Mode> kModeNames[] = {
    {"trace", Mode::kTrace},           {"raster", Mode::kRaster},   {"both", Mode::kBoth},
    {"itembuffer", Mode::kItemBuffer}, {"explain", Mode::kExplain}, {"gputrace", Mode::kGpuTrace}};

struct Options {
    std::string scene;
    std::string output;  // empty: out/SCENE.png
    std::string size;    // WxH, empty: the scene's
    std::string stats;   // JSON file, empty: none
    Mode mode = Mode::kTrace;
    rt::gl::Backend gl = rt::gl::Backend::kAuto;
    rt::AccelKind accel = rt::AccelKind::kBvh;
    bool light_buffer = true;   // shadow feelers through each light's buffer (--no-light-buffer)
    std::string up = "y";       // a bare mesh's up axis (rt::LoadOptions)
    std::optional<int> camera;  // a glTF file's camera (rt::LoadOptions)
    bool item_buffer = false;
    bool with_gpu = false;  // --mode both: the GPU-traced image too (OUT.gputrace.png)
    int threads = 0;
    int spp = 1;               // traced samples per pixel (a square number)
    int msaa = 1;              // raster samples per pixel (1, 2, 4 or 8)
    bool shadow_maps = false;  // --raster-shadows map
    int shadow_map_size = 1024;
    bool environment_maps = false;  // --raster-reflections envmap
    int envmap_size = 256;
    rt::TraceOptions trace;
    bool quiet = false;
    std::string ray_tree;       // "X,Y": print that pixel's rays instead of rendering
    std::string ray_tree_json;  // and write them here
};

// Parses argv; on --help prints and returns the exit code in `exit_code`.
bool parse_command_line(int argc, char** argv, Options& options, int& exit_code);

int run(const Options& options);

}  // namespace rt::renderer
