/*
 * kernel.h - the ray-tracing kernel, in double and in float (internal).
 *
 * One implementation (kernel_impl.h and its parts, in this directory) is
 * compiled twice, by kernel_double.c and kernel_float.c, so both precisions
 * run exactly the same algorithm: the watertight intersection test, the
 * error-bounded offset of secondary ray origins, and the shading of
 * docs/rendering-model.md.  Each precision is reached through its table of
 * operations, rt__kernel_double_ops or rt__kernel_float_ops (SQLite's
 * sqlite3_io_methods is the model): a caller picks a table once, to create
 * a kernel, and afterwards holds an rt_kernel without knowing its
 * precision; the rt__kernel_* functions below call through the table.
 *
 * A kernel is built from a scene's facet records and holds, in its own
 * precision, only what the renderer reads: the facets that can be hit and
 * their precomputed data.  It is immutable once built: any number of
 * threads may trace with it.  Its octree is built on first request, once,
 * under a lock (prepare_octree, thread-safe), and only read afterwards;
 * once it exists, nearest_hit and occluded go through it (same answers).
 * Its kd-tree (prepare_kdtree) is made the same way, and once it exists
 * it serves those two queries instead.
 *
 * Nothing here calls up into the scene, the render or the formats: what a
 * trace reports besides its colour (the counters, a recorder's callbacks)
 * is handed in by the caller.
 */
#ifndef RAYTRACE_KERNEL_H
#define RAYTRACE_KERNEL_H

#include <stdint.h>

#include "base/workers.h"
#include "raytrace/explain.h"
#include "raytrace/render.h"
#include "raytrace/scene.h"

/* A material of a scene: what facets alike share (docs/rendering-model.md:
 * k, t, n, d and C_F), stored once in the scene's table however many
 * facets use it. */
typedef struct rt_material {
    double reflection;      /* k in [0, 1] */
    double transparency;    /* t >= 0, k + t <= 1 */
    double refractive_index; /* n > 0 */
    double diffuse;         /* d >= 0 (1 - k - t in .scn files) */
    rt_rgb8 color;          /* C_F */
    double highlight;       /* s >= 0 (0: no highlight) */
    double exponent;        /* p >= 1 */
} rt_material;

/* A facet as a scene keeps it (24 bytes): its corners, its material,
 * its line in the file and whether a ray can meet it.  Its normal is not
 * stored: rt__facet_normal computes it from the corners. */
typedef struct rt_facet_record {
    int vertex[3];          /* 0-based indices into the vertex array */
    int material;           /* index into the scene's materials */
    int line;               /* of the record in the source; 0: none */
    unsigned char degenerate;   /* 0, RT_FACET_ZERO_AREA or
                                   RT_FACET_REPEATED */
} rt_facet_record;

/* What a kernel is built from. */
typedef struct rt_kernel_source {
    const rt_vec3 *vertices;
    const rt_facet_record *facets;
    int facet_count;
    const rt_material *materials;   /* the facets' materials */
    int material_count;
    const rt_vec3 *normals; /* NULL, or each facet's rt__facet_normal,
                               computed already (the scene's build hands
                               them to the double kernel) */
    const rt_vec3 *vertex_normals;  /* NULL, or per vertex its unit normal
                                       (zero: none); a facet whose three
                                       corners have one is smooth */
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
 * A recorder is told every ray a trace casts, in order, with what it hits
 * and what each term adds to the colour, the values exactly as the trace
 * computes them; the trace's own arithmetic does not change.  The kernel
 * calls the callbacks with `state`; node indices are the recorder's, and
 * -1 (a full recorder) makes the calls about that ray and its descendants
 * no-ops.  rt_explain_pixel's recorder is in src/render/explain.c.
 */
typedef struct rt_trace_recorder {
    void *state;
    /* A ray of `kind` (rt_ray_kind) from node `parent` (-1: a camera ray):
     * its node, or -1 when it is not recorded. */
    int (*on_ray)(void *state, int kind, int parent, int depth,
                  rt_vec3 origin, rt_vec3 direction, double weight);
    /* Ray `node` met facet record `facet` at distance t. */
    void (*on_hit)(void *state, int node, int facet, double t,
                   rt_vec3 point, rt_vec3 normal, int smooth,
                   rt_vec3 shading_normal, rt_vec3 shading_point);
    /* Ray `node` met nothing: the background's term `own`. */
    void (*on_miss)(void *state, int node, rt_color own);
    /* The shadow ray from the hit of `parent` to light `light`: cast or
     * not (N.S <= 0, d = 0), blocked (by facet record `blocker`) or not,
     * and the term `own` it adds. */
    void (*on_shadow)(void *state, int parent, int light, rt_vec3 origin,
                      rt_vec3 direction, double n_dot_s, int cast,
                      int blocked, int blocker, rt_color own,
                      double r_dot_v, rt_color highlight);
} rt_trace_recorder;

/*
 * An eye is what one camera adds to a kernel: the facets' vertices minus
 * the camera's observer, computed once, so that the fast loops save those
 * subtractions for every camera ray (rays from elsewhere ignore it).  It
 * has its kernel's precision, is immutable, and must not outlive its
 * kernel.
 */
typedef struct rt_kernel_eye rt_kernel_eye;

/* Settings of one trace. */
typedef struct rt_trace_settings {
    int max_depth;
    int fast_inv_sqrt;      /* normalise with the handout's fastInvSqrt */
    rt_kernel_choice kernel;    /* RT_KERNEL_SCALAR: the plain loops */
    const rt_kernel_eye *eye;   /* NULL, or the eye (of the same kernel) of
                                   the camera rays' origin */
    int octree;             /* non-zero: queries go through the kernel's
                               octree (rt__kernel_prepare_octree first) */
    const rt_trace_recorder *recorder;  /* NULL (renders), or what records
                                           the rays for rt_explain_pixel */
    int kdtree;             /* non-zero: queries go through the kernel's
                               kd-tree (rt__kernel_prepare_kdtree first);
                               it takes precedence over `octree` */
} rt_trace_settings;

/* Work counters of one thread: the THREAD counters of RT_STATS_MAP
 * (raytrace/render.h), by the same names, summed into rt_render_stats at
 * the end, what the kernel counts for the render's own use, and the
 * thread's last-blocker cache (shade_impl.h), which rides along because
 * the counters are the one thing a thread hands every trace. */
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
    /* no counter: per light, 1 + the kernel index of the facet that last
     * blocked a shadow ray to it, 0 for none; {0} starts empty and
     * rt__counters_forget_blockers() empties it (each row, so that the
     * counts do not depend on which thread took which row) */
    int32_t last_blocker[RT_MAX_LIGHTS];
} rt_counters;
#undef RT_COUNTER_FIELD_
#undef RT_COUNTER_THREAD_
#undef RT_COUNTER_RENDER_
#undef RT_COUNTER_OCTREE_

