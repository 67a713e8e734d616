/*
 * kernel_double.c - the ray-tracing kernel in double precision (the
 * reference).  The implementation is kernel_impl.h.
 */
#include <float.h>

#define REAL double
#define REAL_IS_FLOAT 0
#define REAL_EPS DBL_EPSILON
#define REAL_MIN DBL_MIN           /* smallest normal */
#define REAL_TRUE_MIN DBL_TRUE_MIN /* smallest subnormal */
#define KERNEL(name) rt__kernel_d_##name
#define KERNEL_T rt_kernel_d
#define KERNEL_EYE_T rt_kernel_eye_d
#include "kernel_impl.h"
