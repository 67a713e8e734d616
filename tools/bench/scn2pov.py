#!/usr/bin/env python3
"""scn2pov - a .scn scene (the course's records or the extended ones) as a
POV-Ray 3.7 scene, for timing POV-Ray on the pictures rt-perf renders
(tools/bench/povray-times.sh) and for comparing its pictures with ours
(tools/bench/pov-compare.py).

    scn2pov.py SCENE.scn DEPTH [WIDTH HEIGHT] > SCENE.pov

What is carried over, and how it maps onto POV-Ray 3.7's model (read in its
source, backend/render/trace.cpp: ComputeLightedTexture, ComputeDiffuseColour,
ComputePhongColour):

- the camera: the pinhole of the scene format (the screen 2|AB| wide, B
  projected when AB is not perpendicular to AO, square pixels), as
  `direction`, `right` and `up`;
- every light, a point `light_source` of the light's colour / 255, no fade;
- the background;
- every facet, in one mesh per refractive index: a `smooth_triangle` with
  its three vertex normals (normalised here, as on our load) when all three
  of its vertices carry one, a `triangle` otherwise;
- for each facet a texture with pigment `rgbt <R, G, B, t>` / 255 (t as
  `transmit`) and finish `ambient 0 diffuse D reflection k phong s
  phong_size p`, with D = d / (1 - t): POV-Ray 3.7 multiplies the diffuse
  term by the pigment's opacity 1 - t (not the highlight, not the
  reflection), so our d·(N·S)·C_S·C_F comes out exactly.  POV-Ray's phong
  is phong·max(0, R·L)^phong_size·light colour with R the eye direction
  mirrored about the normal: the same number as our s·max(0, R_l·V)^p·C_S
  (no normalisation, not the facet's colour, no `metallic`);
- transparency: t as transmit, n as `interior { ior n }` of the mesh;
  `global_settings { max_trace_level DEPTH + 1 }` (POV-Ray counts the
  primary ray) and `adc_bailout 0` (POV-Ray otherwise drops rays whose
  weight is under 1/255);
- hard shadows of transparent facets: POV-Ray lets light through a
  transmitting surface; our E_l is 0 behind any facet.  A transparent mesh
  is therefore written twice: the one seen with `no_shadow`, and an
  invisible copy (`no_image no_reflection`) that only casts shadows.

Where POV-Ray's model differs from ours, so that the pictures cannot agree
everywhere:

- the shadow terminator: POV-Ray's shadow rays leave the hit point itself
  (past a 1e-3 tolerance), so a smooth facet lit at a grazing angle is
  shadowed by its neighbours; ours leave Hanika's shading point P'
  (docs/rendering-model.md, "Smooth shading and highlights");
- which side a smooth normal faces: POV-Ray turns the interpolated normal
  to the ray; we turn N_s to the side of the geometric normal, and fall
  back on N_g for a mirror or refracted direction that would cross the
  facet;
- entering or leaving glass: POV-Ray keeps a list of the interiors a ray
  is in; we read it from the facet's winding (the same for a closed mesh
  wound counter-clockwise seen from outside);
- total internal reflection: POV-Ray adds the internally reflected ray
  unweighted; we weight it by t;
- a highlight with phong_size >= 60 is cut where R·L <= 0.0008 (below
  1e-185: invisible);
- the lens (a screen record's aperture and focus) is not carried over:
  POV-Ray's focal_blur samples differently (a warning says so);
- d > 0 with t = 1 cannot be written (POV-Ray's diffuse vanishes with the
  opacity; a warning says so).
Everything else (no ambient, no Fresnel, no gamma with assumed_gamma 1 and
File_Gamma=1 on the command line, no anti-aliasing) is the same model.
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


def unit(v):
    length = dot(v, v) ** 0.5
    return scale(v, 1 / length)


def material(f):
    """(k, R, G, B, t, n, d, s, p) of a facet record, defaults filled."""
    k = f[3]
    t = f[7] if len(f) > 7 else 0.0
    n = f[8] if len(f) > 8 else 1.0
    d = f[9] if len(f) > 9 else 1 - k - t
    s = f[10] if len(f) > 10 else 0.0
    p = f[11] if len(f) > 11 else 1.0
    return (k, f[4], f[5], f[6], t, n, d, s, p)


def texture(m):
    k, r, g, b, t, n, d, s, p = m
    if t >= 1:
        if d > 0:
            sys.stderr.write("scn2pov: warning: d = %g with t = 1: POV-Ray "
                             "has no diffuse there\n" % d)
        diffuse = 0.0
    else:
        diffuse = d / (1 - t)
    return ("texture { pigment { rgbt <%.17g, %.17g, %.17g, %.17g> } "
            "finish { ambient 0 diffuse %.17g brilliance 1 reflection "
            "%.17g specular 0 phong %.17g phong_size %.17g } }"
            % (r / 255, g / 255, b / 255, t, diffuse, k, s, p))


def main():
    if len(sys.argv) not in (3, 5):
        sys.exit("usage: scn2pov.py SCENE.scn DEPTH [WIDTH HEIGHT]")
    lines = numbers(sys.argv[1])
    depth = int(sys.argv[2])
    o = lines[0][:3]
    a, b = lines[1][0:3], lines[1][3:6]
    w, h = int(lines[1][6]), int(lines[1][7])
    if len(lines[1]) > 8 and lines[1][8] > 0:
        sys.stderr.write("scn2pov: warning: the lens (aperture %g) is not "
                         "converted: a pinhole camera\n" % lines[1][8])
    if len(sys.argv) == 5:
        w, h = int(sys.argv[3]), int(sys.argv[4])
    n = int(lines[2][0])
    vertices = lines[3:3 + n]
    m = int(lines[3 + n][0])
    facets = lines[4 + n:4 + n + m]
    rest = lines[4 + n + m:]
    background, lights = rest[0], rest[1:]
    ao = sub(o, a)
    ab = sub(b, a)
    ab = sub(ab, scale(ao, dot(ab, ao) / dot(ao, ao)))  # projected B
    c = cross(ao, ab)
    ac = scale(c, (dot(ab, ab) / dot(c, c)) ** 0.5)
    out = sys.stdout
    out.write("// %s, converted by tools/bench/scn2pov.py\n" % sys.argv[1])
    out.write("#version 3.7;\n")
    out.write("global_settings { assumed_gamma 1.0 max_trace_level %d "
              "adc_bailout 0 ambient_light 0 }\n" % (depth + 1))
    out.write("background { rgb %s }\n" % vec(scale(background, 1 / 255)))
    out.write("camera { perspective location %s direction %s right %s "
              "up %s }\n" % (vec(o), vec(sub(a, o)), vec(scale(ab, 2)),
                             vec(scale(ac, 2.0 * h / w))))
    for light in lights:
        out.write("light_source { %s color rgb %s }\n"
                  % (vec(light[:3]), vec(scale(light[3:6], 1 / 255))))
    textures = {}       # mesh triangles take declared textures only
    groups = {}         # refractive index of transparent facets (None: opaque)
    for f in facets:
        mat = material(f)
        if mat not in textures:
            textures[mat] = "T%d" % len(textures)
            out.write("#declare %s = %s\n" % (textures[mat], texture(mat)))
        groups.setdefault(mat[5] if mat[4] > 0 else None, []).append(f)
    normals = [unit(v[3:6]) if len(v) >= 6 else None for v in vertices]

    def mesh(members, extra, tex=None):
        out.write("mesh {\n")
        for f in members:
            idx = [int(i) - 1 for i in f[:3]]
            p = [vertices[i][:3] for i in idx]
            name = tex or textures[material(f)]
            nv = [normals[i] for i in idx]
            if all(x is not None for x in nv):
                out.write("  smooth_triangle { %s, %s, %s, %s, %s, %s "
                          "texture { %s } }\n"
                          % (vec(p[0]), vec(nv[0]), vec(p[1]), vec(nv[1]),
                             vec(p[2]), vec(nv[2]), name))
            else:
                out.write("  triangle { %s, %s, %s texture { %s } }\n"
                          % (vec(p[0]), vec(p[1]), vec(p[2]), name))
        out.write("  %s\n}\n" % extra)

    for ior, members in groups.items():
        if ior is None:
            mesh(members, "")
        else:
            mesh(members, "interior { ior %.17g } no_shadow" % ior)
            # the copy that casts the hard shadow of section 7
            if "TSHADOW" not in textures.values():
                textures["shadow"] = "TSHADOW"
                out.write("#declare TSHADOW = texture { pigment { rgb 0 } "
                          "finish { ambient 0 diffuse 0 } }\n")
            mesh(members, "no_image no_reflection", "TSHADOW")


if __name__ == "__main__":
    main()
