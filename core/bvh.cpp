#include "core/bvh.h"

#include <algorithm>

namespace rt {
namespace {

constexpr int kBins = 16;
constexpr std::uint32_t kMaxLeafSize = 8;
constexpr float kTraversalCost = 1.0f;  // relative to one primitive test

struct Builder {
    std::span<const Aabb> boxes;
    std::vector<vec3> centres;
    std::vector<std::uint32_t>& prims;
    std::vector<BvhNode>& nodes;

    struct Split {
        int axis = -1;
        float position = 0.0f;
        float cost = kInfinity;
    };

    // Binned SAH (Wald, "On fast construction of SAH-based BVHs", 2007): bins the
    // centroids along each axis and sweeps the bin boundaries for the cheapest split.
    Split find_split(std::uint32_t begin, std::uint32_t end, const Aabb& centre_box) const {
        Split best;
        for (int axis = 0; axis < 3; ++axis) {
            const float lo = centre_box.lo[axis];
            const float extent = centre_box.hi[axis] - lo;
            if (!(extent > 0.0f)) continue;
            const float scale = static_cast<float>(kBins) / extent;
            std::array<Aabb, kBins> bin_box{};
            std::array<std::uint32_t, kBins> bin_count{};
            for (std::uint32_t i = begin; i < end; ++i) {
                const std::uint32_t p = prims[i];
                const int b =
                    std::min(kBins - 1, static_cast<int>((centres[p][axis] - lo) * scale));
                bin_box[b].grow(boxes[p]);
                ++bin_count[b];
            }
            // Sweep from the right to get the cost of every right side, then from the left.
            std::array<float, kBins> right_cost{};
            Aabb acc;
            std::uint32_t n = 0;
            for (int b = kBins - 1; b > 0; --b) {
                acc.grow(bin_box[b]);
                n += bin_count[b];
                right_cost[b] = acc.half_area() * static_cast<float>(n);
            }
            acc = Aabb{};
            n = 0;
            for (int b = 0; b < kBins - 1; ++b) {
                acc.grow(bin_box[b]);
                n += bin_count[b];
                const float cost = acc.half_area() * static_cast<float>(n) + right_cost[b + 1];
                if (cost < best.cost) {
                    best = {axis, lo + static_cast<float>(b + 1) / scale, cost};
                }
            }
        }
        return best;
    }

    void make_leaf(std::uint32_t node, std::uint32_t begin, std::uint32_t end) {
        nodes[node].first = begin;
        nodes[node].count = end - begin;
    }

    void build(std::uint32_t node, std::uint32_t begin, std::uint32_t end, int depth) {
        Aabb box, centre_box;
        for (std::uint32_t i = begin; i < end; ++i) {
            box.grow(boxes[prims[i]]);
            centre_box.grow(centres[prims[i]]);
        }
        nodes[node].lo = box.lo;
        nodes[node].hi = box.hi;
        const std::uint32_t count = end - begin;
        if (count <= 2 || depth >= Bvh::kMaxDepth) return make_leaf(node, begin, end);

        const Split split = find_split(begin, end, centre_box);
        const float leaf_cost = box.half_area() * static_cast<float>(count);
        const float split_cost = kTraversalCost * box.half_area() + split.cost;
        if (split.axis < 0 || (split_cost >= leaf_cost && count <= kMaxLeafSize))
            return make_leaf(node, begin, end);

        auto middle = std::partition(
            prims.begin() + begin, prims.begin() + end,
            [&](std::uint32_t p) { return centres[p][split.axis] < split.position; });
        auto mid = static_cast<std::uint32_t>(middle - prims.begin());
        if (mid == begin || mid == end) mid = begin + count / 2;  // rounding put all on one side

        const auto left = static_cast<std::uint32_t>(nodes.size());
        nodes.emplace_back();
        build(left, begin, mid, depth + 1);
        const auto right = static_cast<std::uint32_t>(nodes.size());
        nodes.emplace_back();
        build(right, mid, end, depth + 1);
        nodes[node].first = right;
        nodes[node].count = 0;
    }
};

}  // namespace

void Bvh::build(std::span<const Aabb> prim_boxes) {
    nodes_.clear();
    prims_.clear();
    if (prim_boxes.empty()) return;
    prims_.resize(prim_boxes.size());
    Builder builder{prim_boxes, {}, prims_, nodes_};
    builder.centres.reserve(prim_boxes.size());
    for (std::uint32_t i = 0; i < prim_boxes.size(); ++i) {
        prims_[i] = i;
        builder.centres.push_back(prim_boxes[i].centre());
    }
    nodes_.reserve(2 * prim_boxes.size());
    nodes_.emplace_back();
    builder.build(0, 0, static_cast<std::uint32_t>(prim_boxes.size()), 0);
}

}  // namespace rt
