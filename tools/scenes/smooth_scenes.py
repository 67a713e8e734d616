#!/usr/bin/env python3
"""smooth_scenes.py - writes the smooth-shading scenes of scenes/:

    smooth-sphere.scn   a low-poly sphere (an icosphere of 80 facets) with its
                        exact vertex normals, on a floor, lit from the side:
                        the shadow terminator crosses the sphere
    smooth-glass.scn    a smooth glass ball (t = 0.9, n = 1.5, 320 facets)
                        before a checkered wall and floor
    teapot.scn          the Utah teapot (Newell 1975) tessellated from its
                        Bezier patches, with the patches' exact normals at the
                        vertices, Phong highlights and two lights, on a floor

Usage: python3 tools/scenes/smooth_scenes.py [OUTDIR]   (default: scenes/)

Pure Python, standard library only; deterministic (the same bytes on every
run).  Numbers are written with 12 significant digits, so that every reader
that rounds decimals correctly gets the same doubles.  The extended .scn
records used (docs/scene-format.md):
    vertex  x, y, z, nx, ny, nz
    facet   a, b, c, k, R, G, B, t, n, d, s, p
"""

import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import teapot_data  # noqa: E402


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def mul(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0])


def unit(a):
    n = math.sqrt(dot(a, a))
    return (a[0] / n, a[1] / n, a[2] / n)


def num(x):
    s = '%.12g' % x
    return '0' if s == '-0' else s


class Mesh:
    """Vertices (with an optional normal each) and facets (index triples,
    0-based here, with their material string)."""

    def __init__(self):
        self.vertices = []          # (point, normal or None)
        self.facets = []            # (i, j, k, material)

    def vertex(self, p, n=None):
        self.vertices.append((p, n))
        return len(self.vertices) - 1

    def facet(self, i, j, k, material):
        self.facets.append((i, j, k, material))

    def quad(self, i, j, k, l, material):
        self.facet(i, j, k, material)
        self.facet(i, k, l, material)


def write_scene(path, header, obs, a, b, w, h, mesh, background, lights):
    out = ['# ' + line if line else '#' for line in header.split('\n')]
    out.append('# Written by tools/scenes/smooth_scenes.py: edit that, '
               'not this file.')
    out.append(' '.join(num(x) for x in obs))
    out.append(' '.join(num(x) for x in a + b) + ' %d %d' % (w, h))
    out.append('%d' % len(mesh.vertices))
    for p, n in mesh.vertices:
        line = ' '.join(num(x) for x in p)
        if n is not None:
            line += '  ' + ' '.join(num(x) for x in n)
        out.append(line)
    out.append('%d' % len(mesh.facets))
    for i, j, k, material in mesh.facets:
        out.append('%d %d %d  %s' % (i + 1, j + 1, k + 1, material))
    out.append('%d %d %d' % background)
    for p, c in lights:
        out.append(' '.join(num(x) for x in p) + '  %d %d %d' % c)
    with open(path, 'w', newline='\n') as f:
        f.write('\n'.join(out) + '\n')


def screen_for(obs, target, distance, half_width):
    """A and B for a camera at obs looking at target, the screen at
    `distance` from obs and 2 half_width wide, B level (z up)."""
    forward = unit(sub(target, obs))
    right = unit(cross(forward, (0.0, 0.0, 1.0)))
    a = add(obs, mul(forward, distance))
    return a, add(a, mul(right, half_width))


