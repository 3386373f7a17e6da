#!/usr/bin/env bash
# The main job: set up, build, and open the viewer on the default scene (or SCENE).
# Without a display it renders the scene headless into out/ instead and says where.
#   scripts/run.sh [SCENE] [flags...]
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
scene=${1:-assets/scenes/whitted.json}
shift || true
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ] && [ -x build/app/viewer/rtview ]; then
    exec build/app/viewer/rtview "$scene" "$@"
fi
echo "no display: rendering headless with rtrender (raster, traced and difference)"
stem=$(basename "${scene%.*}")
build/app/render/rtrender "$scene" --mode both -o "out/$stem.png" --stats "out/$stem.stats.json" "$@"
echo "stats: out/$stem.stats.json"
