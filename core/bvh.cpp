#include "core/bvh.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <thread>

#include "core/large_array.h"
#include "core/parallel.h"
#include "core/simd.h"

namespace rt {
namespace {

constexpr int kBins = 16;

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
// The spare lane of lo carries the primitive's index, of hi the bin the last binning
// put it in (so that the partition after it need not work that out again).
struct PrimRef {
    Float4 lo, hi;

    std::uint32_t index() const { return std::bit_cast<std::uint32_t>(lo[3]); }
    int bin() const { return std::bit_cast<int>(hi[3]); }
    void set_bin(int b) { hi[3] = std::bit_cast<float>(b); }
    // Twice the centre (the halving is left out), its fourth lane 0: those of lo and hi
    // hold integers, tiny floats to the FPU, and arithmetic on them would stall it.
    Float4 centre2() const {
        constexpr Mask4 kXyz{-1, -1, -1, 0};
        return std::bit_cast<Float4>(std::bit_cast<Mask4>(lo) & kXyz) +
               std::bit_cast<Float4>(std::bit_cast<Mask4>(hi) & kXyz);
    }
};

// The primitives of a subtree: their boxes' union and their centres' (doubled) bounds.
struct Bounds {
    Box4 box, centres;
};

struct Split {
    int axis = -1;
    int bin = 0;                    // bins [0, bin] along the axis go left
    std::uint32_t sorted_left = 0;  // if not 0: the range is sorted, its first this many go left
    float cost = kInfinity;
    Bounds left, right;  // a binned split's centres: found by the partition
};

// Which bin a doubled centre falls in along each axis (all in bin 0 along an axis the
// centres do not spread along), the three packed in a primitive's spare lane so that the
// partition need not work them out again. Binned along all three axes, or `only` one.
struct Binner {
    Float4 lo{}, scale{};
    int only = -1;  // -1: all three

    Binner(const Box4& centres, int only_axis) : lo(centres.lo), only(only_axis) {
        const Float4 extent = centres.hi - centres.lo;
        for (int a = 0; a < 3; ++a) {
            const float s = static_cast<float>(kBins) / extent[a];
            scale[a] = extent[a] > 0.0f && std::isfinite(s) ? s : 0.0f;
        }
    }
    Mask4 bins(const Float4& centre2) const {
        const Mask4 b = __builtin_convertvector((centre2 - lo) * scale, Mask4);
        return b < 0 ? 0 : (b > kBins - 1 ? kBins - 1 : b);
    }
    static int packed(const Mask4& b) { return b[0] | b[1] << 4 | b[2] << 8; }
    static int along(int packed_bins, int axis) { return (packed_bins >> (4 * axis)) & 15; }
};

// One pass's bins along the three axes: the boxes of what fell in each, and how many.
// (Their centres' bounds are left to the partition: one pair of boxes, not three.)
struct Bins {
    std::array<std::array<Box4, kBins>, 3> box{};
    std::array<std::array<std::uint32_t, kBins>, 3> count{};

