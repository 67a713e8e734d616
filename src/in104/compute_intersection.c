/*
 * compute_intersection.c - computeIntersection() of the IN 104 handout
 * (intersection.h): where the line of a ray meets the plane of a facet.
 *
 * With N the facet's normal, the line o + t.v meets the plane through a at
 * t = -((o - a).N) / (v.N).  Both dot products are taken in the facet's
 * rescaled frame and v is rescaled by a power of two, so neither overflows
 * nor underflows for any sensible scene; v.N == 0 is the parallel case.
 */
#include "intersection.h"

#include "frame.h"

point computeIntersection(ray r, facet f)
{
    in104_frame frame;
    in104__frame_make(&frame, f.a, f.b, f.c);

    rt_vec3 direction = in104_vec(r.v);
    double length = v3_max_abs(direction);
    if (frame.degenerate || !(length > 0.0) || !isfinite(length))
        return in104_no_point();

    int exponent;
    (void)frexp(length, &exponent);
    rt_vec3 unit_direction = v3(ldexp(direction.x, -exponent),
                                ldexp(direction.y, -exponent),
                                ldexp(direction.z, -exponent));
    double along = v3_dot(unit_direction, frame.normal);
    if (along == 0.0)
        return in104_no_point();        /* parallel to the plane */

    rt_vec3 origin = in104__frame_local(&frame, r.o);
    /* Parameter along unit_direction, in local units, then in scene units. */
    double t = in104__frame_to_world(&frame,
                                     -v3_dot(origin, frame.normal) / along);
    rt_vec3 hit = v3_add(in104_vec(r.o), v3_scale(unit_direction, t));
    if (!v3_is_finite(hit))
        return in104_no_point();        /* nearly parallel: out of range */
    return in104_point(hit);
}
