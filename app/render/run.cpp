// rtrender's job: load, build, render in the chosen mode, write images and stats.
#include <unistd.h>

#include <charconv>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>

#include "app/common/size_arg.h"
#include "app/gl/context.h"
#include "app/gl/gpu_tracer.h"
#include "app/gl/raster_renderer.h"
#include "app/render/options.h"
#include "app/render/progress.h"
#include "app/render/ray_tree_report.h"
#include "core/compare.h"
#include "core/error.h"
#include "core/explain.h"
#include "core/renderer.h"
#include "core/scene_loader.h"
#include "core/stopwatch.h"

namespace rt::renderer {
namespace {

namespace fs = std::filesystem;

// OUT.png, or for --mode both OUT.raster.png, OUT.trace.png and OUT.diff.png.
fs::path output_path(const Options& o, const char* part = nullptr) {
    fs::path base = o.output.empty()
                        ? fs::path("out") / (fs::path(o.scene).stem().string() + ".png")
                        : fs::path(o.output);
    if (part) base.replace_filename(base.stem().string() + "." + part + base.extension().string());
    return base;
}

void write(const rt::Image& image, const fs::path& path, const Options& o) {
    std::error_code ec;
    if (path.has_parent_path()) fs::create_directories(path.parent_path(), ec);
    if (ec) throw rt::Error(path.string(), "output", "cannot create directory: " + ec.message());
    rt::write_image(image, path);
    if (!o.quiet)
        std::printf("wrote %s (%dx%d)\n", path.string().c_str(), image.width, image.height);
}

class Job {
  public:
    explicit Job(const Options& o) : o_(o) {}

    int run();

  private:
    rt::gl::Context& context();
    rt::gl::RasterRenderer& raster();
    rt::Image gpu_trace();
    rt::Image trace();
    rt::ItemBuffer item_buffer();
    rt::Image render_traced(const rt::ItemBuffer* item_buffer, rt::RenderStats& stats,
                            const char* label);
    void report_diff(const rt::Image& raster_image, const rt::Image& traced,
                     const char* part = "diff", const char* what = "raster vs traced");
    void explain(bool write_map);
    void write_stats();
    int ray_tree();

