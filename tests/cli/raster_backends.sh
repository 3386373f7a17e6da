#!/usr/bin/env bash
# EGL and OSMesa drive the same llvmpipe: the raster images of a scene must be identical
# (idiff from OpenImageIO, no pixel may differ), and the item buffers too.
#   raster_backends.sh RTRENDER ASSETS_DIR OUT_DIR
set -eu
rtrender=$1 assets=$2 out=$3
mkdir -p "$out"
for scene in tutorial whitted cornell many_spheres; do
    for mode in raster itembuffer; do
        for gl in egl osmesa; do
            "$rtrender" "$assets/scenes/$scene.json" --mode $mode --gl $gl --size 200x150 -q -o "$out/$scene.$mode.$gl.png"
        done
        idiff -q -fail 0 -failpercent 0 "$out/$scene.$mode.egl.png" "$out/$scene.$mode.osmesa.png" \
            || { echo "FAIL $scene $mode: EGL and OSMesa differ"; exit 1; }
        echo "ok   $scene $mode: EGL and OSMesa identical"
    done
done
