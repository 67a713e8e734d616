#!/usr/bin/env bash
# crossover.sh - where a structure starts to pay: brute force, the octree
# and the kd-tree on small scenes, one thread, in one run (docs/kdtree.md,
# "What auto chooses").
#
#   tools/bench/crossover.sh BUILD_DIR [SCENE ...]
#
# Default scenes: the project's cubes and mirror, the handout's SPD scenes
# of fewer than 5,000 facets, and spheres of 24 to 3,200 facets written
# here as OBJ files (a latitude-longitude sphere, framed and lit as
# rt-export frames an OBJ file).  Each is rendered at SIZE (default 400x400) with --threads 1 by
# `--accel none`, `octree` and `kdtree`, taking turns, ROUNDS times
# (default 5); the table gives the least render time of each (--stats;
# the least is the least disturbed by a loaded machine; the structure's
# build included, as a user pays it) and the fastest choice.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:?usage: crossover.sh BUILD_DIR [SCENE ...]}
shift
rounds=${ROUNDS:-5}
size=${SIZE:-400x400}
. "$here/setup.sh"

sphere() {  # facets (about) file: a lat-long sphere, camera and light
    python3 - "$1" "$2" <<'EOF'
import math, sys
target, path = int(sys.argv[1]), sys.argv[2]
rows = max(2, int(round(math.sqrt(target / 2))))
cols = max(3, target // (2 * rows) + (target % (2 * rows) > 0))
with open(path, "w") as f:
    for i in range(rows + 1):
        th = math.pi * i / rows
        for j in range(cols):
            ph = 2 * math.pi * j / cols
            f.write("v %.9f %.9f %.9f\n" % (math.sin(th) * math.cos(ph),
                    math.sin(th) * math.sin(ph), math.cos(th)))
    for i in range(rows):
        for j in range(cols):
            a = i * cols + j + 1
            b = i * cols + (j + 1) % cols + 1
            c, d = a + cols, b + cols
            if i > 0:
                f.write("f %d %d %d\n" % (a, b, d))
            if i < rows - 1:
                f.write("f %d %d %d\n" % (a, d, c))
EOF
}

scenes=("$@")
if [ ${#scenes[@]} -eq 0 ]; then
    scenes=("$here/../../scenes/cubes.scn" "$here/../../scenes/mirror.scn")
    for s in tetra-s2 tetra-s4 teapot-s2 mount-s2 tetra-s6 gears-s2; do
        f="$here/../../../shared/spd-scenes/$s.scn"
        [ -f "$f" ] && scenes+=("$f")
    done
    for n in 24 50 100 200 400 800 1600 3200; do
        sphere "$n" "$work/sphere-$n.obj"
        scenes+=("$work/sphere-$n.obj")
    done
fi

render_time() {     # scene accel -> seconds of one render (--stats)
    "$build/apps/rt-export" "$1" -o "$work/out.ppm" --threads 1 \
        --size "$size" --accel "$2" --stats -q 2>&1 >/dev/null |
        sed -n 's/^time: .*render \([0-9.]*\) s.*/\1/p'
}

echo "| scene | facets | none | octree | kdtree | fastest |"
echo "|---|--:|--:|--:|--:|---|"
for s in "${scenes[@]}"; do
    declare -A best=([none]=1e9 [octree]=1e9 [kdtree]=1e9)
    for _ in $(seq "$rounds"); do
        for a in none octree kdtree; do
            t=$(render_time "$s" "$a")
            best[$a]=$(awk -v a="$t" -v b="${best[$a]}" 'BEGIN { print (a < b ? a : b) }')
        done
    done
    n=$("$build/apps/rt-export" "$s" -o "$work/out.ppm" --size 8x8 \
        --accel kdtree --stats -q 2>&1 >/dev/null |
        sed -n 's/.*(brute force: \([0-9]*\)).*/\1/p' | head -1)
    fastest=$(printf '%s %s\n' none "${best[none]}" octree "${best[octree]}" \
        kdtree "${best[kdtree]}" | sort -g -k2 | head -1 | cut -d' ' -f1)
    echo "| $(basename "$s") | $n | ${best[none]} | ${best[octree]} | ${best[kdtree]} | $fastest |"
    unset best
done