/* Empties the last-blocker cache of `counters` (its counts stay). */
static inline void rt__counters_forget_blockers(rt_counters *counters)
{
    for (int l = 0; l < RT_MAX_LIGHTS; l++)
        counters->last_blocker[l] = 0;
}

/* An octree lists at most this many facet references per facet (plus
 * RT_OCTREE_REFERENCE_EXTRA) in all its leaves together. */
#define RT_OCTREE_REFERENCE_BUDGET 16
#define RT_OCTREE_REFERENCE_EXTRA 4096

/* A kd-tree lists at most this many facet references per facet (plus
 * RT_KDTREE_REFERENCE_EXTRA) in all its leaves together, and has at most
 * that many nodes; its depth is at most RT_KDTREE_MAX_DEPTH
 * (kdtree_impl.h gives the reasons). */
#define RT_KDTREE_REFERENCE_LIMIT 64
#define RT_KDTREE_REFERENCE_EXTRA 4096
#define RT_KDTREE_MAX_DEPTH 60

/* What an octree holds (octree_build_impl.h builds it on first use); a
 * kd-tree's figures come in the same struct (kdtree_build_impl.h; its
 * `always` counts the facets of a scene whose coordinates leave no room
 * for cells, all of them then). */
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
    uint64_t digest;        /* the kd-tree's: a hash (FNV-1a) of its nodes
                               and lists, equal for equal trees; the
                               octree's: 0 */
} rt_octree_info;

/* A hit as the queries report it (in double whatever the precision). */
typedef struct rt_kernel_hit {
    double t;
    int facet;              /* index of the facet record */
    rt_vec3 point;
    rt_vec3 normal;         /* unit, facing the ray's origin */
} rt_kernel_hit;

typedef struct rt_kernel_ops rt_kernel_ops;

/* A kernel of either precision.  Each precision's kernel (kernel_impl.h)
 * begins with this header, as SQLite's files begin with their methods. */
typedef struct rt_kernel {
    const rt_kernel_ops *ops;
} rt_kernel;

/*
 * The operations of one precision.  Every function but create takes a
 * kernel this table created (and eye_destroy an eye of such a kernel).
 */
