#include "core/tessellate.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace rt {

TriangleMesh tessellate_unit_sphere(int segments) {
    const int slices = std::max(3, segments);
    const int stacks = std::max(2, segments / 2);
    TriangleMesh mesh;
    mesh.name = "sphere" + std::to_string(slices);
    const float pi = std::numbers::pi_v<float>;
    for (int i = 0; i <= stacks; ++i) {
        const float theta = pi * static_cast<float>(i) / static_cast<float>(stacks);
        for (int j = 0; j <= slices; ++j) {
            const float phi = 2.0f * pi * static_cast<float>(j) / static_cast<float>(slices);
            mesh.positions.push_back({std::sin(theta) * std::cos(phi), std::cos(theta),
                                      -std::sin(theta) * std::sin(phi)});
        }
    }
    const auto at = [&](int i, int j) { return static_cast<std::uint32_t>(i * (slices + 1) + j); };
    for (int i = 0; i < stacks; ++i) {
        for (int j = 0; j < slices; ++j) {
            if (i > 0) mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
            if (i < stacks - 1)
                mesh.triangles.push_back({at(i, j + 1), at(i + 1, j), at(i + 1, j + 1)});
        }
    }
    for (const auto& tri : mesh.triangles)
        for (int k = 0; k < 3; ++k) mesh.corner_normals.push_back(mesh.positions[tri[k]]);
    return mesh;
}

int sphere_segments_for(float radius_pixels) {
    if (!(radius_pixels > 0.25f)) return 12;
    const float n = std::numbers::pi_v<float> / std::acos(1.0f - 0.25f / radius_pixels);
    // Beyond some 8e6 pixels the cosine rounds to 1 and n to infinity: clamped as a float,
    // before the cast (infinity cast to int is undefined).
    return static_cast<int>(std::ceil(std::clamp(n, 12.0f, 256.0f)));
}

float projected_radius_pixels(const Camera& camera, const vec3& centre, float radius) {
    const float depth = glm::dot(camera.eye - centre, camera.n);  // along the view axis
    const float distance = glm::length(camera.eye - centre);
    // Wholly behind the eye it is not seen: the coarsest mesh will do. (A cube map's faces
    // look every way: from inside many_spheres' field of 1601 balls, half of them behind a
    // face and a row across its eye plane were drawn at the finest level, 65k triangles each.)
    if (depth < -radius * 1.01f) return 0.0f;
    if (distance <= radius * 1.01f) return 1e6f;  // around the eye
    // Across the eye plane, off to the side: no nearer than its nearest point.
    const float nearest = depth > radius ? depth - radius : distance - radius;
    const float pixels_per_unit =
        camera.N / nearest * static_cast<float>(camera.rows) / (2.0f * camera.H);
    return radius * pixels_per_unit;
}

TriangleMesh plane_quad(const Plane& plane, const vec3& around, float extent) {
    vec3 t1, t2;
    tangent_frame(plane.normal, t1, t2);
    const vec3 centre = around - (glm::dot(around, plane.normal) - plane.offset) * plane.normal;
    TriangleMesh mesh;
    mesh.name = "plane";
    mesh.positions = {centre - extent * t1 - extent * t2, centre + extent * t1 - extent * t2,
                      centre + extent * t1 + extent * t2, centre - extent * t1 + extent * t2};
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    mesh.corner_normals.assign(6, plane.normal);
    return mesh;
}

namespace {

TriangleMesh triangles_of(const Sphere& s, int segments) {
    TriangleMesh mesh = tessellate_unit_sphere(segments);
    for (vec3& p : mesh.positions) p = s.centre + s.radius * p;  // normals stay as they are
    return mesh;
}
TriangleMesh triangles_of(const Triangle& t, int) {
    TriangleMesh mesh;
    mesh.positions = {t.a, t.b, t.c};
    mesh.triangles = {{0, 1, 2}};
    return mesh;
}
TriangleMesh triangles_of(const MeshInstance& m, int) {
    TriangleMesh mesh;
    mesh.name = m.mesh.name;
    mesh.positions = m.mesh.positions;
    mesh.triangles = m.mesh.triangles;
    mesh.corner_normals = m.mesh.corner_normals;
    mesh.corner_uvs = m.mesh.corner_uvs;
    mesh.corner_colours = m.mesh.corner_colours;
    if (m.own_materials) mesh.materials = m.mesh.materials;
    return mesh;
}
TriangleMesh triangles_of(const Plane&, int) { return {}; }

}  // namespace

TriangleMesh object_triangles(const std::vector<TriangleMesh>& meshes, const Object& object,
                              int sphere_segments) {
    return visit_shape(meshes, object,
                       [&](const auto& shape) { return triangles_of(shape, sphere_segments); });
}

}  // namespace rt
