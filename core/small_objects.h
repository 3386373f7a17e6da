#pragma once
// The objects too small on the screen for the item buffer to speak for them. The raster's
// outlines lie within a quarter pixel of the true ones (ItemBuffer::interior), but an
// object a few pixels across may show only a pixel or two (under a pixel across, or a
// crescent a pixel wide where a nearer object hides the rest: many_spheres at 333 x 211),
// and the raster may then cover none of their centres, so that no pixel around names the
// object either. The renderer tests these objects itself at the pixels of their screen
// boxes (core/renderer.cpp, item_buffer_run). Under four pixels across left many_spheres'
// crescents out (7 of 70,263 pixels unlike a trace without the item buffer); under six,
// none (docs/BENCHMARKS.md, seventeenth session).

#include <cstdint>
#include <span>
#include <vector>

#include "core/camera.h"
#include "core/scene.h"

namespace rt {

class SmallObjects {
  public:
    // An object's pixels: columns x0 .. x1 of the rows it covers.
    struct Span {
        std::uint32_t object;
        int x0, x1;
    };
    // Objects whose box, seen by `camera`, is under kPixels across both ways (and wholly in
    // front of the eye), each with its box's pixels and a pixel more all round.
    static constexpr float kPixels = 6.0f;

    SmallObjects() = default;
    SmallObjects(const Scene& scene, const Camera& camera);

    bool empty() const { return spans_.empty(); }
    std::size_t size() const { return objects_; }
    // The small objects on row y, with their columns there.
    std::span<const Span> row(int y) const {
        if (spans_.empty() || y < 0 || y + 1 >= static_cast<int>(row_start_.size())) return {};
        return std::span<const Span>(spans_).subspan(row_start_[y],
                                                     row_start_[y + 1] - row_start_[y]);
    }

  private:
    std::vector<std::uint32_t> row_start_;  // rows + 1: row y's spans are [start[y], start[y + 1])
    std::vector<Span> spans_;
    std::size_t objects_ = 0;
};

}  // namespace rt
