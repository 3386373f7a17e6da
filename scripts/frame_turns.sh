#!/usr/bin/env bash
# The issue's frame (or another scene's) from two builds of rtrender in turns: ROUNDS
# rounds, the order alternating (A B, B A, ...: a fixed order biases the first by 10-15 %
# in some spells, docs/BENCHMARKS.md, thirtieth session), and the median and least of
# each build's trace seconds (`--stats`' trace_seconds).
#   scripts/frame_turns.sh ROUNDS SCENE RTRENDER_A RTRENDER_B [RTRENDER OPTIONS...]
# e.g. scripts/frame_turns.sh 12 assets/scenes/whitted.json /tmp/old/rtrender \
#          build/app/render/rtrender
# Options after the four replace the default `--size 1280x720 --max-depth 2`.
set -euo pipefail
if [ $# -lt 4 ]; then
    sed -n '2,9p' "$0" >&2
    exit 1
fi
rounds=$1 scene=$2 a=$3 b=$4
shift 4
options=("$@")
[ ${#options[@]} -eq 0 ] && options=(--size 1280x720 --max-depth 2)
cd "$(dirname "$0")/.."
export RTVIEW_SHADER_DIR=${RTVIEW_SHADER_DIR:-shaders}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for ((i = 0; i < rounds; ++i)); do
    order="A B"
    ((i % 2)) && order="B A"
    for which in $order; do
        bin=$a
        [ $which = B ] && bin=$b
        "$bin" "$scene" "${options[@]}" -o "$work/frame.png" --stats "$work/stats.json" -q >/dev/null
        python3 -c 'import json, sys; print(sys.argv[1], json.load(open(sys.argv[2]))["trace_seconds"])' \
            "$which" "$work/stats.json" >>"$work/times"
    done
done
python3 - "$work/times" "$rounds" "$a" "$b" <<'PY'
import statistics, sys
times = {}
for line in open(sys.argv[1]):
    which, seconds = line.split()
    times.setdefault(which, []).append(float(seconds))
print(f"{sys.argv[2]} rounds, trace seconds: median (least)")
for which, name in (("A", sys.argv[3]), ("B", sys.argv[4])):
    t = times[which]
    print(f"{which} {statistics.median(t):.4f} ({min(t):.4f})  {name}")
PY
