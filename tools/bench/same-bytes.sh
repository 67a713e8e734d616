#!/usr/bin/env bash
# same-bytes.sh OLD NEW [OUTDIR] - renders every scene of the project (and
# the course's and the SPD scenes of ../shared when that folder is there)
# with two rt-export binaries, OLD and NEW, under eleven option sets (sizes,
# both precisions, the octree, the kd-tree, the scalar loops, samples, stratified
# sampling, a lens), and compares the images byte for byte: how a change
# that must not move a pixel (a restructuring, a faster path) is checked
# against the binary before it.  Prints each difference and a count; exits
# 1 when an image or an exit status differs.
set -u
old=$1 new=$2 out=${3:-$(mktemp -d)}
root=$(cd "$(dirname "$0")/../.." && pwd)
shared=$root/../shared
mkdir -p "$out"
scenes=("$root"/scenes/*.scn "$root"/scenes/*.nff "$root"/tests/data/obj/*.obj
        "$shared"/seed-scenes/*.scn "$shared"/spd-scenes/*.scn
        "$shared"/formats/*.nff)
variants=(""
          "--size 96x72"
          "--size 96x72 --precision float"
          "--size 96x72 --accel octree"
          "--size 96x72 --accel octree --precision float"
          "--size 96x72 --accel kdtree -j3"
          "--size 96x72 --accel kdtree --precision float"
          "--size 64x48 --kernel scalar --accel none"
          "--size 64x48 --kernel scalar --accel none --precision float"
          "--size 48x36 --samples 4 --sampling stratified -j1"
          "--size 48x36 --samples 4 --aperture 0.05 --precision float")
n=0 differ=0 status=0
for s in "${scenes[@]}"; do
    [ -f "$s" ] || continue
    for v in "${variants[@]}"; do
        n=$((n + 1))
        b=$(basename "$s")
        tag=$(echo "$v" | tr -c 'a-z0-9' '_')
        # shellcheck disable=SC2086 # the options are words
        "$old" "$s" -q $v -o "$out/old-$b-$tag.ppm" >/dev/null 2>&1
        ro=$?
        # shellcheck disable=SC2086
        "$new" "$s" -q $v -o "$out/new-$b-$tag.ppm" >/dev/null 2>&1
        rn=$?
        if [ "$ro" -ne "$rn" ]; then
            echo "exit status $b [$v]: $ro, then $rn"
            status=$((status + 1))
        elif [ "$ro" -eq 0 ] &&
             ! cmp -s "$out/old-$b-$tag.ppm" "$out/new-$b-$tag.ppm"; then
            echo "differ $b [$v]"
            differ=$((differ + 1))
        fi
    done
done
echo "same-bytes: $n renders, $differ differ, $status exit-status mismatches"
[ "$differ" -eq 0 ] && [ "$status" -eq 0 ]
