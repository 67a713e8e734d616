#!/usr/bin/env bash
# shading-cost.sh - what smooth shading and highlights cost (docs/performance.md,
# "Smooth shading and highlights: what they cost").
#
#   tools/bench/shading-cost.sh BUILD_DIR SCENE ...
#
# Each SCENE (any of our formats) is written as an extended
# .scn by `rt-convert --extended` (every model parameter kept), then
# tools/bench/scnstrip.py makes the variants: without highlights (s = 0),
# without vertex normals (flat), without either.  Each variant is rendered
# by rt-export at SIZE (default 512x512) with 2 threads; the table gives the
# render time of --stats, the median of RUNS (default 3), the rays of the
# scene as converted and without either (smooth normals change where
# reflected and refracted rays go, so their number), and the render time
# per ray of both.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:?usage: shading-cost.sh BUILD_DIR SCENE ...}
shift
[ $# -gt 0 ] || { echo "usage: shading-cost.sh BUILD_DIR SCENE ..." >&2; exit 2; }
scenes=("$@")
runs=${RUNS:-3}
size=${SIZE:-512x512}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

median() { sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

render() {  # scene.scn -> median render seconds
    for _ in $(seq "$runs"); do
        "$build/apps/rt-export" "$1" -o "$work/out.ppm" -j2 --size "$size" \
            --stats -q 2>&1 >/dev/null |
            sed -n 's/^time: .*render \([0-9.]*\) s.*/\1/p'
    done | median
}

rays() {    # scene.scn -> rays of every kind
    "$build/apps/rt-export" "$1" -o "$work/out.ppm" -j2 --size "$size" \
        --stats -q 2>&1 >/dev/null | sed -n 's/^rays: .*(\([0-9]*\) in all).*/\1/p'
}

count() {   # what the scene holds: smooth facets, facets with s > 0
    python3 - "$1" <<'EOF'
import re, sys
rows = [l.split("#", 1)[0].strip() for l in open(sys.argv[1])]
rows = [[x for x in re.split(r"[,\s]+", l) if x] for l in rows if l]
n = int(float(rows[2][0])); m = int(float(rows[3 + n][0]))
v = rows[3:3 + n]; f = rows[4 + n:4 + n + m]
smooth = sum(all(len(v[int(float(i)) - 1]) >= 6 for i in x[:3]) for x in f)
shiny = sum(len(x) > 10 and float(x[10]) > 0 for x in f)
print(m, smooth, shiny)
EOF
}

echo "| scene ($size) | facets | smooth | with a highlight | as converted | no highlights | no normals | neither | rays as converted / neither | ns per ray as converted / neither |"
echo "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|"
for s in "${scenes[@]}"; do
    name=$(basename "${s%.*}")
    "$build/apps/rt-convert" --extended "$s" "$work/full.scn" >/dev/null
    python3 "$here/scnstrip.py" --highlights "$work/full.scn" "$work/nohl.scn"
    python3 "$here/scnstrip.py" --normals "$work/full.scn" "$work/flat.scn"
    python3 "$here/scnstrip.py" --normals --highlights "$work/full.scn" \
        "$work/none.scn"
    read -r m smooth shiny < <(count "$work/full.scn")
    full=$(render "$work/full.scn")
    nohl=$(render "$work/nohl.scn")
    flat=$(render "$work/flat.scn")
    none=$(render "$work/none.scn")
    ra=$(rays "$work/full.scn")
    rd=$(rays "$work/none.scn")
    awk -v n="$name" -v m="$m" -v sm="$smooth" -v sh="$shiny" -v a="$full" \
        -v b="$nohl" -v c="$flat" -v d="$none" -v ra="$ra" -v rd="$rd" 'BEGIN {
        printf "| %s | %d | %d | %d | %.3f s | %.3f s | %.3f s | %.3f s | %d / %d | %.0f / %.0f |\n",
               n, m, sm, sh, a, b, c, d, ra, rd, 1e9 * a / ra, 1e9 * d / rd }'
done
