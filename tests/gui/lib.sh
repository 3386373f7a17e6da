#!/usr/bin/env bash
# Helpers for rtview's GUI tests: a private Xvfb, the window, input, grabs, pixel checks.
# The tests wait on what rtview shows or says (its log lines, its window), and sleep
# only briefly after that, to let the next frame reach the screen.

work=$(mktemp -d)
xvfb_pid=""
app_pid=""
failures=0
checks=0

cleanup() {
    [ -n "$app_pid" ] && kill "$app_pid" 2>/dev/null
    [ -n "$xvfb_pid" ] && kill "$xvfb_pid" 2>/dev/null
    wait 2>/dev/null
    if [ "$failures" -eq 0 ] && [ -z "${RTVIEW_KEEP_GRABS:-}" ]; then rm -rf "$work"; else echo "grabs and logs kept in $work"; fi
}
trap cleanup EXIT

fail() { echo "FAIL $*"; failures=$((failures + 1)); }
ok() { echo "ok   $*"; }
check() {  # check DESCRIPTION COMMAND...
    checks=$((checks + 1))
    local what=$1
    shift
    if "$@"; then ok "$what"; else fail "$what"; fi
}

start_xvfb() {  # a display of our own: Xvfb picks a free number and tells it on fd 3
    exec 4>"$work/display"
    Xvfb -displayfd 4 -screen 0 3840x2160x24 -nolisten tcp >"$work/xvfb.log" 2>&1 &
    xvfb_pid=$!
    for _ in $(seq 100); do [ -s "$work/display" ] && break; sleep 0.1; done
    [ -s "$work/display" ] || { echo "Xvfb did not start: $(cat "$work/xvfb.log")"; exit 1; }
    export DISPLAY=":$(head -n1 "$work/display")"
}

start_app() {  # start_app COMMAND...: runs it with its output in $work/app.log
    "$@" >"$work/app.log" 2>&1 &
    app_pid=$!
}

log_count() { grep -c -- "$1" "$work/app.log" 2>/dev/null || true; }

wait_for_log() {  # wait_for_log PATTERN COUNT [SECONDS]: until PATTERN has appeared COUNT times
    local pattern=$1 count=$2 seconds=${3:-60}
    for _ in $(seq $((seconds * 10))); do
        [ "$(log_count "$pattern")" -ge "$count" ] && return 0
        kill -0 "$app_pid" 2>/dev/null || { echo "the application exited: $(tail -5 "$work/app.log")"; return 1; }
        sleep 0.1
    done
    echo "timed out waiting for '$pattern' x$count; log:"
    tail -20 "$work/app.log"
    return 1
}

after() {  # after PATTERN ACTION...: do ACTION, then wait for one more PATTERN line than before
    local pattern=$1 before
    shift
    before=$(log_count "$pattern")
    "$@"
    wait_for_log "$pattern" $((before + 1))
}

wait_for_window() {  # wait_for_window NAME_REGEX: sets $wid
    # 60 s: beside the other tests a fresh viewer once showed none in 30 s (CI of da10252,
    # the main suite; it passed under AddressSanitizer in the same run).
    for _ in $(seq 600); do
        wid=$(xdotool search --name "$1" 2>/dev/null | head -n1)
        [ -n "$wid" ] && return 0
        # An application that has exited will show no window: say so at once, with its log.
        if [ -n "${app_pid:-}" ] && ! kill -0 "$app_pid" 2>/dev/null; then
            echo "no window named '$1': the application exited; log:"
            tail -20 "$work/app.log"
            return 1
        fi
        sleep 0.1
    done
    # What a later reader needs to tell a slow start from a hung one.
    echo "no window named '$1' after 60 s; the application is still running; windows:"
    xdotool search --name . getwindowname %@ 2>/dev/null | head -10
    echo "its log:"
    tail -20 "$work/app.log"
    return 1
}

settle() { sleep 0.6; }  # after an observed change: a few frames reach the screen
key() { xdotool windowfocus --sync "$wid" 2>/dev/null; xdotool key --delay 30 "$@"; }
drag() {  # drag BUTTON X0 Y0 X1 Y1 (window coordinates)
    xdotool mousemove --window "$wid" "$2" "$3" mousedown "$1"
    for i in 1 2 3 4 5; do
        xdotool mousemove --window "$wid" $(($2 + ($4 - $2) * i / 5)) $(($3 + ($5 - $3) * i / 5))
        sleep 0.05
    done
    xdotool mouseup "$1"
}
click() { xdotool mousemove --window "$wid" "$1" "$2" click 1; }
# in_one_slow_frame COMMAND...: the input COMMAND sends reaches the viewer all at once, as
# when a frame is slow: the viewer is stopped while it is sent.
in_one_slow_frame() {
    kill -STOP "$app_pid"
    "$@"
    sleep 0.2  # the X server has passed it on
    kill -CONT "$app_pid"
}
grab() { import -window "$wid" "$work/$1.png"; }

# differing PIXELS A B [GEOMETRY]: how many pixels differ by more than 3% (in a crop)
differing() {
    local a=$1 b=$2 crop=${3:-}
    if [ -n "$crop" ]; then
        convert "$a" -crop "$crop" +repage "$work/crop_a.png"
        convert "$b" -crop "$crop" +repage "$work/crop_b.png"
        a="$work/crop_a.png" b="$work/crop_b.png"
    fi
    compare -metric AE -fuzz 3% "$a" "$b" null: 2>&1 | cut -d' ' -f1
}
# at_most N A B [GEOMETRY]: the images differ in at most N pixels
at_most() { local n; n=$(differing "$2" "$3" "${4:-}"); [ "${n%.*}" -le "$1" ] || { echo "    $n pixels differ"; false; }; }
at_least() { local n; n=$(differing "$2" "$3" "${4:-}"); [ "${n%.*}" -ge "$1" ] || { echo "    only $n pixels differ"; false; }; }

finish() {
    echo "$((checks - failures)) passed, $failures failed"
    [ "$failures" -eq 0 ]
}
