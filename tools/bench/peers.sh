#!/usr/bin/env bash
# peers.sh - rt-export against its two peers on the same pictures, in one
# run (docs/performance.md, "Peers: POV-Ray and Embree on the same rays"):
# POV-Ray 3.7 given the same triangles as one mesh, and Intel Embree 3
# tracing the same rays (tools/bench/embree-peer, rt-embree-peer).
#
#   tools/bench/peers.sh BUILD_DIR [SCENE ...]
#
# Default scenes: ../shared/spd-scenes/*.scn, ../shared/formats/rings-s2.nff
# and balls-s3 (tools/bench/sphereflake.py 3).  A scene that is not a
# handout .scn (rings-s2.nff: three lights, NFF diffuse weights) is first
# written as one by rt-convert (its first light, d = 1 - k), so that all
# three renderers see the same picture.  Each is rendered at SIZE (default
# 400x400), depth 5; every time is the median of RUNS (default 3) runs:
#   - rt-export's whole process (wall clock, load and write included), 2
#     threads, --accel kdtree and --accel octree;
#   - POV-Ray's own "Trace Time" at 2 threads (scn2pov.py: one mesh), and
#     its parse + bounding + trace;
#   - at 1 thread, the kd-tree's build ("built in" of --stats) and our
#     render without it (--stats' render time, which includes the build of
#     the first render, minus the build), against rt-embree-peer's
#     rtcCommitScene (Embree's threads=1) and its render;
#   - "rays": the largest relative difference between rt-export's ray
#     counts (camera, shadow, reflection, refraction) and the peer's.
# Then the build of a TERRAIN x TERRAIN height field (tools/bench/
# terrain.py; default 708: 1,002,528 facets; 0 skips it), both at 1 thread.
# Needs povray and a build with rt-embree-peer (Embree 3 found); without
# either, those columns say "-".
#   RUNS=5 TERRAIN=0 tools/bench/peers.sh build ../shared/spd-scenes/balls-s2.scn
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:?usage: peers.sh BUILD_DIR [SCENE ...]}
shift
runs=${RUNS:-3}
size=${SIZE:-400x400}
terrain=${TERRAIN:-708}
. "$here/setup.sh"
export="$build/apps/rt-export"
peer="$build/tools/rt-embree-peer"
[ -x "$peer" ] || peer=""
command -v povray >/dev/null || pov_missing=1
scenes=("$@")
if [ ${#scenes[@]} -eq 0 ]; then
    shared="$here/../../../shared"
    scenes=("$shared"/spd-scenes/*.scn "$shared/formats/rings-s2.nff")
    python3 "$here/sphereflake.py" 3 >"$work/balls-s3.scn"
    scenes+=("$work/balls-s3.scn")
fi

now() { date +%s.%N; }

whole() {   # scene accel -> seconds of the whole rt-export process
    for _ in $(seq "$runs"); do
        t0=$(now)
        "$export" "$1" -o "$work/out.ppm" --threads 2 --size "$size" \
            --depth "$depth" --accel "$2" -q >/dev/null
        t1=$(now)
        awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.6f\n", b - a }'
    done | median
}

pov() {     # scene -> "trace total" seconds (median of each)
    python3 "$here/scn2pov.py" "$1" "$depth" "$width" "$height" \
        >"$work/s.pov"
    for _ in $(seq "$runs"); do
        povray +I"$work/s.pov" +O"$work/s.png" +W"$width" +H"$height" \
            +WT2 -D 2>&1 |
            sed -n 's/.*\(Parse\|Bounding\|Trace\) Time:.*(\([0-9.]*\) seconds).*/\1 \2/p' |
            awk '{ t[$1] = $2 } END { print t["Trace"],
                 t["Parse"] + t["Bounding"] + t["Trace"] }'
    done >"$work/pov.txt"
    echo "$(cut -d' ' -f1 "$work/pov.txt" | median)" \
         "$(cut -d' ' -f2 "$work/pov.txt" | median)"
}

ours1() {   # scene -> "build render-less-build camera shadow reflection refraction"
    for _ in $(seq "$runs"); do
        "$export" "$1" -o "$work/out.ppm" --threads 1 --size "$size" \
            --depth "$depth" --accel kdtree --stats=json -q 2>&1 >/dev/null |
            tail -n 1 | python3 -c '
import json, sys
s = json.load(sys.stdin)
b = s["kdtree"]["build_seconds"]
r = s["rays"]
print(b, s["seconds"]["render"] - b, r["camera"], r["shadow"],
      r["reflection"], r["refraction"])'
    done >"$work/ours.txt"
    echo "$(cut -d' ' -f1 "$work/ours.txt" | median)" \
         "$(cut -d' ' -f2 "$work/ours.txt" | median)" \
         "$(head -n 1 "$work/ours.txt" | cut -d' ' -f3-)"
}

embree() {  # scene -> "build render camera shadow reflection refraction"
    for _ in $(seq "$runs"); do
        "$peer" "$1" --threads 1 --size "$size" --depth "$depth" |
            awk '{ print $5, $8, $11, $13, $15, $17 }'
    done >"$work/embree.txt"
    echo "$(cut -d' ' -f1 "$work/embree.txt" | median)" \
         "$(cut -d' ' -f2 "$work/embree.txt" | median)" \
         "$(head -n 1 "$work/embree.txt" | cut -d' ' -f3-)"
}

rows=()
for s in "${scenes[@]}"; do
    name=$(basename "$s"); name=${name%.*}
    case "$s" in
        *.scn) scn=$s ;;
        *) "$build/apps/rt-convert" "$s" "$work/$name.scn" >/dev/null 2>&1
           scn="$work/$name.scn"; name="$name (as .scn)" ;;
    esac
    facets=$("$export" "$scn" --check 2>/dev/null |
             sed -n 's/^  facets *\([0-9]*\) (\([0-9]*\) can.*/\2/p')
    kd=$(whole "$scn" kdtree)
    oct=$(whole "$scn" octree)
    p="- -"; [ -n "${pov_missing:-}" ] || p=$(pov "$scn")
    o=$(ours1 "$scn")
    e="- - - - - -"; [ -z "$peer" ] || e=$(embree "$scn")
    rows+=("$name $facets $kd $oct $p $o $e")
