#!/usr/bin/env bash
# rtview under a real X server (Xvfb): views, split divider, orbit and reset, a setting,
# the item buffer, saving, resizing, quick scene switches, and quitting. What is on
# screen is checked against rtrender's images of the same view.
#   viewer_test.sh RTVIEW RTRENDER SCENE_DIR BAD_SCENE
set -u
rtview=$1 rtrender=$2 scenes=$3 bad_scene=$4
source "$(dirname "$0")/lib.sh"

scene=$scenes/tutorial.json  # 4:3, so rtrender at 800x600 sees exactly the window's view
W=800 H=600
"$rtrender" "$scene" --mode both --size ${W}x$H -q -o "$work/ref.png"
"$rtrender" "$scene" --size ${W}x$H -q --no-shadows -o "$work/ref_noshadow.png"
"$rtrender" "$scene" --mode explain --size ${W}x$H -q -o "$work/ref.png"
"$rtrender" "$scene" --mode gputrace --size ${W}x$H -q -o "$work/ref.gputrace.png"
convert "$work/ref.explain.png" -crop ${W}x$H+0+0 +repage "$work/ref.why.png"  # the legend strip off
# Where the panel's check boxes are (its layout is fixed: ray-tracer settings first).
SHADOWS="27 130" ITEM_BUFFER="27 153" MAX_DEPTH="120 176" RESOLUTION="120 199"
OPEN_FIELD="100 69"

