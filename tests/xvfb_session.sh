# xvfb_session.sh - sourced by the viewer's X server tests (viewer_xvfb.sh,
# viewer_xvfb_fifo.sh): checks for Xvfb and xdotool (exit 77, skipped,
# without them), makes a work folder ($work), starts Xvfb on a free display
# and exports DISPLAY; on exit kills rt-view ($view_pid, when set) and Xvfb
# and removes the folder.  fail MESSAGE prints rt-view's output ($work/out,
# $work/err) and exits 1.
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
touch "$work/out" "$work/err"

# A free display: Xvfb writes the number it took to fd 3.
# -noreset: the server stays up when its last client (an rt-view that quit)
# goes, so the next xdotool or rt-view does not meet a server regenerating.
Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp -noreset 3>"$work/display" \
    >"$work/xvfb.log" 2>&1 &
xvfb_pid=$!
for _ in $(seq 100); do
    [ -s "$work/display" ] && break
    sleep 0.1
done
[ -s "$work/display" ] || { echo "skipped: Xvfb did not start"; exit 77; }
export DISPLAY=":$(head -n 1 "$work/display")"
unset WAYLAND_DISPLAY SDL_VIDEODRIVER
# X libraries' own allocations are not these tests' business (test_viewer
# checks rt-view's code for leaks).
export ASAN_OPTIONS=detect_leaks=0

# The id of the newest window whose name matches the regular expression $1,
# waiting up to $2 seconds; empty (status 1) when none came.  Each try is a
# query of its own with its X errors dropped: a window another client
# destroys while xdotool lists the names (SDL may replace one, a program
# may be ending) fails only that try.
find_window() {
    local pattern=$1 tries=$(( $2 * 10 )) found
    for _ in $(seq "$tries"); do
        found=$(xdotool search --name "$pattern" 2>/dev/null | tail -n 1)
        [ -n "$found" ] && { echo "$found"; return 0; }
        sleep 0.1
    done
    return 1
}

# The name of the window $window, or empty when it has gone.
window_name() {
    xdotool getwindowname "$window" 2>/dev/null
}
