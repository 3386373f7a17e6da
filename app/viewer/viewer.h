#pragma once
// rtview's window: the raster view drawn live, the traced view refined on a worker
// thread, split, difference and item-buffer views, one camera for both, a Dear ImGui
// panel. The window only reads the images the tracer publishes; the tracer never knows
// about the window.

#include <array>
#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "app/gl/compositor.h"
#include "app/gl/gpu_tracer.h"
#include "app/gl/raster_renderer.h"
#include "app/gl/ray_overlay.h"
#include "app/gl/texture.h"
#include "app/gl/window.h"
#include "app/viewer/camera_controller.h"
#include "app/viewer/frame_history.h"
#include "app/viewer/keys.h"
#include "app/viewer/refinement.h"
#include "app/viewer/scene_switcher.h"
#include "app/viewer/trace_job.h"
#include "core/stopwatch.h"

struct ImDrawList;

namespace rt::viewer {

using rt::gl::View;

struct ViewerOptions {
    std::string scene;
    int width = 1280;
    int height = 720;
    View view = View::kSplit;
    std::filesystem::path save_dir = ".";
    rt::AccelKind accel = rt::AccelKind::kBvh;
    std::string up = "y";  // a bare mesh's up axis (rt::LoadOptions); the panel can change it
    int spp = 16;          // samples per pixel the traced view refines to (1: no anti-aliasing)
    int msaa = 1;          // the raster's tricks at the start (the panel switches them)
    bool shadow_maps = false;
    bool environment_maps = false;
    std::optional<int> camera;  // the first scene's glTF camera (rt::LoadOptions)
};

struct Settings {
    bool shadows = true, reflections = true, refractions = true;
    bool item_buffer = false;
    int max_depth = 5;
    float resolution_scale = 1.0f;  // of the window, for the traced image
    int threads = 0;                // 0: all cores
    int max_spp = 16;               // anti-aliasing after full resolution: 1, 4, 16 or 64
    int msaa = 1;                   // the raster's samples per pixel: 1, 2 or 4
    bool shadow_maps = false;       // the raster's shadows
    bool environment_maps = false;  // the raster's mirrors and glass
    float diff_scale = 0.5f;

    bool operator==(const Settings&) const = default;
};

// What the panel shows. Each figure belongs to something named: the raster pass to the
// camera and size it was last drawn for, the traced figures to the image on screen.
struct FrameStats {
    double raster_ms = 0.0;  // the last raster pass (drawn again only when its camera changes)
    int raster_width = 0, raster_height = 0;
    rt::RenderStats shown;            // the traced image on screen: its level's trace
    std::optional<TraceResult> full;  // the last full-resolution trace (image moved out)
    double item_buffer_ms = 0.0;      // the item buffer: its pass with read-back, or the read-back
    bool item_buffer_shared = false;  // of the ids the raster pass drew with its colours
    FrameHistory frame_ms;            // the UI thread's frames
    FrameHistory trace_ms;            // each traced level, as it arrived
    double gpu_ms = 0.0;              // the last GPU trace, dispatch to texture
    int gpu_width = 0, gpu_height = 0;
    double gpu_upload_ms = 0.0;  // the scene into the GPU tracer's buffers
};

// Which two images the split view sets side by side (left | right, before X swaps them).
enum class SplitPair { kRasterTraced, kRasterGpu, kTracedGpu };

// What is on screen and how: display only, never a reason to trace again.
struct Display {
    View view = View::kSplit;
    float divider = 0.5f;  // of the split view, as a share of the width
    bool swap = false;     // the right image on the left
    SplitPair split = SplitPair::kRasterTraced;
    bool flicker = false;  // Tab held
    bool help = false;
    bool panel = true;    // H
    bool labels = true;   // L: what each part of the view is
    bool lights = false;  // markers at the point lights
    rt::gl::DiffMode diff_mode = rt::gl::DiffMode::kHeat;
    float diff_threshold = 0.0f;  // > 0: the difference view is a mask of pixels over it
};

// A pixel whose rays are drawn in the scene (Ctrl+click, or the panel's "pick pixel").
struct Picked {
    rt::Camera camera;  // the view it was picked in, at the window's size
    int x = 0, y = 0;   // from the bottom left, as rt::Image
    rt::RayNode tree;
};

// The pixel under the cursor, set against both pipelines (the panel's inspector).
struct Inspected {
    rt::Camera camera;
    int x = 0, y = 0;  // from the bottom left
    rt::vec3 raster{0.0f}, traced{0.0f};
    std::uint32_t raster_id = 0;        // item buffer: object + 1, 0 for none
    std::uint32_t traced_object = ~0u;  // the tracer's first hit, ~0 for none
    rt::Cause cause = rt::Cause::kNone;
    rt::ExplainTerms terms;
};

// A mouse drag under way, and where the cursor is.
struct Drag {
    bool orbit = false, pan = false, divider = false;
    glm::dvec2 cursor{0.0, 0.0};
};

class Viewer {
  public:
    explicit Viewer(const ViewerOptions& options);  // throws rt::Error
    ~Viewer();
    int run();
    // Measures the viewer on each scene in turn (app/viewer/viewer_bench.cpp); 1 if one
    // failed to load or to finish tracing.
    int benchmark(const std::vector<std::string>& scenes);

