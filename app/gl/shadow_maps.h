#pragma once
// Shadow maps for the raster view: for each point light a cube of six depth views (90
// degrees each) from the light, holding the distance to the nearest surface, packed into
// one R32F atlas (faces across, lights down) so that GLSL 3.30 samples them through one
// sampler. phong.frag picks the face by the direction's major axis, compares distances
// with a slope-scaled bias and filters 3 x 3 texels (percentage-closer filtering).
// RasterRenderer draws them once, when they are asked for or their size changes: the
// camera never changes them.

#include <array>
#include <optional>

#include <glm/mat4x4.hpp>

#include "app/gl/framebuffer.h"
#include "core/camera.h"

namespace rt::gl {

class ShadowMaps {
  public:
    static constexpr int kMaxLights = 16;       // as RasterRenderer
    static constexpr int kMaxAtlasRows = 8192;  // texels: more lights share it at lower resolution

    // Rows for the first `light_count` lights (a directional one's stays empty: lit);
    // `size`: texels per face side, as asked (lowered where the lights would not fit).
    ShadowMaps(int light_count, int size);

    const Framebuffer& atlas() const { return *atlas_; }
    GLuint texture() const { return atlas_->texture(); }
    int asked() const { return asked_; }
    int size() const { return size_; }
    int lights() const { return lights_; }  // the first `lights` lights have maps
    // Light-relative direction to a face's clip space, the same for every light.
    const std::array<glm::mat4, 6>& faces() const { return faces_; }

    // Each face's camera, at `light` (core's Camera, so the raster's matrices and level of
    // detail apply unchanged).
    static Camera face_camera(const vec3& light, int face, int size);

  private:
    int asked_ = 0, size_ = 0, lights_ = 0;
    std::optional<Framebuffer> atlas_;
    std::array<glm::mat4, 6> faces_{};
};

}  // namespace rt::gl
