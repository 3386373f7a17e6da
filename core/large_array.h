#pragma once
// A std::vector for a build's large arrays: resize() leaves new elements
// default-initialised (for a trivial element type, not written at all), and an array of
// 2 MiB or more takes its memory from the system directly, in transparent huge pages,
// and gives it back to a store of freed arrays that the next build takes from.
//
// Not written: a build's large arrays are written in full by its own passes, in
// parallel; zeroing them first would be a serial pass over the memory that also takes
// every page fault on one thread (20 ms of a million-triangle BVH build on two threads,
// measured).
//
// Page faults: on some machines a fault costs as much as the build's arithmetic (docs/
// BENCHMARKS.md, seventeenth session: 6-16 microseconds for each 4 KiB page on a virtual
// machine; a million-triangle build took its faults again on every rebuild, as the heap
// maps arrays of 32 MiB and more afresh each time, and took 1.2-1.7 times Embree's time).
// A huge page takes one fault for 512 small ones, and an array kept from the last build
// takes none. Where the kernel has no huge page to give it uses small ones.
// RTVIEW_HUGE_PAGES=0 in the environment asks for small pages only (to compare the two,
// or where compacting memory for huge pages stalls: an earlier machine measured a
// million-triangle build 98 -> 126 ms with them, BENCHMARKS.md, 2026-11-24).

#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace rt {

namespace detail {

inline constexpr std::size_t kHugePageBytes = std::size_t{2} << 20;
inline constexpr std::size_t kLargeArrayBytes = kHugePageBytes;  // and above: mapped

// At least `bytes` (>= kLargeArrayBytes), aligned to a huge page; std::bad_alloc if the
// system has none. Freed by release_large with the same `bytes`.
void* reserve_large(std::size_t bytes);
void release_large(void* p, std::size_t bytes) noexcept;

}  // namespace detail

template <class T>
struct LargeArrayAllocator : std::allocator<T> {
    using value_type = T;
    LargeArrayAllocator() = default;
    template <class U>
    LargeArrayAllocator(const LargeArrayAllocator<U>&) noexcept {}
    template <class U>
    struct rebind {
        using other = LargeArrayAllocator<U>;
    };
    T* allocate(std::size_t n) {
        if (large(n)) return static_cast<T*>(detail::reserve_large(n * sizeof(T)));
        return std::allocator<T>::allocate(n);
    }
    void deallocate(T* p, std::size_t n) noexcept {
        if (large(n))
            detail::release_large(p, n * sizeof(T));
        else
            std::allocator<T>::deallocate(p, n);
    }
    template <class U>
    void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
        ::new (static_cast<void*>(p)) U;
    }
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }

  private:
    static bool large([[maybe_unused]] std::size_t n) {
#if defined(__SANITIZE_ADDRESS__)
        return false;  // the sanitizer checks what the heap hands out, not mapped pages
#else
        return n >= detail::kLargeArrayBytes / sizeof(T);
#endif
    }
};

template <class T, class U>
bool operator==(const LargeArrayAllocator<T>&, const LargeArrayAllocator<U>&) noexcept {
    return true;
}

template <class T>
using LargeArray = std::vector<T, LargeArrayAllocator<T>>;

}  // namespace rt
