#!/usr/bin/env python3
"""terrain - a height field of N x N square cells, each cut into two
triangles (2 N^2 facets), as a .scn, for timing builds on a big mesh
(tools/bench/peers.sh: N = 708 gives 1,002,528 facets), or as a binary
PLY of the same mesh (tools/bench/scale.sh).

    terrain.py N > terrain.scn
    terrain.py N --float32 > terrain.scn
    terrain.py N --ply > terrain.ply
    terrain.py N --obj > terrain.obj

The heights are a fixed sum of sines over the square [-1, 1]^2 (no
randomness: the same file every run), at most 0.15; the camera looks down
on it from the south-west at 400 x 400, the light is high in the south;
every facet is opaque grey-green with k = 0 (no reflections: the mesh is
there for its build and its camera and shadow rays).

--float32 rounds every coordinate to the nearest float32 (what a scanned
model's PLY holds) and writes it exactly (the shortest decimal that reads
back as that double), so that the .scn and the PLY of --ply hold the
same vertices, bit for bit, and the same facets in the same order.
--ply writes them as binary little-endian PLY 1.0 (`element vertex` with
`property float x, y, z`, `element face` with `property list uchar int
vertex_indices`, 0-based); a PLY has no camera or light, so its comments
say the ones of the .scn (as rt-export's --look-from, --look-at, --up,
--fov and --light).  It is written a row of cells at a time, with array
slices, not a facet at a time: N = 3163 (20,009,138 facets, 10,017,796
vertices, 380 MB) takes seconds.  --obj writes the same float32 vertices
to nine digits (enough to read back as the same float32, not as the same
double) and the same facets as a Wavefront OBJ, for the sizes whose .scn
would pass the 1 GiB a scene may weigh (20 million facets: about 1.4 GB
as --float32, 0.95 GB as --obj).
"""
import array
import math
import sys


def height(x, y):
    return (0.08 * math.sin(3.1 * x + 0.4) * math.cos(2.3 * y - 0.7) +
            0.04 * math.sin(7.7 * x * y + 1.3) +
            0.03 * math.cos(11.0 * x - 5.0 * y))


O = (-1.1, -1.5, 1.0)                           # the observer
LIGHT = (0.5, -3, 4)
# The options that give a PLY of the mesh the .scn's view: the screen is
# centred on O -> (0, 0, 0), 60 degrees wide, its right horizontal.
VIEW = "--look-from -1.1,-1.5,1 --look-at 0,0,0 --up 0,0,1 --fov 60 " \
       "--light 0.5,-3,4 --size 400x400"


def write_head(out, n):
    out.write("# a height field of %d x %d cells: tools/bench/terrain.py\n"
              % (n, n))
    out.write("-1.1,-1.5,1.0\n")                # the observer O
    # A one unit from O towards (0, 0, 0); B to its right (tan 30 degrees).
    d = math.sqrt(sum(c * c for c in O))
    a = [c - c / d for c in O]
    right = (1.5, -1.1, 0.0)                    # (view x up), horizontal
    r = math.sqrt(sum(c * c for c in right))
    b = [a[i] + right[i] / r * math.tan(math.radians(30)) for i in range(3)]
    out.write(",".join("%.9g" % c for c in a + b) + ",400,400\n")


def write_tail(out):
    out.write("120,160,220\n")                  # the background
    out.write("0.5,-3,4,255,255,255\n")         # the light


def write_facets(out, n):
    out.write("%d\n" % (2 * n * n))
    for j in range(n):
        rows = []
        for i in range(n):
            v = j * (n + 1) + i + 1             # 1-based, lower left
            rows.append("%d,%d,%d,0,150,170,120\n" % (v, v + 1, v + n + 2))
            rows.append("%d,%d,%d,0,150,170,120\n" % (v, v + n + 2, v + n + 1))
        out.write("".join(rows))


def float32_row(n, j):
    """Row j of the vertices, x, y, z interleaved, rounded to float32."""
    y = -1 + 2 * j / n
    row = array.array("f", bytes(12 * (n + 1)))
    row[0::3] = array.array("f", (-1 + 2 * i / n for i in range(n + 1)))
    row[1::3] = array.array("f", [y]) * (n + 1)
    row[2::3] = array.array("f", (height(-1 + 2 * i / n, y)
                                  for i in range(n + 1)))
    return row


