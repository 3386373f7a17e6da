#include "app/gl/gpu_scene.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "app/gl/debug.h"
#include "core/tessellate.h"

namespace rt::gl {

struct GpuMesh::Vertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec3 face_normal;
    glm::vec2 uv{0.0f};
    glm::vec3 colour{1.0f};
};

namespace {

// Sphere levels of detail: the first at or above what the sphere's size asks for.
constexpr int kSphereLevels[] = {12, 16, 24, 32, 48, 64, 96, 128, 192, 256};

// Where the shader's normalize would underflow or overflow (a sliver's cross product),
// the same direction scaled first; zero stays zero. Other normals go as they are.
glm::vec3 normalizable(const glm::vec3& n) {
    const float square = glm::dot(n, n);
    if (square >= std::numeric_limits<float>::min() && square <= 1e30f) return n;
    const float largest = std::max({std::fabs(n.x), std::fabs(n.y), std::fabs(n.z)});
    return largest > 0.0f && std::isfinite(largest) ? n / largest : glm::vec3(0.0f);
}

float max_scale(const glm::mat4& m) {
    return std::max(
        {glm::length(glm::vec3(m[0])), glm::length(glm::vec3(m[1])), glm::length(glm::vec3(m[2]))});
}

// False when the box lies wholly outside one of the clip volume's side planes or its near
// plane (each a plane in world space: the test is exact for the box, not for what it
// holds). A corner within a hair of a plane counts as inside, so that the GPU's own
// rounding of the same transform cannot put a fragment where the box was left out.
bool box_in_view(const Aabb& box, const glm::mat4& view_projection) {
    unsigned outside_all = 0x1fu;  // x < -w, x > w, y < -w, y > w, z < -w
    for (int corner = 0; corner < 8 && outside_all != 0; ++corner) {
        const glm::vec4 c = view_projection * glm::vec4(box.corner(corner), 1.0f);
        const auto beyond = [&](float a, float b) {  // a > b, with a margin for rounding
            return a - b > 1e-4f * (std::fabs(a) + std::fabs(b));
        };
        const unsigned outside = (beyond(-c.x, c.w) ? 0x01u : 0u) |
                                 (beyond(c.x, c.w) ? 0x02u : 0u) |
                                 (beyond(-c.y, c.w) ? 0x04u : 0u) |
                                 (beyond(c.y, c.w) ? 0x08u : 0u) | (beyond(-c.z, c.w) ? 0x10u : 0u);
        outside_all &= outside;
    }
    return outside_all == 0;
}

}  // namespace

GpuMesh::GpuMesh(const TriangleMesh& mesh, bool smooth_faces) {
    std::vector<Vertex> vertices;
    vertices.reserve(3 * mesh.triangles.size());
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
        const glm::vec3 face = normalizable(mesh.face_normal(t));
        // A triangle of no area (its corners on one line as float has them) the tracer
        // never hits; drawn, rounding in the projection could give it a few fragments
        // without a normal: NaN pixels. Its corners at one point draw nothing, and the
        // triangles after it keep their primitive ids (the item buffer's).
        const bool no_area = face == glm::vec3(0.0f);
        for (int k = 0; k < 3; ++k) {
            const glm::vec3 n =
                normalizable(mesh.corner_normals.empty() ? face : mesh.corner_normals[3 * t + k]);
            const glm::vec2 uv =
                mesh.corner_uvs.empty() ? glm::vec2(0.0f) : mesh.corner_uvs[3 * t + k];
            const glm::vec3 colour =
                mesh.corner_colours.empty() ? glm::vec3(1.0f) : mesh.corner_colours[3 * t + k];
            const glm::vec3 p = mesh.positions[mesh.triangles[t][no_area ? 0 : k]];
            vertices.push_back({p, n, smooth_faces ? n : face, uv, colour});
        }
    }
    upload(vertices);
}

GpuMesh::GpuMesh(const std::vector<glm::vec3>& positions, GLenum mode) : mode_(mode) {
    std::vector<Vertex> vertices;
    vertices.reserve(positions.size());
    for (const glm::vec3& p : positions)
        vertices.push_back({p, glm::vec3(0.0f), glm::vec3(0.0f), glm::vec2(0.0f), glm::vec3(1.0f)});
    upload(vertices);
}