    const Options& o_;
    rt::LoadedScene loaded_;
    std::optional<rt::Scene> scene_;  // loaded_.scene, built
    nlohmann::json stats_;
    std::unique_ptr<rt::gl::Context> context_;
    std::unique_ptr<rt::gl::RasterRenderer> raster_;
    std::uint64_t nonfinite_ = 0;
};

rt::gl::Context& Job::context() {
    if (!context_) {
        context_ = rt::gl::create_headless_context(o_.gl, "rtrender");
        stats_["gl"] = context_->description();
        if (!o_.quiet) std::printf("OpenGL: %s\n", context_->description().c_str());
    }
    return *context_;
}

rt::gl::RasterRenderer& Job::raster() {
    if (!raster_) {
        context();
        raster_ = std::make_unique<rt::gl::RasterRenderer>(*scene_);
        raster_->set_msaa(o_.msaa);
        raster_->set_shadow_maps(o_.shadow_maps, o_.shadow_map_size);
        raster_->set_environment_maps(o_.environment_maps, o_.envmap_size);
        stats_["raster_reflections"] = o_.environment_maps ? "envmap" : "none";
        if (o_.environment_maps) stats_["envmap_size"] = o_.envmap_size;
        stats_["msaa"] = o_.msaa;
        stats_["raster_shadows"] = o_.shadow_maps ? "map" : "none";
        if (o_.shadow_maps) stats_["shadow_map_size"] = o_.shadow_map_size;
        if (scene_->lights.size() > rt::gl::RasterRenderer::kMaxLights)
            std::cerr << o_.scene << ": lights: the raster view uses the first "
                      << rt::gl::RasterRenderer::kMaxLights << " of " << scene_->lights.size()
                      << " lights\n";
    }
    return *raster_;
}

rt::Image Job::render_traced(const rt::ItemBuffer* item_buffer, rt::RenderStats& stats,
                             const char* label) {
    rt::RenderOptions options;
    options.threads = o_.threads;
    options.trace = o_.trace;
    options.spp = o_.spp;
    ProgressBar bar(!o_.quiet && isatty(STDERR_FILENO));
    rt::Image image = rt::render(
        *scene_, options, &stats, [&](int done, int total) { bar.update(done, total); }, {},
        item_buffer);
    bar.finish();
    nonfinite_ += stats.nonfinite_pixels;
    if (!o_.quiet)
        std::printf("%s: %.3f s (primary %.3f s, secondary %.3f s) on %d threads, %.2f Mrays/s\n",
                    label, stats.seconds, stats.primary_seconds, stats.secondary_seconds,
                    stats.threads, stats.mrays_per_s());
    return image;
}

// The item buffer, timed both ways: a pass of its own (the first pays for buffers and
// sphere meshes; the second is what a frame costs), and, where the raster pass can draw
// it (one sample a pixel), from the raster pass itself: its cost is what drawing and
// reading the ids adds to a raster frame that is drawn anyway. Both give the same ids (GL
// test); the cheaper is reported as the pass used. The warm passes draw into the storage
// of the cold ones, as frames after the first would.
rt::ItemBuffer Job::item_buffer() {
    rt::gl::RasterRenderer& gl = raster();
    rt::Stopwatch watch;
    rt::gl::RasterRenderer::Frame frame;
    gl.render_item_buffer(scene_->camera, frame.ids);
    stats_["item_buffer_cold_seconds"] = watch.lap();
    gl.render_item_buffer(scene_->camera, frame.ids);
    const double dedicated = watch.seconds();
    stats_["item_buffer_dedicated_seconds"] = dedicated;
    stats_["item_buffer_pass"] = "dedicated";
    stats_["item_buffer_seconds"] = dedicated;
    if (!gl.shares_item_buffer()) return std::move(frame.ids);
    gl.render(scene_->camera, frame.image);  // warm: maps and buffers drawn
    watch.restart();
    gl.render(scene_->camera, frame.image);
    const double plain = watch.lap();
    gl.render_with_item_buffer(scene_->camera, frame);
    const double shared = std::max(0.0, watch.seconds() - plain);
    stats_["item_buffer_shared_seconds"] = shared;
    if (!o_.quiet)
        std::printf(
            "item buffer: its own pass %.4f s; from the raster pass %.4f s (the ids "
            "drawn with the colours, and read back)\n",
            dedicated, shared);
    if (shared < dedicated) {
        stats_["item_buffer_pass"] = "shared";
        stats_["item_buffer_seconds"] = shared;
    }
    return std::move(frame.ids);
}

rt::Image Job::trace() {
    rt::RenderStats stats;
    std::optional<rt::ItemBuffer> ib;
    if (o_.item_buffer) ib = item_buffer();
    rt::Image image =
        render_traced(ib ? &*ib : nullptr, stats, ib ? "traced with item buffer" : "traced");
    stats_["trace_seconds"] = stats.seconds;
    stats_["primary_seconds"] = stats.primary_seconds;
    stats_["secondary_seconds"] = stats.secondary_seconds;
    stats_["threads"] = stats.threads;
    stats_["spp"] = o_.spp;
    stats_["light_buffer"] = o_.light_buffer;
    stats_["rays"] = {{"primary", stats.rays.primary},
                      {"shadow", stats.rays.shadow},
                      {"reflected", stats.rays.reflected},
                      {"refracted", stats.rays.refracted},
                      {"total", stats.rays.total()}};
    stats_["mrays_per_s"] = stats.mrays_per_s();
    stats_["nonfinite_pixels"] = stats.nonfinite_pixels;
    if (!ib) return image;

    // The same frame without the item buffer: what it changes, and what it saves.
    rt::RenderStats reference;
    const rt::Image plain = render_traced(nullptr, reference, "traced without item buffer");
    const std::uint64_t disagreements = rt::item_buffer_disagreements(image, plain);
    const double ib_seconds = stats_["item_buffer_seconds"].get<double>();  // what it cost
    const double saved = reference.primary_seconds - stats.primary_seconds - ib_seconds;
    stats_["item_buffer_disagreements"] = disagreements;
    stats_["item_buffer_fallbacks"] = stats.item_buffer_fallbacks;
    stats_["reference_primary_seconds"] = reference.primary_seconds;
    stats_["primary_seconds_saved"] = saved;
    if (!o_.quiet)
        std::printf(
            "item buffer: %.3f s, primary rays %.3f s instead of %.3f s: "
            "net %s %.3f s; "
            "%llu pixels on edges tested against the objects around them, %llu of %zu pixels "
            "disagree (%.4f%%)\n",
            ib_seconds, stats.primary_seconds, reference.primary_seconds,
            saved >= 0 ? "saving" : "LOSS", std::abs(saved),
            static_cast<unsigned long long>(stats.item_buffer_fallbacks),
            static_cast<unsigned long long>(disagreements), image.pixels.size(),
            100.0 * static_cast<double>(disagreements) / static_cast<double>(image.pixels.size()));
    return image;
}

// The same tracer as a compute shader: the first frame pays for compiling the shader's
// variant; the second is what a frame costs.
rt::Image Job::gpu_trace() {
    context();
    rt::gl::GpuTracer gpu;
    const double upload = gpu.upload(*scene_);
    rt::gl::GpuTraceTimes first, times;
    gpu.render(scene_->camera, o_.trace, &first);
    rt::Image image = gpu.render(scene_->camera, o_.trace, &times);
    const double pixels = static_cast<double>(image.pixels.size());
    stats_["gpu"] = {{"upload_seconds", upload},
                     {"uploaded_bytes", gpu.uploaded_bytes()},
                     {"first_dispatch_seconds", first.dispatch_s},
                     {"dispatch_seconds", times.dispatch_s},
                     {"readback_seconds", times.readback_s},
                     {"primary_mrays_per_s", pixels / times.dispatch_s * 1e-6}};
    if (!o_.quiet)
        std::printf(
            "GPU traced: %.4f s a frame (first %.4f s), read-back %.4f s, upload %.3f s (%.1f "
            "MiB), "
            "%.1f M primary rays/s\n",
            times.dispatch_s, first.dispatch_s, times.readback_s, upload,
            static_cast<double>(gpu.uploaded_bytes()) / (1024.0 * 1024.0),
            pixels / times.dispatch_s * 1e-6);
    return image;
}

void Job::report_diff(const rt::Image& raster_image, const rt::Image& traced, const char* part,
                      const char* what) {
    const rt::ImageDiff d = rt::compare_images(raster_image, traced);
    const float scale = static_cast<float>(std::max(d.max_error, 1.0 / 255.0));
    write(rt::difference_image(raster_image, traced, scale), output_path(o_, part), o_);
    stats_[part] = {{"mean_abs_error", d.mean_abs_error},
                    {"rms", d.rms},
                    {"psnr_db", d.identical() ? 999.0 : d.psnr_db},
                    {"identical", d.identical()},
                    {"non_finite_pixels", d.non_finite},
                    {"max_error", d.max_error},
                    {"threshold", d.threshold},
                    {"share_over_threshold", d.share_over},
                    {"scale", scale}};
    if (o_.quiet) return;
    char psnr[32] = "identical";
    if (!d.identical()) std::snprintf(psnr, sizeof psnr, "%.2f dB", d.psnr_db);
    std::printf(
        "%s: mean abs error %.4f, RMS %.4f, PSNR %s, %.2f%% of pixels differ by "
        "more than %.0f/255 (diff scale 0 to %.3f)\n",
        what, d.mean_abs_error, d.rms, psnr, 100.0 * d.share_over, d.threshold * 255.0, scale);
    if (d.non_finite > 0)
        std::printf("%s: %llu pixels are NaN or infinite in one image\n", what,
                    static_cast<unsigned long long>(d.non_finite));
}

// Why raster and traced differ (core/explain.h): the map as an image, the shares per
// cause in the stats and on one line.
void Job::explain(bool write_map) {
    // The raster drawn again, with what each of its tricks added apart.
    const rt::gl::RasterRenderer::ForExplain r = raster().render_for_explain(scene_->camera);
    rt::RenderOptions options;
    options.threads = o_.threads;
    options.trace = o_.trace;
    rt::Stopwatch watch;
    const rt::ExplainMap map =
        rt::explain(*scene_, scene_->camera, options, r.image, r.ids, {}, &r.tricks);
    stats_["explain_seconds"] = watch.seconds();
    if (write_map) write(rt::explain_image(map), output_path(o_, "explain"), o_);
    const auto shares = rt::cause_shares(map);
    nlohmann::json causes = nlohmann::json::object();
    std::string line;
    for (std::size_t k = 0; k < rt::kCauseCount; ++k) {
        const char* name = rt::kCauseNames[k].name;
        causes[name] = {{"pixels", shares[k].pixels}, {"error", shares[k].error}};
        if (shares[k].pixels == 0.0) continue;
        char part[96];
        std::snprintf(part, sizeof part, "%s%s %.2f%% of pixels, %.1f%% of the difference",
                      line.empty() ? "" : "; ", name, 100.0 * shares[k].pixels,
                      100.0 * shares[k].error);
        line += part;
    }
    stats_["explain"] = causes;
    if (!o_.quiet) std::printf("why they differ: %s\n", line.c_str());
}

void Job::write_stats() {
    const rt::Scene& scene = *scene_;
    stats_["scene"] = o_.scene;
    stats_["mode"] = rt::name_of(kModeNames, o_.mode);
    stats_["width"] = scene.camera.cols;
    stats_["height"] = scene.camera.rows;
    stats_["objects"] = scene.objects.size();
    stats_["triangles"] = scene.triangle_count();
    stats_["accel_memory_bytes"] = scene.accel_memory_bytes();
    std::ofstream out(o_.stats);
    out << stats_.dump(2) << '\n';
    if (!out) throw rt::Error(o_.stats, "stats", "cannot write the file");
}

int Job::run() {
    const fs::path main_output = output_path(o_);
    if (!rt::is_supported_output(main_output))
        throw rt::Error(main_output.string(), "-o", "unsupported format; use .png or .exr");
    std::optional<std::pair<int, int>> size;
    if (!o_.size.empty() && !(size = rt::app::parse_size(o_.size)))
        throw rt::Error("rtrender", "--size",
                        "expected WxH between 1x1 and 16384x16384, got \"" + o_.size + "\"");

    rt::Stopwatch watch;
    const bool show_phases = !o_.quiet && isatty(STDERR_FILENO);
    {
        const PhaseLine phase(show_phases, "loading " + o_.scene);
        loaded_ = rt::load_scene(o_.scene, rt::LoadOptions{.up = o_.up, .camera = o_.camera});
    }
    if (!o_.quiet)
        for (const std::string& w : loaded_.warnings) std::cerr << w << '\n';
    rt::SceneDescription& description = loaded_.scene;
    if (size) description.camera = description.camera.resized(size->first, size->second);
    stats_["load_seconds"] = watch.lap();
    stats_["origin"] = {loaded_.origin.x, loaded_.origin.y, loaded_.origin.z};
    stats_["scale"] = loaded_.scale;
    {
        const PhaseLine phase(show_phases, "building the acceleration structures");
        scene_.emplace(std::move(description), o_.accel, o_.light_buffer);
    }
    const rt::Scene& scene = *scene_;
    stats_["build_seconds"] = watch.lap();
    stats_["accel"] = rt::accel_name(o_.accel);
    if (!o_.ray_tree.empty()) return ray_tree();

    if (o_.mode == Mode::kTrace) {
        write(trace(), main_output, o_);
    } else if (o_.mode == Mode::kGpuTrace) {
        write(gpu_trace(), main_output, o_);
    } else if (o_.mode == Mode::kItemBuffer) {
        write(rt::item_buffer_image(raster().render_item_buffer(scene.camera)), main_output, o_);
    } else {
        rt::gl::RasterRenderer& gl = raster();
        // The first pass also draws the shadow and environment maps; the second is what a
        // frame costs once they exist (what a camera move costs in the viewer).
        watch.restart();
        rt::Image raster_image = gl.render(scene.camera);
        const double first = watch.lap();
        raster_image = gl.render(scene.camera);
        const double frame = watch.seconds();
        stats_["raster_first_seconds"] = first;
        stats_["raster_seconds"] = frame;
        if (!o_.quiet)
            std::printf("raster: %.3f s a frame, with read-back (first %.3f s: maps and buffers)\n",
                        frame, first);
        if (o_.mode == Mode::kRaster) {
            write(raster_image, main_output, o_);
        } else if (o_.mode == Mode::kExplain) {
            explain(true);
        } else {
            const rt::Image traced = trace();
            write(raster_image, output_path(o_, "raster"), o_);
            write(traced, output_path(o_, "trace"), o_);
            report_diff(raster_image, traced);
            if (o_.with_gpu) {
                const rt::Image gpu = gpu_trace();
                write(gpu, output_path(o_, "gputrace"), o_);
                report_diff(traced, gpu, "gpudiff", "CPU vs GPU traced");
            }
            if (!o_.stats.empty()) explain(false);
        }
    }
    if (!o_.stats.empty()) write_stats();
    if (nonfinite_ > 0) {
        std::cerr << o_.scene << ": render: " << nonfinite_
                  << " pixels were NaN or Inf (written black)\n";
        return 1;
    }
    return 0;
}

}  // namespace

// --ray-tree X,Y: the pixel's rays, printed (and written as JSON); no image.
int Job::ray_tree() {
    const auto comma = o_.ray_tree.find(',');
    int x = -1, y = -1;
    const char* s = o_.ray_tree.c_str();
    const auto end = s + o_.ray_tree.size();
    const bool parsed = comma != std::string::npos &&
                        std::from_chars(s, s + comma, x).ptr == s + comma &&
                        std::from_chars(s + comma + 1, end, y).ptr == end;
    if (!parsed)
        throw rt::Error("rtrender", "--ray-tree", "expected X,Y, got \"" + o_.ray_tree + "\"");
    const rt::RayNode root = trace_pixel_tree(*scene_, scene_->camera, o_.trace, x, y);
    print_ray_tree(*scene_, root, x, y, {loaded_.origin, loaded_.scale});
    if (!o_.ray_tree_json.empty())
        write_ray_tree_json(root, x, y, o_.ray_tree_json, {loaded_.origin, loaded_.scale});
    return 0;
}

int run(const Options& options) { return Job(options).run(); }

}  // namespace rt::renderer
