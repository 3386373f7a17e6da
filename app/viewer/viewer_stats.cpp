// The panel's statistics and legends. Every figure says what it belongs to: the raster
// pass to the camera and size it was drawn for, the traced figures to the image on
// screen (and the full-resolution breakdown only while that image is on screen).
#include <algorithm>
#include <cmath>

#include <imgui.h>

#include "app/viewer/panel_widgets.h"
#include "app/viewer/viewer.h"

namespace rt::viewer {
namespace {

void plot(const char* id, const FrameHistory& history, const char* what) {
    const std::vector<float> values = history.values();
    char overlay[96];
    std::snprintf(overlay, sizeof overlay, "%s: median %.1f ms, max %.1f", what, history.median(),
                  history.max());
    ImGui::PlotLines(id, values.data(), static_cast<int>(values.size()), 0, overlay, 0.0f,
                     std::max(50.0f, 1.1f * history.max()), ImVec2(300.0f, 42.0f));
}

}  // namespace

void Viewer::draw_statistics() {
    section("statistics");
    plot("##frames", stats_.frame_ms, "UI frame");
    if (stats_.raster_width > 0)
        ImGui::Text("raster pass: %.1f ms at %dx%d", stats_.raster_ms, stats_.raster_width,
                    stats_.raster_height);
    else
        ImGui::TextDisabled("raster pass: not drawn in this view yet");
    ImGui::TextDisabled("(drawn again only when the camera or the size changes)");
    draw_gpu_statistics();
    if (tracer_.busy()) ImGui::ProgressBar(tracer_.progress(), ImVec2(-1, 0), "tracing");
    if (shown_.level() == 0) {
        ImGui::TextDisabled("traced image: none yet");
        return;
    }
    const bool stale = traced_stale();
    if (stale)
        ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f),
                           "traced image: of the camera or settings before the last change");
    ImGui::Text("traced image: 1/%d resolution, %dx%d, %.1f ms", shown_.level(),
                traced_image_.width, traced_image_.height, 1e3 * stats_.shown.seconds);
    if (stats_.trace_ms.size() > 1) plot("##traces", stats_.trace_ms, "traced levels");
    if (shown_.level() != 1 || stale || !stats_.full) {
        ImGui::TextDisabled("full-resolution figures once the trace reaches 1/1");
        return;
    }
    const rt::RenderStats& s = stats_.full->stats;
    ImGui::Text("full trace: %.1f ms (primary %.1f, secondary %.1f)", 1e3 * s.seconds,
                1e3 * s.primary_seconds, 1e3 * s.secondary_seconds);
    ImGui::Text("%.2f Mrays/s on %d threads", s.mrays_per_s(), s.threads);
    const auto& plain = stats_.full->without_item_buffer;
    if (!plain) return;
    const double saved = 1e3 * (plain->primary_seconds - s.primary_seconds) - stats_.item_buffer_ms;
    ImGui::Text("item buffer: %s %.1f ms, primary %.1f -> %.1f ms",
                stats_.item_buffer_shared ? "read back from the raster pass" : "its own pass",
                stats_.item_buffer_ms, 1e3 * plain->primary_seconds, 1e3 * s.primary_seconds);
    // As rtbench --item-buffer's "net on the frame": the trace without it against the
    // item buffer's own cost plus the trace with it.
    const double frame = s.seconds + 1e-3 * stats_.item_buffer_ms;
    ImGui::TextColored(saved >= 0 ? ImVec4(0.5f, 1.0f, 0.5f, 1.0f) : ImVec4(1.0f, 0.6f, 0.4f, 1.0f),
                       "net %s %.1f ms: the frame %.1f -> %.1f ms, %.2fx",
                       saved >= 0 ? "saving" : "loss", std::abs(saved), 1e3 * plain->seconds,
                       1e3 * frame, frame > 0.0 ? plain->seconds / frame : 0.0);
    const double pixels = static_cast<double>(s.rays.primary);
    ImGui::Text(
        "%llu pixels disagree (%.4f%%), %llu on edges",
        static_cast<unsigned long long>(stats_.full->item_buffer_disagreements),
        100.0 * static_cast<double>(stats_.full->item_buffer_disagreements) / std::max(1.0, pixels),
        static_cast<unsigned long long>(s.item_buffer_fallbacks));
}

