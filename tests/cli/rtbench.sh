#!/usr/bin/env bash
# rtbench runs every structure and checks their answers (and fails on a wrong one),
# sweeps triangle counts into a CSV and a plot, and measures the item buffer.
#   rtbench.sh RTBENCH ASSETS_DIR OUT_DIR
set -u
rtbench=$1 assets=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
failures=0 cases=0
check() { cases=$((cases + 1)); local what=$1; shift; if "$@"; then echo "ok   $what"; else echo "FAIL $what"; failures=$((failures + 1)); fi; }

"$rtbench" "$assets/models/teapot.obj" --size 160x90 --repeats 1 --json "$out/teapot.json" >"$out/teapot.log" 2>&1
check "structures agree on the teapot (exit 0)" test $? -eq 0
check "  ... and say so" grep -q "every structure agrees" "$out/teapot.log"
for key in brute grid bvh2 bvh bvh-packets build_seconds memory_bytes primary shadow secondary mirror mrays_per_s checks; do
    check "  ... JSON has \"$key\"" grep -q "\"$key\"" "$out/teapot.json"
done
if grep -q '"embree"' "$out/teapot.json"; then
    check "  ... and Embree in robust mode beside it, our BVH's time against it" \
        grep -q '"embree_robust_time_ratio"' "$out/teapot.json"
    check "  ... said in the log" grep -q "bvh against embree-robust" "$out/teapot.log"
fi
# A legal mesh of another class: a ground 120 units wide with boxes on it. Secondary rays
# start on the ground's plane, as a renderer's do (else 2e-5 under it, which Embree's
# robust mode answered otherwise), and a ray leaving a wall by the ground meets it within
# float rounding of its start (our test rejects such hits, Embree's takes them): no false
# "WRONG" either way.
town="$(dirname "$0")/../data/mesh/town.obj"
if grep -q '"embree"' "$out/teapot.json"; then
    "$rtbench" "$town" --size 160x90 --repeats 1 >"$out/town.log" 2>&1
    check "structures agree on a ground with boxes on it (exit 0)" test $? -eq 0
    "$rtbench" "$town" --size 1280x720 --repeats 1 --only bvh >"$out/town_hd.log" 2>&1
    check "  ... at 1280x720 too, rays leaving walls by the ground" test $? -eq 0
fi
# Slivers 6 units long and 2e-4 wide, a tube twisted a quarter turn
# (scripts/make_bench_meshes.py's twist): a float test's t there is rounded by more than
# a hit 2e-4 from a ray's start, whichever corner is the triangle's first. The arbiter's
# slack once depended on that corner, and said WRONG on mirror rays here.
if grep -q '"embree"' "$out/teapot.json"; then
    python3 -c "import sys; sys.path.insert(0, sys.argv[1]); import make_bench_meshes as m; \
m.write_obj(sys.argv[2], *m.twist(3000))" "$(dirname "$0")/../../scripts" "$out/twist.obj" >/dev/null
    "$rtbench" "$out/twist.obj" --size 640x360 --repeats 1 --only bvh,embree,bvh-packets >"$out/twist.log" 2>&1
    check "structures agree on a twisted tube of slivers (exit 0)" test $? -eq 0
    check "  ... Embree's misses through them named, not ours" grep -q "embree is wrong on [1-9]" "$out/twist.log"
    # Embree's own wrong answers (by brute force and the exact test) are said, and are not
    # a failure of ours: its default triangle test is not watertight.
    RTBENCH_FAULT=embree "$rtbench" "$assets/models/teapot.obj" --size 160x90 --repeats 1 --only bvh,brute,embree >"$out/fault_embree.log" 2>&1
    check "Embree's wrong answers do not fail the run (exit 0)" test $? -eq 0
    check "  ... and are named" grep -q "^Embree: embree.shadow is wrong where it differs from brute" "$out/fault_embree.log"
fi
RTBENCH_FAULT=grid "$rtbench" "$assets/models/teapot.obj" --size 160x90 --repeats 1 --only grid,brute >"$out/fault.log" 2>&1
check "a structure giving wrong answers makes rtbench fail (exit 1)" test $? -eq 1
check "  ... naming it" grep -q "WRONG: grid" "$out/fault.log"
RTBENCH_FAULT=bvh "$rtbench" "$assets/models/teapot.obj" --size 160x90 --repeats 1 --only bvh >"$out/fault_bvh.log" 2>&1
check "  ... the wide BVH too" grep -q "WRONG: bvh" "$out/fault_bvh.log"
RTBENCH_FAULT=bvh-packets "$rtbench" "$assets/models/teapot.obj" --size 160x90 --repeats 1 --only bvh-packets >"$out/fault_packets.log" 2>&1
check "  ... and its packets" grep -q "WRONG: bvh-packets" "$out/fault_packets.log"

# The GPU tracer's traversal (a compute shader) on the same rays, on both contexts.
for gl in egl osmesa; do
    "$rtbench" "$assets/models/teapot.obj" --size 160x90 --repeats 1 --only bvh --gpu --gl $gl >"$out/gpu_$gl.log" 2>&1
    check "--gpu --gl $gl: the GPU agrees with the references (exit 0)" test $? -eq 0
    check "  ... in a row of its own" grep -q "^gpu " "$out/gpu_$gl.log"
done
RTBENCH_FAULT=gpu "$rtbench" "$assets/models/teapot.obj" --size 160x90 --repeats 1 --only bvh --gpu >"$out/fault_gpu.log" 2>&1
check "  ... and wrong GPU answers fail, naming it" grep -q "WRONG: gpu" "$out/fault_gpu.log"

# A plot path with a space and a quote in it: the user's to choose.
plot="$out/it's a sweep.png"
"$rtbench" --sweep --counts 200,2000 --repeats 1 --csv "$out/sweep.csv" --png "$plot" >"$out/sweep.log" 2>&1
check "sweep runs" test $? -eq 0
check "  ... and writes a row per count and structure" test "$(grep -c '^[0-9]' "$out/sweep.csv")" -ge 8
check "  ... and a plot, at a path with a space and a quote" test -s "$plot"
check "  ... leaving no gnuplot data or script behind" test ! -e "$plot.dat" -a ! -e "$plot.gnuplot"
if grep -q ',embree,' "$out/sweep.csv"; then
  check "  ... and each row's time relative to Embree's (Embree's own: 1)" \
    awk -F, 'NR > 1 && $2 == "embree" && $6 != 1 { bad = 1 } NR > 1 && NF != 6 { bad = 1 } END { exit bad }' "$out/sweep.csv"
fi

"$rtbench" --item-buffer "$assets/scenes/tutorial.json" --size 160x120 --repeats 1 >"$out/ib.log" 2>&1
check "item-buffer demo runs (exit 0: images agree)" test $? -eq 0
check "  ... and reports the net effect" grep -q "net on the frame" "$out/ib.log"
check "  ... and the primary step alone, with and without" \
  grep -Eq "the primary step alone.*packets [0-9.]+ ms, item buffer [0-9.]+ ms" "$out/ib.log"

"$rtbench" "$out/none.obj" >"$out/bad.log" 2>&1
check "a missing file: exit 1, one line" test $? -eq 1 -a "$(wc -l <"$out/bad.log")" -eq 1

echo "$((cases - failures)) passed, $failures failed"
[ "$failures" -eq 0 ]
