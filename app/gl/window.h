#pragma once
// A GLFW window with an OpenGL 3.3 core context, loaded through the same glad loader as
// the headless contexts (fed by glfwGetProcAddress), plus Dear ImGui on top of it.

#include <array>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

struct GLFWwindow;

namespace rt::gl {

class Window {
  public:
    // Throws rt::Error("rtview", "display", ...) when there is no display or no context.
    Window(int width, int height, const std::string& title);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    GLFWwindow* handle() const { return window_; }
    const std::string& description() const { return description_; }
    glm::ivec2 framebuffer_size() const;
    void set_title(const std::string& title);
    bool should_close() const;

    // Dear ImGui on this window. Its GLFW callbacks are not installed: the application's
    // own callbacks decide which events reach ImGui (forward_* below), so that keys that
    // are the application's never reach ImGui's focus and text editing.
    void init_imgui();
    // Keys and mouse buttons reach ImGui 1.86 as a state per frame, so a press and its
    // release within one frame (a quick tap or click while a frame is slow), or two clicks
    // within one, would be lost: each key and button changes state at most once between
    // two of ImGui's frames, and the events beyond that wait, in order, for the next.
    // ImGui 1.86's GLFW back-end reads a button's state from GLFW at each frame, which is
    // the state after the latest event GLFW has seen (a later click's press, say, with
    // this click's release still queued here): the buttons' state ImGui is given is the
    // one delivered from this queue.
    void forward_key(int key, int scancode, int action, int mods);
    void forward_mouse_button(int button, int action, int mods);
    void forward_char(unsigned int c);  // queued with the keys, so typing keeps its order
    static void forward_scroll(GLFWwindow* window, double dx, double dy);
    bool input_pending() const { return !queued_.empty(); }  // for ImGui's next frames
    // A mouse button pressed that no ImGui frame has seen yet: until one has, what the
    // press does (a text field it opens for editing, say) is not known.
    bool press_unseen() const;
    void begin_imgui_frame();
    void end_imgui_frame();  // renders ImGui's draw data
    void swap_buffers();

  private:
    struct InputEvent {
        enum Kind { kKey, kButton, kChar } kind;
        int code = 0, scancode = 0, action = 0, mods = 0;  // a character: its code point
    };
    void deliver_queued();  // as many as may reach ImGui before its next frame, in order
    GLFWwindow* window_ = nullptr;
    std::vector<InputEvent> queued_;      // waiting for ImGui's next frame
    std::vector<InputEvent> changed_;     // keys and buttons changed since ImGui's last frame
    std::array<bool, 5> buttons_down_{};  // as delivered (ImGuiMouseButton_COUNT buttons)
    std::string description_;
    bool imgui_ = false;
};

}  // namespace rt::gl
