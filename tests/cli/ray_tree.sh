#!/usr/bin/env bash
# rtrender --ray-tree X,Y: the pixel's rays printed one a line and written as JSON; a
# pixel outside the image, or not X,Y, is one located line and status 1.
#   ray_tree.sh RTRENDER ASSETS_DIR OUT_DIR
set -u
rtrender=$1
assets=$2
out=$3
rm -rf "$out"
mkdir -p "$out"
failures=0
fail() { echo "FAIL $1"; failures=$((failures + 1)); }

# The Whitted scene's glass ball, at 160 x 120: in, out, and feelers on the way.
scene="$assets/scenes/whitted.json"
if ! "$rtrender" "$scene" --size 160x120 --ray-tree 100,70 --ray-tree-json "$out/tree.json" >"$out/tree.txt" 2>&1; then
    fail "exit status $?: $(cat "$out/tree.txt")"
fi
grep -q "^pixel 100,70 (from the top left): colour (" "$out/tree.txt" || fail "no pixel line: $(head -n2 "$out/tree.txt")"
grep -q "^  primary from " "$out/tree.txt" || fail "no primary ray line"
grep -q "^    shadow to light 0" "$out/tree.txt" || fail "no shadow feeler under the primary ray"
python3 - "$out/tree.json" <<'PY' || fail "the JSON is not the tree: $(head -c 300 "$out/tree.json")"
import json, sys
t = json.load(open(sys.argv[1]))
assert t["pixel"] == [100, 70], t["pixel"]
r = t["ray"]
assert r["kind"] == "primary" and r["hit"] is not None, r["kind"]
assert len(t["colour"]) == 3 and t["colour"] == r["colour"]
kinds = set()
def walk(n):
    kinds.add(n["kind"])
    for c in n["children"]:
        walk(c)
walk(r)
assert {"primary", "shadow"} <= kinds, kinds
PY
lines=$(grep -c "" "$out/tree.txt")
[ "$lines" -ge 3 ] || fail "only $lines lines"

for bad in 160,0 0,120 -1,5 abc 5; do
    if "$rtrender" "$scene" --size 160x120 --ray-tree "$bad" >"$out/bad.txt" 2>&1; then
        fail "--ray-tree $bad: exit status 0"
    fi
    [ "$(grep -c "" "$out/bad.txt")" -eq 1 ] || fail "--ray-tree $bad: not one line: $(cat "$out/bad.txt")"
    grep -q "^rtrender: --ray-tree: " "$out/bad.txt" || fail "--ray-tree $bad: $(cat "$out/bad.txt")"
done

# A scene a million units out: the loader moves it to the origin for float's sake; the
# tree's points are printed where the file put them.
cat >"$out/far.json" <<'JSON'
{ "camera": { "eye": [1000000, 1, 1000006], "u": [1, 0, 0], "v": [0, 1, 0], "n": [0, 0, 1], "H": 0.5, "N": 1 },
  "resolution": [64, 48],
  "lights": [ { "type": "point", "position": [999997, 5, 1000004] } ],
  "materials": { "red": { "ka": 0.2, "kd": 0.8 } },
  "objects": [ { "type": "sphere", "center": [999999.2, 0, 1000000], "radius": 1, "material": "red" } ] }
JSON
if "$rtrender" "$out/far.json" --ray-tree 27,26 --ray-tree-json "$out/far_tree.json" >"$out/far.txt" 2>&1; then
    python3 - "$out/far_tree.json" <<'PY' || fail "far scene: points not in the file's coordinates: $(cat "$out/far.txt")"
import json, math, sys
r = json.load(open(sys.argv[1]))["ray"]
assert all(abs(a - b) < 1e-3 for a, b in zip(r["origin"], [1000000, 1, 1000006])), r["origin"]
p = r["hit"]["point"]
d = math.dist(p, [999999.2, 0, 1000000])
assert abs(d - 1.0) < 1e-3, (p, d)
PY
    grep -q "at (999997, 5, 1000004)" "$out/far.txt" || fail "far scene: the light's position: $(cat "$out/far.txt")"
else
    fail "far scene: $(cat "$out/far.txt")"
fi

# A scene a billionth of a unit across: read in a power-of-two unit of its own; the tree's
# points and distances are printed in the file's.
cat >"$out/tiny.json" <<'JSON'
{ "camera": { "eye": [0, 0, 6e-9], "look_at": [0, 0, 0], "fov": 40 },
  "resolution": [64, 48],
  "lights": [ { "type": "point", "position": [3e-9, 5e-9, 4e-9] } ],
  "objects": [ { "type": "sphere", "center": [0, 0, 0], "radius": 1e-9 } ] }
JSON
if "$rtrender" "$out/tiny.json" --ray-tree 32,24 --ray-tree-json "$out/tiny_tree.json" >"$out/tiny.txt" 2>&1; then
    python3 - "$out/tiny_tree.json" <<'PY' || fail "tiny scene: not in the file's units: $(cat "$out/tiny.txt")"
import json, math, sys
r = json.load(open(sys.argv[1]))["ray"]
assert all(abs(a - b) < 1e-15 for a, b in zip(r["origin"], [0, 0, 6e-9])), r["origin"]
h = r["hit"]
assert abs(math.dist(h["point"], [0, 0, 0]) - 1e-9) < 1e-12, h["point"]
assert abs(h["distance"] - 5e-9) < 1e-10, h["distance"]
PY
else
    fail "tiny scene: $(cat "$out/tiny.txt")"
fi

echo "ray tree: $failures failures"
[ "$failures" -eq 0 ]
