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
// Where the scene's coordinates lie in the file's: a point p is origin + scale * p
// (LoadedScene::origin and LoadedScene::scale).
struct FileFrame {
    glm::dvec3 origin{0.0};
    double scale = 1.0;
};

// Points, directions and distances are printed in the scene file's units.
void print_ray_tree(const Scene& scene, const RayNode& root, int x, int y, const FileFrame& file);
void write_ray_tree_json(const RayNode& root, int x, int y, const std::string& path,
                         const FileFrame& file);

}  // namespace rt::renderer