    void add(PrimRef& p, const Binner& binner) {
        // The box read before the bins are written into it: a read of all of `hi` just
        // after a store into its last lane waits until that store has reached the cache.
        const Float4 lo = p.lo, hi = p.hi;
        const Mask4 b = binner.bins(p.centre2());
        if (binner.only < 0) {
            for (int a = 0; a < 3; ++a) {
                box[a][b[a]].grow(lo, hi);
                ++count[a][b[a]];
            }
        } else {
            const int a = binner.only;
            box[a][b[a]].grow(lo, hi);
            ++count[a][b[a]];
        }
        p.set_bin(Binner::packed(b));
    }
    void add(const Bins& other) {
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < kBins; ++b) {
                box[a][b].grow(other.box[a][b]);
                count[a][b] += other.count[a][b];
            }
    }
};

// Where `left` is set, a box grown by c; the other, by nothing (one comparison each).
[[gnu::always_inline]] inline void grow_one_of(Box4& on_left, Box4& on_right, bool left,
                                               const Float4& c) {
    const Mask4 l = Mask4{} + static_cast<int>(left);
    const Float4 inf = splat<Float4>(kInfinity), ninf = splat<Float4>(-kInfinity);
    on_left.grow(l != 0 ? c : inf, l != 0 ? c : ninf);
    on_right.grow(l != 0 ? inf : c, l != 0 ? ninf : c);
}

// Builds the subtree of [begin, end) into its own node array. The refs live in two
// arrays of the same size: a partition moves a node's refs from the one they are in to
// the other (no copy back), and a leaf's end up in `refs`. Both arrays are shared, and
// subtrees work on disjoint ranges of them, so they can run in parallel. A
// build with a pool of threads bins and partitions its large nodes in parts, one a
// thread, and hands right subtrees to the pool while it builds the left. The tree is the
// same on any number of threads (see Bvh::build).
struct Builder {
    static constexpr std::uint32_t kMinPart = 8192;     // primitives a thread bins or moves
    static constexpr std::uint32_t kMinSubtree = 1024;  // a subtree worth a thread of its own
    static constexpr std::uint32_t kSorted = 16;        // nodes this small are split exactly
    static constexpr std::uint32_t kAllAxes = 4096;     // nodes this small binned along x, y, z

    PrimRef* refs;     // where each leaf's refs end up
    PrimRef* scratch;  // as large as refs: the other side of every other partition
    std::uint32_t max_leaf;
    std::uint32_t split_above;  // up to max_leaf: a leaf only where a split does not pay
    LargeArray<BvhNode> nodes;
    TaskPool* pool = nullptr;  // none: all on this thread

    int parts(std::uint32_t begin, std::uint32_t end) const {
        return pool ? part_count(end - begin, pool->threads(), kMinPart) : 1;
    }

    // Binned SAH (Wald, "On fast construction of SAH-based BVHs", 2007): one pass bins the
    // centres, a sweep per axis finds the cheapest split and, from the bins, both sides'
    // boxes, and the partition their centres' bounds, so no child needs a pass of its own.
    // Along all three axes in nodes of up to kAllAxes primitives, along the widest above:
    // near the leaves is where the widest axis is often not the best cut (a height
    // field's strips, a mesh's thin parts), and the few large nodes at the top, where
    // every primitive is binned, are where the other two axes would cost most
    // (docs/BENCHMARKS.md, sixth session).
    Split find_split(std::uint32_t begin, std::uint32_t end, const Bounds& bounds, PrimRef* r) {
        const Float4 extent = bounds.centres.hi - bounds.centres.lo;
        const int widest = extent[0] >= extent[1] ? (extent[0] >= extent[2] ? 0 : 2)
                                                  : (extent[1] >= extent[2] ? 1 : 2);
        if (!(extent[widest] > 0.0f)) return {};
        if (end - begin <= kSorted) return sorted_split(begin, end, widest, r);
        const Binner binner(bounds.centres, end - begin <= kAllAxes ? -1 : widest);
        Bins bins;
        const int n_parts = parts(begin, end);
        if (n_parts == 1) {
            for (std::uint32_t i = begin; i < end; ++i) bins.add(r[i], binner);
        } else {
            std::vector<Bins> part_bins(static_cast<std::size_t>(n_parts));
            parallel_parts(pool, begin, end, n_parts, [&](int part, std::size_t b, std::size_t e) {
                for (std::size_t i = b; i < e; ++i) part_bins[part].add(r[i], binner);
            });
            for (const Bins& p : part_bins) bins.add(p);
        }
        Split best;
        for (int axis = 0; axis < 3; ++axis)
            if (binner.scale[axis] != 0.0f && (binner.only < 0 || binner.only == axis))
                cheapest_cut(bins, axis, end - begin, best);
        if (best.axis >= 0)
            for (int b = 0; b < kBins; ++b)
                (b <= best.bin ? best.left : best.right).box.grow(bins.box[best.axis][b]);
        return best;
    }

