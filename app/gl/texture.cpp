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

void Texture::upload_row(const std::vector<vec3>& colours) {
    Image row(static_cast<int>(colours.size()), 1);
    row.pixels = colours;
    upload(row);
}

}  // namespace rt::gl
