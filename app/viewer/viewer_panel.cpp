// The Dear ImGui side of the viewer: the panel, the labels over the views, the keys.
#include <algorithm>
#include <cstdlib>
#include <thread>

#include <imgui.h>

#include "app/viewer/keys.h"
#include "app/viewer/viewer.h"
#include "app/viewer/views.h"
#include "core/compare.h"
#include "core/scene_loader.h"

namespace rt::viewer {
namespace {

ImU32 heat_u32(float t) {
    const rt::vec3 c = rt::heat_colour(t);
    return ImGui::GetColorU32(
        ImVec4(rt::srgb_encode(c.x), rt::srgb_encode(c.y), rt::srgb_encode(c.z), 1.0f));
}

void section(const char* title) {
    ImGui::Separator();
    ImGui::TextDisabled("%s", title);
}

void label(ImDrawList* draw, ImVec2 at, const char* text) {
    const ImVec2 size = ImGui::CalcTextSize(text);
    draw->AddRectFilled(ImVec2(at.x - 4, at.y - 2), ImVec2(at.x + size.x + 4, at.y + size.y + 2),
                        IM_COL32(0, 0, 0, 170), 4.0f);
    draw->AddText(at, IM_COL32(255, 255, 255, 255), text);
}

}  // namespace

// The panel stays inside the window: where the user put it while the window has room
// for it, back there when the window grows again after a shrink (to 1 x 1, say), and
// collapsed (to its title bar) while the window is too small to show it beside the image.
void Viewer::keep_panel_inside() {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    const bool room = display.x >= size.x && display.y >= size.y;
    const bool inside = pos.x >= 0.0f && pos.y >= 0.0f && pos.x + size.x <= display.x &&
                        pos.y + size.y <= display.y;
    if (room && inside) {
        panel_pos_ = {pos.x, pos.y};
    } else if (room) {
        ImGui::SetWindowPos(ImVec2(std::clamp(panel_pos_.x, 0.0f, display.x - size.x),
                                   std::clamp(panel_pos_.y, 0.0f, display.y - size.y)));
    }
}

void Viewer::draw_panel() {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const bool small = display.x < 700.0f || display.y < 450.0f;
    if (small != panel_small_) ImGui::SetNextWindowCollapsed(small, ImGuiCond_Always);
    panel_small_ = small;
    ImGui::SetNextWindowPos(ImVec2(panel_pos_.x, panel_pos_.y), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(310, 0), ImGuiCond_FirstUseEver);
    ImGui::Begin("rtview", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    keep_panel_inside();

    const std::filesystem::path shown = scenes_.current();
    const std::string current = shown.filename().string();
    if (ImGui::BeginCombo("scene", current.c_str())) {
        for (const auto& path : scenes_.scenes())
            if (ImGui::Selectable(path.filename().string().c_str(), path.filename() == current))
                scenes_.pick(path);
        ImGui::EndCombo();
    }
    ImGui::TextDisabled("or drop a .json or .obj on the window");
    if (shown.extension() == ".obj") {
        // A bare mesh from a Z-up tool (scans, CAD) is seen from the top: turn it.
        if (ImGui::BeginCombo("up axis", options_.up.c_str())) {
            for (const char* axis : rt::kUpAxes)
                if (ImGui::Selectable(axis, options_.up == axis) && options_.up != axis) {
                    options_.up = axis;
                    scenes_.reload();  // read again with the new axis, next frame
                }
            ImGui::EndCombo();
        }
    }
    // The ray tracer's settings come first: their place does not move with the view.
    if (!error_.empty()) {  // wrapped at the panel's width, however long the message
        ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + 290.0f);
        ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "%s", error_.c_str());
        ImGui::PopTextWrapPos();
    }

    section("ray tracer");
    ImGui::Checkbox("shadows", &settings_.shadows);
    ImGui::SameLine();
    ImGui::Checkbox("reflection", &settings_.reflections);
    ImGui::SameLine();
    ImGui::Checkbox("refraction", &settings_.refractions);
    ImGui::Checkbox("item buffer (primary hits from OpenGL)", &settings_.item_buffer);
    // Every slider clamps what is typed into it (Ctrl+click) to its range, too.
    constexpr ImGuiSliderFlags kClamp = ImGuiSliderFlags_AlwaysClamp;
    ImGui::SliderInt("max depth", &settings_.max_depth, 0, 12, "%d", kClamp);
    ImGui::SliderFloat("resolution", &settings_.resolution_scale, 0.1f, 1.0f, "%.2f x window",
                       kClamp);
    const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    int threads = settings_.threads > 0 ? settings_.threads : cores;
    if (ImGui::SliderInt("threads", &threads, 1, std::max(cores, 16), "%d", kClamp))
        settings_.threads = threads;

    section("view");
    for (std::size_t i = 0; i < kViewCount; ++i) {
        const std::string label = std::to_string(i + 1) + " " + kViews[i].label;
        if (ImGui::RadioButton(label.c_str(), display_.view == kViews[i].value))
            set_view(kViews[i].value);
        if (i % 3 != 2 && i + 1 != kViewCount) ImGui::SameLine();
    }
    if (display_.view == View::kSplit) {
        ImGui::Checkbox("swap sides (X)", &display_.swap);
        ImGui::SliderFloat("divider", &display_.divider, 0.0f, 1.0f, "%.3f", kClamp);
    }
    if (display_.view == View::kDiff)
        ImGui::SliderFloat("diff scale", &settings_.diff_scale, 0.01f, 1.0f, "%.3f", kClamp);

