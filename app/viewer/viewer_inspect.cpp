// Looking at one pixel: its rays picked and drawn in the scene (Ctrl+click), and the
// pixel under the cursor set against both pipelines (the inspector).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "app/viewer/panel_widgets.h"
#include "app/viewer/viewer.h"
// GL's loader (through viewer.h) before GLFW.
#include <GLFW/glfw3.h>
#include <imgui.h>

namespace rt::viewer {
namespace {

// From window (cursor) coordinates to a pixel of a framebuffer-sized camera, bottom row 0.
std::optional<glm::ivec2> cursor_pixel(GLFWwindow* window, double cx, double cy, int width,
                                       int height) {
    int w = 1, h = 1;
    glfwGetWindowSize(window, &w, &h);
    const int x = static_cast<int>(cx * width / std::max(1, w));
    const int y = height - 1 - static_cast<int>(cy * height / std::max(1, h));
    if (cx < 0.0 || cy < 0.0 || x < 0 || y < 0 || x >= width || y >= height) return std::nullopt;
    return glm::ivec2(x, y);
}

std::string rgb8(const rt::vec3& c) {
    char s[48];
    // The bytes a PNG of the frame holds (a NaN gives 0, where a cast of NaN was undefined).
    std::snprintf(s, sizeof s, "%3d %3d %3d", rt::srgb8(c.x), rt::srgb8(c.y), rt::srgb8(c.z));
    return s;
}

}  // namespace

rt::TraceOptions Viewer::trace_options() const {
    rt::TraceOptions o;
    o.shadows = settings_.shadows;
    o.reflections = settings_.reflections;
    o.refractions = settings_.refractions;
    o.max_depth = settings_.max_depth;
    return o;
}

void Viewer::pick(double cursor_x, double cursor_y) {
    pick_mode_ = false;
    const glm::ivec2 fb = window_.framebuffer_size();
    const std::optional<glm::ivec2> p =
        cursor_pixel(window_.handle(), cursor_x, cursor_y, fb.x, fb.y);
    if (!p) return;
    picked_ = Picked{controller_->camera(fb.x, fb.y), p->x, p->y, {}};
    trace_picked();
}

// Traces the picked pixel with the current settings and hands its rays to the overlay.
void Viewer::trace_picked() {
    Picked& p = *picked_;
    p.tree = rt::trace_ray_tree(*scene_, p.camera, trace_options(), p.x, p.y);
    const rt::Aabb box = scene_->bounds();
    const float extent = box.empty() ? 10.0f : glm::length(box.hi - box.lo);
    rays_->set(rt::ray_segments(p.tree, scene_->lights, std::max(1.0f, 0.5f * extent)));
    std::size_t rays = 0;
    const auto count = [&](const auto& self, const rt::RayNode& n) -> void {
        ++rays;
        for (const rt::RayNode& c : n.children) self(self, c);
    };
    count(count, p.tree);
    const int bounces = rt::bounce_depth(p.tree);
    std::printf("picked: pixel %d,%d (from the top left): %zu rays, %d bounce%s, colour %s\n", p.x,
                p.camera.rows - 1 - p.y, rays, bounces, bounces == 1 ? "" : "s",
                rgb8(p.tree.colour).c_str());
    std::fflush(stdout);
}

void Viewer::clear_picked() {
    picked_.reset();
    pick_mode_ = false;
    if (rays_) rays_->clear();
}

// The panel's tree: one line a ray, children folded under their parent.
void Viewer::draw_picked() {
    section("rays of a pixel");
    if (ImGui::Button(pick_mode_ ? "click a pixel..." : "pick pixel (Ctrl+click)"))
        pick_mode_ = !pick_mode_;
    if (picked_) {
        ImGui::SameLine();
        if (ImGui::Button("clear (Esc)")) clear_picked();
    }
    if (!picked_) return;
    ImGui::TextDisabled(
        "pixel %d,%d: white primary, orange shadow (dim: blocked), blue "
        "reflection, green refraction",
        picked_->x, picked_->camera.rows - 1 - picked_->y);
    const auto node = [&](const auto& self, const rt::RayNode& n) -> void {
        char line[256];
        if (n.kind == rt::RayKind::kShadow) {
            std::snprintf(line, sizeof line, "shadow to light %d: %s%s", n.light,
                          n.blocked ? "blocked by " : "clear",
                          n.blocker ? ("\"" + n.blocker->name + "\"").c_str() : "");
        } else if (n.hit) {
            std::snprintf(line, sizeof line, "%s: \"%s\" t=%.4g  w=%.3g  colour %s",
                          rt::ray_kind_name(n.kind), n.hit->name.c_str(), n.hit->t, n.weight,
                          rgb8(n.colour).c_str());
        } else {
            std::snprintf(line, sizeof line, "%s: miss  w=%.3g  background %s",
                          rt::ray_kind_name(n.kind), n.weight, rgb8(n.colour).c_str());
        }
        const ImGuiTreeNodeFlags flags =
            ImGuiTreeNodeFlags_DefaultOpen | (n.children.empty() ? ImGuiTreeNodeFlags_Leaf : 0);
        if (ImGui::TreeNodeEx(&n, flags, "%s", line)) {
            for (const rt::RayNode& c : n.children) self(self, c);
            ImGui::TreePop();
        }
    };
    ImGui::BeginChild("tree", ImVec2(420.0f, 160.0f), true, ImGuiWindowFlags_HorizontalScrollbar);
    node(node, picked_->tree);
    ImGui::EndChild();
}

// The pixel under the cursor, when it or the camera changed and no drag is under way: one
// pixel read back from each raster pass (drawn again only for a new camera) and one ray
// traced in parts; nothing while the camera moves (a drag, or flying with the keys: the
// camera changed since the last frame).
void Viewer::inspect(int width, int height) {
    const std::uint64_t version = controller_->version();
    const bool moving = version != std::exchange(inspect_camera_version_, version);
    if (!display_.panel || moving || drag_.orbit || drag_.pan || drag_.divider) return;
    const std::optional<glm::ivec2> p =
        cursor_pixel(window_.handle(), drag_.cursor.x, drag_.cursor.y, width, height);
    if (!p || ImGui::GetIO().WantCaptureMouse) return;
    const rt::Camera camera = controller_->camera(width, height);
    if (inspected_ && inspected_->camera == camera && inspected_->x == p->x &&
        inspected_->y == p->y)
        return;
    Inspected in;
    in.camera = camera;
    in.x = p->x;
    in.y = p->y;
    raster_texture(camera);
    item_buffer_texture(camera);
    in.raster = raster_fb_->read_pixel(p->x, p->y);
    in.raster_id = ids_fb_->read_id(p->x, p->y);
    rt::RayCounts counts;
    const rt::PrimaryParts parts =
        rt::Tracer(*scene_, trace_options()).trace_parts(camera.ray(p->x, p->y), counts);
    in.traced = parts.colour();
    in.traced_object = parts.object;
    in.terms = rt::explain_terms(parts, in.raster, in.raster_id);
    float shown = 0.0f;  // the displayed difference, as the explain map measures it
    for (int k = 0; k < 3; ++k)
        shown = std::max(shown,
                         std::abs(rt::srgb_encode(in.traced[k]) - rt::srgb_encode(in.raster[k])));
    in.cause = rt::cause_of(in.terms, shown);
    inspected_ = in;
}

void Viewer::draw_inspector() {
    section("pixel under the cursor");
    if (!inspected_) {
        ImGui::TextDisabled("hover over the view");
        return;
    }
    const Inspected& in = *inspected_;
    const auto name = [&](std::uint32_t object) {
        return object < scene_->objects.size() ? "\"" + scene_->objects[object].name + "\""
                                               : std::string("nothing");
    };
    ImGui::Text("pixel %d,%d   object %s", in.x, in.camera.rows - 1 - in.y,
                name(in.traced_object).c_str());
    if (in.raster_id != (in.traced_object == ~0u ? 0u : in.traced_object + 1))
        ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.3f, 1.0f), "the raster sees %s here",
                           name(in.raster_id - 1).c_str());
    ImGui::Text("raster  %s   traced %s   (sRGB)", rgb8(in.raster).c_str(),
                rgb8(in.traced).c_str());
    const rt::vec3 d = in.traced - in.raster;
    ImGui::Text("traced - raster  %+.3f %+.3f %+.3f (linear)", d.x, d.y, d.z);
    ImGui::ColorButton("##cause", imgui_colour(rt::cause_colour(in.cause)),
                       ImGuiColorEditFlags_NoTooltip | ImGuiColorEditFlags_NoPicker,
                       ImVec2(12.0f, 12.0f));
    ImGui::SameLine();
    ImGui::Text("cause: %s", rt::name_of(rt::kCauseNames, in.cause));
}

}  // namespace rt::viewer
