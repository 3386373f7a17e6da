#pragma once
// Comparing two renders of the same view (raster against traced, with against without
// the item buffer), and showing the difference. Errors are measured on the displayed
// values: sRGB-encoded, clamped to [0, 1], as the PNG files hold them.

#include <cstdint>

#include "core/image.h"
#include "core/item_buffer.h"

namespace rt {

struct ImageDiff {
    double mean_abs_error = 0.0;  // over all channels of all pixels
    double rms = 0.0;
    double psnr_db = 0.0;  // infinite when identical (rms 0): print identical() instead
    bool identical() const { return rms == 0.0; }
    double max_error = 0.0;   // the largest channel difference
    double share_over = 0.0;  // share of pixels with a channel differing by more than `threshold`
    std::uint64_t pixels_over = 0;
    std::uint64_t non_finite = 0;  // pixels NaN or infinite in either image (counted as over)
    double threshold = 0.0;
};

// Throws std::invalid_argument if the sizes differ.
ImageDiff compare_images(const Image& a, const Image& b, double threshold = 2.0 / 255.0);

// A false-colour map of the per-pixel difference (largest channel, encoded), from black
// (equal) through blue, magenta and orange to yellow at `scale`, with the colour bar
// and its end values drawn down the right-hand side. Linear RGB, ready to write.
Image difference_image(const Image& a, const Image& b, float scale);

// Object ids in distinct false colours (black where there is nothing).
Image item_buffer_image(const ItemBuffer& ib);
// The colour of one id in that image (linear RGB).
vec3 item_colour(std::uint32_t id);

// The colour map itself, t in [0, 1].
vec3 heat_colour(float t);

}  // namespace rt
