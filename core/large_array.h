#pragma once
// A std::vector whose resize() leaves new elements default-initialised: for a trivial
// element type, not written at all. A build's large arrays are written in full by its
// own passes, in parallel; zeroing them first would be a serial pass over the memory
// that also takes every page fault on one thread (20 ms of a million-triangle BVH
// build on two threads, measured).
// (Tried: transparent huge pages for these arrays, by madvise. The build got slower,
// the faults stalling on compaction, and rays no faster.)

#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace rt {

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
    template <class U>
    void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
        ::new (static_cast<void*>(p)) U;
    }
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
};

template <class T>
using LargeArray = std::vector<T, LargeArrayAllocator<T>>;

}  // namespace rt