    section("statistics");
    ImGui::Text("raster: %.1f ms", stats_.raster_ms);
    if (tracer_.busy()) ImGui::ProgressBar(tracer_.progress(), ImVec2(-1, 0), "tracing");
    ImGui::Text("traced image: 1/%d resolution", std::max(1, stats_.level));
    if (stats_.full) {
        const rt::RenderStats& s = stats_.full->stats;
        ImGui::Text("trace: %.1f ms (primary %.1f, secondary %.1f)", 1e3 * s.seconds,
                    1e3 * s.primary_seconds, 1e3 * s.secondary_seconds);
        ImGui::Text("%.2f Mrays/s on %d threads", s.mrays_per_s(), s.threads);
        if (const auto& plain = stats_.full->without_item_buffer) {
            const double saved =
                1e3 * (plain->primary_seconds - s.primary_seconds) - stats_.item_buffer_ms;
            ImGui::Text("item buffer: pass %.1f ms, primary %.1f -> %.1f ms", stats_.item_buffer_ms,
                        1e3 * plain->primary_seconds, 1e3 * s.primary_seconds);
            ImGui::TextColored(
                saved >= 0 ? ImVec4(0.5f, 1.0f, 0.5f, 1.0f) : ImVec4(1.0f, 0.6f, 0.4f, 1.0f),
                "net %s %.1f ms", saved >= 0 ? "saving" : "loss", std::abs(saved));
            const double pixels = static_cast<double>(stats_.full->stats.rays.primary);
            ImGui::Text("%llu pixels disagree (%.4f%%), %llu fell back",
                        static_cast<unsigned long long>(stats_.full->item_buffer_disagreements),
                        100.0 * static_cast<double>(stats_.full->item_buffer_disagreements) /
                            std::max(1.0, pixels),
                        static_cast<unsigned long long>(s.item_buffer_fallbacks));
        }
    }
    ImGui::Separator();
    for (const Action a : {Action::kResetCamera, Action::kSave, Action::kHelp}) {
        if (a != Action::kResetCamera) ImGui::SameLine();
        if (ImGui::Button(with_keys(a).c_str())) perform(a);
    }
    ImGui::End();
}

void Viewer::draw_overlays(int width, int height) {
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    const float scale =
        static_cast<float>(ImGui::GetIO().DisplaySize.x) / static_cast<float>(std::max(1, width));
    const float w = static_cast<float>(width) * scale, h = static_cast<float>(height) * scale;
    if (quit_asked_ && quit_asked_->seconds() < kQuitSeconds)
        label(ImGui::GetForegroundDrawList(), ImVec2(w * 0.5f - 150.0f, h * 0.5f),
              "Press Esc again to quit (Ctrl+Q quits at once)");
    const View view = shown_view();
    if (view == View::kSplit) {
        const float x = display_.divider * w;
        label(draw, ImVec2(x - 110.0f, h - 30.0f), display_.swap ? "ray traced" : "OpenGL");
        label(draw, ImVec2(x + 12.0f, h - 30.0f), display_.swap ? "OpenGL" : "ray traced");
    } else if (view == View::kDiff) {
        // The colour map and its scale, down the right-hand side.
        const float x0 = w - 40.0f, y0 = 40.0f, y1 = h - 40.0f;
        for (int i = 0; i < 64; ++i) {
            const float a = y1 - (y1 - y0) * static_cast<float>(i) / 64.0f,
                        b = y1 - (y1 - y0) * static_cast<float>(i + 1) / 64.0f;
            draw->AddRectFilled(ImVec2(x0, b), ImVec2(x0 + 16.0f, a),
                                heat_u32((static_cast<float>(i) + 0.5f) / 64.0f));
        }
        char top[32];
        std::snprintf(top, sizeof top, "%.2f", settings_.diff_scale);
        label(draw, ImVec2(x0 - 40.0f, y0 - 8.0f), top);
        label(draw, ImVec2(x0 - 22.0f, y1 - 8.0f), "0");
        label(draw, ImVec2(w * 0.5f - 120.0f, h - 30.0f), "|raster - traced|, sRGB");
    } else {
        const char* names[] = {"OpenGL", "ray traced", "", "", "item buffer (object ids)"};
        label(draw, ImVec2(w * 0.5f - 40.0f, h - 30.0f), names[static_cast<int>(view)]);
    }
}

void Viewer::draw_help() {
    const ImVec2 screen = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(screen.x * 0.5f, screen.y * 0.5f), ImGuiCond_Always,
                            ImVec2(0.5f, 0.5f));
    ImGui::Begin("keys", &display_.help,
                 ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse);
    std::string view_keys, view_labels;
    for (std::size_t i = 0; i < kViewCount; ++i) {
        view_keys += (i ? " " : "") + std::to_string(i + 1);
        view_labels += (i ? ", " : "") + std::string(kViews[i].label);
    }
    const auto row = [](const char* keys, const char* what) {
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(keys);
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(what);
    };
    if (ImGui::BeginTable("keys", 2)) {
        row(view_keys.c_str(), view_labels.c_str());
        for (const Control& c : kControls) row(c.keys, c.what);
        ImGui::EndTable();
    }
    ImGui::End();
}

}  // namespace rt::viewer
