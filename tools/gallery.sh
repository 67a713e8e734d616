#!/usr/bin/env bash
# gallery.sh - renders the gallery: every scene of scenes/ and the models the
# project's generators write, into docs/images/gallery/NAME.png, and writes
# docs/gallery.md (the only source of that file) with each picture, the
# exact command that made it and its render time.
#
#   bash tools/gallery.sh            (from anywhere; `make gallery` builds
#                                     rt-export first and runs it)
#
# Every command is run from the repository root exactly as docs/gallery.md
# prints it (one string, given to bash -c), so that the page cannot show a
# command other than the one that made the picture.  The scenes of scenes/
# are found by glob (*.scn, *.nff, *.obj, *.ply): a scene added there appears
# at the next run.  Generated scenes go to $RT_BUILD/gallery/ (never committed).
# The render time is rt-export's own (--stats=json: seconds.render, the
# facets from memory.facets), measured on the machine that ran the script:
# it is a note on that run, not a benchmark.
#
# Environment: RT_BUILD (the build directory, relative to the root: build,
# as make's; the commands run and printed name $RT_BUILD/apps/rt-export),
# PYTHON (python3), GALLERY_SIDE (the longer side of a picture, 320).
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"

build=${RT_BUILD:-build}
rt=$build/apps/rt-export
side=${GALLERY_SIDE:-320}
python=${PYTHON:-python3}
if [[ ! -x $rt ]]; then
  echo "gallery.sh: $rt not found: run 'make gallery' (or build rt-export)" >&2
  exit 1
fi
command -v "$python" >/dev/null || {
  echo "gallery.sh: $python not found (the generators and the JSON need it)" >&2
  exit 1
}

