// A build's large arrays (core/large_array.h): mapped on huge-page boundaries, and kept
// when freed, within a bound, for the next build to write without taking its page faults
// again.
#include <gtest/gtest.h>

#include <cstdint>

#include "core/large_array.h"

namespace rt {
namespace {

constexpr std::size_t kMiB = std::size_t{1} << 20;

#if defined(__SANITIZE_ADDRESS__)
#define SKIP_UNDER_ASAN() GTEST_SKIP() << "under AddressSanitizer every array is on the heap"
#else
#define SKIP_UNDER_ASAN() (void)0
#endif

TEST(LargeArray, ALargeArrayStartsOnAHugePageAndHoldsWhatIsWritten) {
    SKIP_UNDER_ASAN();
    LargeArray<std::uint32_t> a(3 * kMiB + 5);  // not a whole number of huge pages
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(a.data()) % (2 * kMiB), 0u);
    for (std::size_t i = 0; i < a.size(); ++i) a[i] = static_cast<std::uint32_t>(i * 2654435761u);
    for (std::size_t i = 0; i < a.size(); i += 4093)
        ASSERT_EQ(a[i], static_cast<std::uint32_t>(i * 2654435761u));
    EXPECT_EQ(a.back(), static_cast<std::uint32_t>((a.size() - 1) * 2654435761u));
}

TEST(LargeArray, AFreedArrayIsKeptForTheNextOfItsSizeAndNotForAMuchSmallerOne) {
    SKIP_UNDER_ASAN();
    // Sizes no other test frees, each array marked in its first byte (new memory is
    // zeroed): a much smaller array must not take the kept one, a near one must.
    const void* first = nullptr;
    {
        LargeArray<std::uint8_t> a(200 * kMiB);
        a[0] = 0x5a;
        first = a.data();
    }
    {
        LargeArray<std::uint8_t> small(40 * kMiB);  // a fifth of the kept block: not it
        EXPECT_NE(small[0], 0x5a);
    }
    LargeArray<std::uint8_t> b(200 * kMiB - 100);  // the same huge pages
    EXPECT_EQ(b[0], 0x5a);
    EXPECT_EQ(static_cast<const void*>(b.data()), first);
}

TEST(LargeArray, WhatIsKeptIsBounded) {
    SKIP_UNDER_ASAN();
    // Three arrays of 128 MiB, each with a mark in its first byte (one page written),
    // freed together: at most two fit in what is kept, so of three new arrays of that size
    // at least one is new memory, which the system hands out zeroed. (Not told apart by
    // address: a new mapping may take the range of one given back.)
    {
        LargeArray<std::uint8_t> a(128 * kMiB), b(128 * kMiB), c(128 * kMiB);
        a[0] = b[0] = c[0] = 0xa5;
    }
    LargeArray<std::uint8_t> x(128 * kMiB), y(128 * kMiB), z(128 * kMiB);
    const int kept = (x[0] == 0xa5) + (y[0] == 0xa5) + (z[0] == 0xa5);
    EXPECT_LE(kept, 2);
    EXPECT_GE(kept, 1);  // and what is kept is used
}

}  // namespace
}  // namespace rt
