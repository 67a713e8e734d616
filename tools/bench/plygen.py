#!/usr/bin/env python3
"""plygen - the height field of terrain.py as a PLY mesh, for timing the
PLY reader and the scale benchmark on millions of facets.

    plygen.py N [--format binary_little_endian|binary_big_endian|ascii]
        > terrain.ply

N x N square cells, each cut into two triangles (2 N^2 facets, (N + 1)^2
vertices), the heights terrain.py gives (a fixed sum of sines, the same
file every run).  Vertices are float32 x, y, z; faces a list of uchar
count and int indices (0-based), the triangles terrain.py writes.  The
ASCII form writes each float32 with 9 significant digits, so that it reads
back to the same values as the binary forms: every format of one N gives
the same scene (and rt-convert gives its .scn).  The default format is
binary_little_endian.  The file has no camera or light: readers frame it
with their automatic view.
"""
import argparse
import struct
import sys

from terrain import height

FORMATS = ("binary_little_endian", "binary_big_endian", "ascii")


def as_float32(value):
    return struct.unpack("<f", struct.pack("<f", value))[0]


def main():
    parser = argparse.ArgumentParser(
        description="a terrain height field as a PLY mesh (2 N^2 facets)")
    parser.add_argument("n", type=int, metavar="N",
                        help="cells along each side (N >= 1)")
    parser.add_argument("--format", choices=FORMATS, default=FORMATS[0])
    args = parser.parse_args()
    n = args.n
    if n < 1:
        parser.error("N must be at least 1")
    out = sys.stdout.buffer
    header = ("ply\nformat %s 1.0\n"
              "comment a height field of %d x %d cells: "
              "tools/bench/plygen.py\n"
              "element vertex %d\nproperty float x\nproperty float y\n"
              "property float z\nelement face %d\n"
              "property list uchar int vertex_indices\nend_header\n"
              % (args.format, n, n, (n + 1) * (n + 1), 2 * n * n))
    out.write(header.encode("ascii"))
    order = "<" if args.format == "binary_little_endian" else ">"
    for j in range(n + 1):
        y = -1 + 2 * j / n
        row = []
        for i in range(n + 1):
            x = -1 + 2 * i / n
            row.extend((x, y, height(x, y)))
        if args.format == "ascii":
            out.write("".join("%.9g %.9g %.9g\n" % tuple(
                as_float32(c) for c in row[k:k + 3])
                for k in range(0, len(row), 3)).encode("ascii"))
        else:
            out.write(struct.pack("%s%df" % (order, len(row)), *row))
    face = struct.Struct(order + "B3i")
    for j in range(n):
        rows = []
        for i in range(n):
            v = j * (n + 1) + i                 # 0-based, lower left
            a = (v, v + 1, v + n + 2)
            b = (v, v + n + 2, v + n + 1)
            if args.format == "ascii":
                rows.append("3 %d %d %d\n3 %d %d %d\n" % (a + b))
            else:
                rows.append(face.pack(3, *a) + face.pack(3, *b))
        if args.format == "ascii":
            out.write("".join(rows).encode("ascii"))
        else:
            out.write(b"".join(rows))


if __name__ == "__main__":
    main()
