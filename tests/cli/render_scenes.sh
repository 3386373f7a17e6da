#!/usr/bin/env bash
# rtrender renders every scene in assets/scenes and a bare .obj, writes PNG, EXR and
# the --stats JSON, and says what it wrote.
#   render_scenes.sh RTRENDER ASSETS_DIR OUT_DIR
set -u
rtrender=$1
assets=$2
out=$3
rm -rf "$out"
mkdir -p "$out"
failures=0
cases=0

fail() { echo "FAIL $1"; failures=$((failures + 1)); }

for scene in "$assets"/scenes/*.json "$assets"/models/teapot.obj; do
    name=$(basename "${scene%.*}")
    cases=$((cases + 1))
    if ! timeout 120 "$rtrender" "$scene" --size 96x72 -o "$out/$name.png" --stats "$out/$name.stats.json" >"$out/$name.log" 2>&1; then
        fail "$name: exit status $?: $(cat "$out/$name.log")"
        continue
    fi
    grep -q "^wrote $out/$name.png (96x72)" "$out/$name.log" || fail "$name: no 'wrote' line: $(cat "$out/$name.log")"
    [ -s "$out/$name.png" ] || fail "$name: no PNG written"
    for key in width height threads load_seconds build_seconds trace_seconds primary shadow reflected refracted mrays_per_s; do
        grep -q "\"$key\"" "$out/$name.stats.json" || fail "$name: stats lack \"$key\""
    done
    grep -q '"primary": 6912' "$out/$name.stats.json" || fail "$name: expected 96x72 = 6912 primary rays"
    # The values, not only the keys: sizes as asked, times and rates positive, shadow
    # feelers cast (every shipped scene has lights), the ray total the sum of its kinds.
    python3 - "$out/$name.stats.json" <<'PY' || fail "$name: stats values: $(cat "$out/$name.stats.json")"
import json, sys
s = json.load(open(sys.argv[1]))
def find(d, key):
    if isinstance(d, dict):
        if key in d: return d[key]
        for v in d.values():
            r = find(v, key)
            if r is not None: return r
    return None
assert s["width"] == 96 and s["height"] == 72, "size"
assert s["threads"] >= 1, "threads"
for key in ("trace_seconds", "mrays_per_s"):
    assert find(s, key) > 0, key
assert find(s, "load_seconds") >= 0 and find(s, "build_seconds") >= 0, "load/build"
assert find(s, "shadow") > 0, "no shadow feelers"
assert find(s, "primary") == 96 * 72, "primary"
r = s["rays"]
assert r["total"] == r["primary"] + r["shadow"] + r["reflected"] + r["refracted"], "total"
PY
    grep -q '"nonfinite_pixels": 0' "$out/$name.stats.json" || fail "$name: NaN/Inf pixels"
    echo "ok   $name"
done

# --quiet silences warnings too: an OBJ with a missing MTL file warns without it.
cases=$((cases + 1))
printf 'mtllib gone.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >"$out/warns.obj"
"$rtrender" "$out/warns.obj" --size 32x24 -o "$out/warns.png" >"$out/warns.log" 2>&1
grep -q "warning" "$out/warns.log" || fail "no warning without --quiet: $(cat "$out/warns.log")"
"$rtrender" "$out/warns.obj" --size 32x24 -o "$out/warns.png" --quiet >"$out/warns_quiet.log" 2>&1
if [ -s "$out/warns_quiet.log" ]; then fail "--quiet printed: $(cat "$out/warns_quiet.log")"; else echo "ok   --quiet silences warnings"; fi

cases=$((cases + 1))
if "$rtrender" "$assets/scenes/tutorial.json" --size 64x48 -o "$out/tutorial.exr" --quiet --max-depth 2 --threads 1 \
        --no-shadows --no-reflections --no-refractions >"$out/exr.log" 2>&1; then
    [ -s "$out/tutorial.exr" ] || fail "exr: no file"
    [ -s "$out/exr.log" ] && fail "--quiet printed: $(cat "$out/exr.log")"
    echo "ok   exr + flags"
else
    fail "exr: $(cat "$out/exr.log")"
fi

# --no-light-buffer: every shadow feeler walks the objects' tree; the same image, byte for
# byte, and the stats say which way the feelers went.
cases=$((cases + 1))
for lb in on off; do
    flag=()
    [ "$lb" = off ] && flag=(--no-light-buffer)
    "$rtrender" "$assets/scenes/whitted.json" --size 96x72 -o "$out/lb_$lb.png" --quiet \
        --stats "$out/lb_$lb.json" "${flag[@]}" >"$out/lb_$lb.log" 2>&1 ||
        fail "--light-buffer $lb: $(cat "$out/lb_$lb.log")"
done
if cmp -s "$out/lb_on.png" "$out/lb_off.png" && grep -q '"light_buffer": true' "$out/lb_on.json" &&
    grep -q '"light_buffer": false' "$out/lb_off.json"; then
    echo "ok   --no-light-buffer: the same image"
else
    fail "--no-light-buffer: the images differ or the stats do not say"
fi

# Every acceleration structure renders the same image, byte for byte: they find the
# same hits, and no ray leaving a surface hits that surface again (which once put
# acne on the Cornell box's walls with the grid and brute force, never the BVH).
for name in tutorial cornell many_spheres whitted; do
    "$rtrender" "$assets/scenes/$name.json" --size 96x72 -q -o "$out/$name.bvh.png"
    for accel in bvh2 grid brute; do
        [ "$name" = whitted ] && [ "$accel" = brute ] && continue  # 70k triangles: too slow
        cases=$((cases + 1))
        "$rtrender" "$assets/scenes/$name.json" --size 96x72 -q --accel $accel -o "$out/$name.$accel.png"
        if cmp -s "$out/$name.bvh.png" "$out/$name.$accel.png"; then
            echo "ok   $name: --accel $accel renders what bvh does"
        else
            fail "$name: --accel $accel renders differently from bvh"
        fi
    done
done

# A scene and its mesh under a path with spaces and UTF-8 renders like any other.
cases=$((cases + 1))
mkdir -p "$out/dossier é/models" "$out/dossier é/scènes"
cp "$assets/models/cornell_box.obj" "$assets/models/cornell_box.mtl" "$out/dossier é/models/"
cp "$assets/scenes/cornell.json" "$out/dossier é/scènes/boîte de Cornell.json"
if "$rtrender" "$out/dossier é/scènes/boîte de Cornell.json" --size 64x64 -o "$out/dossier é/out ü.png" -q \
        && [ -s "$out/dossier é/out ü.png" ]; then
    echo "ok   UTF-8 paths with spaces"
else
    fail "UTF-8 paths with spaces"
fi

# Both pipelines and the item buffer: three images, the comparison, the timings.
cases=$((cases + 1))
if "$rtrender" "$assets/scenes/whitted.json" --mode both --item-buffer on --size 120x90 -o "$out/both.png" \
        --stats "$out/both.json" >"$out/both.log" 2>&1; then
    for f in both.raster.png both.trace.png both.diff.png; do [ -s "$out/$f" ] || fail "both: no $f"; done
    for key in raster_seconds item_buffer_seconds primary_seconds secondary_seconds item_buffer_disagreements \
               reference_primary_seconds mean_abs_error rms psnr_db share_over_threshold; do
        grep -q "\"$key\"" "$out/both.json" || fail "both: stats lack \"$key\""
    done
    grep -q "raster vs traced: mean abs error" "$out/both.log" || fail "both: no comparison printed"
    grep -q "pixels disagree" "$out/both.log" || fail "both: no item-buffer report"
    # Why they differ: a share per cause, each column summing to 1, and the pixels no cause
    # explains are those the comparison counts as equal.
    python3 - "$out/both.json" <<'PY' || fail "both: explain stats: $(cat "$out/both.json")"
import json, sys
s = json.load(open(sys.argv[1]))
e = s["explain"]
causes = ["geometry", "shading", "shadow", "reflection", "refraction", "none"]
assert sorted(e) == sorted(causes), e
for col in ("pixels", "error"):
    assert abs(sum(e[c][col] for c in causes) - 1.0) < 1e-9, (col, e)
assert abs(e["none"]["pixels"] - (1.0 - s["diff"]["share_over_threshold"])) < 1e-9, e
assert e["shadow"]["pixels"] > 0 and e["reflection"]["pixels"] > 0 and e["refraction"]["pixels"] > 0, e
PY
    grep -q "why they differ: .*shadow" "$out/both.log" || fail "both: no explain line"
    echo "ok   both + item buffer"
else
    fail "both: $(cat "$out/both.log")"
fi

# The explain map on its own: OUT.explain.png, the map over its legend strip.
cases=$((cases + 1))
if "$rtrender" "$assets/scenes/tutorial.json" --mode explain --size 120x90 -o "$out/why.png" \
        >"$out/why.log" 2>&1 && [ -s "$out/why.explain.png" ] && [ ! -e "$out/why.png" ]; then
    echo "ok   explain"
else
    fail "explain: $(cat "$out/why.log")"
fi

echo "$((cases - failures)) passed, $failures failed"
[ "$failures" -eq 0 ]
