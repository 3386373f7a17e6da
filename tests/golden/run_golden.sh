#!/usr/bin/env bash
# One screenshot test: render SCENE small with rtrender, then compare with rtgolden.
#   run_golden.sh RTRENDER RTGOLDEN NAME REFERENCE SCENE REFERENCE_DIR REPORT_DIR FAIL FAIL_PERCENT EDGES -- RTRENDER_FLAGS...
# EDGES: the share (percent) of pixels the edge rule may accept (rtgolden --edges), or -1.
set -eu
rtrender=$1 rtgolden=$2 name=$3 reference=$4 scene=$5 refs=$6 report=$7 fail=$8 fail_percent=$9
edges=${10}
shift 11
work=$report/work
mkdir -p "$work"
"$rtrender" "$scene" -o "$work/$name.png" --size 160x120 --quiet "$@"
# --mode explain writes OUT.explain.png beside the name it is given.
if [ -f "$work/$name.explain.png" ]; then mv "$work/$name.explain.png" "$work/$name.png"; fi
"$rtgolden" compare "$name" "$work/$name.png" "$refs" "$report" --fail "$fail" --fail-percent "$fail_percent" --edges "$edges" --as "$reference"
