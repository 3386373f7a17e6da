#include "core/image.h"

#include <algorithm>
#include <array>
#include <bit>
#include <limits>

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

namespace {

// The byte by the formula: what the table must reproduce.
int srgb8_by_formula(float linear) {
    return static_cast<int>(std::lround(srgb_encode(linear) * 255.0f));
}

// first[v]: the smallest float whose byte is v or more (v = 1 .. 255), found by bisection
// over the bit patterns of [0, 1], which order as the floats do. The byte of c is then how
// many of them c reaches, since the formula never falls as c grows (tests/unit/
// test_image.cpp checks that and every boundary; all 1,065,353,217 floats of [0, 1] were
// checked once). For speed, the floats of [0, 1) are cut into buckets by the top 16 bits
// of their patterns (each 1/128 of its value wide, narrower than a byte's step anywhere):
// a bucket knows its first float's byte and where the next byte begins.
class Srgb8Table {
  public:
    Srgb8Table() {
        for (int v = 1; v < 256; ++v) {
            std::uint32_t lo = 0, hi = std::bit_cast<std::uint32_t>(1.0f);  // byte(hi) = 255
            while (lo < hi) {
                const std::uint32_t mid = lo + (hi - lo) / 2;
                if (srgb8_by_formula(std::bit_cast<float>(mid)) >= v)
                    hi = mid;
                else
                    lo = mid + 1;
            }
            first_[v] = std::bit_cast<float>(lo);
        }
        buckets_.resize(std::bit_cast<std::uint32_t>(1.0f) >> kShift);
        for (std::uint32_t i = 0; i < buckets_.size(); ++i) {
            const float lo = std::bit_cast<float>(i << kShift);
            const float hi = std::bit_cast<float>(((i + 1) << kShift) - 1);
            const int v = search(lo);
            Bucket& b = buckets_[i];
            b.byte = static_cast<std::uint32_t>(v);
            b.next = v < 255 ? first_[v + 1] : std::numeric_limits<float>::infinity();
            if (v < 254 && first_[v + 2] <= hi) b.byte = kSearch;  // two steps inside (none here)
        }
    }

    std::uint8_t byte(float c) const {
        if (!(c > 0.0f)) return 0;  // zero, negative or NaN
        if (c >= 1.0f) return 255;
        const Bucket& b = buckets_[std::bit_cast<std::uint32_t>(c) >> kShift];
        if (b.byte == kSearch) return static_cast<std::uint8_t>(search(c));
        return static_cast<std::uint8_t>(b.byte + (c >= b.next ? 1u : 0u));
    }

  private:
    static constexpr int kShift = 16;
    static constexpr std::uint32_t kSearch = 256;
    struct Bucket {
        float next;          // the next byte's first float
        std::uint32_t byte;  // the byte of the bucket's first float, or kSearch
    };
    // Binary search without branches: how many of first[1 .. 255] c reaches.
    int search(float c) const {
        int v = 0;
        for (int step = 128; step > 0; step >>= 1) v += c >= first_[v + step] ? step : 0;
        return v;
    }
    std::array<float, 256> first_{};
    std::vector<Bucket> buckets_;
};

const Srgb8Table& srgb8_table() {
    static const Srgb8Table table;
    return table;
}

}  // namespace

std::uint8_t srgb8(float linear) { return srgb8_table().byte(linear); }

std::vector<std::uint8_t> to_srgb8(const Image& image) {
    const Srgb8Table& table = srgb8_table();
    std::vector<std::uint8_t> bytes(image.pixels.size() * 3);
    std::size_t i = 0;
    for (int y = image.height - 1; y >= 0; --y) {
        for (int x = 0; x < image.width; ++x) {
            const vec3& c = image.at(x, y);
            for (int k = 0; k < 3; ++k) bytes[i++] = table.byte(c[k]);
        }
    }
    return bytes;
}

}  // namespace rt