    // GLFW input, forwarded by the static callbacks (app/viewer/viewer_input.cpp).
    void on_key(int key, int scancode, int action, int mods);
    void on_char(unsigned int c);
    void on_mouse_button(int button, int action);
    void on_cursor(double x, double y);
    void on_scroll(double dy);
    void on_drop(const std::string& path);

  private:
    static constexpr double kQuitSeconds = 2.0;     // the second Esc within this quits
    static constexpr double kMessageSeconds = 6.0;  // how long "saved: ..." stays
    static constexpr double kIdleWait = 0.1;        // the longest wait for events
    // Keys and text that came after a click no ImGui frame has seen: they wait for that
    // frame, and go to the viewer or to a text field as its end leaves the editing.
    struct HeldKey {
        bool text = false;
        int key = 0, scancode = 0, action = 0, mods = 0;
        unsigned int c = 0;
    };
    void route_key(int key, int scancode, int action, int mods);
    void route_char(unsigned int c);
    void release_held_keys();
    std::vector<HeldKey> held_keys_;
    void on_escape();
    void quit(const char* how);
    bool load(const std::string& path);  // on failure: false, error_ set, current scene kept
    void install(std::shared_ptr<const rt::Scene> scene,
                 const std::string& path);  // GL upload, camera, restart
    void perform(Action action);
    void frame(float dt);
    void wait_for_events();
    rt::vec3 fly_direction() const;
    double timed_frame(bool wait);  // events (waited for, or polled) and a frame: its ms
    bool frames_until_traced(std::vector<double>& frames);
    void update_trace();
    TraceKey trace_key() const;
    void log_trace_settings(const TraceKey& key);
    void collect_trace();
    void draw_views(int width, int height);
    // The GPU tracer (app/viewer/viewer_gpu.cpp): made once, if the context can.
    void init_gpu();
    GLuint gpu_texture(const rt::Camera& camera);  // traced again for a new camera or settings
    bool gpu_on_screen(View view) const;
    void split_inputs(rt::gl::CompositeInputs& in, int width, int height);
    std::string split_side_label(bool right) const;
    void draw_gpu_statistics();
    GLuint raster_texture(const rt::Camera& camera);  // drawn again only for a new camera
    GLuint item_buffer_texture(const rt::Camera& camera);
    bool traced_stale() const;  // the traced image on screen is of another camera or settings
    void draw_panel();
    void draw_open_field();
    void draw_diff_controls();
    void draw_statistics();
    void draw_item_legend();
    rt::TraceOptions trace_options() const;
    void pick(double cursor_x, double cursor_y);
    void trace_picked();
    void clear_picked();
    void draw_picked();
    void inspect(int width, int height);
    void draw_inspector();
    void draw_why_legend();
    void raster_frames(TraceRequest& request);
    void draw_raster_legend();
    void draw_light_markers(ImDrawList* draw, int width, int height, float scale);
    std::string traced_label() const;
    std::string raster_label() const;
    std::string diff_label(int width) const;
    void keep_panel_inside();
    void draw_overlays(int width, int height);
    void draw_help();
    void save_view(int width, int height);
    void set_view(View view);
    void update_title();
    rt::Camera trace_camera() const;
    View shown_view() const;