    // Along `axis` by centre, ties by index: an order that depends on the set alone. As an
    // integer: the centre's bits made to order as unsigned ints do (+0 for -0), the index
    // below them.
    static std::uint64_t sort_key(const PrimRef& p, int axis) {
        const auto bits = std::bit_cast<std::uint32_t>(p.centre2()[axis] + 0.0f);
        const std::uint32_t ordered = (bits & 0x80000000u) != 0 ? ~bits : bits | 0x80000000u;
        return std::uint64_t{ordered} << 32 | p.index();
    }

    // A small node: every split between its centres sorted along the axis, not 16 bins'
    // worth (most nodes are small, and their bins cost more than their primitives). Each
    // primitive goes to its rank, counted without a branch (a comparison sort's branches
    // are mispredicted half the time).
    static Split sorted_split(std::uint32_t begin, std::uint32_t end, int axis, PrimRef* r) {
        const std::uint32_t n = end - begin;
        std::array<std::uint64_t, kSorted> key;
        for (std::uint32_t i = 0; i < n; ++i) key[i] = sort_key(r[begin + i], axis);
        std::array<PrimRef, kSorted> sorted;
        for (std::uint32_t i = 0; i < n; ++i) {
            std::uint32_t rank = 0;
            for (std::uint32_t j = 0; j < n; ++j) rank += key[j] < key[i];
            sorted[rank] = r[begin + i];
        }
        std::copy(sorted.begin(), sorted.begin() + n, r + begin);
        std::array<Bounds, kSorted> right{};  // right[k]: of [k, n)
        Bounds acc;
        for (std::uint32_t k = n; k-- > 1;) {
            const PrimRef& p = r[begin + k];
            acc.box.grow(p.lo, p.hi);
            acc.centres.grow(p.centre2(), p.centre2());
            right[k] = acc;
        }
        Split best;
        acc = Bounds{};
        for (std::uint32_t k = 1; k < n; ++k) {
            const PrimRef& p = r[begin + k - 1];
            acc.box.grow(p.lo, p.hi);
            acc.centres.grow(p.centre2(), p.centre2());
            const float cost = acc.box.half_area() * static_cast<float>(k) +
                               right[k].box.half_area() * static_cast<float>(n - k);
            if (cost < best.cost) best = {axis, 0, k, cost, acc, right[k]};
        }
        return best;
    }

    // Sweep from the right for every right side's cost, then from the left; `best` kept
    // unless a cut along `axis` costs less. (Only the cost: the chosen cut's boxes are
    // grown afterwards, once.)
    static void cheapest_cut(const Bins& bins, int axis, std::uint32_t total, Split& best) {
        const auto& box = bins.box[axis];
        const auto& count = bins.count[axis];
        // Half the area, without Box4::half_area's test for an empty box: an empty side
        // (here only where its count is 0) costs NaN or infinity, never the least.
        const auto area = [](const Box4& b) {
            const Float4 e = b.hi - b.lo;
            return e[0] * e[1] + e[1] * e[2] + e[2] * e[0];
        };
        std::array<float, kBins> right_cost;
        Box4 acc;
        std::uint32_t n = 0;
        for (int b = kBins - 1; b > 0; --b) {
            acc.grow(box[b]);
            n += count[b];
            right_cost[b] = area(acc) * static_cast<float>(n);
        }
        acc = Box4{};
        n = 0;
        float least = best.cost;
        int at = -1;
        for (int b = 0; b < kBins - 1; ++b) {
            acc.grow(box[b]);
            n += count[b];
            const float cost = area(acc) * static_cast<float>(n) + right_cost[b + 1];
            const bool cheaper = n > 0 && n < total && cost < least;
            least = cheaper ? cost : least;
            at = cheaper ? b : at;
        }
        if (at >= 0) {
            best.axis = axis;
            best.bin = at;
            best.cost = least;
        }
    }

