#!/usr/bin/env bash
# Two builds of rtbench in turns on one mesh: ROUNDS rounds, each running A then B once
# (then B then A), each run `rtbench MESH --threads-sweep THREADS`; prints per build and
# thread count the medians over the rounds of our build rate, its time relative to
# Embree's and Embree's rate, as the sweep's rows print them. Turns put both builds in
# the same spells of a machine whose speed drifts (docs/BENCHMARKS.md, "twenty-third
# session").
#   scripts/build_turns.sh ROUNDS MESH RTBENCH_A RTBENCH_B [THREADS]    (THREADS: 1,2)
# e.g. scripts/build_turns.sh 3 assets/models/stanford-bunny.obj /tmp/old/rtbench \
#          build/app/bench/rtbench
set -euo pipefail
if [ $# -lt 4 ]; then
    sed -n '2,10p' "$0" >&2
    exit 1
fi
rounds=$1 mesh=$2 a=$3 b=$4 threads=${5:-1,2}
cd "$(dirname "$0")/.."
export RTVIEW_SHADER_DIR=${RTVIEW_SHADER_DIR:-shaders}
out=$(mktemp)
trap 'rm -f "$out"' EXIT
for ((i = 0; i < rounds; ++i)); do
    order="A B"
    ((i % 2)) && order="B A"
    for which in $order; do
        bin=$a
        [ "$which" = B ] && bin=$b
        # A row: threads, our rate (our time over Embree's), Embree's rate, the rays' ...
        "$bin" "$mesh" --threads-sweep "$threads" | grep -E '^ +[0-9]+ +[0-9.]+ \(' |
            sed -E 's/[(),x]//g' | awk -v w="$which" '{print w, $1, $2, $3, $4}' >>"$out"
    done
done
python3 - "$out" "$mesh" <<'EOF'
import statistics
import sys

rows = {}
for line in open(sys.argv[1]):
    which, threads, rate, ratio, embree = line.split()
    rows.setdefault((which, int(threads)), []).append((float(rate), float(ratio), float(embree)))
for (which, threads), runs in sorted(rows.items()):
    rate, ratio, embree = (statistics.median(column) for column in zip(*runs))
    print(f"{sys.argv[2]} {which} threads {threads}: build {rate:.2f} Mtri/s, "
          f"{ratio:.3f}x Embree's time (Embree {embree:.2f} Mtri/s), {len(runs)} runs")
EOF
