#include "app/gl/raster_renderer.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <variant>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "app/gl/debug.h"

namespace rt::gl {

namespace {
// The largest mesh any object draws, in triangles (0: no mesh): what the ids must hold.
std::size_t most_mesh_triangles(const Scene& scene) {
    std::size_t most = 0;
    for (const Object& o : scene.objects)
        if (const auto* ref = std::get_if<MeshRef>(&o.shape))
            most = std::max({most, scene.meshes[ref->mesh].triangles.size(), std::size_t{1}});
    return most;
}
}  // namespace

RasterRenderer::RasterRenderer(const Scene& scene, const std::filesystem::path& shaders)
    : scene_(scene),
      gpu_(scene),
      phong_variants_(shaders / "raster.vert", shaders / "phong.frag"),
      ids_variants_(shaders / "raster.vert", shaders / "itembuffer.frag"),
      wire_(shaders / "raster.vert", shaders / "wire.frag"),
      shadow_(shaders / "raster.vert", shaders / "shadow.frag"),
      id_layout_(IdLayout::for_scene(scene.objects.size(), most_mesh_triangles(scene))) {
    for (const rt::Texture& t : scene.textures) textures_.emplace_back().upload_surface(t);
    phong(false, false);  // a shader that does not compile fails here, not at the first frame
}

Program& RasterRenderer::phong(bool shadow_maps, bool environment_maps, bool ids) {
    return phong_variants_.get({std::string("SHADOW_MAPS ") + (shadow_maps ? "1" : "0"),
                                std::string("ENV_MAPS ") + (environment_maps ? "1" : "0"),
                                std::string("TEXTURES ") + (textures_.empty() ? "0" : "1"),
                                ids ? id_define() : std::string("IDS 0")});
}

// What the shaders write of the item buffer: the objects alone where no mesh needs its
// triangles named (IdLayout::kObjectsOnly), else the triangles too (raster.vert's flat
// v_prim). Three variants of phong.frag, not one that always writes both: the colour
// pass alone pays nothing for the ids, nor the objects for the triangles
// (docs/BENCHMARKS.md, "thirty-second session").
std::string RasterRenderer::id_define() const {
    return id_layout_.kind == IdLayout::Kind::kObjectsOnly ? "IDS 1" : "IDS 2";
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
    phong_->set("u_emission", m.emission);
    phong_->set("u_textured", m.texture ? 1 : 0);
    if (m.texture) {
        glActiveTexture(GL_TEXTURE2);
        glBindTexture(GL_TEXTURE_2D, textures_[*m.texture].id());
        glActiveTexture(GL_TEXTURE0);
        phong_->set("u_texture", 2);
    }
    phong_->set("u_ka", m.ka);
    phong_->set("u_kd", m.kd);
    phong_->set("u_ks", m.ks);
    phong_->set("u_shininess", m.shininess);
    phong_->set("u_kr", m.reflectivity);
    phong_->set("u_kt", m.transparency);
    phong_->set("u_ior", m.ior);
    phong_->set("u_checker", m.checker ? 1 : 0);
    if (m.checker) {
        phong_->set("u_checker_a", m.checker->colour_a);
        phong_->set("u_checker_b", m.checker->colour_b);
        phong_->set("u_checker_scale", m.checker->scale);
    }
    phong_->set("u_plane", item.plane ? 1 : 0);
    phong_->set("u_pattern_shift", scene_.pattern_shift(item.object_id - 1, item.material));
    phong_->set("u_sphere", item.sphere ? 1 : 0);
    if (item.plane) {
        glm::vec3 t1, t2;
        tangent_frame(item.plane->normal, t1, t2);
        phong_->set("u_plane_t1", t1);
        phong_->set("u_plane_t2", t2);
    }
}

void RasterRenderer::draw(const Camera& camera) {
    ensure_shadow_maps();
    ensure_environment_maps();
    draw_scene(camera, -1, env_ ? &*env_ : nullptr, drawing_ids_ != nullptr);
}

// Phong over every object but `skip` (an object index, or -1), mirrors and glass looking
// up `env` when given.
void RasterRenderer::draw_scene(const Camera& camera, int skip, const CubeAtlas* env, bool ids) {
    phong_ = &phong(shadow_maps_ && shadows_, env != nullptr, ids);
    set_camera(*phong_, camera);
    set_shadow_uniforms();
    set_environment_uniforms(env);
    phong_->set("u_ambient", scene_.ambient);
    phong_->set("u_prim_bits", id_layout_.shader_prim_bits());
    const int lights = std::min(static_cast<int>(scene_.lights.size()), kMaxLights);
    phong_->set("u_light_count", lights);
    for (int i = 0; i < lights; ++i) {
        const Light& l = scene_.lights[static_cast<std::size_t>(i)];
        const std::string at = "[" + std::to_string(i) + "]";
        const bool directional = l.type == Light::Type::kDirectional;
        phong_->set(("u_light_directional" + at).c_str(), directional ? 1 : 0);
        phong_->set(("u_light_vector" + at).c_str(), directional ? l.direction : l.position);
        phong_->set(("u_light_colour" + at).c_str(), l.colour);
    }
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);  // surfaces are two-sided, as in the tracer
    const std::vector<DrawItem> items = nearest_first(camera);
    for (const DrawItem& item : items) {
        if (item.wire || static_cast<int>(item.object_id) - 1 == skip) continue;
        set_object(*phong_, item, camera);
        set_material(scene_.materials[item.material], item);
        phong_->set("u_object_id", item.object_id);
        const std::size_t object = item.object_id - 1;
        phong_->set("u_env_row", env && object < env_row_.size() ? env_row_[object] : -1);
        item.mesh->draw(item.first_vertex, item.vertex_count);
    }
    draw_wires(items, camera);
    check("RasterRenderer::draw");
}

