#include "app/gl/ray_overlay.h"

#include <glm/geometric.hpp>

#include "app/gl/debug.h"
#include "core/image.h"

namespace rt::gl {
namespace {

struct Vertex {
    glm::vec3 position, other;
    float side;
    glm::vec4 colour;
};

// Cuts the view-space segment a-b to the part in front of z = -near; false if none is.
bool cut_at_near(glm::vec3& a, glm::vec3& b, float near_plane) {
    const float limit = -near_plane * 1.001f;
    const bool a_in = a.z <= limit, b_in = b.z <= limit;
    if (!a_in && !b_in) return false;
    if (a_in != b_in) {
        const float t = (limit - a.z) / (b.z - a.z);
        (a_in ? b : a) = a + t * (b - a);
    }
    return true;
}

}  // namespace

RayOverlay::RayOverlay(const std::filesystem::path& shaders)
    : program_(shaders / "rays.vert", shaders / "rays.frag"),
      vao_(make_vertex_array()),
      vbo_(make_buffer()) {
    glBindVertexArray(vao_.get());
    glBindBuffer(GL_ARRAY_BUFFER, vbo_.get());
    const auto attribute = [](GLuint index, GLint size, std::size_t offset) {
        glEnableVertexAttribArray(index);
        glVertexAttribPointer(index, size, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                              reinterpret_cast<const void*>(offset));
    };
    attribute(0, 3, offsetof(Vertex, position));
    attribute(1, 3, offsetof(Vertex, other));
    attribute(2, 1, offsetof(Vertex, side));
    attribute(3, 4, offsetof(Vertex, colour));
    glBindVertexArray(0);
    check("RayOverlay");
}

vec3 RayOverlay::colour(RayKind kind) {
    switch (kind) {  // Okabe & Ito, as the explain map
        case RayKind::kPrimary:
            return vec3(1.0f);
        case RayKind::kShadow:
            return from_srgb8(230, 159, 0);  // orange
        case RayKind::kReflection:
            return from_srgb8(86, 180, 233);  // sky blue
        case RayKind::kRefraction:
            return from_srgb8(0, 158, 115);  // bluish green
    }
    return vec3(1.0f);
}

void RayOverlay::set(std::vector<RaySegment> segments) {
    segments_ = std::move(segments);
    drawn_for_.reset();
}

GLuint RayOverlay::texture(RasterRenderer& raster, const Camera& camera) {
    if (!target_ || target_->width() != camera.cols || target_->height() != camera.rows) {
        target_.emplace(Framebuffer::Kind::kColour, camera.cols, camera.rows);
        drawn_for_.reset();
    }
    if (drawn_for_ == camera) return target_->texture();
    target_->bind();
    const GLfloat clear[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearBufferfv(GL_COLOR, 0, clear);
    if (!segments_.empty()) {
        // The surfaces' depth, so that a ray behind an object is hidden by it.
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        raster.draw(camera);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

        const DepthRange depth = raster.depth_range(camera);
        const glm::mat4 view = camera.view();
        std::vector<Vertex> vertices;
        for (const RaySegment& s : segments_) {
            glm::vec3 a(view * glm::vec4(s.a, 1.0f)), b(view * glm::vec4(s.b, 1.0f));
            if (!cut_at_near(a, b, depth.near_plane)) continue;
            const glm::vec4 c(colour(s.kind) * (s.blocked ? 0.35f : 1.0f), 1.0f);
            const Vertex corners[4] = {
                {a, b, 1.0f, c}, {a, b, -1.0f, c}, {b, a, 1.0f, c}, {b, a, -1.0f, c}};
            // Seen from b the sideways direction flips: (b, a, +1) lies on (a, b, -1)'s edge.
            for (int i : {0, 1, 2, 0, 2, 3}) vertices.push_back(corners[i]);
        }
        program_.use();
        program_.set("u_projection", camera.projection(depth.near_plane, depth.far_plane));
        program_.set("u_viewport", glm::vec3(static_cast<float>(camera.cols),
                                             static_cast<float>(camera.rows), 0.0f));
        program_.set("u_width", kWidth);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);
        glBindVertexArray(vao_.get());
        glBindBuffer(GL_ARRAY_BUFFER, vbo_.get());
        glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)),
                     vertices.data(), GL_DYNAMIC_DRAW);
        glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertices.size()));
        glBindVertexArray(0);
    }
    check("RayOverlay::texture");
    drawn_for_ = camera;
    return target_->texture();
}

}  // namespace rt::gl
