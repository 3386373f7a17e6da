#include "core/large_array.h"

#include <sys/mman.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <vector>

namespace rt::detail {

namespace {

std::size_t mapped_bytes(std::size_t bytes) {
    return (bytes + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes;
}

bool huge_pages_wanted() {
    static const bool wanted = [] {
        const char* v = std::getenv("RTVIEW_HUGE_PAGES");
        return v == nullptr || std::strcmp(v, "0") != 0;
    }();
    return wanted;
}

void* map_aligned(std::size_t size) {
    // A huge page's worth more than asked for, so that an aligned start can be cut out:
    // the kernel backs only whole, aligned 2 MiB ranges with huge pages.
    const std::size_t span = size + kHugePageBytes;
    void* const got =
        mmap(nullptr, span, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (got == MAP_FAILED) throw std::bad_alloc();
    auto* const base = static_cast<char*>(got);
    const auto at = reinterpret_cast<std::uintptr_t>(base);
    char* const start = base + (kHugePageBytes - at % kHugePageBytes) % kHugePageBytes;
    if (start > base) munmap(base, static_cast<std::size_t>(start - base));
    char* const end = start + size;
    if (end < base + span) munmap(end, static_cast<std::size_t>(base + span - end));
#if defined(MADV_HUGEPAGE)
    if (huge_pages_wanted()) madvise(start, size, MADV_HUGEPAGE);  // a hint: no harm if refused
#endif
    return start;
}

// Freed arrays kept mapped for the next build, up to kKeptBytes in all, as a heap keeps
// freed memory: a rebuild (a scene reloaded, rtbench's timed builds) then writes memory
// whose pages are already there instead of taking their faults again.
class KeptBlocks {
  public:
    static constexpr std::size_t kKeptBytes = std::size_t{256} << 20;

    void* take(std::size_t size) {
        const std::lock_guard lock(mutex_);
        std::size_t best = blocks_.size();
        for (std::size_t i = 0; i < blocks_.size(); ++i)
            if (blocks_[i].size >= size && blocks_[i].size <= 2 * size &&
                (best == blocks_.size() || blocks_[i].size < blocks_[best].size))
                best = i;
        if (best == blocks_.size()) return nullptr;
        const Block b = blocks_[best];
        blocks_.erase(blocks_.begin() + static_cast<std::ptrdiff_t>(best));
        kept_ -= b.size;
        if (b.size > size) munmap(static_cast<char*>(b.at) + size, b.size - size);
        return b.at;
    }
    void give(void* at, std::size_t size) noexcept {
        {
            const std::lock_guard lock(mutex_);
            // The oldest go first: what the last build freed is what the next one asks for.
            while (!blocks_.empty() && kept_ + size > kKeptBytes) {
                munmap(blocks_.front().at, blocks_.front().size);
                kept_ -= blocks_.front().size;
                blocks_.erase(blocks_.begin());
            }
            if (kept_ + size <= kKeptBytes) {
                try {
                    blocks_.push_back({at, size});
                    kept_ += size;
                    return;
                } catch (const std::bad_alloc&) {
                }
            }
        }
        munmap(at, size);
    }

  private:
    struct Block {
        void* at;
        std::size_t size;
    };
    std::mutex mutex_;
    std::vector<Block> blocks_;
    std::size_t kept_ = 0;
};

KeptBlocks& kept_blocks() {
    static KeptBlocks* const blocks = new KeptBlocks;  // never destroyed: frees may come late
    return *blocks;
}

}  // namespace

void* reserve_large(std::size_t bytes) {
    const std::size_t size = mapped_bytes(bytes);
    if (void* at = kept_blocks().take(size)) return at;
    return map_aligned(size);
}

void release_large(void* p, std::size_t bytes) noexcept {
    if (p != nullptr) kept_blocks().give(p, mapped_bytes(bytes));
}

}  // namespace rt::detail
