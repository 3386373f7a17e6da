#pragma once
// SIMD lanes as GCC/Clang vector extensions, without intrinsics in the callers: SSE on
// x86-64 (AVX where the build targets it), NEON on ARM. Float4 serves the four-triangle
// test; the wide BVH uses kBvhWidth lanes: 16 where the build targets AVX-512, 8 under
// AVX, else 4. Packets of rays and the shading take kPacketWidth: 8 under AVX, else 4.

#include <cstdint>

#if defined(__SSE__)
#include <immintrin.h>
#endif

// For the leaf tests handed to a traversal: GCC otherwise leaves them as calls. (On the
// bunny the difference was within rtbench's run-to-run noise: docs/BENCHMARKS.md.)
#define RT_FORCE_INLINE __attribute__((always_inline))

namespace rt {

using Float4 = float __attribute__((vector_size(16)));
using Mask4 = std::int32_t __attribute__((vector_size(16)));  // a comparison: 0 or -1 per lane
#if defined(__AVX__)
using Float8 = float __attribute__((vector_size(32)));
using Mask8 = std::int32_t __attribute__((vector_size(32)));
#endif
#if defined(__AVX512F__)
using Float16 = float __attribute__((vector_size(64)));
using Mask16 = std::int32_t __attribute__((vector_size(64)));
#endif

template <int N>
struct Lanes;
template <>
struct Lanes<4> {
    using Float = Float4;
    using Mask = Mask4;
};
#if defined(__AVX__)
template <>
struct Lanes<8> {
    using Float = Float8;
    using Mask = Mask8;
};
#endif

#if defined(__AVX512F__)
template <>
struct Lanes<16> {
    using Float = Float16;
    using Mask = Mask16;
};
#endif

// Sixteen children a node under AVX-512: a shallower tree, a quarter fewer dependent
// node loads per ray, each node's test still one instruction per plane. On AMD Zen 5,
// shadow and secondary rays 3-9 % faster than with eight on every mesh measured; on Zen 4
// 2-7 % (docs/BENCHMARKS.md, "twenty-fourth session", "twenty-sixth session"). For such
// measurements a build may name the width (-DRTVIEW_BVH_WIDTH=8 in CMAKE_CXX_FLAGS; 4, 8
// under AVX, 16 under AVX-512).
#if defined(RTVIEW_BVH_WIDTH)
static_assert(RTVIEW_BVH_WIDTH == 4 || RTVIEW_BVH_WIDTH == 8 || RTVIEW_BVH_WIDTH == 16,
              "RTVIEW_BVH_WIDTH: 4, 8 or 16");
inline constexpr int kBvhWidth = RTVIEW_BVH_WIDTH;
#elif defined(__AVX512F__)
inline constexpr int kBvhWidth = 16;
#elif defined(__AVX__)
inline constexpr int kBvhWidth = 8;
#else
inline constexpr int kBvhWidth = 4;
#endif
// Rays traced together (core/wide_bvh_packet.h) and shaded together (core/renderer.cpp):
// eight under AVX (Embree's rtcIntersect8 is their yardstick), else four. A build may name
// the width for measurements (-DRTVIEW_PACKET_WIDTH=16 in CMAKE_CXX_FLAGS, under AVX-512;
// rtbench then compares with rtcIntersect16): on Zen 5, packets of sixteen took whitted's
// and many_spheres' frames 0.85-0.86x of the time, but the item buffer's primary speed-up
// on many_spheres fell from 2.55x to about 2.0x, so eight stay (docs/BENCHMARKS.md,
// "thirty-fourth session").
#if defined(RTVIEW_PACKET_WIDTH)
#if !(RTVIEW_PACKET_WIDTH == 4 || (RTVIEW_PACKET_WIDTH == 8 && defined(__AVX__)) || \
      (RTVIEW_PACKET_WIDTH == 16 && defined(__AVX512F__)))