# The scene picker's folder: the real scenes plus one that cannot load.
mkdir -p "$work/assets/scenes"
cp "$scenes"/*.json "$work/assets/scenes/"
ln -s "$(cd "$scenes/../models" && pwd)" "$work/assets/models"
cp "$bad_scene" "$work/assets/scenes/zz_broken.json"
export RTVIEW_ASSET_DIR=$work/assets

start_xvfb
# --spp 1: the checks below compare with rtrender's one-sample images (anti-aliasing has
# its own check at the end).
start_app "$rtview" "$scene" --size ${W}x$H --view raster --save-dir "$work/saves" --spp 1
wait_for_window "^rtview - " || exit 1
wait_for_log "^traced:" 1 || exit 1

# H hides the panel; the labels stay (they name what is shown) until L hides them too.
key h
settle
grab labelled
check "with the panel hidden the view is still labelled" at_least 150 "$work/labelled.png" "$work/ref.raster.png"
# Views, with the panel and labels hidden so the whole window is the view.
key l
settle
grab raster
check "raster view shows rtrender's raster image" at_most 100 "$work/raster.png" "$work/ref.raster.png"
after "^view: traced" key 2 && settle
grab traced
check "traced view shows rtrender's traced image" at_most 100 "$work/traced.png" "$work/ref.trace.png"
check "raster and traced differ where the shadows fall" at_least 3000 "$work/ref.raster.png" "$work/ref.trace.png"
check "  ... and so do the two views on screen" at_least 3000 "$work/raster.png" "$work/traced.png"
# Key 7: the GPU tracer's image (a compute shader on the window's own context), the image
# rtrender --mode gputrace makes of the view.
after "^view: GPU traced" key 7 && settle
grab gputraced
check "GPU traced view shows rtrender --mode gputrace's image" at_most 100 "$work/gputraced.png" "$work/ref.gputrace.png"
check "  ... which is the traced image" at_most 100 "$work/gputraced.png" "$work/traced.png"

# Split view: drag the divider from the middle to x = 600.
after "^view: split" key 3 && settle
drag 1 400 300 600 300
settle
grab split
check "split: raster left of the divider" at_most 100 "$work/split.png" "$work/raster.png" 590x$H+0+0
check "split: traced right of the divider" at_most 100 "$work/split.png" "$work/traced.png" 190x$H+610+0
check "split: the divider moved (its left part is not traced)" at_least 2000 "$work/split.png" "$work/traced.png" 590x$H+0+0
after "^swap:" key x && settle
grab swapped
check "X swaps the sides" at_most 100 "$work/swapped.png" "$work/traced.png" 590x$H+0+0

# Holding Tab flickers between raster and traced.
after "^flicker: on" xdotool keydown Tab
# Grabs until both have been seen (up to 30: a loaded machine draws fewer frames).
seen_raster=0 seen_traced=0
for i in $(seq 30); do
    grab flicker
    at_most 100 "$work/flicker.png" "$work/raster.png" >/dev/null && seen_raster=1
    at_most 100 "$work/flicker.png" "$work/traced.png" >/dev/null && seen_traced=1
    [ $seen_raster$seen_traced = 11 ] && break
    sleep 0.13
done
after "^flicker: off" xdotool keyup Tab
check "holding Tab shows raster and traced in turn" test $seen_raster$seen_traced = 11

# The difference and item-buffer views.
after "^view: difference" key 4 && settle
grab diff
check "difference view is neither image" at_least 20000 "$work/diff.png" "$work/raster.png"
convert -size ${W}x$H xc:black "$work/black.png"
check "  ... and is black where they agree" at_most 100 "$work/diff.png" "$work/black.png" 200x100+600+0
"$rtrender" "$scene" --mode itembuffer --size ${W}x$H -q -o "$work/ref.ids.png"
after "^view: item buffer" key 5 && settle
grab ids
check "item-buffer view shows the object ids" at_most 100 "$work/ids.png" "$work/ref.ids.png"
# The why view: the tracer starts again in parts; at full resolution it is rtrender's map.
traced=$(log_count "^traced:")
after "^view: why" key 6
wait_for_log "^traced:" $((traced + 1)) && settle
grab why
check "why view shows rtrender's explain map" at_most 100 "$work/why.png" "$work/ref.why.png"
after "^view: split" key 3 && settle

# Save: the view and the raster, traced and difference images behind it.
after "^saved: .*diff.png" key F12
check "saved four files" test -s "$work/saves/rtview-1.view.png" -a -s "$work/saves/rtview-1.raster.png" \
    -a -s "$work/saves/rtview-1.trace.png" -a -s "$work/saves/rtview-1.diff.png"
check "saved view matches the window" at_most 20 "$work/saves/rtview-1.view.png" "$work/swapped.png"
check "saved traced image is rtrender's" at_most 20 "$work/saves/rtview-1.trace.png" "$work/ref.trace.png"
check "saved raster image is rtrender's" at_most 20 "$work/saves/rtview-1.raster.png" "$work/ref.raster.png"
# The saved difference shows exactly where the saved raster and traced images differ: its
# lit pixels (the colour bar cropped off) about as many as the pixels that differ.
convert "$work/saves/rtview-1.diff.png" -crop "${W}x$H+0+0" +repage "$work/saved_diff.png"
lit=$(convert "$work/saved_diff.png" -colorspace gray -threshold 2% -format "%[fx:round(mean*w*h)]" info:)
differ=$(compare -metric AE -fuzz 1% "$work/saves/rtview-1.raster.png" "$work/saves/rtview-1.trace.png" null: 2>&1 || true)
check "saved difference lights the $differ differing pixels ($lit lit)" \
    test "${differ%.*}" -gt 1000 -a "$lit" -gt "$((${differ%.*} / 2))" -a "$lit" -lt "$((${differ%.*} * 2))"

# From any view: the raster view saves the traced and difference images too, and the
# window shows where the files went (absolute paths) for a few seconds.
after "^view: raster" key 1 && settle
after "^saved: .*diff.png" key F12
settle
grab saved_message
check "saving from the raster view writes all four" test -s "$work/saves/rtview-2.view.png" -a \
    -s "$work/saves/rtview-2.trace.png" -a -s "$work/saves/rtview-2.diff.png"
check "  ... the log names absolute paths" grep -q "^saved: $work/saves/rtview-2.trace.png" "$work/app.log"
check "  ... and so does the window" at_least 500 "$work/saved_message.png" "$work/raster.png"
sleep 6  # the message goes

# Orbit, then reset: the view changes, and R brings back the first one.
after "^view: raster" key 1 && settle
after "^traced:" drag 1 300 300 420 260 && settle
grab orbited
check "orbiting changes the view" at_least 5000 "$work/orbited.png" "$work/raster.png"
# The title says whether the traced image is the current camera's: "tracing" from the
# moment the camera moves, "traced" once the full-resolution image of it is in.
check "at rest after the orbit the title says traced ($(xdotool getwindowname "$wid"))" \
    grep -q -- "- traced$" <(xdotool getwindowname "$wid")
traced_before=$(log_count "^traced:")
drag 1 300 300 330 300
for _ in $(seq 30); do  # at once here; up to 3 s on a loaded machine
    title=$(xdotool getwindowname "$wid")
    grep -q -- "- tracing$" <<<"$title" && break
    sleep 0.1
done
check "right after another orbit it says tracing ($title)" grep -q -- "- tracing$" <<<"$title"
wait_for_log "^traced:" $((traced_before + 1))
settle
check "  ... and traced once the full trace is in" grep -q -- "- traced$" <(xdotool getwindowname "$wid")
after "^traced:" drag 3 300 300 340 330 && settle
grab panned
check "panning (right drag) changes the view" at_least 5000 "$work/panned.png" "$work/orbited.png"
after "^traced:" key r && settle
grab reset
check "R resets the camera" at_most 100 "$work/reset.png" "$work/raster.png"

# A setting: untick "shadows" in the panel; the traced view loses its shadows.
key h l
settle
after "^traced:" click $SHADOWS
key h l
after "^view: traced" key 2 && settle
grab noshadow
check "shadows off in the panel: the traced view has none" at_most 100 "$work/noshadow.png" "$work/ref_noshadow.png"

# The item buffer: tick it; the tracer reports what it saved and how many pixels differ.
key h l
settle
after "^item buffer:" click $ITEM_BUFFER
line=$(grep "^item buffer:" "$work/app.log" | tail -n1)
disagree=$(echo "$line" | sed -n 's/.*, \([0-9]*\) of \([0-9]*\) pixels disagree.*/\1 \2/p')
check "item buffer on: at most 0.1% of pixels disagree ($line)" \
    test -n "$disagree" -a "$(echo "$disagree" | awk '{print ($1 <= $2 / 1000)}')" = 1