struct rt_kernel_ops {
    rt_precision precision;
    /* A kernel of source's facets and lights; NULL when out of memory or
     * when source->cancel was raised during the construction. */
    rt_kernel *(*create)(const rt_kernel_source *source);
    void (*destroy)(rt_kernel *kernel);
    /* The eye of `origin`; NULL when out of memory. */
    rt_kernel_eye *(*eye_create)(const rt_kernel *kernel, rt_vec3 origin);
    void (*eye_destroy)(rt_kernel_eye *eye);     /* NULL: no-op */
    /* Makes the blocks the brute-force AVX2 loops read unless they exist
     * (thread-safe): RT_OK (also when the processor has no AVX2, or the
     * kernel made them with itself, below RT_ACCEL_AUTO_FACETS facets)
     * or RT_ERR_NOMEM.  Without them brute force runs the scalar loops,
     * with the same hits: a kernel traced through a tree never needs
     * them. */
    rt_status (*prepare_blocks)(const rt_kernel *kernel);
    /*
     * Builds the kernel's octree unless it exists (thread-safe): RT_OK
     * (built now or before; *info filled when not NULL), RT_ERR_NOMEM, or
     * RT_ERR_CANCELLED when `cancel` (may be NULL) is raised before the
     * build completes: it then stops within about a millisecond and
     * nothing is kept, so a later call builds it again.
     */
    rt_status (*prepare_octree)(const rt_kernel *kernel,
                                const rt_cancel *cancel,
                                rt_octree_info *info);
    /* The same for the kernel's kd-tree (docs/kdtree.md): RT_OK,
     * RT_ERR_NOMEM or RT_ERR_CANCELLED, nothing kept when cancelled.
     * Built on `threads` threads of `workers` (NULL: threads of the
     * call's own), the same tree for any count.  Once it exists,
     * nearest_hit and occluded go through it. */
    rt_status (*prepare_kdtree)(const rt_kernel *kernel,
                                const rt_cancel *cancel,
                                rt_workers *workers, int threads,
                                rt_octree_info *info);
    /* The colour the ray carries (docs/rendering-model.md), its work added
     * to *counters. */
    rt_color (*trace)(const rt_kernel *kernel, rt_vec3 origin,
                      rt_vec3 direction, const rt_trace_settings *settings,
                      rt_counters *counters);
    /* Traces `count` rays from `origin` (the camera rays of neighbouring
     * pixels), the colour of ray j into colors[j], each exactly as trace
     * gives it; with the eye of `origin` in settings, a scene of few
     * facets and the fast loops it shares work among them (packets). */
    void (*trace_span)(const rt_kernel *kernel, rt_vec3 origin,
                       const rt_vec3 *directions, int count,
                       const rt_trace_settings *settings,
                       rt_counters *counters, rt_color *colors);
    /* The nearest hit within (0, t_max) of the ray (any direction length;
     * 0 for a zero or non-finite one): non-zero and *hit filled, or 0. */
    int (*nearest_hit)(const rt_kernel *kernel, rt_ray ray, double t_max,
                       rt_kernel_hit *hit);
    /* Non-zero when a facet (other than facet record skip_facet, -1: none)
     * blocks the open segment from `from` to `to`. */
    int (*occluded)(const rt_kernel *kernel, rt_vec3 from, rt_vec3 to,
                    int skip_facet);
};

/* The tables, in kernel_double.c and kernel_float.c. */
extern const rt_kernel_ops rt__kernel_double_ops;
extern const rt_kernel_ops rt__kernel_float_ops;

/* The calls through a kernel's table (NULL kernel or eye: destroy is a
 * no-op; every other call needs a kernel). */
static inline void rt__kernel_destroy(rt_kernel *kernel)
{
    if (kernel != NULL)
        kernel->ops->destroy(kernel);
}

static inline rt_kernel_eye *rt__kernel_eye_create(const rt_kernel *kernel,
                                                   rt_vec3 origin)
{
    return kernel->ops->eye_create(kernel, origin);
}

static inline void rt__kernel_eye_destroy(const rt_kernel *kernel,
                                          rt_kernel_eye *eye)
{
    kernel->ops->eye_destroy(eye);
}

static inline rt_status rt__kernel_prepare_blocks(const rt_kernel *kernel)
{
    return kernel->ops->prepare_blocks(kernel);
}

static inline rt_status rt__kernel_prepare_octree(const rt_kernel *kernel,
                                                  const rt_cancel *cancel,
                                                  rt_octree_info *info)
{
    return kernel->ops->prepare_octree(kernel, cancel, info);
}

static inline rt_status rt__kernel_prepare_kdtree(const rt_kernel *kernel,
                                                  const rt_cancel *cancel,
                                                  rt_workers *workers,
                                                  int threads,
                                                  rt_octree_info *info)
{
    return kernel->ops->prepare_kdtree(kernel, cancel, workers, threads,
                                       info);
}

static inline rt_color rt__kernel_trace(const rt_kernel *kernel,
                                        rt_vec3 origin, rt_vec3 direction,
                                        const rt_trace_settings *settings,
                                        rt_counters *counters)
{
    return kernel->ops->trace(kernel, origin, direction, settings, counters);
}

static inline void rt__kernel_trace_span(const rt_kernel *kernel,
                                         rt_vec3 origin,
                                         const rt_vec3 *directions,
                                         int count,
                                         const rt_trace_settings *settings,
                                         rt_counters *counters,
                                         rt_color *colors)
{
    kernel->ops->trace_span(kernel, origin, directions, count, settings,
                            counters, colors);
}

static inline int rt__kernel_nearest_hit(const rt_kernel *kernel, rt_ray ray,
                                         double t_max, rt_kernel_hit *hit)
{
    return kernel->ops->nearest_hit(kernel, ray, t_max, hit);
}

static inline int rt__kernel_occluded(const rt_kernel *kernel, rt_vec3 from,
                                      rt_vec3 to, int skip_facet)
{
    return kernel->ops->occluded(kernel, from, to, skip_facet);
}

#endif /* RAYTRACE_KERNEL_H */
