#include "core/wide_bvh.h"

#include <algorithm>
#include <cstring>
#include <limits>

#include "core/large_array.h"
#include "core/parallel.h"

namespace rt {
namespace {

template <int N>
void set_lane(WideBvhNode<N>& node, int lane, const Aabb& box) {
    for (int a = 0; a < 3; ++a) {
        node.bounds[a][lane] = box.lo[a];
        node.bounds[a + 3][lane] = box.hi[a];
    }
}

template <int N>
WideBvhNode<N> empty_node() {
    using Float = typename Lanes<N>::Float;
    WideBvhNode<N> node{};
    for (int a = 0; a < 3; ++a) {
        node.bounds[a] = splat<Float>(kInfinity);
        node.bounds[a + 3] = splat<Float>(-kInfinity);
    }
    return node;
}

// Calls body(item) for each item of a list sorted by `position` (a start within
// [0, total)), on the pool: in parts of about equal spans of [0, total), so that parts
// of many small items and of a few large ones take about as long.
template <class Items, class Position, class Body>
void for_each_spread(TaskPool* pool, int threads, Items& items, std::size_t total,
                     Position&& position, Body&& body) {
    const int parts = pool ? part_count(items.size(), threads * 4, 1) : 1;
    const auto first_at = [&](std::size_t at) {
        return std::partition_point(items.begin(), items.end(),
                                    [&](const auto& item) { return position(item) < at; });
    };
    parallel_parts(pool, 0, total, parts, [&](int, std::size_t begin, std::size_t end) {
        for (auto it = first_at(begin); it != items.end() && position(*it) < end; ++it) body(*it);
    });
}

// Collapses a binary BVH into wide nodes (build only), the collapse of least cost
// (Ylitie, Karras and Laine, "Efficient Incoherent Ray Traversal on GPUs Through
// Compressed Wide BVHs", HPG 2017). A ray enters a wide node about as often as the area
// of its box, so the cost of a collapse is the sum of its wide nodes' areas (its leaves
// are the binary tree's, whatever the collapse: their cost is the same). For each binary
// node and each number of lanes j <= N, from the leaves up: the least cost of its subtree
// when it may take up to j lanes of its parent, as one lane (a leaf, or a wide node of
// its own) or its two children's lanes, split between them as is cheapest. Then, from
// the root down, the tree those costs name.
//
// The greedy collapse it replaces (open the child of largest area until there are N)
// left the nodes near the leaves half empty, 3.5 to 4.4 lanes of 8 in use: 14,287 wide
// nodes for a 120,000-triangle vase where this one makes 8,267 (docs/BENCHMARKS.md).
//
// Both passes run on the pool. The binary tree is cut into parts, its subtrees of at
// most kPartNodes nodes (each a range of the depth-first array), and the few nodes above
// them, the top. Costs: the parts in parallel, then the top. The wide tree: the top's
// wide nodes first, then each part's wide nodes, written in parallel where a count of
// each part's nodes puts them. The cut depends on the tree alone, so the wide tree is
// the same on any number of threads.
template <int N>
class Collapser {
  public:
    using Node = WideBvhNode<N>;

    Collapser(std::span<const BvhNode> tree, TaskPool* pool, int threads)
        : tree_(tree), pool_(pool), threads_(threads), cost_(tree.size()), split_(tree.size()) {
        cut(0, static_cast<std::uint32_t>(tree.size()));
        for_each_spread(
            pool_, threads_, parts_, tree_.size(), [](const Range& r) { return r.first; },
            [&](const Range& r) {
                // Children come after their parent (the left one right after it), so one
                // pass from the back sees both children first.
                for (std::uint32_t i = r.end; i-- > r.first;) cost(i);
            });
        for (std::size_t k = top_.size(); k-- > 0;) cost(top_[k]);
    }

    // The wide tree, its root first.
    void write(LargeArray<Node>& out) {
        std::vector<Node> top;
        std::vector<Deferred> parts;
        if (top_.empty()) {
            parts.push_back({0, 0, kNoParent, 0});
        } else {
            write_top(0, static_cast<std::uint32_t>(tree_.size()), top, parts);
        }
        out.clear();
        if (pool_) {
            place_parts(top, parts, out);
        } else {  // one after the other: where each goes is known without counting
            out.reserve(tree_.size() / (N - 1) + 1);
            out.assign(top.begin(), top.end());
            for (Deferred& d : parts) {
                d.at = static_cast<std::uint32_t>(out.size());
                append_part(d.binary, out);
            }
        }
        for (const Deferred& d : parts)
            if (d.parent != kNoParent) out[d.parent].child[d.lane] = d.at;
    }

