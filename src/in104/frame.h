/*
 * frame.h - the local frame of a facet, shared by the functions of the
 * IN 104 compatibility layer (internal, not installed).
 *
 * Every geometric function of the layer works in the facet's own frame:
 * coordinates relative to vertex a, divided by a power of two so that the
 * longest edge component is in [0.5, 1) (an exact rescaling), and the
 * normal as the cross product of the rescaled edges, itself rescaled by a
 * power of two.  This keeps slivers and very large or very small scenes
 * away from overflow, underflow and the cancellation of the normal
 * equations.  Conversions between the handout's point and rt_vec3 live here
 * too.
 */
#ifndef IN104_FRAME_H
#define IN104_FRAME_H

#include "geometry.h"
#include "base/vecmath.h"

typedef struct in104_frame {
    rt_vec3 origin;     /* vertex a, in scene coordinates */
    int exponent;       /* local = (world - origin) * 2^-exponent */
    rt_vec3 edge_ab;    /* (b - a) / scale */
    rt_vec3 edge_ac;    /* (c - a) / scale */
    rt_vec3 normal;     /* edge_ab x edge_ac times a power of two, its
                           largest component in [0.5, 1) */
    rt_vec3 unit;       /* the unit normal, (0, 0, 0) for a zero-area facet */
    int degenerate;     /* non-zero: zero area (or non-finite vertices) */
} in104_frame;

static inline rt_vec3 in104_vec(point p)
{
    return v3(p.x, p.y, p.z);
}

static inline point in104_point(rt_vec3 v)
{
    point p = {v.x, v.y, v.z};
    return p;
}

/*
 * a*b - c*d to within about one rounding of the result, even when the two
 * products nearly cancel (Kahan's algorithm with fma): the cross products of
 * a sliver's nearly parallel edges keep their accuracy.
 */
static inline double in104_difference_of_products(double a, double b,
                                                  double c, double d)
{
    double cd = c * d;
    double error = fma(-c, d, cd);      /* cd - c*d, exactly */
    return fma(a, b, -cd) + error;
}

/* a x b, each component accurate to about one rounding (see above). */
static inline rt_vec3 in104_cross(rt_vec3 a, rt_vec3 b)
{
    return v3(in104_difference_of_products(a.y, b.z, a.z, b.y),
              in104_difference_of_products(a.z, b.x, a.x, b.z),
              in104_difference_of_products(a.x, b.y, a.y, b.x));
}

/* The point with three NaN coordinates: "no answer". */
static inline point in104_no_point(void)
{
    point p = {(double)NAN, (double)NAN, (double)NAN};
    return p;
}

/* Fills `frame` for the triangle a, b, c. */
void in104__frame_make(in104_frame *frame, point a, point b, point c);

/* (p - origin) * 2^-exponent: p in the frame's local coordinates. */
rt_vec3 in104__frame_local(const in104_frame *frame, point p);

/* v * 2^exponent: a local length or vector back in scene units. */
double in104__frame_to_world(const in104_frame *frame, double length);

#endif /* IN104_FRAME_H */
