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
. "$(dirname "$0")/xvfb_session.sh"

"$RT_VIEW" "$RT_SOURCE_DIR/scenes/cubes.scn" >"$work/out" 2>"$work/err" &
view_pid=$!
window=$(find_window '^cubes\.scn.*done' 90) ||
    fail "no finished rt-view window within 90 s"
# The window has the image's size (400x400): window point = pixel.
timeout 10 xdotool mousemove --window "$window" 268 124 click 1 ||
    fail "xdotool could not click"
for _ in $(seq 100); do
    grep -q 'shadowed by' "$work/out" && break
    sleep 0.1
done
# rt-export --explain's text (the one formatter), the scene as given
grep -q "^pixel 268,124 of $RT_SOURCE_DIR/scenes/cubes.scn: C = " \
    "$work/out" || fail "the click did not explain pixel 268,124"
grep -q 'shadow ray to light 0: .*, E 0, shadowed by facet 9 (line 47), ' \
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
