#pragma once
// Cube maps for the raster's classic tricks, packed into one 2D atlas (faces across, one
// row per cube) so that GLSL 3.30 samples any of them through one sampler:
// - shadow maps: per point light, six 90-degree views from the light holding the
//   distance to the nearest surface (R32F); phong.frag compares distances with a
//   slope-scaled bias and filters 3 x 3 texels (percentage-closer filtering);
// - environment maps: per mirror or glass object, six views from its centre of the rest
//   of the scene (RGBA32F), looked up along the reflected and refracted directions.
// phong.frag picks a direction's face by its major axis. RasterRenderer draws them only
// when they are switched on or resized: the camera never changes them.

#include <array>
#include <optional>

#include <glm/mat4x4.hpp>

#include "app/gl/framebuffer.h"
#include "core/camera.h"

namespace rt::gl {

class CubeAtlas {
  public:
    static constexpr int kMaxRows = 16;         // cubes
    static constexpr int kMaxAtlasRows = 8192;  // texels: more cubes share it at lower resolution

    // `rows` cubes of `size` texels a face side (lowered where they would not fit), of
    // distances (Framebuffer::Kind::kDistance) or colours (kColour).
    CubeAtlas(Framebuffer::Kind kind, int rows, int size);

    const Framebuffer& atlas() const { return *atlas_; }
    GLuint texture() const { return atlas_->texture(); }
    int asked() const { return asked_; }
    int size() const { return size_; }
    int rows() const { return rows_; }
    // Direction from the cube's centre to a face's clip space, the same for every cube.
    const std::array<glm::mat4, 6>& faces() const { return faces_; }

    // Each face's camera at `centre` (core's Camera, so the raster's matrices and level of
    // detail apply unchanged).
    static Camera face_camera(const vec3& centre, int face, int size);

  private:
    int asked_ = 0, size_ = 0, rows_ = 0;
    std::optional<Framebuffer> atlas_;
    std::array<glm::mat4, 6> faces_{};
};

}  // namespace rt::gl
