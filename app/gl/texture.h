#pragma once
// A 2D texture holding an rt::Image (linear RGB floats), re-specified when its size changes.

#include "app/gl/gl.h"
#include "core/image.h"

namespace rt::gl {

class Texture {
  public:
    Texture();
    ~Texture();
    Texture(const Texture&) = delete;
    Texture& operator=(const Texture&) = delete;

    void upload(const Image& image);
    // A row of colours (a palette or a colour map), sampled by index or by t in [0, 1].
    void upload_row(const std::vector<vec3>& colours);
    GLuint id() const { return id_; }
    int width() const { return width_; }
    int height() const { return height_; }

  private:
    GLuint id_ = 0;
    int width_ = 0, height_ = 0;
};

}  // namespace rt::gl
