#pragma once
// The classic pipeline: the same rt::Scene drawn with per-fragment Phong in GLSL, from
// the same camera (core's view and projection), with the same materials and lights,
// and no shadows, reflection or refraction. Also the item-buffer pass.

#include <filesystem>
#include <optional>
#include <string>

#include "app/gl/cube_atlas.h"
#include "app/gl/framebuffer.h"
#include "app/gl/gpu_scene.h"
#include "app/gl/program.h"
#include "app/gl/texture.h"
#include "core/explain.h"
#include "core/image.h"
#include "core/item_buffer.h"
#include "core/scene.h"

namespace rt::gl {

class RasterRenderer {
  public:
    static constexpr int kMaxLights = 16;  // as in shaders/phong.frag

    // Needs a current GL context; throws rt::Error on a shader that is missing or broken.
    explicit RasterRenderer(const Scene& scene,
                            const std::filesystem::path& shaders = shader_dir());

    // Off-screen at the camera's resolution, read back: linear RGB, bottom row first.
    Image render(const Camera& camera);
    // Object id + 1 and triangle index per pixel, read back.
    ItemBuffer render_item_buffer(const Camera& camera);
    // The same into a previous frame's storage (Image::resize), as a viewer or a
    // benchmark drawing frame after frame would.
    void render(const Camera& camera, Image& into);
    void render_item_buffer(const Camera& camera, ItemBuffer& into);

    // The same passes, left on the GPU: their off-screen targets, for a viewer to sample.
    // With `with_ids` (and shares_item_buffer()) the colour pass draws the item buffer
    // too, into attachments 1 and 2 of the same target (Kind::kColourAndIds).
    const Framebuffer& render_to_texture(const Camera& camera, bool with_ids = false);
    const Framebuffer& render_item_buffer_to_texture(const Camera& camera);

    // The colour pass and its item buffer: from one draw where it can (one sample a
    // pixel: an id cannot be averaged, so with MSAA the ids take a pass of their own).
    // The same ids as render_item_buffer() either way (GL test).
    static bool shares_item_buffer_at(int msaa) { return msaa == 1; }
    bool shares_item_buffer() const { return shares_item_buffer_at(msaa_); }
    struct Frame {
        Image image;
        ItemBuffer ids;
        bool shared = false;  // from the colour pass itself
    };
    Frame render_with_item_buffer(const Camera& camera);
    void render_with_item_buffer(const Camera& camera, Frame& into);

    // How the targets hold the ids: IdLayout::for_scene unless set (the GL tests compare
    // the layouts); setting it drops the targets, made again at the next pass.
    const IdLayout& id_layout() const { return id_layout_; }
    void set_id_layout(IdLayout layout);
    // How the ids are read back (Framebuffer::IdReads; kAuto unless a test compares).
    void set_id_reads(Framebuffer::IdReads how) { id_reads_ = how; }

    // Multisample anti-aliasing of the colour pass (1, 2, 4 or 8 samples; 1: none). The
    // item buffer stays one sample a pixel: an object id cannot be averaged.
    void set_msaa(int samples) { msaa_ = samples; }
    int msaa() const { return msaa_; }
    // Shadows by shadow maps (app/gl/cube_atlas.h), `size` texels a face side; drawn again
    // only when switched on or resized. Off: the classic pipeline's unshadowed Phong.
    void set_shadow_maps(bool on, int size = 1024);
    bool shadow_maps() const { return shadow_maps_; }
    const CubeAtlas* shadow_map_data() const { return shadows_ ? &*shadows_ : nullptr; }
    // Environment maps for mirrors and glass (app/gl/cube_atlas.h): the reflected and
    // refracted directions looked up in a cube seen from the object's centre, weighted by
    // the material's reflectivity and transparency as the tracer weights its rays.
    void set_environment_maps(bool on, int size = 256);
    bool environment_maps() const { return env_maps_; }

    // For the explain map: the image with the tricks as set, its item buffer, and what
    // each trick added (rendered again without it; empty where it is off), so that each
    // term compares like with like.
    struct ForExplain {
        Image image;
        ItemBuffer ids;
        RasterTricks tricks;
    };
    ForExplain render_for_explain(const Camera& camera);

    // The two passes into whatever framebuffer is bound.
    void draw(const Camera& camera);
    void draw_ids(const Camera& camera);
    // The near and far planes these passes use for `camera`.
    DepthRange depth_range(const Camera& camera) const { return gpu_.depth_range(camera); }

    // phong.frag compiled with or without each trick, and with texture lookups when the
    // scene has textures (compiled when first asked for); with `ids`, writing the item
    // buffer too (into Framebuffer::Kind::kColourAndIds).
    Program& phong(bool shadow_maps, bool environment_maps, bool ids = false);

  private:
    void set_camera(Program& program, const Camera& camera);
    std::vector<DrawItem> nearest_first(const Camera& camera);
    void draw_wires(const std::vector<DrawItem>& items, const Camera& camera);
    void set_material(const Material& m, const DrawItem& item);
    void draw_scene(const Camera& camera, int skip, const CubeAtlas* env, bool ids = false);
    std::string id_define() const;
    Program& ids_program() { return ids_variants_.get({id_define()}); }
    void ensure_shadow_maps();
    void set_shadow_uniforms();
    void ensure_environment_maps();
    void set_environment_uniforms(const CubeAtlas* env);
    void set_object(Program& program, const DrawItem& item, const Camera& camera);
    Framebuffer& target(std::optional<Framebuffer>& fb, Framebuffer::Kind kind,
                        const Camera& camera, int samples = 1);

    const Scene& scene_;
    GpuScene gpu_;
    std::vector<Texture> textures_;   // the scene's surface textures
    ProgramVariants phong_variants_;  // with and without each trick (phong.frag)
    Program* phong_ = nullptr;        // the variant draw_scene() is drawing with
    ProgramVariants ids_variants_;    // itembuffer.frag, for objects alone or with triangles
    Program wire_;
    Program shadow_;
    std::optional<Framebuffer> colour_target_;
    std::optional<Framebuffer> id_target_;
    std::optional<Framebuffer> shared_target_;  // colour and ids from one draw
    const Framebuffer* drawing_ids_ = nullptr;  // the bound target, where it is shared_target_
    IdLayout id_layout_;                        // Framebuffer's ctor and the shaders' u_prim_bits
    Framebuffer::IdReads id_reads_ = Framebuffer::IdReads::kAuto;
    int msaa_ = 1;
    bool shadow_maps_ = false;
    int shadow_size_ = 1024;
    std::optional<CubeAtlas> shadows_;
    static constexpr int kEnvPasses = 2;
    static constexpr std::size_t kMaxEnvMaps = 4;  // mirrors and glass with a map
    bool env_maps_ = false;
    int env_size_ = 256;
    std::optional<CubeAtlas> env_;
    std::vector<int> env_row_;  // per object: its environment map's row, or -1
    int env_terms_ = 3;  // which environment terms phong.frag adds: 1 reflection, 2 refraction
};

}  // namespace rt::gl
