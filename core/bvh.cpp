#include "core/bvh.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <future>
#include <thread>

#include "core/simd.h"

namespace rt {
namespace {

constexpr int kBins = 16;
constexpr std::uint32_t kParallelMin = 20000;  // subtrees smaller than this are built in place

// A box in SIMD lanes x, y, z (the fourth is spare), so growing it is two instructions.
struct Box4 {
    Float4 lo = splat<Float4>(kInfinity), hi = splat<Float4>(-kInfinity);

    void grow(const Float4& l, const Float4& h) {
        lo = vmin(lo, l);
        hi = vmax(hi, h);
    }
    void grow(const Box4& b) { grow(b.lo, b.hi); }
    float half_area() const {
        const Float4 e = hi - lo;
        return e[0] >= 0.0f && e[1] >= 0.0f && e[2] >= 0.0f
                   ? e[0] * e[1] + e[1] * e[2] + e[2] * e[0]
                   : 0.0f;
    }
    Aabb aabb() const { return {{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}}; }
};

// A primitive's box, moved around in place as the build partitions: no indirection.
// The spare lane of lo carries the primitive's index, of hi nothing.
struct PrimRef {
    Float4 lo, hi;

    std::uint32_t index() const { return std::bit_cast<std::uint32_t>(lo[3]); }
    Float4 centre2() const { return lo + hi; }  // twice the centre: the halving is left out
};

// The primitives of a subtree: their boxes' union and their centres' (doubled) bounds.
struct Bounds {
    Box4 box, centres;
};

struct Split {
    int axis = -1;
    int bin = 0;  // bins [0, bin] go left
    float cost = kInfinity;
    Bounds left, right;
};

// Which of the bins along one axis a doubled centre falls in.
struct Binner {
    int axis;
    float lo, scale;

    int operator()(const PrimRef& p) const {
        const int b = static_cast<int>((p.centre2()[axis] - lo) * scale);
        return std::clamp(b, 0, kBins - 1);
    }
};

// Builds the subtree of refs[begin, end) into its own node array; the refs array is
// shared, and subtrees work on disjoint ranges of it, so they can run in parallel.
struct Builder {
    std::vector<PrimRef>& refs;
    std::uint32_t max_leaf;
    std::vector<BvhNode> nodes;
    int parallel_depth = 0;  // levels still allowed to hand a subtree to another thread

    // Binned SAH (Wald, "On fast construction of SAH-based BVHs", 2007) along the axis
    // where the centres spread most: one pass bins them, a sweep finds the cheapest split
    // and, from the bins, both sides' bounds, so no child needs a pass of its own.
    Split find_split(std::uint32_t begin, std::uint32_t end, const Bounds& bounds,
                     Binner& binner) const {
        const Float4 extent = bounds.centres.hi - bounds.centres.lo;
        const int axis = extent[0] >= extent[1] ? (extent[0] >= extent[2] ? 0 : 2)
                                                : (extent[1] >= extent[2] ? 1 : 2);
        const float scale = static_cast<float>(kBins) / extent[axis];
        if (!(extent[axis] > 0.0f) || !std::isfinite(scale)) return {};
        binner = {axis, bounds.centres.lo[axis], scale};
        std::array<Bounds, kBins> bins{};
        std::array<std::uint32_t, kBins> count{};
        for (std::uint32_t i = begin; i < end; ++i) {
            const PrimRef& p = refs[i];
            const int b = binner(p);
            bins[b].box.grow(p.lo, p.hi);
            const Float4 c = p.centre2();
            bins[b].centres.grow(c, c);
            ++count[b];
        }
        // Sweep from the right for every right side, then from the left.
        std::array<Bounds, kBins> right{};
        std::array<float, kBins> right_cost{};
        Bounds acc;
        std::uint32_t n = 0;
        for (int b = kBins - 1; b > 0; --b) {
            acc.box.grow(bins[b].box);
            acc.centres.grow(bins[b].centres);
            n += count[b];
            right[b] = acc;
            right_cost[b] = acc.box.half_area() * static_cast<float>(n);
        }
        Split best;
        acc = Bounds{};
        n = 0;
        for (int b = 0; b < kBins - 1; ++b) {
            acc.box.grow(bins[b].box);
            acc.centres.grow(bins[b].centres);
            n += count[b];
            const float cost = acc.box.half_area() * static_cast<float>(n) + right_cost[b + 1];
            if (n > 0 && n < end - begin && cost < best.cost)
                best = {axis, b, cost, acc, right[b + 1]};
        }
        return best;
    }

