#include "app/gl/context.h"

#include <stdexcept>

#include "app/gl/debug.h"
#include "app/gl/gl.h"
#include "core/error.h"

namespace rt::gl {

namespace detail {

std::string load_gl(ProcLoader loader) {
    const int version = gladLoadGL(reinterpret_cast<GLADloadfunc>(loader));
    if (version == 0) throw std::runtime_error("could not load the OpenGL functions");
    if (GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) < 33)
        throw std::runtime_error("OpenGL 3.3 core or later is needed, the context has " +
                                 std::to_string(GLAD_VERSION_MAJOR(version)) + "." +
                                 std::to_string(GLAD_VERSION_MINOR(version)));
    install_debug_output();
    return std::string(reinterpret_cast<const char*>(glGetString(GL_RENDERER))) + ", OpenGL " +
           reinterpret_cast<const char*>(glGetString(GL_VERSION));
}

}  // namespace detail

std::string compute_unavailable_reason() {
    if (GLAD_GL_VERSION_4_3) return "";
    return std::string("compute shaders need OpenGL 4.3; this context has ") +
           reinterpret_cast<const char*>(glGetString(GL_VERSION));
}

std::unique_ptr<Context> create_headless_context(Backend backend, const std::string& program) {
    std::string failures;
    if (backend == Backend::kEgl || backend == Backend::kAuto) {
        try {
            return detail::create_egl_context();
        } catch (const std::exception& e) {
            failures += std::string("EGL: ") + e.what();
        }
    }
    if (backend == Backend::kOsmesa || backend == Backend::kAuto) {
        try {
            return detail::create_osmesa_context();
        } catch (const std::exception& e) {
            failures += (failures.empty() ? "" : "; ") + std::string("OSMesa: ") + e.what();
        }
    }
    throw Error(program, "--gl", "cannot create an OpenGL context (" + failures + ")");
}

}  // namespace rt::gl
