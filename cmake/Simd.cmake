# The x86-64 level the whole project compiles for (every target alike, so inline code
# agrees between files). The tracer's wide BVH runs eight lanes under AVX, four under
# SSE2 (core/simd.h); eight is what keeps it near Embree, which picks its ISA at run
# time. Contraction to FMA stays off, so the images are the same bit for bit at either
# level.
#   auto: x86-64-v3 (AVX2, FMA, BMI) when the machine building it runs that, else the
#         compiler's default. rtview is built where it runs; for a binary to copy to
#         older machines, configure with -DRTVIEW_SIMD=sse2.
#   avx2: x86-64-v3 regardless.   sse2: the compiler's default (x86-64).
set(RTVIEW_SIMD "auto" CACHE STRING "auto | avx2 | sse2")
set_property(CACHE RTVIEW_SIMD PROPERTY STRINGS auto avx2 sse2)
if(NOT RTVIEW_SIMD MATCHES "^(auto|avx2|sse2)$")
  message(FATAL_ERROR "RTVIEW_SIMD must be auto, avx2 or sse2, not '${RTVIEW_SIMD}'")
endif()

add_compile_options(-ffp-contract=off)

set(RTVIEW_SIMD_LEVEL "default")
if(CMAKE_SYSTEM_PROCESSOR MATCHES "^(x86_64|AMD64)$" AND NOT RTVIEW_SIMD STREQUAL "sse2")
  include(CheckCXXCompilerFlag)
  include(CheckCXXSourceRuns)
  check_cxx_compiler_flag(-march=x86-64-v3 RTVIEW_HAVE_MARCH_V3)
  set(use_v3 ${RTVIEW_HAVE_MARCH_V3})
  if(use_v3 AND RTVIEW_SIMD STREQUAL "auto")
    check_cxx_source_runs([[
      int main() {
        return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") &&
               __builtin_cpu_supports("bmi") && __builtin_cpu_supports("bmi2") ? 0 : 1;
      }]] RTVIEW_HOST_RUNS_AVX2)
    set(use_v3 ${RTVIEW_HOST_RUNS_AVX2})
  endif()
  if(RTVIEW_SIMD STREQUAL "avx2" AND NOT RTVIEW_HAVE_MARCH_V3)
    message(FATAL_ERROR "RTVIEW_SIMD=avx2: the compiler does not take -march=x86-64-v3")
  endif()
  if(use_v3)
    add_compile_options(-march=x86-64-v3)
    set(RTVIEW_SIMD_LEVEL "x86-64-v3 (AVX2)")
  endif()
endif()
message(STATUS "rtview SIMD: ${RTVIEW_SIMD_LEVEL}")