# Where the raster is on screen (the split view), its pass draws the ids with its colours:
# once the camera has moved and rests, the item buffer is read back from that pass.
key h l  # the panel out of the way of the drag
after "^view: split" key 3 && settle
shared=$(log_count "^item buffer: read back from the raster pass")
drag 1 450 300 465 300
check "split view: the item buffer is read back from the raster pass" \
    wait_for_log "^item buffer: read back from the raster pass" $((shared + 1)) 30
line=$(grep "^item buffer:" "$work/app.log" | tail -n1)
disagree=$(echo "$line" | sed -n 's/.*, \([0-9]*\) of \([0-9]*\) pixels disagree.*/\1 \2/p')
check "  ... and at most 0.1% of pixels disagree ($line)" \
    test -n "$disagree" -a "$(echo "$disagree" | awk '{print ($1 <= $2 / 1000)}')" = 1
after "^traced:" key r && settle
after "^view: traced" key 2 && settle
key h l

# Resizing (down to 1x1, up to 4K), hiding the window, and quick scene switches never crash.
for size in "1 1" "3840 2160" "1200 300" "200 900" "$W $H"; do xdotool windowsize "$wid" $size; sleep 0.3; done
xdotool windowunmap "$wid"; sleep 0.5; xdotool windowmap "$wid"; sleep 0.3
# Back at its size, the window shows the traced view again, whole: wait for it (up to
# 15 s) rather than trusting a sleep, and compare with rtrender's image of it.
key h l  # hide the panel and labels, as when the reference was grabbed
redrawn=1
for _ in $(seq 30); do
    sleep 0.5
    grab resized
    if at_most 600 "$work/resized.png" "$work/ref_noshadow.png" >/dev/null; then redrawn=0; break; fi
