#include "core/wide_bvh.h"

#include <algorithm>
#include <limits>

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

// Collapses a binary BVH into wide nodes (build only): each wide node opens its binary
// node's children, the largest (by surface area) interior one first, until there are N;
// a child of at most leaf_size primitives becomes a leaf lane.
template <int N>
class Collapser {
  public:
    Collapser(std::span<const BvhNode> tree, std::uint32_t leaf_size,
              std::vector<WideBvhNode<N>>& out)
        : tree_(tree), leaf_size_(leaf_size), out_(out), begin_(tree.size()), end_(tree.size()) {
        // Each binary node's slot range: children come after their parent, so one pass
        // from the back sees both children first.
        for (std::size_t i = tree.size(); i-- > 0;) {
            const BvhNode& n = tree[i];
            begin_[i] = n.is_leaf() ? n.first : begin_[i + 1];
            end_[i] = n.is_leaf() ? n.first + n.count : end_[n.first];
        }
    }

    // Makes the wide node for binary node `index`; returns its position in `out`.
    std::uint32_t collapse(std::uint32_t index) {
        std::array<std::uint32_t, N> children{};
        std::array<float, N> area{};  // each child's, computed once
        int n = 1;
        children[0] = index;
        while (n < N) {
            int widest = -1;
            for (int k = 0; k < n; ++k)
                if (opens(children[k]) && (widest < 0 || area[k] > area[widest])) widest = k;
            if (widest < 0) break;
            const std::uint32_t parent = children[widest];
            children[widest] = parent + 1;  // the left child follows its parent
            area[widest] = box(parent + 1).half_area();
            children[n] = tree_[parent].first;
            area[n] = box(children[n]).half_area();
            ++n;
        }

        const auto at = static_cast<std::uint32_t>(out_.size());
        out_.push_back(empty_node<N>());
        for (int k = 0; k < n; ++k) {
            const std::uint32_t c = children[k];
            const bool leaf = !opens(c);
            const std::uint32_t target = leaf ? begin_[c] : collapse(c);
            WideBvhNode<N>& node = out_[at];  // collapse() may have moved the array
            set_lane(node, k, box(c));
            node.child[k] = target;
            node.count[k] = leaf ? size(c) : 0;
        }
        return at;
    }

  private:
    std::uint32_t size(std::uint32_t i) const { return end_[i] - begin_[i]; }
    Aabb box(std::uint32_t i) const { return {tree_[i].lo, tree_[i].hi}; }
    bool opens(std::uint32_t i) const { return !tree_[i].is_leaf() && size(i) > leaf_size_; }

    std::span<const BvhNode> tree_;
    std::uint32_t leaf_size_;
    std::vector<WideBvhNode<N>>& out_;
    std::vector<std::uint32_t> begin_, end_;  // each binary node's slot range
};

}  // namespace

template <int N>
void WideBvh<N>::build(std::span<const Aabb> prim_boxes, std::uint32_t leaf_size, int threads) {
    nodes_.clear();
    prims_.clear();
    bounds_ = Aabb{};
    if (prim_boxes.empty()) return;
    leaf_size = std::max(1u, leaf_size);
    Bvh binary;
    binary.build(prim_boxes, leaf_size, threads);
    prims_.assign(binary.order().begin(), binary.order().end());
    bounds_ = binary.bounds();
    nodes_.reserve(binary.node_count() / (N - 1) + 1);
    Collapser<N>(binary.nodes(), leaf_size, nodes_).collapse(0);
}

template class WideBvh<4>;
#if defined(__AVX__)
template class WideBvh<8>;
#endif

}  // namespace rt
