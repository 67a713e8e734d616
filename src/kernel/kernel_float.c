/*
 * kernel_float.c - the ray-tracing kernel in single precision (faster,
 * less accurate; docs/accuracy.md measures by how much):
 * the table rt__kernel_float_ops, which kernel_impl.h defines with its
 * operations.
 */
#include <float.h>

#define REAL float
#define REAL_IS_FLOAT 1
#define REAL_EPS FLT_EPSILON
#define REAL_MIN FLT_MIN           /* smallest normal */
#define REAL_TRUE_MIN FLT_TRUE_MIN /* smallest subnormal */
#define KERNEL_T kernel_float
#define KERNEL_EYE_T kernel_eye_float
#define KERNEL_OPS rt__kernel_float_ops
#include "kernel_impl.h"
