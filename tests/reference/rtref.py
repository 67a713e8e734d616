#!/usr/bin/env python3
"""rtref.py - an independent reference renderer for libraytrace scenes.

Implements SPEC.md sections 1-4 from the text alone, in pure Python 3
(standard library only), so that the C renderer's images can be checked
against something that shares none of its code.  It is meant to be correct
for the project's own, well-conditioned scenes, not robust in general.

Usage:
    python3 tests/reference/rtref.py SCENE.scn OUT.ppm [--depth N] [--p3]

Choices, where they differ on purpose from the C library:

* Parsing: tokens are separated by commas and/or white space, '#' starts a
  comment, a UTF-8 BOM and CRLF are accepted; records are read in the order
  of SPEC section 1.  Only light validation (enough for valid files): counts,
  record lengths, indices in 1..n.
* Camera (SPEC 2): B is replaced by its orthogonal projection on the plane
  through A perpendicular to AO; AC = (AO x AB) |AB| / |AO x AB|; pixel
  (i, j) is seen through P = A + (2(i+1/2)/w - 1) AB
  + (1 - 2(j+1/2)/h) (h/w) AC, and the primary ray starts at O with the
  unit direction of P - O (a facet between O and the screen is visible).
* Intersection: Moller-Trumbore in double, two-sided (no culling), the
  triangle's border counts as inside (u >= 0, v >= 0, u + v <= 1).  The C
  code uses Woop et al.'s watertight test instead.  A facet whose edge cross
  product is zero (collinear vertices) is dropped at load time: never hit.
* Secondary rays (shadow and reflection) start exactly at the hit point,
  ignore the facet they leave, and only accept hits with t > EPS_REL * scale,
  where scale is the largest absolute coordinate in the scene (vertices, O,
  A, B, light) and EPS_REL = 1e-9.  (The C code instead offsets the origin
  along the normal by a bound relative to the coordinates' magnitude.)
  A shadow ray is blocked by a hit with EPS < t < d (1 - 1e-9), d the
  distance to the light: "strictly between".
* Shading (SPEC 3), per channel:
      C = k C_R + E (1 - k) (N.S) C_S C_F / 255
  N faces the incoming ray, E = 1 when N.S > 0 and the shadow ray is free.
  C_R is traced only when k > 0 (k C_R = 0 otherwise).  Reflection level:
  the primary ray is level 0; a hit on a ray of level L traces its
  reflection only if L < depth, otherwise C_R = 0 (black).
* Colours are Python floats through the recursion; each channel is clamped
  to [0, 255] and rounded half away from zero (floor(x + 0.5)) once.
* Output: PPM P6 (default) or P3 (--p3, lines of at most 70 characters),
  maxval 255, rows top to bottom.
"""

import math
import re
import sys

EPS_REL = 1e-9


# ---------------------------------------------------------------- vectors
def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def mul(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0])


def norm(a):
    return math.sqrt(dot(a, a))


def unit(a):
    return mul(a, 1.0 / norm(a))


# ---------------------------------------------------------------- parsing
class SceneError(Exception):
    pass


def read_records(text):
    """Yields (line_number, [float, ...]) for every non-empty line."""
    if text.startswith('\ufeff'):
        text = text[1:]
    for number, line in enumerate(text.splitlines(), 1):
        line = line.split('#', 1)[0]
        tokens = [t for t in re.split(r'[,\s]+', line) if t]
        if tokens:
            yield number, [float(t) for t in tokens]


def integral(x, what, line):
    if x != math.floor(x):
        raise SceneError('line %d: %s must be integral, found %r'
                         % (line, what, x))
    return int(x)


class Scene:
    pass


