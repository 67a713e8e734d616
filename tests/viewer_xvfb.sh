#!/usr/bin/env bash
# viewer_xvfb.sh - rt-view on a real X server (Xvfb), driven by xdotool: a
# left click on a pixel of scenes/cubes.scn's floor in the cube's shadow
# prints that pixel's ray tree, which names the facet casting the shadow and
# its line; N switches to the normal view (named in the title); Escape
# clears and Q quits with status 0.  Also saves a screenshot of the click
# (xwd) when RT_XVFB_SCREENSHOT names a file.  Exits 77 (skipped) without
# Xvfb or xdotool.
#
# Environment: RT_VIEW (the rt-view binary), RT_SOURCE_DIR (the sources).
set -u
for tool in Xvfb xdotool; do
    command -v "$tool" >/dev/null 2>&1 || {
        echo "skipped: $tool is not installed"; exit 77; }
done
work=$(mktemp -d)
xvfb_pid=
view_pid=
cleanup() {
    [ -n "$view_pid" ] && kill "$view_pid" 2>/dev/null
    [ -n "$xvfb_pid" ] && kill "$xvfb_pid" 2>/dev/null
    wait 2>/dev/null
    rm -rf "$work"
}
trap cleanup EXIT
fail() { echo "FAIL: $*"; echo "--- rt-view stdout"; cat "$work/out";
         echo "--- rt-view stderr"; cat "$work/err"; exit 1; }

# A free display: Xvfb writes the number it took to fd 3.
Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp 3>"$work/display" \
    >"$work/xvfb.log" 2>&1 &
xvfb_pid=$!
for _ in $(seq 100); do
    [ -s "$work/display" ] && break
    sleep 0.1
done
[ -s "$work/display" ] || { echo "skipped: Xvfb did not start"; exit 77; }
export DISPLAY=":$(head -n 1 "$work/display")"
unset WAYLAND_DISPLAY SDL_VIDEODRIVER
# X libraries' own allocations are not this test's business (test_viewer
# checks rt-view's code for leaks).
export ASAN_OPTIONS=detect_leaks=0

"$RT_VIEW" "$RT_SOURCE_DIR/scenes/cubes.scn" >"$work/out" 2>"$work/err" &
view_pid=$!
window=$(timeout 20 xdotool search --sync --name 'cubes.scn.*done' | head -n 1)
[ -n "$window" ] || fail "no finished rt-view window within 20 s"
# The window has the image's size (400x400): window point = pixel.
timeout 10 xdotool mousemove --window "$window" 268 124 click 1 ||
    fail "xdotool could not click"
for _ in $(seq 100); do
    grep -q 'shadowed by' "$work/out" && break
    sleep 0.1
done
grep -q '^cubes.scn pixel (268, 124)' "$work/out" ||
    fail "the click did not explain pixel (268, 124)"
grep -q 'shadow to light 0: .* E 0: shadowed by facet 9 (line 47)' \
    "$work/out" || fail "the shadow's blocker is not facet 9 (line 47)"
if [ -n "${RT_XVFB_SCREENSHOT:-}" ] && command -v xwd >/dev/null; then
    sleep 0.3
    xwd -silent -id "$window" -out "$RT_XVFB_SCREENSHOT" ||
        echo "warning: no screenshot"
fi
timeout 10 xdotool key --window "$window" n
for _ in $(seq 100); do
    xdotool getwindowname "$window" | grep -q 'normal view' && break
    sleep 0.1
done
xdotool getwindowname "$window" | grep -q 'normal view' ||
    fail "N did not show the normal view"
timeout 10 xdotool key --window "$window" Escape
# The window is gone before the key's release: X's BadWindow is expected.
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
