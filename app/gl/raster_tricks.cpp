// The raster pipeline's classic tricks (app/gl/cube_atlas.h): shadow maps and
// environment maps, each drawn once when switched on or resized, never for a camera move.
#include <algorithm>
#include <string>

#include <glm/geometric.hpp>

#include "app/gl/debug.h"
#include "app/gl/raster_renderer.h"

namespace rt::gl {
namespace {

// Keeps the draw framebuffer and viewport across drawing into an atlas.
class KeepTarget {
  public:
    KeepTarget() {
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer_);
        glGetIntegerv(GL_VIEWPORT, viewport_);
    }
    ~KeepTarget() {
        glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(framebuffer_));
        glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
    }
    KeepTarget(const KeepTarget&) = delete;
    KeepTarget& operator=(const KeepTarget&) = delete;

  private:
    GLint framebuffer_ = 0, viewport_[4] = {};
};

void set_faces(Program& program, const char* name, const CubeAtlas& atlas) {
    for (int f = 0; f < 6; ++f)
        program.set((std::string(name) + "[" + std::to_string(f) + "]").c_str(),
                    atlas.faces()[static_cast<std::size_t>(f)]);
}

}  // namespace

void RasterRenderer::set_shadow_maps(bool on, int size) {
    shadow_maps_ = on;
    shadow_size_ = size;
}

// Draws the shadow maps if they are asked for and missing or of another size, leaving the
// framebuffer binding and viewport as they were.
void RasterRenderer::ensure_shadow_maps() {
    if (!shadow_maps_ || scene_.lights.empty() || (shadows_ && shadows_->asked() == shadow_size_))
        return;
    const KeepTarget keep;
    shadows_.emplace(Framebuffer::Kind::kDistance, static_cast<int>(scene_.lights.size()),
                     shadow_size_);
    const int size = shadows_->size();
    shadows_->atlas().bind();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    for (int i = 0; i < shadows_->rows(); ++i) {
        const Light& light = scene_.lights[static_cast<std::size_t>(i)];
        if (light.type != Light::Type::kPoint) continue;  // no map: lit everywhere
        for (int face = 0; face < 6; ++face) {
            const Camera camera = CubeAtlas::face_camera(light.position, face, size);
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
    check("RasterRenderer::ensure_shadow_maps");
}

void RasterRenderer::set_shadow_uniforms() {
    const bool on = shadow_maps_ && shadows_.has_value();
    if (!on) return;
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, shadows_->texture());
    phong_->set("u_shadow_atlas", 0);
    phong_->set("u_shadow_size", shadows_->size());
    phong_->set("u_shadow_rows", shadows_->rows());
    set_faces(*phong_, "u_face_vp", *shadows_);
}

void RasterRenderer::set_environment_maps(bool on, int size) {
    env_maps_ = on;
    env_size_ = size;
    if (!on) env_.reset();
}

// A cube per mirror or glass object (not planes: a cube at no centre), from its centre:
// the rest of the scene as the raster draws it, for the kMaxEnvMaps objects that look
// largest from the scene's camera (each costs 6 x kEnvPasses draws of the scene). Drawn
// kEnvPasses times, each pass looking up the last one's maps, so that mirrors show each
// other (a mirror in a mirror in the first pass is its plain colour).
void RasterRenderer::ensure_environment_maps() {
    if (!env_maps_ || (env_ && env_->asked() == env_size_)) return;
    env_row_.assign(scene_.objects.size(), -1);
    struct Candidate {
        std::size_t object;
        vec3 centre;
        float apparent;  // radius over distance from the camera
    };
    std::vector<Candidate> candidates;
    std::vector<bool> seen(scene_.objects.size(), false);
    for (const DrawItem& item : gpu_.draw_list(scene_.camera, GpuScene::Keep::kAll)) {
        const std::size_t object = item.object_id - 1;
        const Material& m = scene_.materials[item.material];
        const bool mirror_or_glass = m.reflectivity > 0.0f || m.transparency > 0.0f;
        if (!mirror_or_glass || item.plane || item.wire || seen[object]) continue;
        seen[object] = true;
        const Aabb box = scene_.object_bounds(scene_.objects[object]);
        if (box.empty()) continue;
        const vec3 centre = 0.5f * (box.lo + box.hi);
        const float distance = std::max(glm::length(centre - scene_.camera.eye), 1e-6f);
        candidates.push_back({object, centre, 0.5f * glm::length(box.hi - box.lo) / distance});
    }
    if (candidates.empty()) return;
    std::sort(candidates.begin(), candidates.end(),
              [](const Candidate& a, const Candidate& b) { return a.apparent > b.apparent; });
    if (candidates.size() > kMaxEnvMaps) candidates.resize(kMaxEnvMaps);
    std::vector<vec3> centres;
    for (const Candidate& c : candidates) {
        env_row_[c.object] = static_cast<int>(centres.size());
        centres.push_back(c.centre);
    }
    const KeepTarget keep;
    std::optional<CubeAtlas> previous;
    for (int pass = 0; pass < kEnvPasses; ++pass) {
        CubeAtlas next(Framebuffer::Kind::kColour, static_cast<int>(centres.size()), env_size_);
        const int size = next.size();
        next.atlas().bind();
        const vec3 bg = scene_.background;
        const GLfloat clear[4] = {bg.x, bg.y, bg.z, 1.0f};
        glClearBufferfv(GL_COLOR, 0, clear);
        for (std::size_t object = 0; object < env_row_.size(); ++object) {
            const int row = env_row_[object];
            if (row < 0) continue;
            for (int face = 0; face < 6; ++face) {
                glViewport(face * size, row * size, size, size);
                draw_scene(
                    CubeAtlas::face_camera(centres[static_cast<std::size_t>(row)], face, size),
                    static_cast<int>(object), previous ? &*previous : nullptr);
            }
        }
        glBindTexture(GL_TEXTURE_2D, next.texture());  // looked up between texels
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        previous.emplace(std::move(next));
    }
    env_.emplace(std::move(*previous));
    check("RasterRenderer::ensure_environment_maps");
}

RasterRenderer::ForExplain RasterRenderer::render_for_explain(const Camera& camera) {
    ForExplain out;
    out.image = render(camera);
    out.ids = render_item_buffer(camera);
    const auto added = [&](const Image& without) {  // what the trick added: with - without
        Image d(out.image.width, out.image.height);
        for (std::size_t i = 0; i < d.pixels.size(); ++i)
            d.pixels[i] = out.image.pixels[i] - without.pixels[i];
        return d;
    };
    if (shadow_maps_ && shadows_) {
        shadow_maps_ = false;  // the maps stay; they are just not looked up
        out.tricks.shadow = added(render(camera));
        shadow_maps_ = true;
    }
    if (env_maps_ && env_) {
        env_terms_ = 2;
        out.tricks.reflection = added(render(camera));
        env_terms_ = 1;
        out.tricks.refraction = added(render(camera));
        env_terms_ = 3;
    }
    return out;
}

void RasterRenderer::set_environment_uniforms(const CubeAtlas* env) {
    if (!env) return;
    phong_->set("u_env_terms", env_terms_);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, env->texture());
    glActiveTexture(GL_TEXTURE0);
    phong_->set("u_env_atlas", 1);
    phong_->set("u_env_size", env->size());
    phong_->set("u_env_rows", env->rows());
    set_faces(*phong_, "u_face_vp", *env);
}

}  // namespace rt::gl
