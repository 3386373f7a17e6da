#include "app/gl/raster_renderer.h"

#include <string>

#include <glm/matrix.hpp>

#include "app/gl/debug.h"

namespace rt::gl {

RasterRenderer::RasterRenderer(const Scene& scene, const std::filesystem::path& shaders)
    : scene_(scene),
      gpu_(scene),
      phong_(shaders / "raster.vert", shaders / "phong.frag"),
      ids_(shaders / "raster.vert", shaders / "itembuffer.frag"),
      wire_(shaders / "raster.vert", shaders / "wire.frag"),
      shadow_(shaders / "raster.vert", shaders / "shadow.frag") {}

void RasterRenderer::set_shadow_maps(bool on, int size) {
    shadow_maps_ = on;
    shadow_size_ = size;
}

// Draws the shadow maps if they are asked for and missing or of another size, leaving the
// framebuffer binding and viewport as they were.
void RasterRenderer::ensure_shadow_maps() {
    if (!shadow_maps_ || scene_.lights.empty() || (shadows_ && shadows_->asked() == shadow_size_))
        return;
    GLint framebuffer = 0, viewport[4] = {};
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
    glGetIntegerv(GL_VIEWPORT, viewport);
    shadows_.emplace(static_cast<int>(scene_.lights.size()), shadow_size_);
    const int size = shadows_->size();
    shadows_->atlas().bind();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    for (int i = 0; i < shadows_->lights(); ++i) {
        const Light& light = scene_.lights[static_cast<std::size_t>(i)];
        if (light.type != Light::Type::kPoint) continue;  // no map: lit everywhere
        for (int face = 0; face < 6; ++face) {
            const Camera camera = ShadowMaps::face_camera(light.position, face, size);
            set_camera(shadow_, camera);
            shadow_.set("u_light", light.position);
            glViewport(face * size, i * size, size, size);
            for (const DrawItem& item : gpu_.draw_list(camera)) {
                if (item.wire) continue;
                set_object(shadow_, item, camera);
                item.mesh->draw(item.first_vertex, item.vertex_count);
            }
        }
    }
    glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(framebuffer));
    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    check("RasterRenderer::ensure_shadow_maps");
}

void RasterRenderer::set_shadow_uniforms() {
    const bool on = shadow_maps_ && shadows_.has_value();
    phong_.set("u_shadow_maps", on ? 1 : 0);
    if (!on) return;
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, shadows_->texture());
    phong_.set("u_shadow_atlas", 0);
    phong_.set("u_shadow_size", shadows_->size());
    phong_.set("u_shadow_rows", shadows_->lights());
    for (int f = 0; f < 6; ++f)
        phong_.set(("u_face_vp[" + std::to_string(f) + "]").c_str(),
                   shadows_->faces()[static_cast<std::size_t>(f)]);
}

void RasterRenderer::set_camera(Program& program, const Camera& camera) {
    const DepthRange depth = gpu_.depth_range(camera);
    program.use();
    program.set("u_view_projection",
                camera.projection(depth.near_plane, depth.far_plane) * camera.view());
    program.set("u_eye", camera.eye);
}

void RasterRenderer::set_object(Program& program, const DrawItem& item, const Camera& camera) {
    const glm::mat4 to_world = item.model * item.shape;
    if (item.sphere)
        program.set("u_eye_local", glm::vec3(glm::inverse(to_world) * glm::vec4(camera.eye, 1.0f)));
    program.set("u_model", item.model);
    program.set("u_shape", item.shape);
    program.set("u_normal_matrix", glm::transpose(glm::inverse(glm::mat3(to_world))));
}

void RasterRenderer::set_material(const Material& m, const DrawItem& item) {
    phong_.set("u_ka", m.ka);
    phong_.set("u_kd", m.kd);
    phong_.set("u_ks", m.ks);
    phong_.set("u_shininess", m.shininess);
    phong_.set("u_checker", m.checker ? 1 : 0);
    if (m.checker) {
        phong_.set("u_checker_a", m.checker->colour_a);
        phong_.set("u_checker_b", m.checker->colour_b);
        phong_.set("u_checker_scale", m.checker->scale);
    }
    phong_.set("u_plane", item.plane ? 1 : 0);
    phong_.set("u_pattern_shift", scene_.pattern_shift(item.object_id - 1, item.material));
    phong_.set("u_sphere", item.sphere ? 1 : 0);
    if (item.plane) {
        glm::vec3 t1, t2;
        tangent_frame(item.plane->normal, t1, t2);
        phong_.set("u_plane_t1", t1);
        phong_.set("u_plane_t2", t2);
    }
}

