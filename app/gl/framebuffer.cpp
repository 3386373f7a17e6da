#include "app/gl/framebuffer.h"

#include <stdexcept>
#include <string>
#include <vector>

#include "app/gl/debug.h"

namespace rt::gl {

Framebuffer::Framebuffer(Kind kind, int width, int height)
    : kind_(kind), width_(width), height_(height), fbo_(make_framebuffer()) {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.get());
    const int attachments = kind == Kind::kColour ? 1 : 2;
    for (int i = 0; i < attachments; ++i) {
        colour_[i] = make_texture();
        glBindTexture(GL_TEXTURE_2D, colour_[i].get());
        const bool colour = kind == Kind::kColour;
        glTexImage2D(GL_TEXTURE_2D, 0, colour ? GL_RGBA32F : GL_R32UI, width, height, 0,
                     colour ? GL_RGBA : GL_RED_INTEGER, colour ? GL_FLOAT : GL_UNSIGNED_INT,
                     nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i),
                               GL_TEXTURE_2D, colour_[i].get(), 0);
    }
    depth_ = make_renderbuffer();
    glBindRenderbuffer(GL_RENDERBUFFER, depth_.get());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.get());
    const GLenum draw[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glDrawBuffers(attachments, draw);
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("framebuffer incomplete (status " + std::to_string(status) + ")");
    check("Framebuffer");
}

void Framebuffer::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.get());
    glViewport(0, 0, width_, height_);
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    if (kind_ == Kind::kItemBuffer) {
        const GLuint zero[4] = {0, 0, 0, 0};
        glClearBufferuiv(GL_COLOR, 0, zero);
        glClearBufferuiv(GL_COLOR, 1, zero);
    }
}

Image Framebuffer::read_colour() const {
    Image image(width_, height_);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.get());
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width_, height_, GL_RGB, GL_FLOAT, image.pixels.data());
    check("read_colour");
    return image;
}

vec3 Framebuffer::read_pixel(int x, int y) const {
    vec3 c(0.0f);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.get());
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(x, y, 1, 1, GL_RGB, GL_FLOAT, &c.x);
    check("read_pixel");
    return c;
}

std::uint32_t Framebuffer::read_id(int x, int y) const {
    std::uint32_t id = 0;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.get());
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(x, y, 1, 1, GL_RED_INTEGER, GL_UNSIGNED_INT, &id);
    check("read_id");
    return id;
}

ItemBuffer Framebuffer::read_item_buffer() const {
    ItemBuffer ib(width_, height_);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.get());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glReadPixels(0, 0, width_, height_, GL_RED_INTEGER, GL_UNSIGNED_INT, ib.object.data());
    glReadBuffer(GL_COLOR_ATTACHMENT1);
    glReadPixels(0, 0, width_, height_, GL_RED_INTEGER, GL_UNSIGNED_INT, ib.prim.data());
    check("read_item_buffer");
    return ib;
}

}  // namespace rt::gl