done
check "after the resizes the traced view is drawn again at ${W}x$H" test "$redrawn" -eq 0
check "  ... at its size" test "$(identify -format %wx%h "$work/resized.png")" = "${W}x$H"
key h l
# The panel is back where it was (it used to be left off-screen after the 1 x 1 resize):
# a click on its shadows box reaches it.
settle
after "^trace settings:" click $SHADOWS
check "after the resizes the panel is where it was" \
    grep -q "shadows on" <(grep "^trace settings:" "$work/app.log" | tail -n1)
after "^scene:" key Next Next Next Next Next Next Next Prior
after "^traced:" true
check "still running after resizes, unmapping and scene switches" kill -0 "$app_pid"

# A scene that does not load, at run time: the error is reported and the scene kept.
# (The picker and PageDown go through the same loading as a dropped file.)
errors=$(log_count "radius: must be > 0")
scene_count=$(ls "$work/assets/scenes"/*.json | wc -l)
for _ in $(seq "$scene_count"); do after "^scene:\|radius: must be > 0" key Next; done  # one is broken
check "a broken scene at run time is reported" test "$(log_count "radius: must be > 0")" -gt "$errors"
check "  ... and the viewer keeps running" kill -0 "$app_pid"
# F5 reads the scene on screen again (a broken one asked for before is not it).
shown=$(grep "^scene:" "$work/app.log" | tail -n1 | cut -d' ' -f2)
loaded=$(log_count "^scene:")
after "^scene:" key F5
check "F5 reads the scene shown again ($shown)" test "$(log_count "^scene:")" -gt "$loaded" -a \
    "$(grep "^scene:" "$work/app.log" | tail -n1 | cut -d' ' -f2)" = "$shown"
# The panel's path field opens any file: a click in it, the start of a path, Tab to
# complete it, Enter to open. Typed at once after the click, while a frame is slow (the
# viewer stopped): the first characters used to be taken as the viewer's keys, as the
# field is not being edited until ImGui's next frame has seen the click.
in_one_slow_frame xdotool mousemove --window "$wid" $OPEN_FIELD click 1 \
    type --delay 5 "$work/assets/scenes/tutor"
after "^scene: .*tutorial.json" xdotool key --delay 100 Tab Return
check "a path typed in the panel (Tab completed) opens the scene" \
    grep -q "^scene: $work/assets/scenes/tutorial.json" <(grep "^scene:" "$work/app.log" | tail -n1)

# With the panel focused by a click, Tab then a digit: the digit switches the view; it is
# never typed into a slider that Tab focused (it used to go into the threads slider).
after "^traced:" click $SHADOWS  # (the panel is shown) ImGui's focus is on it
xdotool keydown Tab; sleep 1.5; after "^flicker: off" xdotool keyup Tab  # held: it repeats
splits=$(log_count "^view: split")
key 3
wait_for_log "^view: split" $((splits + 1)) 5
check "Tab then 3 with the panel focused: the view changes" test "$(log_count "^view: split")" -gt "$splits"
# The traced view: it follows each change at once (the raster view waits for a rest).
after "^view: traced" key 2

# A value typed into a slider (Ctrl+click, type, Enter) is clamped to the slider's range.
# (The same at once, in one slow frame: the keys go to the field the click opened.)
after "^trace settings:" in_one_slow_frame xdotool mousemove --window "$wid" $MAX_DEPTH \
    keydown ctrl click 1 keyup ctrl key --delay 5 BackSpace BackSpace BackSpace 5 4 Return
check "max depth typed as 54 becomes 12 ($(grep "^trace settings:" "$work/app.log" | tail -n1))" \
    grep -q "max depth 12," <(grep "^trace settings:" "$work/app.log" | tail -n1)

# Clicks on the shadows box far faster than frames come: each one counts. They reach the
# panel one change a frame, so each toggle starts a trace and logs its settings.
# toggles DESCRIPTION N XDOTOOL_ARGS...: the clicks, then N new settings lines (once no
# new line has come for two seconds), the last one N toggles away from the first.
toggles() {
    local what=$1 n=$2 before expected lines_before lines now
    shift 2
    settle
    before=$(grep "^trace settings:" "$work/app.log" | tail -n1 | sed -n 's/.*shadows \(o[nf]*\),.*/\1/p')
    expected=$before
    [ $((n % 2)) = 1 ] && { expected=on; [ "$before" = on ] && expected=off; }
    lines_before=$(log_count "^trace settings:")
    xdotool mousemove --window "$wid" $SHADOWS "$@"
    lines=-1
    for _ in $(seq 40); do
        sleep 1
        now=$(log_count "^trace settings:")
        [ "$now" = "$lines" ] && break
        lines=$now
        sleep 1
    done
    check "$what: $n toggles ($((lines - lines_before)) settings lines)" test "$((lines - lines_before))" -eq "$n"
    check "  ... and shadows end $expected ($(grep "^trace settings:" "$work/app.log" | tail -n1))" \
        grep -q "shadows $expected," <(grep "^trace settings:" "$work/app.log" | tail -n1)
}
# Two clicks within one frame used to count once.
toggles "nine quick clicks" 9 click --repeat 9 --delay 1 1
# A release that reaches the window with the next click's press, that click held: ImGui
# 1.86's back-end read the button as GLFW last saw it (held), so the first click's release
# never reached the panel and the two clicks made one toggle (lost on a fast machine).
toggles "a release with the next press" 2 mousedown 1 mouseup 1 mousedown 1 sleep 0.5 mouseup 1
after "^trace settings:" click $SHADOWS

