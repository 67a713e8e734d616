#!/usr/bin/env bash
# bare-debian.sh - install the .deb on a bare Debian and use it there.
#
#   tools/package/bare-debian.sh build/raytrace_0.5.0_amd64.deb [SUITE]
#
# Builds a minimal Debian (debootstrap --variant=minbase, SUITE bookworm by
# default) in a temporary folder, and in a copy of it for each of the two
# ways of installing a local package (in a chroot):
#   dpkg: `dpkg -i` unpacks it, then stops at the first shared library the
#         bare system lacks; `apt-get -f install` brings them and configures;
#   apt:  `apt-get install ./raytrace.deb` does both at once;
# then checks that every installed program answers --version and has its
# manual page, that rt-export renders an installed scene to a PNG of the
# size asked (and rt-export-mpi, when the package has it, the same bytes on
# 2 ranks), and that `dpkg -r` removes it, leaving none of its files.
#
# Needs root, debootstrap (Debian package `debootstrap`) and a Debian mirror
# (DEBIAN_MIRROR, http://deb.debian.org/debian by default).  With
# BARE_DEBIAN_PICTURE=file.png the render is copied out to look at.  Not
# part of `make test`: it downloads about 100 MB and takes a minute or two.
# Prints what each step did and exits non-zero at the first that fails.
set -euo pipefail

deb=${1:?usage: bare-debian.sh PACKAGE.deb [SUITE]}
suite=${2:-bookworm}
mirror=${DEBIAN_MIRROR:-http://deb.debian.org/debian}

[ "$(id -u)" -eq 0 ] || { echo "bare-debian.sh: needs root (chroot)" >&2; exit 2; }
command -v debootstrap >/dev/null ||
    { echo "bare-debian.sh: needs debootstrap (apt-get install debootstrap)" >&2; exit 2; }
[ -f "$deb" ] || { echo "bare-debian.sh: no package $deb" >&2; exit 2; }

work=$(mktemp -d /tmp/bare-debian.XXXXXX)
cleanup() {
    umount "$work"/*/proc "$work"/*/sys 2>/dev/null || true
    rm -rf "$work"
}
trap cleanup EXIT

echo "== debootstrap --variant=minbase $suite"
debootstrap --variant=minbase "$suite" "$work/bare" "$mirror" > "$work/log" 2>&1 ||
    { tail -n 20 "$work/log" >&2; exit 1; }
echo "packages installed: $(chroot "$work/bare" dpkg-query -f '.\n' -W | wc -l)"

# What runs in the chroot: $1 is the form (dpkg or apt).
# shellcheck disable=SC2016 # expanded in the chroot's shell
inside='
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive LC_ALL=C
cd /tmp
apt-get update -qq 2> /dev/null
if [ "$1" = dpkg ]; then
    echo "== dpkg -i raytrace.deb"
    if dpkg -i raytrace.deb > dpkg.log 2>&1; then
        echo "dpkg -i: installed at once (the system had every library)"
    else
        grep -E "depends on" dpkg.log | sed "s/^ */  /"
        echo "== apt-get -f install"
        apt-get -f install -y -qq > apt.log 2>&1 || { tail -n 20 apt.log; exit 1; }
    fi
else
    echo "== apt-get install ./raytrace.deb"
    apt-get install -y -qq ./raytrace.deb > apt.log 2>&1 || { tail -n 20 apt.log; exit 1; }
fi
echo "packages installed: $(dpkg-query -f ".\n" -W | wc -l)"
dpkg-query -W -f "raytrace: \${Status}, version \${Version}\n" raytrace
echo "== the programs"
for program in $(dpkg -L raytrace | grep "^/usr/bin/."); do
    name=${program##*/}
    "$program" --version
    [ -f "/usr/share/man/man1/$name.1" ] || [ -f "/usr/share/man/man1/$name.1.gz" ] ||
        { echo "no manual page for $name"; exit 1; }
done
echo "== rt-export on an installed scene"
rt-export /usr/share/raytrace/scenes/cubes.scn -o cubes.png --size 320x240
[ "$(od -An -tx1 -N8 cubes.png | tr -d " \n")" = 89504e470d0a1a0a ] ||
    { echo "cubes.png is not a PNG"; exit 1; }
size=$(od -An -tu1 -j16 -N8 cubes.png |
       awk "{print \$1*16777216+\$2*65536+\$3*256+\$4 \"x\" \$5*16777216+\$6*65536+\$7*256+\$8}")
echo "cubes.png: PNG $size, $(wc -c < cubes.png) bytes"
[ "$size" = 320x240 ]
if [ -x /usr/bin/rt-export-mpi ]; then
    echo "== rt-export-mpi on 2 ranks"
    mpirun --allow-run-as-root --oversubscribe -np 2 rt-export-mpi \
        /usr/share/raytrace/scenes/cubes.scn -o cubes-mpi.png --size 320x240
    cmp cubes.png cubes-mpi.png
    echo "cubes-mpi.png: the same bytes as cubes.png"
fi
echo "== dpkg -r raytrace"
dpkg -L raytrace | grep -E "^/usr/(bin|lib|include|share/raytrace)/" | sort > files
dpkg -r raytrace > /dev/null
left=0
while read -r file; do
    if [ -f "$file" ]; then echo "left behind: $file"; left=1; fi
done < files
[ "$left" -eq 0 ]
echo "removed: none of its $(wc -l < files) files is left"
'

for form in dpkg apt; do
    echo "==== installing with $form"
    root="$work/$form"
    cp -a "$work/bare" "$root"
    cp "$deb" "$root/tmp/raytrace.deb"
    mount -t proc proc "$root/proc"
    mount -t sysfs sysfs "$root/sys" # Open MPI's hwloc reads the cores there
    chroot "$root" /bin/bash -c "$inside" inside "$form"
    umount "$root/proc" "$root/sys"
done
if [ -n "${BARE_DEBIAN_PICTURE:-}" ]; then
    cp "$work/apt/tmp/cubes.png" "$BARE_DEBIAN_PICTURE"
    echo "the render is in $BARE_DEBIAN_PICTURE"
fi
echo "bare-debian.sh: on a bare $suite the package installs (dpkg -i with" \
     "apt-get -f install, and apt-get install), runs and is removed"