def parse_scene(text):
    records = read_records(text)

    def take(count, what):
        try:
            line, values = next(records)
        except StopIteration:
            raise SceneError('unexpected end of file: expected ' + what)
        if len(values) != count:
            raise SceneError('line %d: expected %d values for %s, found %d'
                             % (line, count, what, len(values)))
        for v in values:
            if not math.isfinite(v):
                raise SceneError('line %d: non-finite number' % line)
        return line, values

    s = Scene()
    _, s.obs = take(3, 'the observer')
    _, screen = take(8, 'the screen')
    s.a, s.b = tuple(screen[0:3]), tuple(screen[3:6])
    line, _ = 0, None
    s.width = integral(screen[6], 'w', 0)
    s.height = integral(screen[7], 'h', 0)
    line, (n,) = take(1, 'the vertex count')
    n = integral(n, 'n', line)
    s.vertices = [tuple(take(3, 'a vertex')[1]) for _ in range(n)]
    line, (m,) = take(1, 'the facet count')
    m = integral(m, 'm', line)
    s.facets = []
    for _ in range(m):
        line, v = take(7, 'a facet')
        idx = [integral(x, 'index', line) for x in v[0:3]]
        for i in idx:
            if not 1 <= i <= n:
                raise SceneError('line %d: index %d not in 1..%d'
                                 % (line, i, n))
        k = v[3]
        if not 0.0 <= k <= 1.0:
            raise SceneError('line %d: k not in [0, 1]' % line)
        colour = tuple(float(integral(c, 'colour', line)) for c in v[4:7])
        s.facets.append((tuple(s.vertices[i - 1] for i in idx), k, colour))
    _, bg = take(3, 'the background colour')
    s.background = tuple(bg)
    _, light = take(6, 'the light source')
    s.light, s.light_colour = tuple(light[0:3]), tuple(light[3:6])
    extra = next(records, None)
    if extra is not None:
        raise SceneError('line %d: unexpected data after the light source'
                         % extra[0])
    return s


# ---------------------------------------------------------------- geometry
class Facet:
    __slots__ = ('p0', 'e1', 'e2', 'normal', 'k', 'colour')

    def __init__(self, vertices, k, colour):
        a, b, c = vertices
        self.p0 = a
        self.e1 = sub(b, a)
        self.e2 = sub(c, a)
        self.normal = unit(cross(self.e1, self.e2))
        self.k = k
        self.colour = colour


def make_facets(scene):
    facets = []
    for vertices, k, colour in scene.facets:
        a, b, c = vertices
        e1, e2 = sub(b, a), sub(c, a)
        if norm(cross(e1, e2)) <= 1e-14 * norm(e1) * norm(e2):
            sys.stderr.write('rtref: warning: degenerate facet ignored\n')
            continue
        facets.append(Facet(vertices, k, colour))
    return facets


def intersect(facet, origin, direction):
    """Moller-Trumbore: the t of the hit, or None."""
    e1, e2 = facet.e1, facet.e2
    p = cross(direction, e2)
    det = dot(e1, p)
    if det == 0.0 or abs(det) < 1e-15 * norm(e1) * norm(e2):
        return None                     # ray parallel to the plane
    inv = 1.0 / det
    s = sub(origin, facet.p0)
    u = dot(s, p) * inv
    if u < 0.0 or u > 1.0:
        return None
    q = cross(s, e1)
    v = dot(direction, q) * inv
    if v < 0.0 or u + v > 1.0:
        return None
    return dot(e2, q) * inv