  private:
    static constexpr std::uint8_t kFewer = 0;  // as cheap with a lane fewer
    static constexpr std::uint32_t kPartNodes = 4096;
    static constexpr std::uint32_t kNoParent = ~0u;

    struct Range {
        std::uint32_t first, end;  // a subtree: binary nodes [first, end)
    };
    // A part's root, met as lane `lane` of the top's node `parent`; at: its count of
    // wide nodes, then where its first goes.
    struct Deferred {
        std::uint32_t binary, at, parent;
        int lane;
    };

    // Subtree [i, end) into the parts, or onto the top and its children cut in turn.
    void cut(std::uint32_t i, std::uint32_t end) {
        if (end - i <= kPartNodes || tree_[i].is_leaf()) {
            parts_.push_back({i, end});
            return;
        }
        top_.push_back(i);
        cut(i + 1, tree_[i].first);
        cut(tree_[i].first, end);
    }

    // Node i's costs, from its children's.
    void cost(std::uint32_t i) {
        const BvhNode& n = tree_[i];
        if (n.is_leaf()) {
            cost_[i].fill(0.0f);
            split_[i].fill(1);
            return;
        }
        // Both children within j lanes: the cheapest split, k lanes to the left (k = 1
        // where none is cheaper, as when a box beyond float's range has no finite area).
        // All j at once, lane j - 1: for each k, the left's cost with k lanes plus the
        // right's with j - k, read from the right's costs shifted up by k lanes behind
        // infinities (no split of j < k + 1 lanes gives the left k). In turn over k, a
        // lane keeps the first least: the comparisons a loop over j and k made.
        using Float = typename rt::Lanes<N>::Float;
        using Mask = typename rt::Lanes<N>::Mask;
        std::array<float, 2 * N> right;  // [N + m]: the right's cost with m + 1 lanes
        std::fill_n(right.begin(), N, kInfinity);
        std::copy(cost_[n.first].begin(), cost_[n.first].end(), right.begin() + N);
        const std::array<float, N>& left = cost_[i + 1];
        const auto right_with_left = [&](int k) {
            Float shifted;
            std::memcpy(&shifted, right.data() + N - k, sizeof shifted);
            return splat<Float>(left[k - 1]) + shifted;
        };
        Float both = right_with_left(1);
        Mask k_best = Mask{} + 1;
        for (int k = 2; k < N; ++k) {
            const Float c = right_with_left(k);
            const Mask cheaper = c < both;
            both = cheaper ? c : both;
            k_best = cheaper ? Mask{} + k : k_best;
        }
        // One lane: a wide node of its own, its children in its N lanes. More lanes:
        // the children's, where that costs less than fewer lanes.
        cost_[i][0] = Aabb{n.lo, n.hi}.half_area() + both[N - 1];
        split_[i][0] = static_cast<std::uint8_t>(k_best[N - 1]);
        for (int j = 2; j <= N; ++j) {
            const bool fewer = !(both[j - 1] < cost_[i][j - 2]);
            cost_[i][j - 1] = fewer ? cost_[i][j - 2] : both[j - 1];
            split_[i][j - 1] = fewer ? kFewer : static_cast<std::uint8_t>(k_best[j - 1]);
        }
    }

    struct Lanes {
        std::array<std::uint32_t, N> node{}, end{};  // binary node, its subtree's end
        int n = 0;
    };
    // The lanes of the wide node for interior binary node `index` (subtree [index, end)).
    Lanes lanes(std::uint32_t index, std::uint32_t end) const {
        Lanes l;
        if (tree_[index].is_leaf()) {  // a tree of one leaf
            l.node[0] = index, l.end[0] = end, l.n = 1;
            return l;
        }
        lanes_of(index + 1, tree_[index].first, split_[index][0], l);
        lanes_of(tree_[index].first, end, N - split_[index][0], l);
        return l;
    }
    // Appends the lanes binary node i (subtree [i, end)) takes when it may take up to j.
    void lanes_of(std::uint32_t i, std::uint32_t end, int j, Lanes& l) const {
        while (j > 1 && split_[i][j - 1] == kFewer) --j;
        if (j == 1 || tree_[i].is_leaf()) {
            l.node[l.n] = i, l.end[l.n] = end, ++l.n;
            return;
        }
        const int k = split_[i][j - 1];
        lanes_of(i + 1, tree_[i].first, k, l);
        lanes_of(tree_[i].first, end, j - k, l);
    }

