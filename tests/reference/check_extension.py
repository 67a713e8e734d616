#!/usr/bin/env python3
"""check_extension.py - checks the physics of rtref.py's extension (several
lights, refraction, depth of field) against closed-form answers.

Usage: python3 tests/reference/check_extension.py     (under a second)

Prints one line per check and exits 1 if any fails.  Standard library only;
it imports rtref.py from the same folder.  The checks:

1. a slab with parallel faces (n = 1.5) shifts a ray without turning it:
   for parallel rays at several angles and entry points, the ray leaving
   the slab has the incoming direction, every ray of the family is moved by
   the same vector (so the scene behind is translated, not deformed), and
   the shift is the textbook d sin(i - r) / cos r;
2. total internal reflection starts exactly at the critical angle
   asin(1/n): refract() on both sides of it, and a traced ray inside glass
   sees what is transmitted just below the angle and the mirror image just
   above it;
3. the refraction of an entering ray obeys Snell's law sin i = n sin r, and
   a ray leaving reverses it;
4. two lights: with k = t = 0 and a black background the image lit by both
   is the per-channel sum of the images lit by each (within 1 for rounding);
5. a facet with t = 1, n = 1 that shadows nothing is invisible;
6. depth of field: a plane at the focal distance renders the same with and
   without aperture (within 1), a plane elsewhere does not; the concentric
   mapping keeps the lens samples in the unit disk.
"""

import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import rtref  # noqa: E402

FAILURES = []


def check(name, ok, detail=''):
    print('%s  %s%s' % ('ok  ' if ok else 'FAIL', name,
                        (': ' + detail) if detail else ''))
    if not ok:
        FAILURES.append(name)


def renderer(text, depth=5, samples=1):
    return rtref.Renderer(rtref.parse_scene(text), depth, samples)


SLAB_FACETS = ((1, 3, 2), (1, 4, 3), (5, 6, 7), (5, 7, 8), (1, 2, 6),
               (1, 6, 5), (2, 3, 7), (2, 7, 6), (3, 4, 8), (3, 8, 7),
               (4, 1, 5), (4, 5, 8))


def slab_scene(thickness, ior):
    """A closed box [-50, 50]^2 x [0, thickness], outward windings, every
    facet t = 1, n = ior."""
    corners = ''.join('%r, %r, %r\n' % (x, y, z)
                      for z in (0.0, thickness)
                      for x, y in ((-50, -50), (50, -50), (50, 50),
                                   (-50, 50)))
    facets = ''.join('%d, %d, %d,  0, 255, 255, 255,  1, %r\n' % (f + (ior,))
                     for f in SLAB_FACETS)
    return ('0, 0, 100\n0, 0, 90,  1, 0, 90,  4, 4\n8\n' + corners +
            '12\n' + facets + '0, 0, 0\n0, 0, 1000,  255, 255, 255\n')


def follow(r, origin, direction):
    """Follows a ray through transparent facets by the rule of rtref's
    trace (refract, or mirror on total internal reflection) until it meets
    nothing; returns the last origin and direction."""
    skip, tmin = None, 0.0
    for crossed in range(10):
        t, f = r.nearest(origin, direction, skip, tmin)
        if f is None:
            if crossed < 2:
                raise AssertionError('the ray missed the slab')
            return origin, direction
        hit = rtref.add(origin, rtref.mul(direction, t))
        out = rtref.refract(direction, f.normal, f.ior)
        if out is None:
            n = f.normal if rtref.dot(f.normal, direction) < 0 else \
                rtref.mul(f.normal, -1.0)
            out = rtref.unit(rtref.sub(direction,
                                       rtref.mul(n, 2 * rtref.dot(direction,
                                                                  n))))
        origin, direction, skip, tmin = hit, out, f, r.eps
    raise AssertionError('ray did not leave the slab')


