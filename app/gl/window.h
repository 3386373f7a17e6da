#pragma once
// A GLFW window with an OpenGL 3.3 core context, loaded through the same glad loader as
// the headless contexts (fed by glfwGetProcAddress), plus Dear ImGui on top of it.

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
    // Keys reach ImGui 1.86 as a state per frame, so a press and its release within one
    // frame (a quick tap while a frame is slow) would be lost: such a release is held
    // back until ImGui has seen the press in a frame.
    void forward_key(int key, int scancode, int action, int mods);
    static void forward_char(GLFWwindow* window, unsigned int c);
    static void forward_mouse_button(GLFWwindow* window, int button, int action, int mods);
    static void forward_scroll(GLFWwindow* window, double dx, double dy);
    void begin_imgui_frame();
    void end_imgui_frame();  // renders ImGui's draw data
    void swap_buffers();

  private:
    struct KeyEvent {
        int key, scancode, action, mods;
    };
    GLFWwindow* window_ = nullptr;
    std::vector<int> pressed_this_frame_;  // keys ImGui has not yet seen down in a frame
    std::vector<KeyEvent> held_releases_;  // their releases, for after the next frame starts
    std::string description_;
    bool imgui_ = false;
};

}  // namespace rt::gl
