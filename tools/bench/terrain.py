#!/usr/bin/env python3
"""terrain - a height field of N x N square cells, each cut into two
triangles (2 N^2 facets), as a .scn, for timing builds on a big mesh
(tools/bench/peers.sh: N = 708 gives 1,002,528 facets; tools/bench/
scale.sh).

    terrain.py N > terrain.scn
    terrain.py --obj N > terrain.obj
    terrain.py --nff N > terrain.nff
    terrain.py [--obj] --float32 N > terrain.scn

--obj writes the same mesh as an OBJ (`v x y z` and `f a b c`, the
vertices written as in the .scn; the reader makes its own camera and
light); --nff writes it as NFF in the style of the SPD generators: the
view of the .scn, its background and light, one `f` material, and each
facet as a polygon `p 3` with its three vertices on their own lines (an
NFF polygon shares no vertices, so the file is about twice the .scn).
tools/bench/parse-rate.sh times the readers on the three.

--float32 rounds every coordinate to the nearest float32, as
tools/bench/plygen.py's PLY of the same N holds it (what a scanned model
holds): the .scn then writes each as the shortest decimal that reads back
as the same double, so that it and the PLY are one scene, vertex for
vertex and bit for bit, the same facets in the same order; an OBJ writes
each to nine digits (the same float32, not the same double), which keeps
20 million facets (N = 3163) under the 1 GiB a scene may weigh (0.92 GB;
1.36 GB as the exact .scn).  tools/bench/scale.sh times the steps on them.

The heights are a fixed sum of sines over the square [-1, 1]^2 (no
randomness: the same file every run), at most 0.15; the camera looks down
on it from the south-west at 400 x 400, the light is high in the south;
every facet is opaque grey-green with k = 0 (no reflections: the mesh is
there for its build and its camera and shadow rays).
"""
import array
import itertools
import math
import sys


def height(x, y):
    return (0.08 * math.sin(3.1 * x + 0.4) * math.cos(2.3 * y - 0.7) +
            0.04 * math.sin(7.7 * x * y + 1.3) +
            0.03 * math.cos(11.0 * x - 5.0 * y))


# The options that give a PLY or an OBJ of the mesh the .scn's view
# (tools/bench/scale.sh): the screen centred on O -> (0, 0, 0), 60 degrees
# wide, its right horizontal; the .scn's light.
VIEW = "--look-from -1.1,-1.5,1 --look-at 0,0,0 --up 0,0,1 --fov 60 " \
       "--light 0.5,-3,4 --size 400x400"


def usage():
    sys.exit("usage: terrain.py [--obj | --nff] [--float32] N > terrain.scn")


def vertices(n, exact=None):
    """The (n + 1)^2 vertices, row by row, as the .scn writes them; with
    exact "scn" or "obj", rounded to float32 and written as --float32
    says."""
    if exact is None:
        for j in range(n + 1):
            y = -1 + 2 * j / n
            yield from (("%.7g" % (-1 + 2 * i / n), "%.7g" % y,
                         "%.7g" % height(-1 + 2 * i / n, y))
                        for i in range(n + 1))
        return
    form = "%r" if exact == "scn" else "%.9g"
    for j in range(n + 1):
        y = -1 + 2 * j / n
        row = array.array("f", bytes(12 * (n + 1)))
        row[0::3] = array.array("f", (-1 + 2 * i / n for i in range(n + 1)))
        row[1::3] = array.array("f", [y]) * (n + 1)
        row[2::3] = array.array("f", (height(-1 + 2 * i / n, y)
                                      for i in range(n + 1)))
        c = row.tolist()                        # the doubles they widen to
        yield from ((form % c[k], form % c[k + 1], form % c[k + 2])
                    for k in range(0, len(c), 3))


def facets(n, j):
    """The 2 n facets of row j, each three 1-based vertex numbers."""
    for i in range(n):
        v = j * (n + 1) + i + 1                 # 1-based, lower left
        yield (v, v + 1, v + n + 2)
        yield (v, v + n + 2, v + n + 1)


def write_obj(out, n, exact):
    out.write("# a height field of %d x %d cells: tools/bench/terrain.py\n"
              % (n, n))
    rows = vertices(n, "obj" if exact else None)
    for j in range(n + 1):                      # a row at a time
        out.write("".join("v %s %s %s\n" % c
                          for c in itertools.islice(rows, n + 1)))
    for j in range(n):
        out.write("".join("f %d %d %d\n" % f for f in facets(n, j)))


def write_nff(out, n):
    points = list(vertices(n))
    out.write("# a height field of %d x %d cells: tools/bench/terrain.py\n"
              % (n, n))
    # the view of the .scn: from O towards the origin, z up, 60 degrees
    out.write("v\nfrom -1.1 -1.5 1.0\nat 0 0 0\nup 0 0 1\nangle 60\n"
              "hither 0.01\nresolution 400 400\n")
    out.write("b %.9g %.9g %.9g\n" % (120 / 255, 160 / 255, 220 / 255))
    out.write("l 0.5 -3 4\n")
    out.write("f %.9g %.9g %.9g 1 0 0 0 0\n" % (150 / 255, 170 / 255,
                                                 120 / 255))
    for j in range(n):
        out.write("".join("p 3\n%s %s %s\n%s %s %s\n%s %s %s\n"
                          % (points[a - 1] + points[b - 1] + points[c - 1])
                          for a, b, c in facets(n, j)))


def main():
    args = sys.argv[1:]
    kind = "scn"
    if args and args[0] in ("--obj", "--nff"):
        kind = args.pop(0)[2:]
    exact = bool(args) and args[0] == "--float32" and kind != "nff"
    if exact:
        args.pop(0)
    if len(args) != 1 or not args[0].isdigit() or int(args[0]) < 1:
        usage()
    n = int(args[0])
    out = sys.stdout
    if kind == "obj":
        write_obj(out, n, exact)
        return
    if kind == "nff":
        write_nff(out, n)
        return
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
    rows = vertices(n, "scn" if exact else None)
    for j in range(n + 1):                      # a row at a time
        out.write("".join("%s,%s,%s\n" % c
                          for c in itertools.islice(rows, n + 1)))
    out.write("%d\n" % (2 * n * n))
    for j in range(n):
        out.write("".join("%d,%d,%d,0,150,170,120\n" % f
                          for f in facets(n, j)))
    out.write("120,160,220\n")                  # the background
    out.write("0.5,-3,4,255,255,255\n")         # the light


if __name__ == "__main__":
    main()
