#!/usr/bin/env bash
# The test suite under sanitizers, each in a build of its own:
#   AddressSanitizer + UndefinedBehaviorSanitizer (+ LeakSanitizer): unit, GL, golden and
#   command-line tests of the headless configuration;
#   ThreadSanitizer: the threaded renderer, the BVH's parallel build and the viewer's
#   trace job.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
status=0

echo "== AddressSanitizer + UndefinedBehaviorSanitizer"
asan="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRTVIEW_BUILD_VIEWER=OFF \
    -DCMAKE_CXX_FLAGS="$asan" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
cmake --build build-asan
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# Leaks: the unit tests load and render every scene without GL, with LeakSanitizer on.
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0"
ASAN_OPTIONS="detect_leaks=1:abort_on_error=1" ctest --test-dir build-asan --output-on-failure -j "$(nproc)" -L unit \
    || status=1
# With GL loaded, Mesa's EGL keeps allocations until exit that the unwinder cannot place
# (no frame pointers in Mesa), so these run with leak detection off: memory errors and
# undefined behaviour are still caught.
ASAN_OPTIONS="detect_leaks=0:abort_on_error=1" ctest --test-dir build-asan --output-on-failure -j "$(nproc)" \
    -L "gl|golden|cli" || status=1
unset LSAN_OPTIONS UBSAN_OPTIONS

echo "== ThreadSanitizer"
cmake -S . -B build-tsan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS="-fsanitize=thread" \
    -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=thread" >/dev/null
cmake --build build-tsan --target rt_tests rt_viewer_tests
TSAN_OPTIONS="halt_on_error=1" build-tsan/tests/rt_tests --gtest_filter='Render.*:AccelTest.*:Bvh.*' || status=1
TSAN_OPTIONS="halt_on_error=1" build-tsan/tests/rt_viewer_tests --gtest_filter='TraceJob.*' || status=1
exit $status
