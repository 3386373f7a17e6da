#pragma once
// A 2D texture holding an rt::Image (linear RGB floats), re-specified when its size changes.

#include "app/gl/gl.h"
#include "app/gl/handle.h"
#include "core/image.h"
#include "core/texture.h"

namespace rt::gl {

class Texture {
  public:
    Texture();

    void upload(const Image& image);
    // A row of colours (a palette or a colour map), sampled by index or by t in [0, 1].
    void upload_row(const std::vector<vec3>& colours);
    // A surface's texture, filtered as core/texture.h says the tracer samples it:
    // bilinear on the linear texels, level 0, its wrap modes; row 0 at t = 0.
    void upload_surface(const rt::Texture& texture);
    // width x height RGBA32F texels from a buffer on the GPU (row 0 first), copied there.
    void upload_from_buffer(GLuint buffer, int width, int height);
    GLuint id() const { return id_.get(); }
    int width() const { return width_; }
    int height() const { return height_; }

  private:
    TextureHandle id_;
    int width_ = 0, height_ = 0;
};

}  // namespace rt::gl
