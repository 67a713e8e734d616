#!/usr/bin/env bash
# view-frames.sh - how soon rt-view shows a picture after a move: the real
# rt-view on Xvfb, driven by xdotool, with --stats.  The scene renders once;
# then MOVES times: a left drag (an orbit) once the previous render is done,
# and the --stats line of the render it started is kept.  Prints each line,
# then the least, median and largest time to the first pass (1/8) and to
# its display ("first shown": the pass uploaded and drawn), and to the full
# picture.
#
#   tools/bench/view-frames.sh RT_VIEW SCENE [MOVES] [rt-view options...]
#   tools/bench/view-frames.sh build/apps/rt-view balls-s2.scn 10 --size 640x480
#
# Needs Xvfb and xdotool (apt-get install xvfb xdotool).
set -euo pipefail
view=$1 scene=$2 moves=${3:-10}
shift 3 || shift $#
work=$(mktemp -d)
trap 'kill $pid $xvfb 2>/dev/null; wait 2>/dev/null; rm -rf "$work"' EXIT
Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp -noreset \
    3>"$work/display" >/dev/null 2>&1 &
xvfb=$!
for _ in $(seq 100); do [ -s "$work/display" ] && break; sleep 0.1; done
export DISPLAY=":$(head -n 1 "$work/display")"
unset WAYLAND_DISPLAY SDL_VIDEODRIVER
"$view" "$scene" --stats "$@" >"$work/out" 2>"$work/err" &
pid=$!
name=$(basename "$scene")
window=
for _ in $(seq 300); do
    window=$(xdotool search --name "^${name//./\\.} .* - done in" 2>/dev/null |
             tail -n 1) && [ -n "$window" ] && break
    sleep 0.1
done
[ -n "$window" ] || { echo "no finished rt-view window" >&2; exit 1; }
for i in $(seq "$moves"); do
    before=$(grep -c '^rt-view: render ' "$work/err" || true)
    x=$((150 + (i % 5) * 10))
    xdotool mousemove --window "$window" "$x" 150 mousedown 1 \
        mousemove --window "$window" $((x + 30)) 160 mouseup 1
    for _ in $(seq 600); do
        now=$(grep -c '^rt-view: render ' "$work/err" || true)
        [ "$now" -gt "$before" ] &&
            xdotool getwindowname "$window" | grep -q ' - done in' && break
        sleep 0.05
    done
done
xdotool key --window "$window" q 2>/dev/null || true
wait "$pid" || true
pid=
grep '^rt-view: render ' "$work/err"
# render 1 is the first picture; the others follow the moves.
grep '^rt-view: render ' "$work/err" | tail -n +2 | python3 -c '
import re, sys
def ms(text):
    m = re.match(r"([0-9.]+) (ms|s)", text)
    return float(m.group(1)) * (1 if m.group(2) == "ms" else 1000)
rows = {"1/8": [], "first shown": [], "full": []}
for line in sys.stdin:
    for key, pattern in (("1/8", r"1/8 in ([0-9.]+ m?s)"),
                         ("first shown", r"first shown at ([0-9.]+ m?s)"),
                         ("full", r"full in ([0-9.]+ m?s)")):
        m = re.search(pattern, line)
        if m:
            rows[key].append(ms(m.group(1)))
for key, values in rows.items():
    if values:
        values.sort()
        print("%-12s least %7.1f ms  median %7.1f ms  largest %7.1f ms  "
              "(%d moves)" % (key, values[0], values[len(values) // 2],
                              values[-1], len(values)))
'
