#!/usr/bin/env python3
"""terrain - a height field of N x N square cells, each cut into two
triangles (2 N^2 facets), as a .scn, for timing builds on a big mesh
(tools/bench/peers.sh: N = 708 gives 1,002,528 facets).

    terrain.py N > terrain.scn

The heights are a fixed sum of sines over the square [-1, 1]^2 (no
randomness: the same file every run), at most 0.15; the camera looks down
on it from the south-west at 400 x 400, the light is high in the south;
every facet is opaque grey-green with k = 0 (no reflections: the mesh is
there for its build and its camera and shadow rays).
"""
import math
import sys


def height(x, y):
    return (0.08 * math.sin(3.1 * x + 0.4) * math.cos(2.3 * y - 0.7) +
            0.04 * math.sin(7.7 * x * y + 1.3) +
            0.03 * math.cos(11.0 * x - 5.0 * y))


def main():
    if len(sys.argv) != 2 or not sys.argv[1].isdigit() or \
            int(sys.argv[1]) < 1:
        sys.exit("usage: terrain.py N > terrain.scn")
    n = int(sys.argv[1])
    out = sys.stdout
    out.write("# a height field of %d x %d cells: tools/bench/terrain.py\n"
              % (n, n))
    out.write("-1.1,-1.5,1.0\n")                # the observer O
    # A one unit from O towards (0, 0, 0); B to its right (tan 30 degrees).
    o = (-1.1, -1.5, 1.0)
    d = math.sqrt(sum(c * c for c in o))
    a = [c - c / d for c in o]
    right = (1.5, -1.1, 0.0)                    # (view x up), horizontal
    r = math.sqrt(sum(c * c for c in right))
    b = [a[i] + right[i] / r * math.tan(math.radians(30)) for i in range(3)]
    out.write(",".join("%.9g" % c for c in a + b) + ",400,400\n")
    out.write("%d\n" % ((n + 1) * (n + 1)))
    for j in range(n + 1):
        y = -1 + 2 * j / n
        out.write("".join("%.7g,%.7g,%.7g\n" % (-1 + 2 * i / n, y,
                                                height(-1 + 2 * i / n, y))
                          for i in range(n + 1)))
    out.write("%d\n" % (2 * n * n))
    for j in range(n):
        rows = []
        for i in range(n):
            v = j * (n + 1) + i + 1             # 1-based, lower left
            rows.append("%d,%d,%d,0,150,170,120\n" % (v, v + 1, v + n + 2))
            rows.append("%d,%d,%d,0,150,170,120\n" % (v, v + n + 2, v + n + 1))
        out.write("".join(rows))
    out.write("120,160,220\n")                  # the background
    out.write("0.5,-3,4,255,255,255\n")         # the light


if __name__ == "__main__":
    main()
