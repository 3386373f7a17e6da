// libFuzzer target: the BVH builders and traversals, fed boxes directly. The bytes pick
// boxes near the origin, far away (1e7, 1e30), collapsed onto one point, or repeated, and
// rays including NaN and infinite ones. Every traversal must end, stay in bounds (the
// sanitizers watch the fixed stacks), and visit each primitive at most once.
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
    const std::size_t count = 1 + in.next() * 4u;
    const float base = base_of(in.next());
    std::vector<rt::Aabb> boxes;
    for (std::size_t i = 0; i < count && in.at < in.size; ++i) {
        if (base == 0.5f) {
            boxes.push_back({rt::vec3(base), rt::vec3(base)});
            continue;
        }
        const rt::vec3 lo{in.coordinate(base), in.coordinate(base), in.coordinate(base)};
        const rt::vec3 e{0.01f * in.next(), 0.01f * in.next(), 0.01f * in.next()};
        const int repeats = 1 + in.next() % 4;  // duplicated boxes
        for (int r = 0; r < repeats; ++r) boxes.push_back({lo, lo + e});
    }
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::vector<rt::Ray> rays = {{rt::vec3(nan), rt::vec3(1.0f)},
                                 {rt::vec3(base), rt::vec3(0.0f, 0.0f, 1.0f)},
                                 {rt::vec3(base - 100.0f), rt::vec3(1.0f, 1.0f, 1.0f)},
                                 {rt::vec3(base), rt::vec3(rt::kInfinity, 0.0f, 0.0f)}};
    while (in.at + 6 <= in.size) {
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
    }
    return 0;
}
