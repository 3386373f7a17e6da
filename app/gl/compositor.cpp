#include "app/gl/compositor.h"

#include <algorithm>
#include <string>

#include "app/gl/debug.h"
#include "core/compare.h"

namespace rt::gl {

Compositor::Compositor(const std::filesystem::path& shaders)
    : programs_(shaders / "fullscreen.vert", shaders / "present.frag"),
      vao_(make_vertex_array()) {  // the full-screen triangle comes from gl_VertexID
    std::vector<vec3> heat(256);
    for (std::size_t i = 0; i < heat.size(); ++i)
        heat[i] = heat_colour(static_cast<float>(i) / 255.0f);
    heat_map_.upload_row(heat);
    set_item_palette(1);
    program(View::kSplit, DiffMode::kHeat, false);  // a shader that does not compile fails here
}

void Compositor::set_item_palette(std::size_t object_count) {
    std::vector<vec3> colours(std::clamp<std::size_t>(object_count + 1, 2, 16384));
    for (std::size_t i = 0; i < colours.size(); ++i)
        colours[i] = item_colour(static_cast<std::uint32_t>(i));
    palette_.upload_row(colours);
}

Program& Compositor::program(View view, DiffMode diff_mode, bool overlay) {
    if (view == View::kGpuTrace) view = View::kTrace;  // the same picture, another source
    return programs_.get(
        {"VIEW " + std::to_string(static_cast<int>(view)),
         "DIFF_MODE " + std::to_string(view == View::kDiff ? static_cast<int>(diff_mode) : 0),
         std::string("OVERLAY ") + (overlay ? "1" : "0")});
}

void Compositor::draw(const CompositeInputs& in, int width, int height) {
    Program& program = this->program(in.view, in.diff_mode, in.overlay != 0);
    program.use();
    const GLuint textures[] = {in.raster,     in.traced,  in.item_buffer, heat_map_.id(),
                               palette_.id(), in.explain, in.overlay};
    const char* names[] = {"u_raster",  "u_traced",  "u_ids",    "u_heat",
                           "u_palette", "u_explain", "u_overlay"};
    for (int i = 0; i < 7; ++i) {
        glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(i));
        glBindTexture(GL_TEXTURE_2D, textures[i]);
        program.set(names[i], i);
    }
    glActiveTexture(GL_TEXTURE0);
    program.set("u_viewport",
                glm::vec3(static_cast<float>(width), static_cast<float>(height), 0.0f));
    program.set("u_divider", in.divider);
    program.set("u_swap", in.swap ? 1 : 0);
    program.set("u_diff_scale", std::max(in.diff_scale, 1e-4f));
    program.set("u_diff_threshold", in.diff_threshold);
    program.set("u_palette_size", palette_.width());
    program.set("u_ids_shift", in.item_buffer_shift);
    glDisable(GL_DEPTH_TEST);
    glBindVertexArray(vao_.get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    check("Compositor::draw");
}

}  // namespace rt::gl
