#include "app/gl/framebuffer.h"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/gl/debug.h"

namespace rt::gl {

namespace {
// A rasteriser that runs on the CPU, where a pixel buffer object copies nothing in the
// background (Mesa's llvmpipe and softpipe; "swrast" in older names).
bool software_renderer() {
    const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    if (!name) return false;
    const std::string renderer(name);
    for (const char* cpu : {"llvmpipe", "softpipe", "swrast"})
        if (renderer.find(cpu) != std::string::npos) return true;
    return false;
}

void require_complete(const char* what) {
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error(std::string(what) + " incomplete (status " +
                                 std::to_string(status) + ")");
}
}  // namespace

IdLayout IdLayout::for_scene(std::size_t objects, std::size_t most_triangles) {
    if (most_triangles == 0) return {Kind::kObjectsOnly, 0};
    const int prim_bits = 32 - static_cast<int>(std::bit_width(objects));
    if (prim_bits >= 1 && most_triangles <= (std::uint64_t{1} << prim_bits))
        return {Kind::kPacked, prim_bits};
    return {Kind::kSeparate, 0};
}

Framebuffer::Framebuffer(Kind kind, int width, int height, int samples, IdLayout ids)
    : kind_(kind),
      width_(width),
      height_(height),
      samples_(kind == Kind::kColour ? std::max(1, samples) : 1),
      ids_(ids),
      fbo_(make_framebuffer()) {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.get());
    // The colour (all but kItemBuffer), the ids (kItemBuffer, kColourAndIds), and the
    // triangles' own target only where the layout has one.
    const bool has_ids = kind == Kind::kItemBuffer || kind == Kind::kColourAndIds;
    const int attachments =
        (kind == Kind::kItemBuffer ? 0 : 1) + (has_ids ? 1 + (ids.second_target() ? 1 : 0) : 0);
    for (int i = 0; i < attachments; ++i) {
        colour_[i] = make_texture();
        glBindTexture(GL_TEXTURE_2D, colour_[i].get());
        if (kind == Kind::kColour || (kind == Kind::kColourAndIds && i == 0))
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT,
                         nullptr);
        else if (kind == Kind::kDistance)
            glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, width, height, 0, GL_RED, GL_FLOAT, nullptr);
        else
            glTexImage2D(GL_TEXTURE_2D, 0, GL_R32UI, width, height, 0, GL_RED_INTEGER,
                         GL_UNSIGNED_INT, nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i),
                               GL_TEXTURE_2D, colour_[i].get(), 0);
    }
    depth_ = make_renderbuffer();
    glBindRenderbuffer(GL_RENDERBUFFER, depth_.get());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.get());
    const GLenum draw[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
    glDrawBuffers(attachments, draw);
    require_complete("framebuffer");
    if (has_ids) draw_ids(true);
    if (samples_ > 1) {
        GLint most = 1;
        glGetIntegerv(GL_MAX_SAMPLES, &most);
        if (samples_ > most)
            throw std::runtime_error(std::to_string(samples_) + "x MSAA: this GL offers at most " +
                                     std::to_string(most) + " samples");
        ms_fbo_ = make_framebuffer();
        glBindFramebuffer(GL_FRAMEBUFFER, ms_fbo_.get());
        ms_colour_ = make_renderbuffer();
        glBindRenderbuffer(GL_RENDERBUFFER, ms_colour_.get());
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_RGBA32F, width, height);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                  ms_colour_.get());
        ms_depth_ = make_renderbuffer();
        glBindRenderbuffer(GL_RENDERBUFFER, ms_depth_.get());
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_DEPTH_COMPONENT32F, width,
                                         height);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                  ms_depth_.get());
        require_complete("multisampled framebuffer");
    }
    if (has_ids) {
        // Storage once: a fresh buffer each read cost fresh pages each frame.
        ids_pbo_ = make_buffer();
        glBindBuffer(GL_PIXEL_PACK_BUFFER, ids_pbo_.get());
        glBufferData(GL_PIXEL_PACK_BUFFER,
                     static_cast<GLsizeiptr>(width) * height * (ids.second_target() ? 8 : 4),
                     nullptr, GL_STREAM_READ);
        glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
        software_ = software_renderer();
    }
    check("Framebuffer");
}

void Framebuffer::resolve() const {
    if (samples_ <= 1) return;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, ms_fbo_.get());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo_.get());
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.get());
    check("Framebuffer::resolve");
}

