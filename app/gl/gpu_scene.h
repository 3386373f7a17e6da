#pragma once
// The scene's geometry on the GPU, and the list of draws that shows it from a camera.
// Meshes are uploaded once; spheres use a shared unit sphere at a level of detail
// chosen per frame from their size on screen; planes are one unit quad, placed per
// frame under the eye and scaled far past the horizon.

#include <map>
#include <optional>
#include <vector>

#include "app/gl/gl.h"
#include "app/gl/handle.h"
#include "core/scene.h"

namespace rt::gl {

class GpuMesh {
  public:
    // Non-indexed triangles: position, shading normal and face normal per corner.
    // With smooth_faces the face normal is the shading normal (analytic spheres).
    explicit GpuMesh(const TriangleMesh& mesh, bool smooth_faces = false);
    // Lines (GL_LINES: two vertices a segment) or points (GL_POINTS), positions only.
    GpuMesh(const std::vector<glm::vec3>& positions, GLenum mode);

    void draw(GLint first_vertex, GLsizei vertex_count) const;
    GLsizei vertex_count() const { return vertex_count_; }

  private:
    struct Vertex;
    void upload(const std::vector<Vertex>& vertices);

    VertexArrayHandle vao_;
    BufferHandle vbo_;
    GLsizei vertex_count_ = 0;
    GLenum mode_ = GL_TRIANGLES;
};

struct DrawItem {
    const GpuMesh* mesh = nullptr;
    GLint first_vertex = 0;
    GLsizei vertex_count = 0;
    glm::mat4 model{1.0f};  // object space -> world (the object's transform)
    glm::mat4 shape{1.0f};  // mesh vertices -> object space (sphere centre and radius, plane frame)
    std::uint32_t material = 0;
    std::uint32_t object_id = 0;    // object index + 1, as the item buffer stores it
    const Plane* plane = nullptr;   // for the checker's in-plane coordinates
    bool sphere = false;            // the mesh is the unit sphere: normals are its positions
    glm::vec3 pattern_shift{0.0f};  // Scene::pattern_shift of the object and material
    bool wire = false;  // a mesh's lines or points: raster only, unlit, not in the item buffer
};

struct DepthRange {
    float near_plane = 0.1f;
    float far_plane = 1000.0f;
};

class GpuScene {
  public:
    explicit GpuScene(const Scene& scene);

    // Which objects a draw list holds. kInView leaves out those whose box lies wholly
    // beyond one side of the camera's frustum or behind its near plane: they could add no
    // fragment, so the image and the item buffer are the same without them (a cube map's
    // face sees about a sixth of a scene that surrounds its centre). kAll keeps them.
    enum class Keep { kInView, kAll };

    std::vector<DrawItem> draw_list(const Camera& camera, Keep keep = Keep::kInView);
    DepthRange depth_range(const Camera& camera) const;

  private:
    const GpuMesh& sphere_level(float radius_pixels);
    float plane_extent(const Camera& camera) const;
    void add_mesh_draws(std::uint32_t object, const Object& o, const MeshRef& ref,
                        std::vector<DrawItem>& out) const;

    const Scene& scene_;
    Aabb bounds_;
    // Draw items point into these, so they never move once made (a vector filled once,
    // maps whose nodes stay put).
    std::vector<GpuMesh> meshes_;                      // per scene mesh
    std::map<std::uint32_t, GpuMesh> lines_, points_;  // per scene mesh that has them
    std::map<std::uint32_t, GpuMesh> triangles_;       // per triangle object
    std::map<int, GpuMesh> spheres_;                   // per level of detail
    std::optional<GpuMesh> quad_;
};

}  // namespace rt::gl
