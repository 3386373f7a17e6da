#pragma once
// The rays of a picked pixel drawn in the scene: line segments, one colour per kind,
// depth-tested against the raster pass's surfaces, into a transparent layer of their own
// that the compositor lays over any view. Drawn again only when the camera or the rays
// change, so that they stay in the scene while the user orbits.

#include <optional>
#include <vector>

#include "app/gl/framebuffer.h"
#include "app/gl/handle.h"
#include "app/gl/program.h"
#include "app/gl/raster_renderer.h"
#include "core/ray_tree.h"

namespace rt::gl {

class RayOverlay {
  public:
    static constexpr float kWidth = 3.0f;  // pixels

    explicit RayOverlay(const std::filesystem::path& shaders = shader_dir());

    void set(std::vector<RaySegment> segments);
    void clear() { set({}); }
    bool empty() const { return segments_.empty(); }

    // The layer for `camera` (RGBA32F, linear, premultiplied by nothing: alpha 0 where no
    // ray is): the scene's depth from `raster`, then the rays.
    GLuint texture(RasterRenderer& raster, const Camera& camera);

    // A kind's colour (linear RGB); blocked feelers are drawn dimmed.
    static vec3 colour(RayKind kind);

  private:
    Program program_;
    VertexArrayHandle vao_;
    BufferHandle vbo_;
    std::vector<RaySegment> segments_;
    std::optional<Framebuffer> target_;
    std::optional<Camera> drawn_for_;  // what the layer holds
};

}  // namespace rt::gl
