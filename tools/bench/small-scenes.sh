#!/usr/bin/env bash
# small-scenes.sh - the handout's small scenes against POV-Ray 3.7, side by
# side in one run (docs/performance.md, "Small scenes: the cost of each
# ray").
#
#   tools/bench/small-scenes.sh BUILD_DIR [BASELINE_BUILD_DIR]
#
# For each of scenes/cubes.scn and scenes/mirror.scn at SIZE (default
# 1920x1080), depth 5, ROUNDS times (default 5), taking turns: rt-export on
# 2 threads (its render time from --stats, and the CPU time of the whole
# process: loading and writing included), the baseline build the same way
# when given, and POV-Ray with 2 threads (+WT2; its "Trace Time" line gives
# the wall time and the CPU time of tracing, its start-up and parsing
# excluded).  Then rt-export on one thread for the cycles per ray: its CPU
# time times the clock, measured in the same run by a chain of dependent
# integer additions (one a cycle), over the rays --stats counts.  Prints
# Markdown tables of the medians.  Needs povray (apt-get install povray)
# for its columns; the rest runs without it.  Run it on an idle machine.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:?usage: small-scenes.sh BUILD_DIR [BASELINE_BUILD_DIR]}
base=${2:-}
rounds=${ROUNDS:-5}
size=${SIZE:-1920x1080}
. "$here/setup.sh"

# The clock: a dependent chain of additions, timed in CPU seconds.
cat >"$work/clock.c" <<'EOF'
#include <stdio.h>
#include <time.h>
int main(void)
{
    struct timespec a, b;
    volatile unsigned long seed = 1;
    unsigned long x = seed, n = 400000000UL;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &a);
    for (unsigned long i = 0; i < n; i++)
        __asm__ volatile("add $1, %0" : "+r"(x));
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &b);
    double s = (double)(b.tv_sec - a.tv_sec) + (b.tv_nsec - a.tv_nsec) * 1e-9;
    printf("%.4f\n", (double)n / s / 1e9 + 0 * (double)x);
    return 0;
}
EOF
cc -O2 -o "$work/clock" "$work/clock.c"

# rt-export BUILD SCENE THREADS -> "render_seconds cpu_seconds rays"
ours() {
    local out
    out=$( { TIMEFORMAT='cpu %3U %3S'
             time "$1/apps/rt-export" "$2" -o "$work/out.ppm" -j "$3" \
                 --size "$size" --depth "$depth" --stats -q >/dev/null; } 2>&1 )
    awk '/^time:/ { for (i = 1; i <= NF; i++) if ($i == "render") r = $(i + 1) }
         /^rays:/ { for (i = 1; i <= NF; i++) if ($i == "in") t = $(i - 1)
                    gsub(/[^0-9]/, "", t) }
         /^cpu / { c = $2 + $3 }
         END { print r, c, t }' <<<"$out"
}

pov() {     # scene -> "trace_wall trace_cpu"
    povray +I"$work/$1.pov" +O"$work/s.png" +W"$width" +H"$height" +WT2 -D \
        2>&1 | awk '/Trace Time:/ { w = $0; sub(/.*\(/, "", w); sub(/ .*/, "", w) }
                    /CPU-seconds/ && w != "" && c == "" {
                        for (i = 1; i <= NF; i++) if ($i == "CPU-seconds") c = $(i - 1) }
                    END { print w, c }'
}

have_pov=0
command -v povray >/dev/null && have_pov=1
scenes=(cubes mirror)
for s in "${scenes[@]}"; do
    [ $have_pov = 1 ] &&
        python3 "$here/scn2pov.py" "$here/../../scenes/$s.scn" "$depth" \
            "$width" "$height" >"$work/$s.pov"
done

: >"$work/log"
for r in $(seq "$rounds"); do
    echo "clock - $("$work/clock")" >>"$work/log"
    for s in "${scenes[@]}"; do
        echo "$s new2 $(ours "$build" "$here/../../scenes/$s.scn" 2)" >>"$work/log"
        [ -n "$base" ] &&
            echo "$s base2 $(ours "$base" "$here/../../scenes/$s.scn" 2)" >>"$work/log"
        [ $have_pov = 1 ] && echo "$s pov $(pov "$s")" >>"$work/log"
        echo "$s new1 $(ours "$build" "$here/../../scenes/$s.scn" 1)" >>"$work/log"
        [ -n "$base" ] &&
            echo "$s base1 $(ours "$base" "$here/../../scenes/$s.scn" 1)" >>"$work/log"
    done
done

col() {     # scene kind field -> median
    awk -v s="$1" -v k="$2" -v f="$3" '$1 == s && $2 == k { print $(f + 2) }' \
        "$work/log" | median
}
ghz=$(col clock - 1)
echo "Clock (dependent additions, median of $rounds): $ghz GHz; $rounds rounds, $size, depth $depth."
echo
echo "| scene | POV-Ray trace wall / CPU | rt-export render wall / process CPU (2 threads) | POV-Ray ÷ ours, wall | POV-Ray ÷ ours, CPU | baseline wall / CPU |"
echo "|---|--:|--:|--:|--:|--:|"
for s in "${scenes[@]}"; do
    nw=$(col "$s" new2 1); nc=$(col "$s" new2 2)
    pw=-; pc=-; rw=-; rc=-; bw=-
    if [ $have_pov = 1 ]; then
        pw=$(col "$s" pov 1); pc=$(col "$s" pov 2)
        rw=$(awk -v a="$pw" -v b="$nw" 'BEGIN { printf "%.2fx", a / b }')
        rc=$(awk -v a="$pc" -v b="$nc" 'BEGIN { printf "%.2fx", a / b }')
        pw="$pw s"; pc="$pc s"
    fi
    [ -n "$base" ] && bw="$(col "$s" base2 1) s / $(col "$s" base2 2) s"
    echo "| $s | $pw / $pc | $nw s / $nc s | $rw | $rc | $bw |"
done
echo
echo "| scene | rays | one thread: CPU s | cycles per ray | baseline CPU s | baseline cycles per ray |"
echo "|---|--:|--:|--:|--:|--:|"
for s in "${scenes[@]}"; do
    n=$(col "$s" new1 3); c=$(col "$s" new1 2)
    cy=$(awk -v c="$c" -v g="$ghz" -v n="$n" 'BEGIN { printf "%.0f", c * g * 1e9 / n }')
    bc=-; bcy=-
    if [ -n "$base" ]; then
        bc=$(col "$s" base1 2)
        bcy=$(awk -v c="$bc" -v g="$ghz" -v n="$n" 'BEGIN { printf "%.0f", c * g * 1e9 / n }')
    fi
    echo "| $s | $n | $c | $cy | $bc | $bcy |"
done
