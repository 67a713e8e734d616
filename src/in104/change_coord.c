/*
 * change_coord.c - changeCoord() of the IN 104 handout (intersection.h):
 * the coordinates (u, v, w) of a point in a facet's frame.
 *
 * With d = p - a, e1 = b - a, e2 = c - a and N = e1 x e2:
 *     u = ((d x e2).N) / (N.N),  v = ((e1 x d).N) / (N.N),  w = d.N / |N|,
 * which follows from crossing d = u.e1 + v.e2 + w.n with e2 and e1.  The
 * 2x2 normal equations would cancel their determinant
 * |e1|^2 |e2|^2 - (e1.e2)^2 to nothing on a sliver; here the cross products
 * are computed without cancellation (frame.h) and the dot products with N
 * add terms of one sign, so u and v stay accurate to a few roundings for
 * points in the plane, whatever the sliver's aspect ratio.
 */
#include "intersection.h"

#include "frame.h"

point changeCoord(point p, facet f)
{
    in104_frame frame;
    in104__frame_make(&frame, f.a, f.b, f.c);
    if (frame.degenerate)
        return in104_no_point();

    rt_vec3 d = in104__frame_local(&frame, p);
    rt_vec3 n = frame.normal;
    double area = v3_dot(in104_cross(frame.edge_ab, frame.edge_ac), n);

    point result;
    result.x = v3_dot(in104_cross(d, frame.edge_ac), n) / area;
    result.y = v3_dot(in104_cross(frame.edge_ab, d), n) / area;
    result.z = in104__frame_to_world(&frame, v3_dot(d, frame.unit));
    return result;
}
