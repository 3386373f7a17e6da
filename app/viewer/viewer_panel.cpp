// The viewer's panel (the statistics and legends are in viewer_stats.cpp, the labels over
// the view in viewer_overlays.cpp) and the help.
#include <algorithm>
#include <array>
#include <cstdlib>
#include <thread>

#include <imgui.h>

#include "app/viewer/keys.h"
#include "app/viewer/panel_widgets.h"
#include "app/viewer/viewer.h"
#include "app/viewer/views.h"
#include "core/compare.h"
#include "core/scene_loader.h"

namespace rt::viewer {
namespace {

// Every slider clamps what is typed into it (Ctrl+click) to its range, too.
constexpr ImGuiSliderFlags kClamp = ImGuiSliderFlags_AlwaysClamp;

// Tab in the open field: the longest completion of what is typed, among the folders and
// the scene and mesh files of its folder; `user` collects the candidates to show.
int complete_path(ImGuiInputTextCallbackData* data) {
    auto& candidates = *static_cast<std::vector<std::string>*>(data->UserData);
    candidates.clear();
    const std::string typed(data->Buf, static_cast<std::size_t>(data->BufTextLen));
    const auto slash = typed.find_last_of('/');
    const std::string dir = slash == std::string::npos ? "." : typed.substr(0, slash + 1);
    const std::string prefix = slash == std::string::npos ? typed : typed.substr(slash + 1);
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(dir, ec)) {
        std::string name = e.path().filename().string();
        const std::string ext = e.path().extension().string();
        const bool dir_entry = e.is_directory(ec);
        if (name.rfind(prefix, 0) != 0 || (name[0] == '.' && prefix.empty())) continue;
        if (!dir_entry && !rt::is_scene_file(e.path())) continue;
        candidates.push_back(dir_entry ? name + "/" : name);
    }
    std::sort(candidates.begin(), candidates.end());
    if (candidates.empty()) return 0;
    std::string common = candidates.front();
    for (const std::string& c : candidates)
        common.resize(static_cast<std::size_t>(
            std::mismatch(common.begin(), common.end(), c.begin(), c.end()).first -
            common.begin()));
    const std::string completed = (slash == std::string::npos ? "" : dir) + common;
    data->DeleteChars(0, data->BufTextLen);
    data->InsertChars(0, completed.c_str());
    if (candidates.size() == 1) candidates.clear();  // done: nothing left to choose
    return 0;
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
    draw_open_field();
    if (rt::is_bare_mesh(shown)) {
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
    ImGui::SliderInt("max depth", &settings_.max_depth, 0, 12, "%d", kClamp);
    ImGui::SliderFloat("resolution", &settings_.resolution_scale, 0.1f, 1.0f, "%.2f x window",
                       kClamp);
    const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    int threads = settings_.threads > 0 ? settings_.threads : cores;
    if (ImGui::SliderInt("threads", &threads, 1, std::max(cores, 16), "%d", kClamp))
        settings_.threads = threads;
    // After full resolution the traced view refines to this many samples per pixel.
    static constexpr int kSpp[] = {1, 4, 16, 64};
    const char* spp_names[] = {"off (1 sample per pixel)", "4 samples per pixel",
                               "16 samples per pixel", "64 samples per pixel"};
    int spp_index = static_cast<int>(
        std::find(std::begin(kSpp), std::end(kSpp), settings_.max_spp) - std::begin(kSpp));
    if (ImGui::Combo("anti-aliasing", &spp_index, spp_names, 4))
        settings_.max_spp = kSpp[std::clamp(spp_index, 0, 3)];
    section("raster");
    const int most = max_msaa_;
    static constexpr int kMsaa[] = {1, 2, 4, 8};
    const char* msaa_names[] = {"off", "2x", "4x", "8x"};
    int msaa_index = static_cast<int>(
        std::find(std::begin(kMsaa), std::end(kMsaa), settings_.msaa) - std::begin(kMsaa));
    const int offered = most >= 8 ? 4 : most >= 4 ? 3 : most >= 2 ? 2 : 1;
    if (ImGui::Combo("MSAA", &msaa_index, msaa_names, offered))
        settings_.msaa = kMsaa[std::clamp(msaa_index, 0, offered - 1)];
    ImGui::Checkbox("shadow maps (a depth cube per point light)", &settings_.shadow_maps);
    ImGui::Checkbox("environment maps (mirrors and glass)", &settings_.environment_maps);

    section("view");
    for (std::size_t i = 0; i < kViewCount; ++i) {
        const std::string label = std::to_string(i + 1) + " " + kViews[i].label;
        const bool unavailable = kViews[i].value == View::kGpuTrace && !gpu_;
        if (unavailable) ImGui::BeginDisabled();
        if (ImGui::RadioButton(label.c_str(), display_.view == kViews[i].value))
            set_view(kViews[i].value);
        if (unavailable) ImGui::EndDisabled();
        if (unavailable && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
            ImGui::SetTooltip("%s", gpu_unavailable_.c_str());
        if (i % 3 != 2 && i + 1 != kViewCount) ImGui::SameLine();
    }
    ImGui::Checkbox("labels (L)", &display_.labels);
    ImGui::SameLine();
    ImGui::Checkbox("light markers", &display_.lights);
    if (display_.view == View::kSplit) {
        const char* pairs[] = {"raster | traced", "raster | GPU traced", "traced | GPU traced"};
        int pair = static_cast<int>(display_.split);
        if (gpu_ && ImGui::Combo("sides", &pair, pairs, 3)) {
            display_.split = static_cast<SplitPair>(pair);
            std::printf("split: %s\n", pairs[pair]);
            std::fflush(stdout);
        }
        ImGui::Checkbox("swap sides (X)", &display_.swap);
        ImGui::SliderFloat("divider", &display_.divider, 0.0f, 1.0f, "%.3f", kClamp);
    }
    if (display_.view == View::kDiff) draw_diff_controls();
    if (display_.view == View::kItemBuffer) draw_item_legend();
    if (display_.view == View::kWhy) draw_why_legend();
    if (display_.view == View::kRaster || display_.view == View::kSplit ||
        display_.view == View::kDiff)
        draw_raster_legend();

    draw_inspector();
    draw_picked();
    draw_statistics();
    ImGui::Separator();
    for (const Action a : {Action::kResetCamera, Action::kSave, Action::kHelp}) {
        if (a != Action::kResetCamera) ImGui::SameLine();
        if (ImGui::Button(with_keys(a).c_str())) perform(a);
    }
    ImGui::End();
}

// A path typed (Tab completes, Enter opens), beside the picker and drops.
void Viewer::draw_open_field() {
    ImGui::SetNextItemWidth(230.0f);
    const bool enter = ImGui::InputTextWithHint(
        "##open", "path of a scene or model (Tab completes)", open_path_.data(), open_path_.size(),
        ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_CallbackCompletion,
        complete_path, &open_candidates_);
    ImGui::SameLine();
    if ((ImGui::Button("open") || enter) && open_path_[0] != '\0') {
        std::filesystem::path path(open_path_.data());
        if (const char* home = std::getenv("HOME"); home && open_path_[0] == '~')
            path = std::string(home) + std::string(open_path_.data() + 1);
        scenes_.pick(std::filesystem::absolute(path));
        open_candidates_.clear();
    }
    for (std::size_t i = 0; i < std::min<std::size_t>(open_candidates_.size(), 8); ++i)
        ImGui::TextDisabled("  %s", open_candidates_[i].c_str());
    if (open_candidates_.size() > 8)
        ImGui::TextDisabled("  ... %zu more", open_candidates_.size() - 8);
    ImGui::TextDisabled("or drop a scene or model file on the window; F5 reads it again");
}

void Viewer::draw_diff_controls() {
    const char* modes[] = {"heat: largest channel", "signed luminance", "per channel"};
    int mode = static_cast<int>(display_.diff_mode);
    if (ImGui::Combo("diff mode", &mode, modes, 3))
        display_.diff_mode = static_cast<rt::gl::DiffMode>(mode);
    ImGui::SliderFloat("diff scale", &settings_.diff_scale, 0.01f, 1.0f, "%.3f", kClamp);
    bool mask = display_.diff_threshold > 0.0f;
    if (ImGui::Checkbox("threshold mask", &mask))
        display_.diff_threshold = mask ? 2.0f / 255.0f : 0.0f;
    if (mask) {
        ImGui::SliderFloat("threshold", &display_.diff_threshold, 1.0f / 255.0f, 0.5f, "%.4f",
                           kClamp);
        ImGui::TextDisabled("white: a channel differs by more (%.1f/255)",
                            255.0f * display_.diff_threshold);
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
