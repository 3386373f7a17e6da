#!/usr/bin/env bash
# Set up, build with warnings as errors, and run the whole test suite.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh -DRTVIEW_WERROR=ON
status=0
ctest --test-dir build --output-on-failure -j "$(nproc)" || status=$?
[ -f build/golden_report/index.html ] && echo "screenshot report: build/golden_report/index.html"
exit $status
