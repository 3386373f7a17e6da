#!/usr/bin/env bash
# The main job: set up, build, and render the default scene (or SCENE) into out/.
#   scripts/run.sh [SCENE] [rtrender flags...]
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
scene=${1:-assets/scenes/whitted.json}
shift || true
stem=$(basename "${scene%.*}")
build/app/render/rtrender "$scene" -o "out/$stem.png" --stats "out/$stem.stats.json" "$@"
echo "stats: out/$stem.stats.json"
