// rtrender: renders a scene headless, ray traced and/or through OpenGL.
//   rtrender SCENE [-o OUT.png|OUT.exr] [--mode trace|raster|both|itembuffer|explain|gputrace]
//            [--gl egl|osmesa] [--with-gpu]
//            [--item-buffer on|off] [--accel bvh|bvh2|grid|brute] [--size WxH] [--threads N]
//            [--max-depth N] [--spp N] [--msaa N] [--raster-shadows none|map]
//            [--raster-reflections none|envmap] [--no-shadows]
//            [--no-reflections] [--no-refractions] [--no-light-buffer] [--stats FILE.json]
//            [--quiet] [--up AXIS]

#include <iostream>

#include <CLI/CLI.hpp>

#include "app/common/cli_names.h"
#include "app/render/options.h"
#include "core/error.h"
#include "core/renderer.h"
#include "core/scene_loader.h"

namespace rt::renderer {

bool parse_command_line(int argc, char** argv, Options& o, int& exit_code) {
    CLI::App app{"rtrender: renders a scene with rtview's Whitted ray tracer and/or OpenGL"};
    bool no_shadows = false, no_reflections = false, no_refractions = false,
         no_light_buffer = false;
    std::string item_buffer = "off";
    app.add_option("scene", o.scene, "Scene or model file (.json, .obj, .gltf, .glb, .ply, .stl)")
        ->required();
    app.add_option("-o,--output", o.output, "Output image (.png or .exr); default out/SCENE.png");
    app.add_option("--mode", o.mode,
                   "trace, raster, both (raster, traced and difference), itembuffer, explain "
                   "(why they differ: OUT.explain.png), or gputrace (the tracer as an OpenGL "
                   "4.3 compute shader)")
        ->transform(rt::app::cli_names(kModeNames));
    app.add_flag("--with-gpu", o.with_gpu,
                 "With --mode both: also the GPU-traced image (OUT.gputrace.png) and its "
                 "difference to the CPU-traced one");
    app.add_option("--gl", o.gl, "OpenGL context: egl, osmesa, or auto (EGL, then OSMesa)")
        ->transform(rt::app::cli_names(rt::gl::kBackendNames));
    app.add_option("--accel", o.accel,
                   "Acceleration structure: bvh (wide, default), bvh2 (binary), grid or brute")
        ->transform(rt::app::cli_names(rt::kAccelNames));
    app.add_option("--item-buffer", item_buffer,
                   "Primary hits from the raster item buffer: on or off")
        ->check(CLI::IsMember({"on", "off"}));
    app.add_option("--size", o.size, "Image size WxH (default: the scene's resolution)");
    app.add_option("--camera", o.camera,
                   "Which of a glTF file's perspective cameras to look through: 0 (the "
                   "first, default), 1, ...")
        ->check(CLI::Range(0, 1 << 20));
    app.add_option("--up", o.up, "A bare mesh's up axis: y (default), z, x, -y, -z or -x")
        ->check(CLI::IsMember(
            std::vector<std::string>(std::begin(rt::kUpAxes), std::end(rt::kUpAxes))));
    app.add_option("--threads", o.threads, "Worker threads (default: all cores)")
        ->check(CLI::Range(1, 1024));
    app.add_option("--max-depth", o.trace.max_depth, "Maximum reflection/refraction depth")
        ->check(CLI::Range(0, 64));
    app.add_option("--min-weight", o.trace.min_weight,
                   "Cast no reflected or refracted ray that adds less than this to the pixel")
        ->check(CLI::Range(0.0f, 1.0f));
    app.add_option("--spp", o.spp,
                   "Traced samples per pixel: 1 (the pixel centre, default), 4, 16, 64, ... "
                   "(a square number; stratified, jittered, box-filtered)")
        ->check(CLI::Validator(
            [](const std::string& s) {
                try {
                    return rt::valid_spp(std::stoi(s)) ? std::string()
                                                       : "expected a square number from 1 to 1024";
                } catch (const std::exception&) {
                    return std::string("expected a square number from 1 to 1024");
                }
            },
            "SQUARE"));
    app.add_option("--msaa", o.msaa,
                   "Raster multisample anti-aliasing: 1 (none, default), 2, 4 or 8 samples")
        ->check(CLI::IsMember({1, 2, 4, 8}));
    std::string raster_shadows = "none";
    app.add_option("--raster-shadows", raster_shadows,
                   "Raster shadows: none (the classic pipeline, default) or map (shadow maps)")
        ->check(CLI::IsMember({"none", "map"}));
    app.add_option("--shadow-map-size", o.shadow_map_size,
                   "Shadow map texels a cube face side (default 1024)")
        ->check(CLI::Range(16, 4096));
    std::string raster_reflections = "none";
    app.add_option("--raster-reflections", raster_reflections,
                   "Raster mirrors and glass: none (their local colour, default) or envmap "
                   "(environment maps)")
        ->check(CLI::IsMember({"none", "envmap"}));
    app.add_option("--envmap-size", o.envmap_size,
                   "Environment map texels a cube face side (default 256)")
        ->check(CLI::Range(16, 2048));
    app.add_flag("--no-shadows", no_shadows, "Trace no shadow feelers");
    app.add_flag("--no-reflections", no_reflections, "Trace no reflected rays");
    app.add_flag("--no-refractions", no_refractions, "Trace no refracted rays");
    app.add_flag("--no-light-buffer", no_light_buffer,
                 "Build no light buffers: shadow feelers walk the objects' tree (the same "
                 "image, slower: what the light buffers save)");
    app.add_option("--stats", o.stats, "Write render statistics as JSON");
    app.add_flag("-q,--quiet", o.quiet, "Print nothing but errors");
    app.add_option("--ray-tree", o.ray_tree,
                   "Print the rays pixel X,Y (from the top left, at --size) spawns, instead "
                   "of rendering");
    app.add_option("--ray-tree-json", o.ray_tree_json, "With --ray-tree: write them as JSON");
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        exit_code = app.exit(e);
        return false;
    } catch (const CLI::ParseError& e) {
        std::cerr << "rtrender: command line: " << e.what() << " (see rtrender --help)\n";
        exit_code = 1;
        return false;
    }
    o.item_buffer = item_buffer == "on";
    o.shadow_maps = raster_shadows == "map";
    o.environment_maps = raster_reflections == "envmap";
    if (o.item_buffer && o.spp > 1) {
        std::cerr << "rtrender: command line: --item-buffer on needs --spp 1 (the item buffer "
                     "holds the pixel centres' first hits only)\n";
        exit_code = 1;
        return false;
    }
    const bool gpu = o.mode == Mode::kGpuTrace || o.with_gpu;
    if (gpu && (o.spp > 1 || o.item_buffer)) {
        std::cerr << "rtrender: command line: the GPU tracer traces the pixel centres only (no "
                     "--spp above 1, no --item-buffer)\n";
        exit_code = 1;
        return false;
    }
    o.trace.shadows = !no_shadows;
    o.trace.reflections = !no_reflections;
    o.trace.refractions = !no_refractions;
    o.light_buffer = !no_light_buffer;
    return true;
}

}  // namespace rt::renderer

int main(int argc, char** argv) {
    rt::renderer::Options options;
    int exit_code = 0;
    if (!rt::renderer::parse_command_line(argc, argv, options, exit_code)) return exit_code;
    try {
        return rt::renderer::run(options);
    } catch (const rt::Error& e) {
        std::cerr << e.what() << '\n';
        return 1;
    } catch (const std::exception& e) {  // a GL failure, out of memory: still one line
        std::cerr << options.scene << ": error: " << e.what() << '\n';
        return 1;
    }
}
