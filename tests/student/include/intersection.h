#ifndef INTERSECTION_H
#define INTERSECTION_H

#include "geometry.h"

/* Where the line of r meets the plane of f; NaN coordinates when the ray
 * is parallel to the plane. */
point computeIntersection(ray r, facet f);

/* Non-zero when p, a point of the plane of f, is in the triangle (EPSILON
 * around it included). */
int isInFacet(point p, facet f);

#endif
