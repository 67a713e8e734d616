#!/usr/bin/env bash
# viewer_xvfb_fifo.sh - rt-view --watch on a real X server (Xvfb), driven by
# xdotool, when the watched scene is replaced by a FIFO that no one writes:
# the reload runs on a worker thread (blocked opening the FIFO, or refused
# at once by the library), so the window still answers; Escape then quits
# with status 0, and in a second run SIGTERM ends it with 143.  rt-view
# used to read on its event loop and froze for ever.  The time from the key
# or the signal to the exit is printed, not asserted (a 90 s bound only
# stops a frozen rt-view).  Exits 77 (skipped) without Xvfb or xdotool.
#
# Environment: RT_VIEW (the rt-view binary), RT_SOURCE_DIR (the sources).
set -u
. "$(dirname "$0")/xvfb_session.sh"

# Starts rt-view --watch on a copy of cubes.scn named $1.scn, waits for its
# finished window, then puts a FIFO in the file's place and waits until
# rt-view has looked at it (its title says it is loading, or why not).
start_and_replace() {
    local name=$1
    cp "$RT_SOURCE_DIR/scenes/cubes.scn" "$work/$name.scn"
    "$RT_VIEW" --watch "$work/$name.scn" >"$work/out" 2>"$work/err" &
    view_pid=$!
    window=$(find_window "^$name\.scn.*done" 90) ||
        fail "no finished rt-view window within 90 s"
    rm "$work/$name.scn"
    mkfifo "$work/$name.scn"
    for _ in $(seq 100); do
        kill -0 "$view_pid" 2>/dev/null ||
            fail "rt-view ended when its scene became a FIFO"
        title=$(window_name) ||
            window=$(find_window "^$name\.scn" 1) || true
        case "$title" in
            *loading*|*"$name.scn:"*) break ;;
        esac
        sleep 0.1
    done
    echo "title after the FIFO: $title"
}

# Waits for rt-view to end; prints the milliseconds since $1 (date +%s%N)
# and leaves its status in $status.
wait_exit() {
    local since=$1
    for _ in $(seq 2000); do
        kill -0 "$view_pid" 2>/dev/null || break
        sleep 0.01
    done
    kill -0 "$view_pid" 2>/dev/null && fail "rt-view still runs 20 s later"
    echo "exited $(( ($(date +%s%N) - since) / 1000000 )) ms later"
    wait "$view_pid"
    status=$?
    view_pid=
}

start_and_replace watched
# The window answers: N (the normal view of the picture still shown).
timeout 10 xdotool key --window "$window" n
for _ in $(seq 100); do
    window_name | grep -q 'normal view' && break
    sleep 0.1
done
window_name | grep -q 'normal view' ||
    fail "N was not answered after the FIFO: $(window_name)"
since=$(date +%s%N)
# The window is gone before the key's release: X's BadWindow is expected.
timeout 10 xdotool key --window "$window" Escape 2>/dev/null
wait_exit "$since"
[ "$status" -eq 0 ] || fail "Escape: rt-view exited $status"
# xdotool pressed Escape through XTEST (the window had the focus) and ended
# on the window's BadWindow before releasing it: the server (kept up by
# -noreset) would hold the key down and repeat it into the next window.
xdotool keyup Escape 2>/dev/null

start_and_replace signalled
since=$(date +%s%N)
kill -TERM "$view_pid"
wait_exit "$since"
[ "$status" -eq 143 ] || fail "SIGTERM: rt-view exited $status, not 143"
echo "2 passed, 0 failed"
