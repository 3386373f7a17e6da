#pragma once
// Four float lanes as GCC/Clang vector extensions: SSE on x86-64, NEON on ARM, without
// intrinsics. Used by the four-wide BVH's box test and the four-triangle test.

#include <cstdint>

#if defined(__SSE__)
#include <xmmintrin.h>
#endif

namespace rt {

using Float4 = float __attribute__((vector_size(16)));
using Mask4 = std::int32_t __attribute__((vector_size(16)));  // a comparison: 0 or -1 per lane

inline Float4 splat(float x) { return Float4{x, x, x, x}; }
// Lane-wise min and max: where a lane of `a` is NaN, the lane of `b` is taken (SSE's
// minps/maxps rule, kept by the portable form).
// bits(): one bit per lane, lane 0 lowest. GCC does not find minps, maxps or movmskps
// in the portable forms, so on SSE they are spelled out.
#if defined(__SSE__)
inline Float4 min4(Float4 a, Float4 b) { return _mm_min_ps(a, b); }
inline Float4 max4(Float4 a, Float4 b) { return _mm_max_ps(a, b); }
inline unsigned bits(Mask4 m) {
    return static_cast<unsigned>(_mm_movemask_ps(reinterpret_cast<__m128>(m)));
}
#else
inline Float4 min4(Float4 a, Float4 b) { return a < b ? a : b; }
inline Float4 max4(Float4 a, Float4 b) { return a > b ? a : b; }
inline unsigned bits(Mask4 m) { return (m[0] & 1u) | (m[1] & 2u) | (m[2] & 4u) | (m[3] & 8u); }
#endif

}  // namespace rt
