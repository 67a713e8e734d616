/*
 * fast_inv_sqrt.h - the IN 104 handout's fastInvSqrt, defined once: a
 * bit-level first guess of 1/sqrt(x) refined by one Newton step (Lomont,
 * "Fast Inverse Square Root", 2003, gives both constants).  The kernel uses
 * it to normalise vectors under rt_render_options.fast_inv_sqrt
 * (rt-export --fast-sqrt), and libraytrace-util exports the float one as
 * the course's fastInvSqrt (include/in104/util.h), so both compute the
 * same bits.  Internal header: static inline, nothing exported.
 */
#ifndef RT_FAST_INV_SQRT_H
#define RT_FAST_INV_SQRT_H

#include <stdint.h>
#include <string.h>

/* Single precision: the classic 0x5f3759df guess, then
 * y (1.5 - (x / 2) y y), evaluated in that order. */
static inline float rt_fast_inv_sqrtf(float x)
{
    float y = x;
    uint32_t i;
    memcpy(&i, &y, sizeof i);
    i = UINT32_C(0x5f3759df) - (i >> 1);
    memcpy(&y, &i, sizeof y);
    return y * (1.5f - 0.5f * x * y * y);
}

/* Double precision: the same method with the 64-bit constant. */
static inline double rt_fast_inv_sqrt(double x)
{
    double y = x;
    uint64_t i;
    memcpy(&i, &y, sizeof i);
    i = UINT64_C(0x5fe6eb50c7b537a9) - (i >> 1);
    memcpy(&y, &i, sizeof y);
    return y * (1.5 - 0.5 * x * y * y);
}

#endif /* RT_FAST_INV_SQRT_H */
