/* intersection.c - a ray and the plane of a facet, a point and a facet. */
#include <math.h>

#include "intersection.h"

point computeIntersection(ray r, facet f)
{
    vector n = vcross(vsub(f.b, f.a), vsub(f.c, f.a));
    double across = vdot(n, r.v);
    point none = {NAN, NAN, NAN};

    if (0 == across)
        return none;
    return vadd(r.o, vscale(r.v, vdot(n, vsub(f.a, r.o)) / across));
}

/* p is in when each of its barycentric coordinates is at least -EPSILON
 * (relative to the facet's size). */
int isInFacet(point p, facet f)
{
    vector n = vcross(vsub(f.b, f.a), vsub(f.c, f.a));
    double area2 = vdot(n, n);
    double u, v, w;

    if (0 == area2 || isnan(p.x) || isnan(p.y) || isnan(p.z))
        return 0;
    u = vdot(n, vcross(vsub(f.c, f.b), vsub(p, f.b))) / area2;
    v = vdot(n, vcross(vsub(f.a, f.c), vsub(p, f.c))) / area2;
    w = vdot(n, vcross(vsub(f.b, f.a), vsub(p, f.a))) / area2;
    return u >= -EPSILON && v >= -EPSILON && w >= -EPSILON;
}
