#include "core/texture.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace rt {

int wrap_texel(int i, int size, Wrap mode) {
    switch (mode) {
        case Wrap::kClamp:
            return std::clamp(i, 0, size - 1);
        case Wrap::kMirror: {
            const int period = 2 * size;
            const int m = ((i % period) + period) % period;
            return m < size ? m : period - 1 - m;
        }
        default:
            return ((i % size) + size) % size;
    }
}

vec3 Texture::sample(glm::vec2 uv) const {
    if (width <= 0 || height <= 0) return vec3(1.0f);
    // Far outside [0, 1] a float has no fraction left: fold repeats into one period first.
    const auto fold = [](float c, Wrap mode) {
        if (mode == Wrap::kClamp || !std::isfinite(c)) return std::isfinite(c) ? c : 0.0f;
        const float period = mode == Wrap::kMirror ? 2.0f : 1.0f;
        return c - period * std::floor(c / period);
    };
    const float x = fold(uv.x, wrap_u) * static_cast<float>(width) - 0.5f;
    const float y = fold(uv.y, wrap_v) * static_cast<float>(height) - 0.5f;
    const float fx = std::floor(x), fy = std::floor(y);
    const float ax = x - fx, ay = y - fy;
    const float w = static_cast<float>(width), h = static_cast<float>(height);
    const int x0 = static_cast<int>(std::clamp(fx, -2.0f * w, 2.0f * w));
    const int y0 = static_cast<int>(std::clamp(fy, -2.0f * h, 2.0f * h));
    const int xa = wrap_texel(x0, width, wrap_u), xb = wrap_texel(x0 + 1, width, wrap_u);
    const int ya = wrap_texel(y0, height, wrap_v), yb = wrap_texel(y0 + 1, height, wrap_v);
    const vec3 top = (1.0f - ax) * at(xa, ya) + ax * at(xb, ya);
    const vec3 bottom = (1.0f - ax) * at(xa, yb) + ax * at(xb, yb);
    return (1.0f - ay) * top + ay * bottom;
}

namespace {

ImageReader& image_reader() {
    static ImageReader reader;  // set before main() by rt_image_io, when linked
    return reader;
}

[[noreturn]] void no_image_reader(const std::string& file, const std::string& where) {
    throw Error(file, where,
                "this program reads no image files (textures): it is built without rt_image_io");
}

}  // namespace

void install_image_reader(const ImageReader& reader) { image_reader() = reader; }

Texture read_texture(const std::filesystem::path& path, const std::string& file,
                     const std::string& where) {
    if (!image_reader().read) no_image_reader(file, where);
    return image_reader().read(path, file, where);
}

Texture decode_texture(const std::vector<unsigned char>& bytes, const std::string& extension,
                       const std::string& file, const std::string& where) {
    if (!image_reader().decode) no_image_reader(file, where);
    return image_reader().decode(bytes, extension, file, where);
}

}  // namespace rt