#error "RTVIEW_PACKET_WIDTH: 4, 8 under AVX, 16 under AVX-512"
#endif
inline constexpr int kPacketWidth = RTVIEW_PACKET_WIDTH;
#elif defined(__AVX__)
inline constexpr int kPacketWidth = 8;
#else
inline constexpr int kPacketWidth = 4;
#endif

template <class V>
V splat(float x) {
    return V{} + x;
}

// Lane-wise min and max: where a lane of `a` is NaN, the lane of `b` is taken (SSE's
// minps/maxps rule, kept by the portable form). bits(): one bit per lane, lane 0
// lowest. GCC does not find minps, maxps or movmskps in the portable forms, so where
// the instructions exist they are spelled out.
#if defined(__SSE__)
inline Float4 vmin(Float4 a, Float4 b) { return _mm_min_ps(a, b); }
inline Float4 vmax(Float4 a, Float4 b) { return _mm_max_ps(a, b); }
inline unsigned bits(Mask4 m) {
    return static_cast<unsigned>(_mm_movemask_ps(reinterpret_cast<__m128>(m)));
}
#else
inline Float4 vmin(Float4 a, Float4 b) { return a < b ? a : b; }
inline Float4 vmax(Float4 a, Float4 b) { return a > b ? a : b; }
inline unsigned bits(Mask4 m) { return (m[0] & 1u) | (m[1] & 2u) | (m[2] & 4u) | (m[3] & 8u); }
#endif

inline Float4 vabs(Float4 a) { return vmax(a, -a); }
#if defined(__SSE__)
inline Float4 vsqrt(Float4 a) { return _mm_sqrt_ps(a); }  // correctly rounded, as std::sqrt
#else
inline Float4 vsqrt(Float4 a) {
    for (int i = 0; i < 4; ++i) a[i] = __builtin_sqrtf(a[i]);
    return a;
}
#endif
// Lane by lane std::floor (exact either way).
#if defined(__SSE4_1__)
inline Float4 vfloor(Float4 a) { return _mm_floor_ps(a); }
#else
inline Float4 vfloor(Float4 a) {
    for (int i = 0; i < 4; ++i) a[i] = __builtin_floorf(a[i]);
    return a;
}
#endif

#if defined(__AVX__)  // without AVX, eight lanes are not used (and would change the ABI)
inline Float8 vmin(Float8 a, Float8 b) { return _mm256_min_ps(a, b); }
inline Float8 vmax(Float8 a, Float8 b) { return _mm256_max_ps(a, b); }
inline Float8 vabs(Float8 a) { return vmax(a, -a); }
inline Float8 vsqrt(Float8 a) { return _mm256_sqrt_ps(a); }
inline Float8 vfloor(Float8 a) { return _mm256_floor_ps(a); }
inline unsigned bits(Mask8 m) {
    return static_cast<unsigned>(_mm256_movemask_ps(reinterpret_cast<__m256>(m)));
}
#endif

