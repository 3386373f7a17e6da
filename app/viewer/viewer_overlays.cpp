// What is drawn over the view: labels naming each part (L), the difference view's scale,
// light markers, and messages (saved files, the quit prompt). Labels stay when the panel
// is hidden (H); L hides them for a clean view.
#include <algorithm>
#include <cstdio>
#include <string>

#include <imgui.h>
#include <glm/geometric.hpp>

#include "app/viewer/panel_widgets.h"
#include "app/viewer/viewer.h"
#include "app/viewer/views.h"

namespace rt::viewer {
namespace {

ImU32 heat_u32(float t) { return ImGui::GetColorU32(imgui_colour(rt::heat_colour(t))); }

// The colour bar of the difference view, down the right-hand side.
void diff_scale_bar(ImDrawList* draw, float w, float h, rt::gl::DiffMode mode, float scale) {
    const float x0 = w - 40.0f, y0 = 40.0f, y1 = h - 40.0f;
    for (int i = 0; i < 64; ++i) {
        const float t = (static_cast<float>(i) + 0.5f) / 64.0f;
        const float a = y1 - (y1 - y0) * static_cast<float>(i) / 64.0f,
                    b = y1 - (y1 - y0) * static_cast<float>(i + 1) / 64.0f;
        ImU32 c = heat_u32(t);
        if (mode == rt::gl::DiffMode::kSigned) {  // bottom: traced brighter, top: raster
            const float l = 2.0f * t - 1.0f;
            c = l > 0.0f ? ImGui::GetColorU32(ImVec4(l, 0.25f * l, 0.15f * l, 1.0f))
                         : ImGui::GetColorU32(ImVec4(-0.2f * l, -0.5f * l, -l, 1.0f));
        } else if (mode == rt::gl::DiffMode::kChannels) {
            c = ImGui::GetColorU32(ImVec4(t, t, t, 1.0f));
        }
        draw->AddRectFilled(ImVec2(x0, b), ImVec2(x0 + 16.0f, a), c);
    }
    char top[32], bottom[32];
    std::snprintf(top, sizeof top, "%s%.2f", mode == rt::gl::DiffMode::kSigned ? "+" : "", scale);
    std::snprintf(bottom, sizeof bottom, "%s", mode == rt::gl::DiffMode::kSigned ? "-" : "0");
    if (mode == rt::gl::DiffMode::kSigned) std::snprintf(bottom, sizeof bottom, "-%.2f", scale);
    label(draw, ImVec2(x0 - 48.0f, y0 - 8.0f), top);
    label(draw, ImVec2(x0 - 48.0f, y1 - 8.0f), bottom);
}

}  // namespace

std::string Viewer::raster_label() const {
    std::string text = "OpenGL";
    if (settings_.shadow_maps) text += ", shadow maps";
    if (settings_.environment_maps) text += ", env maps";
    if (settings_.msaa > 1) text += ", " + std::to_string(settings_.msaa) + "x MSAA";
    return text;
}

std::string Viewer::traced_label() const {
    std::string text = "ray traced";
    if (shown_.level() > 1) text += ", 1/" + std::to_string(shown_.level()) + " resolution";
    if (shown_.level() == 1 && shown_spp_ > 1)
        text += ", " + std::to_string(shown_spp_) + " samples per pixel";
    if (shown_.level() == 1 && shown_spp_ < settings_.max_spp && !traced_stale() && !explain_)
        text += " (anti-aliasing...)";
    if (traced_stale()) text += " - tracing... (this image is from before the last change)";
    return text;
}

std::string Viewer::diff_label(int width) const {
    static const char* const kModes[] = {"|raster - traced|, largest channel",
                                         "raster - traced, luminance (red: raster brighter)",
                                         "|raster - traced| per channel"};
    std::string text = kModes[static_cast<int>(display_.diff_mode)];
    if (display_.diff_threshold > 0.0f) {
        char mask[96];
        std::snprintf(mask, sizeof mask, "white: a channel differs by more than %.1f/255",
                      255.0f * display_.diff_threshold);
        text = mask;
    }
    text += ", sRGB";
    if (traced_image_.width < width)
        text += "; at the traced image's 1/" + std::to_string(std::max(1, shown_.level())) +
                " resolution (the raster drawn at that size)";
    if (traced_stale()) text += " - tracing...";
    return text;
}

void Viewer::draw_light_markers(ImDrawList* draw, int width, int height, float scale) {
    const rt::Camera cam = controller_->camera(width, height);
    int index = 0;
    for (const rt::Light& light : scene_->lights) {
        ++index;
        if (light.type != rt::Light::Type::kPoint) continue;
        const rt::vec3 rel = light.position - cam.eye;
        const float depth = -glm::dot(rel, cam.n);
        if (depth <= 0.0f) continue;  // behind the camera
        const float sx = glm::dot(rel, cam.u) * cam.N / depth / cam.W;
        const float sy = glm::dot(rel, cam.v) * cam.N / depth / cam.H;
        const ImVec2 at(0.5f * (sx + 1.0f) * static_cast<float>(width) * scale,
                        (1.0f - 0.5f * (sy + 1.0f)) * static_cast<float>(height) * scale);
        draw->AddCircleFilled(at, 7.0f, IM_COL32(255, 220, 60, 230));
        draw->AddCircle(at, 8.0f, IM_COL32(0, 0, 0, 230), 0, 2.0f);
        const std::string text = "light " + std::to_string(index);
        label(draw, ImVec2(at.x + 11.0f, at.y - 7.0f), text.c_str());
    }
}

void Viewer::draw_overlays(int width, int height) {
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    ImDrawList* front = ImGui::GetForegroundDrawList();
    const float scale =
        static_cast<float>(ImGui::GetIO().DisplaySize.x) / static_cast<float>(std::max(1, width));
    const float w = static_cast<float>(width) * scale, h = static_cast<float>(height) * scale;
    if (quit_asked_ && quit_asked_->seconds() < kQuitSeconds)
        label(front, ImVec2(w * 0.5f - 150.0f, h * 0.5f),
              "Press Esc again to quit (Ctrl+Q quits at once)");
    if (saved_at_ && saved_at_->seconds() < kMessageSeconds)
        label(front, ImVec2(w * 0.5f - 200.0f, h * 0.5f - 60.0f), saved_.c_str());
    if (display_.lights) draw_light_markers(draw, width, height, scale);
    if (!display_.labels) return;
    const View view = shown_view();
    const std::string traced = traced_label();
    if (view == View::kSplit) {
        const float x = display_.divider * w;
        const std::string first = split_side_label(false), second = split_side_label(true);
        const char* left = display_.swap ? second.c_str() : first.c_str();
        const char* right = display_.swap ? first.c_str() : second.c_str();
        label(draw, ImVec2(x - ImGui::CalcTextSize(left).x - 12.0f, h - 30.0f), left);
        label(draw, ImVec2(x + 12.0f, h - 30.0f), right);
    } else if (view == View::kDiff) {
        if (display_.diff_threshold <= 0.0f)
            diff_scale_bar(draw, w, h, display_.diff_mode, settings_.diff_scale);
        const std::string text = diff_label(width);
        label(draw, ImVec2(w * 0.5f - 0.5f * ImGui::CalcTextSize(text.c_str()).x, h - 30.0f),
              text.c_str());
    } else {
        const std::string text =
            view == View::kRaster  ? raster_label()
            : view == View::kTrace ? traced
            : view == View::kGpuTrace
                ? "GPU traced (" + std::to_string(stats_.gpu_width) + "x" +
                      std::to_string(stats_.gpu_height) + ", " +
                      std::to_string(static_cast<int>(stats_.gpu_ms + 0.5)) + " ms)"
            : view == View::kItemBuffer ? std::string("item buffer (object ids)")
            : traced_stale() || !explanation_
                ? std::string("why they differ - tracing...")
                : "why they differ: each pixel's largest term" +
                      (shown_.level() > 1 ? ", 1/" + std::to_string(shown_.level()) + " resolution"
                                          : std::string());
        label(draw, ImVec2(w * 0.5f - 0.5f * ImGui::CalcTextSize(text.c_str()).x, h - 30.0f),
              text.c_str());
    }
}

}  // namespace rt::viewer
