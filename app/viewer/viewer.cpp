#include "app/viewer/viewer.h"
#include "app/viewer/keys.h"
#include "app/viewer/views.h"

#include <cstdio>
#include <iostream>

#include "app/gl/gl.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/gl/debug.h"
#include "core/error.h"
#include "core/scene_loader.h"
#include "core/stopwatch.h"

namespace rt::viewer {
namespace {

using Clock = std::chrono::steady_clock;

Viewer* viewer_of(GLFWwindow* w) { return static_cast<Viewer*>(glfwGetWindowUserPointer(w)); }

}  // namespace

namespace {

// The part of loading that needs no GL: parse and build. Throws rt::Error.
std::shared_ptr<const rt::Scene> read_scene(const std::string& path, rt::AccelKind accel,
                                            const std::string& up,
                                            std::optional<int> camera = std::nullopt) {
    rt::LoadedScene loaded = rt::load_scene(path, rt::LoadOptions{.up = up, .camera = camera});
    for (const std::string& w : loaded.warnings) std::cerr << w << '\n';
    return std::make_shared<const rt::Scene>(std::move(loaded.scene), accel);
}

}  // namespace

Viewer::Viewer(const ViewerOptions& options)
    : options_(options),
      first_scene_(read_scene(options.scene, options.accel, options.up,
                              options.camera)),  // a bad file fails before any window opens
      window_(options.width, options.height, "rtview"),
      scenes_(scenes_dir()),
      tracer_([] { glfwPostEmptyEvent(); }),
      display_{.view = options.view} {
    GLFWwindow* w = window_.handle();
    glfwSetWindowUserPointer(w, this);
    // Every event comes here first; what ImGui gets is decided in viewer_input.cpp.
    glfwSetKeyCallback(w, [](GLFWwindow* win, int key, int scancode, int action, int mods) {
        viewer_of(win)->on_key(key, scancode, action, mods);
    });
    glfwSetCharCallback(w, [](GLFWwindow* win, unsigned int c) { viewer_of(win)->on_char(c); });
    glfwSetMouseButtonCallback(w, [](GLFWwindow* win, int button, int action, int mods) {
        viewer_of(win)->window_.forward_mouse_button(button, action, mods);
        viewer_of(win)->on_mouse_button(button, action);
    });
    glfwSetCursorPosCallback(
        w, [](GLFWwindow* win, double x, double y) { viewer_of(win)->on_cursor(x, y); });
    glfwSetScrollCallback(w, [](GLFWwindow* win, double dx, double dy) {
        rt::gl::Window::forward_scroll(win, dx, dy);
        viewer_of(win)->on_scroll(dy);
    });
    glfwSetDropCallback(w, [](GLFWwindow* win, int count, const char** paths) {
        if (count > 0) viewer_of(win)->on_drop(paths[0]);
    });
    window_.init_imgui();
    compositor_ = std::make_unique<rt::gl::Compositor>();
    rays_ = std::make_unique<rt::gl::RayOverlay>();
    init_gpu();
    settings_.max_spp = options.spp;
    glGetIntegerv(GL_MAX_SAMPLES, &max_msaa_);
    if (options.msaa > max_msaa_)
        throw rt::Error("rtview", "--msaa",
                        std::to_string(options.msaa) + " samples: this OpenGL offers at most " +
                            std::to_string(max_msaa_));
    settings_.msaa = options.msaa;
    settings_.shadow_maps = options.shadow_maps;
    settings_.environment_maps = options.environment_maps;
    std::printf("OpenGL: %s\n", window_.description().c_str());
    install(std::move(first_scene_), options.scene);
}

Viewer::~Viewer() { tracer_.cancel(); }

bool Viewer::load(const std::string& path) {
    try {
        install(read_scene(path, options_.accel, options_.up), path);
        return true;
    } catch (const std::exception& e) {
        error_ = e.what();
        std::fprintf(stderr, "%s\n", error_.c_str());
        return false;
    }
}

void Viewer::install(std::shared_ptr<const rt::Scene> scene, const std::string& path) {
    auto raster = std::make_unique<rt::gl::RasterRenderer>(*scene);
    tracer_.cancel();  // the worker lets go of the old scene before it goes
    raster_ = std::move(raster);
    scene_ = std::move(scene);
    ++scene_serial_;  // the GPU tracer uploads it when it is first shown
    scenes_.shown(path);
    controller_ = std::make_unique<CameraController>(scene_->camera, scene_->bounds());
    compositor_->set_item_palette(scene_->objects.size());
    schedule_.reset();
    traced_image_ = rt::Image(1, 1);
    traced_image_.pixels[0] = scene_->background;
    traced_texture_.upload(traced_image_);
    explain_texture_.upload(rt::Image(1, 1));
    explanation_.reset();
    clear_picked();
    inspected_.reset();
    stats_ = FrameStats{};
    raster_camera_.reset();
    ids_camera_.reset();
    shown_.reset();
    error_.clear();
    std::printf("scene: %s (%zu objects, %zu triangles)\n", path.c_str(), scene_->objects.size(),
                scene_->triangle_count());
    std::fflush(stdout);
}

rt::Camera Viewer::trace_camera() const {
    const glm::ivec2 fb = window_.framebuffer_size();
    const auto scaled = [&](int n) {
        return std::max(1, static_cast<int>(static_cast<float>(n) * settings_.resolution_scale));
    };
    return controller_->camera(scaled(fb.x), scaled(fb.y));
}

TraceKey Viewer::trace_key() const {
    const rt::Camera camera = trace_camera();
    TraceKey key;
    key.camera_version = controller_->version();
    key.width = camera.cols;
    key.height = camera.rows;
    key.shadows = settings_.shadows;
    key.reflections = settings_.reflections;
    key.refractions = settings_.refractions;
    key.max_depth = settings_.max_depth;
    key.item_buffer = settings_.item_buffer;
    key.threads = settings_.threads;
    key.explain = explain_;
    key.max_spp = settings_.max_spp;
    return key;
}

// One line whenever the tracer's settings change (not the camera or the size): what the
// user set is on record, and the GUI test reads it.
void Viewer::log_trace_settings(const TraceKey& key) {
    TraceKey settings = key;
    settings.camera_version = 0;
    settings.width = settings.height = 0;
    settings.explain = false;  // how it is traced, not what
    if (logged_settings_ && *logged_settings_ == settings) return;
    logged_settings_ = settings;
    if (picked_) trace_picked();  // its rays as the new settings cast them
    const auto on = [](bool b) { return b ? "on" : "off"; };
    std::printf(
        "trace settings: shadows %s, reflections %s, refractions %s, max depth %d, "
        "item buffer %s, threads %d\n",
        on(key.shadows), on(key.reflections), on(key.refractions), key.max_depth,
        on(key.item_buffer), key.threads);
    std::fflush(stdout);
}

// The schedule (refinement.h) says when and at which levels; the item buffer is made
// for chains that reach full resolution.
void Viewer::update_trace() {
    if (shown_view() == View::kWhy) {
        explain_ = true;
    } else if (explain_) {
        TraceKey plain = trace_key();
        plain.explain = false;
        TraceKey parts = plain;
        parts.explain = true;
        if (shown_.stale(parts)) explain_ = false;  // something else changed: trace plainly
    }
    const TraceKey key = trace_key();
    const View view = shown_view();
    const bool gpu_only = view == View::kGpuTrace ||
                          (view == View::kSplit && display_.split == SplitPair::kRasterGpu);
    const bool on_screen =
        display_.flicker || (view != View::kRaster && view != View::kItemBuffer && !gpu_only);
    // Off screen, what the tracer is doing for an older camera only slows the raster down.
    if (!on_screen && !shown_.asked_for(key)) tracer_.stop();
    std::vector<int> levels = schedule_.update(key, clock_.seconds(), on_screen);
    if (levels.empty()) return;
    log_trace_settings(key);
    TraceRequest request;
    request.scene = scene_;
    request.camera = trace_camera();
    request.options.threads = settings_.threads;
    request.options.trace = trace_options();
    request.levels = std::move(levels);
    if (settings_.item_buffer && request.levels.back() == 1) {
        // From the raster pass on screen where it drew the ids for this very camera (one
        // sample a pixel): then only their read-back costs. Else a pass of their own.
        const rt::Stopwatch watch;
        // Only this member copies it, so a count of one means no trace still reads it.
        if (item_buffer_storage_.use_count() != 1)
            item_buffer_storage_ = std::make_shared<rt::ItemBuffer>();
        stats_.item_buffer_shared = raster_ids_ && raster_camera_ == request.camera;
        if (stats_.item_buffer_shared) {
            raster_fb_->start_item_buffer_read().finish(*item_buffer_storage_);
        } else {
            raster_->render_item_buffer(request.camera, *item_buffer_storage_);
            ids_camera_.reset();  // the pass drew over the item-buffer view's texture
        }
        request.item_buffer = item_buffer_storage_;
        stats_.item_buffer_ms = watch.milliseconds();
    }
    if (key.explain) raster_frames(request);
    for (int spp = 4; !key.explain && request.levels.back() == 1 && spp <= settings_.max_spp;
         spp *= 4)
        request.spp_passes.push_back(spp);
    request.id = ++request_id_;
    shown_.submitted(request_id_, key);
    tracer_.submit(std::move(request));
}

// The raster image and item buffer at each level's size, for the explain map.
void Viewer::apply_raster_settings() {
    raster_->set_msaa(settings_.msaa);
    raster_->set_shadow_maps(settings_.shadow_maps);
    raster_->set_environment_maps(settings_.environment_maps);
    raster_env_ = settings_.environment_maps;
    raster_msaa_ = settings_.msaa;
    raster_shadows_ = settings_.shadow_maps;
}

void Viewer::raster_frames(TraceRequest& request) {
    apply_raster_settings();  // the explain map compares what the raster view shows
    for (int level : request.levels) {
        const rt::Camera camera = request.camera.resized(std::max(1, request.camera.cols / level),
                                                         std::max(1, request.camera.rows / level));
        rt::gl::RasterRenderer::ForExplain r = raster_->render_for_explain(camera);
        auto frame = std::make_shared<RasterFrame>(
            RasterFrame{std::move(r.image), std::move(r.ids), std::move(r.tricks)});
        request.explain.push_back(std::move(frame));
    }
    raster_camera_.reset();  // the passes drew over the views' textures
    ids_camera_.reset();
}

void Viewer::collect_trace() {
    std::optional<TraceResult> result = tracer_.take();
    if (!result || result->id != request_id_) return;
    traced_image_ = std::move(result->image);
    traced_texture_.upload(traced_image_);
    if (result->explanation) {
        explanation_ = std::move(result->explanation);
        explain_texture_.upload(explanation_->colours);
    }
    shown_.arrived(result->id, result->level);
    shown_spp_ = result->spp;
    if (result->spp > 1) {
        std::printf("antialiased: %dx%d at %d samples per pixel in %.3f s\n", traced_image_.width,
                    traced_image_.height, result->spp, result->stats.seconds);
        std::fflush(stdout);
        update_title();
        return;
    }
    stats_.shown = result->stats;
    stats_.trace_ms.add(static_cast<float>(1e3 * result->stats.seconds));
    if (result->level == 1) {
        std::printf("traced: %dx%d in %.3f s (primary %.3f s, secondary %.3f s), %.2f Mrays/s\n",
                    traced_image_.width, traced_image_.height, result->stats.seconds,
                    result->stats.primary_seconds, result->stats.secondary_seconds,
                    result->stats.mrays_per_s());
        if (const auto& plain = result->without_item_buffer)
            std::printf(
                "item buffer: %s %.3f s, primary %.3f s instead of %.3f s, %llu of %zu pixels "
                "disagree; the frame %.3f s instead of %.3f s\n",
                stats_.item_buffer_shared ? "read back from the raster pass" : "its own pass",
                stats_.item_buffer_ms * 1e-3, result->stats.primary_seconds, plain->primary_seconds,
                static_cast<unsigned long long>(result->item_buffer_disagreements),
                traced_image_.pixels.size(), result->stats.seconds + stats_.item_buffer_ms * 1e-3,
                plain->seconds);
        std::fflush(stdout);
        stats_.full = std::move(result);
    }
    update_title();
}

View Viewer::shown_view() const {
    if (!display_.flicker) return display_.view;
    // Holding Tab alternates raster and traced four times a second.
    const auto phase = static_cast<long long>(glfwGetTime() * 4.0);
    return phase % 2 == 0 ? View::kRaster : View::kTrace;
}

bool Viewer::traced_stale() const { return shown_.stale(trace_key()); }

GLuint Viewer::raster_texture(const rt::Camera& camera) {
    const bool ids =
        settings_.item_buffer && rt::gl::RasterRenderer::shares_item_buffer_at(settings_.msaa);
    if (raster_camera_ != camera || raster_msaa_ != settings_.msaa ||
        raster_shadows_ != settings_.shadow_maps || raster_env_ != settings_.environment_maps ||
        raster_ids_ != ids) {
        apply_raster_settings();
        const rt::Stopwatch watch;
        raster_fb_ = &raster_->render_to_texture(camera, ids);
        raster_ids_ = ids;
        raster_texture_ = raster_fb_->texture();
        glFinish();  // so that the time is the GPU's too
        stats_.raster_ms = watch.milliseconds();
        stats_.raster_width = camera.cols;
        stats_.raster_height = camera.rows;
        raster_camera_ = camera;
    }
    return raster_texture_;
}

GLuint Viewer::item_buffer_texture(const rt::Camera& camera) {
    if (ids_camera_ != camera) {
        ids_fb_ = &raster_->render_item_buffer_to_texture(camera);
        ids_texture_ = ids_fb_->texture();
        ids_camera_ = camera;
    }
    return ids_texture_;
}

// The raster and item-buffer passes run again only when their camera (or the window)
// changes: at rest a frame is the composite and the panel. The difference view compares
// like with like: while the traced image is coarser than the window, the raster is drawn
// at the traced image's size (the same pixel centres), and the view says so.
void Viewer::draw_views(int width, int height) {
    rt::gl::CompositeInputs in;
    in.view = shown_view();
    in.divider = display_.divider;
    in.swap = display_.swap;
    in.diff_scale = settings_.diff_scale;
    in.diff_mode = display_.diff_mode;
    in.diff_threshold = display_.diff_threshold;
    in.traced = traced_texture_.id();
    in.explain = explain_texture_.id();
    if (in.view == View::kSplit) {
        split_inputs(in, width, height);
    } else if (in.view == View::kGpuTrace) {
        in.traced = gpu_texture(trace_camera());
    } else if (in.view != View::kTrace && in.view != View::kItemBuffer && in.view != View::kWhy) {
        const bool coarse = traced_image_.width < width || traced_image_.height < height;
        in.raster =
            raster_texture(in.view == View::kDiff && coarse
                               ? controller_->camera(traced_image_.width, traced_image_.height)
                               : controller_->camera(width, height));
    }
    if (in.view == View::kItemBuffer) {
        in.item_buffer = item_buffer_texture(controller_->camera(width, height));
        in.item_buffer_shift = ids_fb_->ids().shader_prim_bits();
    }
    if (!rays_->empty()) in.overlay = rays_->texture(*raster_, controller_->camera(width, height));
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
    compositor_->draw(in, width, height);
}

void Viewer::frame(float dt) {
    const rt::Stopwatch watch;
    const glm::ivec2 fb = window_.framebuffer_size();
    if (const std::optional<std::string> next = scenes_.take()) load(*next);
    const rt::vec3 fly = fly_direction();
    if (fly != rt::vec3(0.0f)) {
        GLFWwindow* w = window_.handle();
        const bool fast = glfwGetKey(w, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ||
                          glfwGetKey(w, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
        controller_->fly(fly, dt, fast);
    }
    update_trace();
    collect_trace();
    update_title();  // "tracing" from the frame the camera moves, not from the next level
    inspect(fb.x, fb.y);
    draw_views(fb.x, fb.y);
    if (save_requested_) {
        save_requested_ = false;
        save_view(fb.x, fb.y);
    }
    window_.begin_imgui_frame();
    if (display_.panel) draw_panel();
    draw_overlays(fb.x, fb.y);  // labels (L), light markers, messages
    if (display_.help) draw_help();
    window_.end_imgui_frame();
    release_held_keys();  // the frame has seen the clicks before them
    rt::gl::check("Viewer::frame");
    window_.swap_buffers();
    stats_.frame_ms.add(static_cast<float>(watch.milliseconds()));
}

// The loop waits for events while nothing on screen moves by itself, so that the tracer
// has the cores: a traced level (the trace job wakes the loop), a key, a click or a drag
// ends the wait at once, and a frame comes at least every kIdleWait for what changes
// with time (the progress bar, the flicker, messages, the schedule's rest). It polls
// while the camera flies or ImGui still has input queued.
void Viewer::wait_for_events() {
    if (fly_direction() != rt::vec3(0.0f) || window_.input_pending() || !held_keys_.empty())
        glfwPollEvents();
    else
        glfwWaitEventsTimeout(kIdleWait);
}

int Viewer::run() {
    update_title();
    auto last = Clock::now();
    while (!window_.should_close()) {
        const glm::ivec2 fb = window_.framebuffer_size();
        if (fb.x <= 0 || fb.y <= 0) {  // minimised: nothing to draw, nothing to trace
            glfwWaitEventsTimeout(0.1);
            last = Clock::now();
            continue;
        }
        wait_for_events();
        const auto now = Clock::now();
        frame(std::min(0.1f, std::chrono::duration<float>(now - last).count()));
        last = now;
    }
    return 0;
}

void Viewer::set_view(View view) {
    display_.view = view;
    std::printf("view: %s\n", view_label(view));
    std::fflush(stdout);
    update_title();
}

void Viewer::update_title() {
    std::string title = "rtview - " + std::filesystem::path(scenes_.current()).filename().string() +
                        " - " + view_label(display_.view);
    title += shown_.complete(trace_key()) ? " - traced" : " - tracing";
    if (title != title_) window_.set_title(title);
    title_ = title;
}

}  // namespace rt::viewer
