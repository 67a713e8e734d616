#!/usr/bin/env python3
"""add-normals - area-weighted vertex normals for a model that has none, so
that it renders smooth (docs/shading.md).

    add-normals.py IN.obj OUT.obj      # adds `vn` lines, faces become v//vn
    add-normals.py IN.scn OUT.scn      # vertex records become x,y,z,nx,ny,nz

The normal of a vertex is the sum, over the facets that use it, of the
facet's (b - a) x (c - a) (twice its area times its unit normal, so large
facets weigh more), normalised; vertices at the same position are welded
for the sum (they get the same normal).  The facets' winding must be consistent
(it is in OBJ files made by modelling programs).  A vertex whose sum is
zero keeps no normal (its facets stay flat).  Polygons of an OBJ are fanned
from their first corner for the sum; OBJ faces that already name a normal
are refused.  Nothing else in the file changes.
"""
import re
import sys

from vectors import cross, dot, scale, sub


def normals(points, triangles):
    # vertices at the same position share their sum (a model's seams often
    # repeat a vertex: welding them keeps the seam from showing)
    slot = {}
    where = [slot.setdefault(tuple(p), len(slot)) for p in points]
    acc = [[0.0, 0.0, 0.0] for _ in slot]
    for a, b, c in triangles:
        n = cross(sub(points[b], points[a]), sub(points[c], points[a]))
        for i in (a, b, c):
            j = where[i]
            acc[j] = [acc[j][k] + n[k] for k in range(3)]
    out = []
    for n in (acc[j] for j in where):
        length = dot(n, n) ** 0.5
        out.append(scale(n, 1 / length) if length > 0 else None)
    return out


def obj(src, dst):
    lines = open(src, encoding="utf-8-sig").read().splitlines()
    points, faces = [], []
    for line in lines:
        f = line.split()
        if not f:
            continue
        if f[0] == "v":
            points.append([float(x) for x in f[1:4]])
        elif f[0] == "f":
            idx = []
            for corner in f[1:]:
                parts = corner.split("/")
                if len(parts) >= 3 and parts[2]:
                    sys.exit("add-normals: %s already has normals" % src)
                i = int(parts[0])
                idx.append(i - 1 if i > 0 else len(points) + i)
            faces.append(idx)
        elif f[0] == "vn":
            sys.exit("add-normals: %s already has normals" % src)
    tris = [(f[0], f[j], f[j + 1]) for f in faces for j in range(1, len(f) - 1)]
    ns = normals(points, tris)
    # one vn per vertex, in vertex order; a vertex without one gets (0,0,1)
    # written but its faces' corners do not name it
    with open(dst, "w") as out:
        nv = 0
        for line in lines:
            f = line.split()
            if f and f[0] == "v":
                out.write(line + "\n")
                n = ns[nv] or [0.0, 0.0, 1.0]
                out.write("vn %.9g %.9g %.9g\n" % tuple(n))
                nv += 1
            elif f and f[0] == "f":
                corners = []
                for corner in f[1:]:
                    parts = corner.split("/")
                    i = int(parts[0])
                    k = i - 1 if i > 0 else nv + i
                    vt = parts[1] if len(parts) > 1 else ""
                    if ns[k] is None:
                        corners.append("%s/%s" % (parts[0], vt) if vt
                                       else parts[0])
                    else:
                        corners.append("%d/%s/%d" % (k + 1, vt, k + 1))
                out.write("f " + " ".join(corners) + "\n")
            else:
                out.write(line + "\n")


def scn(src, dst):
    raw = open(src, encoding="utf-8-sig").read().splitlines()
    body = [i for i, l in enumerate(raw) if l.split("#", 1)[0].strip()]

    def values(i):
        return [float(x) for x in
                re.split(r"[,\s]+", raw[i].split("#", 1)[0].strip()) if x]

    n = int(values(body[2])[0])
    vrows = body[3:3 + n]
    points = [values(i)[:3] for i in vrows]
    m = int(values(body[3 + n])[0])
    tris = [tuple(int(x) - 1 for x in values(i)[:3])
            for i in body[4 + n:4 + n + m]]
    ns = normals(points, tris)
    for row, p, nrm in zip(vrows, points, ns):
        raw[row] = "%.17g, %.17g, %.17g" % tuple(p)
        if nrm is not None:
            raw[row] += ", %.17g, %.17g, %.17g" % tuple(nrm)
    with open(dst, "w") as out:
        out.write("\n".join(raw) + "\n")


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: add-normals.py IN.obj|IN.scn OUT")
    if sys.argv[1].endswith(".obj"):
        obj(sys.argv[1], sys.argv[2])
    else:
        scn(sys.argv[1], sys.argv[2])


if __name__ == "__main__":
    main()
