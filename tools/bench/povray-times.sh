#!/usr/bin/env bash
# povray-times.sh - POV-Ray 3.7's own trace time against rt-export's render
# time on the same pictures (docs/performance.md, "The octree").
#
#   tools/bench/povray-times.sh BUILD_DIR [SCENE.scn ...]
#
# Default scenes: ../shared/spd-scenes/*.scn.  Each is converted by
# tools/bench/scn2pov.py (the same triangles, every light, max_trace_level =
# depth + 1) and rendered by both at SIZE (default 400x400) with 2 threads;
# the table gives POV-Ray's "Trace Time" (its start-up and
# parsing excluded) and rt-export's render time (--stats) with brute force
# and with the octree, each the median of RUNS (default 3) runs.  Needs
# povray (apt-get install povray); without it, prints only ours.
#   SIZE=1920x1080 RUNS=5 tools/bench/povray-times.sh build scenes/cubes.scn
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:?usage: povray-times.sh BUILD_DIR [SCENE.scn ...]}
shift
scenes=("$@")
if [ ${#scenes[@]} -eq 0 ]; then
    scenes=("$here"/../../../shared/spd-scenes/*.scn)
fi
runs=${RUNS:-3}
size=${SIZE:-400x400}
. "$here/setup.sh"

ours() {    # scene accel -> seconds of render
    for _ in $(seq "$runs"); do
        "$build/apps/rt-export" "$1" -o "$work/out.ppm" --threads 2 \
            --size "${width}x$height" --accel "$2" --stats -q 2>&1 >/dev/null |
            sed -n 's/^time: .*render \([0-9.]*\) s.*/\1/p'
    done | median
}

pov() {     # scene -> POV-Ray's trace time
    python3 "$here/scn2pov.py" "$1" "$depth" "$width" "$height" \
        >"$work/s.pov"
    for _ in $(seq "$runs"); do
        povray +I"$work/s.pov" +O"$work/s.png" +W"$width" +H"$height" +WT2 -D \
            2>&1 | sed -n 's/.*Trace Time:.*(\([0-9.]*\) seconds).*/\1/p'
    done | median
}

echo "| scene ($size) | facets | POV-Ray trace | brute force | octree | octree vs POV-Ray | octree vs brute force |"
echo "|---|--:|--:|--:|--:|--:|--:|"
for s in "${scenes[@]}"; do
    name=$(basename "$s" .scn)
    facets=$("$build/apps/rt-export" "$s" --check 2>/dev/null |
             sed -n 's/^  facets *\([0-9]*\).*/\1/p')
    none=$(ours "$s" none)
    tree=$(ours "$s" octree)
    if command -v povray >/dev/null; then
        p=$(pov "$s")
    else
        p=""
    fi
    awk -v n="$name" -v f="$facets" -v p="$p" -v b="$none" -v o="$tree" '
        function ratio(x, y) {
            if (x == "" || y == 0) return "-";
            if (x >= y) return sprintf("%.1fx faster", x / y);
            return sprintf("%.1fx slower", y / x);
        }
        BEGIN {
            printf "| %s | %s | %s | %.3f s | %.3f s | %s | %s |\n",
                   n, f, (p == "" ? "-" : sprintf("%.3f s", p)), b, o,
                   ratio(p, o), ratio(b, o);
        }'
done