void RasterRenderer::draw(const Camera& camera) {
    ensure_shadow_maps();
    set_camera(phong_, camera);
    set_shadow_uniforms();
    phong_.set("u_ambient", scene_.ambient);
    const int lights = std::min(static_cast<int>(scene_.lights.size()), kMaxLights);
    phong_.set("u_light_count", lights);
    for (int i = 0; i < lights; ++i) {
        const Light& l = scene_.lights[static_cast<std::size_t>(i)];
        const std::string at = "[" + std::to_string(i) + "]";
        const bool directional = l.type == Light::Type::kDirectional;
        phong_.set(("u_light_directional" + at).c_str(), directional ? 1 : 0);
        phong_.set(("u_light_vector" + at).c_str(), directional ? l.direction : l.position);
        phong_.set(("u_light_colour" + at).c_str(), l.colour);
    }
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);  // surfaces are two-sided, as in the tracer
    const std::vector<DrawItem> items = gpu_.draw_list(camera);
    for (const DrawItem& item : items) {
        if (item.wire) continue;
        set_object(phong_, item, camera);
        set_material(scene_.materials[item.material], item);
        item.mesh->draw(item.first_vertex, item.vertex_count);
    }
    draw_wires(items, camera);
    check("RasterRenderer::draw");
}

// A mesh's lines and points, in its material's diffuse colour, unlit: they have no
// normal to light. The tracer does not see them (it renders surfaces).
void RasterRenderer::draw_wires(const std::vector<DrawItem>& items, const Camera& camera) {
    bool any = false;
    for (const DrawItem& item : items) {
        if (!item.wire) continue;
        if (!any) {
            set_camera(wire_, camera);
            glPointSize(3.0f);
            any = true;
        }
        set_object(wire_, item, camera);
        wire_.set("u_colour", scene_.materials[item.material].kd);
        item.mesh->draw(item.first_vertex, item.vertex_count);
    }
}

void RasterRenderer::draw_ids(const Camera& camera) {
    set_camera(ids_, camera);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    for (const DrawItem& item : gpu_.draw_list(camera)) {
        if (item.wire) continue;  // the tracer's first hits are surfaces
        set_object(ids_, item, camera);
        ids_.set("u_object_id", item.object_id);
        ids_.set("u_prim_base", item.prim_base);
        item.mesh->draw(item.first_vertex, item.vertex_count);
    }
    check("RasterRenderer::draw_ids");
}

Framebuffer& RasterRenderer::target(std::optional<Framebuffer>& fb, Framebuffer::Kind kind,
                                    const Camera& camera, int samples) {
    if (!fb || fb->width() != camera.cols || fb->height() != camera.rows ||
        fb->samples() != samples)
        fb.emplace(kind, camera.cols, camera.rows, samples);
    return *fb;
}

const Framebuffer& RasterRenderer::render_to_texture(const Camera& camera) {
    Framebuffer& fb = target(colour_target_, Framebuffer::Kind::kColour, camera, msaa_);
    fb.bind();
    const glm::vec3 bg = scene_.background;
    glClearColor(bg.x, bg.y, bg.z, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    draw(camera);
    fb.resolve();
    return fb;
}

const Framebuffer& RasterRenderer::render_item_buffer_to_texture(const Camera& camera) {
    Framebuffer& fb = target(id_target_, Framebuffer::Kind::kItemBuffer, camera);
    fb.bind();
    draw_ids(camera);
    return fb;
}

Image RasterRenderer::render(const Camera& camera) {
    return render_to_texture(camera).read_colour();
}

ItemBuffer RasterRenderer::render_item_buffer(const Camera& camera) {
    return render_item_buffer_to_texture(camera).read_item_buffer();
}

}  // namespace rt::gl