out=docs/images/gallery
work=$build/gallery
mkdir -p "$out" "$work"
rm -f "$out"/*.png
md=$work/gallery.md.new
entries=$work/entries.md
: >"$entries"
count=0

# size_for SCENE [OPTIONS...]: the scene's own image size, scaled so that the
# longer side is $side (same aspect ratio, so the framing is the scene's).
size_for() {
  local w h
  read -r w h < <("$rt" --check "$@" | awk '$1 == "image" { print $2, $4; exit }')
  if (( w >= h )); then
    echo "${side}x$(( (h * side + w / 2) / w ))"
  else
    echo "$(( (w * side + h / 2) / h ))x${side}"
  fi
}

# shot NAME TITLE DESCRIPTION PREPARE RENDER: runs PREPARE (a command that
# writes the scene, or ""), then RENDER (an rt-export command writing
# $out/NAME.png, without -q --stats=json, which shot adds), and appends the
# entry.
shot() {
  local name=$1 title=$2 text=$3 prepare=$4 render="$5 -q --stats=json"
  local json=$work/$name.json
  echo "gallery: $name" >&2
  if [[ -n $prepare ]]; then
    bash -c "$prepare"
  fi
  if ! bash -c "$render" 2>"$json" >/dev/null; then
    echo "gallery.sh: $name: the render failed:" >&2
    cat "$json" >&2
    exit 1
  fi
  local facts
  facts=$(tail -n 1 "$json" | "$python" -c '
import json, sys
d = json.load(sys.stdin)
print("%.3f s to render (%.4f s to load), %s facets, %d x %d, %d ray%s a pixel" % (
    d["seconds"]["render"], d["seconds"]["load"],
    format(d["memory"]["facets"], ",d"), d["width"], d["height"],
    d["samples"], "" if d["samples"] == 1 else "s"))')
  {
    printf '## %s\n\n' "$title"
    printf '![%s](images/gallery/%s.png)\n\n' "$text" "$name"
    printf '%s.\n\n' "$facts"
    printf '```sh\n'
    if [[ -n $prepare ]]; then
      printf '%s\n' "$prepare"
    fi
    printf '%s\n```\n\n' "$render"
  } >>"$entries"
  count=$((count + 1))
}

# What each shipped scene shows, and the options its render needs; a scene
# not named here gets its file name and no option.
describe() {
  case $1 in
    cubes.scn) echo "The handout's cube above a reflective floor";;
    empty.scn) echo "No facets at all: every pixel is the background";;
    focus.scn) echo "Depth of field: five cubes, the middle one in focus";;
    glass.scn) echo "The cube through a glass slab, two coloured lights";;
    mirror.scn) echo "The cube and a mirror wall behind it";;
    nff-sphere.nff) echo "An NFF sphere, tessellated, lit from the eye";;
    one-facet.scn) echo "One triangle seen from above";;
    two-facets.scn) echo "A small triangle casting its shadow on a large one";;
    smooth-glass.scn) echo "A smooth glass ball before a checkered wall";;
    smooth-sphere.scn) echo "An 80-facet sphere with vertex normals, smooth";;
    teapot.scn) echo "The Utah teapot: smooth shading, highlights, two lights";;
    *) echo "$1";;
  esac
}
options() {
  case $1 in
    focus.scn) echo " --samples 16";;
    *) echo "";;
  esac
}

# 1. The shipped scenes.
shopt -s nullglob
for scene in scenes/*.scn scenes/*.nff scenes/*.obj scenes/*.ply; do
  base=${scene#scenes/}
  name=${base%.*}-${base##*.}
  name=${name%-scn}
  opts=$(options "$base")
  size=$(size_for "$scene")
  shot "$name" "scenes/$base" "$(describe "$base")" "" \
    "$rt $scene -o $out/$name.png --size $size$opts"
done

# 2. Another view of a shipped scene, with the command line's camera and
# lights.
shot cubes-view "scenes/cubes.scn from the command line's camera, two lights" \
  "The cube seen lower, lit by a warm and a cool light" "" \
  "$rt scenes/cubes.scn -o $out/cubes-view.png --size 320x240 --look-from 12,-4,9 --look-at 0,0,1 --fov 50 --light 4,-6,10,255,220,180 --light -5,-3,8,80,120,255"
shot teapot-normals "scenes/teapot.scn, the shading normals (--view shading-normal)" \
  "The teapot coloured by its interpolated normals" "" \
  "$rt scenes/teapot.scn -o $out/teapot-normals.png --size 320x240 --view shading-normal"

# 3. Models the project generates: the SPD sphereflake as NFF spheres and
# as polygons, a terrain as .scn, OBJ (flat and with vertex normals) and
# PLY.
shot balls-nff "The SPD sphereflake, size 2, NFF spheres (tools/bench/balls-nff.py)" \
  "91 balls in a fractal flake on an orange floor, smooth, with highlights" \
  "mkdir -p $work && $python tools/bench/balls-nff.py 2 > $work/balls-s2.nff" \
  "$rt $work/balls-s2.nff -o $out/balls-nff.png --size 320x320"
shot balls-scn "The SPD sphereflake, size 2, polygon spheres (tools/bench/sphereflake.py)" \
  "The same flake, each ball the SPD's 108-facet polygon sphere, flat" \
  "mkdir -p $work && $python tools/bench/sphereflake.py 2 > $work/balls-s2.scn" \
  "$rt $work/balls-s2.scn -o $out/balls-scn.png --size 320x320"
shot terrain-scn "A height field of 2 x 60 x 60 facets (tools/bench/terrain.py)" \
  "A rolling grey-green terrain seen from the south-west" \
  "mkdir -p $work && $python tools/bench/terrain.py 60 > $work/terrain-60.scn" \
  "$rt $work/terrain-60.scn -o $out/terrain-scn.png --size 320x320"
shot terrain-obj "The same terrain as an OBJ, with vertex normals (terrain.py --obj, add-normals.py)" \
  "The terrain of an OBJ under the automatic camera (z up) and light, smooth" \
  "mkdir -p $work && $python tools/bench/terrain.py --obj 60 > $work/terrain-60.obj && $python tools/bench/add-normals.py $work/terrain-60.obj $work/terrain-60-smooth.obj" \
  "$rt $work/terrain-60-smooth.obj -o $out/terrain-obj.png --size 320x240 --up-axis z"
shot terrain-ply "The same terrain as a binary PLY (tools/bench/plygen.py)" \
  "The terrain of a PLY under the automatic camera (z up) and light, flat facets" \
  "mkdir -p $work && $python tools/bench/plygen.py 60 > $work/terrain-60.ply" \
  "$rt $work/terrain-60.ply -o $out/terrain-ply.png --size 320x240 --up-axis z"
shot teapot-generated "The teapot as tools/scenes/smooth_scenes.py writes it, from the handle's side" \
  "The teapot seen from behind its handle, the blue light's highlight on its body" \
  "mkdir -p $work/smooth && $python tools/scenes/smooth_scenes.py $work/smooth" \
  "$rt $work/smooth/teapot.scn -o $out/teapot-generated.png --size 320x240 --look-from -10,-7,4.5 --look-at 0,0,1 --fov 45"

{
  echo "<!-- generated by make gallery (tools/gallery.sh); do not edit -->"
  echo "# Gallery"
  echo
  echo "A picture of every scene in [\`scenes/\`](../scenes) and of models the"
  echo "project's own generators write (NFF, OBJ, PLY), each with the command"
  echo "that made it, run from the repository root after \`make\` (or"
  echo "\`make gallery\`, which renders them all again and rewrites this page)."
  echo "Times are rt-export's \`--stats=json\` (\`seconds.render\`) on the machine"
  echo "that last ran \`make gallery\` ($(nproc) cores), rendering at the"
  echo "size shown; they vary from run to run."
  echo
  echo "$count pictures, $(du -ch "$out"/*.png | awk 'END { print $1 }') in all."
  echo
  cat "$entries"
} >"$md"
mv "$md" docs/gallery.md
echo "gallery: $count pictures in $out, docs/gallery.md" >&2
