#!/usr/bin/env bash
# hostile-probes.sh [BIN_DIR] - the hostile inputs of the third round's
# first issue (docs/robustness-input.md), written into a work folder and
# each loaded and rendered by BIN_DIR/rt-export (default build/apps): its
# exit status, seconds and peak memory (GNU time, /usr/bin/time) and the
# first line it printed.  What a stranger's small file may cost is the
# question; the budgets that answer it are the loader's named constants.
# The files take about 70 MB; the work folder is removed at exit.
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$root/build/apps}
[ -x /usr/bin/time ] || { echo "hostile-probes: needs GNU time (/usr/bin/time)"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
python3 - <<'PY'
import math, os
W = open
os.makedirs('m', exist_ok=True)
W('m/shadow.obj', 'w').write('mtllib /etc/shadow\nmtllib /proc/self/maps\n'
    'mtllib ../x.mtl\nmtllib nosuch.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n')
view = 'v\nfrom 0 0 0\nat 0 0 1\nup 0 1 0\nangle 45\nhither 1\nresolution 400 400\nl 0 5 0\nf 1 0 0 1 0 0 0 0\n'
W('around.nff', 'w').write(view + ''.join('s 0 0 0 %g\n' % (1 + i * 0.1) for i in range(20)))
W('behind.nff', 'w').write(view + ''.join('s 0 0 %g 0.5\n' % (-2 - i) for i in range(20)))
W('tiny.nff', 'w').write('v\nfrom 0 0 -1\nat 0 0 0\nup 0 1 0\nangle 45\nhither 1\n'
    'resolution 64 64\nl 0 5 0\nf 1 0 0 1 0 0 0 0\ns 0 0 0 1e-30\n')
W('fan.obj', 'w').write('v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf ' + '1 2 ' * 250000 + '\n')
os.makedirs('sp', exist_ok=True)
W('sp/m.mtl', 'w').write('newmtl red\nKd 1 0 0\n' + '# padding\n' * 700000)
W('sp/s.obj', 'w').write(''.join('mtllib ' + './' * (i % 5) + '/' * (i // 5 % 3) + 'm.mtl\n'
    for i in range(1000)) + 'usemtl red\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n')
os.makedirs('self', exist_ok=True)
W('self/s.obj', 'w').write('mtllib s.obj\n' * 20 + 'v 0 0 0\nv 1 0 0\nv 0 1 0\n' + 'f 1 2 3\n' * 100000)
n = 1000000
W('convex.obj', 'w').write(''.join('v %.9f %.9f 0\n' % (math.cos(2 * math.pi * i / n),
    math.sin(2 * math.pi * i / n)) for i in range(n)) + 'f ' + ' '.join(str(i + 1) for i in range(n)) + '\n')
W('names.obj', 'w').write('v 0 0 0\nv 1 0 0\nv 0 1 0\n' + ''.join('usemtl name%d\nf 1 2 3\n' % i for i in range(1000000)))
W('lights.nff', 'w').write('v\nfrom 0 0 -5\nat 0 0 0\nup 0 1 0\nangle 45\nhither 1\nresolution 400 400\n'
    + ''.join('l %d 5 -5\n' % i for i in range(100000)) + 'f 1 0 0 1 0 0 0 0\np 3\n-1 -1 0\n1 -1 0\n0 1 0\n')
W('kst.nff', 'w').write('v\nfrom 0 0 -5\nat 0 0 0\nup 0 1 0\nangle 45\nhither 1\nresolution 64 64\n'
    'l 0 5 -5\nf 1 0 0 1 1e308 0 1e308 1.5\np 3\n-1 -1 0\n1 -1 0\n0 1 0\n')
os.makedirs('order', exist_ok=True)
W('order/m.mtl', 'w').write('newmtl red\nKd 1 0 0\n')
W('order/s.obj', 'w').write('usemtl red\nmtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n')
k = 30000
pts = []
for i in range(k):
    pts.append((i, 0))
    pts.append((i + 0.5, 10))
pts += [(k, -1), (0, -1)]
W('comb.obj', 'w').write(''.join('v %g %g 0\n' % p for p in pts) + 'f ' + ' '.join(str(i + 1) for i in range(len(pts))) + '\n')
PY
probe() {
    local label=$1
    shift
    /usr/bin/time -f "%e s %M KB" -o time.txt "$bin/rt-export" "$@" -q -o o.ppm \
        >out.txt 2>err.txt
    local code=$?
    printf '%-32s exit %d  %-18s %s\n' "$label" "$code" "$(tail -n 1 time.txt)" \
        "$(head -n 1 err.txt | cut -c1-110)"
}
probe "mtllib /etc/shadow, maps, .." m/shadow.obj --size 64x64
echo "    lines of /etc/shadow quoted: $(grep -c 'root:' err.txt)"
probe "20 spheres around the eye" around.nff
probe "20 spheres behind the eye" behind.nff
probe "a sphere of radius 1e-30" tiny.nff
probe "f 1 2 1 2 ... (1 MB)" fan.obj --size 64x64
probe "a 7 MB MTL, 1000 spellings" sp/s.obj --size 64x64
probe "an OBJ its own library 20x" self/s.obj --size 64x64
probe "a 1M-corner convex face" convex.obj
probe "10^6 unknown usemtl names" names.obj --size 64x64
probe "100000 lights" lights.nff
probe "Ks = T = 1e308" kst.nff
probe "usemtl before mtllib" order/s.obj --size 64x64
probe "a comb of 60k corners" comb.obj --size 64x64
