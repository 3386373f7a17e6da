// The viewer's input: keys, the mouse, scrolling and dropped files, and what each
// control does. What reaches ImGui and what reaches the viewer is decided here.
#include "app/viewer/keys.h"
#include "app/viewer/viewer.h"
#include "app/viewer/views.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_internal.h>  // ClosePopupToLevel: Esc closes an open drop-down

namespace rt::viewer {
namespace {

// Whether a text field (or a slider turned into one by Ctrl+click) is being edited now,
// as of the last frame's end: io.WantTextInput lags a frame behind, and a key right after
// Enter would still go to the field that Enter closed.
bool editing_text() {
    const ImGuiContext& g = *ImGui::GetCurrentContext();
    return g.ActiveId != 0 && g.InputTextState.ID == g.ActiveId;
}

bool is_modifier(int key) {
    return key == GLFW_KEY_LEFT_SHIFT || key == GLFW_KEY_RIGHT_SHIFT ||
           key == GLFW_KEY_LEFT_CONTROL || key == GLFW_KEY_RIGHT_CONTROL ||
           key == GLFW_KEY_LEFT_ALT || key == GLFW_KEY_RIGHT_ALT || key == GLFW_KEY_LEFT_SUPER ||
           key == GLFW_KEY_RIGHT_SUPER;
}

}  // namespace

// W A S D Q E held (while no text field has the keys): where the camera flies.
rt::vec3 Viewer::fly_direction() const {
    if (ImGui::GetIO().WantCaptureKeyboard) return rt::vec3(0.0f);
    GLFWwindow* w = window_.handle();
    const auto down = [&](int key) { return glfwGetKey(w, key) == GLFW_PRESS ? 1.0f : 0.0f; };
    return {down(GLFW_KEY_D) - down(GLFW_KEY_A), down(GLFW_KEY_E) - down(GLFW_KEY_Q),
            down(GLFW_KEY_W) - down(GLFW_KEY_S)};
}

// A key or a character that comes while a click has not yet reached ImGui's frame (the
// click and the typing after it in one slow frame) waits for that frame: whether it is
// text for the field the click opened or the viewer's own key is known only then.
void Viewer::on_key(int key, int scancode, int action, int mods) {
    if (window_.press_unseen() || !held_keys_.empty())
        held_keys_.push_back({.key = key, .scancode = scancode, .action = action, .mods = mods});
    else
        route_key(key, scancode, action, mods);
}

void Viewer::on_char(unsigned int c) {
    if (window_.press_unseen() || !held_keys_.empty())
        held_keys_.push_back({.text = true, .c = c});
    else
        route_char(c);
}

// After each ImGui frame, in order, until one waits for a later click.
void Viewer::release_held_keys() {
    std::size_t n = 0;
    for (; n < held_keys_.size() && !window_.press_unseen(); ++n) {
        const HeldKey k = held_keys_[n];
        if (k.text)
            route_char(k.c);
        else
            route_key(k.key, k.scancode, k.action, k.mods);
    }
    held_keys_.erase(held_keys_.begin(), held_keys_.begin() + static_cast<std::ptrdiff_t>(n));
}

// Keys are the viewer's, except while a text field is being edited (a click in one, or
// Ctrl+click on a slider): then every key is ImGui's. ImGui always learns the modifiers
// (Ctrl+click needs them) and every release, so no key stays down in it; Tab and the
// others never reach its focus and tabbing, which used to turn a slider into a text
// field that the next digit typed into.
void Viewer::route_key(int key, int scancode, int action, int mods) {
    const bool editing = editing_text();
    if (editing || is_modifier(key) || action == GLFW_RELEASE)
        window_.forward_key(key, scancode, action, mods);
    if (editing) return;
    // A held control follows its key alone: Tab pressed with Shift and let go without it
    // (or the other way round) still ends the flicker.
    if (action_of(key, 0) == Action::kFlicker && (action == GLFW_PRESS || action == GLFW_RELEASE)) {
        display_.flicker = action == GLFW_PRESS;
        std::printf("flicker: %s\n", display_.flicker ? "on" : "off");
        std::fflush(stdout);
    }
    if (action != GLFW_PRESS) return;
    if (key >= GLFW_KEY_1 && key < GLFW_KEY_1 + static_cast<int>(kViewCount)) {
        const View view = kViews[key - GLFW_KEY_1].value;
        if (view == View::kGpuTrace && !gpu_) {
            std::printf("view: GPU traced is unavailable: %s\n", gpu_unavailable_.c_str());
            std::fflush(stdout);
            return;
        }
        return set_view(view);
    }
    perform(action_of(key, mods));
}

// What a control does, whether from its key or the panel's button.
void Viewer::perform(Action action) {
    switch (action) {
        case Action::kSwap:
            display_.swap = !display_.swap;
            std::printf("swap: %s\n", display_.swap ? "traced left" : "raster left");
            std::fflush(stdout);
            break;
        case Action::kPanel:
            display_.panel = !display_.panel;
            break;
        case Action::kLabels:
            display_.labels = !display_.labels;
            break;
        case Action::kResetCamera:
            controller_->reset();
            break;
        case Action::kHelp:
            display_.help = !display_.help;
            break;
        case Action::kSave:
            save_requested_ = true;
            break;
        case Action::kNextScene:
            scenes_.step(1);
            break;
        case Action::kPreviousScene:
            scenes_.step(-1);
            break;
        case Action::kReload:
            scenes_.reload();
            break;
        case Action::kEscape:
            on_escape();
            break;
        case Action::kQuit:
            quit("Ctrl+Q");
            break;
        case Action::kFlicker:  // held, not pressed: on_key
        case Action::kNone:
            break;
    }
}

// Esc closes what is open (the help, a drop-down); with nothing open it asks, and a
// second Esc within kQuitSeconds quits: one keystroke never loses the camera and settings.
void Viewer::on_escape() {
    if (display_.help) {
        display_.help = false;
    } else if (picked_ || pick_mode_) {
        clear_picked();
    } else if (ImGui::IsPopupOpen(nullptr,
                                  ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel)) {
        ImGui::ClosePopupToLevel(0, true);
    } else if (quit_asked_ && quit_asked_->seconds() < kQuitSeconds) {
        quit("Esc Esc");
    } else {
        quit_asked_.emplace();
        std::printf("Esc: press Esc again to quit\n");
        std::fflush(stdout);
    }
}

void Viewer::quit(const char* how) {
    std::printf("quit: %s\n", how);
    std::fflush(stdout);
    glfwSetWindowShouldClose(window_.handle(), GLFW_TRUE);
}

void Viewer::on_mouse_button(int button, int action) {
    if (action == GLFW_RELEASE) {
        drag_.orbit = drag_.pan = drag_.divider = false;
        return;
    }
    if (ImGui::GetIO().WantCaptureMouse) return;
    int width = 1, height = 1;
    glfwGetWindowSize(window_.handle(), &width, &height);
    GLFWwindow* w = window_.handle();
    const bool ctrl = glfwGetKey(w, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS ||
                      glfwGetKey(w, GLFW_KEY_RIGHT_CONTROL) == GLFW_PRESS;
    if (button == GLFW_MOUSE_BUTTON_LEFT && (ctrl || pick_mode_)) {
        pick(drag_.cursor.x, drag_.cursor.y);
    } else if (button == GLFW_MOUSE_BUTTON_LEFT) {
        const bool near_divider =
            display_.view == View::kSplit &&
            std::abs(drag_.cursor.x - static_cast<double>(display_.divider) * width) < 8.0;
        (near_divider ? drag_.divider : drag_.orbit) = true;
    } else {
        drag_.pan = true;  // right or middle
    }
}

void Viewer::on_cursor(double x, double y) {
    const glm::dvec2 delta = glm::dvec2(x, y) - drag_.cursor;
    drag_.cursor = {x, y};
    int w = 1, h = 1;
    glfwGetWindowSize(window_.handle(), &w, &h);
    if (drag_.divider)
        display_.divider = std::clamp(static_cast<float>(x / std::max(1, w)), 0.0f, 1.0f);
    if (drag_.orbit) controller_->orbit(static_cast<float>(delta.x), static_cast<float>(delta.y));
    if (drag_.pan) controller_->pan(static_cast<float>(delta.x), static_cast<float>(delta.y), h);
}

void Viewer::on_scroll(double dy) {
    if (!ImGui::GetIO().WantCaptureMouse) controller_->zoom(static_cast<float>(dy));
}

void Viewer::on_drop(const std::string& path) { scenes_.pick(path); }

// Characters are text only while a text field is being edited.
void Viewer::route_char(unsigned int c) {
    if (editing_text()) window_.forward_char(c);
}

}  // namespace rt::viewer
