/*
 * kernel_double.c - the ray-tracing kernel in double precision (the
 * reference): rt__kernel_double_ops.  The implementation is kernel_impl.h.
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

const rt_kernel_ops rt__kernel_double_ops = {
    .precision = RT_PRECISION_DOUBLE,
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
