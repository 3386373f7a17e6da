#pragma once
// The renderer's primary step, a tile's first hits (core/renderer.cpp): from the item
// buffer (Weghorst, Hooper & Greenberg 1984), the ids the raster drew, each pixel tested
// against the object it names and a pixel on an edge against the objects named around
// it; or without it, the camera rays in packets through the scene.

#include <cstdint>
#include <vector>

#include "core/hit.h"
#include "core/item_buffer.h"
#include "core/scene.h"
#include "core/small_objects.h"
#include "core/tile_rays.h"
#include "core/tile_runner.h"

namespace rt::detail {

// The first hits of tile t's pixels (hits[i]: row by row from its top left, as `rays`
// holds them), each the hit Scene::intersect gives its ray but where the raster and the
// tracer disagree at a pixel (at most 0.01 % of them: docs/BENCHMARKS.md). `small`: what
// the ids cannot speak for (core/small_objects.h). Returns how many pixels were on an edge
// or missed what they named.
std::uint64_t item_buffer_hits(const Scene& scene, const ItemBuffer& ib, const SmallObjects& small,
                               const Tile& t, const TileRays& rays, std::vector<Hit>& hits);

// The same tile's first hits without the item buffer: its camera rays through the scene
// kPacketWidth at a time (Scene::intersect_packet), made first into `tile`.
void primary_packets(const Scene& scene, const TileRays& rays, std::vector<Ray>& tile,
                     std::vector<Hit>& hits);

}  // namespace rt::detail
