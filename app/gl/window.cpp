#include "app/gl/window.h"

#include <algorithm>
#include <cstdlib>

#include "app/gl/context.h"
#include "app/gl/debug.h"
#include "app/gl/gl.h"
#define GLFW_INCLUDE_NONE  // glad provides the GL declarations
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "core/error.h"

namespace rt::gl {
namespace {

std::string glfw_error() {
    const char* text = nullptr;
    glfwGetError(&text);
    return text ? text : "unknown GLFW error";
}

}  // namespace

Window::Window(int width, int height, const std::string& title) {
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    if ((!x11 || !*x11) && (!wayland || !*wayland))
        throw Error("rtview", "display",
                    "no display (DISPLAY is not set); for headless rendering use rtrender");
    if (!glfwInit())
        throw Error("rtview", "display",
                    "cannot open the display: " + glfw_error() + "; use rtrender");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, debug_output_requested() ? GLFW_TRUE : GLFW_FALSE);
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window_) {
        const std::string why = glfw_error();
        glfwTerminate();
        throw Error("rtview", "display", "cannot create an OpenGL 3.3 core window: " + why);
    }
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(1);
    try {
        description_ =
            "GLFW: " + detail::load_gl(reinterpret_cast<detail::ProcLoader>(glfwGetProcAddress));
    } catch (const std::exception& e) {
        glfwDestroyWindow(window_);
        glfwTerminate();
        throw Error("rtview", "display", e.what());
    }
}

Window::~Window() {
    if (imgui_) {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }
    glfwDestroyWindow(window_);
    glfwTerminate();
}

glm::ivec2 Window::framebuffer_size() const {
    glm::ivec2 size;
    glfwGetFramebufferSize(window_, &size.x, &size.y);
    return size;
}

void Window::set_title(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }
bool Window::should_close() const { return glfwWindowShouldClose(window_); }

void Window::init_imgui() {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the user's directory
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window_, /*install_callbacks=*/false);
    glfwSetWindowFocusCallback(window_, ImGui_ImplGlfw_WindowFocusCallback);
    glfwSetCursorEnterCallback(window_, ImGui_ImplGlfw_CursorEnterCallback);
    ImGui_ImplOpenGL3_Init("#version 330 core");
    imgui_ = true;
}

void Window::forward_key(int key, int scancode, int action, int mods) {
    const auto seen = std::find(pressed_this_frame_.begin(), pressed_this_frame_.end(), key);
    if (action == GLFW_RELEASE && seen != pressed_this_frame_.end()) {
        held_releases_.push_back({key, scancode, action, mods});
        return;
    }
    if (action == GLFW_PRESS) pressed_this_frame_.push_back(key);
    ImGui_ImplGlfw_KeyCallback(window_, key, scancode, action, mods);
}
void Window::forward_char(GLFWwindow* window, unsigned int c) {
    ImGui_ImplGlfw_CharCallback(window, c);
}
void Window::forward_mouse_button(GLFWwindow* window, int button, int action, int mods) {
    ImGui_ImplGlfw_MouseButtonCallback(window, button, action, mods);
}
void Window::forward_scroll(GLFWwindow* window, double dx, double dy) {
    ImGui_ImplGlfw_ScrollCallback(window, dx, dy);
}

void Window::begin_imgui_frame() {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    // This frame has seen this batch's presses; their held-back releases count from the next.
    pressed_this_frame_.clear();
    for (const KeyEvent& e : held_releases_)
        ImGui_ImplGlfw_KeyCallback(window_, e.key, e.scancode, e.action, e.mods);
    held_releases_.clear();
}

void Window::end_imgui_frame() {
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void Window::swap_buffers() { glfwSwapBuffers(window_); }

}  // namespace rt::gl
