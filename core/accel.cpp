#include "core/accel.h"

namespace rt {

void Accel::build(std::span<const Aabb> boxes, AccelKind kind, std::uint32_t leaf_size, int threads,
                  std::uint32_t split_above) {
    kind_ = kind;
    order_.clear();
    switch (kind) {
        case AccelKind::kBvh: {
            DefaultWideBvh wide;
            wide.build(boxes, leaf_size, threads, split_above);
            impl_ = std::move(wide);
            return;
        }
        case AccelKind::kBvh2: {
            Bvh bvh;
            bvh.build(boxes, leaf_size, threads, split_above);
            impl_ = std::move(bvh);
            return;
        }
        case AccelKind::kGrid: {
            UniformGrid grid;
            grid.build(boxes);
            impl_ = std::move(grid);
            break;
        }
        case AccelKind::kBrute: {
            BruteForce brute;
            brute.build(boxes);
            impl_ = brute;
            break;
        }
    }
    order_.resize(boxes.size());
    std::iota(order_.begin(), order_.end(), 0u);
}

std::size_t Accel::memory_bytes() const {
    const std::size_t own = order_.size() * sizeof(std::uint32_t);
    return own + std::visit([](const auto& impl) { return impl.memory_bytes(); }, impl_);
}

}  // namespace rt
