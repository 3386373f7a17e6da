#pragma once
// Off-screen render targets at the tracer's resolution, and their read-back into
// core's plain data (rt::Image, rt::ItemBuffer), bottom row first like GL.

#include <cstddef>
#include <cstdint>

#include "app/gl/gl.h"
#include "app/gl/handle.h"
#include "core/image.h"
#include "core/item_buffer.h"

namespace rt::gl {

// How a target holds the item buffer's two ids. Objects only: a scene without a mesh
// (only a mesh's pixels need their triangle; the read-back names triangle 0 everywhere).
// Packed: one R32UI target of (object id << prim_bits) | triangle, where every mesh's
// triangles fit below the bits the object ids need: one target written, cleared and read
// instead of two. Separate: a second R32UI target of triangle indices, where they do not
// fit. The shaders take prim_bits (0 unless packed) as u_prim_bits.
struct IdLayout {
    enum class Kind { kObjectsOnly, kPacked, kSeparate };
    Kind kind = Kind::kSeparate;
    int prim_bits = 0;  // kPacked: the triangle's share of the 32 bits

    // For a scene of `objects` objects (ids 1 to objects) whose largest mesh has
    // `most_triangles` triangles (0: no mesh).
    static IdLayout for_scene(std::size_t objects, std::size_t most_triangles);
    bool second_target() const { return kind == Kind::kSeparate; }
    std::uint32_t shader_prim_bits() const {
        return kind == Kind::kPacked ? static_cast<std::uint32_t>(prim_bits) : 0u;
    }
};

class Framebuffer {
  public:
    enum class Kind {
        kColour,       // one RGBA32F attachment: linear colour, read back unencoded
        kItemBuffer,   // R32UI attachments: object id + 1, then any triangle index (IdLayout)
        kDistance,     // one R32F attachment: a distance (shadow maps), cleared to "far"
        kColourAndIds  // both of the first two in one draw (one sample only): the raster
                       // image and its item buffer from the same pass
    };

    // `samples` > 1 (colour only): drawn multisampled, into renderbuffers; resolve()
    // averages the samples into the texture that texture() and the reads see.
    // Unless `ids` has a second target, there is no triangle attachment at all (drawing,
    // clearing and reading a second id target cost many_spheres' raster frame about 1.5 ms
    // on llvmpipe, and it held 3.7 MB at 1280 x 720).
    Framebuffer(Kind kind, int width, int height, int samples = 1, IdLayout ids = {});

    int width() const { return width_; }
    int height() const { return height_; }
    int samples() const { return samples_; }
    const IdLayout& ids() const { return ids_; }
    void resolve() const;  // after drawing; nothing to do with one sample
    // The colour attachments are textures, so a later pass can sample them.
    GLuint texture(int attachment = 0) const { return colour_[attachment].get(); }
    void bind() const;  // as the draw target, with the viewport set, depth (and ids) cleared
    // Whether draws write the ids (kItemBuffer, kColourAndIds): off for what the tracer
    // does not see (lines and points), on again after.
    void draw_ids(bool on) const;

    Image read_colour() const;
    void read_colour(Image& into) const;  // into's storage reused (Image::resize)
    ItemBuffer read_item_buffer() const;
    // The item buffer's read-back started into a pixel buffer object and finished later,
    // so that the CPU can do other work while a GPU copies (kItemBuffer, kColourAndIds).
    // The buffer is the framebuffer's own, made once: finish a read before the next
    // starts, and before the framebuffer goes or is drawn into again. Where the rasteriser
    // runs on the CPU (llvmpipe, softpipe), nothing copies while the CPU works, and the
    // buffer is a second copy of the ids (0.2 ms at 1280 x 720 here): there `kAuto` reads
    // them at finish, straight into the caller's storage.
    enum class IdReads { kAuto, kPixelBuffer, kDirect };
    class ItemBufferRead {
      public:
        // Waits for the copy and maps the buffer, or (read straight) reads the ids now.
        ItemBuffer finish();
        void finish(ItemBuffer& into);  // into's storage reused (ItemBuffer::resize)

      private:
        friend class Framebuffer;
        ItemBufferRead(const Framebuffer& fb, bool direct) : fb_(fb), direct_(direct) {}
        const Framebuffer& fb_;
        bool direct_;
    };
    ItemBufferRead start_item_buffer_read(IdReads how = IdReads::kAuto) const;
    // One pixel (x, y from the bottom left): a colour, or an item buffer's object id + 1
    // (unpacked).
    vec3 read_pixel(int x, int y) const;
    std::uint32_t read_id(int x, int y) const;

  private:
    int id_attachment() const { return kind_ == Kind::kColourAndIds ? 1 : 0; }
    // glReadPixels of the id target into `objects` and of any triangles' target into
    // `triangles`: the caller's memory, or offsets into the bound pixel-pack buffer.
    void read_ids(void* objects, void* triangles) const;

    Kind kind_;
    int width_, height_, samples_;
    IdLayout ids_;
    FramebufferHandle fbo_;
    TextureHandle colour_[3];
    RenderbufferHandle depth_;
    FramebufferHandle ms_fbo_;  // samples > 1: what is drawn into
    RenderbufferHandle ms_colour_, ms_depth_;
    BufferHandle ids_pbo_;   // the item buffer's read-back (objects, then any triangles)
    bool software_ = false;  // GL_RENDERER is a rasteriser on the CPU (IdReads::kAuto)
};

}  // namespace rt::gl
