#!/usr/bin/env bash
# bare-debian.sh - install the .deb on a bare Debian and use it there.
#
#   tools/package/bare-debian.sh build/raytrace_0.5.0_amd64.deb [SUITE]
#
# Builds a minimal Debian (debootstrap --variant=minbase, SUITE bookworm by
# default) in a temporary folder, copies the package in, and inside it (in a
# chroot):
#   1. `dpkg -i` the package: on a bare system it unpacks, then stops at the
#      first shared library the system lacks (libpng16-16 at least);
#   2. `apt-get -f install` brings those libraries in and configures it;
#   3. every installed program answers --version, has its manual page, and
#      rt-export renders an installed scene to a PNG whose size is checked;
#   4. `dpkg -r` removes it and leaves none of its files.
# A bare system's apt also takes the package in one step
# (`apt install ./raytrace_*.deb`); step 1-2 is the dpkg form.
#
# Needs root, debootstrap (Debian package `debootstrap`) and a Debian mirror
# (DEBIAN_MIRROR, http://deb.debian.org/debian by default).  With
# BARE_DEBIAN_PICTURE=file.png the render is copied out to look at.  Not part of
# `make test`: it downloads about 100 MB and runs a few minutes.  Prints what
# each step did and exits non-zero at the first that fails.
set -euo pipefail

deb=${1:?usage: bare-debian.sh PACKAGE.deb [SUITE]}
suite=${2:-bookworm}
mirror=${DEBIAN_MIRROR:-http://deb.debian.org/debian}

[ "$(id -u)" -eq 0 ] || { echo "bare-debian.sh: needs root (chroot)" >&2; exit 2; }
command -v debootstrap >/dev/null ||
    { echo "bare-debian.sh: needs debootstrap (apt-get install debootstrap)" >&2; exit 2; }
[ -f "$deb" ] || { echo "bare-debian.sh: no package $deb" >&2; exit 2; }

root=$(mktemp -d /tmp/bare-debian.XXXXXX)
cleanup() {
    umount "$root/proc" 2>/dev/null || true
    rm -rf "$root"
}
trap cleanup EXIT

echo "== debootstrap --variant=minbase $suite"
debootstrap --variant=minbase "$suite" "$root" "$mirror" > "$root.log" 2>&1 ||
    { tail -n 20 "$root.log" >&2; rm -f "$root.log"; exit 1; }
rm -f "$root.log"
mount -t proc proc "$root/proc"
echo "packages installed before: $(chroot "$root" dpkg-query -f '.\n' -W | wc -l)"
cp "$deb" "$root/tmp/raytrace.deb"

chroot "$root" /bin/bash -euo pipefail -c '
export DEBIAN_FRONTEND=noninteractive LC_ALL=C
echo "== dpkg -i"
if dpkg -i /tmp/raytrace.deb > /tmp/dpkg.log 2>&1; then
    echo "dpkg -i: installed at once (the system had every library)"
else
    grep -E "depends on|not installed" /tmp/dpkg.log | sed "s/^/  /"
    echo "== apt-get -f install"
    apt-get update -qq
    apt-get -f install -y -qq > /tmp/apt.log 2>&1 || { tail -n 20 /tmp/apt.log; exit 1; }
    grep -E "^(Get|Setting up raytrace)" /tmp/apt.log | wc -l |
        sed "s/^/  apt lines (downloads and raytrace set up): /"
fi
dpkg-query -W -f "status: \${Status}, version \${Version}\n" raytrace
echo "== the programs"
for program in $(dpkg -L raytrace | grep "^/usr/bin/"); do
    name=${program##*/}
    "$program" --version
    [ -f "/usr/share/man/man1/$name.1" ] || [ -f "/usr/share/man/man1/$name.1.gz" ] ||
        { echo "no manual page for $name"; exit 1; }
done
echo "== rt-export on an installed scene"
cd /tmp
rt-export /usr/share/raytrace/scenes/cubes.scn -o cubes.png --size 320x240
head -c 24 cubes.png | od -An -tx1 | tr -d " \n" | cut -c1-16 | grep -qx 89504e470d0a1a0a ||
    { echo "cubes.png is not a PNG"; exit 1; }
width=$(od -An -tu1 -j16 -N4 cubes.png | awk "{print \$1*16777216+\$2*65536+\$3*256+\$4}")
height=$(od -An -tu1 -j20 -N4 cubes.png | awk "{print \$1*16777216+\$2*65536+\$3*256+\$4}")
echo "cubes.png: PNG ${width}x${height}, $(wc -c < cubes.png) bytes"
[ "$width" = 320 ] && [ "$height" = 240 ]
echo "== dpkg -r"
dpkg -L raytrace | grep -E "^/usr/(bin|lib|include|share/raytrace)/" | sort > /tmp/files
dpkg -r raytrace > /dev/null
left=0
while read -r file; do [ -f "$file" ] && { echo "left behind: $file"; left=1; }; done < /tmp/files
[ "$left" -eq 0 ]
echo "removed: $(wc -l < /tmp/files) files gone"
'
if [ -n "${BARE_DEBIAN_PICTURE:-}" ]; then
    cp "$root/tmp/cubes.png" "$BARE_DEBIAN_PICTURE"
    echo "the render is in $BARE_DEBIAN_PICTURE"
fi
echo "bare-debian.sh: the package installs, runs and is removed on a bare $suite"
