// EGL on Mesa's surfaceless platform: no display server, no window, rendering into FBOs.
// Falls back to EGL device enumeration where the surfaceless platform is missing.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/gl/context.h"
#include "app/gl/debug.h"

namespace rt::gl::detail {
namespace {

std::string egl_error(const char* what) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04x", static_cast<unsigned>(eglGetError()));
    return std::string(what) + " failed (EGL error " + code + ")";
}

// An EGL display is one per process and platform: eglTerminate on it ends every context
// made on it. So each context holds a reference, and the last one terminates.
class DisplayRefs {
  public:
    void add(EGLDisplay d) {
        std::lock_guard lock(mutex_);
        ++count_[d];
    }
    void release(EGLDisplay d) {
        std::lock_guard lock(mutex_);
        if (--count_[d] > 0) return;
        count_.erase(d);
        eglTerminate(d);
    }

  private:
    std::mutex mutex_;
    std::map<EGLDisplay, int> count_;
};

DisplayRefs& display_refs() {
    static DisplayRefs refs;
    return refs;
}

EGLDisplay device_display() {
    auto query_devices =
        reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    if (!query_devices) return EGL_NO_DISPLAY;
    EGLint count = 0;
    if (!query_devices(0, nullptr, &count) || count <= 0) return EGL_NO_DISPLAY;
    std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
    query_devices(count, devices.data(), &count);
    for (EGLDeviceEXT device : devices) {
        EGLDisplay display = eglGetPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
        EGLint major = 0, minor = 0;
        if (display != EGL_NO_DISPLAY && eglInitialize(display, &major, &minor)) return display;
    }
    return EGL_NO_DISPLAY;
}

class EglContext : public Context {
  public:
    EglContext() {
        display_ =
            eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        EGLint major = 0, minor = 0;
        std::string platform = "EGL surfaceless";
        if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, &major, &minor)) {
            display_ = device_display();
            platform = "EGL device";
            if (display_ == EGL_NO_DISPLAY)
                throw std::runtime_error("no surfaceless platform and no usable EGL device");
        }
        display_refs().add(display_);
        if (!eglBindAPI(EGL_OPENGL_API)) fail("eglBindAPI(EGL_OPENGL_API)");
        // No config: EGL_KHR_no_config_context, which Mesa has; no surface either.
        for (const auto& version : kCoreVersions) {
            const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                         version[0],
                                         EGL_CONTEXT_MINOR_VERSION,
                                         version[1],
                                         EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                         EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                         EGL_CONTEXT_OPENGL_DEBUG,
                                         debug_output_requested() ? EGL_TRUE : EGL_FALSE,
                                         EGL_NONE};
            context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
            if (context_ != EGL_NO_CONTEXT) break;
        }
        if (context_ == EGL_NO_CONTEXT) fail("eglCreateContext (OpenGL 3.3 core or later)");
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            fail("eglMakeCurrent");
        try {
            description_ =
                platform + ": " + load_gl(reinterpret_cast<ProcLoader>(eglGetProcAddress));
        } catch (...) {
            release();
            throw;
        }
    }

    ~EglContext() override { release(); }

    void make_current() override {
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            throw std::runtime_error(egl_error("eglMakeCurrent"));
    }

  private:
    [[noreturn]] void fail(const char* what) {
        const std::string message = egl_error(what);
        release();
        throw std::runtime_error(message);
    }

    void release() {
        if (display_ == EGL_NO_DISPLAY) return;
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
        display_refs().release(display_);  // terminated when no other context uses it
        display_ = EGL_NO_DISPLAY;
    }

    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<Context> create_egl_context() { return std::make_unique<EglContext>(); }

}  // namespace rt::gl::detail
