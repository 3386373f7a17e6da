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
//
// So may a sphere cut by the image's edge: where its true outline reaches into the
// outermost row or column by less than the raster's quarter pixel, no pixel of the image
// names it, and the pixels it covers there have no neighbour beyond the edge to put them
// on an edge (many_spheres at 1280 x 720: two pixels of its right-hand column). Such a
// sphere is tested at the outermost pixels along its box where it reaches in by under two
// pixels (its outline's own extents; an ellipsoid, or a sphere across the eye's plane,
// wherever its box crosses the edge). A mesh, a triangle or a plane is drawn as it is:
// where it covers a pixel's centre, the raster names it there.

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
    // front of the eye), each with its box's pixels and a pixel more all round; and spheres
    // cut by the image's edge, with the outermost pixels along them.
    static constexpr float kPixels = 6.0f;

    SmallObjects() = default;
    SmallObjects(const Scene& scene, const Camera& camera);

    bool empty() const { return spans_.empty() && side_spans_.empty(); }
    std::size_t size() const { return objects_; }  // the small ones
    // The objects on row y, with their columns there; but those on the image's first and
    // last columns only (the spheres cut by its left and right sides), apart in side(y),
    // which only the runs at those columns need.
    std::span<const Span> row(int y) const { return of_row(row_start_, spans_, y); }
    std::span<const Span> side(int y) const { return of_row(side_start_, side_spans_, y); }

  private:
    static std::span<const Span> of_row(const std::vector<std::uint32_t>& start,
                                        const std::vector<Span>& spans, int y) {
        if (spans.empty() || y < 0 || y + 1 >= static_cast<int>(start.size())) return {};
        return std::span<const Span>(spans).subspan(start[y], start[y + 1] - start[y]);
    }

    // rows + 1 each: row y's spans are [start[y], start[y + 1])
    std::vector<std::uint32_t> row_start_, side_start_;
    std::vector<Span> spans_, side_spans_;
    std::size_t objects_ = 0;
};

}  // namespace rt
