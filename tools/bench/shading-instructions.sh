#!/usr/bin/env bash
# shading-instructions.sh - what smooth shading and highlights cost, in
# instructions per ray (callgrind: exact, whatever the machine's load;
# docs/performance.md, "Smooth shading and highlights: what they cost").
#
#   tools/bench/shading-instructions.sh BUILD_DIR SCENE ...
#
# The variants of tools/bench/shading-cost.sh (the scene as
# `rt-convert --extended` writes it, without highlights, without vertex
# normals, without either), each run under `valgrind --tool=callgrind` with
# one thread at SIZE (default 160x120) and at 1x1; the difference of the two
# counts over the difference of their rays (--stats) is the render's
# instructions per ray, with the load, the octree's build and the start-up
# taken out.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:?usage: shading-instructions.sh BUILD_DIR SCENE ...}
shift
[ $# -gt 0 ] || { echo "usage: shading-instructions.sh BUILD_DIR SCENE ..." >&2; exit 2; }
size=${SIZE:-160x120}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

count() {   # scene size -> "instructions rays"
    valgrind --tool=callgrind --callgrind-out-file="$work/cg.out" \
        "$build/apps/rt-export" "$1" -o "$work/out.ppm" -j1 --size "$2" \
        --stats -q >"$work/log" 2>&1
    local ir rays
    ir=$(sed -n 's/.*Collected : \([0-9]*\).*/\1/p' "$work/log")
    rays=$(sed -n 's/^rays: .*(\([0-9]*\) in all).*/\1/p' "$work/log")
    echo "$ir $rays"
}

per_ray() { # scene -> instructions per ray of the render
    read -r i1 r1 < <(count "$1" "$size")
    read -r i0 r0 < <(count "$1" 1x1)
    awk -v a="$i1" -v b="$i0" -v c="$r1" -v d="$r0" \
        'BEGIN { printf "%.0f", (a - b) / (c - d) }'
}

echo "| scene ($size, 1 thread) | as converted | no highlights | no normals | neither | both vs neither |"
echo "|---|--:|--:|--:|--:|--:|"
for s in "$@"; do
    name=$(basename "${s%.*}")
    "$build/apps/rt-convert" --extended "$s" "$work/full.scn" >/dev/null 2>&1
    python3 "$here/scnstrip.py" --highlights "$work/full.scn" "$work/nohl.scn"
    python3 "$here/scnstrip.py" --normals "$work/full.scn" "$work/flat.scn"
    python3 "$here/scnstrip.py" --normals --highlights "$work/full.scn" \
        "$work/none.scn"
    a=$(per_ray "$work/full.scn")
    b=$(per_ray "$work/nohl.scn")
    c=$(per_ray "$work/flat.scn")
    d=$(per_ray "$work/none.scn")
    awk -v n="$name" -v a="$a" -v b="$b" -v c="$c" -v d="$d" 'BEGIN {
        printf "| %s | %d | %d | %d | %d | %+.1f %% |\n",
               n, a, b, c, d, 100 * (a - d) / d }'
done
