#!/usr/bin/env bash
# Every file in the bad-input corpus, and every bad flag, must make rtrender print exactly
# one line "FILE: WHERE: WHAT" on stderr and exit with status 1: no crash, no hang,
# no image.
#   bad_input.sh RTRENDER CORPUS_DIR
set -u
rtrender=$1
corpus=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
cases=0

# check NAME EXPECTED_FILE_PREFIX [EXPECTED_WHERE] -- ARGS...
check() {
    local name=$1 file=$2 where="[^:]+"
    if [ "$3" != "--" ]; then where=$3; shift; fi
    shift 3
    cases=$((cases + 1))
    local status=0 start=$SECONDS
    timeout 20 "$rtrender" "$@" -o "$work/out.png" >"$work/stdout" 2>"$work/stderr" || status=$?
    local took=$((SECONDS - start))
    local lines
    lines=$(wc -l <"$work/stderr")
    local message
    message=$(cat "$work/stderr")
    if [ "$status" -ne 1 ]; then
        echo "FAIL $name: exit status $status, expected 1 ($message)"
    elif [ "$lines" -ne 1 ]; then
        echo "FAIL $name: $lines lines on stderr, expected 1:"; sed 's/^/    /' "$work/stderr"
    elif ! grep -Eq "^$file[^:]*: $where: .+$" "$work/stderr"; then
        echo "FAIL $name: not 'FILE: WHERE: WHAT' naming $file at $where: $message"
    elif [ -e "$work/out.png" ]; then
        echo "FAIL $name: wrote an image anyway"
    elif [ "$took" -gt 2 ]; then
        echo "FAIL $name: took ${took}s to refuse a bad file"
    else
        echo "ok   $name: $message"
        return
    fi
    failures=$((failures + 1))
}

# Each corpus file with the exact place its error must name.
where_of() {
    case $1 in
        binary_garbage.json) echo "line 1, column 1" ;;
        binary_garbage.obj) echo "byte 27" ;;
        deeply_nested.json) echo "\(document\)" ;;
        empty.json) echo "line 1" ;;
        huge_number.json) echo "line 3, column 45" ;;
        mesh_index_out_of_range.json) echo "line 5" ;;
        missing_mesh.json) echo "/objects/0/file" ;;
        misspelt_key.json) echo "/materials/shiny/reflectivty" ;;
        nan_literal.json) echo "line 3, column 44" ;;
        nan_vertex.obj) echo "line 2" ;;
        negative_radius.json) echo "/objects/0/radius" ;;
        singular_matrix.json) echo "/objects/0/transform" ;;
        trailing_comma.json) echo "line 4, column 36" ;;
        truncated.json) echo "line 4, column 27" ;;
        unknown_material.json) echo "/objects/0/material" ;;
        unknown_object_type.json) echo "/objects/0/type" ;;
        wrong_type.json) echo "/objects/0/radius" ;;
        zero_index.obj) echo "line 4" ;;
        zero_up.json) echo "/camera/up" ;;
        bom_zero_index.obj) echo "line 3" ;;
        gltf_accessor_out_of_range.gltf) echo "/accessors/0" ;;
        gltf_index_out_of_range.gltf) echo "/accessors/4" ;;
        gltf_missing_buffer.gltf) echo "load" ;;
        gltf_node_cycle.gltf) echo "/nodes/0" ;;
        gltf_required_extension.gltf) echo "/extensionsRequired" ;;
        gltf_truncated.glb) echo "load" ;;
        gltf_bad_image.gltf) echo "/images/0" ;;
        ply_truncated.ply) echo "element face" ;;
        stl_truncated.stl) echo "parse" ;;
        texture_missing.obj) echo "material \"broken\" map_Kd" ;;
        *) echo "UNLISTED" ;;  # a new corpus file must say where its error is
    esac
}
for path in "$corpus"/*.json "$corpus"/*.obj "$corpus"/*.gltf "$corpus"/*.glb "$corpus"/*.ply \
    "$corpus"/*.stl; do
    name=$(basename "$path")
    case $name in
        index_out_of_range.obj) continue ;;           # a part of mesh_index_out_of_range.json
        mesh_index_out_of_range.json) expected="$corpus/index_out_of_range.obj" ;;
        *) expected=$path ;;
    esac
    check "$name" "$expected" "$(where_of "$name")" -- "$path"
done

# Made here rather than committed: huge sparse files, and NUL bytes in a text file.
truncate -s 3G "$work/sparse.obj"
truncate -s 100M "$work/sparse.json"
printf 'v 0 0 0\n' >"$work/nul.obj" && truncate -s 1M "$work/nul.obj"
for f in sparse.obj sparse.json nul.obj; do check "$f" "$work/$f" -- "$work/$f"; done
# Paths with spaces and UTF-8: errors name them whole.
mkdir -p "$work/scènes avec espaces"
cp "$corpus/negative_radius.json" "$work/scènes avec espaces/sphère ü.json"
check "UTF-8 path with spaces" "$work/scènes avec espaces/sphère ü.json" -- "$work/scènes avec espaces/sphère ü.json"

scene="$corpus/../../../assets/scenes/tutorial.json"
check "missing scene file" "$work/none.json" -- "$work/none.json"
check "--size not WxH" "rtrender" -- "$scene" --size 640
check "--size zero" "rtrender" -- "$scene" --size 0x480
check "--threads 0" "rtrender" -- "$scene" --threads 0
check "--max-depth -1" "rtrender" -- "$scene" --max-depth -1
check "unknown flag" "rtrender" -- "$scene" --shadows-please
check "directory as scene" "$corpus" -- "$corpus"
check "--gl nonsense" "rtrender" -- "$scene" --mode raster --gl nonsense
check "--up nonsense" "rtrender" -- "$scene" --up w
check "--mode by number" "rtrender" -- "$scene" --mode 2
check "--accel nonsense" "rtrender" -- "$scene" --accel kdtree
# No EGL vendor library: EGL cannot start, and --gl egl allows no fallback.
export __EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json
check "no EGL" "rtrender" -- "$scene" --mode raster --gl egl
unset __EGL_VENDOR_LIBRARY_FILENAMES
export RTVIEW_SHADER_DIR=/nonexistent/shaders
check "missing shaders" "/nonexistent/shaders/raster.vert" -- "$scene" --mode raster
unset RTVIEW_SHADER_DIR
status=0
timeout 10 "$rtrender" "$scene" -o "$work/out.bmp" 2>"$work/stderr" || status=$?
cases=$((cases + 1))
if [ "$status" -ne 1 ] || ! grep -q "out.bmp: -o: unsupported format" "$work/stderr"; then
    echo "FAIL -o out.bmp: status $status: $(cat "$work/stderr")"
    failures=$((failures + 1))
fi

echo "$((cases - failures)) passed, $failures failed"
[ "$failures" -eq 0 ]
