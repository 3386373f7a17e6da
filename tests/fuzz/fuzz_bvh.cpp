// libFuzzer target: the BVH builders and traversals, fed boxes directly. The bytes pick
// boxes near the origin, far away (1e7, 1e30), collapsed onto one point, or repeated, and
// rays including NaN and infinite ones. Every traversal must end, stay in bounds (the
// sanitizers watch the fixed stacks), and visit each primitive at most once.
//
// A first byte of kMany or more asks for thousands of boxes, drawn from a generator the
// next bytes seed (the input is too short to spell them out): enough for the parts of
// the build that only large trees reach, the binary build's binning and partitioning on
// the pool (core/bvh.cpp, from kMinPart primitives) and the wide collapse's parts
// (core/wide_bvh.cpp, trees of over kPartNodes nodes).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <vector>

#include "core/bvh.h"
#include "core/wide_bvh.h"

namespace {

struct Bytes {
    const std::uint8_t* data;
    std::size_t size, at = 0;
    std::uint8_t next() { return at < size ? data[at++] : 0; }
    float coordinate(float base) {
        return base + static_cast<float>(static_cast<std::int8_t>(next())) * 0.25f;
    }
};

// Bytes from a seed instead of the input (a 32-bit LCG, its high byte): the many boxes.
struct Generated {
    std::uint32_t state;
    std::uint8_t next() {
        state = state * 1664525u + 1013904223u;
        return static_cast<std::uint8_t>(state >> 24);
    }
    float coordinate(float base) {
        return base + static_cast<float>(static_cast<std::int8_t>(next())) * 0.25f;
    }
};

constexpr std::uint8_t kMany = 0xF0;
constexpr std::size_t kManyStep = 2048;  // boxes per step above kMany: 2,048 to 32,768

template <class Source>
void add_box(Source& in, float base, std::vector<rt::Aabb>& boxes) {
    if (base == 0.5f) {
        boxes.push_back({rt::vec3(base), rt::vec3(base)});
        return;
    }
    const rt::vec3 lo{in.coordinate(base), in.coordinate(base), in.coordinate(base)};
    const rt::vec3 e{0.01f * in.next(), 0.01f * in.next(), 0.01f * in.next()};
    const int repeats = 1 + in.next() % 4;  // duplicated boxes
    for (int r = 0; r < repeats; ++r) boxes.push_back({lo, lo + e});
}

float base_of(std::uint8_t mode) {
    switch (mode % 6) {
        case 0:
            return 0.0f;
        case 1:
            return 1e3f;
        case 2:
            return 1e7f;
        case 3:
            return -1e7f;
        case 4:
            return 1e30f;
        default:
            return 0.5f;  // the collapsed case: every box the same point
    }
}

template <class Tree>
void walk(const Tree& tree, const std::vector<rt::Ray>& rays, std::size_t prims) {
    std::vector<std::uint8_t> seen(prims);
    for (const rt::Ray& ray : rays) {
        for (int any = 0; any < 2; ++any) {
            std::fill(seen.begin(), seen.end(), 0);
            float t_max = rt::kInfinity;
            const auto visit = [&](std::uint32_t slot, float&) {
                if (slot >= prims || seen[slot]++) std::abort();  // out of range, or twice
                return false;
            };
            if (any)
                tree.template traverse<true>(ray, t_max, visit);
            else
                tree.template traverse<false>(ray, t_max, visit);
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    Bytes in{data, size};
    const std::uint8_t first = in.next();
    const float base = base_of(in.next());
    std::vector<rt::Aabb> boxes;
    std::size_t max_rays = ~std::size_t{0};
    if (first >= kMany) {
        const std::size_t count = (first - kMany + 1u) * kManyStep;
        Generated gen{static_cast<std::uint32_t>(in.next()) << 8 | in.next()};
        while (boxes.size() < count) add_box(gen, base, boxes);
        max_rays = 16;  // each ray's walk clears a flag per box: keep an input under a second
    } else {
        const std::size_t count = 1 + first * 4u;
        for (std::size_t i = 0; i < count && in.at < in.size; ++i) add_box(in, base, boxes);
    }
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::vector<rt::Ray> rays = {{rt::vec3(nan), rt::vec3(1.0f)},
                                 {rt::vec3(base), rt::vec3(0.0f, 0.0f, 1.0f)},
                                 {rt::vec3(base - 100.0f), rt::vec3(1.0f, 1.0f, 1.0f)},
                                 {rt::vec3(base), rt::vec3(rt::kInfinity, 0.0f, 0.0f)}};
    while (in.at + 6 <= in.size && rays.size() < max_rays) {
        const rt::vec3 o{in.coordinate(base), in.coordinate(base), in.coordinate(base)};
        const rt::vec3 d{in.coordinate(0.0f), in.coordinate(0.0f), in.coordinate(0.0f)};
        rays.push_back({o, d});
    }
    for (std::uint32_t leaf : {1u, 4u}) {
        rt::Bvh binary;
        binary.build(boxes, leaf);
        walk(binary, rays, boxes.size());
        rt::WideBvh<4> wide4;
        wide4.build(boxes, leaf);
        walk(wide4, rays, boxes.size());
#if defined(__AVX__)
        rt::WideBvh<8> wide8;
        wide8.build(boxes, leaf);
        walk(wide8, rays, boxes.size());
#endif
#if defined(__AVX512F__)
        rt::WideBvh<16> wide16;
        wide16.build(boxes, leaf);
        walk(wide16, rays, boxes.size());
#endif
    }
    return 0;
}
