/*
 * kernel.h - the ray-tracing kernel, in double and in float (internal).
 *
 * One implementation (kernel_impl.h and its parts, in this directory) is
 * compiled twice, by kernel_double.c and kernel_float.c, so both precisions
 * run exactly the same algorithm:
 * the watertight intersection test, the error-bounded offset of secondary
 * ray origins, and the shading of docs/rendering-model.md.  A kernel is
 * built from a scene's facet records and holds, in its own precision, only
 * what the renderer reads: the facets that can be hit and their precomputed data.
 * A kernel is immutable once built: any number of threads may trace with it.
 * Its octree (octree_impl.h) is built on first request, once, under a lock
 * (rt__kernel_*_octree_prepare, thread-safe), and only read afterwards;
 * once it exists, nearest_hit and occluded go through it (same answers).
 * octree_prepare returns RT_OK (built now or before; *info filled when not
 * NULL), RT_ERR_NOMEM, or RT_ERR_CANCELLED when `cancel` (may be NULL) is
 * raised before the build completes: the build then stops within about a
 * millisecond and nothing is kept, so a later call builds it again.
 *
 * trace_span traces `count` camera rays from `origin` (the camera rays of
 * neighbouring pixels), the colour of ray j into colors[j], each exactly
 * as trace would give it; with the eye of `origin` in settings, a scene of
 * few facets and the fast loops it shares work among them
 * (packet_impl.h).
 *
 * An eye is what one render adds to a kernel: the facets' vertices minus
 * the camera's observer, computed once, so that the fast loops save those
 * subtractions for every camera ray (rays from elsewhere ignore it).  It is
 * immutable too, and must not outlive its kernel.
 */
#ifndef RAYTRACE_KERNEL_H
#define RAYTRACE_KERNEL_H

#include <stdint.h>

#include "raytrace/explain.h"
#include "raytrace/render.h"
#include "raytrace/scene.h"

/* What a kernel is built from. */
typedef struct rt_kernel_source {
    const rt_vec3 *vertices;
    const rt_facet_info *facets;
    int facet_count;
    const rt_light *lights; /* light_count >= 1 */
    int light_count;
    rt_rgb8 background;
    const rt_cancel *cancel;    /* NULL, or a flag the construction polls:
                                   raised, it stops and returns NULL */
} rt_kernel_source;

/* Facets a kernel's construction handles between two polls of its
 * source's cancellation flag. */
#define RT_KERNEL_POLL 65536

/*
 * A recorder (explain.c) is told every ray a trace casts, in order, with
 * what it hits and what each term adds to the colour, the values exactly as
 * the trace computes them; the trace's own arithmetic does not change.
 * Node indices are the recorder's; -1 (a full recorder) makes the calls
 * about that ray and its descendants no-ops.
 */
typedef struct rt_trace_recorder rt_trace_recorder;
int rt__record_ray(rt_trace_recorder *recorder, int kind, int parent,
                   int depth, rt_vec3 origin, rt_vec3 direction,
                   double weight);
void rt__record_hit(rt_trace_recorder *recorder, int node, int facet,
                    double t, rt_vec3 point, rt_vec3 normal);
void rt__record_miss(rt_trace_recorder *recorder, int node, rt_color own);
void rt__record_shadow(rt_trace_recorder *recorder, int parent, int light,
                       rt_vec3 origin, rt_vec3 direction, double n_dot_s,
                       int cast, int blocked, int blocker, rt_color own);

/* Settings of one trace. */
typedef struct rt_trace_settings {
    int max_depth;
    int fast_inv_sqrt;      /* normalise with the handout's fastInvSqrt */
    rt_kernel_choice kernel;    /* RT_KERNEL_SCALAR: the plain loops */
    const void *eye;        /* NULL, or the rt_kernel_eye_d/_f (matching
                               the kernel) of the camera rays' origin */
    int octree;             /* non-zero: queries go through the kernel's
                               octree (rt__kernel_*_octree_prepare first) */
    rt_trace_recorder *recorder;    /* NULL (renders), or what records the
                                       rays for rt_explain_pixel */
} rt_trace_settings;