// Nearest first, so that the depth test rejects hidden fragments before they are shaded
// (many_spheres' environment maps, looking across 1601 balls: 145 s unsorted, 2 s sorted).
// The item-buffer pass draws in the same order, so that where two surfaces tie in depth
// it names the one the colour pass shows.
std::vector<DrawItem> RasterRenderer::nearest_first(const Camera& camera) {
    std::vector<DrawItem> items = gpu_.draw_list(camera);
    const auto distance = [&](const DrawItem& item) {
        return item.plane ? INFINITY
                          : glm::length(glm::vec3((item.model * item.shape)[3]) - camera.eye);
    };
    std::vector<std::pair<float, std::size_t>> order;
    for (std::size_t i = 0; i < items.size(); ++i) order.emplace_back(distance(items[i]), i);
    std::sort(order.begin(), order.end());
    std::vector<DrawItem> sorted;
    sorted.reserve(items.size());
    for (const auto& [d, i] : order) sorted.push_back(items[i]);
    return sorted;
}

// A mesh's lines and points, in its material's diffuse colour, unlit: they have no
// normal to light. The tracer does not see them (it renders surfaces), so where the
// target holds an item buffer too they leave it alone.
void RasterRenderer::draw_wires(const std::vector<DrawItem>& items, const Camera& camera) {
    bool any = false;
    for (const DrawItem& item : items) {
        if (!item.wire) continue;
        if (!any) {
            set_camera(wire_, camera);
            glPointSize(3.0f);
            if (drawing_ids_) drawing_ids_->draw_ids(false);
            any = true;
        }
        set_object(wire_, item, camera);
        wire_.set("u_colour", scene_.materials[item.material].kd);
        item.mesh->draw(item.first_vertex, item.vertex_count);
    }
    if (any && drawing_ids_) drawing_ids_->draw_ids(true);
}

void RasterRenderer::draw_ids(const Camera& camera) {
    Program& ids = ids_program();
    set_camera(ids, camera);
    ids.set("u_prim_bits", id_layout_.shader_prim_bits());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    for (const DrawItem& item : nearest_first(camera)) {
        if (item.wire) continue;  // the tracer's first hits are surfaces
        set_object(ids, item, camera);
        ids.set("u_object_id", item.object_id);
        item.mesh->draw(item.first_vertex, item.vertex_count);
    }
    check("RasterRenderer::draw_ids");
}

Framebuffer& RasterRenderer::target(std::optional<Framebuffer>& fb, Framebuffer::Kind kind,
                                    const Camera& camera, int samples) {
    if (!fb || fb->width() != camera.cols || fb->height() != camera.rows ||
        fb->samples() != samples)
        fb.emplace(kind, camera.cols, camera.rows, samples, id_layout_);
    return *fb;
}

void RasterRenderer::set_id_layout(IdLayout layout) {
    id_layout_ = layout;
    id_target_.reset();
    shared_target_.reset();
}

const Framebuffer& RasterRenderer::render_to_texture(const Camera& camera, bool with_ids) {
    const bool ids = with_ids && shares_item_buffer();
    Framebuffer& fb = ids ? target(shared_target_, Framebuffer::Kind::kColourAndIds, camera)
                          : target(colour_target_, Framebuffer::Kind::kColour, camera, msaa_);
    drawing_ids_ = ids ? &fb : nullptr;
    fb.bind();
    const glm::vec3 bg = scene_.background;
    const GLfloat clear[4] = {bg.x, bg.y, bg.z, 1.0f};
    glClearBufferfv(GL_COLOR, 0, clear);  // not glClear: it would write floats into the ids
    draw(camera);
    drawing_ids_ = nullptr;
    fb.resolve();
    return fb;
}

RasterRenderer::Frame RasterRenderer::render_with_item_buffer(const Camera& camera) {
    Frame frame;
    render_with_item_buffer(camera, frame);
    return frame;
}

void RasterRenderer::render_with_item_buffer(const Camera& camera, Frame& frame) {
    frame.shared = shares_item_buffer();
    if (frame.shared) {
        const Framebuffer& fb = render_to_texture(camera, true);
        Framebuffer::ItemBufferRead ids = fb.start_item_buffer_read(id_reads_);
        fb.read_colour(frame.image);  // meanwhile, on a GPU
        ids.finish(frame.ids);
        return;
    }
    render(camera, frame.image);
    render_item_buffer(camera, frame.ids);
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

void RasterRenderer::render(const Camera& camera, Image& into) {
    render_to_texture(camera).read_colour(into);
}

ItemBuffer RasterRenderer::render_item_buffer(const Camera& camera) {
    return render_item_buffer_to_texture(camera).read_item_buffer();
}

void RasterRenderer::render_item_buffer(const Camera& camera, ItemBuffer& into) {
    render_item_buffer_to_texture(camera).start_item_buffer_read(id_reads_).finish(into);
}

}  // namespace rt::gl
