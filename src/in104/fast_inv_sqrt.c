/*
 * fast_inv_sqrt.c - fastInvSqrt() of the course's libutil (util.h): the
 * single-precision function of fast_inv_sqrt.h, which the kernel uses too,
 * so rt-export --fast-sqrt and a course program compute the same bits.
 */
#include "util.h"

#include "base/fast_inv_sqrt.h"

float fastInvSqrt(float x)
{
    return rt_fast_inv_sqrtf(x);
}