# The difference at a quarter of the window's resolution compares like with like: the
# raster is drawn at the traced image's size, so with shadows off (the tutorial scene,
# opened by the path field above, then has little the raster lacks) next to nothing
# lights up, at full resolution or at a quarter (not every edge of a blocky trace against
# a sharp raster).
lit() { convert "$1" -crop "$((W - 50))x$H+0+0" -colorspace gray -threshold 2% -format "%[fx:round(mean*w*h)]" info:; }
if grep -q "shadows on" <(grep "^trace settings:" "$work/app.log" | tail -n1); then
    after "^trace settings:" click $SHADOWS
fi
after "^view: difference" key 4
key h l && settle
grab diff_full
key h l && settle
xdotool mousemove --window "$wid" $RESOLUTION keydown ctrl click 1 keyup ctrl
sleep 0.3
after "^traced: $((W / 4))x$((H / 4))" key BackSpace BackSpace BackSpace BackSpace BackSpace BackSpace 0 period 2 5 Return
key h l && settle
grab diff_quarter
key h l && settle
full=$(lit "$work/diff_full.png") quarter=$(lit "$work/diff_quarter.png")
check "difference of $(basename "$(grep "^scene:" "$work/app.log" | tail -n1 | cut -d' ' -f2)") at 1/4 resolution lights next to nothing ($quarter pixels; $full at full)" \
    test "$full" -lt 300 -a "$quarter" -lt 600
xdotool mousemove --window "$wid" $RESOLUTION keydown ctrl click 1 keyup ctrl
sleep 0.3
after "^traced: ${W}x$H" key BackSpace BackSpace BackSpace BackSpace BackSpace BackSpace 1 Return

# One Esc asks; a second within two seconds quits.
after "^Esc: press Esc again" key Escape
sleep 0.5
check "one Esc does not quit" kill -0 "$app_pid"
key Escape
for _ in $(seq 50); do kill -0 "$app_pid" 2>/dev/null || break; sleep 0.1; done
status=0
if kill -0 "$app_pid" 2>/dev/null; then status=124; else wait "$app_pid" || status=$?; fi
app_pid=""
check "a second Esc quits with status 0" test "$status" -eq 0

