#!/usr/bin/env bash
# embree_peer_rays.sh - rt-embree-peer (tools/bench/embree-peer) casts the
# rays rt-export casts: on scenes/glass.scn (mirrors, glass, refraction,
# total internal reflection) and scenes/cubes.scn, its camera ray count
# equals rt-export's and its shadow, reflection and refraction counts are
# within 0.5 % of rt-export's --stats=json (Embree's float hits differ from
# our exact ones on a few grazing rays), each kind the scene has being
# non-zero in both.  No timing is checked.
#
# Environment: RT_EMBREE_PEER, RT_EXPORT (the programs), RT_SOURCE_DIR.
set -u
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

for scene in glass cubes; do
    file="$RT_SOURCE_DIR/scenes/$scene.scn"
    [ -f "$file" ] || { echo "SKIP: no $file"; exit 77; }
    peer=$("$RT_EMBREE_PEER" "$file" --threads 1) ||
        fail "rt-embree-peer failed on $scene.scn"
    ours=$("$RT_EXPORT" "$file" -o "$work/out.ppm" --threads 1 \
           --stats=json -q 2>&1 >/dev/null | tail -n 1 |
           sed 's/.*"rays":{"camera":\([0-9]*\),"shadow":\([0-9]*\),"reflection":\([0-9]*\),"refraction":\([0-9]*\).*/\1 \2 \3 \4/')
    echo "$scene: rt-export $ours; $peer"
    echo "$ours" | grep -Eq '^[0-9]+ [0-9]+ [0-9]+ [0-9]+$' ||
        fail "no ray counts in rt-export's --stats=json"
    echo "$peer" | awk -v ours="$ours" -v scene="$scene" '
        /^embree: / {
            split(ours, o, " ");
            e[1] = $11; e[2] = $13; e[3] = $15; e[4] = $17;
            if (e[1] != o[1]) {
                print "camera rays: " e[1] " against " o[1]; bad = 1;
            }
            for (k = 2; k <= 4; k++) {
                d = e[k] - o[k]; if (d < 0) d = -d;
                if (d > 0.005 * o[k] || (o[k] == 0) != (e[k] == 0)) {
                    print "ray kind " k ": " e[k] " against " o[k]; bad = 1;
                }
            }
            seen = 1;
        }
        END {
            if (!seen) { print "no embree: line"; exit 1 }
            if (scene == "glass" && (o[4] == 0 || o[3] == 0)) {
                print "glass.scn casts no refraction or reflection rays";
                exit 1;
            }
            exit bad;
        }' || fail "$scene.scn: the counts disagree"
done
echo "rt-embree-peer casts rt-export's rays"