# ------------------------------------------------------------------ spheres
def icosphere(frequency):
    """Unit-sphere points and outward-wound triangles: the icosahedron, each
    face cut into frequency^2 triangles, the new points pushed onto the
    sphere."""
    g = (1.0 + math.sqrt(5.0)) / 2.0
    base = [(-1, g, 0), (1, g, 0), (-1, -g, 0), (1, -g, 0),
            (0, -1, g), (0, 1, g), (0, -1, -g), (0, 1, -g),
            (g, 0, -1), (g, 0, 1), (-g, 0, -1), (-g, 0, 1)]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11),
             (1, 5, 9), (5, 11, 4), (11, 10, 2), (10, 7, 6), (7, 1, 8),
             (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9),
             (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    points, index = [], {}

    def point(p):
        p = unit(p)
        key = tuple(round(c, 9) for c in p)
        if key not in index:
            index[key] = len(points)
            points.append(p)
        return index[key]

    triangles = []
    for fa, fb, fc in faces:
        pa, pb, pc = (unit(tuple(float(c) for c in base[x]))
                      for x in (fa, fb, fc))

        def at(i, j):       # i along ab, j along ac, i + j <= frequency
            s = 1.0 - (i + j) / frequency
            return point(add(add(mul(pa, s), mul(pb, i / frequency)),
                             mul(pc, j / frequency)))
        for i in range(frequency):
            for j in range(frequency - i):
                triangles.append((at(i, j), at(i + 1, j), at(i, j + 1)))
                if i + j < frequency - 1:
                    triangles.append((at(i + 1, j), at(i + 1, j + 1),
                                      at(i, j + 1)))
    out = []
    for t in triangles:         # wind every facet counter-clockwise outside
        a, b, c = (points[x] for x in t)
        if dot(cross(sub(b, a), sub(c, a)), add(add(a, b), c)) < 0.0:
            t = (t[0], t[2], t[1])
        out.append(t)
    return points, out


def add_sphere(mesh, centre, radius, frequency, material, normals=True):
    points, triangles = icosphere(frequency)
    first = len(mesh.vertices)
    for p in points:
        mesh.vertex(add(centre, mul(p, radius)), p if normals else None)
    for a, b, c in triangles:
        mesh.facet(first + a, first + b, first + c, material)
    return len(triangles)


def add_floor_quad(mesh, x0, x1, y0, y1, z, material):
    i = mesh.vertex((x0, y0, z))
    j = mesh.vertex((x1, y0, z))
    k = mesh.vertex((x1, y1, z))
    l = mesh.vertex((x0, y1, z))
    mesh.quad(i, j, k, l, material)


def smooth_sphere(outdir):
    mesh = Mesh()
    # the sphere: radius 1 about the origin, 80 facets, matte orange with a
    # faint highlight; the floor 1.02 below its centre (a gap of 0.02)
    n = add_sphere(mesh, (0.0, 0.0, 0.0), 1.0, 2,
                   '0 230 140 60  0 1  1 0.25 30')
    add_floor_quad(mesh, -7.0, 7.0, -5.0, 9.0, -1.02,
                   '0 200 200 190')
    obs = (0.31, -5.2, 1.13)
    a, b = screen_for(obs, (0.0, 0.0, -0.15), 1.0, 0.42)
    header = (
        'smooth-sphere.scn - a low-poly sphere with exact vertex normals\n'
        '(SPEC section 8 smooth shading), lit from the side.\n'
        '\n'
        'A unit sphere at the origin: an icosahedron each of whose faces is\n'
        'cut into 4 (%d facets), every vertex on the sphere carrying its\n'
        'exact normal (the vertex itself); k = 0, d = 1, a faint highlight\n'
        's = 0.25, p = 30.  A matte floor at z = -1.02.  One white light\n'
        'at (6, -2.5, 1.2), to the right and a little in front: the shadow\n'
        'terminator runs down the middle of the sphere, and with Hanika\'s\n'
        'shading point it is a smooth curve, not a staircase of facets.\n'
        'The sphere\'s shadow falls on the floor to the left.' % n)
    write_scene(os.path.join(outdir, 'smooth-sphere.scn'), header, obs, a, b,
                200, 150, mesh, (20, 24, 40),
                [((6.0, -2.5, 1.2), (255, 255, 255))])


def smooth_glass(outdir):
    mesh = Mesh()
    n = add_sphere(mesh, (0.0, 0.0, 0.0), 1.0, 4,
                   '0 235 245 255  0.9 1.5  0.1 0.5 60')
    # a checkered wall (8 x 6 squares of 1) at y = 2.6 and floor (8 x 6)
    # at z = -1.05, both matte
    colours = [(230, 70, 60), (245, 225, 90), (60, 120, 220), (240, 240, 240)]
    squares = 0
    for row in range(6):
        for col in range(8):
            x0, z0 = -4.0 + col, -1.05 + row
            c = colours[(row + col) % 2 + 2 * (row // 3)]
            i = mesh.vertex((x0, 2.6, z0))
            j = mesh.vertex((x0 + 1.0, 2.6, z0))
            k = mesh.vertex((x0 + 1.0, 2.6, z0 + 1.0))
            l = mesh.vertex((x0, 2.6, z0 + 1.0))
            mesh.quad(i, j, k, l, '0 %d %d %d' % c)
            squares += 1
    for row in range(6):
        for col in range(8):
            x0, y0 = -4.0 + col, -3.4 + row
            c = (200, 200, 200) if (row + col) % 2 else (60, 60, 70)
            add_floor_quad(mesh, x0, x0 + 1.0, y0, y0 + 1.0, -1.05,
                           '0 %d %d %d' % c)
            squares += 1
    obs = (0.23, -5.4, 0.71)
    a, b = screen_for(obs, (0.0, 0.0, 0.1), 1.0, 0.6)
    header = (
        'smooth-glass.scn - a smooth glass ball (SPEC sections 7 and 8).\n'
        '\n'
        'A unit sphere at the origin, an icosahedron whose faces are each\n'
        'cut into 16 (%d facets, wound counter-clockwise seen from\n'
        'outside), exact vertex normals; glass: k = 0, t = 0.9, n = 1.5,\n'
        'd = 0.1, highlight s = 0.5, p = 60.  Behind it a checkered wall\n'
        '(y = 2.6, red/yellow below, blue/white above) and a checkered floor\n'
        '(z = -1.05), %d squares of 2 facets.  One white light, up and to\n'
        'the left.  Through the ball the checks are seen upside down and\n'
        'reversed, smoothly bent (no facet stripes).' % (n, squares))
    write_scene(os.path.join(outdir, 'smooth-glass.scn'), header, obs, a, b,
                200, 150, mesh, (30, 30, 40),
                [((-4.0, -5.0, 6.0), (255, 255, 255))])


# ------------------------------------------------------------------ teapot
def bernstein(t):
    s = 1.0 - t
    return (s * s * s, 3.0 * s * s * t, 3.0 * s * t * t, t * t * t)


def bernstein_d(t):
    s = 1.0 - t
    return (-3.0 * s * s, 3.0 * s * s - 6.0 * s * t,
            6.0 * s * t - 3.0 * t * t, 3.0 * t * t)


def patch_eval(ctrl, u, v):
    """Point, d/du and d/dv of a bicubic Bezier patch (ctrl: 4 rows of 4,
    u along the rows' order, v along a row)."""
    bu, bv, du, dv = bernstein(u), bernstein(v), bernstein_d(u), \
        bernstein_d(v)
    p, pu, pv = [0.0] * 3, [0.0] * 3, [0.0] * 3
    for i in range(4):
        for j in range(4):
            q = ctrl[i][j]
            for c in range(3):
                p[c] += bu[i] * bv[j] * q[c]
                pu[c] += du[i] * bv[j] * q[c]
                pv[c] += bu[i] * dv[j] * q[c]
    return tuple(p), tuple(pu), tuple(pv)


def patch_normal(ctrl, u, v):
    """The unit normal du x dv; where it vanishes (a patch whose row of
    control points collapses to a pole) the limit towards the inside of the
    patch: du x dv evaluated 1e-4 inside along u.  Poles on the z axis (the
    lid's knob, the bottom) get exactly (0, 0, +-1), their tangent plane
    being horizontal by symmetry."""
    p, pu, pv = patch_eval(ctrl, u, v)
    n = cross(pu, pv)
    if math.sqrt(dot(n, n)) < 1e-9:
        inner = u + 1e-4 if u < 0.5 else u - 1e-4
        _, pu, pv = patch_eval(ctrl, inner, v)
        n = cross(pu, pv)
        if abs(p[0]) < 1e-12 and abs(p[1]) < 1e-12:
            n = (0.0, 0.0, 1.0 if n[2] > 0.0 else -1.0)
    return p, unit(n)


def teapot(outdir):
    points = teapot_data.POINTS
    mesh = Mesh()
    resolution = 4
    body = '0 185 55 45  0 1  0.8 0.6 30'
    count = 0
    for number, patch in enumerate(teapot_data.PATCHES, 1):
        if number > 28:     # the bottom (patches 29-32): never seen
            continue
        ctrl = [[points[patch[4 * i + j] - 1] for j in range(4)]
                for i in range(4)]
        # Newell's patches are all oriented alike: du x dv points into the
        # pot (into the handle's and spout's tubes, below the lid's knob:
        # checked patch by patch at its centre when this was written), so
        # every normal is turned round to point outwards.
        flip = True
        grid = []
        for i in range(resolution + 1):
            row = []
            for j in range(resolution + 1):
                p, n = patch_normal(ctrl, i / resolution, j / resolution)
                if flip:
                    n = mul(n, -1.0)
                row.append(mesh.vertex(p, n))
            grid.append(row)

        def place(idx):
            return mesh.vertices[idx][0]
        for i in range(resolution):
            for j in range(resolution):
                a, b = grid[i][j], grid[i + 1][j]
                c, d = grid[i + 1][j + 1], grid[i][j + 1]
                for tri in ((a, b, c), (a, c, d)):
                    pa, pb, pc = (place(x) for x in tri)
                    area = cross(sub(pb, pa), sub(pc, pa))
                    if math.sqrt(dot(area, area)) < 1e-9:
                        continue        # the collapsed quads at a pole
                    mesh.facet(tri[0], tri[1], tri[2], body)
                    count += 1
    add_floor_quad(mesh, -12.0, 12.0, -9.0, 15.0, 0.0, '0.15 190 190 175')
    obs = (4.3, -9.1, 5.4)
    a, b = screen_for(obs, (0.2, 0.0, 1.25), 1.0, 0.45)
    header = (
        'teapot.scn - the Utah teapot with smooth shading and highlights\n'
        '(SPEC section 8).\n'
        '\n'
        'Martin Newell\'s 1975 Bezier patches (tools/scenes/teapot_data.py),\n'
        'the bottom left out (never seen), each of the 28 others cut into\n'
        '4 x 4 quads of 2 triangles (the collapsed ones at the lid\'s pole\n'
        'dropped): %d facets, every vertex with the exact normal of its\n'
        'patch (du x dv, turned outwards; at a pole its limit).  The pot:\n'
        'k = 0, d = 0.8, brick red, highlight s = 0.6, p = 30.  A floor at\n'
        'z = 0 (k = 0.15).  Two lights: a white key light up and to the\n'
        'right, a dimmer blue fill light to the left; each gives its own\n'
        'highlight and shadow.' % count)
    write_scene(os.path.join(outdir, 'teapot.scn'), header, obs, a, b,
                200, 150, mesh, (25, 28, 40),
                [((1.5, -8.0, 9.0), (255, 250, 240)),
                 ((-9.0, -4.0, 6.0), (90, 110, 170))])


def main(argv):
    outdir = argv[1] if len(argv) > 1 else os.path.join(
        os.path.dirname(os.path.abspath(__file__)), '..', '..', 'scenes')
    smooth_sphere(outdir)
    smooth_glass(outdir)
    teapot(outdir)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
