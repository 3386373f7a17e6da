// rtbench --gpu: the GPU tracer's traversal (shaders/gputrace.comp with RAY_QUERIES) as one
// more structure, on the same triangles and rays as the others and checked like them.
#include "app/bench/bench.h"
#include "app/gl/gpu_tracer.h"
#include "core/compare.h"
#include "core/renderer.h"
#include "core/stopwatch.h"

namespace rt::bench {
namespace {

class Gpu : public Structure {
  public:
    explicit Gpu(rt::gl::Backend backend)
        : context_(rt::gl::create_headless_context(backend, "rtbench")) {
        tracer_ = std::make_unique<rt::gl::GpuTracer>();
        std::printf("gpu: %s\n", context_->description().c_str());
    }
    std::string name() const override { return "gpu"; }
    void prepare(const rt::TriangleMesh& mesh) override { mesh_ = mesh; }
    // Core's binary BVH over the triangles (flatten), then the buffers up: what a scene
    // change costs the GPU tracer.
    void build() override {
        rt::SceneDescription d;
        d.meshes.push_back(mesh_);
        d.objects.push_back(rt::Object{"mesh", rt::MeshRef{0, true}, 0, std::nullopt});
        const rt::Scene scene(std::move(d), rt::AccelKind::kBrute);  // the GPU builds its own
        tracer_->upload(scene);
    }
    std::size_t memory_bytes() const override { return tracer_->uploaded_bytes(); }
    Result intersect(const rt::Ray& ray, float t_max) const override {
        std::vector<Result> answers(1);
        trace({ray}, {t_max}, false, 1, answers);
        return answers[0];
    }
    bool occluded(const rt::Ray& ray, float t_max) const override {
        std::vector<Result> answers(1);
        trace({ray}, {t_max}, true, 1, answers);
        return answers[0].hit();
    }
    std::optional<double> trace_set(const RaySet& set, std::size_t stride,
                                    std::vector<Result>& answers) const override {
        return trace(set.rays, set.t_max, set.occlusion, stride, answers);
    }

  private:
    double trace(const std::vector<rt::Ray>& rays, const std::vector<float>& t_max, bool any_hit,
                 std::size_t stride, std::vector<Result>& answers) const {
        std::vector<glm::vec4> rows;
        rows.reserve(2 * (rays.size() / stride + 1));
        for (std::size_t r = 0; r < rays.size(); r += stride) {
            rows.emplace_back(rays[r].origin, t_max[r]);
            rows.emplace_back(rays[r].dir, any_hit ? 1.0f : 0.0f);
        }
        rt::gl::GpuTraceTimes times;
        const std::vector<rt::gl::GpuRayAnswer> gpu = tracer_->trace_rays(rows, &times);
        answers.assign(gpu.size(), Result{});
        for (std::size_t i = 0; i < gpu.size(); ++i)
            if (gpu[i].hit) answers[i] = Result{gpu[i].t, gpu[i].prim};
        return times.dispatch_s;
    }

    std::unique_ptr<rt::gl::Context> context_;
    std::unique_ptr<rt::gl::GpuTracer> tracer_;
    rt::TriangleMesh mesh_;
};

}  // namespace

std::unique_ptr<Structure> make_gpu(rt::gl::Backend backend) {
    return std::make_unique<Gpu>(backend);
}

nlohmann::json time_gpu_frame(const rt::SceneDescription& description, const rt::Camera& camera,
                              const rt::TraceOptions& options, int repeats, int threads) {
    rt::SceneDescription d = description;
    d.camera = camera;
    const rt::Scene scene(std::move(d));  // the CPU's structures too: it renders the frame
    rt::gl::GpuTracer tracer;
    const double upload = tracer.upload(scene);
    rt::gl::GpuTraceTimes times;
    tracer.render(camera, options, &times);  // warm-up: the program's variant, the caches
    std::vector<double> seconds;
    for (int k = 0; k < repeats; ++k) {
        tracer.render(camera, options, &times);
        seconds.push_back(times.dispatch_s);
    }
    const double s = median(seconds);
    // The same frame from the CPU tracer: the GPU's image must be the same picture.
    rt::RenderOptions cpu;
    cpu.trace = options;
    cpu.threads = threads;
    const rt::ImageDiff diff =
        rt::compare_images(rt::render(scene, cpu), tracer.render(camera, options));
    std::printf(
        "gpu frame: %dx%d, shadows %s, max depth %d: %.2f ms median of %d (%.0f frames/s), "
        "%.1f M primary rays/s; scene upload %.3f s\n",
        camera.cols, camera.rows, options.shadows ? "on" : "off", options.max_depth, 1e3 * s,
        repeats, 1.0 / s, static_cast<double>(camera.cols) * camera.rows / s * 1e-6, upload);
    std::printf(
        "gpu frame against the CPU tracer's: PSNR %.1f dB, %.4f %% of pixels differ by more "
        "than 2/255\n",
        diff.identical() ? 999.0 : diff.psnr_db, 100.0 * diff.share_over);
    return {{"width", camera.cols},
            {"height", camera.rows},
            {"max_depth", options.max_depth},
            {"shadows", options.shadows},
            {"dispatch_seconds", s},
            {"frames_per_s", 1.0 / s},
            {"upload_seconds", upload},
            {"psnr_db_against_cpu", diff.identical() ? 999.0 : diff.psnr_db},
            {"share_over_2_255_against_cpu", diff.share_over}};
}

}  // namespace rt::bench