void GpuMesh::upload(const std::vector<Vertex>& vertices) {
    vertex_count_ = static_cast<GLsizei>(vertices.size());
    vao_ = make_vertex_array();
    vbo_ = make_buffer();
    glBindVertexArray(vao_.get());
    glBindBuffer(GL_ARRAY_BUFFER, vbo_.get());
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)),
                 vertices.data(), GL_STATIC_DRAW);
    const std::size_t offsets[] = {offsetof(Vertex, position), offsetof(Vertex, normal),
                                   offsetof(Vertex, face_normal), offsetof(Vertex, uv),
                                   offsetof(Vertex, colour)};
    for (GLuint a = 0; a < 5; ++a) {  // position, normal, face normal, uv, colour
        glEnableVertexAttribArray(a);
        glVertexAttribPointer(a, a == 3 ? 2 : 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                              reinterpret_cast<const void*>(offsets[a]));
    }
    glBindVertexArray(0);
    check("GpuMesh upload");
}

void GpuMesh::draw(GLint first_vertex, GLsizei vertex_count) const {
    glBindVertexArray(vao_.get());
    glDrawArrays(mode_, first_vertex, vertex_count);
}

GpuScene::GpuScene(const Scene& scene) : scene_(scene), bounds_(scene.bounds()) {
    meshes_.reserve(scene.meshes.size());
    for (std::uint32_t m = 0; m < scene.meshes.size(); ++m) {
        const TriangleMesh& mesh = scene.meshes[m];
        meshes_.emplace_back(mesh);
        std::vector<glm::vec3> ends, points;
        for (const glm::uvec2& segment : mesh.segments)
            ends.insert(ends.end(), {mesh.positions[segment[0]], mesh.positions[segment[1]]});
        for (std::uint32_t p : mesh.points) points.push_back(mesh.positions[p]);
        if (!ends.empty()) lines_.try_emplace(m, ends, GL_LINES);
        if (!points.empty()) points_.try_emplace(m, points, GL_POINTS);
    }
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i) {
        if (std::holds_alternative<Triangle>(scene.objects[i].shape))
            triangles_.try_emplace(i, object_triangles(scene.meshes, scene.objects[i], 0));
    }
    quad_.emplace(plane_quad(Plane{{0, 0, 1}, 0}, glm::vec3(0.0f), 1.0f));
}

const GpuMesh& GpuScene::sphere_level(float radius_pixels) {
    const int wanted = sphere_segments_for(radius_pixels);
    const int level = *std::find_if(std::begin(kSphereLevels), std::end(kSphereLevels) - 1,
                                    [&](int l) { return l >= wanted; });
    auto it = spheres_.find(level);
    if (it == spheres_.end())
        it = spheres_.try_emplace(level, tessellate_unit_sphere(level), true).first;
    return it->second;
}

// Far enough that the quad's edge is a fraction of a pixel below the true horizon.
float GpuScene::plane_extent(const Camera& camera) const {
    const float radius = bounds_.empty() ? 1.0f : 0.5f * glm::length(bounds_.extent());
    const glm::vec3 centre = bounds_.empty() ? glm::vec3(0.0f) : bounds_.centre();
    // The floor only keeps a scene of one point, seen from that point, from a zero range.
    return 1000.0f *
           std::max({radius, glm::length(camera.eye - centre), std::numeric_limits<float>::min()});
}

namespace {

// The distance from `eye` to the plane of object `o`, in world space.
float plane_distance(const Plane& p, const Object& o, const glm::vec3& eye) {
    if (!o.transform) return std::fabs(glm::dot(eye, p.normal) - p.offset);
    const glm::vec3 point = o.transform->point_to_world(p.offset * p.normal);
    const glm::vec3 normal = o.transform->normal_to_world(p.normal);
    return std::fabs(glm::dot(eye - point, normal));
}

}  // namespace

DepthRange GpuScene::depth_range(const Camera& camera) const {
    DepthRange range;
    range.far_plane = 3.0f * plane_extent(camera);
    // The near plane as far out as the nearest bounded object allows, for depth precision.
    float nearest = range.far_plane;
    if (!bounds_.empty())
        nearest = glm::length(
            glm::max(glm::max(bounds_.lo - camera.eye, camera.eye - bounds_.hi), glm::vec3(0.0f)));
    // Planes are unbounded: the eye's distance to each (a camera skimming the floor, or
    // under it, must not have the floor clipped at the near plane while the tracer sees it).
    for (const Object& o : scene_.objects)
        if (const auto* p = std::get_if<Plane>(&o.shape))
            nearest = std::min(nearest, plane_distance(*p, o, camera.eye));
    // Capped at the view plane's distance N, as the tutorial's frustum starts there, but
    // never below a millionth of the far plane: a scene far larger than N, seen from
    // afar, would otherwise have all its depths round to the far plane's and fail the
    // depth test (a 24-bit depth buffer tells about 1e6 steps apart).
    const float closest_allowed = std::min(range.far_plane * 1e-6f, camera.N);
    const float farthest_allowed = std::max(range.far_plane * 1e-6f, camera.N);
    range.near_plane = std::clamp(0.5f * nearest, closest_allowed, farthest_allowed);
    return range;
}

