#!/usr/bin/env bash
# scale.sh - rt-export on meshes of millions of facets, step by step, in
# one run (docs/performance.md, "Scale: millions of facets"; issue 29):
# the height field of tools/bench/terrain.py at about 1, 5 and 20 million
# facets, as a binary little-endian PLY (tools/bench/plygen.py) and, up to
# SCN_MAX million facets (default 5), as the .scn of the same mesh
# (terrain.py --float32: the PLY's float32 vertices written exactly, the
# same facets in the same order); above it, whose .scn would pass the 1 GiB
# a scene may weigh, as an OBJ of the same mesh instead (terrain.py --obj
# --float32: the vertices to nine digits), the text file rt-export reads
# without a PLY reader.
#
#   tools/bench/scale.sh [--sizes 1,5,20] [--runs N] [BUILD_DIR]
#
# --sizes: millions of facets (a size s is a grid of n x n cells, n =
# ceil(sqrt(s 10^6 / 2)): 1 -> 708 (1,002,528 facets), 5 -> 1582
# (5,005,448), 20 -> 3163 (20,009,138); 0.01 -> 71, a quick try).
# --runs: every figure is the median of N runs (default 3).  BUILD_DIR
# defaults to build.  Each run is one whole rt-export process, 2 threads,
# 400x400, depth 5, the default --accel (auto: the kd-tree), --stats=json,
# the image written to the work folder; its steps are --stats' load (read),
# the kd-tree's "build_seconds" (build), render less build (trace: the
# build is done by the first render, inside its time) and write; "whole"
# is the wall clock of the process, "peak" its maximum resident set
# (/usr/bin/time's %M, else getrusage of the child), "B/facet" the peak
# over the facets, "read peak" that of `rt-export FILE --check` (the read
# alone, one run).  The keys of --stats=json whose names hold "peak"
# (rt-export's own "memory": peak_bytes, load_peak_bytes,
# peak_bytes_per_facet, where it has them) are shown in the last column
# (bytes as MB), from the first run.  A PLY or an OBJ has no camera: their
# runs are given the .scn's view (terrain.VIEW: --look-from, --look-at,
# --up, --fov, --light), so the formats cast the same rays (the "rays"
# column).  A PLY that rt-export does not read (no
# PLY reader in this build) gives the row "skipped: rt-export cannot read
# PLY (not built)".  A size whose runs would not fit in memory (the last
# size's bytes per facet, else 600, times its facets, beyond 80 % of
# MemAvailable) is skipped and says so.
#
# Then rt-embree-peer (tools/bench/embree-peer, built where Embree 3 is
# found) on the .scn and OBJ rows (it takes the file's own camera: on an
# OBJ the automatic one, other rays, see its "rays"): its load,
# rtcCommitScene (2 threads), render (one thread, as always), whole
# process and peak.  The files live in a temporary folder, removed as soon
# as their size is done; the script says how big they were.
#   tools/bench/scale.sh --sizes 1,5 --runs 3 build
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
sizes=1,5,20
runs=3
build=build
while [ $# -gt 0 ]; do
    case "$1" in
        --sizes) sizes=${2:?--sizes needs a list}; shift 2 ;;
        --runs) runs=${2:?--runs needs a count}; shift 2 ;;
        -*) echo "usage: scale.sh [--sizes 1,5,20] [--runs N] [BUILD_DIR]" >&2
            exit 2 ;;
        *) build=$1; shift ;;
    esac
done
scn_max=${SCN_MAX:-5}
size=400x400
. "$here/setup.sh"
export="$build/apps/rt-export"
[ -x "$export" ] || { echo "scale.sh: no $export (build first)" >&2; exit 1; }
peer="$build/tools/rt-embree-peer"
[ -x "$peer" ] || peer=""
read -r -a view <<<"$(cd "$here" && python3 -c 'import terrain; print(terrain.VIEW)')"
if [ -x /usr/bin/time ]; then
    measure() { /usr/bin/time -f '%M' -o "$work/peak" "$@"; }
else
    measure() {
        python3 -c 'import resource, subprocess, sys
status = subprocess.call(sys.argv[2:])
open(sys.argv[1], "w").write("%d\n" %
    resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)
sys.exit(status)' "$work/peak" "$@"
    }
fi
now() { date +%s.%N; }
col() { cut -d' ' -f"$1" "$work/runs" | median; }

cache() { sed -n "s/^$1:[A-Z]*=//p" "$build/CMakeCache.txt" 2>/dev/null; }
cc=$(cache CMAKE_C_COMPILER)
echo "scale.sh: $(date -u '+%Y-%m-%d %H:%M UTC'), commit" \
     "$(git -C "$here" rev-parse --short HEAD 2>/dev/null || echo '?')," \
     "$(cache CMAKE_BUILD_TYPE), $("${cc:-cc}" --version 2>/dev/null | head -n 1)"
