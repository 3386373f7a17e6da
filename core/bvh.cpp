#include "core/bvh.h"

#include <algorithm>
#include <future>
#include <thread>

namespace rt {
namespace {

constexpr int kBins = 16;
constexpr std::uint32_t kMaxLeafSize = 2;
constexpr float kTraversalCost = 1.0f;         // relative to one primitive test
constexpr std::uint32_t kParallelMin = 20000;  // subtrees smaller than this are built in place

struct Split {
    int axis = -1;
    float position = 0.0f;
    float cost = kInfinity;
};

// Builds the subtree of prims[begin, end) into its own node array; the prims array is
// shared, and subtrees work on disjoint ranges of it, so they can run in parallel.
struct Builder {
    std::span<const Aabb> boxes;
    const std::vector<vec3>& centres;
    std::vector<std::uint32_t>& prims;
    std::vector<BvhNode> nodes;
    int parallel_depth = 0;  // levels still allowed to hand a subtree to another thread

    // Binned SAH (Wald, "On fast construction of SAH-based BVHs", 2007) along the axis
    // where the centroids spread most: one pass bins them, a sweep finds the cheapest split.
    Split find_split(std::uint32_t begin, std::uint32_t end, const Aabb& centre_box) const {
        const vec3 extent = centre_box.extent();
        const int axis =
            extent.x >= extent.y ? (extent.x >= extent.z ? 0 : 2) : (extent.y >= extent.z ? 1 : 2);
        if (!(extent[axis] > 0.0f)) return {};
        const float lo = centre_box.lo[axis], scale = static_cast<float>(kBins) / extent[axis];
        std::array<Aabb, kBins> bin_box{};
        std::array<std::uint32_t, kBins> bin_count{};
        for (std::uint32_t i = begin; i < end; ++i) {
            const std::uint32_t p = prims[i];
            const int b = std::min(kBins - 1, static_cast<int>((centres[p][axis] - lo) * scale));
            bin_box[b].grow(boxes[p]);
            ++bin_count[b];
        }
        // Sweep from the right for every right side's cost, then from the left.
        std::array<float, kBins> right_cost{};
        Aabb acc;
        std::uint32_t n = 0;
        for (int b = kBins - 1; b > 0; --b) {
            acc.grow(bin_box[b]);
            n += bin_count[b];
            right_cost[b] = acc.half_area() * static_cast<float>(n);
        }
        Split best;
        acc = Aabb{};
        n = 0;
        for (int b = 0; b < kBins - 1; ++b) {
            acc.grow(bin_box[b]);
            n += bin_count[b];
            const float cost = acc.half_area() * static_cast<float>(n) + right_cost[b + 1];
            if (cost < best.cost) best = {axis, lo + static_cast<float>(b + 1) / scale, cost};
        }
        return best;
    }

    std::uint32_t partition(std::uint32_t begin, std::uint32_t end, const Split& split) {
        const auto middle = std::partition(
            prims.begin() + begin, prims.begin() + end,
            [&](std::uint32_t p) { return centres[p][split.axis] < split.position; });
        const auto mid = static_cast<std::uint32_t>(middle - prims.begin());
        return mid == begin || mid == end ? begin + (end - begin) / 2
                                          : mid;  // rounding put all on one side
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
        const auto leaf = [&] {
            nodes[node].first = begin;
            nodes[node].count = count;
        };
        if (count <= 2 || depth >= Bvh::kMaxDepth) return leaf();
        const Split split = find_split(begin, end, centre_box);
        const float leaf_cost = box.half_area() * static_cast<float>(count);
        if (split.axis < 0 ||
            (kTraversalCost * box.half_area() + split.cost >= leaf_cost && count <= kMaxLeafSize))
            return leaf();
        const std::uint32_t mid = partition(begin, end, split);

        // The right subtree on another thread while this one builds the left.
        std::future<std::vector<BvhNode>> right_nodes;
        if (parallel_depth > 0 && end - mid >= kParallelMin) {
            // Captured by value: this builder goes on changing parallel_depth meanwhile.
            right_nodes = std::async(std::launch::async,
                                     [this, mid, end, depth, levels = parallel_depth - 1] {
                                         Builder right{boxes, centres, prims, {}, levels};
                                         right.nodes.reserve(2 * (end - mid));
                                         right.nodes.emplace_back();
                                         right.build(0, mid, end, depth + 1);
                                         return std::move(right.nodes);
                                     });
        }
        const auto left = static_cast<std::uint32_t>(nodes.size());
        nodes.emplace_back();
        const int spent = right_nodes.valid() ? 1 : 0;  // a thread went to the right subtree
        parallel_depth -= spent;
        build(left, begin, mid, depth + 1);
        parallel_depth += spent;
        const auto right = static_cast<std::uint32_t>(nodes.size());
        if (right_nodes.valid()) {
            std::vector<BvhNode> sub = right_nodes.get();
            for (BvhNode& n : sub)
                if (!n.is_leaf()) n.first += right;  // child links were relative to the subtree
            nodes.insert(nodes.end(), sub.begin(), sub.end());
        } else {
            nodes.emplace_back();
            build(right, mid, end, depth + 1);
        }
        nodes[node].first = right;
        nodes[node].count = 0;
    }
};

int parallel_levels() {
    int levels = 0;
    for (unsigned threads = std::max(1u, std::thread::hardware_concurrency()); threads > 1;
         threads /= 2)
        ++levels;
    return levels;
}

}  // namespace

void Bvh::build(std::span<const Aabb> prim_boxes) {
    nodes_.clear();
    prims_.clear();
    if (prim_boxes.empty()) return;
    prims_.resize(prim_boxes.size());
    std::vector<vec3> centres(prim_boxes.size());
    for (std::uint32_t i = 0; i < prim_boxes.size(); ++i) {
        prims_[i] = i;
        centres[i] = prim_boxes[i].centre();
    }
    Builder builder{prim_boxes, centres, prims_, {}, parallel_levels()};
    builder.nodes.reserve(2 * prim_boxes.size());
    builder.nodes.emplace_back();
    builder.build(0, 0, static_cast<std::uint32_t>(prim_boxes.size()), 0);
    nodes_ = std::move(builder.nodes);
}

}  // namespace rt
