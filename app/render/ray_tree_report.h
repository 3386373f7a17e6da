#pragma once
// rtrender --ray-tree X,Y: the rays one pixel spawned, printed one a line (indented by
// depth) and, with --ray-tree-json FILE, written as JSON.

#include <string>

#include <glm/vec3.hpp>

#include "core/ray_tree.h"
#include "core/scene.h"
#include "core/tracer.h"

namespace rt::renderer {

// X, Y from the image's top-left; throws rt::Error when they are outside the camera.
RayNode trace_pixel_tree(const Scene& scene, const Camera& camera, const TraceOptions& options,
                         int x, int y);
// Points are printed in the scene file's coordinates: `origin` is LoadedScene::origin.
void print_ray_tree(const Scene& scene, const RayNode& root, int x, int y,
                    const glm::dvec3& origin);
void write_ray_tree_json(const RayNode& root, int x, int y, const std::string& path,
                         const glm::dvec3& origin);

}  // namespace rt::renderer