# Without a display, or with a bad scene: one line, status 1.
out=$(env -u DISPLAY -u WAYLAND_DISPLAY "$rtview" "$scene" 2>&1); status=$?
check "no display: one line, exit 1 ($out)" test "$status" -eq 1 -a "$(echo "$out" | wc -l)" -eq 1
check "  ... which points to rtrender" grep -q rtrender <<<"$out"
out=$("$rtview" "$bad_scene" 2>&1); status=$?
check "bad scene: one line, exit 1 ($out)" test "$status" -eq 1 -a "$(echo "$out" | wc -l)" -eq 1

# Anti-aliasing: once at full resolution the traced view refines to 4 samples per pixel,
# and then it is rtrender --spp 4's image.
"$rtrender" "$scene" --size ${W}x$H -q --spp 4 -o "$work/ref_spp4.png"
start_app "$rtview" "$scene" --size ${W}x$H --view trace --spp 4
wait_for_window "^rtview - " && wait_for_log "^antialiased: ${W}x$H at 4 samples" 1 || exit 1
key h l
settle
grab spp4
check "anti-aliased traced view is rtrender --spp 4's image" at_most 100 "$work/spp4.png" "$work/ref_spp4.png"
check "  ... which differs from one sample per pixel" at_least 500 "$work/ref_spp4.png" "$work/ref.trace.png"
kill "$app_pid" 2>/dev/null
wait "$app_pid" 2>/dev/null
app_pid=""

# A pixel's rays (whitted.json: its mirror ball is left of the middle). Ctrl+click on the
# ball: the reflected ray, in its sky blue, starts at the clicked pixel (where the primary
# ray hit the ball) and leaves it; it stays drawn while the camera orbits; Esc clears it.
blue() {  # blue IMAGE [GEOMETRY]: how many pixels have the reflection's colour
    convert "$1" ${2:+-crop "$2" +repage} -fuzz 0.5% -fill white -opaque "rgb(86,180,233)" \
        -fill black +opaque white -format "%[fx:round(mean*w*h)]" info:
}
start_app "$rtview" "$scenes/whitted.json" --size ${W}x$H --view raster --spp 1
wait_for_window "^rtview - " && wait_for_log "^traced:" 1 || exit 1
key h l
settle
grab rays_before
after "^picked:" xdotool mousemove --window "$wid" 200 250 keydown ctrl click 1 keyup ctrl
settle
grab rays_picked
picked=$(grep "^picked:" "$work/app.log" | tail -n1)
check "Ctrl+click traces the pixel's rays ($picked)" grep -q "^picked: pixel 200,250 .* [1-9][0-9]* bounce" <<<"$picked"
check "  ... the reflected ray is drawn ($(blue "$work/rays_picked.png") pixels, $(blue "$work/rays_before.png") before)" \
    test "$(blue "$work/rays_picked.png")" -gt $(($(blue "$work/rays_before.png") + 300))
check "  ... from the clicked pixel ($(blue "$work/rays_picked.png" 13x13+194+244) pixels within 6 of it)" \
    test "$(blue "$work/rays_picked.png" 13x13+194+244)" -gt 3
after "^traced:" drag 1 500 500 600 480
settle
grab rays_orbited
check "  ... and still drawn after an orbit ($(blue "$work/rays_orbited.png") pixels)" \
    test "$(blue "$work/rays_orbited.png")" -gt 1000
check "  ... seen from elsewhere" at_least 2000 "$work/rays_orbited.png" "$work/rays_picked.png"
key Escape
settle
grab rays_cleared
check "Esc clears them ($(blue "$work/rays_cleared.png") pixels left)" \
    test "$(blue "$work/rays_cleared.png")" -lt $(($(blue "$work/rays_orbited.png") / 10))
kill "$app_pid" 2>/dev/null
wait "$app_pid" 2>/dev/null
app_pid=""

finish
