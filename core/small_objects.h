#pragma once
// The objects too small on the screen for the item buffer to speak for them: under a
// few pixels across, the raster (a sphere's tessellation, a triangle's sample points) may
// cover none of the pixel centres the true shape covers, and then no pixel around names
// the object either (ItemBuffer::interior). The renderer tests these objects itself at
// the pixels of their screen boxes (core/renderer.cpp, item_buffer_run).

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
    static constexpr float kPixels = 4.0f;

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