def check_slab():
    d, ior = 2.0, 1.5
    r = renderer(slab_scene(d, ior))
    worst_dir, worst_spread, worst_shift = 0.0, 0.0, 0.0
    for degrees in (0.0, 10.0, 30.0, 50.0, 70.0, 85.0):
        i = math.radians(degrees)
        direction = (math.sin(i), 0.0, -math.cos(i))
        shifts = []
        for x0, y0 in ((-3.0, 0.0), (0.25, 1.5), (4.0, -7.0), (11.0, 2.0)):
            origin = (x0, y0, d + 0.5)
            end, out = follow(r, origin, direction)
            worst_dir = max(worst_dir, rtref.norm(rtref.sub(out, direction)))
            # where the straight ray would be at the exit's height
            s = (end[2] - origin[2]) / direction[2]
            straight = rtref.add(origin, rtref.mul(direction, s))
            shifts.append(rtref.sub(end, straight))
        spread = max(rtref.norm(rtref.sub(a, shifts[0])) for a in shifts)
        worst_spread = max(worst_spread, spread)
        # textbook lateral displacement, perpendicular to the ray
        rr = math.asin(math.sin(i) / ior)
        expected = d * math.sin(i - rr) / math.cos(rr)
        along = rtref.dot(shifts[0], direction)
        lateral = rtref.norm(rtref.sub(shifts[0],
                                       rtref.mul(direction, along)))
        worst_shift = max(worst_shift, abs(lateral - expected))
    check('slab: the ray leaves with its incoming direction',
          worst_dir < 1e-12, 'largest |out - in| %.1e' % worst_dir)
    check('slab: every parallel ray is shifted by the same vector',
          worst_spread < 1e-12, 'largest spread %.1e' % worst_spread)
    check('slab: the shift is d sin(i - r) / cos r',
          worst_shift < 1e-12, 'largest error %.1e' % worst_shift)


def check_snell():
    worst = 0.0
    for ior in (1.33, 1.5, 2.4):
        nw = (0.0, 0.0, 1.0)
        for degrees in (0.0, 15.0, 40.0, 75.0, 89.0):
            i = math.radians(degrees)
            into = (math.sin(i), 0.0, -math.cos(i))      # against n_w
            t = rtref.refract(into, nw, ior)
            worst = max(worst, abs(math.sin(i) - ior * t[0]))
            back = rtref.refract(rtref.mul(t, -1.0), nw, ior)   # leaving
            worst = max(worst, rtref.norm(rtref.add(back, into)))
    check('Snell: sin i = n sin r entering, reversed leaving',
          worst < 1e-14, 'largest error %.1e' % worst)


def check_tir():
    ior = 1.5
    critical = math.asin(1.0 / ior)
    nw = (0.0, 0.0, 1.0)

    def leaving(angle):               # from inside (I.n_w > 0)
        return (math.sin(angle), 0.0, math.cos(angle))
    below = rtref.refract(leaving(critical * (1 - 1e-9)), nw, ior)
    above = rtref.refract(leaving(critical * (1 + 1e-9)), nw, ior)
    check('TIR: refract() transmits just below asin(1/n), reflects just '
          'above', below is not None and above is None)
    grazing = below is not None and abs(below[2]) < 1e-3
    check('TIR: just below the critical angle the ray leaves grazing',
          grazing, 'z of T %.1e' % (below[2] if below else float('nan')))

    # traced: a glass facet (t = 1, n = 1.5) in z = 0, winding normal +z,
    # a ray from below (inside); the transmitted ray sees the blue
    # background above, the mirror ray the lit green floor below.
    scene = '''0, 0, 10
0, 0, 9,  1, 0, 9,  2, 2
7
-40, -40, 0
 40, -40, 0
  0,  40, 0
-200, -200, -20
 200, -200, -20
 200,  200, -20
-200,  200, -20
3
1, 2, 3,  0, 255, 255, 255,  1, 1.5
4, 5, 6,  0, 0, 255, 0
4, 6, 7,  0, 0, 255, 0
0, 0, 255
0, 0, -10,  255, 255, 255
'''
    r = renderer(scene)
    results = {}
    for label, factor in (('below', 1 - 1e-6), ('above', 1 + 1e-6)):
        angle = critical * factor
        direction = leaving(angle)
        origin = rtref.sub((0.0, 0.0, 0.0), rtref.mul(direction, 5.0))
        results[label] = r.trace(origin, direction, 0, None, 0.0)
    ok_below = tuple(results['below']) == (0.0, 0.0, 255.0)
    ok_above = results['above'][1] > 0.0 and results['above'][2] == 0.0
    check('TIR: traced, 1e-6 below asin(1/n) sees through (background)',
          ok_below, str(tuple(round(c, 3) for c in results['below'])))
    check('TIR: traced, 1e-6 above asin(1/n) sees the mirror image (floor)',
          ok_above, str(tuple(round(c, 3) for c in results['above'])))


LIGHTS_SCENE = '''0, 0, 10
0, 0, 5,  4, 0, 5,  32, 24
7
-6, -4, 0
 6, -4, 0
 0,  5, 0
-1.13, -1.27, 2
 1.58, -0.93, 2
-0.17,  1.74, 2
 7, 7, 0
2
1, 2, 3,  0, 180, 200, 220
4, 5, 6,  0, 40, 120, 255
0, 0, 0
%s
'''