class Renderer:
    def __init__(self, scene, depth):
        self.scene = scene
        self.depth = depth
        self.facets = make_facets(scene)
        points = [scene.obs, scene.a, scene.b, scene.light] + scene.vertices
        scale = max(1e-300, max(abs(c) for p in points for c in p))
        self.eps = EPS_REL * scale
        self.light = scene.light
        self.light_colour = scene.light_colour
        self.background = scene.background

    def nearest(self, origin, direction, skip, tmin):
        best_t, best = math.inf, None
        for f in self.facets:
            if f is skip:
                continue
            t = intersect(f, origin, direction)
            if t is not None and tmin < t < best_t:
                best_t, best = t, f
        return best_t, best

    def blocked(self, origin, direction, distance, skip):
        tmax = distance * (1.0 - 1e-9)
        for f in self.facets:
            if f is skip:
                continue
            t = intersect(f, origin, direction)
            if t is not None and self.eps < t < tmax:
                return True
        return False

    def trace(self, origin, direction, level, skip, tmin):
        t, f = self.nearest(origin, direction, skip, tmin)
        if f is None:
            return self.background
        hit = add(origin, mul(direction, t))
        n = f.normal
        if dot(n, direction) > 0.0:
            n = mul(n, -1.0)
        k = f.k
        colour = [0.0, 0.0, 0.0]
        to_light = sub(self.light, hit)
        distance = norm(to_light)
        if distance > 0.0 and k < 1.0:
            s = mul(to_light, 1.0 / distance)
            ns = dot(n, s)
            if ns > 0.0 and not self.blocked(hit, s, distance, f):
                w = (1.0 - k) * ns / 255.0
                for c in range(3):
                    colour[c] = w * self.light_colour[c] * f.colour[c]
        if k > 0.0 and level < self.depth:
            r = sub(direction, mul(n, 2.0 * dot(direction, n)))
            reflected = self.trace(hit, unit(r), level + 1, f, self.eps)
            for c in range(3):
                colour[c] += k * reflected[c]
        return colour

    def render(self):
        s = self.scene
        a, o = s.a, s.obs
        ao = sub(o, a)
        ab = sub(s.b, a)
        ab = sub(ab, mul(ao, dot(ab, ao) / dot(ao, ao)))   # projection of B
        aob = cross(ao, ab)
        if norm(ao) == 0.0 or norm(aob) == 0.0:
            raise SceneError('degenerate camera')
        ac = mul(aob, norm(ab) / norm(aob))
        w, h = s.width, s.height
        rows = []
        for j in range(h):
            y = (1.0 - 2.0 * (j + 0.5) / h) * (h / w)
            row = bytearray()
            for i in range(w):
                x = 2.0 * (i + 0.5) / w - 1.0
                p = add(a, add(mul(ab, x), mul(ac, y)))
                c = self.trace(o, unit(sub(p, o)), 0, None, 0.0)
                for v in c:
                    v = min(255.0, max(0.0, v))
                    row.append(int(math.floor(v + 0.5)))
            rows.append(bytes(row))
        return rows


def write_ppm(path, w, h, rows, ascii_format):
    if not ascii_format:
        with open(path, 'wb') as out:
            out.write(b'P6\n%d %d\n255\n' % (w, h))
            for row in rows:
                out.write(row)
        return
    lines, line = [], ''
    for row in rows:
        for v in row:
            token = str(v)
            if line and len(line) + 1 + len(token) > 70:
                lines.append(line)
                line = token
            else:
                line = line + ' ' + token if line else token
    if line:
        lines.append(line)
    with open(path, 'w', newline='\n') as out:
        out.write('P3\n%d %d\n255\n' % (w, h))
        out.write('\n'.join(lines) + '\n')


def main(argv):
    args, depth, ascii_format = [], 5, False
    it = iter(argv[1:])
    for arg in it:
        if arg == '--depth':
            depth = int(next(it))
        elif arg.startswith('--depth='):
            depth = int(arg.split('=', 1)[1])
        elif arg == '--p3':
            ascii_format = True
        else:
            args.append(arg)
    if len(args) != 2 or depth < 0:
        sys.stderr.write('usage: rtref.py SCENE.scn OUT.ppm [--depth N] '
                         '[--p3]\n')
        return 2
    with open(args[0], encoding='utf-8') as f:
        text = f.read()
    try:
        scene = parse_scene(text)
        rows = Renderer(scene, depth).render()
    except SceneError as e:
        sys.stderr.write('rtref: %s: %s\n' % (args[0], e))
        return 1
    write_ppm(args[1], scene.width, scene.height, rows, ascii_format)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
