#!/usr/bin/env python3
"""balls-nff - the SPD sphereflake ("balls") as an NFF file whose spheres are
NFF spheres (`s` records), so that our NFF reader tessellates them and gives
their vertices the exact normals of the sphere (docs/shading.md).

    balls-nff.py SIZE_FACTOR > balls-sN.nff

The spheres, the floor, the view and the light are those of
tools/bench/sphereflake.py (the SPD's geometry, restated there).  The
material is ours, not the SPD's: floor `f 1 0.75 0.33 1 0 0 0 0`; balls
`f 1 0.9 0.7 0.5 0.5 3.0827 0 0` (Kd 0.5, Ks 0.5 as the .scn's k, and the
Phong exponent of the SPD's other scenes, rings and mount, 3.0827).
"""
import sys

from sphereflake import children_directions, flake, number


def main():
    if len(sys.argv) != 2 or not sys.argv[1].isdigit():
        sys.exit("usage: balls-nff.py SIZE_FACTOR > balls-sN.nff")
    spheres = []
    flake(int(sys.argv[1]), [0, 0, 0], 0.5, [0, 0, 1], children_directions(),
          spheres)
    w = sys.stdout.write
    w("# the SPD sphereflake (balls), size factor %s, with NFF spheres: "
      "tools/bench/balls-nff.py\n" % sys.argv[1])
    w("v\nfrom 2.1 1.3 1.7\nat 0 0 0\nup 0 0 1\nangle 45\nhither 0.01\n"
      "resolution 400 400\n")
    w("b 0.078 0.361 0.753\n")
    w("l 4 3 2\n")
    w("f 1 0.75 0.33 1 0 0 0 0\n")
    w("p 4\n12 12 -0.5\n-12 12 -0.5\n-12 -12 -0.5\n12 -12 -0.5\n")
    w("f 1 0.9 0.7 0.5 0.5 3.0827 0 0\n")
    for center, radius in spheres:
        w("s %s %s\n" % (" ".join(number(x) for x in center), number(radius)))


if __name__ == "__main__":
    main()
