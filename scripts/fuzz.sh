#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (AddressSanitizer and UBSan on) and runs each
# for SECONDS (default 30) from its seed corpus in tests/fuzz/corpus. A crash leaves
# crash-* files in build-fuzz/; make each a regression file in tests/data/bad/.
#   scripts/fuzz.sh [SECONDS]      a longer run: scripts/fuzz.sh 3600
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-30}
scripts/setup.sh
flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer -g -O1"
CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DRTVIEW_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_UNITY_BUILD=ON \
    -DCMAKE_C_FLAGS="$flags" -DCMAKE_CXX_FLAGS="$flags" >/dev/null
cmake --build build-fuzz
echo "== fuzzers built at ${SECONDS} s of fuzz.sh"
# The fuzzers run at once, as many as there are cores (each is one process on one core):
# each still has its SECONDS, and CI waits for less than half the time on two cores.
# fuzz_bvh runs alone, last: its large trees are built on the thread pool, and beside
# another fuzzer it ran 249 inputs in 30 s where alone it ran 852.
run_fuzzer() {  # run_fuzzer CORPUS BINARY: its exit status in build-fuzz/BINARY.status
    local corpus=$1 binary=$2 run=0
    mkdir -p "build-fuzz/corpus-$corpus"
    (cd build-fuzz && tests/fuzz/"$binary" -max_total_time="$seconds" -timeout=5 -rss_limit_mb=4096 \
        -print_final_stats=1 "corpus-$corpus" "../tests/fuzz/corpus/$corpus" >"$binary.log" 2>&1) || run=$?
    echo "$run" >"build-fuzz/$binary.status"
}
targets=(json:fuzz_scene_json obj:fuzz_obj gltf:fuzz_gltf mesh:fuzz_ply_stl image:fuzz_image bvh:fuzz_bvh)
for target in "${targets[@]}"; do
    rm -f "build-fuzz/${target#*:}.status"
    if [ "$target" = bvh:fuzz_bvh ]; then
        wait
        run_fuzzer bvh fuzz_bvh
        continue
    fi
    while [ "$(jobs -rp | wc -l)" -ge "$(nproc)" ]; do wait -n || true; done
    run_fuzzer "${target%%:*}" "${target#*:}" &
done
wait
status=0
for target in "${targets[@]}"; do
    corpus=${target%%:*} binary=${target#*:}
    echo "== $binary: ${seconds}s from tests/fuzz/corpus/$corpus"
    run=$(cat "build-fuzz/$binary.status" 2>/dev/null || echo "no status")
    grep -E "^(#[0-9]+ +DONE|stat::number_of_executed_units|stat::peak_rss_mb)" "build-fuzz/$binary.log" || true
    if [ "$run" != 0 ]; then
        grep -E "ERROR|SUMMARY|Test unit written|==[0-9]+==" "build-fuzz/$binary.log" 2>/dev/null | head -20 || true
        echo "FAIL $binary (exit $run): see build-fuzz/$binary.log and build-fuzz/crash-*"
        status=1
    else
        echo "ok   $binary"
    fi
done
exit $status
