/*
 * kernel_float.c - the ray-tracing kernel in single precision (faster,
 * less accurate; docs/accuracy.md measures by how much).  The
 * implementation is kernel_impl.h.
 */
#include <float.h>

#define REAL float
#define REAL_IS_FLOAT 1
#define REAL_EPS FLT_EPSILON
#define REAL_MIN FLT_MIN           /* smallest normal */
#define REAL_TRUE_MIN FLT_TRUE_MIN /* smallest subnormal */
#define KERNEL(name) rt__kernel_f_##name
#define KERNEL_T rt_kernel_f
#define KERNEL_EYE_T rt_kernel_eye_f
#include "kernel_impl.h"
