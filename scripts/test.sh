#!/usr/bin/env bash
# Set up, build with warnings as errors, and run the whole test suite: unit, GL
# (EGL and OSMesa), screenshot, command-line and GUI (Xvfb) tests. Then the headless
# configuration (no GLFW, no X11, no viewer) is built and its tests run too, then the
# suite under AddressSanitizer/UBSan and ThreadSanitizer, then each fuzzer for 30 s.
#   scripts/test.sh [--quick]
# --quick: the build and its unit, GL, screenshot and command-line tests only (a couple
# of minutes), for the edit-build-test loop. CI runs the whole suite.
set -euo pipefail
cd "$(dirname "$0")/.."
quick=0
case "${1:-}" in
  --quick) quick=1 ;;
  "") ;;
  *) echo "usage: scripts/test.sh [--quick]" >&2; exit 2 ;;
esac
scripts/setup.sh
scripts/build.sh -DRTVIEW_WERROR=ON
status=0
if [ $quick -eq 1 ]; then
  ctest --test-dir build --output-on-failure -j "$(nproc)" -L "unit|gl|golden|cli" || status=$?
  exit $status
fi
echo "== the main suite, built at ${SECONDS} s"
ctest --test-dir build --output-on-failure -j "$(nproc)" || status=$?
[ -f build/golden_report/index.html ] && echo "screenshot report: build/golden_report/index.html"

echo "== headless configuration (-DRTVIEW_BUILD_VIEWER=OFF), at ${SECONDS} s"
# What the configuration changes is the programs, built without the viewer's packages:
# its screenshot tests (every scene through EGL and OSMesa) and command-line tests, and
# only what they run is built. The GL library's sources are the same in both
# configurations (only the window's targets drop out) and the unit tests are the same
# code, so their tests (rt_gl_tests, rt_tests) ran in the main build. This build and the sanitizers' and fuzzers' are unity builds
# (CMAKE_UNITY_BUILD: eight sources a compile), half the compile time of one file each;
# the main build above compiles each file alone, so an include that a file forgot still
# fails there.
cmake -S . -B build-headless -G Ninja -DCMAKE_BUILD_TYPE=Release -DRTVIEW_WERROR=ON -DRTVIEW_BUILD_VIEWER=OFF \
    -DCMAKE_UNITY_BUILD=ON >/dev/null
cmake --build build-headless --target rtrender rtbench rtgolden
echo "== headless tests, built at ${SECONDS} s"
ctest --test-dir build-headless --output-on-failure -j "$(nproc)" -L "golden|cli" || status=$?

echo "== sanitizers, at ${SECONDS} s"
scripts/sanitize.sh || status=1
echo "== fuzzing, at ${SECONDS} s"
scripts/fuzz.sh 30 || status=1
echo "== done in ${SECONDS} s"
exit $status