    // Moves the refs of bins [0, split.bin] to the front of [begin, end) of the other
    // array, the rest behind them, points `r` there and fills in both sides' centre
    // bounds; returns where the right side starts. A sorted small node is split where it
    // lies.
    std::uint32_t partition(std::uint32_t begin, std::uint32_t end, Split& split, PrimRef*& r) {
        if (split.sorted_left != 0) return begin + split.sorted_left;
        PrimRef* const to = r == refs ? scratch : refs;
        const std::uint32_t mid = partition(
            begin, end, r, to,
            [axis = split.axis, bin = split.bin](const PrimRef& p) {
                return Binner::along(p.bin(), axis) <= bin;
            },
            split.left.centres, split.right.centres);
        r = to;
        return mid;
    }
    template <class GoesLeft>
    std::uint32_t partition(std::uint32_t begin, std::uint32_t end, const PrimRef* from,
                            PrimRef* to, const GoesLeft& goes_left, Box4& left_centres,
                            Box4& right_centres) {
        const int n_parts = parts(begin, end);
        if (n_parts == 1) {  // lefts from the front, rights from the back: no branches to miss
            std::uint32_t left = begin, right = end;
            Box4 on_left, on_right;  // not the callers': those might alias `to`, so live in memory
            for (std::uint32_t i = begin; i < end; ++i) {
                const PrimRef p = from[i];
                const bool l = goes_left(p);
                to[l ? left : right - 1] = p;
                grow_one_of(on_left, on_right, l, p.centre2());
                left += l;
                right -= !l;
            }
            left_centres = on_left;
            right_centres = on_right;
            return left;
        }
        // Each part counts its left side; then each writes both sides at its own offsets.
        const auto n = static_cast<std::size_t>(n_parts);
        std::vector<std::uint32_t> lefts(n), sizes(n);
        parallel_parts(pool, begin, end, n_parts, [&](int part, std::size_t b, std::size_t e) {
            sizes[part] = static_cast<std::uint32_t>(e - b);
            lefts[part] = static_cast<std::uint32_t>(std::count_if(from + b, from + e, goes_left));
        });
        std::uint32_t mid = begin;
        for (std::uint32_t l : lefts) mid += l;
        std::vector<std::uint32_t> left_at(n), right_at(n);
        for (std::size_t p = 0, l = begin, r = mid; p < n; ++p) {
            left_at[p] = static_cast<std::uint32_t>(l);
            right_at[p] = static_cast<std::uint32_t>(r);
            l += lefts[p];
            r += sizes[p] - lefts[p];
        }
        std::vector<std::array<Box4, 2>> centres(n);  // each part's left and right
        parallel_parts(pool, begin, end, n_parts, [&](int part, std::size_t b, std::size_t e) {
            std::uint32_t left = left_at[part], right = right_at[part];
            Box4 on_left, on_right;
            for (std::size_t i = b; i < e; ++i) {
                const PrimRef p = from[i];
                const bool l = goes_left(p);
                to[l ? left++ : right++] = p;
                grow_one_of(on_left, on_right, l, p.centre2());
            }
            centres[part] = {on_left, on_right};
        });
        for (const auto& c : centres) {
            left_centres.grow(c[0]);
            right_centres.grow(c[1]);
        }
        return mid;
    }

