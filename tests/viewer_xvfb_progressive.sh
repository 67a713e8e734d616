#!/usr/bin/env bash
# viewer_xvfb_progressive.sh - rt-view's renders off the event loop on a
# real X server (Xvfb), driven by xdotool.  The scene, made here, is slow
# to render by brute force (20,000 small triangles, --accel none): its
# picture, then its normal view, take seconds.  rt-view shows the picture
# coarse to fine (the title names the pass); N during that render cancels
# it and starts the normal view on the rendering threads (rt-view used to
# render views on its event loop, deaf to keys until they were done); the
# window answers meanwhile (its title keeps changing); Escape then ends
# rt-view with status 0, cancelling the view.  --stats reports both renders
# cancelled.  The time from Escape to the exit is printed and checked
# against a loose 2 s (what it is meant to be is under 0.2 s; a loaded
# machine may take longer to schedule the process and X).  A second run
# drags the mouse during the picture's render: the render is cancelled
# (--stats reports it, and the time from the drag is printed) and the
# moved camera's starts.  Exits 77
# (skipped) without Xvfb or xdotool.
#
# Environment: RT_VIEW (the rt-view binary), RT_SOURCE_DIR (the sources).
set -u
. "$(dirname "$0")/xvfb_session.sh"

# Small triangles scattered (a fixed linear congruential sequence) in front
# of a large floor; the camera of scenes/two-facets.scn at 320 x 240.
awk -v count=20000 'BEGIN {
    seed = 12345
    printf "0, 0, 10\n0, 0, 5,  4, 0, 5,  320, 240\n%d\n", 3 * count + 3
    for (i = 0; i < count; i++) {
        seed = (seed * 1103515245 + 12345) % 2147483648; x = -8 + 16 * seed / 2147483648
        seed = (seed * 1103515245 + 12345) % 2147483648; y = -6 + 12 * seed / 2147483648
        seed = (seed * 1103515245 + 12345) % 2147483648; z = 0.5 + 1.5 * seed / 2147483648
        printf "%.4f, %.4f, %.4f\n", x - 0.2, y - 0.1, z
        printf "%.4f, %.4f, %.4f\n", x + 0.2, y - 0.1, z + 0.1
        printf "%.4f, %.4f, %.4f\n", x, y + 0.2, z
    }
    printf "-30, -30, 0\n30, -30, 0\n0, 40, 0\n%d\n", count + 1
    for (i = 0; i < count; i++)
        printf "%d, %d, %d, 0.3, %d, %d, 200\n", 3 * i + 1, 3 * i + 2,
               3 * i + 3, (i * 37) % 256, (i * 91) % 256
    printf "%d, %d, %d, 0.5, 180, 180, 180\n", 3 * count + 1, 3 * count + 2,
           3 * count + 3
    printf "30, 30, 60\n-3, 2, 20, 255, 255, 255\n"
}' >"$work/slow.scn"

"$RT_VIEW" "$work/slow.scn" --accel none --stats >"$work/out" 2>"$work/err" &
view_pid=$!
# The picture rendering: the title names the pass ("1/8: 3% - 0.4 s").
window=$(find_window '^slow\.scn .* - (1/[248]|full): [0-9]+% - ' 90) ||
    fail "no rt-view window rendering its picture within 90 s"
echo "rendering: $(window_name)"
timeout 10 xdotool key --window "$window" n
title=
for _ in $(seq 100); do
    title=$(window_name)
    case "$title" in *"normal view"*) break ;; esac
    sleep 0.1
done
echo "after N: $title"
case "$title" in
    *"normal view"*) ;;
    *) fail "N did not show the normal view: $title" ;;
esac
case "$title" in
    *"done in"*) fail "the normal view finished before the test could use" \
                      "it (the scene is too quick here): $title" ;;
esac
# The window answers while the view renders: its title (the elapsed time)
# keeps changing.
sleep 0.5
later=$(window_name)
echo "0.5 s later: $later"
[ "$later" != "$title" ] || fail "the title stood still while the view rendered"
case "$later" in
    *"done in"*) fail "the normal view finished before Escape (the scene" \
                      "is too quick here): $later" ;;
esac

since=$(date +%s%N)
# The window is gone before the key's release: X's BadWindow is expected.
timeout 10 xdotool key --window "$window" Escape 2>/dev/null
for _ in $(seq 2000); do
    kill -0 "$view_pid" 2>/dev/null || break
    sleep 0.01
done
kill -0 "$view_pid" 2>/dev/null && fail "rt-view still runs 20 s after Escape"
took=$(( ($(date +%s%N) - since) / 1000000 ))
echo "exited $took ms after Escape (meant: under 200 ms)"
wait "$view_pid"
status=$?
view_pid=
xdotool keyup Escape 2>/dev/null
[ "$status" -eq 0 ] || fail "Escape: rt-view exited $status"
[ "$took" -lt 2000 ] || fail "rt-view took $took ms to exit after Escape"
cat "$work/err"
grep -q '^rt-view: render 1 (picture): cancelled in ' "$work/err" ||
    fail "--stats did not report the picture cancelled by N"
grep -q '^rt-view: render 2 (normal view): cancelled in ' "$work/err" ||
    fail "--stats did not report the normal view cancelled by Escape"

# A move during a render cancels it: a left drag while the picture renders
# ends that render (--stats says so) and starts the moved camera's, whose
# title is back at the first pass.
"$RT_VIEW" "$work/slow.scn" --accel none --stats >"$work/out2" 2>"$work/err2" &
view_pid=$!
window=$(find_window '^slow\.scn .* - (1/[248]|full): [0-9]+% - ' 90) ||
    fail "no rt-view window rendering its picture within 90 s (second run)"
sleep 0.3
echo "before the drag: $(window_name)"
since=$(date +%s%N)
timeout 10 xdotool mousemove --window "$window" 160 120 mousedown 1 \
    mousemove --window "$window" 200 130 mouseup 1 ||
    fail "xdotool could not drag"
for _ in $(seq 2000); do
    grep -q '^rt-view: render 1 (picture): cancelled in ' "$work/err2" && break
    sleep 0.005
done
took=$(( ($(date +%s%N) - since) / 1000000 ))
grep -q '^rt-view: render 1 (picture): cancelled in ' "$work/err2" ||
    fail "the drag did not cancel the picture's render within 10 s"
echo "the picture's render cancelled $took ms after the drag began" \
     "(xdotool's own time included)"
title=$(window_name)
echo "after the drag: $title"
case "$title" in
    *"done in"*) fail "the moved picture finished at once (too quick)" ;;
esac
timeout 10 xdotool key --window "$window" Escape 2>/dev/null
wait "$view_pid"
status=$?
view_pid=
xdotool keyup Escape 2>/dev/null
[ "$status" -eq 0 ] || fail "Escape after the drag: rt-view exited $status"
cat "$work/err2"
grep -q '^rt-view: render 2 (picture): cancelled in ' "$work/err2" ||
    fail "--stats did not report the moved camera's render (render 2)"
[ "$took" -lt 2000 ] || fail "the drag took $took ms to cancel the render"
echo "2 passed, 0 failed"
