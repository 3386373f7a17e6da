// OSMesa: Mesa's off-screen software context. osmesa.h pulls in the system GL/gl.h, so
// this file must not see glad's header; GL is loaded through OSMesaGetProcAddress.
#include <GL/osmesa.h>

#include <stdexcept>
#include <vector>

#include "app/gl/context.h"

namespace rt::gl::detail {
namespace {

class OsmesaContext : public Context {
  public:
    OsmesaContext() {
        for (const auto& version : kCoreVersions) {
            const int attributes[] = {OSMESA_FORMAT,
                                      OSMESA_RGBA,
                                      OSMESA_DEPTH_BITS,
                                      24,
                                      OSMESA_PROFILE,
                                      OSMESA_CORE_PROFILE,
                                      OSMESA_CONTEXT_MAJOR_VERSION,
                                      version[0],
                                      OSMESA_CONTEXT_MINOR_VERSION,
                                      version[1],
                                      0};
            context_ = OSMesaCreateContextAttribs(attributes, nullptr);
            if (context_) break;
        }
        if (!context_)
            throw std::runtime_error(
                "OSMesaCreateContextAttribs (OpenGL 3.3 core or later) failed");
        // OSMesa needs a buffer to be current; all rendering goes to FBOs, so 1x1 will do.
        if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
            OSMesaDestroyContext(context_);
            throw std::runtime_error("OSMesaMakeCurrent failed");
        }
        try {
            description_ = "OSMesa: " + load_gl(reinterpret_cast<ProcLoader>(OSMesaGetProcAddress));
        } catch (...) {
            OSMesaDestroyContext(context_);
            throw;
        }
    }

    void make_current() override {
        if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, 1, 1))
            throw std::runtime_error("OSMesaMakeCurrent failed");
    }

    ~OsmesaContext() override {
        // Released first: a context destroyed while current keeps its framebuffer.
        OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
        OSMesaDestroyContext(context_);
    }

  private:
    OSMesaContext context_ = nullptr;
    std::vector<unsigned char> buffer_ = std::vector<unsigned char>(4);
};

}  // namespace

std::unique_ptr<Context> create_osmesa_context() { return std::make_unique<OsmesaContext>(); }

}  // namespace rt::gl::detail
