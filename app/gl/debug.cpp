#include "app/gl/debug.h"

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "app/gl/gl.h"

namespace rt::gl {
namespace {

std::atomic<std::uint64_t> g_errors{0};
std::atomic<bool> g_installed{false};

void GLAD_API_PTR on_debug_message(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei,
                                   const GLchar* message, const void*) {
    // Compile errors become rt::Error from Program, with the file name: not repeated here.
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION || source == GL_DEBUG_SOURCE_SHADER_COMPILER)
        return;
    const bool error = type == GL_DEBUG_TYPE_ERROR || type == GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR;
    if (error) g_errors.fetch_add(1);
    std::fprintf(stderr, "GL debug: %s (source 0x%x, type 0x%x, id %u): %s\n",
                 error ? "error" : "warning", source, type, id, message);
}

}  // namespace

bool debug_output_requested() {
#ifndef NDEBUG
    return true;
#else
    const char* env = std::getenv("RTVIEW_GL_DEBUG");
    return env && std::string(env) == "1";
#endif
}

bool install_debug_output() {
    g_installed = false;
    if (!debug_output_requested() || !GLAD_GL_KHR_debug) return false;
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(on_debug_message, nullptr);
    g_installed = true;
    return true;
}

bool debug_output_installed() { return g_installed.load(); }

std::uint64_t debug_error_count() { return g_errors.load(); }

void check(const char* where) {
    std::string errors;
    for (GLenum e; (e = glGetError()) != GL_NO_ERROR;) {
        char code[16];
        std::snprintf(code, sizeof code, "0x%04x", e);
        errors += (errors.empty() ? "" : ", ") + std::string(code);
    }
    if (!errors.empty())
        throw std::runtime_error(std::string("OpenGL error ") + errors + " in " + where);
}

}  // namespace rt::gl
