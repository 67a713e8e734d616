#!/usr/bin/env bash
# mpi-scaling.sh - what docs/mpi.md's model is built from:
#   1. rt-export on all cores against rt-export-mpi as 1 rank x T threads
#      and as T ranks x 1 thread (T = the cores), the same image, checked
#      byte for byte; wall times, each rank's bands and the imbalance;
#   2. the bytes and messages per rendered row and the scene's broadcast;
#   3. the time one core takes per row of a 3840-pixel row at 16 samples
#      (a 16-row stripe through the middle of the image, and the mean row
#      of the whole image, scaled from a render on one core), and how much
#      costlier than the mean row the slowest band's rows were (PEAK).
# Usage: tools/bench/mpi-scaling.sh [BUILD_DIR [SCENE [WxH]]]
#   defaults: build, ../shared/spd-scenes/balls-s2.scn, 1920x1080.
# Each time is the best of REPEAT runs (3).  Run it on an idle machine;
# it takes a few minutes on two cores.  The
# ranks are not bound to cores (--bind-to none): Open MPI binds each of
# one or two ranks to a single core by default, where -j 2 would run both
# threads on that core.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)    # the project
build=${1:-$root/build}
scene=${2:-$root/../shared/spd-scenes/balls-s2.scn}
size=${3:-1920x1080}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_plm_rsh_agent=false  # local ranks only: never called
export OMPI_MCA_btl_vader_single_copy_mechanism=none  # containers: no CMA
[ -r "$scene" ] || { echo "mpi-scaling.sh: cannot read $scene" >&2; exit 1; }
cores=$(nproc)
width=${size%x*} height=${size#*x}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

now() { date +%s.%N; }
calc() { awk "BEGIN { printf \"%.${2:-3}f\", $1 }"; }
# wall NAME COMMAND...: runs it $REPEAT times (default 3), prints the
# fastest run's seconds, that run's stderr in $work/NAME.err (the best of
# several: other work on the machine only ever adds time)
wall() {
    local name=$1 start end seconds best=
    shift
    for _ in $(seq "${REPEAT:-3}"); do
        start=$(now)
        "$@" >/dev/null 2>"$work/run.err" ||
            { cat "$work/run.err" >&2; echo "failed: $*" >&2; exit 1; }
        end=$(now)
        seconds=$(calc "$end - $start")
        if [ -z "$best" ] || [ "$(calc "$seconds < $best" 0)" = 1 ]; then
            best=$seconds
            mv "$work/run.err" "$work/$name.err"
        fi
    done
    echo "$best"
}

echo "machine: $cores cores, $(uname -m), $(mpirun --version | head -n 1)"
echo "load before: $(uptime | sed 's/.*load/load/')"
echo "scene: $scene ($(wc -c <"$scene") bytes), $size, 1 sample"
echo
t_export=$(wall export "$build/apps/rt-export" -q "$scene" --size "$size" \
    -j "$cores" -o "$work/export.ppm")
echo "rt-export -j $cores:                 $t_export s"
t_one=$(wall one mpirun --bind-to none -np 1 "$build/apps/rt-export-mpi" \
    -q --stats "$scene" --size "$size" -j "$cores" -o "$work/one.ppm")
echo "mpirun -np 1 rt-export-mpi -j $cores:  $t_one s (mpirun's start included)"
t_many=$(wall many mpirun --bind-to none -np "$cores" \
    "$build/apps/rt-export-mpi" -q --stats "$scene" --size "$size" -j 1 \
    -o "$work/many.ppm")
echo "mpirun -np $cores rt-export-mpi -j 1:  $t_many s (mpirun's start included)"
cmp "$work/export.ppm" "$work/one.ppm"
cmp "$work/export.ppm" "$work/many.ppm"
echo "the three images are identical"
t_start=$(wall start mpirun --oversubscribe -np "$cores" /bin/true)
echo "mpirun -np $cores /bin/true (the start alone): $t_start s"
echo
echo "-np 1 x $cores threads:"
grep 'rank\|render' "$work/one.err" | sed 's/^/  /'
echo "-np $cores x 1 thread:"
grep 'rank\|render' "$work/many.err" | sed 's/^/  /'
echo
bands=$(sed -n 's/.*bands of \([0-9]*\) rows.*/\1/p' "$work/many.err")
per_band=$(calc "2 / $bands")
echo "per row: $((width * 3)) bytes of pixels to rank 0; per band of" \
     "$bands rows: 1 message of 4 bytes (the band) and 1 of" \
     "$((width * 3 * bands)) bytes (its rows), so $per_band messages a row"
echo "scene broadcast: 16 bytes (verdict, length) then $(wc -c <"$scene")" \
     "bytes, once"
echo
stripe=$(wall stripe "$build/apps/rt-export" -q "$scene" --size 3840x2160 \
    --samples 16 --region 0,1072,3840,1088 -j 1 -o "$work/stripe.ppm")
per_row=$(calc "$stripe / 16" 4)
echo "one core, 3840x2160 at 16 samples, rows 1072..1087, the middle:" \
     "$stripe s, $per_row s a row"
t_serial=$(wall serial "$build/apps/rt-export" -q "$scene" --size "$size" \
    -j 1 -o "$work/serial.ppm")
mean_row=$(calc "$t_serial / $height * 3840 / $width * 16" 4)
echo "one core, the whole $size image at 1 sample: $t_serial s;" \
     "mean row scaled to 3840 pixels x 16 samples: $mean_row s"
peak=$(awk '/in its slowest band/ {
        for (i = 1; i <= NF; i++) {
            if ($i == "rows,") rows += $(i - 1)
            if ($i == "rendering") busy += $(i - 2)
            if ($(i + 1) == "in" && $(i + 3) == "slowest") {
                v = $i + 0; if (v > slow) slow = v
            }
        }
    } END { if (rows > 0 && busy > 0) printf "%.2f", slow / (busy / rows) }' \
    "$work/many.err")
echo "PEAK (-np $cores x 1 thread): the slowest band's time a row over the" \
     "mean row's: $peak"
echo "load after: $(uptime | sed 's/.*load/load/')"
