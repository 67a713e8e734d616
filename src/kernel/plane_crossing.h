/*
 * plane_crossing.h - where a ray's line crosses a facet's plane, to about
 * 30 significant digits (internal; shared by both precisions' kernels).
 *
 * The watertight test computes a hit's distance t from barycentric weights
 * (intersect_impl.h).  That sum cancels when the facet is far larger than
 * the ray's distance to it - a ground of half-size 1e6 seen from 1.7 above
 * gives t to 1 % in float, with an error bound larger than t itself - and
 * the test then cannot tell that the facet lies in front of the ray, so it
 * drops it.  For those hits, and only those, the kernel asks this module
 * instead: t = n.(a - o) / n.d with n = (b - a) x (c - a), evaluated in
 * double-double arithmetic from the exact coordinates (a float is exact in
 * double), with a rigorous bound on its error (docs/accuracy.md, "Facets
 * far larger than their distance").
 */
#ifndef RAYTRACE_PLANE_CROSSING_H
#define RAYTRACE_PLANE_CROSSING_H

/*
 * The line o + t d against the plane through a, b, c (3 doubles each,
 * finite; the facet not of zero area).  Returns 1 with *t and *error,
 * |t_exact - *t| <= *error, when the origin provably lies farther than
 * `origin_error` (>= 0, in the coordinates' units) from the plane and the
 * direction provably is not parallel to it; else 0 (the crossing cannot
 * be told from the origin: the caller rejects the hit).  *t may be
 * infinite when it exceeds the range of double.  Thread-safe.
 */
int rt__plane_crossing(const double a[3], const double b[3],
                       const double c[3], const double o[3],
                       const double d[3], double origin_error, double *t,
                       double *error);

/*
 * Which side of the plane through a, b, c (finite, not of zero area) the
 * point o lies on: 1 on the side of (b - a) x (c - a), -1 on the other,
 * 0 when the double-double evaluation cannot tell (o in the plane, or
 * within about 1e-30 of the facet's size from it).  Thread-safe.
 */
int rt__plane_side(const double a[3], const double b[3], const double c[3],
                   const double o[3]);

#endif /* RAYTRACE_PLANE_CROSSING_H */