done

table() {
    awk -v size="$size" '
    function ratio(slow, fast) {        # how many times faster `fast` is
        if (slow == "-" || fast == "-" || fast == 0) return "-";
        return sprintf("%.2f×", slow / fast);
    }
    function sec(x) {
        if (x == "-") return "-";
        return sprintf(x < 0.01 ? "%.4f s" : "%.3f s", x);
    }
    function rel(a, b) { return a == b ? 0 : (a > b ? a - b : b - a) / (a > b ? a : b); }
    BEGIN {
        print "| scene (" size ") | facets | rt-export whole, 2 threads, kd-tree | octree | POV-Ray trace | POV trace / ours | POV parse+bound+trace / ours | Embree build, 1 thread | our build | ours / Embree | Embree render, 1 thread | our render | ours / Embree | rays differ by |";
        print "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|";
    }
    {
        # name facets kd oct povtrace povtotal ob or oc os of ot eb er ec es ef et
        n = NF; name = $1;
        for (i = 2; i <= n - 17; i++) name = name " " $i;
        f = $(n-16); kd = $(n-15); oc = $(n-14); pt = $(n-13); pa = $(n-12);
        ob = $(n-11); orr = $(n-10); eb = $(n-5); er = $(n-4);
        d = "-";
        if (eb != "-") {
            d = 0;
            for (k = 0; k < 4; k++) {
                r = rel($(n-9+k), $(n-3+k));
                if (r > d) d = r;
            }
            d = sprintf("%.3f %%", 100 * d);
        }
        printf "| %s | %d | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n",
            name, f, sec(kd), sec(oc), sec(pt), ratio(pt, kd), ratio(pa, kd),
            sec(eb), sec(ob), ratio(ob, eb), sec(er), sec(orr),
            ratio(orr, er), d;
    }'
}
printf '%s\n' "${rows[@]}" | LC_ALL=C.UTF-8 table

if [ "$terrain" -gt 0 ]; then
    python3 "$here/terrain.py" "$terrain" >"$work/terrain.scn"
    o=$(ours1 "$work/terrain.scn")
    e="- -"; [ -z "$peer" ] || e=$(embree "$work/terrain.scn")
    echo
    echo "| build, 1 thread | facets | Embree | our kd-tree | ours / Embree |"
    echo "|---|--:|--:|--:|--:|"
    awk -v o="$o" -v e="$e" -v n="$((2 * terrain * terrain))" \
        -v t="$terrain" 'BEGIN {
        split(o, a, " "); split(e, b, " ");
        printf "| terrain %d×%d×2 | %d | %s | %.3f s | %s |\n", t, t, n,
            b[1] == "-" ? "-" : sprintf("%.3f s", b[1]), a[1],
            b[1] == "-" ? "-" : sprintf("%.1f×", a[1] / b[1]);
    }'
fi
