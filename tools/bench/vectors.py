"""vectors - the 3-vector arithmetic the benchmark scripts share
(scn2pov.py, sphereflake.py): vectors as lists of three floats."""
import math


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def add(a, b):
    return [a[i] + b[i] for i in range(3)]


def scale(a, s):
    return [x * s for x in a]


def dot(a, b):
    return sum(a[i] * b[i] for i in range(3))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0]]


def unit(a):
    return scale(a, 1.0 / math.sqrt(dot(a, a)))
