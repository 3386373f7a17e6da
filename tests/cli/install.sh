#!/usr/bin/env bash
# The installed programs run from wherever they are installed: `cmake --install` into a
# scratch prefix, and the Debian package (cpack -G DEB) unpacked into a scratch root,
# each render a scene with its own shaders and assets, the images the build tree's.
#   install.sh BUILD_DIR SOURCE_DIR OUT_DIR
set -u
build=$1 source=$2 out=$3
rm -rf "$out"
mkdir -p "$out"
unset RTVIEW_SHADER_DIR RTVIEW_ASSET_DIR
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }
ok() { echo "ok   $*"; }

"$build/app/render/rtrender" "$source/assets/scenes/tutorial.json" --mode both --size 160x120 -q \
    -o "$out/reference.png" || fail "the build tree's rtrender"

# Renders with the programs under PREFIX, from another working folder; NAME labels it.
renders_like_the_build() {
    local prefix=$1 name=$2
    for p in rtrender rtbench; do
        [ -x "$prefix/bin/$p" ] || fail "$name: no $prefix/bin/$p"
        # In its constant data, where a compiled-in path would be. (Debug information
        # names source files, and so do the sanitizers' reports: not paths it reads.)
        if grep -q -a -e __asan_init -e __ubsan_handle -e __tsan_init "$prefix/bin/$p"; then
            echo "skip $name: $p is instrumented, its source paths are the sanitizer's"
            continue
        fi
        objcopy -O binary --only-section=.rodata "$prefix/bin/$p" "$out/$p.rodata"
        if grep -q -a -F "$source" "$out/$p.rodata"; then
            fail "$name: $p holds the source tree's path $source"
        else
            ok "$name: $p holds no path of the source tree"
        fi
    done
    (cd / && "$prefix/bin/rtrender" "$prefix/share/rtview/assets/scenes/tutorial.json" --mode both \
        --size 160x120 -q -o "$out/$name.png") || { fail "$name: rtrender failed"; return; }
    for image in raster trace; do
        if idiff -q -fail 0 -failpercent 0 "$out/$name.$image.png" "$out/reference.$image.png"; then
            ok "$name: the $image image is the build tree's"
        else
            fail "$name: the $image image differs from the build tree's"
        fi
    done
    # Its image codec (lib/rtview, opened when a file other than a PNG is read or written)
    # is the installed one: an EXR is written with it; without it a PNG still is, and the
    # EXR's failure is one line naming where the codec should be.
    "$prefix/bin/rtrender" "$prefix/share/rtview/assets/scenes/tutorial.json" --mode trace \
        --size 16x16 -q -o "$out/$name.exr" && [ -s "$out/$name.exr" ] &&
        ok "$name: it writes EXR through its codec" || fail "$name: no EXR through its codec"
    mv "$prefix/lib/rtview" "$prefix/lib/rtview.away"
    msg=$("$prefix/bin/rtrender" "$prefix/share/rtview/assets/scenes/tutorial.json" --mode trace \
        --size 16x16 -q -o "$out/$name.none.exr" 2>&1)
    status=$?
    "$prefix/bin/rtrender" "$prefix/share/rtview/assets/scenes/tutorial.json" --mode trace \
        --size 16x16 -q -o "$out/$name.nocodec.png" || fail "$name: no PNG without the codec"
    mv "$prefix/lib/rtview.away" "$prefix/lib/rtview"
    if [ $status -eq 1 ] && [ "$(wc -l <<<"$msg")" -eq 1 ] &&
        grep -q -F "$prefix/lib/rtview/librtview_image_oiio.so" <<<"$msg"; then
        ok "$name: it opens the installed codec ($msg)"
    else
        fail "$name: without the installed codec: status $status, '$msg'"
    fi
    # Its shaders are the installed ones: without them it says which file it could not read.
    mv "$prefix/share/rtview/shaders" "$prefix/share/rtview/shaders.away"
    msg=$("$prefix/bin/rtrender" "$prefix/share/rtview/assets/scenes/tutorial.json" --mode raster \
        --size 16x16 -q -o "$out/$name.none.png" 2>&1)
    status=$?
    mv "$prefix/share/rtview/shaders.away" "$prefix/share/rtview/shaders"
    if [ $status -eq 1 ] && grep -q -F "$prefix/share/rtview/shaders" <<<"$msg"; then
        ok "$name: it reads the installed shaders ($msg)"
    else
        fail "$name: without the installed shaders: status $status, '$msg'"
    fi
}

cmake --install "$build" --prefix "$out/prefix" >"$out/install.log" 2>&1 || fail "cmake --install: $(tail -3 "$out/install.log")"
renders_like_the_build "$out/prefix" installed

if cpack -G DEB --config "$build/CPackConfig.cmake" -B "$out/package" >"$out/cpack.log" 2>&1; then
    deb=$(ls "$out"/package/rtview_*.deb)
    depends=$(dpkg-deb -f "$deb" Depends)
    for lib in libopenimageio libpng16 libegl1 libosmesa6 libegl-mesa0; do
        if grep -q "$lib" <<<"$depends"; then ok "package depends on $lib"; else fail "package does not depend on $lib: $depends"; fi
    done
    dpkg-deb -x "$deb" "$out/root"
    renders_like_the_build "$out/root/usr" package
else
    fail "cpack -G DEB: $(tail -3 "$out/cpack.log")"
fi
[ $failures -eq 0 ] && echo "all install checks passed"
exit $((failures > 0))
