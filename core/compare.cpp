#include "core/compare.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include <glm/common.hpp>

#include "core/bitmap_font.h"

namespace rt {
namespace {

// Per channel, on the displayed values. A NaN or infinite pixel (a broken render) is as
// far as a pixel can be from anything: 1 in every channel, never a NaN statistic.
vec3 pixel_difference(const vec3& a, const vec3& b) {
    if (!finite(a) || !finite(b)) return vec3(1.0f);
    return glm::abs(srgb_encode(a) - srgb_encode(b));
}

// Colours given in sRGB terms are decoded, so that they show as written once encoded.
vec3 from_srgb(float r, float g, float b) {
    return {srgb_decode(r), srgb_decode(g), srgb_decode(b)};
}

std::string short_number(float v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.3g", static_cast<double>(v));
    std::string s = buffer;
    s.erase(std::remove(s.begin(), s.end(), '+'), s.end());
    return s;
}

}  // namespace

vec3 heat_colour(float t) {
    static const std::array<vec3, 5> stops = {
        from_srgb(0, 0, 0), from_srgb(0.1f, 0.2f, 0.85f), from_srgb(0.8f, 0.15f, 0.75f),
        from_srgb(1.0f, 0.55f, 0.1f), from_srgb(1.0f, 1.0f, 0.4f)};
    const float x = std::clamp(t, 0.0f, 1.0f) * static_cast<float>(stops.size() - 1);
    const auto i = std::min(static_cast<std::size_t>(x), stops.size() - 2);
    const float f = x - static_cast<float>(i);
    return stops[i] * (1.0f - f) + stops[i + 1] * f;
}

ImageDiff compare_images(const Image& a, const Image& b, double threshold) {
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument("compare_images: the sizes differ");
    ImageDiff d;
    d.threshold = threshold;
    double sum = 0.0, sum_sq = 0.0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        const vec3 diff = pixel_difference(a.pixels[i], b.pixels[i]);
        d.non_finite += !finite(a.pixels[i]) || !finite(b.pixels[i]);
        double largest = 0.0;
        for (int k = 0; k < 3; ++k) {
            sum += diff[k];
            sum_sq += static_cast<double>(diff[k]) * diff[k];
            largest = std::max(largest, static_cast<double>(diff[k]));
        }
        d.max_error = std::max(d.max_error, largest);
        d.pixels_over += largest > threshold;
    }
    const double n = 3.0 * static_cast<double>(std::max<std::size_t>(1, a.pixels.size()));
    d.mean_abs_error = sum / n;
    d.rms = std::sqrt(sum_sq / n);
    d.psnr_db = d.rms > 0.0 ? 20.0 * std::log10(1.0 / d.rms) : INFINITY;
    d.share_over = static_cast<double>(d.pixels_over) /
                   std::max<double>(1.0, static_cast<double>(a.pixels.size()));
    return d;
}

Image difference_image(const Image& a, const Image& b, float scale) {
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument("difference_image: the sizes differ");
    // The scale down the right-hand side: a colour strip, and its end values beside it.
    const int text_scale = a.height >= 200 ? 2 : 1;
    const int strip = 4 + 4 * text_scale;
    const int bar = strip + 4 + 4 * text_scale * 6;
    Image out(a.width + bar, a.height);
    const float s = scale > 0.0f ? scale : 1.0f;
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            const vec3 d = pixel_difference(a.at(x, y), b.at(x, y));
            out.at(x, y) = heat_colour(std::max({d.x, d.y, d.z}) / s);
        }
        const vec3 c =
            heat_colour(static_cast<float>(y) / static_cast<float>(std::max(1, a.height - 1)));
        for (int x = a.width + 2; x < a.width + strip; ++x) out.at(x, y) = c;
    }
    const vec3 white(1.0f);
    const int text_x = a.width + strip + 3;
    draw_text(out, text_x, a.height - 2, short_number(s), text_scale, white);  // top: the scale
    draw_text(out, text_x, 6 * text_scale, "0", text_scale, white);            // bottom: zero
    return out;
}

vec3 item_colour(std::uint32_t id) {
    if (id == ItemBuffer::kEmpty) return vec3(0.0f);
    // A golden-ratio walk around the hue circle keeps neighbouring ids apart.
    const float hue = std::fmod(static_cast<float>(id) * 0.61803398875f, 1.0f);
    const vec3 rgb =
        glm::clamp(glm::abs(glm::mod(hue * 6.0f + vec3(0, 4, 2), 6.0f) - 3.0f) - 1.0f, 0.0f, 1.0f);
    return from_srgb(0.25f + 0.75f * rgb.x, 0.25f + 0.75f * rgb.y, 0.25f + 0.75f * rgb.z);
}

Image item_buffer_image(const ItemBuffer& ib) {
    Image out(ib.width, ib.height);
    for (std::size_t i = 0; i < ib.ids.size(); ++i) out.pixels[i] = item_colour(ib.object_id(i));
    return out;
}

}  // namespace rt
