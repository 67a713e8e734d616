#!/usr/bin/env python3
"""mesh_models.py - writes the small mesh models of scenes/ that the README
renders (OBJ and PLY have no camera or light: rt-export frames them and
lights them with its defaults, docs/formats.md):

    model.obj, model.mtl   a torus of 16 x 8 quads (256 facets once cut)
                           with exact vertex normals (vn), red plastic
                           (Kd, Ks 0.6, Ns 60: a Phong highlight), lying on
                           a grey square floor of two facets
    ball.ply               an ASCII PLY: an icosphere of 80 facets with its
                           exact vertex normals (nx ny nz)

Usage: python3 tools/scenes/mesh_models.py [OUTDIR]   (default: scenes/)

Pure Python, standard library only; deterministic (the same bytes on every
run), numbers with 9 significant digits.
"""

import math
import os
import sys


def num(x):
    s = "%.9g" % x
    return "0" if s in ("-0", "0") else s


def torus(major=1.0, minor=0.38, nu=16, nv=8):
    """Vertices (x, y, z), normals and quads (vertex indices from 0) of a
    torus round the z axis."""
    verts, norms, quads = [], [], []
    for i in range(nu):
        u = 2 * math.pi * i / nu
        for j in range(nv):
            v = 2 * math.pi * j / nv
            n = (math.cos(v) * math.cos(u), math.cos(v) * math.sin(u),
                 math.sin(v))
            c = (major * math.cos(u), major * math.sin(u), 0.0)
            verts.append(tuple(c[k] + minor * n[k] for k in range(3)))
            norms.append(n)
    for i in range(nu):
        for j in range(nv):
            a = i * nv + j
            b = ((i + 1) % nu) * nv + j
            c = ((i + 1) % nu) * nv + (j + 1) % nv
            d = i * nv + (j + 1) % nv
            quads.append((a, b, c, d))
    return verts, norms, quads


def write_obj(outdir):
    verts, norms, quads = torus()
    floor_z = -0.38
    floor = [(-2.2, -2.2, floor_z), (2.2, -2.2, floor_z),
             (2.2, 2.2, floor_z), (-2.2, 2.2, floor_z)]
    lines = ["# model.obj - a red plastic torus of 16 x 8 quads with its exact",
             "# vertex normals, on a grey floor (256 + 2 facets). Z-up.",
             "# Written by tools/scenes/mesh_models.py: edit that, not this file.",
             "mtllib model.mtl", "o torus"]
    lines += ["v %s %s %s" % tuple(num(c) for c in p) for p in verts]
    lines += ["vn %s %s %s" % tuple(num(c) for c in n) for n in norms]
    lines.append("usemtl red_plastic")
    for q in quads:
        lines.append("f " + " ".join("%d//%d" % (k + 1, k + 1) for k in q))
    base = len(verts)
    lines.append("o floor")
    lines += ["v %s %s %s" % tuple(num(c) for c in p) for p in floor]
    lines.append("usemtl floor")
    lines.append("f %d %d %d %d" % tuple(base + k + 1 for k in range(4)))
    with open(os.path.join(outdir, "model.obj"), "w", newline="\n") as f:
        f.write("\n".join(lines) + "\n")
    mtl = ["# model.mtl - the materials of model.obj.",
           "# Written by tools/scenes/mesh_models.py: edit that, not this file.",
           "newmtl red_plastic", "Kd 0.8 0.12 0.08", "Ks 0.6 0.6 0.6",
           "Ns 60", "illum 2", "",
           "newmtl floor", "Kd 0.6 0.6 0.6", "illum 1"]
    with open(os.path.join(outdir, "model.mtl"), "w", newline="\n") as f:
        f.write("\n".join(mtl) + "\n")


def icosphere(levels=1):
    t = (1 + math.sqrt(5)) / 2
    pts = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0),
           (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
           (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11),
             (1, 5, 9), (5, 11, 4), (11, 10, 2), (10, 7, 6), (7, 1, 8),
             (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9),
             (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]

    def unit(p):
        n = math.sqrt(sum(c * c for c in p))
        return tuple(c / n for c in p)

    pts = [unit(p) for p in pts]
    for _ in range(levels):
        cache, out = {}, []

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in cache:
                pts.append(unit(tuple((pts[a][k] + pts[b][k]) / 2
                                      for k in range(3))))
                cache[key] = len(pts) - 1
            return cache[key]

        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            out += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = out
    return pts, faces


def write_ply(outdir):
    pts, faces = icosphere()
    lines = ["ply", "format ascii 1.0",
             "comment ball.ply - an icosphere of 80 facets with its exact"
             " vertex normals",
             "comment Z-up",
             "comment Written by tools/scenes/mesh_models.py",
             "element vertex %d" % len(pts),
             "property float x", "property float y", "property float z",
             "property float nx", "property float ny", "property float nz",
             "element face %d" % len(faces),
             "property list uchar int vertex_indices", "end_header"]
    lines += [" ".join(num(c) for c in p + p) for p in pts]
    lines += ["3 %d %d %d" % f for f in faces]
    with open(os.path.join(outdir, "ball.ply"), "w", newline="\n") as f:
        f.write("\n".join(lines) + "\n")


def main():
    outdir = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "..", "scenes")
    write_obj(outdir)
    write_ply(outdir)


if __name__ == "__main__":
    main()
