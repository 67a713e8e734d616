/*
 * kernel_double.c - the ray-tracing kernel in double precision (the
 * reference): the table rt__kernel_double_ops, which kernel_impl.h
 * defines with its operations.
 */
#include <float.h>

#define REAL double
#define REAL_IS_FLOAT 0
#define REAL_EPS DBL_EPSILON
#define REAL_MIN DBL_MIN           /* smallest normal */
#define REAL_TRUE_MIN DBL_TRUE_MIN /* smallest subnormal */
#define KERNEL_T kernel_double
#define KERNEL_EYE_T kernel_eye_double
#define KERNEL_OPS rt__kernel_double_ops
#include "kernel_impl.h"