    void build(std::uint32_t node, std::uint32_t begin, std::uint32_t end, const Bounds& bounds,
               int depth, PrimRef* r) {
        const Aabb box = bounds.box.aabb();
        nodes[node].lo = box.lo;
        nodes[node].hi = box.hi;
        const std::uint32_t count = end - begin;
        const auto leaf = [&] {
            nodes[node].first = begin;
            nodes[node].count = count;
            // In a leaf, the order is by index (see Bvh::build): sorted here, in the
            // subtree's thread, while the leaf's refs are in the cache.
            if (r != refs) std::copy(r + begin, r + end, refs + begin);
            std::sort(refs + begin, refs + end,
                      [](const PrimRef& a, const PrimRef& b) { return a.index() < b.index(); });
        };
        if (count <= split_above || depth >= Bvh::kMaxDepth) return leaf();
        Split split = find_split(begin, end, bounds, r);
        if (split.axis < 0) return leaf();  // all centres in one point: nothing separates them
        // The caller tests up to max_leaf at once (a mesh's eight triangles are one test,
        // core/mesh.cpp), so such a subtree is split only where its halves' boxes are much
        // smaller together: a room's walls, not a patch of a scanned surface.
        if (count <= max_leaf && split.left.box.half_area() + split.right.box.half_area() >=
                                     Bvh::kKeepLeaf * bounds.box.half_area())
            return leaf();
        const std::uint32_t mid = partition(begin, end, split, r);

        // The right subtree to the pool (into nodes of its own) while this thread builds the
        // left; a small one here after it.
        TaskPool::Group group;
        LargeArray<BvhNode> right_nodes;
        const bool fork = pool && end - mid >= kMinSubtree && mid - begin >= kMinSubtree;
        if (fork)
            pool->run(group, [&, r, right = split.right] {
                Builder sub{refs, scratch, max_leaf, split_above, {}, pool};
                sub.nodes.reserve(2 * (end - mid) / max_leaf);
                sub.nodes.emplace_back();
                sub.build(0, mid, end, right, depth + 1, r);
                right_nodes = std::move(sub.nodes);
            });
        const auto left = static_cast<std::uint32_t>(nodes.size());
        nodes.emplace_back();
        build(left, begin, mid, split.left, depth + 1, r);
        const auto right = static_cast<std::uint32_t>(nodes.size());
        if (fork) {
            pool->wait(group);
            for (BvhNode& n : right_nodes)
                if (!n.is_leaf()) n.first += right;  // child links were relative to the subtree
            nodes.insert(nodes.end(), right_nodes.begin(), right_nodes.end());
        } else {
            nodes.emplace_back();
            build(right, mid, end, split.right, depth + 1, r);
        }
        nodes[node].first = right;
        nodes[node].count = 0;
    }
};

}  // namespace

void Bvh::build(std::span<const Aabb> prim_boxes, std::uint32_t max_leaf, int threads,
                std::uint32_t split_above) {
    nodes_.clear();
    prims_.clear();
    if (prim_boxes.empty()) return;
    threads = build_threads(threads);
    const auto count = static_cast<std::uint32_t>(prim_boxes.size());
    LargeArray<PrimRef> refs(count), scratch(count);  // written by the passes below
    // A pool only where there is more than one thread and enough to share.
    TaskPool* workers =
        threads > 1 && count >= 2 * Builder::kMinSubtree ? &TaskPool::shared(threads) : nullptr;
    const int n_parts = workers ? part_count(count, threads, Builder::kMinPart) : 1;
    std::vector<Bounds> part_bounds(static_cast<std::size_t>(n_parts));
    parallel_parts(workers, 0, count, n_parts, [&](int part, std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            const Aabb& b = prim_boxes[i];
            const auto index = static_cast<std::uint32_t>(i);
            refs[i] = {Float4{b.lo.x, b.lo.y, b.lo.z, std::bit_cast<float>(index)},
                       Float4{b.hi.x, b.hi.y, b.hi.z, 0.0f}};
            part_bounds[part].box.grow(refs[i].lo, refs[i].hi);
            const Float4 c = refs[i].centre2();
            part_bounds[part].centres.grow(c, c);
        }
    });
    Bounds bounds;
    for (const Bounds& b : part_bounds) {
        bounds.box.grow(b.box);
        bounds.centres.grow(b.centres);
    }
    max_leaf = std::max(1u, max_leaf);
    split_above = split_above == 0 ? max_leaf : std::min(split_above, max_leaf);
    Builder builder{refs.data(), scratch.data(), max_leaf, split_above, {}, workers};
    builder.nodes.reserve(2 * prim_boxes.size() / builder.max_leaf + 1);
    builder.nodes.emplace_back();
    builder.build(0, 0, count, bounds, 0, refs.data());
    nodes_ = std::move(builder.nodes);
    prims_.resize(refs.size());
    parallel_parts(workers, 0, count, n_parts, [&](int, std::size_t begin, std::size_t end) {
        for (std::size_t s = begin; s < end; ++s) prims_[s] = refs[s].index();
    });
    // Which primitives share a node depends on the set alone (bins and the small nodes'
    // sort do not see the order); in a leaf, the order is by index (sorted as each leaf
    // was made). So the tree, slots included, is the same however the partitions ordered
    // things, on any thread count.
}

}  // namespace rt