/* Work counters of one thread: the THREAD counters of RT_STATS_MAP
 * (raytrace/render.h), by the same names, summed into rt_render_stats at
 * the end, and what the kernel counts for the render's own use. */
#define RT_COUNTER_FIELD_(type, name, origin, merge, group, key, title)     \
    RT_COUNTER_##origin##_(type, name)
#define RT_COUNTER_THREAD_(type, name) type name;
#define RT_COUNTER_RENDER_(type, name)
#define RT_COUNTER_OCTREE_(type, name)
typedef struct rt_counters {
    RT_STATS_MAP(RT_COUNTER_FIELD_)
    uint64_t early_exit_saved;  /* facets a shadow ray did not test after
                                   its first hit */
    int out_of_memory;          /* a ray tree outgrew the memory */
} rt_counters;
#undef RT_COUNTER_FIELD_
#undef RT_COUNTER_THREAD_
#undef RT_COUNTER_RENDER_
#undef RT_COUNTER_OCTREE_

/* An octree lists at most this many facet references per facet (plus
 * RT_OCTREE_REFERENCE_EXTRA) in all its leaves together. */
#define RT_OCTREE_REFERENCE_BUDGET 16
#define RT_OCTREE_REFERENCE_EXTRA 4096

/* What an octree holds (kernel_impl.h builds it on first use). */
typedef struct rt_octree_info {
    double build_seconds;
    uint64_t nodes;
    uint64_t leaves;
    int depth;
    uint64_t references;    /* facet indices in all leaves */
    uint64_t always;        /* facets every ray tests, in no leaf (all of
                               them when the coordinates leave no room for
                               cells; else 0: slivers are in leaves) */
    uint64_t slivers;       /* facets listed in leaves whose shape the
                               stopping rule cannot trust: never left out */
    uint64_t bytes;
} rt_octree_info;

/* A hit as the queries report it (in double whatever the precision). */
typedef struct rt_kernel_hit {
    double t;
    int facet;              /* index of the facet record */
    rt_vec3 point;
    rt_vec3 normal;         /* unit, facing the ray's origin */
} rt_kernel_hit;

#define RT_KERNEL_DECLARE(suffix)                                            \
    typedef struct rt_kernel_##suffix rt_kernel_##suffix;                    \
    rt_kernel_##suffix *rt__kernel_##suffix##_create(                        \
        const rt_kernel_source *source);                                     \
    void rt__kernel_##suffix##_free(rt_kernel_##suffix *kernel);             \
    typedef struct rt_kernel_eye_##suffix rt_kernel_eye_##suffix;            \
    rt_kernel_eye_##suffix *rt__kernel_##suffix##_eye_create(                \
        const rt_kernel_##suffix *kernel, rt_vec3 eye);                      \
    void rt__kernel_##suffix##_eye_free(rt_kernel_eye_##suffix *eye);        \
    rt_color rt__kernel_##suffix##_trace(                                    \
        const rt_kernel_##suffix *kernel, rt_vec3 origin,                    \
        rt_vec3 direction, const rt_trace_settings *settings,                \
        rt_counters *counters);                                              \
    void rt__kernel_##suffix##_trace_span(                                  \
        const rt_kernel_##suffix *kernel, rt_vec3 origin,                    \
        const rt_vec3 *directions, int count,                                \
        const rt_trace_settings *settings, rt_counters *counters,            \
        rt_color *colors);                                                   \
    int rt__kernel_##suffix##_nearest_hit(const rt_kernel_##suffix *kernel,  \
                                          rt_ray ray, double t_max,          \
                                          rt_kernel_hit *hit);               \
    int rt__kernel_##suffix##_occluded(const rt_kernel_##suffix *kernel,     \
                                       rt_vec3 from, rt_vec3 to,             \
                                       int skip_facet);                      \
    rt_status rt__kernel_##suffix##_octree_prepare(                          \
        const rt_kernel_##suffix *kernel, const rt_cancel *cancel,           \
        rt_octree_info *info);

RT_KERNEL_DECLARE(d)
RT_KERNEL_DECLARE(f)

#endif /* RAYTRACE_KERNEL_H */
