#!/usr/bin/env bash
# accel-study.sh - the octree against the kd-tree on the same scenes, in
# one run: the study the handout asks for (docs/kdtree.md, "The octree
# and the kd-tree compared").
#
#   tools/bench/accel-study.sh BUILD_DIR [SCENE ...]
#
# Default scenes: the SPD scenes (../shared/spd-scenes/*.scn) and the
# project's cubes and mirror.  Each is rendered at SIZE (default 400x400)
# with --threads 1 by `--accel octree` and `--accel kdtree`, taking turns,
# ROUNDS times (default 3); the table gives, per structure, its counts
# (exact: facets tested, traversal steps and leaves per query, references
# and bytes per facet, from --stats=json), its build seconds and the least
# render time less the build (the render alone), and whether the two
# images are the same bytes.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:?usage: accel-study.sh BUILD_DIR [SCENE ...]}
shift
rounds=${ROUNDS:-3}
size=${SIZE:-400x400}
. "$here/setup.sh"

scenes=("$@")
if [ ${#scenes[@]} -eq 0 ]; then
    scenes=("$here"/../../../shared/spd-scenes/*.scn
            "$here/../../scenes/cubes.scn" "$here/../../scenes/mirror.scn")
fi

run() {     # scene accel -> the --stats=json object
    "$build/apps/rt-export" "$1" -o "$work/$2.ppm" --threads 1 \
        --size "$size" --accel "$2" --stats=json -q 2>&1 >/dev/null | tail -1
}

echo "| scene | facets | structure | tests/query | steps/query | leaves/query | references/facet | bytes/facet | build s | render s (less build) | same image |"
echo "|---|--:|---|--:|--:|--:|--:|--:|--:|--:|:-:|"
for s in "${scenes[@]}"; do
    for a in octree kdtree; do
        : >"$work/$a.json"
    done
    for _ in $(seq "$rounds"); do
        for a in octree kdtree; do
            run "$s" "$a" >>"$work/$a.json"
        done
    done
    same=no
    cmp -s "$work/octree.ppm" "$work/kdtree.ppm" && same=yes
    for a in octree kdtree; do
        python3 - "$work/$a.json" "$(basename "$s" .scn)" "$a" "$same" <<'EOF'
import json, sys
runs = [json.loads(line) for line in open(sys.argv[1]) if line.strip()]
key = "kdtree" if sys.argv[3] == "kdtree" else "octree"
s = runs[0][key]
alone = min(r["seconds"]["render"] - r[key]["build_seconds"] for r in runs)
build = min(r[key]["build_seconds"] for r in runs)
q = max(s["queries"], 1)
print("| %s | %d | %s | %.2f | %.2f | %.2f | %.2f | %.1f | %.3f | %.3f | %s |" % (
    sys.argv[2], s["facets"], sys.argv[3], s["facet_tests"] / q,
    s["steps"] / q, s["leaves_visited"] / q, s["references_per_facet"],
    s["bytes_per_facet"], build, alone, sys.argv[4]))
EOF
    done
done
