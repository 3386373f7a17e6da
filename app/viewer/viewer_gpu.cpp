// The third pipeline in the viewer: the GPU tracer's image (app/gl/gpu_tracer.h) as a
// view of its own (key 7) and as either side of the split view. It is traced again, in
// full, whenever the camera, the window or a tracer setting changes: no coarse levels
// (at the panel's resolution, as the CPU-traced view: on llvmpipe a smaller image keeps
// the window responsive).
#include <cstdio>

#include <imgui.h>

#include "app/viewer/panel_widgets.h"
#include "app/viewer/viewer.h"
#include "core/error.h"

namespace rt::viewer {

void Viewer::init_gpu() {
    try {
        gpu_ = std::make_unique<rt::gl::GpuTracer>();
        std::printf("GPU tracer: ready\n");
    } catch (const rt::Error& e) {
        gpu_unavailable_ = e.what();
        std::printf("GPU tracer: unavailable (%s)\n", e.what());
    }
}

bool Viewer::gpu_on_screen(View view) const {
    return view == View::kGpuTrace ||
           (view == View::kSplit && display_.split != SplitPair::kRasterTraced);
}

GLuint Viewer::gpu_texture(const rt::Camera& camera) {
    if (!gpu_) return 0;
    if (gpu_serial_ != scene_serial_) {
        stats_.gpu_upload_ms = 1e3 * gpu_->upload(*scene_);
        gpu_serial_ = scene_serial_;
        gpu_camera_.reset();
    }
    const rt::TraceOptions options = trace_options();
    if (gpu_camera_ != camera || !(gpu_options_ == options)) {
        const rt::Stopwatch watch;
        gpu_->dispatch(camera, options);
        gpu_texture_.upload_from_buffer(gpu_->pixel_buffer(), camera.cols, camera.rows);
        glFinish();  // so that the time is the GPU's
        stats_.gpu_ms = watch.milliseconds();
        stats_.gpu_width = camera.cols;
        stats_.gpu_height = camera.rows;
        gpu_camera_ = camera;
        gpu_options_ = options;
    }
    return gpu_texture_.id();
}

// The split view's two images: the raster (at the window's size), the CPU-traced image
// or the GPU-traced one; the compositor draws `raster` left and `traced` right.
void Viewer::split_inputs(rt::gl::CompositeInputs& in, int width, int height) {
    const rt::Camera camera = controller_->camera(width, height);
    const GLuint traced = traced_texture_.id();
    const rt::Camera gpu_camera = trace_camera();  // at the panel's resolution, as the CPU's
    switch (display_.split) {
        case SplitPair::kRasterTraced:
            in.raster = raster_texture(camera);
            break;
        case SplitPair::kRasterGpu:
            in.raster = raster_texture(camera);
            in.traced = gpu_texture(gpu_camera);
            break;
        case SplitPair::kTracedGpu:
            in.traced = gpu_texture(gpu_camera);
            in.raster = traced;
            break;
    }
}

std::string Viewer::split_side_label(bool right) const {
    const bool left_is_raster = display_.split != SplitPair::kTracedGpu;
    const bool right_is_gpu = display_.split != SplitPair::kRasterTraced;
    if (right) return right_is_gpu ? "GPU traced" : traced_label();
    return left_is_raster ? raster_label() : traced_label();
}

void Viewer::draw_gpu_statistics() {
    if (!gpu_) {
        ImGui::TextDisabled("GPU traced: unavailable");
        return;
    }
    if (stats_.gpu_width == 0) {
        ImGui::TextDisabled("GPU traced: not shown in this view yet");
        return;
    }
    ImGui::Text("GPU traced: %.1f ms at %dx%d (scene upload %.1f ms)", stats_.gpu_ms,
                stats_.gpu_width, stats_.gpu_height, stats_.gpu_upload_ms);
}

}  // namespace rt::viewer
