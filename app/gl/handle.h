#pragma once
// OpenGL object names that delete themselves: movable, never copied, so a constructor
// that throws after creating one leaks nothing, and classes that hold them are movable
// values (no unique_ptr needed to keep a name from being deleted twice).
//
//   BufferHandle vbo = make_buffer();      glBindBuffer(GL_ARRAY_BUFFER, vbo.get());

#include <utility>

#include "app/gl/gl.h"

namespace rt::gl {

template <class Kind>
class Handle {
  public:
    Handle() = default;
    explicit Handle(GLuint id) : id_(id) {}
    ~Handle() { reset(); }
    Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
    Handle& operator=(Handle&& other) noexcept {
        if (this != &other) {
            reset();
            id_ = std::exchange(other.id_, 0);
        }
        return *this;
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;

    GLuint get() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    void reset() {
        if (id_ != 0) Kind::destroy(id_);
        id_ = 0;
    }

  private:
    GLuint id_ = 0;
};

struct BufferKind {
    static void destroy(GLuint id) { glDeleteBuffers(1, &id); }
};
struct VertexArrayKind {
    static void destroy(GLuint id) { glDeleteVertexArrays(1, &id); }
};
struct TextureKind {
    static void destroy(GLuint id) { glDeleteTextures(1, &id); }
};
struct FramebufferKind {
    static void destroy(GLuint id) { glDeleteFramebuffers(1, &id); }
};
struct RenderbufferKind {
    static void destroy(GLuint id) { glDeleteRenderbuffers(1, &id); }
};
struct ShaderKind {
    static void destroy(GLuint id) { glDeleteShader(id); }
};
struct ProgramKind {
    static void destroy(GLuint id) { glDeleteProgram(id); }
};

using BufferHandle = Handle<BufferKind>;
using VertexArrayHandle = Handle<VertexArrayKind>;
using TextureHandle = Handle<TextureKind>;
using FramebufferHandle = Handle<FramebufferKind>;
using RenderbufferHandle = Handle<RenderbufferKind>;
using ShaderHandle = Handle<ShaderKind>;
using ProgramHandle = Handle<ProgramKind>;

// A new name from one of GL's glGen* functions, held by a handle of that kind.
template <class Kind>
Handle<Kind> generate(void (*gen)(GLsizei, GLuint*)) {
    GLuint id = 0;
    gen(1, &id);
    return Handle<Kind>(id);
}
inline BufferHandle make_buffer() { return generate<BufferKind>(glGenBuffers); }
inline VertexArrayHandle make_vertex_array() {
    return generate<VertexArrayKind>(glGenVertexArrays);
}
inline TextureHandle make_texture() { return generate<TextureKind>(glGenTextures); }
inline FramebufferHandle make_framebuffer() { return generate<FramebufferKind>(glGenFramebuffers); }
inline RenderbufferHandle make_renderbuffer() {
    return generate<RenderbufferKind>(glGenRenderbuffers);
}

}  // namespace rt::gl
