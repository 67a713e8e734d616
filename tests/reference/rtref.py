#!/usr/bin/env python3
"""rtref.py - an independent reference renderer for libraytrace scenes.

Implements the rendering model (sections 1-4, the extension of section 7:
several lights, transparency and refraction, depth of field, and section 8:
vertex normals, the shading point of the shadow terminator, Phong
highlights) from the text alone, in pure Python 3 (standard library only), so that the C renderer's
images can be checked against something that shares none of its code.  It
is meant to be correct for the project's own, well-conditioned scenes, not
robust in general.

Usage:
    python3 tests/reference/rtref.py SCENE.scn OUT.ppm [--depth N]
                                     [--samples N] [--p3]

Choices, where they differ on purpose from the C library:

* Parsing: tokens are separated by commas and/or white space, '#' starts a
  comment, a UTF-8 BOM and CRLF are accepted; records are read in the order
  of section 1, with the extended records of sections 7 and 8:
      screen  xA,yA,zA, xB,yB,zB, w,h [, a, f]   (a = 0, f = |AO| by default)
      vertex  x,y,z [, nx,ny,nz]                 (a vertex normal)
      facet   a,b,c, k, R,G,B [, t [, n [, d [, s, p]]]]
              (t = 0, n = 1, d = 1 - k - t, s = 0, p = 1 by default)
      light   x,y,z, R,G,B, then zero or more further lights, one a line,
              until the end of the file.
  Validation is light (enough for valid files, with line and column):
  counts, record lengths, integral values, indices in 1..n, colours in
  0..255, k >= 0, t >= 0, k + t <= 1, n > 0, a >= 0, f > 0, d >= 0 (any
  k + t + d), s >= 0, p >= 1, a vertex normal finite and non-zero.  A
  vertex normal is normalised on load (n / |n|, one division per
  component); a facet is smooth when all three of its vertices carry one.
* Camera (section 2): B is replaced by its orthogonal projection on the
  plane through A perpendicular to AO (AB' below); AC' = (AO x AB')|AB'| /
  |AO x AB'|.  A point at pixel coordinates (x, y) (x from the left edge,
  y from the top edge, in pixels) is P = A + s AB' + t AC' with
  s = (2x - w)/w and t = (h - 2y)/w; pixel (i, j)'s centre is
  (i + 1/2, j + 1/2).  The primary ray starts at O with the unit direction
  of P - O (a facet between O and the screen is visible).
* Samples and depth of field (section 7), the project's decisions:
  --samples N (N = n*n a square, default 1) takes n x n samples per pixel.
  Sample (sx, sy), sx the column and sy the row of the pixel's n x n
  sub-grid, sy the outer loop and sx the inner one, looks through the
  screen point at pixel coordinates (i + (sx+1/2)/n, j + (sy+1/2)/n).
  With aperture a = 0 its ray is O -> P (no lens arithmetic at all).
  With a > 0 the lens point uses the TRANSPOSED stratum:
      (xl, yl) = ((sy+1/2)/n, (sx+1/2)/n),  p = 2 xl - 1,  q = 2 yl - 1,
  mapped to the unit disk by Shirley and Chiu's concentric mapping:
      p = q = 0      -> (u, v) = (0, 0)
      |p| > |q|      -> r = p, phi = (pi/4)(q/p)
      otherwise      -> r = q, phi = pi/2 - (pi/4)(p/q)
      (u, v) = (r cos phi, r sin phi);
  L = O + a (u AB'/|AB'| + v AC'/|AC'|), w^ = (A - O)/|A - O|,
  F = O + (P - O) f / ((P - O).w^), and the ray starts at L with the unit
  direction of F - L.  The pixel is the mean of its samples: their sum in
  that loop order, times 1/(n n), then clamped and rounded once.  With
  --samples 1 the single sample is the pixel centre and the lens centre.
* Intersection: Moller-Trumbore in double, two-sided (no culling), the
  triangle's border counts as inside (u >= 0, v >= 0, u + v <= 1).  The C
  code uses Woop et al.'s watertight test instead.  A facet whose edge cross
  product is zero (collinear vertices) is dropped at load time: never hit.
* Secondary rays (shadow, reflection, refraction) start exactly at the hit
  point, ignore the facet they leave, and only accept hits with
  t > EPS_REL * scale, where scale is the largest absolute coordinate in
  the scene (vertices, O, A, B, every light) and EPS_REL = 1e-9.  (The C
  code instead offsets the origin along the normal by a bound relative to
  the coordinates' magnitude.)  A shadow ray is blocked by a hit on any
  facet, transparent or not, with EPS < t < d (1 - 1e-9), d the distance
  to the light: "strictly between" (shadows stay hard).
* Shading (sections 3 and 7), per channel, d = 1 - k - t:
      C = k C_R + t C_T + d sum_l E_l (N.S_l) C_S,l C_F / 255
  N faces the incoming ray, E_l = 1 when N.S_l > 0 and the shadow ray to
  light l is free.  Evaluation order: the light terms first, light by
  light in file order, each (d (N.S_l) / 255) C_S,l C_F, then + k C_R,
  then + t C_T (with t = 0 and one light this is exactly the handout
  renderer's arithmetic).  The direct term is skipped when d <= 0 (d is
  computed in double, so k + t = 1 may leave a d of about 1e-17 either
  side of 0).  C_R is traced only when k > 0 and C_T only when t > 0 (a
  term with zero weight is not traced).
* Refraction (section 7): n_w the unit winding normal (b-a) x (c-a); with
  I the unit incoming direction, I.n_w < 0 enters (eta = 1/n, N_t = n_w),
  otherwise the ray leaves (eta = n, N_t = -n_w); c = -I.N_t,
  q = 1 - eta^2 (1 - c^2).  q < 0: total internal reflection, C_T is the
  colour of the mirror ray R = I - 2 (I.N) N (the same ray as C_R, traced
  once when both are needed); otherwise C_T is the colour of the ray of
  unit direction T = eta I + (eta c - sqrt(q)) N_t.
* Section 8, smooth facets.  The hit's barycentric weights are
  Moller-Trumbore's: (b_a, b_b, b_c) = (1 - u - v, u, v).  N_g is the
  facet's normal turned to face the incoming ray (the N above).  The
  shading normal N_s = normalise(b_a n_a + b_b n_b + b_c n_c), turned to
  N_g's side (N_s := -N_s when N_s.N_g < 0); N_s = N_g where the sum's
  length is zero or not finite, and on a flat facet.  N_s stands in every
  cosine: N.S_l, the highlight, the mirror ray R = I - 2 (I.N_s) N_s, and
  Snell's law (the refraction's enter/leave test stays the winding
  normal's; c and T are computed with N_s turned like N_t, which is N_g).
  A smooth facet's mirror direction with R.N_g <= 0 (below the facet) is
  recomputed with N_g; its refracted direction with T.N_g >= 0 (above the
  facet) is recomputed with N_t = N_g (which may then be a total internal
  reflection); a total internal reflection found with N_s stays one and
  takes the mirror ray (itself N_s's, with the same fallback).  On a flat
  facet none of this runs: the arithmetic is exactly that of section 7.
* The shadow terminator (section 8).  The shading point, Hanika's
      P' = P + sum_i b_i (P - v_i - min(0, (P - v_i).n_i) n_i)
  is computed in its collected form P' = P - sum_i b_i min(0,
  (P - v_i).n_i) n_i (the same in exact arithmetic, as sum_i b_i v_i = P
  and sum_i b_i = 1), with the corner normals as loaded (not turned), the
  corners' terms added in the order a, b, c and only where (P - v_i).n_i
  < 0; on a flat facet P' = P.  READING OF THE SPEC: S_l is section 3's,
  the unit vector from the hit point P to light l, in N_s.S_l, in the
  diffuse term and in the highlight's R_l; only the shadow ray moves: it
  starts at P', goes towards light l (unit direction of L - P', length
  |L - P'|), skips the facet it leaves and is blocked by a hit with
  EPS < t < |L - P'| (1 - 1e-9).  E_l = 1 when N_s.S_l > 0 and that ray
  is free.
* Highlights (section 8): with V = -I and R_l = 2 (N_s.S_l) N_s - S_l,
  light l adds E_l s max(0, R_l.V)^p C_S,l (the light's colour).  A light
  is considered (shadow ray and all) when d > 0 or s > 0; for each light
  in file order the diffuse term (d (N_s.S_l) / 255) C_S,l C_F is added
  first (when d > 0), then the highlight s (R_l.V)^p C_S,l (when s > 0 and
  R_l.V > 0; Python's ** for the power), and after all lights + k C_R,
  then + t C_T.  So
      C = k C_R + t C_T + sum_l [d E_l (N_s.S_l) C_S,l C_F / 255
                                 + E_l s max(0, R_l.V)^p C_S,l].
  With no vertex normal and s = 0 everywhere this is section 7's
  arithmetic, operation for operation.
* Speed only: facets are grouped in runs of 16 consecutive ones (file
  order), each with a bounding sphere enlarged by a margin far above
  rounding; a ray whose line misses a run's sphere, or whose [tmin, tmax]
  cannot reach it, skips the run.  Every facet that could be hit is still
  tested, in file order, so the nearest hit (ties included) is the one a
  test of every facet finds.
* Depth: the primary ray is level 0; every reflected or refracted ray is
  one level more.  A hit on a ray of level L traces its reflected and
  refracted rays only if L < depth, otherwise C_R = C_T = 0 (black).
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


TOKEN = re.compile(r'[^,\s]+')


def read_records(text):
    """Yields (line_number, [float, ...], [column, ...]) for every non-empty
    line (columns 1-based, in characters, the BOM not counted)."""
    if text.startswith('\ufeff'):
        text = text[1:]
    for number, line in enumerate(text.splitlines(), 1):
        line = line.split('#', 1)[0]
        values, columns = [], []
        for m in TOKEN.finditer(line):
            try:
                values.append(float(m.group()))
            except ValueError:
                raise SceneError('line %d, column %d: expected a number, '
                                 'found %r' % (number, m.start() + 1,
                                               m.group()))
            columns.append(m.start() + 1)
        if values:
            yield number, values, columns


def integral(x, what, line, column=None):
    if x != math.floor(x):
        raise SceneError('%s: %s must be integral, found %r'
                         % (where(line, column), what, x))
    return int(x)


def where(line, column=None):
    if column is None:
        return 'line %d' % line
    return 'line %d, column %d' % (line, column)


def colour_of(values, columns, line):
    out = []
    for v, col in zip(values, columns):
        c = integral(v, 'a colour component', line, col)
        if not 0 <= c <= 255:
            raise SceneError('%s: colour component %d not in 0..255'
                             % (where(line, col), c))
        out.append(float(c))
    return tuple(out)


class Scene:
    pass


def parse_scene(text):
    records = read_records(text)

    def take(counts, what):
        try:
            line, values, columns = next(records)
        except StopIteration:
            raise SceneError('unexpected end of file: expected ' + what)
        if len(values) not in counts:
            raise SceneError('line %d: expected %s values for %s, found %d'
                             % (line, ' or '.join(str(c) for c in counts),
                                what, len(values)))
        for v, col in zip(values, columns):
            if not math.isfinite(v):
                raise SceneError('%s: non-finite number' % where(line, col))
        return line, values, columns

    s = Scene()
    _, obs, _ = take((3,), 'the observer')
    s.obs = tuple(obs)
    line, screen, cols = take((8, 10), 'the screen')
    s.a, s.b = tuple(screen[0:3]), tuple(screen[3:6])
    s.width = integral(screen[6], 'w', line, cols[6])
    s.height = integral(screen[7], 'h', line, cols[7])
    for v, col in ((s.width, cols[6]), (s.height, cols[7])):
        if not 1 <= v <= 16384:
            raise SceneError('%s: w and h must be in 1..16384, found %d'
                             % (where(line, col), v))
    if len(screen) == 10:
        s.aperture, s.focus = screen[8], screen[9]
        if not s.aperture >= 0.0:
            raise SceneError('%s: the aperture a must be >= 0, found %r'
                             % (where(line, cols[8]), s.aperture))
        if not s.focus > 0.0:
            raise SceneError('%s: the focal distance f must be > 0, found %r'
                             % (where(line, cols[9]), s.focus))
    else:
        s.aperture, s.focus = 0.0, norm(sub(s.obs, s.a))
    line, (n,), cols = take((1,), 'the vertex count')
    n = integral(n, 'n', line, cols[0])
    s.vertices, s.normals = [], []
    for _ in range(n):
        line, v, cols = take((3, 6), 'a vertex')
        s.vertices.append(tuple(v[0:3]))
        if len(v) == 6:
            nv = tuple(v[3:6])
            length = norm(nv)
            if not (length > 0.0 and math.isfinite(length)):
                raise SceneError('%s: a vertex normal must be non-zero, '
                                 'found %r' % (where(line, cols[3]), nv))
            s.normals.append(mul(nv, 1.0 / length))
        else:
            s.normals.append(None)
    line, (m,), cols = take((1,), 'the facet count')
    m = integral(m, 'm', line, cols[0])
    s.facets = []
    for _ in range(m):
        line, v, cols = take((7, 8, 9, 10, 12), 'a facet')
        idx = [integral(x, 'index', line, col)
               for x, col in zip(v[0:3], cols[0:3])]
        for i, col in zip(idx, cols):
            if not 1 <= i <= n:
                raise SceneError('%s: index %d not in 1..%d'
                                 % (where(line, col), i, n))
        k = v[3]
        if not k >= 0.0:
            raise SceneError('%s: k must be >= 0, found %r'
                             % (where(line, cols[3]), k))
        colour = colour_of(v[4:7], cols[4:7], line)
        t = v[7] if len(v) >= 8 else 0.0
        ior = v[8] if len(v) >= 9 else 1.0
        if not t >= 0.0:
            raise SceneError('%s: t must be >= 0, found %r'
                             % (where(line, cols[7]), t))
        if not k + t <= 1.0:
            raise SceneError('%s: k + t must be <= 1, found %r + %r'
                             % (where(line, cols[7] if len(v) >= 8
                                      else cols[3]), k, t))
        if not ior > 0.0:
            raise SceneError('%s: the refractive index n must be > 0, '
                             'found %r' % (where(line, cols[8]), ior))
        if len(v) >= 10:
            d = v[9]
            if not d >= 0.0:
                raise SceneError('%s: d must be >= 0, found %r'
                                 % (where(line, cols[9]), d))
        else:
            d = 1.0 - k - t
        if len(v) == 12:
            shine, exponent = v[10], v[11]
            if not shine >= 0.0:
                raise SceneError('%s: s must be >= 0, found %r'
                                 % (where(line, cols[10]), shine))
            if not exponent >= 1.0:
                raise SceneError('%s: p must be >= 1, found %r'
                                 % (where(line, cols[11]), exponent))
        else:
            shine, exponent = 0.0, 1.0
        corner_normals = tuple(s.normals[i - 1] for i in idx)
        if any(x is None for x in corner_normals):
            corner_normals = None
        s.facets.append((tuple(s.vertices[i - 1] for i in idx), k, colour,
                         t, ior, d, shine, exponent, corner_normals))
    line, bg, cols = take((3,), 'the background colour')
    s.background = colour_of(bg, cols, line)
    line, light, cols = take((6,), 'the light source `x, y, z, R, G, B`')
    s.lights = [(tuple(light[0:3]), colour_of(light[3:6], cols[3:6], line))]
    while True:
        try:
            line, light, cols = take((6,), 'a light')
        except SceneError as e:
            if str(e).startswith('unexpected end of file'):
                break
            raise SceneError('%s (after the light source only further '
                             'lights `x, y, z, R, G, B` may follow)' % e)
        s.lights.append((tuple(light[0:3]),
                         colour_of(light[3:6], cols[3:6], line)))
    return s


# ---------------------------------------------------------------- geometry
class Facet:
    __slots__ = ('p0', 'e1', 'e2', 'normal', 'k', 'colour', 't', 'ior', 'd',
                 'vertices', 'normals', 'shine', 'exponent')

    def __init__(self, vertices, k, colour, t, ior, d=None, shine=0.0,
                 exponent=1.0, normals=None):
        a, b, c = vertices
        self.vertices = vertices
        self.p0 = a
        self.e1 = sub(b, a)
        self.e2 = sub(c, a)
        self.normal = unit(cross(self.e1, self.e2))   # the winding normal
        self.k = k
        self.colour = colour
        self.t = t
        self.ior = ior
        self.d = 1.0 - k - t if d is None else d
        self.shine = shine              # s, the highlight weight
        self.exponent = exponent        # p, its exponent
        self.normals = normals          # (n_a, n_b, n_c) unit, or None


def make_facets(scene):
    facets = []
    for record in scene.facets:
        vertices = record[0]
        a, b, c = vertices
        e1, e2 = sub(b, a), sub(c, a)
        if norm(cross(e1, e2)) <= 1e-14 * norm(e1) * norm(e2):
            sys.stderr.write('rtref: warning: degenerate facet ignored\n')
            continue
        facets.append(Facet(*record))
    return facets


def intersect(facet, origin, direction):
    """Moller-Trumbore: (t, u, v) of the hit, or None.  The hit's
    barycentric weights are (1 - u - v, u, v) for the corners (a, b, c)."""
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
    return dot(e2, q) * inv, u, v


def shading_normal(facet, u, v, ng):
    """Section 8: N_s = normalise(sum beta_i n_i) turned to N_g's side;
    N_g where the sum is zero or not finite, or the facet is flat."""
    if facet.normals is None:
        return ng
    na, nb, nc = facet.normals
    wa = 1.0 - u - v
    summed = (wa * na[0] + u * nb[0] + v * nc[0],
              wa * na[1] + u * nb[1] + v * nc[1],
              wa * na[2] + u * nb[2] + v * nc[2])
    length = norm(summed)
    if not (length > 0.0 and math.isfinite(length)):
        return ng
    ns = mul(summed, 1.0 / length)
    if dot(ns, ng) < 0.0:
        ns = mul(ns, -1.0)
    return ns


def shading_point(facet, hit, u, v):
    """Section 8, Hanika's shading point P' = P + sum_i beta_i (P - v_i -
    min(0, (P - v_i).n_i) n_i).  Since sum_i beta_i v_i = P and the weights
    sum to 1, this is P - sum_i beta_i min(0, (P - v_i).n_i) n_i, the form
    computed here (the corner normals as given, normalised; not turned)."""
    if facet.normals is None:
        return hit
    shift = [0.0, 0.0, 0.0]
    for w, corner, n in zip((1.0 - u - v, u, v), facet.vertices,
                            facet.normals):
        along = dot(sub(hit, corner), n)
        if along < 0.0:
            for c in range(3):
                shift[c] += w * along * n[c]
    return (hit[0] - shift[0], hit[1] - shift[1], hit[2] - shift[2])


def refract(direction, winding_normal, ior, normal=None):
    """Section 7: the unit refracted direction, or None for total internal
    reflection.  direction is the unit incoming direction I.  Whether the
    ray enters or leaves is the winding normal's to say; Snell's law uses
    `normal` (section 8's N_s) turned like N_t, or N_t itself when None."""
    if dot(direction, winding_normal) < 0.0:
        eta, nt = 1.0 / ior, winding_normal          # entering
    else:
        eta, nt = ior, mul(winding_normal, -1.0)     # leaving
    if normal is not None:
        nt = normal if dot(normal, nt) >= 0.0 else mul(normal, -1.0)
    c = -dot(direction, nt)
    q = 1.0 - eta * eta * (1.0 - c * c)
    if q < 0.0:
        return None
    return unit(add(mul(direction, eta), mul(nt, eta * c - math.sqrt(q))))


def concentric_disk(p, q):
    """Shirley and Chiu's concentric map of (p, q) in [-1, 1]^2 to the
    unit disk."""
    if p == 0.0 and q == 0.0:
        return 0.0, 0.0
    if abs(p) > abs(q):
        r, phi = p, (math.pi / 4.0) * (q / p)
    else:
        r, phi = q, math.pi / 2.0 - (math.pi / 4.0) * (p / q)
    return r * math.cos(phi), r * math.sin(phi)


CHUNK = 16          # facets per bounding sphere (a pruning that changes no hit)


class Renderer:
    def __init__(self, scene, depth, samples=1):
        self.scene = scene
        self.depth = depth
        self.samples = samples
        self.facets = make_facets(scene)
        points = [scene.obs, scene.a, scene.b] + \
            [p for p, _ in scene.lights] + scene.vertices
        scale = max(1e-300, max(abs(c) for p in points for c in p))
        self.eps = EPS_REL * scale
        self.lights = scene.lights
        self.background = scene.background
        # Consecutive runs of CHUNK facets (file order kept) with a bounding
        # sphere each, enlarged by a margin far above rounding: a ray whose
        # line misses the sphere cannot hit a facet of the run.
        self.chunks = []
        for start in range(0, len(self.facets), CHUNK):
            run = self.facets[start:start + CHUNK]
            corners = [p for f in run for p in f.vertices]
            lo = [min(p[c] for p in corners) for c in range(3)]
            hi = [max(p[c] for p in corners) for c in range(3)]
            centre = tuple(0.5 * (lo[c] + hi[c]) for c in range(3))
            radius = max(norm(sub(p, centre)) for p in corners)
            radius = radius * (1.0 + 1e-6) + 1e-6 * scale
            self.chunks.append((centre, radius, run))

    def candidates(self, origin, direction, tmin, tmax):
        """The runs of facets a ray (unit direction) from origin may hit
        with tmin < t < tmax, in file order."""
        for centre, radius, run in self.chunks:
            oc = sub(centre, origin)
            along = dot(oc, direction)
            if along + radius < tmin or along - radius > tmax:
                continue
            if dot(oc, oc) - along * along > radius * radius:
                continue
            yield run

    def nearest(self, origin, direction, skip, tmin):
        best_t, best, best_uv = math.inf, None, None
        for run in self.candidates(origin, direction, tmin, math.inf):
            for f in run:
                if f is skip:
                    continue
                hit = intersect(f, origin, direction)
                if hit is not None and tmin < hit[0] < best_t:
                    best_t, best, best_uv = hit[0], f, hit[1:]
        return best_t, best, best_uv

    def blocked(self, origin, direction, distance, skip):
        tmax = distance * (1.0 - 1e-9)
        for run in self.candidates(origin, direction, self.eps, tmax):
            for f in run:
                if f is skip:
                    continue
                hit = intersect(f, origin, direction)
                if hit is not None and self.eps < hit[0] < tmax:
                    return True
        return False

    def mirror_direction(self, direction, ns, ng, smooth):
        r = sub(direction, mul(ns, 2.0 * dot(direction, ns)))
        if smooth and dot(r, ng) <= 0.0:        # below the facet: use N_g
            r = sub(direction, mul(ng, 2.0 * dot(direction, ng)))
        return unit(r)

    def trace(self, origin, direction, level, skip, tmin):
        t, f, uv = self.nearest(origin, direction, skip, tmin)
        if f is None:
            return self.background
        hit = add(origin, mul(direction, t))
        n = f.normal                            # N_g, facing the ray
        if dot(n, direction) > 0.0:
            n = mul(n, -1.0)
        smooth = f.normals is not None
        ns = shading_normal(f, uv[0], uv[1], n)
        k, tr, d, shine = f.k, f.t, f.d, f.shine
        colour = [0.0, 0.0, 0.0]
        if d > 0.0 or shine > 0.0:
            start = shading_point(f, hit, uv[0], uv[1])
            view = mul(direction, -1.0)
            for light, light_colour in self.lights:
                to_light = sub(light, hit)      # S_l: from the hit point
                distance = norm(to_light)
                if distance == 0.0:
                    continue
                s = mul(to_light, 1.0 / distance)
                cos = dot(ns, s)
                if not cos > 0.0:
                    continue
                if start is hit:
                    free = not self.blocked(hit, s, distance, f)
                else:                           # the shadow ray leaves P'
                    ray = sub(light, start)
                    length = norm(ray)
                    free = length > 0.0 and not self.blocked(
                        start, mul(ray, 1.0 / length), length, f)
                if not free:
                    continue
                if d > 0.0:
                    w = d * cos / 255.0
                    for c in range(3):
                        colour[c] += w * light_colour[c] * f.colour[c]
                if shine > 0.0:
                    rl = sub(mul(ns, 2.0 * cos), s)
                    rv = dot(rl, view)
                    if rv > 0.0:
                        w = shine * rv ** f.exponent
                        for c in range(3):
                            colour[c] += w * light_colour[c]
        if level < self.depth and (k > 0.0 or tr > 0.0):
            mirror = None
            if k > 0.0:
                r = self.mirror_direction(direction, ns, n, smooth)
                mirror = self.trace(hit, r, level + 1, f, self.eps)
                for c in range(3):
                    colour[c] += k * mirror[c]
            if tr > 0.0:
                if smooth:
                    refracted = refract(direction, f.normal, f.ior, ns)
                    if refracted is not None and dot(refracted, n) >= 0.0:
                        refracted = refract(direction, f.normal, f.ior)
                else:
                    refracted = refract(direction, f.normal, f.ior)
                if refracted is not None:
                    through = self.trace(hit, refracted, level + 1, f,
                                         self.eps)
                else:                                   # total internal
                    if mirror is None:                  # reflection
                        r = self.mirror_direction(direction, ns, n, smooth)
                        mirror = self.trace(hit, r, level + 1, f, self.eps)
                    through = mirror
                for c in range(3):
                    colour[c] += tr * through[c]
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
        n = math.isqrt(self.samples)
        inv = 1.0 / (n * n)
        aperture, focus = s.aperture, s.focus
        ab_hat = tuple(c / norm(ab) for c in ab)
        ac_hat = tuple(c / norm(ac) for c in ac)
        lens = []                      # (x, y) offsets in the pixel, L
        for sy in range(n):
            for sx in range(n):
                dx, dy = (sx + 0.5) / n, (sy + 0.5) / n
                if aperture > 0.0:
                    u, v = concentric_disk(2.0 * ((sy + 0.5) / n) - 1.0,
                                           2.0 * ((sx + 0.5) / n) - 1.0)
                    offset = mul(add(mul(ab_hat, u), mul(ac_hat, v)),
                                 aperture)
                    lens.append((dx, dy, add(o, offset)))
                else:
                    lens.append((dx, dy, None))
        w_hat = tuple(c / norm(sub(a, o)) for c in sub(a, o))
        rows = []
        for j in range(h):
            row = bytearray()
            for i in range(w):
                total = [0.0, 0.0, 0.0]
                for dx, dy, lens_point in lens:
                    x, y = i + dx, j + dy
                    p = add(a, add(mul(ab, (2.0 * x - w) / w),
                                   mul(ac, (h - 2.0 * y) / w)))
                    po = sub(p, o)
                    if lens_point is None:
                        c = self.trace(o, unit(po), 0, None, 0.0)
                    else:
                        along = dot(po, w_hat)
                        focal = add(o, tuple(c * focus / along for c in po))
                        c = self.trace(lens_point,
                                       unit(sub(focal, lens_point)),
                                       0, None, 0.0)
                    for ch in range(3):
                        total[ch] += c[ch]
                for v in total:
                    v = min(255.0, max(0.0, v * inv))
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
    args, depth, samples, ascii_format = [], 5, 1, False
    it = iter(argv[1:])
    for arg in it:
        if arg == '--depth':
            depth = int(next(it))
        elif arg.startswith('--depth='):
            depth = int(arg.split('=', 1)[1])
        elif arg == '--samples':
            samples = int(next(it))
        elif arg.startswith('--samples='):
            samples = int(arg.split('=', 1)[1])
        elif arg == '--p3':
            ascii_format = True
        else:
            args.append(arg)
    if len(args) != 2 or depth < 0 or samples < 1 \
            or math.isqrt(samples) ** 2 != samples:
        sys.stderr.write('usage: rtref.py SCENE.scn OUT.ppm [--depth N] '
                         '[--samples N] [--p3]\n'
                         '  (--samples: a square, 1, 4, 9, 16, ...)\n')
        return 2
    with open(args[0], encoding='utf-8') as f:
        text = f.read()
    try:
        scene = parse_scene(text)
        rows = Renderer(scene, depth, samples).render()
    except SceneError as e:
        sys.stderr.write('rtref: %s: %s\n' % (args[0], e))
        return 1
    write_ppm(args[1], scene.width, scene.height, rows, ascii_format)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