cpu=$(sed -n 's/^model name[^:]*: //p' /proc/cpuinfo | head -n 1)
echo "machine: $(nproc) cores ($cpu," \
     "$(awk '/MemTotal/ { printf "%.1f GB", $2 / 1048576 }' /proc/meminfo));" \
     "load at the start $(cut -d' ' -f1-3 /proc/loadavg); median of $runs runs"
echo

# run FILE FORMAT -> "load build trace write whole peak_kb rays peaks", one
# line per run in $work/runs, then the peak of reading alone (--check) in
# $work/readkb; non-zero (the message in $work/err) when rt-export fails.
run() {
    local extra=()
    [ "$2" = scn ] || extra=("${view[@]}")   # a PLY or an OBJ
    : >"$work/runs"
    for _ in $(seq "$runs"); do
        t0=$(now)
        if ! measure "$export" "$1" -o "$work/out.ppm" --threads 2 \
                --stats=json -q "${extra[@]}" 2>"$work/err" >/dev/null; then
            return 1
        fi
        t1=$(now)
        tail -n 1 "$work/err" | python3 -c '
import json, sys
s = json.load(sys.stdin)
sec = s["seconds"]
tree = s.get("kdtree") or s.get("octree") or {}
build = tree.get("build_seconds", 0.0)
peaks = []
def find(d, path):
    for k, v in d.items():
        if isinstance(v, dict):
            find(v, path + k + ".")
        elif "peak" in k and k.endswith("_bytes"):
            peaks.append("%s=%.1fMB" % (k[:-len("_bytes")], v / 1e6))
        elif "peak" in k:
            peaks.append("%s=%.6g" % (k, v))
find(s, "")
print(sec["load"], build, sec["render"] - build, sec["write"],
      float(sys.argv[2]) - float(sys.argv[1]), open(sys.argv[3]).read().strip(),
      s["rays"]["total"], ",".join(peaks) or "-")' "$t0" "$t1" "$work/peak" \
            >>"$work/runs"
    done
    measure "$export" "$1" --check "${extra[@]}" >/dev/null 2>&1 || return 1
    cp "$work/peak" "$work/readkb"
}

# embree FILE -> "load build trace whole peak_kb rays" (medians)
embree() {
    : >"$work/runs"
    for _ in $(seq "$runs"); do
        t0=$(now)
        measure "$peer" "$1" --threads 2 --size "$size" >"$work/peer" \
            2>"$work/peer.err" || return 1
        t1=$(now)
        awk -v t0="$t0" -v t1="$t1" -v kb="$(cat "$work/peak")" '
            /^embree: / { printf "%s %s %s %.6f %s %d\n", $19, $5, $8,
                          t1 - t0, kb, $11 + $13 + $15 + $17 }' \
            "$work/peer" >>"$work/runs"
    done
    echo "$(col 1) $(col 2) $(col 3) $(col 4) $(col 5) $(col 6)"
}

knows_ply() { "$export" --help 2>&1 | grep -qi 'ply'; }  # main before PLY

rows=()     # facets format MB load build trace write whole kb readkb rays peaks
peers=()    # facets format load build trace whole kb rays
files=()    # facets format bytes
bpf=600     # bytes per facet expected of the next size
for s in ${sizes//,/ }; do
    n=$(awk -v s="$s" 'BEGIN { x = sqrt(s * 1e6 / 2); n = int(x);
                               if (n < x) n++; if (n < 1) n = 1; print n }')
    facets=$((2 * n * n))
    avail=$(awk '/MemAvailable/ { print $2 * 1024 }' /proc/meminfo)
    need=$(awk -v b="$bpf" -v f="$facets" 'BEGIN { printf "%.0f", b * f }')
    if awk -v a="$avail" -v n="$need" 'BEGIN { exit !(n > 0.8 * a) }'; then
        rows+=("$facets - - skipped: needs about $((need / 1000000000)) GB ($bpf B/facet), $((avail / 1000000000)) GB available")
        continue
    fi
    formats=(obj ply)
    awk -v s="$s" -v m="$scn_max" 'BEGIN { exit !(s <= m) }' &&
        formats=(scn ply)
    for f in "${formats[@]}"; do
        file="$work/terrain-$n.$f"
        case $f in
            scn) python3 "$here/terrain.py" --float32 "$n" >"$file" ;;
            obj) python3 "$here/terrain.py" --obj --float32 "$n" >"$file" ;;
            ply) python3 "$here/plygen.py" "$n" >"$file" ;;
        esac
        bytes=$(stat -c %s "$file")
        files+=("$facets $f $bytes")
        mb=$(awk -v b="$bytes" 'BEGIN { printf "%.1f", b / 1e6 }')
        if run "$file" "$f"; then
            r="$(col 1) $(col 2) $(col 3) $(col 4) $(col 5) $(col 6)"
            rows+=("$facets $f $mb $r $(cat "$work/readkb") $(head -n 1 "$work/runs" | cut -d' ' -f7-)")
            bpf=$(awk -v k="$(col 6)" -v f="$facets" \
                  'BEGIN { printf "%.0f", 1.1 * k * 1024 / f }')
        elif [ "$f" = ply ] && ! knows_ply; then
            rows+=("$facets $f $mb skipped: rt-export cannot read PLY (not built)")
        else
            rows+=("$facets $f $mb failed: $(tail -n 1 "$work/err" | cut -c1-120)")
        fi
        if [ -n "$peer" ] && [ "$f" != ply ]; then
            if e=$(embree "$file"); then
                peers+=("$facets $f $e")
            else
                peers+=("$facets $f failed: $(tail -n 1 "$work/peer.err" | cut -c1-100)")
            fi
        fi
        rm -f "$file"
    done
