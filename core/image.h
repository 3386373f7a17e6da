#pragma once
// Linear float RGB, stored bottom row first like OpenGL; flipped once when written.

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "core/ray.h"

namespace rt {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<vec3> pixels;  // row-major, row 0 at the bottom

    Image() = default;
    Image(int w, int h)
        : width(w), height(h), pixels(static_cast<std::size_t>(w) * h, vec3(0.0f)) {}

    // To w x h, keeping the storage where it is big enough: a frame read into the
    // previous frame's image, not into fresh pages (the kernel zeroes each on first
    // touch: 1280 x 720 floats cost about 4 ms of page faults here). Pixels are left
    // as they were; the caller overwrites them.
    void resize(int w, int h) {
        width = w, height = h;
        pixels.resize(static_cast<std::size_t>(w) * h);
    }

    vec3& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * width + x]; }
    const vec3& at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
};

// The sRGB transfer function (IEC 61966-2-1), on [0, 1]; values outside are clamped.
float srgb_encode(float linear);
float srgb_decode(float encoded);
inline vec3 srgb_encode(const vec3& linear) {
    return {srgb_encode(linear.x), srgb_encode(linear.y), srgb_encode(linear.z)};
}
// A colour given as 8-bit sRGB (as palettes are written), in linear RGB.
vec3 from_srgb8(int r, int g, int b);
// One channel as 8-bit sRGB: lround(255 srgb_encode(linear)), bit for bit, from a table
// of the smallest value that reaches each byte (no power per channel: to_srgb8 of a
// 1280 x 720 frame took 9 % of rtrender's instructions, 345 M, in powf). NaN gives 0.
std::uint8_t srgb8(float linear);
// 8-bit sRGB, top row first: what a PNG holds.
std::vector<std::uint8_t> to_srgb8(const Image& image);

// Writes .png (8-bit sRGB) or .exr (linear half float); throws rt::Error on failure.
void write_image(const Image& image, const std::filesystem::path& path);
// Reads any format OpenImageIO knows into linear RGB (8-bit files are taken as sRGB).
Image read_image(const std::filesystem::path& path);
bool is_supported_output(const std::filesystem::path& path);

}  // namespace rt
