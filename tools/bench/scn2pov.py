#!/usr/bin/env python3
"""scn2pov - a .scn scene as a POV-Ray 3.7 scene, for timing POV-Ray on
the pictures rt-perf renders (tools/bench/povray-times.sh).

    scn2pov.py SCENE.scn DEPTH [WIDTH HEIGHT] > SCENE.pov

The same camera (the pinhole of the scene format: the screen 2|AB| wide,
B projected when AB is not perpendicular to AO), the same triangles in one
mesh, one point light, the background, and for each facet a finish with
diffuse 1 - k and reflection k (no ambient, no specular), with
max_trace_level = DEPTH + 1 (POV-Ray counts the primary ray).  Only what
the scene format holds: a scene with several lights or transparency is
refused.
"""
import re
import sys

from vectors import cross, dot, scale, sub


def numbers(path):
    lines = []
    with open(path, encoding="utf-8-sig") as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line:
                lines.append([float(x) for x in re.split(r"[,\s]+", line)
                              if x])
    return lines


def vec(v):
    return "<%.17g, %.17g, %.17g>" % tuple(v)


def main():
    if len(sys.argv) not in (3, 5):
        sys.exit("usage: scn2pov.py SCENE.scn DEPTH [WIDTH HEIGHT]")
    lines = numbers(sys.argv[1])
    depth = int(sys.argv[2])
    o = lines[0][:3]
    a, b = lines[1][0:3], lines[1][3:6]
    w, h = int(lines[1][6]), int(lines[1][7])
    if len(sys.argv) == 5:
        w, h = int(sys.argv[3]), int(sys.argv[4])
    n = int(lines[2][0])
    vertices = lines[3:3 + n]
    m = int(lines[3 + n][0])
    facets = lines[4 + n:4 + n + m]
    rest = lines[4 + n + m:]
    background, light = rest[0], rest[1]
    if len(rest) > 2 or any(len(f) > 7 for f in facets):
        sys.exit("scn2pov: several lights or transparency: not converted")
    ao = sub(o, a)
    ab = sub(b, a)
    ab = sub(ab, scale(ao, dot(ab, ao) / dot(ao, ao)))  # projected B
    c = cross(ao, ab)
    ac = scale(c, (dot(ab, ab) / dot(c, c)) ** 0.5)
    out = sys.stdout
    out.write("// %s, converted by tools/bench/scn2pov.py\n" % sys.argv[1])
    out.write("#version 3.7;\n")
    out.write("global_settings { assumed_gamma 1.0 max_trace_level %d "
              "ambient_light 0 }\n" % (depth + 1))
    out.write("background { rgb %s }\n" % vec(scale(background, 1 / 255)))
    out.write("camera { perspective location %s direction %s right %s "
              "up %s }\n" % (vec(o), vec(sub(a, o)), vec(scale(ab, 2)),
                             vec(scale(ac, 2.0 * h / w))))
    out.write("light_source { %s color rgb %s }\n"
              % (vec(light[:3]), vec(scale(light[3:6], 1 / 255))))
    textures = {}       # mesh triangles take declared textures only
    for f in facets:
        key = tuple(f[3:7])
        if key not in textures:
            textures[key] = "T%d" % len(textures)
            out.write("#declare %s = texture { pigment { rgb %s } "
                      "finish { ambient 0 diffuse %.17g reflection %.17g "
                      "specular 0 phong 0 } }\n"
                      % (textures[key], vec(scale(f[4:7], 1 / 255)),
                         1 - f[3], f[3]))
    out.write("mesh {\n")
    for f in facets:
        p = [vertices[int(i) - 1] for i in f[:3]]
        out.write("  triangle { %s, %s, %s texture { %s } }\n"
                  % (vec(p[0]), vec(p[1]), vec(p[2]), textures[tuple(f[3:7])]))
    out.write("}\n")


if __name__ == "__main__":
    main()
