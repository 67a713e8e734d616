#!/usr/bin/env bash
# viewer_xvfb_move.sh - rt-view's camera moves on a real X server (Xvfb),
# driven by xdotool, on a copy of scenes/cubes.scn: a left drag (orbit),
# then a wheel notch (dolly), each changes what the window shows (the
# screenshots' checksums once each render is done); C prints the camera as
# rt-export options; rt-export with them writes an image equal, byte for
# byte (both converted to raw RGB), to the one S saves in the viewer.
# Prints how long each step took.  Exits 77 (skipped) without Xvfb,
# xdotool, or a way to take a screenshot (xwd with ImageMagick's convert,
# or ImageMagick's import).
#
# Environment: RT_VIEW, RT_EXPORT (the binaries), RT_SOURCE_DIR.
set -u
. "$(dirname "$0")/xvfb_session.sh"

if command -v xwd >/dev/null 2>&1 && command -v convert >/dev/null 2>&1; then
    # screenshot FILE: the window's pixels as raw RGB
    screenshot() { xwd -silent -id "$window" | convert xwd:- rgb:"$1"; }
elif command -v import >/dev/null 2>&1; then
    screenshot() { import -silent -window "$window" rgb:"$1"; }
else
    echo "skipped: neither xwd with convert nor import takes screenshots"
    exit 77
fi
command -v convert >/dev/null 2>&1 || {
    echo "skipped: ImageMagick's convert is not installed"; exit 77; }

now() { date +%s.%N; }
since() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.2f", b - a }'; }

cp "$RT_SOURCE_DIR/scenes/cubes.scn" "$work/cubes.scn"
"$RT_VIEW" "$work/cubes.scn" -o "$work/view.ppm" >"$work/out" \
    2>"$work/err" &
view_pid=$!
start=$(now)
window=$(find_window '^cubes\.scn.*done' 90) ||
    fail "no finished rt-view window within 90 s"
echo "first render shown after $(since "$start") s: $(window_name)"

# settled BEFORE: waits until the finished window shows something other
# than the screenshot BEFORE, the same in two screenshots in a row; its
# checksum on stdout.
settled() {
    local before=$1 last="" sum
    for _ in $(seq 300); do
        if window_name | grep -q ' - done in '; then
            screenshot "$work/shot.rgb" 2>/dev/null &&
                sum=$(cksum <"$work/shot.rgb") || sum=""
            if [ -n "$sum" ] && [ "$sum" != "$before" ] &&
                [ "$sum" = "$last" ]; then
                echo "$sum"
                return 0
            fi
            last=$sum
        fi
        sleep 0.1
    done
    return 1
}

screenshot "$work/first.rgb" || fail "no screenshot"
first=$(cksum <"$work/first.rgb")

# A left drag: press, three motions, release.
start=$(now)
timeout 10 xdotool mousemove --window "$window" 200 200 mousedown 1 \
    mousemove --window "$window" 215 195 sleep 0.05 \
    mousemove --window "$window" 240 190 sleep 0.05 \
    mousemove --window "$window" 260 185 mouseup 1 ||
    fail "xdotool could not drag"
dragged=$(settled "$first") || fail "the drag did not change the window"
echo "left drag rendered and shown after $(since "$start") s: $(window_name)"
grep -q '^pixel ' "$work/out" && fail "the drag explained a pixel"

# A wheel notch towards the scene.
start=$(now)
timeout 10 xdotool mousemove --window "$window" 200 200 click 4 ||
    fail "xdotool could not turn the wheel"
wheeled=$(settled "$dragged") || fail "the wheel did not change the window"
echo "wheel rendered and shown after $(since "$start") s: $(window_name)"
[ "$wheeled" != "$first" ] || fail "the wheel went back to the first view"

# C: the camera as rt-export options.
timeout 10 xdotool key --window "$window" c
for _ in $(seq 100); do
    grep -q '^# written to ' "$work/out" && break
    sleep 0.1
done
options=$(grep '^--look-from ' "$work/out" | tail -n 1)
[ -n "$options" ] || fail "C printed no rt-export options"
[ -f "$work/cubes-camera.txt" ] || fail "C wrote no cubes-camera.txt"
grep -qxF -- "$options" "$work/cubes-camera.txt" ||
    fail "cubes-camera.txt does not hold the options printed"
echo "C: $options"

# rt-export with them, and S in the viewer.
start=$(now)
# shellcheck disable=SC2086  # the options are words
"$RT_EXPORT" "$work/cubes.scn" $options -o "$work/export.ppm" ||
    fail "rt-export $options failed"
echo "rt-export took $(since "$start") s"
timeout 10 xdotool key --window "$window" s
for _ in $(seq 100); do
    grep -q "^$work/view.ppm\$" "$work/out" && break
    sleep 0.1
done
grep -q "^$work/view.ppm\$" "$work/out" || fail "S did not save view.ppm"
convert "$work/export.ppm" rgb:"$work/export.rgb" &&
    convert "$work/view.ppm" rgb:"$work/view.rgb" ||
    fail "convert could not read the images"
cmp "$work/export.rgb" "$work/view.rgb" ||
    fail "S's image differs from rt-export's with C's options"

timeout 10 xdotool key --window "$window" q 2>/dev/null
for _ in $(seq 100); do
    kill -0 "$view_pid" 2>/dev/null || break
    sleep 0.1
done
kill -0 "$view_pid" 2>/dev/null && fail "rt-view still runs after Q"
wait "$view_pid"
status=$?
view_pid=
[ "$status" -eq 0 ] || fail "rt-view exited $status"
echo "1 passed, 0 failed"