void Framebuffer::draw_ids(bool on) const {
    const int ids = id_attachment();
    GLenum draw[3] = {ids == 1 ? GLenum{GL_COLOR_ATTACHMENT0} : GLenum{GL_NONE}, GL_NONE, GL_NONE};
    if (on) draw[ids] = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(ids);
    if (on && ids_.second_target())
        draw[ids + 1] = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(ids + 1);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo_.get());
    glDrawBuffers(ids + 2, draw);
}

void Framebuffer::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, samples_ > 1 ? ms_fbo_.get() : fbo_.get());
    glViewport(0, 0, width_, height_);
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    if (kind_ == Kind::kDistance) {
        const GLfloat far[4] = {3.0e38f, 0.0f, 0.0f, 0.0f};
        glClearBufferfv(GL_COLOR, 0, far);
    }
    if (kind_ == Kind::kItemBuffer || kind_ == Kind::kColourAndIds) {
        const GLuint zero[4] = {0, 0, 0, 0};
        glClearBufferuiv(GL_COLOR, id_attachment(), zero);
        if (ids_.second_target()) glClearBufferuiv(GL_COLOR, id_attachment() + 1, zero);
    }
}

Image Framebuffer::read_colour() const {
    Image image;
    read_colour(image);
    return image;
}

void Framebuffer::read_colour(Image& image) const {
    image.resize(width_, height_);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.get());
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width_, height_, GL_RGB, GL_FLOAT, image.pixels.data());
    check("read_colour");
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
    glReadBuffer(GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(id_attachment()));
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(x, y, 1, 1, GL_RED_INTEGER, GL_UNSIGNED_INT, &id);
    check("read_id");
    return id >> ids_.shader_prim_bits();
}

ItemBuffer Framebuffer::read_item_buffer() const { return start_item_buffer_read().finish(); }

void Framebuffer::read_ids(void* objects, void* triangles) const {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.get());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    for (int k = 0; k < (ids_.second_target() ? 2 : 1); ++k) {
        glReadBuffer(GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(id_attachment() + k));
        glReadPixels(0, 0, width_, height_, GL_RED_INTEGER, GL_UNSIGNED_INT,
                     k == 0 ? objects : triangles);
    }
}

// The id attachments into the framebuffer's pixel buffer, objects then any triangles:
// glReadPixels into a bound pixel-pack buffer returns at once on a GPU, the copy going on
// while the CPU works. Directly: nothing until finish.
Framebuffer::ItemBufferRead Framebuffer::start_item_buffer_read(IdReads how) const {
    const bool direct = how == IdReads::kDirect || (how == IdReads::kAuto && software_);
    if (!direct) {
        const std::uintptr_t bytes = static_cast<std::uintptr_t>(width_) * height_ * 4;
        glBindBuffer(GL_PIXEL_PACK_BUFFER, ids_pbo_.get());
        read_ids(nullptr, reinterpret_cast<void*>(bytes));  // offsets into the buffer
        glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
        check("start_item_buffer_read");
    }
    return ItemBufferRead(*this, direct);
}

ItemBuffer Framebuffer::ItemBufferRead::finish() {
    ItemBuffer ib;
    finish(ib);
    return ib;
}

// As the targets hold them: packed ids stay packed (ItemBuffer::ids), objects alone are
// packed ids of no triangle bits, and only separate triangles fill ib.prim.
void Framebuffer::ItemBufferRead::finish(ItemBuffer& ib) {
    const IdLayout& layout = fb_.ids_;
    ib.resize(fb_.width_, fb_.height_, static_cast<int>(layout.shader_prim_bits()),
              layout.second_target());
    const std::size_t count = ib.ids.size();
    if (direct_) {
        fb_.read_ids(ib.ids.data(), ib.prim.data());
        check("ItemBufferRead::finish");
        return;
    }
    glBindBuffer(GL_PIXEL_PACK_BUFFER, fb_.ids_pbo_.get());
    const std::size_t targets = layout.second_target() ? 2 : 1;
    const void* data = glMapBufferRange(
        GL_PIXEL_PACK_BUFFER, 0, static_cast<GLsizeiptr>(targets * count * 4), GL_MAP_READ_BIT);
    if (data) {
        const auto* words = static_cast<const std::uint32_t*>(data);
        std::copy(words, words + count, ib.ids.begin());
        if (layout.second_target()) std::copy(words + count, words + 2 * count, ib.prim.begin());
        glUnmapBuffer(GL_PIXEL_PACK_BUFFER);
    }
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    check("ItemBufferRead::finish");
    if (!data) throw std::runtime_error("item buffer: the pixel buffer could not be mapped");
}

}  // namespace rt::gl
