#!/usr/bin/env bash
# One screenshot test: render SCENE small with rtrender, then compare with rtgolden.
#   run_golden.sh RTRENDER RTGOLDEN NAME REFERENCE SCENE REFERENCE_DIR REPORT_DIR FAIL FAIL_PERCENT -- RTRENDER_FLAGS...
set -eu
rtrender=$1 rtgolden=$2 name=$3 reference=$4 scene=$5 refs=$6 report=$7 fail=$8 fail_percent=$9
shift 10
work=$report/work
mkdir -p "$work"
"$rtrender" "$scene" -o "$work/$name.png" --size 160x120 --quiet "$@"
"$rtgolden" compare "$name" "$work/$name.png" "$refs" "$report" --fail "$fail" --fail-percent "$fail_percent" --as "$reference"
