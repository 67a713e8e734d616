#!/usr/bin/env python3
"""sphereflake - Eric Haines' SPD "balls" scene (the sphereflake) as a .scn,
at any size factor, for the benchmarks of tools/bench/peers.sh (balls-s3:
820 spheres, 88,562 facets).

    sphereflake.py SIZE_FACTOR > balls-sN.scn

The geometry is the SPD's (balls.c, public domain; the facts restated
here, not its code): a sphere of radius 1/2 at the origin, each sphere
bearing nine of a third of its radius on its upper side (three rings of
three, the trio rotated by asin(2/sqrt(6)) about (1, -1, 0) and repeated
at 120 degrees about z), turned so that the parent's "up" points from
its own parent to it; a square floor of half-side 12 at z = -1/2.  As in
the converted ../shared/spd-scenes/balls-s2.scn (which size factor 2
reproduces, facet for facet): each sphere is the SPD's polygon sphere, a
cube whose faces are cut into 3 x 3 cells at equal angles (-45, -15, 15,
45 degrees), projected onto the sphere, every cell fanned into two
triangles (108 a sphere), vertices written with 6 significant digits as
the NFF has them; the NFF view and the first light only; floor
colour (1, 0.75, 0.33) with k = 0, spheres (1, 0.9, 0.7) with k = 0.5
(the NFF Ks), colours times 255, 400 x 400.
"""
import math
import sys

from vectors import add, cross, dot, scale, sub, unit


def rotate(v, axis, angle):
    """v turned by `angle` about the unit `axis` (Rodrigues)."""
    c, s = math.cos(angle), math.sin(angle)
    return add(add(scale(v, c), scale(cross(axis, v), s)),
               scale(axis, dot(axis, v) * (1 - c)))


def children_directions():
    """The nine offsets of the children, for a parent whose up is +z."""
    d = 1 / math.sqrt(2)
    trio = [[d, d, 0], [d, 0, -d], [0, d, -d]]
    axis = unit([1, -1, 0])
    tilt = math.asin(2 / math.sqrt(6))
    trio = [rotate(v, axis, tilt) for v in trio]
    return [rotate(v, [0, 0, 1], k * 2 * math.pi / 3)
            for k in range(3) for v in trio]


def flake(level, center, radius, up, directions, out):
    """Appends (center, radius) of the sphere and its descendants."""
    out.append((center, radius))
    if level == 0:
        return
    if up[2] >= 1:
        turn = None
    elif up[2] <= -1:
        turn = ([0, 1, 0], math.pi)
    else:
        turn = (unit(cross([0, 0, 1], up)), math.acos(up[2]))
    reach = radius * (1 + 1 / 3)        # parent's radius plus the child's
    for v in directions:
        w = v if turn is None else rotate(v, turn[0], turn[1])
        flake(level - 1, add(center, scale(w, reach)), radius / 3, w,
              directions, out)


# The cube's faces in the SPD's order: the axis a face is normal to, its
# sign, the cells along the face's first and second coordinates (the other
# two axes in increasing order; cell i spans grid lines i and i + 1), which
# of the two loops is the outer one, and the corners of a cell in order,
# as offsets from its lowest grid point (the polygon fanned from the first
# corner: triangles 0 1 2 and 2 3 0).
UP, DOWN = (0, 1, 2), (2, 1, 0)
FACES = [
    (0, -1, DOWN, UP, "v", ((1, 0), (0, 0), (0, 1), (1, 1))),
    (1, -1, UP, UP, "v", ((0, 0), (1, 0), (1, 1), (0, 1))),
    (2, -1, UP, DOWN, "v", ((0, 1), (1, 1), (1, 0), (0, 0))),
    (0, 1, DOWN, UP, "u", ((1, 0), (1, 1), (0, 1), (0, 0))),
    (1, 1, UP, UP, "u", ((0, 0), (0, 1), (1, 1), (1, 0))),
    (2, 1, UP, DOWN, "u", ((0, 1), (0, 0), (1, 0), (1, 1))),
]


def sphere_cells():
    """The unit sphere's 54 cells, each 4 points, in the SPD's order."""
    lines = [math.tan(math.radians(a)) for a in (-45, -15, 15, 45)]
    cells = []
    for axis, sign, us, vs, outer, corners in FACES:
        others = [i for i in range(3) if i != axis]
        pairs = ([(u, v) for v in vs for u in us] if outer == "v" else
                 [(u, v) for u in us for v in vs])
        for u, v in pairs:
            quad = []
            for du, dv in corners:
                p = [0.0, 0.0, 0.0]
                p[axis] = sign
                p[others[0]] = lines[u + du]
                p[others[1]] = lines[v + dv]
                quad.append(unit(p))
            cells.append(quad)
    return cells


def number(x):
    text = "%.6g" % x
    return "0" if text == "-0" else text


def main():
    if len(sys.argv) != 2 or not sys.argv[1].isdigit():
        sys.exit("usage: sphereflake.py SIZE_FACTOR > balls-sN.scn")
    level = int(sys.argv[1])
    spheres = []
    flake(level, [0, 0, 0], 0.5, [0, 0, 1], children_directions(), spheres)

    eye, at, up, angle = [2.1, 1.3, 1.7], [0, 0, 0], [0, 0, 1], 45.0
    view = unit(sub(at, eye))
    screen = add(eye, view)
    right = add(screen, scale(unit(cross(view, up)),
                              math.tan(math.radians(angle / 2))))
    vertices, facets = [], []
    floor = [[12, 12, -0.5], [-12, 12, -0.5], [-12, -12, -0.5],
             [12, -12, -0.5]]
    vertices += floor
    floor_color = "255,191,84"
    facets.append((1, 2, 3, "0", floor_color))
    facets.append((1, 3, 4, "0", floor_color))
    ball_color = ",".join(str(round(c * 255)) for c in (1.0, 0.9, 0.7))
    cells = sphere_cells()
    for center, radius in spheres:
        index = {}

        def vertex(p):
            key = tuple(number(x) for x in add(center, scale(p, radius)))
            if key not in index:
                vertices.append(key)
                index[key] = len(vertices)
            return index[key]

        for quad in cells:
            q = [vertex(p) for p in quad]
            facets.append((q[0], q[1], q[2], "0.5", ball_color))
            facets.append((q[2], q[3], q[0], "0.5", ball_color))

    w = sys.stdout.write
    w("# the SPD sphereflake (balls), size factor %d: tools/bench/"
      "sphereflake.py\n" % level)
    w(",".join(number(x) for x in eye) + "\n")
    w(",".join("%.9g" % x for x in screen + right) + ",400,400\n")
    w("%d\n" % len(vertices))
    for v in vertices:
        w(",".join(v if isinstance(v[0], str) else map(number, v)) + "\n")
    w("%d\n" % len(facets))
    for a, b, c, k, color in facets:
        w("%d,%d,%d,%s,%s\n" % (a, b, c, k, color))
    w("20,92,192\n")       # the background (0.078, 0.361, 0.753) x 255
    w("4,3,2,255,255,255\n")


if __name__ == "__main__":
    main()
