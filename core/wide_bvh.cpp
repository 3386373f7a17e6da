#include "core/wide_bvh.h"

#include <algorithm>
#include <limits>

namespace rt {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

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
        node.bounds[a] = splat<Float>(kInf);
        node.bounds[a + 3] = splat<Float>(-kInf);
    }
    return node;
}

}  // namespace

template <int N>
void WideBvh<N>::build(std::span<const Aabb> prim_boxes, std::uint32_t leaf_size) {
    nodes_.clear();
    prims_.clear();
    bounds_ = Aabb{};
    if (prim_boxes.empty()) return;
    Bvh binary;
    leaf_size_ = std::max(1u, leaf_size);
    binary.build(prim_boxes, leaf_size_);
    const std::span<const BvhNode> tree = binary.nodes();
    prims_.assign(binary.order().begin(), binary.order().end());
    bounds_ = binary.bounds();

    // Each binary node's slot range: children come after their parent, so one pass
    // from the back sees both children first.
    subtree_begin_.resize(tree.size());
    subtree_end_.resize(tree.size());
    for (std::size_t i = tree.size(); i-- > 0;) {
        const BvhNode& n = tree[i];
        subtree_begin_[i] = n.is_leaf() ? n.first : subtree_begin_[i + 1];
        subtree_end_[i] = n.is_leaf() ? n.first + n.count : subtree_end_[n.first];
    }
    nodes_.reserve(tree.size() / (N - 1) + 1);
    collapse(tree, 0);
    subtree_begin_ = {};
    subtree_end_ = {};
}

// Makes the wide node for binary node `index` and returns its position: the node's two
// children are opened up, the largest (by surface area) interior one first, until there
// are N; a child of at most leaf_size primitives becomes a leaf lane.
template <int N>
std::uint32_t WideBvh<N>::collapse(std::span<const BvhNode> tree, std::uint32_t index) {
    const auto size = [&](std::uint32_t i) { return subtree_end_[i] - subtree_begin_[i]; };
    const auto box = [&](std::uint32_t i) { return Aabb{tree[i].lo, tree[i].hi}; };
    const auto opens = [&](std::uint32_t i) { return !tree[i].is_leaf() && size(i) > leaf_size_; };

    std::array<std::uint32_t, N> children{};
    int n = 1;
    children[0] = index;
    while (n < N) {
        int widest = -1;
        for (int k = 0; k < n; ++k)
            if (opens(children[k]) &&
                (widest < 0 || box(children[k]).half_area() > box(children[widest]).half_area()))
                widest = k;
        if (widest < 0) break;
        const std::uint32_t parent = children[widest];
        children[widest] = parent + 1;  // the left child follows its parent
        children[n++] = tree[parent].first;
    }

    const auto at = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back(empty_node<N>());
    for (int k = 0; k < n; ++k) {
        const std::uint32_t c = children[k];
        const bool leaf = !opens(c);
        const std::uint32_t target = leaf ? subtree_begin_[c] : collapse(tree, c);
        Node& node = nodes_[at];  // collapse() may have moved the array
        set_lane(node, k, box(c));
        node.child[k] = target;
        node.count[k] = leaf ? size(c) : 0;
    }
    return at;
}

template class WideBvh<4>;
#if defined(__AVX__)
template class WideBvh<8>;
#endif

}  // namespace rt