void GpuScene::add_mesh_draws(std::uint32_t object, const Object& o, const MeshRef& ref,
                              std::vector<DrawItem>& out) const {
    const TriangleMesh& mesh = scene_.meshes[ref.mesh];
    DrawItem item;
    item.mesh = &meshes_[ref.mesh];
    item.model = o.transform ? o.transform->m : glm::mat4(1.0f);
    item.object_id = object + 1;
    const bool per_triangle = ref.own_materials && !mesh.materials.empty();
    const auto count = static_cast<std::uint32_t>(mesh.triangles.size());
    // One draw per run of triangles that share a material, in the mesh's own order, each
    // from its first triangle's vertices on, so that a triangle's index is its vertices'
    // over three (raster.vert's v_prim, for the item buffer).
    for (std::uint32_t start = 0; start < count;) {
        std::uint32_t end = start + 1;
        if (per_triangle)
            while (end < count && mesh.materials[end] == mesh.materials[start]) ++end;
        else
            end = count;
        item.material = per_triangle ? mesh.materials[start] : o.material;
        item.first_vertex = static_cast<GLint>(3 * start);
        item.vertex_count = static_cast<GLsizei>(3 * (end - start));
        out.push_back(item);
        start = end;
    }
    item.wire = true;
    item.material = o.material;
    item.first_vertex = 0;
    for (const auto* wires : {&lines_, &points_}) {
        const auto it = wires->find(ref.mesh);
        if (it == wires->end()) continue;
        item.mesh = &it->second;
        item.vertex_count = item.mesh->vertex_count();
        out.push_back(item);
    }
}

std::vector<DrawItem> GpuScene::draw_list(const Camera& camera, Keep keep) {
    std::vector<DrawItem> out;
    const float extent = plane_extent(camera);
    const DepthRange depth = depth_range(camera);
    const glm::mat4 view_projection =
        camera.projection(depth.near_plane, depth.far_plane) * camera.view();
    for (std::uint32_t i = 0; i < scene_.objects.size(); ++i) {
        const Object& o = scene_.objects[i];
        if (keep == Keep::kInView && !std::holds_alternative<Plane>(o.shape)) {
            const Aabb box = scene_.object_bounds(o);
            if (!box.empty() && !box_in_view(box, view_projection)) continue;
        }
        DrawItem item;
        item.model = o.transform ? o.transform->m : glm::mat4(1.0f);
        item.material = o.material;
        item.object_id = i + 1;
        if (const auto* s = std::get_if<Sphere>(&o.shape)) {
            const glm::vec3 centre = glm::vec3(item.model * glm::vec4(s->centre, 1.0f));
            item.mesh = &sphere_level(
                projected_radius_pixels(camera, centre, s->radius * max_scale(item.model)));
            item.shape =
                glm::scale(glm::translate(glm::mat4(1.0f), s->centre), glm::vec3(s->radius));
            item.sphere = true;
        } else if (const auto* p = std::get_if<Plane>(&o.shape)) {
            // The unit quad in z = 0, turned into the plane's frame, centred under the eye.
            glm::vec3 t1, t2;
            tangent_frame(p->normal, t1, t2);
            const glm::vec3 eye = o.transform
                                      ? glm::vec3(o.transform->inv * glm::vec4(camera.eye, 1.0f))
                                      : camera.eye;
            const glm::vec3 centre = eye - (glm::dot(eye, p->normal) - p->offset) * p->normal;
            item.shape = glm::mat4(glm::vec4(extent * t1, 0.0f), glm::vec4(extent * t2, 0.0f),
                                   glm::vec4(p->normal, 0.0f), glm::vec4(centre, 1.0f));
            item.mesh = &*quad_;
            item.plane = p;
        } else if (std::holds_alternative<Triangle>(o.shape)) {
            item.mesh = &triangles_.at(i);
        } else {
            add_mesh_draws(i, o, std::get<MeshRef>(o.shape), out);
            continue;
        }
        item.vertex_count = item.mesh->vertex_count();
        out.push_back(item);
    }
    return out;
}

}  // namespace rt::gl
