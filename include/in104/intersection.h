/*
 * intersection.h - the geometric functions of the IN 104 course handout
 * (compatibility layer of libraytrace, library raytrace-in104).
 *
 * These are the functions the handout's graded tests call.  Every one is a
 * pure function of its arguments: no allocation, no global state, safe to
 * call from any number of threads at once.  None of them crashes or has
 * undefined behaviour for any input; the cases without a meaningful answer
 * (a ray parallel to a plane, a facet of zero area) give the documented
 * results below, never garbage.
 *
 * Numerics: the plane and the facet frame are computed from the vertices
 * with cross products of the edges (never through the 2x2 normal
 * equations, and with products that cannot cancel away), after an exact
 * power-of-two rescaling, so that slivers (one side 1e12 times shorter than
 * the others) and coordinates anywhere from 1e-150 to 1e150 give finite,
 * accurate results.  The normal stored in
 * f.n is not read: a facet built by hand with only a, b, c set works too.
 */
#ifndef IN104_INTERSECTION_H
#define IN104_INTERSECTION_H

#include "geometry.h"
#include "in104_export.h"

#ifdef __cplusplus
extern "C" {
#endif

/*
 * The facet a, b, c with its unit normal n = (b - a) x (c - a) / |...|,
 * reflection coefficient k = 0 and colour black (0, 0, 0).
 * Zero-area facet (the three points collinear, or two of them equal): n is
 * the zero vector (0, 0, 0); the facet is otherwise returned as given.
 * Example: createFacet((0,0,0), (1,0,0), (0,1,0)).n == (0, 0, 1).
 */
IN104_API facet createFacet(point a, point b, point c);

/*
 * The point where the line of r (all of it: o + t.v for every real t) meets
 * the plane through f.a, f.b, f.c.  r.v need not be unit length, and the
 * point is returned even when it lies behind the origin (t < 0) or at it
 * (t = 0): check ((p - r.o) . r.v > 0) if only the half-line counts.
 * Example: o = (0,0,0), v = (1,3,2), facet (-1,-1,1), (1,-1,-1), (0,1,1)
 * gives (1/3, 1, 2/3); v = (-1,-3,-2) gives the same point.
 *
 * No single point: when r.v is parallel to the plane (r.v . n == 0, whether
 * the line lies in the plane or not), when r.v is the zero vector, when the
 * facet has zero area (no plane), or when the point would not be finite
 * (nearly parallel, beyond the range of double), every coordinate of the
 * result is NaN.  Test it with isnan(p.x); isInFacet() returns 0 for it.
 */
IN104_API point computeIntersection(ray r, facet f);

/*
 * The coordinates (u, v, w) of p in the facet's frame:
 *     p = a + u.(b - a) + v.(c - a) + w.n
 * with n the unit normal of createFacet() (so w is the signed distance from
 * p to the plane).  p is inside the triangle when u >= 0, v >= 0 and
 * u + v <= 1 (and w = 0).  Returned as a point: x = u, y = v, z = w.
 * Example: facet (0,0,0), (1,0,0), (0,1,0): p = (0.25, 0.5, 2) gives
 * (0.25, 0.5, 2).
 *
 * Zero-area facet (vertices collinear in floating point, no frame): every
 * coordinate of the result is NaN.  A sliver (nearly collinear vertices,
 * aspect ratio up to 1e12 and beyond) still has a frame and gives finite
 * results, accurate to a few roundings for points in its plane.
 */
IN104_API point changeCoord(point p, facet f);

/*
 * Non-zero when p lies in the triangle f.a, f.b, f.c or on its border,
 * within EPSILON: precisely, when the Euclidean distance from p to the
 * closed triangle (a set of points in space) is at most EPSILON.  So a point
 * on an edge or a vertex is in; a point in the plane more than EPSILON
 * outside an edge is out; a point within EPSILON of the plane above the
 * inside of the triangle is in, one farther from the plane is out.  EPSILON
 * is an absolute length in scene units, as in the handout (suited to scenes
 * whose sizes are about 1e-3 to 1e6; the renderer itself uses no such
 * constant).  Distances within rounding of EPSILON may go either way.
 * Example: triangle (0,0,0), (0,1,0), (1,0,0): (0.5, 0.5, 0) is in (on the
 * long edge), (-0.5, -0.5, 0) is out.
 *
 * Returns 0 for a zero-area facet (the renderer never hits one,
 * docs/rendering-model.md) and for a point with a NaN or infinite
 * coordinate (such as computeIntersection()'s answer for a parallel ray).
 */
IN104_API int isInFacet(point p, facet f);

#ifdef __cplusplus
}
#endif

#endif /* IN104_INTERSECTION_H */