def check_two_lights():
    one = '-3.875, 0.125, 4,  200, 150, 100'
    two = '2.3, -1.7, 5,  60, 100, 140'
    both = renderer(LIGHTS_SCENE % (one + '\n' + two)).render()
    first = renderer(LIGHTS_SCENE % one).render()
    second = renderer(LIGHTS_SCENE % two).render()
    worst = 0
    for rb, r1, r2 in zip(both, first, second):
        for b, x, y in zip(rb, r1, r2):
            worst = max(worst, abs(b - min(255, x + y)))
    check('two lights: the image is the sum of the one-light images',
          worst <= 1, 'largest difference %d' % worst)


def check_invisible():
    base = '''0, 0, 10
0, 0, 5,  4, 0, 5,  32, 24
%d
-6, -4, 0
 6, -4, 0
 0,  5, 0
%s
%d
1, 2, 3,  0.4, 201, 100, 50
%s
20, 40, 60
0.125, 0.125, 4,  255, 204, 102
'''
    glass_v = '-1, -1, 6\n1, -1, 6\n0, 1.5, 6'
    glass_f = '4, 5, 6,  0, 255, 255, 255,  1, 1'
    with_glass = renderer(base % (6, glass_v, 2, glass_f)).render()
    without = renderer(base % (3, '', 1, '')).render()
    check('a facet with t = 1, n = 1 that shadows nothing is invisible',
          with_glass == without)


def check_focus():
    # a two-coloured plane perpendicular to w^ at distance 6 from O, seen
    # with the lens focused on it and with the lens focused elsewhere.
    def scene(a, f, z):
        return '''0, 0, 10
0, 0, 8,  1, 0, 8,  24, 16,  %r, %r
4
-3, -2, %r
 3, -2, %r
 3,  2, %r
-3,  2, %r
2
1, 2, 3,  0, 255, 60, 30
1, 3, 4,  0, 30, 90, 255
10, 10, 10
0.3, 0.2, 9,  255, 255, 255
''' % (a, f, z, z, z, z)
    pinhole = renderer(scene(0.0, 6.0, 4.0), samples=4).render()
    focused = renderer(scene(0.3, 6.0, 4.0), samples=4).render()
    defocused = renderer(scene(0.3, 3.0, 4.0), samples=4).render()
    worst = max(abs(x - y) for a, b in zip(pinhole, focused)
                for x, y in zip(a, b))
    moved = sum(1 for a, b in zip(pinhole, defocused)
                for x, y in zip(a, b) if x != y)
    check('DoF: the plane at the focal distance stays sharp (= pinhole)',
          worst <= 1, 'largest difference %d' % worst)
    check('DoF: the same plane out of focus blurs', moved > 0,
          '%d channels differ from the pinhole image' % moved)
    # ray level: every primary ray of the lens, continued to the focal
    # plane z = 4 (perpendicular to w^ at f = 6), meets it where the
    # pinhole ray of the same sample does; its origin is on the lens disk.
    class Recorder(rtref.Renderer):
        def trace(self, origin, direction, level, skip, tmin):
            self.rays.append((origin, direction))
            return self.background

    def primary_rays(a, wide):
        r = Recorder(rtref.parse_scene(scene(a, 6.0, 4.0).replace(
            '24, 16', wide)), 1, 16)
        r.rays = []
        r.render()
        return r.rays

    def on_plane(ray):
        (o, d) = ray
        return rtref.add(o, rtref.mul(d, (4.0 - o[2]) / d[2]))

    worst, off_lens = 0.0, 0
    for wide in ('24, 16', '8, 40'):          # wide and tall fields of view
        pin, lens = primary_rays(0.0, wide), primary_rays(0.3, wide)
        for p_ray, l_ray in zip(pin, lens):
            worst = max(worst, rtref.norm(rtref.sub(on_plane(p_ray),
                                                    on_plane(l_ray))))
            lo = rtref.sub(l_ray[0], (0.0, 0.0, 10.0))
            if lo[2] != 0.0 or rtref.norm(lo) > 0.3 * (1 + 1e-12):
                off_lens += 1
    check('DoF: every lens ray meets the focal plane at the pinhole '
          "ray's point", worst < 1e-12, 'largest distance %.1e' % worst)
    check('DoF: every lens ray starts on the lens disk (radius a)',
          off_lens == 0, '%d outside' % off_lens)
    inside = all(math.hypot(*rtref.concentric_disk(2 * (a + .5) / 8 - 1,
                                                   2 * (b + .5) / 8 - 1))
                 <= 1.0 for a in range(8) for b in range(8))
    check('DoF: the concentric mapping stays in the unit disk', inside)


def main():
    check_slab()
    check_snell()
    check_tir()
    check_two_lights()
    check_invisible()
    check_focus()
    if FAILURES:
        print('%d check(s) failed' % len(FAILURES))
        return 1
    print('all checks passed')
    return 0


if __name__ == '__main__':
    sys.exit(main())
