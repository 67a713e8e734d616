#!/usr/bin/env python3
"""scnstrip - an extended .scn without its vertex normals and/or highlights,
for measuring what they cost (docs/performance.md, "Smooth shading and
highlights: what they cost") and for pov-compare.py's shadow mask.

    scnstrip.py [--normals] [--highlights] [--course] IN.scn OUT.scn

--normals cuts every vertex record to `x, y, z` (every facet flat);
--highlights cuts every facet record to `a, b, c, k, R, G, B, t, n, d`
(s = 0, no highlight; d is kept, so the diffuse term does not change);
--course (with both) also drops d, which must then be 1 - k - t, so that
a reader older than the extended records' d, s, p (commit 69deee2) reads
the file and renders the same diffuse term.
Comments and everything else stay as they are.
"""
import re
import sys


def strip(src, dst, normals, highlights, course=False):
    with open(src, encoding="utf-8-sig") as f:
        raw = f.read().splitlines()
    body = [i for i, l in enumerate(raw) if l.split("#", 1)[0].strip()]

    def values(i):
        return [x for x in
                re.split(r"[,\s]+", raw[i].split("#", 1)[0].strip()) if x]

    n = int(float(values(body[2])[0]))
    m = int(float(values(body[3 + n])[0]))
    if normals:
        for i in body[3:3 + n]:
            raw[i] = ", ".join(values(i)[:3])
    if highlights:
        for i in body[4 + n:4 + n + m]:
            v = values(i)
            if course and len(v) > 9:
                k, t = float(v[3]), float(v[7])
                if abs(float(v[9]) - (1 - k - t)) > 1e-9:
                    sys.exit("scnstrip: %s:%d: d = %s is not 1 - k - t: "
                             "no course record holds it" % (src, i + 1, v[9]))
                raw[i] = ", ".join(v[:9])
            elif len(v) > 10:
                raw[i] = ", ".join(v[:10])
    with open(dst, "w") as f:
        f.write("\n".join(raw) + "\n")


def main():
    args = sys.argv[1:]
    normals = "--normals" in args
    highlights = "--highlights" in args
    course = "--course" in args
    files = [a for a in args if not a.startswith("--")]
    if (len(files) != 2 or len(files) + normals + highlights + course
            != len(args) or (course and not (normals and highlights))):
        sys.exit("usage: scnstrip.py [--normals] [--highlights] [--course] "
                 "IN OUT")
    strip(files[0], files[1], normals, highlights, course)


if __name__ == "__main__":
    main()
