#!/usr/bin/env bash
# ray-budget.sh - instructions per ray by kind, counted by callgrind
# (docs/performance.md, "Small scenes: the cost of each ray").
#
#   tools/bench/ray-budget.sh BUILD_DIR [SCENE.scn ...]
#
# Renders each scene (default scenes/cubes.scn and scenes/mirror.scn) with
# BUILD_DIR's rt-export on one thread at SIZE (default 480x270, the same
# mix of rays per camera ray as 1920x1080) under valgrind's callgrind,
# which counts instructions exactly whatever the load.  Each query's
# function, with the facet tests inlined in it, is charged to its kind of
# ray: camera rays (packet_nearest, tile_make, nearest_eye_avx2), shadow
# rays (packet_any_hit, any_hit_avx2, any_hit_scalar), reflection rays
# (nearest_avx2, nearest_scalar); the rest of the program (camera rays'
# directions, shading, hit points, offsets, the image) is divided among all
# rays.  A function the compiler inlined away is reported, not guessed.
# Needs valgrind.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:?usage: ray-budget.sh BUILD_DIR [SCENE.scn ...]}
shift
scenes=("$@")
[ ${#scenes[@]} -eq 0 ] && scenes=("$here/../../scenes/cubes.scn" "$here/../../scenes/mirror.scn")
size=${SIZE:-480x270}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

echo "| scene ($size, 1 thread) | rays: camera / shadow / reflection | camera ray query | shadow ray query | reflection ray query | the rest, per ray | all, per ray |"
echo "|---|--:|--:|--:|--:|--:|--:|"
for s in "${scenes[@]}"; do
    valgrind --tool=callgrind --callgrind-out-file="$work/cg" \
        "$build/apps/rt-export" "$s" -o "$work/out.ppm" -j 1 --size "$size" \
        --stats -q >/dev/null 2>"$work/stats"
    callgrind_annotate --inclusive=yes --show-percs=no "$work/cg" >"$work/annotated" 2>/dev/null
    read -r camera shadow reflection < <(awk '/^rays:/ {
        for (i = 1; i <= NF; i++) {
            if ($i ~ /^camera/) c = $(i - 1)
            if ($i ~ /^shadow/) s = $(i - 1)
            if ($i ~ /^reflection/) r = $(i - 1)
        }
        print c, s, r }' "$work/stats")
    awk -v name="$(basename "$s")" -v c="$camera" -v s="$shadow" \
        -v r="$reflection" '
        function kind(f) {
            if (f ~ /:(packet_nearest|tile_make|nearest_eye_avx2)([.][a-z0-9.]*)? /) return "camera"
            if (f ~ /:(packet_any_hit|any_hit_avx2|any_hit_scalar)([.][a-z0-9.]*)? /) return "shadow"
            if (f ~ /:(nearest_avx2|nearest_scalar)([.][a-z0-9.]*)? /) return "reflection"
            return ""
        }
        /PROGRAM TOTALS/ { v = $1; gsub(/,/, "", v); total = v }
        $1 ~ /^[0-9,]+$/ && $2 ~ /:/ {
            v = $1; gsub(/,/, "", v)
            k = kind($2 " ")
            if (k != "") { cost[k] += v; seen[k] = 1 }
        }
        END {
            rays = c + s + r
            rest = total - cost["camera"] - cost["shadow"] - cost["reflection"]
            printf "| %s | %d / %d / %d |", name, c, s, r
            n["camera"] = c; n["shadow"] = s; n["reflection"] = r
            split("camera shadow reflection", kinds, " ")
            for (j = 1; j <= 3; j++) {
                k = kinds[j]
                if (n[k] == 0) printf " - |"
                else if (!seen[k]) printf " (inlined) |"
                else printf " %.0f |", cost[k] / n[k]
            }
            printf " %.0f | %.0f |\n", rest / rays, total / rays
        }' "$work/annotated"
done
