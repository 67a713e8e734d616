# setup.sh - sourced by the benchmark scripts that time renders against
# POV-Ray (povray-times.sh, small-scenes.sh), after they set `size`
# (WxH): its width and height, the depth every render uses (5, rt-export's
# default and POV-Ray's max_trace_level there), a work folder removed at
# exit, and median (of numbers, one a line, on standard input).
width=${size%x*}
height=${size#*x}
depth=5
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

median() { sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
