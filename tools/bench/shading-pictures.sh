#!/usr/bin/env bash
# shading-pictures.sh - before, after and POV-Ray side by side (docs/shading.md).
#
#   tools/bench/shading-pictures.sh BUILD OLD_BUILD OUT_DIR SCENE ...
#
# For each SCENE (any of our formats), writes OUT_DIR/shading-NAME.png: three
# pictures of SIZE (default 320x240), labelled, side by side:
#   before   OLD_BUILD's rt-export (main before smooth shading and highlights,
#            commit 69deee2) on SCENE itself: flat facets, no highlights
#            (a .scn with the records that reader lacks is first cut to the
#            ones it has by scnstrip.py --normals --highlights --course; one
#            whose d is not 1 - k - t, which no record of that reader holds,
#            is rendered by BUILD without its normals and highlights, which
#            is byte for byte what a scene without them rendered before);
#   after    BUILD's rt-export on SCENE; an OBJ model without `vn` lines is
#            given area-weighted vertex normals first (add-normals.py);
#   POV-Ray  POV-Ray 3.7 on what `rt-convert --extended` writes of the same
#            input (scn2pov.py: smooth_triangle, phong, interior).
# DEPTH (default 5) is the depth of every render.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:?usage: shading-pictures.sh BUILD OLD_BUILD OUT_DIR SCENE ...}
old=${2:?usage: shading-pictures.sh BUILD OLD_BUILD OUT_DIR SCENE ...}
out=${3:?usage: shading-pictures.sh BUILD OLD_BUILD OUT_DIR SCENE ...}
shift 3
size=${SIZE:-320x240}
depth=${DEPTH:-5}
w=${size%x*}
h=${size#*x}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"

label() {   # in.png text out.png
    convert "$1" -fill white -undercolor '#00000080' -pointsize 13 \
        -gravity northwest -annotate +4+4 "$2" "$3"
}

for s in "$@"; do
    name=$(basename "${s%.*}")
    in=$s
    before=$s
    flat=$old
    case $s in
    *.scn)
        before=$work/before.scn
        if ! python3 "$here/scnstrip.py" --normals --highlights --course \
                "$s" "$before" 2>/dev/null; then
            python3 "$here/scnstrip.py" --normals --highlights "$s" "$before"
            flat=$build
        fi ;;
    *.obj)
        if ! grep -q '^vn ' "$s"; then
            cp "$(dirname "$s")"/*.mtl "$work"/ 2>/dev/null || true
            in=$work/$name.obj
            python3 "$here/add-normals.py" "$s" "$in"
        fi ;;
    esac
    "$flat/apps/rt-export" -q -j2 --size "$size" --depth "$depth" "$before" \
        -o "$work/before.png" >/dev/null
    "$build/apps/rt-export" -q -j2 --size "$size" --depth "$depth" "$in" \
        -o "$work/after.png" >/dev/null
    "$build/apps/rt-convert" --extended "$in" "$work/$name.scn" >/dev/null
    python3 "$here/scn2pov.py" "$work/$name.scn" "$depth" "$w" "$h" \
        >"$work/$name.pov"
    povray +I"$work/$name.pov" +O"$work/pov.png" +W"$w" +H"$h" -D -A +WT2 \
        File_Gamma=1.0 >/dev/null 2>&1
    # POV-Ray marks its PNG linear (gAMA 1); the values are already ours
    convert "$work/pov.png" -set colorspace sRGB "$work/pov8.png"
    label "$work/before.png" "before (flat)" "$work/a.png"
    label "$work/after.png" "after" "$work/b.png"
    label "$work/pov8.png" "POV-Ray 3.7" "$work/c.png"
    convert "$work/a.png" "$work/b.png" "$work/c.png" +append \
        "$out/shading-$name.png"
    echo "$out/shading-$name.png"
done
