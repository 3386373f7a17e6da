#pragma once
// Small Dear ImGui pieces the panel, the statistics and the overlays share.

#include <imgui.h>

#include "core/compare.h"
#include "core/image.h"

namespace rt::viewer {

// A titled part of the panel.
inline void section(const char* title) {
    ImGui::Separator();
    ImGui::TextDisabled("%s", title);
}

// A linear colour as ImGui's (sRGB) colour.
inline ImVec4 imgui_colour(const rt::vec3& linear, float alpha = 1.0f) {
    return {rt::srgb_encode(linear.x), rt::srgb_encode(linear.y), rt::srgb_encode(linear.z), alpha};
}

// White text on a dark rounded box, readable over any image.
inline void label(ImDrawList* draw, ImVec2 at, const char* text) {
    const ImVec2 size = ImGui::CalcTextSize(text);
    draw->AddRectFilled(ImVec2(at.x - 4, at.y - 2), ImVec2(at.x + size.x + 4, at.y + size.y + 2),
                        IM_COL32(0, 0, 0, 170), 4.0f);
    draw->AddText(at, IM_COL32(255, 255, 255, 255), text);
}

}  // namespace rt::viewer
