#!/usr/bin/env bash
# OpenImageIO (its 261 shared libraries: 0.26-0.38 s of every process start) is loaded
# only when an image other than a PNG is read or written (core/image_codec.h):
#   - no program, nor the test programs, needs it to start (ldd);
#   - rtrender's --help, a bad scene's one-line error, a render to PNG and a scene whose
#     textures are PNG or JPEG never load it (the dynamic linker's own account,
#     LD_DEBUG=files), nor does rtview's --help;
#   - an EXR, and a CMYK JPEG texture (left to the codec), do: the check above can see it.
#   image_codec.sh ASSETS_DIR TEST_DATA_DIR BAD_SCENE PROGRAM...   (rtrender first)
set -u
assets=$1 data=$2 bad=$3
shift 3
rtrender=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }
ok() { echo "ok   $*"; }

for program in "$@"; do
    if ldd "$program" | grep -q OpenImageIO; then
        fail "$(basename "$program") links OpenImageIO: $(ldd "$program" | grep OpenImageIO | head -1)"
    else
        ok "$(basename "$program") links no OpenImageIO"
    fi
done

# loads NAME YES|NO COMMAND...: whether COMMAND's process opened libOpenImageIO.
loads() {
    local name=$1 expected=$2
    shift 2
    LD_DEBUG=files LD_DEBUG_OUTPUT="$work/ld" "$@" >/dev/null 2>&1
    local found=NO
    if grep -q "file=libOpenImageIO\.so" "$work"/ld.* 2>/dev/null; then found=YES; fi
    rm -f "$work"/ld.*
    if [ "$found" = "$expected" ]; then
        ok "$name: OpenImageIO loaded: $found"
    else
        fail "$name: OpenImageIO loaded: $found, expected $expected"
    fi
}
scene=$assets/scenes/tutorial.json
loads "rtrender --help" NO "$rtrender" --help
loads "a bad scene's error" NO "$rtrender" "$bad" -o "$work/bad.png"
loads "a render to PNG" NO "$rtrender" "$scene" --size 32x24 -q -o "$work/t.png"
[ -s "$work/t.png" ] || fail "no PNG written"
loads "a render to EXR" YES "$rtrender" "$scene" --size 32x24 -q -o "$work/t.exr"
[ -s "$work/t.exr" ] || fail "no EXR written"
loads "a scene with PNG textures" NO "$rtrender" "$assets/scenes/textured.json" --size 32x24 -q -o "$work/x.png"
[ -s "$work/x.png" ] || fail "no PNG written for the textured scene"
loads "a JPEG texture" NO "$rtrender" "$data/jpeg/quad.obj" --size 32x24 -q -o "$work/j.png"
[ -s "$work/j.png" ] || fail "no PNG written for the JPEG-textured model"
loads "a CMYK JPEG texture" YES "$rtrender" "$data/jpeg/cmyk_quad.obj" --size 32x24 -q -o "$work/c.png"
[ -s "$work/c.png" ] || fail "no PNG written for the CMYK-textured model"
for program in "$@"; do
    case $(basename "$program") in
        rtview) loads "rtview --help" NO "$program" --help ;;
    esac
done

[ $failures -eq 0 ] && echo "all image codec checks passed"
exit $((failures > 0))
