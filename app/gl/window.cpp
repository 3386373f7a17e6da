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
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, debug_output_requested() ? GLFW_TRUE : GLFW_FALSE);
    for (const auto& version : detail::kCoreVersions) {  // the highest the driver gives
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, version[0]);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, version[1]);
        window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
        if (window_) break;
    }
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
    if (action == GLFW_REPEAT && queued_.empty()) {  // a held key's repeat changes no state
        ImGui_ImplGlfw_KeyCallback(window_, key, scancode, action, mods);
        return;
    }
    queued_.push_back({InputEvent::kKey, key, scancode, action, mods});
    deliver_queued();
}

void Window::forward_mouse_button(int button, int action, int mods) {
    queued_.push_back({InputEvent::kButton, button, 0, action, mods});
    deliver_queued();
}

void Window::deliver_queued() {
    std::size_t n = 0;
    for (; n < queued_.size(); ++n) {
        const InputEvent& e = queued_[n];
        if (e.kind == InputEvent::kChar) {  // text changes no state: it only keeps its place
            ImGui_ImplGlfw_CharCallback(window_, static_cast<unsigned int>(e.code));
            continue;
        }
        const auto same = [&](const InputEvent& c) { return c.kind == e.kind && c.code == e.code; };
        if (std::any_of(changed_.begin(), changed_.end(), same)) break;  // ImGui's next frame
        changed_.push_back(e);
        if (e.kind == InputEvent::kButton) {
            if (e.code >= 0 && e.code < static_cast<int>(buttons_down_.size()))
                buttons_down_[static_cast<std::size_t>(e.code)] = e.action == GLFW_PRESS;
            ImGui_ImplGlfw_MouseButtonCallback(window_, e.code, e.action, e.mods);
        } else
            ImGui_ImplGlfw_KeyCallback(window_, e.code, e.scancode, e.action, e.mods);
    }
    queued_.erase(queued_.begin(), queued_.begin() + static_cast<std::ptrdiff_t>(n));
}

bool Window::press_unseen() const {
    const auto press = [](const InputEvent& e) {
        return e.kind == InputEvent::kButton && e.action == GLFW_PRESS;
    };
    return std::any_of(changed_.begin(), changed_.end(), press) ||
           std::any_of(queued_.begin(), queued_.end(), press);
}

void Window::forward_char(unsigned int c) {
    queued_.push_back({InputEvent::kChar, static_cast<int>(c)});
    deliver_queued();
}
void Window::forward_scroll(GLFWwindow* window, double dx, double dy) {
    ImGui_ImplGlfw_ScrollCallback(window, dx, dy);
}

void Window::begin_imgui_frame() {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
#if IMGUI_VERSION_NUM < 18700  // later versions take the events themselves, in order
    ImGuiIO& io = ImGui::GetIO();
    for (std::size_t i = 0; i < buttons_down_.size(); ++i) io.MouseDown[i] = buttons_down_[i];
#endif
    ImGui::NewFrame();
    // ImGui has taken this frame's key and button states: the next changes may go in.
    changed_.clear();
}

void Window::end_imgui_frame() {
    ImGui::Render();
    // What waited goes in now, after this frame has used its text (ImGui drops typed
    // characters at the end of a frame): keys and text then both count for the next.
    deliver_queued();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void Window::swap_buffers() { glfwSwapBuffers(window_); }

}  // namespace rt::gl