    ViewerOptions options_;
    std::shared_ptr<const rt::Scene> first_scene_;  // read before the window opens
    rt::gl::Window window_;
    std::unique_ptr<rt::gl::Compositor> compositor_;
    std::shared_ptr<const rt::Scene> scene_;
    std::unique_ptr<rt::gl::RasterRenderer> raster_;
    std::unique_ptr<CameraController> controller_;
    SceneSwitcher scenes_;  // what is shown, what to show next
    TraceJob tracer_;
    rt::gl::Texture traced_texture_;
    rt::Image traced_image_;  // what traced_texture_ holds
    // The last item buffer handed to the tracer, read into again once the tracer has let
    // it go (fresh pages cost more than reading the ids: Image::resize).
    std::shared_ptr<rt::ItemBuffer> item_buffer_storage_;
    rt::gl::Texture explain_texture_;
    std::unique_ptr<rt::gl::GpuTracer> gpu_;  // none where the context has no compute shaders
    std::string gpu_unavailable_;             // why not
    rt::gl::Texture gpu_texture_;
    std::optional<rt::Camera> gpu_camera_;  // what gpu_texture_ holds
    rt::TraceOptions gpu_options_;
    std::uint64_t scene_serial_ = 0, gpu_serial_ = 0;  // installed scenes; the one uploaded
    std::unique_ptr<rt::gl::RayOverlay> rays_;
    std::optional<Picked> picked_;
    bool pick_mode_ = false;  // the next left click picks
    std::optional<Inspected> inspected_;
    std::uint64_t inspect_camera_version_ = 0;        // the camera of the last frame inspect() saw
    const rt::gl::Framebuffer* raster_fb_ = nullptr;  // holding raster_texture_
    const rt::gl::Framebuffer* ids_fb_ = nullptr;     // holding ids_texture_
    std::shared_ptr<const Explanation> explanation_;  // what explain_texture_ holds
    // Trace in parts for the why view: on from when it is shown until the camera or a
    // setting changes with another view shown (a view change alone never retraces).
    bool explain_ = false;

    Settings settings_;
    RefinementSchedule schedule_;
    std::optional<TraceKey> logged_settings_;
    rt::Stopwatch clock_;  // the viewer's time, for the schedule
    std::uint64_t request_id_ = 0;
    ShownTrace shown_;   // what the traced image on screen belongs to
    int shown_spp_ = 1;  // its samples per pixel
    FrameStats stats_;
    std::optional<rt::Camera> raster_camera_, ids_camera_;  // what the textures hold
    int raster_msaa_ = 1;                                   // and with how many samples
    bool raster_shadows_ = false;                           // and shadow maps or not
    bool raster_env_ = false;                               // and environment maps or not
    bool raster_ids_ = false;                               // and the item buffer with it
    void apply_raster_settings();
    int max_msaa_ = 1;  // what the context offers
    GLuint raster_texture_ = 0, ids_texture_ = 0;

    Display display_;
    std::optional<rt::Stopwatch> quit_asked_;  // since the first Esc
    glm::vec2 panel_pos_{10.0f, 10.0f};        // where the panel belongs (the user's, once moved)
    bool panel_small_ = false;                 // collapsed because the window is small
    bool save_requested_ = false;
    std::string saved_;  // what the last save wrote, shown for a while
    std::optional<rt::Stopwatch> saved_at_;
    std::string error_;
    std::array<char, 1024> open_path_{};        // the panel's path field
    std::vector<std::string> open_candidates_;  // its Tab completions
    std::string title_;
    Drag drag_;
};

}  // namespace rt::viewer
