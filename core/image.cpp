#include "core/image.h"

#include <algorithm>

namespace rt {

float srgb_encode(float linear) {
    const float c = std::clamp(linear, 0.0f, 1.0f);
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

vec3 from_srgb8(int r, int g, int b) {
    return {srgb_decode(static_cast<float>(r) / 255.0f),
            srgb_decode(static_cast<float>(g) / 255.0f),
            srgb_decode(static_cast<float>(b) / 255.0f)};
}

float srgb_decode(float encoded) {
    const float c = std::clamp(encoded, 0.0f, 1.0f);
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

std::vector<std::uint8_t> to_srgb8(const Image& image) {
    std::vector<std::uint8_t> bytes(image.pixels.size() * 3);
    std::size_t i = 0;
    for (int y = image.height - 1; y >= 0; --y) {
        for (int x = 0; x < image.width; ++x) {
            const vec3& c = image.at(x, y);
            for (int k = 0; k < 3; ++k)
                bytes[i++] = static_cast<std::uint8_t>(std::lround(srgb_encode(c[k]) * 255.0f));
        }
    }
    return bytes;
}

}  // namespace rt