// The item-buffer view's colours: which object each is (the first ones; the colour is
// the object's index + 1 through core's item_colour).
void Viewer::draw_item_legend() {
    constexpr std::size_t kListed = 16;
    const std::size_t n = scene_->objects.size();
    for (std::size_t i = 0; i < std::min(n, kListed); ++i) {
        const rt::vec3 c = rt::item_colour(static_cast<std::uint32_t>(i + 1));
        ImGui::ColorButton("##item", imgui_colour(c),
                           ImGuiColorEditFlags_NoTooltip | ImGuiColorEditFlags_NoPicker,
                           ImVec2(12.0f, 12.0f));
        ImGui::SameLine();
        const std::string& name = scene_->objects[i].name;
        ImGui::Text("%zu %s", i, name.empty() ? "(unnamed)" : name.c_str());
    }
    if (n > kListed) ImGui::TextDisabled("... and %zu more objects", n - kListed);
    ImGui::TextDisabled("black: no object (the background)");
}

// The why view's causes: colour, name, and their shares of the image on screen.
void Viewer::draw_why_legend() {
    static const char* const kMeaning[] = {"the pipelines see different objects first",
                                           "same object, different local Phong",
                                           "light the shadow feelers found blocked",
                                           "the mirror term",
                                           "the transmitted term",
                                           "the images agree to 2/255"};
    if (ImGui::BeginTable("causes", 3, ImGuiTableFlags_SizingFixedFit)) {
        ImGui::TableSetupColumn("cause");
        ImGui::TableSetupColumn("pixels");
        ImGui::TableSetupColumn("of the diff");
        ImGui::TableHeadersRow();
        for (std::size_t k = 0; k < rt::kCauseCount; ++k) {
            ImGui::TableNextColumn();
            ImGui::ColorButton("##cause", imgui_colour(rt::cause_colour(rt::kCauseNames[k].value)),
                               ImGuiColorEditFlags_NoTooltip | ImGuiColorEditFlags_NoPicker,
                               ImVec2(12.0f, 12.0f));
            ImGui::SameLine();
            ImGui::TextUnformatted(rt::kCauseNames[k].name);
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", kMeaning[k]);
            ImGui::TableNextColumn();
            if (explanation_) ImGui::Text("%5.1f %%", 100.0 * explanation_->shares[k].pixels);
            ImGui::TableNextColumn();
            if (explanation_) ImGui::Text("%5.1f %%", 100.0 * explanation_->shares[k].error);
        }
        ImGui::EndTable();
    }
    ImGui::TextDisabled("traced - raster, split into terms that sum to it;");
    ImGui::TextDisabled("a pixel's colour is its largest term (docs/explain.md)");
}

// Why the classic pipeline's picture lacks what the tracer shows.
void Viewer::draw_raster_legend() {
    const auto& m = scene_->materials;
    const bool mirrors = std::any_of(m.begin(), m.end(),
                                     [](const rt::Material& x) { return x.reflectivity > 0.0f; });
    const bool glass = std::any_of(m.begin(), m.end(),
                                   [](const rt::Material& x) { return x.transparency > 0.0f; });
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + 300.0f);
    if ((mirrors || glass) && settings_.environment_maps)
        ImGui::TextDisabled(
            "Mirrors and glass look up environment maps, seen from each object's centre: "
            "near objects show in the wrong place in them (parallax), and glass bends once.");
    else if (mirrors || glass)
        ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.5f, 1.0f),
                           "OpenGL draws %s with its local Phong colour only, often dark: the "
                           "classic pipeline has no reflection or refraction.",
                           mirrors && glass ? "mirror and glass"
                           : mirrors        ? "a mirror"
                                            : "glass");
    if (settings_.shadow_maps)
        ImGui::TextDisabled(
            "Shadows come from shadow maps: a depth cube per point light, compared with a "
            "bias and filtered; the why view shows where they miss the tracer's feelers.");
    else
        ImGui::TextDisabled(
            "OpenGL has no shadows either: each light reaches every surface facing it.");
    ImGui::PopTextWrapPos();
}

}  // namespace rt::viewer
