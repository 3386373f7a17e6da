#pragma once
// Puts a view on the screen: the raster image, the traced image, the two split at a
// divider, their difference in false colour, the item buffer, or why they differ (the
// explain map); encoded to sRGB
// by the same transfer function as the files.

#include "app/gl/handle.h"
#include "app/gl/program.h"
#include "app/gl/texture.h"

namespace rt::gl {

// In the order of the keys 1 to 7 (the viewer relies on it). The GPU-traced view is drawn
// as the traced view, with the GPU tracer's image as `traced`.
enum class View { kRaster, kTrace, kSplit, kDiff, kItemBuffer, kWhy, kGpuTrace };

// How the difference view shows raster - traced (sRGB values).
enum class DiffMode {
    kHeat,      // the largest channel's |difference| through the heat colour map
    kSigned,    // luminance: red where the raster is brighter, blue where the traced is
    kChannels,  // |difference| per channel, as a colour
};

struct CompositeInputs {
    GLuint raster = 0;               // RGBA32F, linear
    GLuint traced = 0;               // RGB32F, linear, any resolution (coarse while moving)
    GLuint item_buffer = 0;          // R32UI object ids, shifted up by item_buffer_shift bits
    unsigned item_buffer_shift = 0;  // the target's IdLayout::shader_prim_bits()
    GLuint explain = 0;              // RGB32F, linear: core's explain map in colour (the why view)
    GLuint overlay = 0;              // RGBA32F, linear, over any view (a picked pixel's rays), or 0
    View view = View::kSplit;
    float divider = 0.5f;     // split: the divider's x as a share of the width
    bool swap = false;        // split: traced on the left
    float diff_scale = 0.5f;  // diff: the difference shown at the top of the colour map
    DiffMode diff_mode = DiffMode::kHeat;
    float diff_threshold = 0.0f;  // diff: > 0: a mask, white where a channel differs by more
};

class Compositor {
  public:
    explicit Compositor(const std::filesystem::path& shaders = shader_dir());

    // Draws into the bound framebuffer over the viewport (x, y, width, height).
    void draw(const CompositeInputs& in, int width, int height);
    // The palette of item-buffer ids, from core's item_colour(), for `object_count` objects.
    void set_item_palette(std::size_t object_count);
    // present.frag compiled for a view (compiled when first asked for).
    Program& program(View view, DiffMode diff_mode, bool overlay);

  private:
    ProgramVariants programs_;  // per view, difference mode and overlay
    Texture heat_map_;
    Texture palette_;
    VertexArrayHandle vao_;
};

}  // namespace rt::gl
