// rtbench: measures the acceleration structures and the item buffer.
//   rtbench SCENE_OR_MESH [--json FILE] [--size WxH] [--threads N] [--repeats N] [--gpu]
//   rtbench SCENE_OR_MESH --threads-sweep 1,2,4,... [--json FILE]
//   rtbench --sweep [--csv FILE] [--png FILE] [--counts N,N,...]
//   rtbench --item-buffer SCENE [--json FILE] [--size WxH] [--gl egl|osmesa]

#include <iostream>
#include <thread>

#include <CLI/CLI.hpp>

#include "app/bench/modes.h"
#include "app/common/cli_names.h"
#include "app/common/size_arg.h"
#include "core/error.h"
#include "core/texture.h"

namespace {

// rtbench measures geometry and never links an image library (it must run where there
// is a GPU driver and nothing else): a scene's textures are read as plain white.
rt::Texture white_texture() {
    rt::Texture t;
    t.name = "white (rtbench reads no images)";
    t.width = t.height = 1;
    t.texels = {rt::vec3(1.0f)};
    return t;
}

}  // namespace

int main(int argc, char** argv) {
    std::setvbuf(stdout, nullptr, _IOLBF, 0);  // each line out at once, also into a pipe
    rt::install_image_reader(
        {[](const std::filesystem::path&, const std::string&, const std::string&) {
             return white_texture();
         },
         [](const std::vector<unsigned char>&, const std::string&, const std::string&,
            const std::string&) { return white_texture(); }});
    CLI::App app{
        "rtbench: BVH, grid and brute force against Intel Embree; the item buffer's saving"};
    std::string scene, json, size = "1280x720", csv = "sweep.csv", png = "sweep.png";
    rt::gl::Backend gl = rt::gl::Backend::kAuto;
    bool sweep = false, item_buffer = false, gpu = false;
    rt::TraceOptions gpu_frame;
    std::vector<std::string> only;
    std::vector<int> counts{1000, 10000, 100000, 1000000};
    int threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency())), repeats = 5;
    app.add_option("scene", scene, "Scene (.json) or mesh (.obj)");
    app.add_option("--json", json, "Write the figures as JSON");
    app.add_option("--size", size, "Camera resolution WxH for primary rays (default 1280x720)");
    app.add_option("--threads", threads, "Threads, for every structure alike")
        ->check(CLI::Range(1, 256));
    app.add_option("--repeats", repeats, "Timed passes (the median is reported)")
        ->check(CLI::Range(1, 100));
    app.add_option("--only", only,
                   "Structures to run: brute, grid, bvh2, bvh, embree, embree-robust, bvh-packets, "
                   "embree-packets (default: all); bvh and a reference (embree, or brute "
                   "without it) always run")
        ->delimiter(',');
    std::vector<int> threads_sweep;
    app.add_option("--threads-sweep", threads_sweep,
                   "Build and trace rates of our BVH and Embree on each of these thread counts "
                   "(e.g. 1,2,4,8)")
        ->delimiter(',')
        ->check(CLI::Range(1, 256));
    app.add_flag("--sweep", sweep, "Time per ray against triangle count on a tessellated sphere");
    app.add_option("--csv", csv, "--sweep: the data (default sweep.csv, in the current folder)");
    app.add_option("--counts", counts,
                   "--sweep: triangle counts (default 1000,10000,100000,1000000)")
        ->delimiter(',')
        ->check(CLI::Range(8, 50000000));
    app.add_option("--png", png,
                   "--sweep: the plot, needs gnuplot (default sweep.png, in the current folder)");
    app.add_flag("--item-buffer", item_buffer, "A Whitted frame with and without the item buffer");
    app.add_flag("--gpu", gpu,
                 "Also the GPU tracer's traversal (an OpenGL 4.3 compute shader) on the same rays");
    app.add_option("--max-depth", gpu_frame.max_depth,
                   "--gpu: the bounces of the GPU-traced frame of the whole scene (default 5)")
        ->check(CLI::Range(0, 64));
    app.add_option("--gl", gl, "--item-buffer, --gpu: egl, osmesa or auto")
        ->transform(rt::app::cli_names(rt::gl::kBackendNames));
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << "rtbench: command line: " << e.what() << " (see rtbench --help)\n";
        return 1;
    }
    const auto parsed = rt::app::parse_size(size);
    if (!parsed) {
        std::cerr << "rtbench: --size: expected WxH, got \"" << size << "\"\n";
        return 1;
    }
    if (!sweep && scene.empty()) {
        std::cerr << "rtbench: command line: a scene or mesh is required (or --sweep; see rtbench "
                     "--help)\n";
        return 1;
    }
    const auto [w, h] = *parsed;
    rt::bench::MeasureOptions measure;
    measure.threads = threads;
    measure.repeats = repeats;
    try {
        if (sweep) {
            rt::bench::SweepOptions o;
            o.csv = csv;
            o.png = png;
            o.measure = measure;
            o.triangle_counts = counts;
            return rt::bench::run_sweep(o);
        }
        if (item_buffer)
            return rt::bench::run_item_buffer({scene, json, w, h, threads, repeats, gl});
        return rt::bench::run_scene(
            {scene, only, json, w, h, measure, gpu, gpu_frame, gl, threads_sweep});
    } catch (const rt::Error& e) {
        std::cerr << e.what() << '\n';
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "rtbench: error: " << e.what() << '\n';
        return 1;
    }
}
