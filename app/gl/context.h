#pragma once
// Headless OpenGL contexts. Creating one makes it current on the calling thread and
// loads the GL functions through it.

#include <memory>
#include <string>

#include "core/names.h"

namespace rt::gl {

enum class Backend { kAuto, kEgl, kOsmesa };
inline constexpr Named<Backend> kBackendNames[] = {
    {"egl", Backend::kEgl}, {"osmesa", Backend::kOsmesa}, {"auto", Backend::kAuto}};

class Context {
  public:
    virtual ~Context() = default;
    // "EGL surfaceless: llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 (Core Profile) Mesa 22.3.6"
    const std::string& description() const { return description_; }
    // Makes this context current on the calling thread again (after another was).
    virtual void make_current() = 0;

  protected:
    std::string description_;
};

// kAuto tries EGL first, then OSMesa. Throws rt::Error ("PROGRAM: --gl: ...") when no
// context can be made, saying why each attempt failed.
std::unique_ptr<Context> create_headless_context(Backend backend, const std::string& program);

// Compute shaders and shader storage buffers (OpenGL 4.3) in the current context: what
// the GPU tracer needs. Empty when there; else why not, in words.
std::string compute_unavailable_reason();

namespace detail {
// The core versions a context asks for, best first: a vendor driver gives exactly the
// version asked (NVIDIA: "OpenGL 3.3.0" for 3.3), Mesa its highest whatever is asked.
inline constexpr int kCoreVersions[][2] = {{4, 6}, {4, 5}, {4, 3}, {3, 3}};
using ProcLoader = void* (*)(const char*);
std::unique_ptr<Context> create_egl_context();     // throws std::runtime_error
std::unique_ptr<Context> create_osmesa_context();  // throws std::runtime_error
// Loads GL through `loader` into the current context; returns "RENDERER, VERSION".
std::string load_gl(ProcLoader loader);
}  // namespace detail

}  // namespace rt::gl
