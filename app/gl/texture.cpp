#include "app/gl/texture.h"

#include "app/gl/debug.h"

namespace rt::gl {

Texture::Texture() : id_(make_texture()) {
    glBindTexture(GL_TEXTURE_2D, id_.get());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);  // coarse pixels stay square
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

void Texture::upload(const Image& image) {
    glBindTexture(GL_TEXTURE_2D, id_.get());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    if (image.width != width_ || image.height != height_) {
        width_ = image.width;
        height_ = image.height;
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F, width_, height_, 0, GL_RGB, GL_FLOAT,
                     image.pixels.data());
    } else {
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width_, height_, GL_RGB, GL_FLOAT,
                        image.pixels.data());
    }
    check("Texture::upload");
}

void Texture::upload_surface(const rt::Texture& texture) {
    glBindTexture(GL_TEXTURE_2D, id_.get());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    width_ = texture.width;
    height_ = texture.height;
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F, width_, height_, 0, GL_RGB, GL_FLOAT,
                 texture.texels.data());
    const auto wrap = [](Wrap w) {
        return w == Wrap::kClamp    ? GL_CLAMP_TO_EDGE
               : w == Wrap::kMirror ? GL_MIRRORED_REPEAT
                                    : GL_REPEAT;
    };
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap(texture.wrap_u));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap(texture.wrap_v));
    check("Texture::upload_surface");
}

void Texture::upload_row(const std::vector<vec3>& colours) {
    Image row(static_cast<int>(colours.size()), 1);
    row.pixels = colours;
    upload(row);
}

void Texture::upload_from_buffer(GLuint buffer, int width, int height) {
    glBindTexture(GL_TEXTURE_2D, id_.get());
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, buffer);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    width_ = width;
    height_ = height;
}

}  // namespace rt::gl
