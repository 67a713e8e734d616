/*
 * exact.h - geometric predicates with exact signs (internal): the
 * orientation of three points in a plane and the cross product of a
 * triangle's edges, both zero exactly when the points are collinear.  The
 * scene builder decides with them which facets have no area, and the
 * polygon triangulator which corners are convex and which triangles to
 * keep, so that both decide the same way.
 */
#ifndef RAYTRACE_EXACT_H
#define RAYTRACE_EXACT_H

#include "raytrace/vec3.h"

/*
 * The orientation ax by - ay bx + bx cy - by cx + cx ay - cy ax of the 2D
 * points (a, b, c): positive when they turn counter-clockwise, negative
 * clockwise, zero exactly when they are collinear (barring underflow: the
 * products of coordinates below about 1e-154 may round to zero).  The
 * value is within an ulp or so; a floating-point evaluation answers
 * whenever its error bound proves the sign, the exact one otherwise.
 * Thread-safe.
 */
double rt__orient2d(double ax, double ay, double bx, double by, double cx,
                    double cy);

/*
 * (b - a) x (c - a) evaluated from the vertices without rounding the edges:
 * each component is the orientation of the triangle projected on a
 * coordinate plane, computed exactly and rounded once.  Zero exactly when
 * the vertices are collinear (the vertices are first scaled by a power of
 * two, so that the products neither overflow nor underflow at any scale).
 * Thread-safe.
 */
rt_vec3 rt__exact_cross(rt_vec3 a, rt_vec3 b, rt_vec3 c);

/* Non-zero exactly when rt__exact_cross(a, b, c) is not the zero vector
 * (the triangle has an area: the scene builder keeps it), decided by a
 * floating-point cross product when it is far from zero, by the same
 * exact evaluation otherwise.  Thread-safe. */
int rt__triangle_has_area(rt_vec3 a, rt_vec3 b, rt_vec3 c);

#endif /* RAYTRACE_EXACT_H */