done

LC_ALL=C.UTF-8 awk '
function sec(x) { return sprintf(x < 0.01 ? "%.4f" : "%.3f", x); }
function rate(x) {
    return x >= 1e6 ? sprintf("%.2f M", x / 1e6) : sprintf("%.0f k", x / 1e3);
}
BEGIN {
    print "| facets | format | file MB | read s (MB/s) | build s (facets/s) | trace s (rays/s) | write s | whole s | peak MB | B/facet | read peak MB | target | met? | rays | --stats peak |";
    print "|--:|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|---|---|--:|---|";
}
{
    f = $1; fmt = $2;
    tw = "-"; tp = "-"; tb = "-";   # targets: whole s, peak bytes, B/facet
    if (fmt == "scn" && f > 900000 && f < 1100000) { tw = 2; tp = 200e6 }
    if (fmt == "ply" && f > 4500000 && f < 5500000) { tw = 6; tb = 150 }
    if (fmt == "ply" && f > 18000000 && f < 22000000) { tw = 25; tp = 3e9 }
    target = "-";
    if (tw != "-" && tb != "-")
        target = "≤ " tw " s, ≤ " tb " B/facet";
    else if (tw != "-")
        target = "≤ " tw " s, ≤ " (tp >= 1e9 ? tp / 1e9 " GB" : tp / 1e6 " MB");
    if ($4 !~ /^[0-9.]+$/) {        # skipped or failed
        rest = $4; for (i = 5; i <= NF; i++) rest = rest " " $i;
        printf "| %d | %s | %s | %s | | | | | | | | %s | | | |\n", f, fmt,
            ($3 == "" || fmt == "-") ? "-" : $3, rest, target;
        next;
    }
    load = $4; build = $5; trace = $6; write = $7; whole = $8;
    peak = $9 * 1024; readpeak = $10 * 1024; rays = $11; peaks = $12;
    gsub(",", ", ", peaks);
    met = "-";
    if (tw != "-") {
        bad = "";
        if (whole > tw) bad = "whole";
        if ((tp != "-" && peak > tp) || (tb != "-" && peak / f > tb))
            bad = bad (bad == "" ? "" : ", ") "memory";
        met = bad == "" ? "yes" : "no (" bad ")";
    }
    printf "| %d | %s | %s | %s (%.0f) | %s (%s) | %s (%s) | %s | %s | %.0f | %.0f | %.0f | %s | %s | %d | %s |\n",
        f, fmt, $3, sec(load), $3 / load, sec(build), rate(f / build),
        sec(trace), rate(rays / trace), sec(write), sec(whole),
        peak / 1e6, peak / f, readpeak / 1e6, target, met, rays, peaks;
}' < <(printf '%s\n' "${rows[@]}")

if [ -n "$peer" ] && [ ${#peers[@]} -gt 0 ]; then
    echo
    echo "rt-embree-peer on the .scn and OBJ rows (build 2 threads, render 1 thread):"
    echo
    echo "| facets | format | read s | build s (facets/s) | trace s (rays/s), 1 thread | whole s | peak MB | B/facet | rays |"
    echo "|--:|---|--:|--:|--:|--:|--:|--:|--:|"
    printf '%s\n' "${peers[@]}" | LC_ALL=C.UTF-8 awk '
    function sec(x) { return sprintf(x < 0.01 ? "%.4f" : "%.3f", x); }
    function rate(x) {
        return x >= 1e6 ? sprintf("%.2f M", x / 1e6) : sprintf("%.0f k", x / 1e3);
    }
    $3 == "failed:" { f = $1; fmt = $2; $1 = ""; $2 = "";
                      print "| " f " | " fmt " |" $0 " | | | | | | |"; next }
    { f = $1; peak = $7 * 1024;
      printf "| %d | %s | %s | %s (%s) | %s (%s) | %s | %.0f | %.0f | %d |\n",
          f, $2, sec($3), sec($4), rate(f / $4), sec($5), rate($8 / $5),
          sec($6), peak / 1e6, peak / f, $8; }'
elif [ -z "$peer" ]; then
    echo
    echo "rt-embree-peer: not built (Embree 3 not found), no peer figures"
fi
echo
echo "files (generated in $work, removed after their size):" \
     "$(printf '%s\n' "${files[@]}" |
        awk '{ printf "%s%d %s %.1f MB", (NR > 1 ? "; " : ""), $1, $2, $3 / 1e6 }')"
echo "load at the end $(cut -d' ' -f1-3 /proc/loadavg)"
