/*
 * exact.h - the cross product of a triangle's edges with exact signs
 * (internal), zero exactly when its corners are collinear.  The scene
 * builder decides with it which facets have no area, and the polygon
 * triangulator which triangles to keep, so that both decide the same way.
 */
#ifndef RAYTRACE_EXACT_H
#define RAYTRACE_EXACT_H

#include "raytrace/vec3.h"

/*
 * (b - a) x (c - a) evaluated from the vertices without rounding the edges:
 * each component is the orientation of the triangle projected on a
 * coordinate plane, computed exactly and rounded once.  Zero exactly when
 * the vertices are collinear (the vertices are first scaled by a power of
 * two, so that the products neither overflow nor underflow at any scale).
 * Thread-safe.
 */
rt_vec3 rt__exact_cross(rt_vec3 a, rt_vec3 b, rt_vec3 c);

/* The unit normal of the facet (a, b, c), in the direction of
 * (b - a) x (c - a): rt__exact_cross normalised, accurate for any shape
 * (slivers and needles included); zero for a zero-area facet.  The one
 * definition the scene and its kernels share.  Thread-safe. */
rt_vec3 rt__facet_normal(rt_vec3 a, rt_vec3 b, rt_vec3 c);

/* Non-zero exactly when rt__exact_cross(a, b, c) is not the zero vector
 * (the triangle has an area: the scene builder keeps it), decided by a
 * floating-point cross product when it is far from zero, by the same
 * exact evaluation otherwise.  Thread-safe. */
int rt__triangle_has_area(rt_vec3 a, rt_vec3 b, rt_vec3 c);

#endif /* RAYTRACE_EXACT_H */
