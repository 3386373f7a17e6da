#pragma once
// Triangle meshes for the analytic shapes, for the raster pipeline (no GL here: the
// GL side uploads what these return).

#include "core/camera.h"
#include "core/mesh.h"
#include "core/scene.h"
#include "core/shapes.h"

namespace rt {

// A unit sphere at the origin as a latitude/longitude mesh with `segments` slices
// around and segments / 2 stacks; vertices lie on the sphere, normals are exact.
TriangleMesh tessellate_unit_sphere(int segments);

// Enough slices around that a sphere of `radius_pixels` on screen differs from its
// polygon by at most a quarter pixel: r (1 - cos(pi / n)) <= 1/4. Between 12 and 256.
int sphere_segments_for(float radius_pixels);

// The on-screen radius, in pixels, of a sphere of `radius` at `centre` (world space).
float projected_radius_pixels(const Camera& camera, const vec3& centre, float radius);

// An object's shape as triangles in its own (object) space: a sphere as a latitude/
// longitude mesh of `sphere_segments`, a triangle as itself, a mesh as its triangles
// (with its per-triangle materials); a plane has none (unbounded: the raster view draws
// plane_quad under the eye). What rtbench's flattened scene and the raster view's
// single triangles are made of.
TriangleMesh object_triangles(const std::vector<TriangleMesh>& meshes, const Object& object,
                              int sphere_segments);

// A square of the plane, half-size `extent`, centred on the point of the plane nearest
// to `around`, as two triangles in the plane's own (object) space.
TriangleMesh plane_quad(const Plane& plane, const vec3& around, float extent);

}  // namespace rt
