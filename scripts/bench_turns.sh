#!/usr/bin/env bash
# Two builds of rtbench in turns on one mesh: ROUNDS rounds, each running A then B once,
# and the median over the rounds of each ratio to Embree's time per ray that the `bvh` and
# `bvh-packets` rows print. On a machine whose speed drifts in spells (docs/BENCHMARKS.md,
# "twenty-third session"), turns put both builds in the same spells.
#   scripts/bench_turns.sh ROUNDS MESH RTBENCH_A RTBENCH_B [RTBENCH OPTIONS...]
# e.g. scripts/bench_turns.sh 10 assets/models/stanford-bunny.obj /tmp/old/rtbench \
#          build/app/bench/rtbench
# Options after the four replace the default `--repeats 7`.
# LD_LIBRARY_PATH_A, LD_LIBRARY_PATH_B: where set, the library path of A's or B's runs:
# one rtbench against two builds of Embree (docs/BENCHMARKS.md, thirty-first session).
set -euo pipefail
if [ $# -lt 4 ]; then
    sed -n '2,11p' "$0" >&2
    exit 1
fi
rounds=$1 mesh=$2 a=$3 b=$4
shift 4
options=("$@")
[ ${#options[@]} -eq 0 ] && options=(--repeats 7)
cd "$(dirname "$0")/.."
export RTVIEW_SHADER_DIR=${RTVIEW_SHADER_DIR:-shaders}
out=$(mktemp)
trap 'rm -f "$out"' EXIT
# The order alternates (A B, B A, ...): two runs always in the same order put the first
# 10-15 % behind in some spells and ahead in others (docs/BENCHMARKS.md, thirtieth session).
for ((i = 0; i < rounds; ++i)); do
    order="A B"
    ((i % 2)) && order="B A"
    for which in $order; do
        bin=$a lib=${LD_LIBRARY_PATH_A:-}
        [ $which = B ] && bin=$b lib=${LD_LIBRARY_PATH_B:-}
        env ${lib:+LD_LIBRARY_PATH="$lib"} "$bin" "$mesh" --only bvh,embree,bvh-packets,embree-packets "${options[@]}" |
            sed -n "s/^\(bvh\|bvh-packets\) .*/$which &/p" >>"$out"
    done
done
python3 - "$out" "$rounds" <<'EOF'
import re, statistics, sys
rows = {}
for line in open(sys.argv[1]):
    which, structure = line.split()[:2]
    ratios = [float(x) for x in re.findall(r"\(([0-9.]+)x\)", line)]
    rows.setdefault((which, structure), []).append(ratios)
print(f"medians of {sys.argv[2]} rounds, time per ray over Embree's: primary / shadow / secondary / mirror")
for (which, structure), runs in sorted(rows.items(), key=lambda kv: (kv[0][1], kv[0][0])):
    cols = [statistics.median(r[i] for r in runs) for i in range(len(runs[0]))]
    print(f"{which} {structure:12s}", " / ".join(f"{c:.3f}x" for c in cols))
EOF
