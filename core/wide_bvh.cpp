#include "core/wide_bvh.h"

#include <algorithm>
#include <limits>

#include "core/large_array.h"

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
template <int N>
class Collapser {
  public:
    Collapser(std::span<const BvhNode> tree, std::vector<WideBvhNode<N>>& out)
        : tree_(tree), out_(out), cost_(tree.size()), split_(tree.size()) {
        // Children come after their parent (the left one right after it), so one pass from
        // the back sees both children first.
        for (std::size_t i = tree.size(); i-- > 0;) {
            const BvhNode& n = tree[i];
            if (n.is_leaf()) {
                cost_[i].fill(0.0f);
                split_[i].fill(1);
                continue;
            }
            const std::array<float, N>& left = cost_[i + 1];
            const std::array<float, N>& right = cost_[n.first];
            // Both children within j lanes: the cheapest split, k lanes to the left (k = 1
            // where none is cheaper, as when a box beyond float's range has no finite area).
            std::array<float, N + 1> both{};
            std::array<std::uint8_t, N + 1> k_best{};
            for (int j = 2; j <= N; ++j) {
                float best = left[0] + right[j - 2];
                int k_at = 1;
                for (int k = 2; k < j; ++k) {  // without branches: which k wins is random
                    const float c = left[k - 1] + right[j - k - 1];
                    const bool cheaper = c < best;
                    best = cheaper ? c : best;
                    k_at = cheaper ? k : k_at;
                }
                both[j] = best;
                k_best[j] = static_cast<std::uint8_t>(k_at);
            }
            // One lane: a wide node of its own, its children in its N lanes. More lanes:
            // the children's, where that costs less than fewer lanes.
            cost_[i][0] = Aabb{n.lo, n.hi}.half_area() + both[N];
            split_[i][0] = k_best[N];
            for (int j = 2; j <= N; ++j) {
                const bool fewer = !(both[j] < cost_[i][j - 2]);
                cost_[i][j - 1] = fewer ? cost_[i][j - 2] : both[j];
                split_[i][j - 1] = fewer ? kFewer : k_best[j];
            }
        }
    }

    // Makes the wide node for binary node `index`; returns its position in `out`.
    std::uint32_t collapse(std::uint32_t index) {
        std::array<std::uint32_t, N> lanes{};
        int n = 0;
        if (tree_[index].is_leaf()) {
            lanes[n++] = index;  // a tree of one leaf
        } else {
            lanes_of(index + 1, split_[index][0], lanes, n);
            lanes_of(tree_[index].first, N - split_[index][0], lanes, n);
        }
        const auto at = static_cast<std::uint32_t>(out_.size());
        out_.push_back(empty_node<N>());
        for (int k = 0; k < n; ++k) {
            const BvhNode& c = tree_[lanes[k]];
            const std::uint32_t target = c.is_leaf() ? c.first : collapse(lanes[k]);
            WideBvhNode<N>& node = out_[at];  // collapse() may have moved the array
            set_lane(node, k, Aabb{c.lo, c.hi});
            node.child[k] = target;
            node.count[k] = c.count;  // 0 for a wide node
        }
        return at;
    }

  private:
    static constexpr std::uint8_t kFewer = 0;  // as cheap with a lane fewer

    // Appends the lanes binary node i takes when it may take up to j.
    void lanes_of(std::uint32_t i, int j, std::array<std::uint32_t, N>& lanes, int& n) const {
        while (j > 1 && split_[i][j - 1] == kFewer) --j;
        if (j == 1 || tree_[i].is_leaf()) {
            lanes[n++] = i;
            return;
        }
        const int k = split_[i][j - 1];
        lanes_of(i + 1, k, lanes, n);
        lanes_of(tree_[i].first, j - k, lanes, n);
    }

    std::span<const BvhNode> tree_;
    std::vector<WideBvhNode<N>>& out_;
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
    nodes_.reserve(binary.node_count() / (N - 1) + 1);
    Collapser<N>(binary.nodes(), nodes_).collapse(0);
}

template class WideBvh<4>;
#if defined(__AVX__)
template class WideBvh<8>;
#endif

}  // namespace rt
