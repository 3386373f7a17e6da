#pragma once
// The viewer's controls, once: the key handler looks keys up here, the help overlay
// lists this table, the panel's buttons take their key hints from it. The views' keys
// (1 to 6) come from kViews (views.h), in the same way.

#include <cstddef>
#include <optional>
#include <string>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>  // key codes only: this header needs no GL

namespace rt::viewer {

enum class Action {
    kNone,  // a control that is not one key press (mouse drags, held keys): help only
    kFlicker,
    kSwap,
    kPanel,
    kLabels,
    kResetCamera,
    kNextScene,
    kPreviousScene,
    kReload,
    kSave,
    kHelp,
    kEscape,
    kQuit,
};

struct KeyChord {
    int key = GLFW_KEY_UNKNOWN;
    int mods = 0;  // exactly these of Shift, Ctrl, Alt, Super
};

struct Control {
    Action action;
    const char* name;  // short, for a button
    const char* keys;  // as the help shows them
    const char* what;
    KeyChord chords[2];  // the presses that do it (unused ones: GLFW_KEY_UNKNOWN)
};

inline constexpr int kChordMods = GLFW_MOD_SHIFT | GLFW_MOD_CONTROL | GLFW_MOD_ALT | GLFW_MOD_SUPER;

inline constexpr Control kControls[] = {
    {Action::kFlicker,
     "flicker",
     "Tab (hold)",
     "flicker between raster and traced",
     {{GLFW_KEY_TAB}}},
    {Action::kSwap, "swap sides", "X", "swap the split view's sides", {{GLFW_KEY_X}}},
    {Action::kPanel, "panel", "H", "hide or show the panel", {{GLFW_KEY_H}}},
    {Action::kLabels, "labels", "L", "hide or show the labels over the view", {{GLFW_KEY_L}}},
    {Action::kNone, "orbit", "left drag", "orbit (on the split divider: move it)", {}},
    {Action::kNone, "pan", "right/middle drag", "pan", {}},
    {Action::kNone, "zoom", "wheel", "zoom", {}},
    {Action::kNone, "fly", "W A S D, Q E", "fly; Shift: faster", {}},
    {Action::kResetCamera, "reset camera", "R", "reset the camera", {{GLFW_KEY_R}}},
    {Action::kNextScene,
     "next scene",
     "PageDown",
     "next scene in the scenes folder",
     {{GLFW_KEY_PAGE_DOWN}}},
    {Action::kPreviousScene, "previous scene", "PageUp", "previous scene", {{GLFW_KEY_PAGE_UP}}},
    {Action::kReload, "reload", "F5", "read the scene file again", {{GLFW_KEY_F5}}},
    {Action::kSave,
     "save",
     "F12 or P",
     "save the view (and raster, traced, difference)",
     {{GLFW_KEY_F12}, {GLFW_KEY_P}}},
    {Action::kHelp,
     "keys",
     "F1 or ?",
     "this help",
     {{GLFW_KEY_F1}, {GLFW_KEY_SLASH, GLFW_MOD_SHIFT}}},
    {Action::kEscape,
     "close",
     "Esc",
     "close the help or a drop-down, clear a picked pixel's rays; twice: quit",
     {{GLFW_KEY_ESCAPE}}},
    {Action::kQuit, "quit", "Ctrl+Q", "quit", {{GLFW_KEY_Q, GLFW_MOD_CONTROL}}},
};

// The action a key press does (Caps Lock and Num Lock aside), if any.
constexpr Action action_of(int key, int mods) {
    for (const Control& c : kControls)
        for (const KeyChord& chord : c.chords)
            if (chord.key != GLFW_KEY_UNKNOWN && chord.key == key &&
                chord.mods == (mods & kChordMods))
                return c.action;
    return Action::kNone;
}

// "reset camera (R)": a button's label with the keys that do the same.
inline std::string with_keys(Action action) {
    for (const Control& c : kControls)
        if (c.action == action) return std::string(c.name) + " (" + c.keys + ")";
    return {};
}

// No key press does two things.
constexpr bool chords_unique() {
    for (const Control& a : kControls)
        for (const KeyChord& x : a.chords)
            for (const Control& b : kControls)
                for (const KeyChord& y : b.chords)
                    if (&x != &y && x.key != GLFW_KEY_UNKNOWN && x.key == y.key && x.mods == y.mods)
                        return false;
    return true;
}
static_assert(chords_unique(), "a key press bound to two controls");

}  // namespace rt::viewer
