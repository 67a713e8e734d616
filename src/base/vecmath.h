/*
 * vecmath.h - small vector arithmetic on rt_vec3, shared by the modules.
 *
 * Everything is static inline and does exactly the IEEE operations written
 * (the library is built with -ffp-contract=off), so results do not depend on
 * the compiler's mood.  Not public API.
 */
#ifndef RAYTRACE_VECMATH_H
#define RAYTRACE_VECMATH_H

#include <math.h>

#include "raytrace/vec3.h"

static inline rt_vec3 v3(double x, double y, double z)
{
    return (rt_vec3){x, y, z};
}

static inline rt_vec3 v3_add(rt_vec3 a, rt_vec3 b)
{
    return v3(a.x + b.x, a.y + b.y, a.z + b.z);
}

static inline rt_vec3 v3_sub(rt_vec3 a, rt_vec3 b)
{
    return v3(a.x - b.x, a.y - b.y, a.z - b.z);
}

static inline rt_vec3 v3_scale(rt_vec3 a, double s)
{
    return v3(a.x * s, a.y * s, a.z * s);
}

static inline rt_vec3 v3_neg(rt_vec3 a)
{
    return v3(-a.x, -a.y, -a.z);
}

static inline double v3_dot(rt_vec3 a, rt_vec3 b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

static inline rt_vec3 v3_cross(rt_vec3 a, rt_vec3 b)
{
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z,
              a.x * b.y - a.y * b.x);
}

/* Euclidean length, without overflow or underflow for any finite vector. */
static inline double v3_length(rt_vec3 a)
{
    double m = fmax(fabs(a.x), fmax(fabs(a.y), fabs(a.z)));
    if (m == 0.0 || isinf(m))
        return m;
    double x = a.x / m, y = a.y / m, z = a.z / m;
    return m * sqrt(x * x + y * y + z * z);
}

/* a / |a|; the zero vector stays zero. */
static inline rt_vec3 v3_normalize(rt_vec3 a)
{
    double m = fmax(fabs(a.x), fmax(fabs(a.y), fabs(a.z)));
    if (m == 0.0)
        return a;
    rt_vec3 s = v3(a.x / m, a.y / m, a.z / m);
    return v3_scale(s, 1.0 / sqrt(v3_dot(s, s)));
}

/* Largest absolute component. */
static inline double v3_max_abs(rt_vec3 a)
{
    return fmax(fabs(a.x), fmax(fabs(a.y), fabs(a.z)));
}

static inline rt_vec3 v3_abs(rt_vec3 a)
{
    return v3(fabs(a.x), fabs(a.y), fabs(a.z));
}

static inline double v3_get(rt_vec3 a, int axis)
{
    return axis == 0 ? a.x : axis == 1 ? a.y : a.z;
}

static inline int v3_is_finite(rt_vec3 a)
{
    return isfinite(a.x) && isfinite(a.y) && isfinite(a.z);
}

#endif /* RAYTRACE_VECMATH_H */