#if defined(__AVX512F__)
// The masked forms with every lane set: GCC 12's _mm512_min_ps warns of the undefined
// vector it passes through.
inline Float16 vmin(Float16 a, Float16 b) { return _mm512_mask_min_ps(a, 0xffff, a, b); }
inline Float16 vmax(Float16 a, Float16 b) { return _mm512_mask_max_ps(a, 0xffff, a, b); }
inline Float16 vabs(Float16 a) { return vmax(a, -a); }
inline Float16 vsqrt(Float16 a) { return _mm512_mask_sqrt_ps(a, 0xffff, a); }
inline Float16 vfloor(Float16 a) {
    return _mm512_mask_roundscale_ps(a, 0xffff, a, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
}
inline unsigned bits(Mask16 m) {
    return static_cast<unsigned>(_mm512_movepi32_mask(reinterpret_cast<__m512i>(m)));
}
#endif

// A comparison as a bit per lane, lane 0 lowest: bits(a < b) and so on, each lane the
// IEEE predicate of its operator (false where a lane is NaN; kNe true). Where AVX-512
// compares into a mask register, that mask is the answer: GCC would otherwise turn it
// into a vector of lanes and back (vcmpps, vmovdqa32 or vpmovm2d, then vpmovd2m or
// vmovmskps, then kmov), steps on the path from a node's load to the next node's address.
enum class Compare { kLt, kLe, kGt, kGe, kNe };

template <Compare C, class V>
[[gnu::always_inline]] inline unsigned lanes(V a, V b) {
#if defined(__AVX512F__)
    constexpr int kPredicate = C == Compare::kLt   ? _CMP_LT_OQ
                               : C == Compare::kLe ? _CMP_LE_OQ
                               : C == Compare::kGt ? _CMP_GT_OQ
                               : C == Compare::kGe ? _CMP_GE_OQ
                                                   : _CMP_NEQ_UQ;
    if constexpr (sizeof(V) == 64) return _mm512_cmp_ps_mask(a, b, kPredicate);
#if defined(__AVX512VL__)
    if constexpr (sizeof(V) == 32) return _mm256_cmp_ps_mask(a, b, kPredicate);
    if constexpr (sizeof(V) == 16) return _mm_cmp_ps_mask(a, b, kPredicate);
#endif
#endif
    if constexpr (sizeof(V) < 64) {
        if constexpr (C == Compare::kLt) return bits(a < b);
        if constexpr (C == Compare::kLe) return bits(a <= b);
        if constexpr (C == Compare::kGt) return bits(a > b);
        if constexpr (C == Compare::kGe) return bits(a >= b);
        if constexpr (C == Compare::kNe) return bits(a != b);
    }
}

// sizeof(V) / 4 floats from p, which need not be aligned.
template <class V>
[[gnu::always_inline]] inline V load(const float* p) {
    V v;
    __builtin_memcpy(&v, p, sizeof v);
    return v;
}

// Lane k: a's where bit k of `mask` is set, else b's. Where AVX-512 blends under a mask
// register, the bits are that mask; elsewhere they become a vector of lanes.
template <class V>
[[gnu::always_inline]] inline V select_bits(unsigned mask, V a, V b) {
#if defined(__AVX512F__)
    if constexpr (sizeof(V) == 64) return _mm512_mask_blend_ps(static_cast<__mmask16>(mask), b, a);
#if defined(__AVX512VL__)
    if constexpr (sizeof(V) == 32) return _mm256_mask_blend_ps(static_cast<__mmask8>(mask), b, a);
    if constexpr (sizeof(V) == 16) return _mm_mask_blend_ps(static_cast<__mmask8>(mask), b, a);
#endif
#endif
    if constexpr (sizeof(V) < 64) {
        using M = typename Lanes<sizeof(V) / sizeof(float)>::Mask;
        M bit;
        for (int k = 0; k < static_cast<int>(sizeof(V) / sizeof(float)); ++k) bit[k] = 1 << k;
        return ((M{} + static_cast<std::int32_t>(mask)) & bit) != 0 ? a : b;
    }
}

#if defined(__SSE__)
// A row of Floats floats (3 or 4) as a vector, the lanes beyond it zero. Three are read
// without touching the fourth (the last vertex of an array has none after it): a load
// under a mask, where masked lanes cannot fault, else a pair and a single.
template <int Floats>
[[gnu::always_inline]] inline __m128 load_row(const float* p) {
    static_assert(Floats == 3 || Floats == 4);
    if constexpr (Floats == 4) {
        return _mm_loadu_ps(p);
    } else {
#if defined(__AVX512VL__)
        return _mm_maskz_loadu_ps(0x7, p);
#elif defined(__AVX__)
        return _mm_maskload_ps(p, _mm_setr_epi32(-1, -1, -1, 0));
#else
        return _mm_movelh_ps(_mm_castpd_ps(_mm_load_sd(reinterpret_cast<const double*>(p))),
                             _mm_load_ss(p + 2));
#endif
    }
}
#endif

// Lane k of out[c] is rows[k][c]: N rows of Floats floats (4, or 3 with out[3] zero),
// transposed (N = 4 or 8). Each row is read as one vector under SSE and AVX (load_row),
// else float by float.
template <int N, int Floats = 4>
inline void transpose_rows(const float* const* rows, typename Lanes<N>::Float (&out)[4]) {
#if defined(__AVX__)
    if constexpr (N == 8) {
        const auto pair = [&](int k) {  // rows k and k + 4: lanes k of each half
            return _mm256_insertf128_ps(_mm256_castps128_ps256(load_row<Floats>(rows[k])),
                                        load_row<Floats>(rows[k + 4]), 1);
        };
        const __m256 r04 = pair(0), r15 = pair(1), r26 = pair(2), r37 = pair(3);
        const __m256 lo01 = _mm256_unpacklo_ps(r04, r15), hi01 = _mm256_unpackhi_ps(r04, r15);
        const __m256 lo23 = _mm256_unpacklo_ps(r26, r37), hi23 = _mm256_unpackhi_ps(r26, r37);
        out[0] = _mm256_shuffle_ps(lo01, lo23, 0x44);
        out[1] = _mm256_shuffle_ps(lo01, lo23, 0xee);
        out[2] = _mm256_shuffle_ps(hi01, hi23, 0x44);
        out[3] = _mm256_shuffle_ps(hi01, hi23, 0xee);
        return;
    }
#endif
#if defined(__AVX512F__)
    if constexpr (N == 16) {  // two halves of eight, side by side
        typename Lanes<8>::Float low[4], high[4];
        transpose_rows<8, Floats>(rows, low);
        transpose_rows<8, Floats>(rows + 8, high);
        for (int c = 0; c < 4; ++c)
            out[c] = __builtin_shufflevector(low[c], high[c], 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11,
                                             12, 13, 14, 15);
        return;
    }
#endif
#if defined(__SSE__)
    if constexpr (N == 4) {
        __m128 r0 = load_row<Floats>(rows[0]), r1 = load_row<Floats>(rows[1]);
        __m128 r2 = load_row<Floats>(rows[2]), r3 = load_row<Floats>(rows[3]);
        _MM_TRANSPOSE4_PS(r0, r1, r2, r3);
        out[0] = r0, out[1] = r1, out[2] = r2, out[3] = r3;
        return;
    }
#endif
    for (int k = 0; k < N; ++k)
        for (int c = 0; c < 4; ++c) out[c][k] = c < Floats ? rows[k][c] : 0.0f;
}

// The smallest and the largest lane, in log2(lanes) steps (no lane may be NaN).
inline float hmin(Float4 v) {
    v = vmin(v, __builtin_shufflevector(v, v, 2, 3, 0, 1));
    return vmin(v, __builtin_shufflevector(v, v, 1, 0, 3, 2))[0];
}
inline float hmax(Float4 v) {
    v = vmax(v, __builtin_shufflevector(v, v, 2, 3, 0, 1));
    return vmax(v, __builtin_shufflevector(v, v, 1, 0, 3, 2))[0];
}
#if defined(__AVX__)
inline float hmin(Float8 v) {
    return hmin(
        vmin(__builtin_shufflevector(v, v, 0, 1, 2, 3), __builtin_shufflevector(v, v, 4, 5, 6, 7)));
}
inline float hmax(Float8 v) {
    return hmax(
        vmax(__builtin_shufflevector(v, v, 0, 1, 2, 3), __builtin_shufflevector(v, v, 4, 5, 6, 7)));
}
#endif
#if defined(__AVX512F__)
inline float hmin(Float16 v) {
    return hmin(vmin(__builtin_shufflevector(v, v, 0, 1, 2, 3, 4, 5, 6, 7),
                     __builtin_shufflevector(v, v, 8, 9, 10, 11, 12, 13, 14, 15)));
}
inline float hmax(Float16 v) {
    return hmax(vmax(__builtin_shufflevector(v, v, 0, 1, 2, 3, 4, 5, 6, 7),
                     __builtin_shufflevector(v, v, 8, 9, 10, 11, 12, 13, 14, 15)));
}
#endif

}  // namespace rt