    void build(std::uint32_t node, std::uint32_t begin, std::uint32_t end, const Bounds& bounds,
               int depth) {
        const Aabb box = bounds.box.aabb();
        nodes[node].lo = box.lo;
        nodes[node].hi = box.hi;
        const std::uint32_t count = end - begin;
        const auto leaf = [&] {
            nodes[node].first = begin;
            nodes[node].count = count;
        };
        if (count <= max_leaf || depth >= Bvh::kMaxDepth) return leaf();
        Binner binner{};
        const Split split = find_split(begin, end, bounds, binner);
        if (split.axis < 0) return leaf();  // all centres in one point: nothing separates them
        const auto middle =
            std::partition(refs.begin() + begin, refs.begin() + end,
                           [&](const PrimRef& p) { return binner(p) <= split.bin; });
        const auto mid = static_cast<std::uint32_t>(middle - refs.begin());

        // The right subtree on another thread while this one builds the left.
        std::future<std::vector<BvhNode>> right_nodes;
        if (parallel_depth > 0 && end - mid >= kParallelMin) {
            // Captured by value: this builder goes on changing parallel_depth meanwhile.
            right_nodes = std::async(
                std::launch::async,
                [this, mid, end, depth, right = split.right, levels = parallel_depth - 1] {
                    Builder sub{refs, max_leaf, {}, levels};
                    sub.nodes.reserve(2 * (end - mid) / max_leaf);
                    sub.nodes.emplace_back();
                    sub.build(0, mid, end, right, depth + 1);
                    return std::move(sub.nodes);
                });
        }
        const auto left = static_cast<std::uint32_t>(nodes.size());
        nodes.emplace_back();
        const int spent = right_nodes.valid() ? 1 : 0;  // a thread went to the right subtree
        parallel_depth -= spent;
        build(left, begin, mid, split.left, depth + 1);
        parallel_depth += spent;
        const auto right = static_cast<std::uint32_t>(nodes.size());
        if (right_nodes.valid()) {
            std::vector<BvhNode> sub = right_nodes.get();
            for (BvhNode& n : sub)
                if (!n.is_leaf()) n.first += right;  // child links were relative to the subtree
            nodes.insert(nodes.end(), sub.begin(), sub.end());
        } else {
            nodes.emplace_back();
            build(right, mid, end, split.right, depth + 1);
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

void Bvh::build(std::span<const Aabb> prim_boxes, std::uint32_t max_leaf) {
    nodes_.clear();
    prims_.clear();
    if (prim_boxes.empty()) return;
    std::vector<PrimRef> refs(prim_boxes.size());
    Bounds bounds;
    for (std::uint32_t i = 0; i < prim_boxes.size(); ++i) {
        const Aabb& b = prim_boxes[i];
        refs[i] = {Float4{b.lo.x, b.lo.y, b.lo.z, std::bit_cast<float>(i)},
                   Float4{b.hi.x, b.hi.y, b.hi.z, 0.0f}};
        bounds.box.grow(refs[i].lo, refs[i].hi);
        const Float4 c = refs[i].centre2();
        bounds.centres.grow(c, c);
    }
    Builder builder{refs, std::max(1u, max_leaf), {}, parallel_levels()};
    builder.nodes.reserve(2 * prim_boxes.size() / builder.max_leaf + 1);
    builder.nodes.emplace_back();
    builder.build(0, 0, static_cast<std::uint32_t>(refs.size()), bounds, 0);
    nodes_ = std::move(builder.nodes);
    prims_.resize(refs.size());
    for (std::size_t s = 0; s < refs.size(); ++s) prims_[s] = refs[s].index();
}

}  // namespace rt