def scn(n):
    out = sys.stdout
    write_head(out, n)
    out.write("%d\n" % ((n + 1) * (n + 1)))
    for j in range(n + 1):
        out.write("".join("%.7g,%.7g,%.7g\n" % (-1 + 2 * i / n, -1 + 2 * j / n,
                                                height(-1 + 2 * i / n,
                                                       -1 + 2 * j / n))
                          for i in range(n + 1)))
    write_facets(out, n)
    write_tail(out)


def scn_float32(n):
    out = sys.stdout
    write_head(out, n)
    out.write("%d\n" % ((n + 1) * (n + 1)))
    for j in range(n + 1):
        c = float32_row(n, j).tolist()          # the doubles they widen to
        out.write("".join("%r,%r,%r\n" % (c[k], c[k + 1], c[k + 2])
                          for k in range(0, len(c), 3)))
    write_facets(out, n)
    write_tail(out)


def obj(n):
    out = sys.stdout
    out.write("# a height field of %d x %d cells: tools/bench/terrain.py\n"
              "# view (rt-export): %s\n" % (n, n, VIEW))
    for j in range(n + 1):
        c = float32_row(n, j).tolist()
        out.write("".join("v %.9g %.9g %.9g\n" % (c[k], c[k + 1], c[k + 2])
                          for k in range(0, len(c), 3)))
    for j in range(n):
        rows = []
        for i in range(n):
            v = j * (n + 1) + i + 1             # 1-based, lower left
            rows.append("f %d %d %d\nf %d %d %d\n"
                        % (v, v + 1, v + n + 2, v, v + n + 2, v + n + 1))
        out.write("".join(rows))


def little_endian(a):
    if sys.byteorder != "little":
        a.byteswap()
    return a.tobytes()


def ply(n):
    out = sys.stdout.buffer
    head = ["ply", "format binary_little_endian 1.0",
            "comment a height field of %d x %d cells: "
            "tools/bench/terrain.py" % (n, n),
            "comment view (rt-export): " + VIEW,
            "element vertex %d" % ((n + 1) * (n + 1)),
            "property float x", "property float y", "property float z",
            "element face %d" % (2 * n * n),
            "property list uchar int vertex_indices", "end_header"]
    out.write(("\n".join(head) + "\n").encode("ascii"))
    for j in range(n + 1):
        out.write(little_endian(float32_row(n, j)))
    m = 2 * n                                   # the facets of a row
    record = bytearray(13 * m)
    record[0::13] = b"\x03" * m
    corner = [array.array("i", bytes(4 * m)) for _ in range(3)]
    for j in range(n):
        v = j * (n + 1)                         # 0-based, lower left
        lower = array.array("i", range(v, v + n))
        upper = array.array("i", range(v + n + 1, v + 2 * n + 1))
        right = array.array("i", range(v + 1, v + n + 1))
        diagonal = array.array("i", range(v + n + 2, v + 2 * n + 2))
        # (v, v + 1, v + n + 2) then (v, v + n + 2, v + n + 1), as the .scn
        corner[0][0::2] = lower
        corner[0][1::2] = lower
        corner[1][0::2] = right
        corner[1][1::2] = diagonal
        corner[2][0::2] = diagonal
        corner[2][1::2] = upper
        for c in range(3):
            raw = little_endian(array.array("i", corner[c]))
            for b in range(4):
                record[1 + 4 * c + b::13] = raw[b::4]
        out.write(record)


def main():
    modes = {"": scn, "--float32": scn_float32, "--ply": ply, "--obj": obj}
    args = sys.argv[1:]
    if not 1 <= len(args) <= 2 or not args[0].isdigit() or \
            int(args[0]) < 1 or (args + [""])[1] not in modes:
        sys.exit("usage: terrain.py N [--float32 | --ply | --obj] > FILE")
    modes[(args + [""])[1]](int(args[0]))


if __name__ == "__main__":
    main()
