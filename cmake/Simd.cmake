# The x86-64 level the whole project compiles for (every target alike, so inline code
# agrees between files). The tracer's wide BVH has nodes of sixteen under AVX-512, eight
# under AVX, four under SSE2 (core/simd.h); packets of rays are eight under AVX. The
# width is what keeps it near Embree, which picks its ISA at run time. Contraction to
# FMA stays off, so the images are the same bit for bit at every level.
#   auto: what measured fastest on the machine building it (docs/BENCHMARKS.md,
#         "fourteenth session"): x86-64-v4 (AVX-512) on an AMD processor that runs it
#         (Zen 4, eight lanes: shadow rays and packets 5-10 % faster; Zen 5, nodes of
#         sixteen: shadow and secondary rays 3-9 % faster again, "twenty-fourth"), else
#         x86-64-v3 (AVX2, FMA, BMI) where the machine runs that (on an Intel Xeon the
#         AVX-512 build was no faster), else the compiler's default. rtview is built
#         where it runs; for a binary to copy to other machines, configure with
#         -DRTVIEW_SIMD=avx2 or sse2.
#   avx512: x86-64-v4 regardless.   avx2: x86-64-v3 regardless (also for valgrind, which
#         does not decode AVX-512).
#   sse2: the compiler's default (x86-64).
set(RTVIEW_SIMD "auto" CACHE STRING "auto | avx512 | avx2 | sse2")
set_property(CACHE RTVIEW_SIMD PROPERTY STRINGS auto avx512 avx2 sse2)
if(NOT RTVIEW_SIMD MATCHES "^(auto|avx512|avx2|sse2)$")
  message(FATAL_ERROR "RTVIEW_SIMD must be auto, avx512, avx2 or sse2, not '${RTVIEW_SIMD}'")
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
  check_cxx_compiler_flag(-march=x86-64-v4 RTVIEW_HAVE_MARCH_V4)
  set(use_v4 OFF)
  if(RTVIEW_SIMD STREQUAL "avx512")
    if(NOT RTVIEW_HAVE_MARCH_V4)
      message(FATAL_ERROR "RTVIEW_SIMD=avx512: the compiler does not take -march=x86-64-v4")
    endif()
    set(use_v4 ON)
  elseif(use_v3 AND RTVIEW_SIMD STREQUAL "auto" AND RTVIEW_HAVE_MARCH_V4)
    check_cxx_source_runs([[
      int main() {
        return __builtin_cpu_is("amd") && __builtin_cpu_supports("avx512f") &&
               __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512cd") &&
               __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl") ? 0 : 1;
      }]] RTVIEW_HOST_AMD_AVX512)
    set(use_v4 ${RTVIEW_HOST_AMD_AVX512})
  endif()
  if(use_v4)
    add_compile_options(-march=x86-64-v4)
    set(RTVIEW_SIMD_LEVEL "x86-64-v4 (AVX-512, nodes of sixteen)")
  elseif(use_v3)
    add_compile_options(-march=x86-64-v3)
    set(RTVIEW_SIMD_LEVEL "x86-64-v3 (AVX2)")
  endif()
endif()
message(STATUS "rtview SIMD: ${RTVIEW_SIMD_LEVEL}")
