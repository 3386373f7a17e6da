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

# --gl auto falls back to OSMesa when EGL cannot start (no EGL vendor library here), and
# renders the same image.
__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json "$rtrender" "$assets/scenes/tutorial.json" \
    --mode raster --gl auto --size 200x150 -o "$out/auto.png" >"$out/auto.log" 2>&1 \
    || { echo "FAIL --gl auto without EGL: $(cat "$out/auto.log")"; exit 1; }
grep -q "^OpenGL: OSMesa" "$out/auto.log" || { echo "FAIL --gl auto did not say it fell back to OSMesa: $(cat "$out/auto.log")"; exit 1; }
idiff -q -fail 0 -failpercent 0 "$out/auto.png" "$out/tutorial.raster.osmesa.png" \
    || { echo "FAIL --gl auto (OSMesa) differs from --gl osmesa"; exit 1; }
echo "ok   --gl auto falls back to OSMesa when EGL cannot start"
