#!/usr/bin/env python3
"""stiff_ground.py - a ground far wider than the eye is high, and its exact image.

Usage:
    python3 tests/reference/stiff_ground.py RATIO ORIENTATION PRECISION OUT.scn OUT.ppm

Writes a scene: a square ground of half-size RATIO * 1.7 made of two
facets, an eye 1.7 above its centre looking along it (so the horizon falls
between the two middle rows of a 32 x 32 image), a light 1e30 away along
the ground's normal; ORIENTATION `flat` puts the ground on z = 0,
`tilted` turns the whole scene by two rotations with rational sines (3/5,
4/5 about x, then 5/13, 12/13 about z), so that no coordinate is round.
Then writes the image the rendering model gives for that scene, computed
with exact rational arithmetic (fractions.Fraction) from the coordinates as
a render in PRECISION (`double` or `float`) holds them: the file's decimal
numbers are exact doubles, and a float render rounds each to the nearest
float.  Nothing here shares code with the C renderer.

Why the colours are exact: the ground's colour is (200, 150, 100) with
k = 0 and a white light (255) so far along the normal that N.S is 1 to
about 1e-15: the diffuse term is the colour itself, an integer, in either
precision.  A pixel whose ray misses the ground shows the background
(40, 80, 200).  A ground seen from below (an eye that float's rounding of
the vertices puts under the plane) faces the light away: black.
"""

import struct
import sys
from fractions import Fraction as Q

SIDE = 32
HEIGHT = 1.7
GROUND = (200, 150, 100)
SKY = (40, 80, 200)


def rotate(p):
    """The two rotations of `tilted`, in exact rationals."""
    x, y, z = p
    c, s = Q(3, 5), Q(4, 5)             # about x
    y, z = c * y - s * z, s * y + c * z
    c, s = Q(5, 13), Q(12, 13)          # about z
    x, y = c * x - s * y, s * x + c * y
    return (x, y, z)


def to_double(p):
    return tuple(float(v) for v in p)


def to_float(v):
    return struct.unpack('f', struct.pack('f', v))[0]


def scene(ratio, orientation):
    """Observer, screen centre, screen right, vertices, light (doubles)."""
    h = Q(HEIGHT)
    half = Q(ratio) * h
    points = {
        'O': (Q(0), Q(0), h),
        'A': (Q(0), Q(1), h),
        'B': (Q(1), Q(1), h),
        'L': (Q(0), Q(0), Q(10) ** 30),
        'v1': (-half, -half, Q(0)), 'v2': (half, -half, Q(0)),
        'v3': (half, half, Q(0)), 'v4': (-half, half, Q(0)),
    }
    if orientation == 'tilted':
        points = {k: rotate(v) for k, v in points.items()}
    return {k: to_double(v) for k, v in points.items()}


def write_scene(s, path):
    r = repr
    with open(path, 'w') as f:
        f.write('# stiff_ground.py: a ground far wider than the eye is high\n')
        f.write('%s, %s, %s\n' % tuple(map(r, s['O'])))
        f.write('%s, %s, %s,  %s, %s, %s,  %d, %d\n'
                % (tuple(map(r, s['A'])) + tuple(map(r, s['B'])) + (SIDE, SIDE)))
        f.write('4\n')
        for k in ('v1', 'v2', 'v3', 'v4'):
            f.write('%s, %s, %s\n' % tuple(map(r, s[k])))
        f.write('2\n1, 2, 3, 0, %d, %d, %d\n1, 3, 4, 0, %d, %d, %d\n'
                % (GROUND + GROUND))
        f.write('%d, %d, %d\n' % SKY)
        f.write('%s, %s, %s, 255, 255, 255\n' % tuple(map(r, s['L'])))


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0])


def camera_rays(s, precision):
    """Each pixel's ray (origin, direction), as the renderer computes them:
    the camera model in double (the screen's B is already perpendicular:
    AB is along x, AO along y before the rotation, so no projection), then
    rounded to float for a float render.  Returns exact rationals."""
    o, a, b = s['O'], s['A'], s['B']
    ab = tuple(x - y for x, y in zip(b, a))
    ao = tuple(x - y for x, y in zip(o, a))
    c = (ao[1] * ab[2] - ao[2] * ab[1], ao[2] * ab[0] - ao[0] * ab[2],
         ao[0] * ab[1] - ao[1] * ab[0])
    # AC = (AO x AB) |AB| / |AO x AB|: here |AB| = |AO| = 1 up to rounding,
    # and the rays' rounding cannot move a pixel centre across the horizon
    # (half a pixel away): the classification below is exact.
    n_ab = sum(x * x for x in ab) ** 0.5
    n_c = sum(x * x for x in c) ** 0.5
    ac = tuple(x * n_ab / n_c for x in c)
    rays = []
    for j in range(SIDE):
        row = []
        for i in range(SIDE):
            sx = (2 * (i + 0.5)) / SIDE - 1
            sy = 1 - (2 * (j + 0.5)) / SIDE
            p = tuple(a[k] + sx * ab[k] + sy * ac[k] for k in range(3))
            d = tuple(p[k] - o[k] for k in range(3))
            origin = o
            if precision == 'float':
                origin = tuple(map(to_float, origin))
                d = tuple(map(to_float, d))
            row.append((tuple(map(Q, origin)), tuple(map(Q, d))))
        rays.append(row)
    return rays


def hits(origin, d, tri):
    """Exact: the line meets the closed triangle at t > 0."""
    a, b, c = tri
    n = cross(sub(b, a), sub(c, a))
    across = dot(n, d)
    if across == 0:
        return False
    t = dot(n, sub(a, origin)) / across
    if t <= 0:
        return False
    p = tuple(origin[k] + t * d[k] for k in range(3))
    for u, v in ((a, b), (b, c), (c, a)):
        if dot(cross(sub(v, u), sub(p, u)), n) < 0:
            return False
    return True


def image(s, precision):
    conv = (lambda v: tuple(Q(to_float(x)) for x in v)) if precision == 'float' \
        else (lambda v: tuple(Q(x) for x in v))
    v = [conv(s[k]) for k in ('v1', 'v2', 'v3', 'v4')]
    light = conv(s['L'])
    tris = [(v[0], v[1], v[2]), (v[0], v[2], v[3])]
    normal = cross(sub(v[1], v[0]), sub(v[2], v[0]))
    pixels = []
    for row in camera_rays(s, precision):
        for origin, d in row:
            if not any(hits(origin, d, t) for t in tris):
                pixels.append(SKY)
                continue
            # The normal faces the ray; lit when the light is on that side
            # (nothing else can shadow: the two facets are coplanar).
            facing = -1 if dot(normal, d) > 0 else 1
            lit = facing * dot(normal, sub(light, v[0])) > 0
            pixels.append(GROUND if lit else (0, 0, 0))
    return pixels


def main(argv):
    if len(argv) != 6 or argv[2] not in ('flat', 'tilted') or \
            argv[3] not in ('double', 'float'):
        sys.stderr.write(__doc__)
        return 2
    ratio, orientation, precision = float(argv[1]), argv[2], argv[3]
    s = scene(ratio, orientation)
    write_scene(s, argv[4])
    with open(argv[5], 'wb') as f:
        f.write(b'P6\n%d %d\n255\n' % (SIDE, SIDE))
        f.write(bytes(c for p in image(s, precision) for c in p))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
