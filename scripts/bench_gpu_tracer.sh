#!/usr/bin/env bash
# The CPU tracer against the GPU tracer (rtrender --mode gputrace) on every shipped scene:
# 5 interleaved runs each at 1280x720, medians of the trace time (CPU: trace_seconds;
# GPU: gpu.dispatch_seconds, the second frame, without the read-back).
#   scripts/bench_gpu_tracer.sh [BUILD_DIR] [GL_BACKEND]
set -eu
build=${1:-build} gl=${2:-egl}
rtrender=$build/app/render/rtrender
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
seconds() { python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(eval(sys.argv[2], {}, d))" "$1" "$2"; }
for scene in assets/scenes/*.json; do
    cpu="" gpu=""
    for _ in 1 2 3 4 5; do
        "$rtrender" "$scene" --size 1280x720 --threads 2 -q -o "$out/c.png" --stats "$out/c.json"
        cpu="$cpu $(seconds "$out/c.json" "trace_seconds")"
        "$rtrender" "$scene" --size 1280x720 --mode gputrace --gl "$gl" -q -o "$out/g.png" --stats "$out/g.json"
        gpu="$gpu $(seconds "$out/g.json" "gpu['dispatch_seconds']")"
    done
    python3 - "$(basename "$scene" .json)" "$cpu" "$gpu" <<'PY'
import statistics, sys
cpu = statistics.median(map(float, sys.argv[2].split()))
gpu = statistics.median(map(float, sys.argv[3].split()))
print(f"{sys.argv[1]:14s} CPU {cpu:.3f} s   GPU {gpu:.3f} s   GPU/CPU {gpu / cpu:.2f}")
PY
done
