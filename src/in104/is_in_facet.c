/*
 * is_in_facet.c - isInFacet() of the IN 104 handout (intersection.h): is a
 * point within EPSILON of a triangle?
 *
 * The distance from p to the closed triangle is its distance to the plane
 * when p projects inside the triangle, and otherwise its distance to the
 * nearest of the three edges (as segments, in space).  All in the facet's
 * rescaled frame (frame.h), then brought back to scene units.
 *
 * "Projects inside" is decided by the three edge functions
 * ((to - from) x (p - from)).N, and only when each is larger than a bound on
 * its rounding error; a point too close to an edge's line to tell is
 * measured against the edges instead.  That is always safe: an inside point
 * that close to a line is at most that close to the triangle's border, so
 * the edge distance is then its true distance to rounding.  Without the
 * bound, a point beyond a sliver's sharp corner (on the extension of two
 * nearly parallel edges) can pass all three signs by rounding and be
 * declared at distance 0.
 */
#include "intersection.h"

#include <float.h>

#include "frame.h"

/* Distance from p to the segment [from, to] (from != to). */
static double segment_distance(rt_vec3 p, rt_vec3 from, rt_vec3 to)
{
    rt_vec3 edge = v3_sub(to, from);
    double t = v3_dot(v3_sub(p, from), edge) / v3_dot(edge, edge);
    t = fmin(fmax(t, 0.0), 1.0);
    return v3_length(v3_sub(p, v3_add(from, v3_scale(edge, t))));
}

static double sum_abs(rt_vec3 v)
{
    return fabs(v.x) + fabs(v.y) + fabs(v.z);
}

/* Non-zero when p is certainly on the inner side of the edge from -> to:
 * the edge function exceeds a generous bound on its rounding error (which
 * includes the rounding of p into the local frame). */
static int certainly_inside_edge(rt_vec3 p, rt_vec3 from, rt_vec3 to,
                                 rt_vec3 normal)
{
    rt_vec3 edge = v3_sub(to, from);
    rt_vec3 offset = v3_sub(p, from);
    double value = v3_dot(in104_cross(edge, offset), normal);
    double bound = 16.0 * DBL_EPSILON * sum_abs(edge)
                   * (sum_abs(offset) + sum_abs(p) + sum_abs(from))
                   * sum_abs(normal);
    return value > bound;
}

int isInFacet(point p, facet f)
{
    in104_frame frame;
    in104__frame_make(&frame, f.a, f.b, f.c);
    if (frame.degenerate)
        return 0;

    rt_vec3 q = in104__frame_local(&frame, p);
    if (!v3_is_finite(q))
        return 0;

    rt_vec3 a = v3(0.0, 0.0, 0.0), b = frame.edge_ab, c = frame.edge_ac;
    double distance;
    if (certainly_inside_edge(q, a, b, frame.normal)
        && certainly_inside_edge(q, b, c, frame.normal)
        && certainly_inside_edge(q, c, a, frame.normal)) {
        distance = fabs(v3_dot(q, frame.unit));
    } else {
        distance = fmin(segment_distance(q, a, b),
                        fmin(segment_distance(q, b, c),
                             segment_distance(q, c, a)));
    }
    return in104__frame_to_world(&frame, distance) <= EPSILON;
}
