// rtrender: renders a scene file headless and writes the image (and, on request, stats).
//   rtrender SCENE [-o OUT.png|OUT.exr] [--size WxH] [--threads N] [--max-depth N]
//            [--no-shadows] [--no-reflections] [--no-refractions] [--stats FILE.json] [--quiet]

#include <unistd.h>

#include <charconv>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "app/render/progress.h"
#include "core/error.h"
#include "core/renderer.h"
#include "core/scene_loader.h"

namespace {

struct Args {
    std::string scene;
    std::string output;
    std::string size;
    std::string stats;
    int threads = 0;
    int max_depth = rt::TraceOptions{}.max_depth;
    bool no_shadows = false, no_reflections = false, no_refractions = false, quiet = false;
};

struct Timings {
    double load = 0.0, build = 0.0;
};

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::optional<std::pair<int, int>> parse_size(const std::string& text) {
    int w = 0, h = 0;
    const char* end = text.data() + text.size();
    const auto [x_at, ec1] = std::from_chars(text.data(), end, w);
    if (ec1 != std::errc{} || x_at == end || (*x_at != 'x' && *x_at != 'X')) return std::nullopt;
    const auto [h_end, ec2] = std::from_chars(x_at + 1, end, h);
    if (ec2 != std::errc{} || h_end != end) return std::nullopt;
    if (w < 1 || h < 1 || w > 16384 || h > 16384) return std::nullopt;
    return std::make_pair(w, h);
}

void write_stats(const std::string& path, const Args& args, const rt::Scene& scene, const Timings& t,
                 const rt::RenderStats& s) {
    const nlohmann::json j = {
        {"scene", args.scene},
        {"width", scene.camera.cols},
        {"height", scene.camera.rows},
        {"threads", s.threads},
        {"objects", scene.objects.size()},
        {"triangles", scene.triangle_count()},
        {"load_seconds", t.load},
        {"build_seconds", t.build},
        {"trace_seconds", s.seconds},
        {"rays",
         {{"primary", s.rays.primary},
          {"shadow", s.rays.shadow},
          {"reflected", s.rays.reflected},
          {"refracted", s.rays.refracted},
          {"total", s.rays.total()}}},
        {"mrays_per_s", s.mrays_per_s()},
        {"accel_memory_bytes", scene.accel_memory_bytes()},
        {"nonfinite_pixels", s.nonfinite_pixels},
    };
    std::ofstream out(path);
    out << j.dump(2) << '\n';
    if (!out) throw rt::Error(path, "stats", "cannot write the file");
}

void ensure_parent_directory(const std::filesystem::path& path) {
    const auto parent = path.parent_path();
    std::error_code ec;
    if (!parent.empty()) std::filesystem::create_directories(parent, ec);
    if (ec) throw rt::Error(path.string(), "output", "cannot create directory: " + ec.message());
}

int run(const Args& args) {
    const std::filesystem::path output =
        args.output.empty() ? std::filesystem::path("out") / (std::filesystem::path(args.scene).stem().string() + ".png")
                            : std::filesystem::path(args.output);
    if (!rt::is_supported_output(output)) throw rt::Error(output.string(), "-o", "unsupported format; use .png or .exr");
    std::optional<std::pair<int, int>> size;
    if (!args.size.empty() && !(size = parse_size(args.size)))
        throw rt::Error("rtrender", "--size", "expected WxH between 1x1 and 16384x16384, got \"" + args.size + "\"");

    Timings timings;
    auto start = std::chrono::steady_clock::now();
    rt::LoadedScene loaded = rt::load_scene(args.scene);
    for (const std::string& w : loaded.warnings) std::cerr << w << '\n';
    rt::Scene& scene = loaded.scene;
    if (size) scene.camera = scene.camera.resized(size->first, size->second);
    timings.load = seconds_since(start);
    start = std::chrono::steady_clock::now();
    scene.build();
    timings.build = seconds_since(start);

    rt::RenderOptions options;
    options.threads = args.threads;
    options.trace.max_depth = args.max_depth;
    options.trace.shadows = !args.no_shadows;
    options.trace.reflections = !args.no_reflections;
    options.trace.refractions = !args.no_refractions;
    rtrender::ProgressBar bar(!args.quiet && isatty(STDERR_FILENO));
    rt::RenderStats stats;
    const rt::Image image = rt::render(scene, options, &stats, [&](int done, int total) { bar.update(done, total); });
    bar.finish();

    ensure_parent_directory(output);
    rt::write_image(image, output);
    if (!args.stats.empty()) write_stats(args.stats, args, scene, timings, stats);
    if (stats.nonfinite_pixels > 0)
        std::cerr << args.scene << ": render: " << stats.nonfinite_pixels << " pixels were NaN or Inf (written black)\n";
    if (!args.quiet) {
        std::printf("%s: %dx%d, %zu objects, %.3f s on %d threads, %.2f Mrays/s\n", output.string().c_str(),
                    image.width, image.height, scene.objects.size(), stats.seconds, stats.threads, stats.mrays_per_s());
    }
    return stats.nonfinite_pixels > 0 ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"rtrender: renders a scene with rtview's Whitted ray tracer"};
    Args args;
    app.add_option("scene", args.scene, "Scene file (.json or .obj)")->required();
    app.add_option("-o,--output", args.output, "Output image (.png or .exr); default out/SCENE.png");
    app.add_option("--size", args.size, "Image size WxH (default: the scene's resolution)");
    app.add_option("--threads", args.threads, "Worker threads (default: all cores)")->check(CLI::Range(1, 1024));
    app.add_option("--max-depth", args.max_depth, "Maximum reflection/refraction depth")->check(CLI::Range(0, 64));
    app.add_flag("--no-shadows", args.no_shadows, "Trace no shadow feelers");
    app.add_flag("--no-reflections", args.no_reflections, "Trace no reflected rays");
    app.add_flag("--no-refractions", args.no_refractions, "Trace no refracted rays");
    app.add_option("--stats", args.stats, "Write render statistics as JSON");
    app.add_flag("-q,--quiet", args.quiet, "Print nothing but errors");
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << "rtrender: command line: " << e.what() << " (see rtrender --help)\n";
        return 1;
    }
    try {
        return run(args);
    } catch (const rt::Error& e) {
        std::cerr << e.what() << '\n';
        return 1;
    } catch (const std::exception& e) {  // out of memory and the like: still one line
        std::cerr << args.scene << ": error: " << e.what() << '\n';
        return 1;
    }
}
