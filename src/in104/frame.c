/*
 * frame.c - the local frame of a facet (see frame.h).
 */
#include "frame.h"

/* The exponent e of m = f * 2^e, f in [0.5, 1); m finite and non-zero. */
static int binary_exponent(double m)
{
    int exponent;
    (void)frexp(m, &exponent);
    return exponent;
}

static rt_vec3 scale_by_power_of_two(rt_vec3 v, int exponent)
{
    return v3(ldexp(v.x, exponent), ldexp(v.y, exponent),
              ldexp(v.z, exponent));
}

void in104__frame_make(in104_frame *frame, point a, point b, point c)
{
    rt_vec3 origin = in104_vec(a);
    rt_vec3 ab = v3_sub(in104_vec(b), origin);
    rt_vec3 ac = v3_sub(in104_vec(c), origin);
    double m = fmax(v3_max_abs(ab), v3_max_abs(ac));

    frame->origin = origin;
    frame->exponent = 0;
    frame->edge_ab = ab;
    frame->edge_ac = ac;
    frame->normal = v3(0.0, 0.0, 0.0);
    frame->unit = v3(0.0, 0.0, 0.0);
    frame->degenerate = 1;
    if (!(m > 0.0) || !isfinite(m) || !v3_is_finite(origin))
        return;                         /* a point, or non-finite input */

    frame->exponent = binary_exponent(m);
    frame->edge_ab = scale_by_power_of_two(ab, -frame->exponent);
    frame->edge_ac = scale_by_power_of_two(ac, -frame->exponent);

    rt_vec3 normal = in104_cross(frame->edge_ab, frame->edge_ac);
    double n = v3_max_abs(normal);
    if (!(n > 0.0))
        return;                         /* collinear: zero area */
    frame->normal = scale_by_power_of_two(normal, -binary_exponent(n));
    frame->unit = v3_normalize(frame->normal);
    frame->degenerate = 0;
}

rt_vec3 in104__frame_local(const in104_frame *frame, point p)
{
    return scale_by_power_of_two(v3_sub(in104_vec(p), frame->origin),
                                 -frame->exponent);
}

double in104__frame_to_world(const in104_frame *frame, double length)
{
    return ldexp(length, frame->exponent);
}