    // The wide node for binary node `index` with its lanes (children: `child` of each).
    template <class Child>
    Node node(const Lanes& l, Child&& child) const {
        Node node = empty_node<N>();
        for (int k = 0; k < l.n; ++k) {
            const BvhNode& c = tree_[l.node[k]];
            set_lane(node, k, Aabb{c.lo, c.hi});
            node.child[k] = c.is_leaf() ? c.first : child(k);
            node.count[k] = c.count;  // 0 for a wide node
        }
        return node;
    }

    // The top's wide node for binary node `index`, into `top`, its lanes that root a
    // part into `parts`; returns its position.
    std::uint32_t write_top(std::uint32_t index, std::uint32_t end, std::vector<Node>& top,
                            std::vector<Deferred>& parts) const {
        const auto at = static_cast<std::uint32_t>(top.size());
        top.emplace_back();
        const Lanes l = lanes(index, end);
        const Node n = node(l, [&](int k) {
            if (l.end[k] - l.node[k] > kPartNodes)
                return write_top(l.node[k], l.end[k], top, parts);
            parts.push_back({l.node[k], 0, at, k});
            return 0u;  // set once the parts are placed
        });
        top[at] = n;
        return at;
    }

    // The wide nodes of the part rooted at binary node `index`.
    std::uint32_t count(std::uint32_t index) const {
        std::uint32_t total = 1;
        const Lanes l = lanes(index, 0);
        for (int k = 0; k < l.n; ++k)
            if (!tree_[l.node[k]].is_leaf()) total += count(l.node[k]);
        return total;
    }

    // Writes them from out[next] on, depth first.
    void write_part(std::uint32_t index, LargeArray<Node>& out, std::uint32_t& next) const {
        const std::uint32_t at = next++;
        const Lanes l = lanes(index, 0);
        out[at] = node(l, [&](int k) {
            const std::uint32_t child = next;
            write_part(l.node[k], out, next);
            return child;
        });
    }

    // On the pool: each part's wide nodes counted, then written where the counts put them.
    void place_parts(const std::vector<Node>& top, std::vector<Deferred>& parts,
                     LargeArray<Node>& out) const {
        for_each_spread(
            pool_, threads_, parts, tree_.size(), [](const Deferred& d) { return d.binary; },
            [&](Deferred& d) { d.at = count(d.binary); });
        auto at = static_cast<std::uint32_t>(top.size());
        for (Deferred& d : parts) at += std::exchange(d.at, at);
        out.resize(at);
        std::copy(top.begin(), top.end(), out.begin());
        for_each_spread(
            pool_, threads_, parts, at, [](const Deferred& d) { return d.at; },
            [&](const Deferred& d) {
                std::uint32_t next = d.at;
                write_part(d.binary, out, next);
            });
    }

    // The same, appended.
    void append_part(std::uint32_t index, LargeArray<Node>& out) const {
        const auto at = static_cast<std::uint32_t>(out.size());
        out.emplace_back();
        const Lanes l = lanes(index, 0);
        const Node n = node(l, [&](int k) {
            const auto child = static_cast<std::uint32_t>(out.size());
            append_part(l.node[k], out);
            return child;
        });
        out[at] = n;
    }

    std::span<const BvhNode> tree_;
    TaskPool* pool_;
    int threads_;
    std::vector<std::uint32_t> top_;  // the top's binary nodes, parents before children
    std::vector<Range> parts_;        // by first node
    // Written in full, children before parents, before anything reads them.
    LargeArray<std::array<float, N>> cost_;          // [node][j - 1]: up to j lanes
    LargeArray<std::array<std::uint8_t, N>> split_;  // [node][j - 1]: lanes to the left
};

}  // namespace

template <int N>
void WideBvh<N>::build(std::span<const Aabb> prim_boxes, std::uint32_t leaf_size, int threads,
                       std::uint32_t split_above) {
    nodes_.clear();
    prims_.clear();
    bounds_ = Aabb{};
    if (prim_boxes.empty()) return;
    leaf_size = std::max(1u, leaf_size);
    Bvh binary;
    binary.build(prim_boxes, leaf_size, threads, split_above);
    prims_ = binary.take_order();
    bounds_ = binary.bounds();
    threads = build_threads(threads);
    TaskPool* const pool = threads > 1 ? &TaskPool::shared(threads) : nullptr;
    Collapser<N>(binary.nodes(), pool, threads).write(nodes_);
}

template class WideBvh<4>;
#if defined(__AVX__)
template class WideBvh<8>;
#endif
#if defined(__AVX512F__)
template class WideBvh<16>;
#endif

}  // namespace rt
