/*
 * kernel_float.c - the ray-tracing kernel in single precision (faster,
 * less accurate; docs/accuracy.md measures by how much):
 * rt__kernel_float_ops.  The implementation is kernel_impl.h.
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

const rt_kernel_ops rt__kernel_float_ops = {
    .precision = RT_PRECISION_FLOAT,
    .create = kernel_create,
    .destroy = kernel_destroy,
    .eye_create = kernel_eye_create,
    .eye_destroy = kernel_eye_destroy,
    .prepare_octree = kernel_prepare_octree,
    .trace = kernel_trace,
    .trace_span = kernel_trace_span,
    .nearest_hit = kernel_nearest_hit,
    .occluded = kernel_occluded,
};
