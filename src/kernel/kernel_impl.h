/*
 * kernel_impl.h - the ray-tracing kernel, written once for any precision:
 * the kernel object (its data, its construction), the trace context, the
 * order in which its parts are compiled, and the operations the table of
 * kernel.h points at.
 *
 * Included by kernel_double.c and kernel_float.c with
 *     REAL       the floating-point type (double or float)
 *     REAL_IS_FLOAT  1 for float
 *     REAL_EPS   its machine epsilon (DBL_EPSILON or FLT_EPSILON)
 *     REAL_MIN, REAL_TRUE_MIN  its smallest normal and subnormal numbers
 *     KERNEL_T, KERNEL_EYE_T   the names of its kernel and eye structs
 *     KERNEL_OPS the name of its table (rt__kernel_double_ops ...)
 * Everything here is static but the table of operations at the end,
 * KERNEL_OPS, which kernel.h declares.  The parts, each using only those
 * before it:
 *     real_impl.h          vector arithmetic and error bounds
 *     intersect_impl.h     the watertight test and the tie rule
 *     simd_impl.h          the exact AVX2 filter over blocks of eight
 *                          facets
 *     octree_impl.h        the octree's nodes (octree_build_impl.h builds
 *                          them, octree_walk_impl.h walks a ray through
 *                          them)
 *     kdtree_impl.h        the kd-tree's nodes (kdtree_split_impl.h
 *                          splits a node, kdtree_build_impl.h builds
 *                          the tree on several threads,
 *                          kdtree_walk_impl.h walks it)
 *     query_brute_impl.h   nearest hit and any hit over every facet
 *     query_octree_impl.h  the same through the octree
 *     query_kdtree_impl.h  the same through the kd-tree
 *     query_impl.h         the queries a trace makes: the only chooser
 *     shade_impl.h         what happens at a hit: the point, its offsets,
 *                          the direct light (shade_hit)
 *     trace_impl.h         the two trace loops (opaque, transparent)
 *     packet_impl.h        camera rays in packets: a tile cull, SIMD
 *                          across rays
 */
#include <pthread.h>
#include <stdlib.h>
#include <tgmath.h>
#include <string.h>

#include <stdatomic.h>
#include <stdint.h>

#include "kernel.h"

#include "base/clock.h"
#include "base/exact.h"
#include "base/fast_inv_sqrt.h"
#include "base/pages.h"
#include "kernel/plane_crossing.h"
#include "real_impl.h"

/* A material of the scene in this precision, with what shading needs
 * precomputed: facets alike share one. */
typedef struct material {
    REAL k;                 /* reflection */
    REAL diffuse[3];        /* d C_S C_F / 255 per channel, for the first
                               light (d = 1 - k - t in .scn files) */
    REAL t;                 /* transparency */
    REAL n;                 /* refractive index */
    REAL d;                 /* diffuse weight */
    REAL s;                 /* highlight weight (0: none) */
    REAL p;                 /* highlight exponent, >= 1 */
} material;

/* A facet that can be hit: 48 bytes in double, 32 in float.  Its
 * corners are indices into the kernel's vertices, which a mesh shares
 * between the facets around each (about six on a terrain).  With the
 * corners copied into every facet it took 104 bytes in double, 56 in
 * float; the shared vertices add back 24 bytes (12 in float) per vertex,
 * and a terrain has half as many vertices as facets: 44 bytes a facet
 * saved in double, 18 in float. */
typedef struct tri {
    vec normal;             /* unit, in the direction of (b-a) x (c-a) */
    int v[3];               /* its corners a, b, c: indices into the
                               kernel's vertices */
    int facet;              /* index of the facet record */
    int material;           /* index into the kernel's materials */
} tri;

/* Corner j (0, 1, 2: a, b, c) of facet f, whose kernel's vertices are
 * `vertices`. */
static inline const vec *corner(const vec *vertices, const tri *f, int j)
{
    return &vertices[f->v[j]];
}

typedef struct block block;     /* eight facets, simd_impl.h */
typedef struct octree octree;   /* octree_impl.h */
typedef struct kdtree kdtree;   /* kdtree_impl.h */

/* The vertices minus one ray origin, for the rays that start there, and
 * for a scene of few facets their edge functions for the packets. */
typedef struct KERNEL_EYE_T {
    vec origin;
    block *blocks;
    int count;                  /* the kernel's facets */
    double *edges;          /* NULL, or the facets' edge functions by
                               frame (packet_impl.h) */
} KERNEL_EYE_T;

typedef struct KERNEL_T {
    rt_kernel base;         /* first: the table of operations */
    tri *tris;
    int count;
    vec *vertices;          /* the scene's vertices in this precision
                               (from_rt), which tris' v[] index: 0 ..
                               vertex_count - 1, one past the largest
                               index a facet of tris uses */
    int vertex_count;
    /* The same facets, eight by eight, for the brute-force AVX2 loops:
     * made with the kernel when it has fewer than RT_ACCEL_AUTO_FACETS
     * facets (where `auto` picks brute force), else by the first call of
     * prepare_blocks (a brute-force render); until then those loops give
     * way to the scalar ones (the same hits).  A tree's leaves gather
     * their facets from `tris`, so a big mesh never holds this copy. */
    _Atomic(block *) blocks;
    int block_count;
    int avx2;               /* the processor runs the AVX2 loops */
    vec light;              /* the first light */
    vec *lights;            /* every light, the first included */
    int light_count;
    material *materials;    /* the scene's, in this precision */
    int material_count;
    REAL *more_diffuse;     /* per material m, per further light l >= 1:
                               d C_S,l C_F / 255 at [(m (L-1) + l-1) 3 + c] */
    int transparent;        /* some facet has t > 0 */
    vec *vertex_normals;    /* NULL when no facet is smooth; else per
                               vertex its unit normal (zero: none) */
    unsigned char *smooth;  /* NULL, or per facet of tris: 1 when each
                               corner has a vertex normal */
    int shading;            /* some facet is smooth or has a highlight */
    vec *light_colors;      /* C_S,l per light, for the highlights */
    REAL background[3];
    struct shadow_plane *planes;    /* NULL, or per facet, and */
    REAL *light_side;       /* per light and facet: the shadow packets'
                               cull (packet_impl.h) */
    REAL extent;            /* the largest |coordinate| of a vertex or a
                               light */
    _Atomic(octree *) tree;     /* built on first use, then only read */
    _Atomic(kdtree *) kd;       /* the same for the kd-tree */
    pthread_mutex_t tree_lock;  /* serialises those constructions and the
                                   blocks' */
} KERNEL_T;

/* k's blocks, once made; else NULL. */
static inline const block *blocks_of(const KERNEL_T *k)
{
    return atomic_load_explicit((_Atomic(block *) *)&k->blocks,
                                memory_order_acquire);
}

/* The precision's kernel behind the interface's handle (its first
 * member), and the same for an eye. */
static inline const KERNEL_T *kernel_of(const rt_kernel *kernel)
{
    return (const KERNEL_T *)kernel;
}

static inline const KERNEL_EYE_T *eye_of(const rt_kernel_eye *eye)
{
    return (const KERNEL_EYE_T *)eye;
}

/*
 * What the queries and the shading of one trace read besides the rays,
 * set once per trace (trace_context()) and passed by pointer: the kernel,
 * how to query it, and where to report.  The loops that inline the
 * shading build it as a local constant, so its fields stay in registers.
 */
typedef struct trace_ctx {
    const KERNEL_T *k;
    const octree *tree;         /* NULL: brute force */
    const KERNEL_EYE_T *eye;    /* NULL, or the eye of the camera rays'
                                   origin (nearest() reads it for them) */
    int simd;                   /* the AVX2 loops */
    int fast;                   /* normalise with fastInvSqrt */
    int max_depth;
    rt_counters *counters;
    const rt_trace_recorder *rec;   /* NULL in renders */
    const kdtree *kd;           /* NULL, or the kd-tree the queries use
                                   (then tree is NULL) */
    int shading;                /* the kernel has smooth facets or
                                   highlights: shade_hit() computes N_s,
                                   P' and the highlight (a constant 0
                                   compiles that code away) */
} trace_ctx;

#include "intersect_impl.h"
#include "simd_impl.h"
#include "octree_impl.h"
#include "octree_build_impl.h"
#include "octree_walk_impl.h"
#include "kdtree_impl.h"
#include "kdtree_split_impl.h"
#include "kdtree_build_impl.h"
#include "kdtree_walk_impl.h"

/* k's octree, once prepare_octree() has built it; else NULL. */
static const octree *octree_of(const KERNEL_T *k)
{
    return atomic_load_explicit((_Atomic(octree *) *)&k->tree,
                                memory_order_acquire);
}

/* k's kd-tree, once prepare_kdtree() has built it; else NULL. */
static const kdtree *kdtree_of(const KERNEL_T *k)
{
    return atomic_load_explicit((_Atomic(kdtree *) *)&k->kd,
                                memory_order_acquire);
}

/* The context of a trace with `settings`, recording into `rec` (the
 * settings' recorder, or NULL given as a constant for the renders' copy
 * of the loops). */
static inline trace_ctx trace_context(const KERNEL_T *k,
                                      const rt_trace_settings *settings,
                                      rt_counters *counters,
                                      const rt_trace_recorder *rec)
{
    return (trace_ctx){
        k, settings->octree && !settings->kdtree ? octree_of(k) : NULL,
        eye_of(settings->eye), k->avx2 && settings->kernel != RT_KERNEL_SCALAR,
        settings->fast_inv_sqrt, settings->max_depth, counters, rec,
        settings->kdtree ? kdtree_of(k) : NULL, k->shading};
}

/* The context of the queries nearest_hit and occluded: the fast loops,
 * the kd-tree once built, else the octree once built, nothing recorded. */
static inline trace_ctx query_context(const KERNEL_T *k,
                                      rt_counters *counters)
{
    const kdtree *kd = kdtree_of(k);
    return (trace_ctx){k,    kd != NULL ? NULL : octree_of(k),
                       NULL, k->avx2,
                       0,    0,
                       counters, NULL,
                       kd};
}

#include "query_brute_impl.h"
#include "query_octree_impl.h"
#include "query_kdtree_impl.h"
#include "query_impl.h"
#include "shade_impl.h"
#include "trace_impl.h"
#include "packet_impl.h"

static void kernel_destroy(rt_kernel *kernel);

/* Material m of source `s` in this precision, with its diffuse terms
 * for every light. */
static void add_material(KERNEL_T *k, const rt_kernel_source *s, int m)
{
    const rt_material *given = &s->materials[m];
    material *out = &k->materials[m];
    int more = s->light_count - 1;
    out->k = (REAL)given->reflection;
    out->t = (REAL)given->transparency;
    out->n = (REAL)given->refractive_index;
    /* The file's rule d = 1 - k - t in this precision (so a handout
     * facet gets exactly the (1 - k) of section 3); else the given d. */
    REAL d = given->diffuse == 1.0 - given->reflection - given->transparency
                 ? 1 - out->k - out->t
                 : (REAL)given->diffuse;
    out->d = d;
    out->s = (REAL)given->highlight;
    out->p = (REAL)given->exponent;
    k->shading |= out->s > 0;
    REAL color[3] = {given->color.r, given->color.g, given->color.b};
    for (int l = 0; l < s->light_count; l++) {
        const rt_rgb8 *c8 = &s->lights[l].color;
        REAL light[3] = {c8->r, c8->g, c8->b};
        REAL *terms = l == 0 ? out->diffuse
                             : &k->more_diffuse[((size_t)m * (size_t)more +
                                                 (size_t)(l - 1)) * 3];
        for (int c = 0; c < 3; c++)
            terms[c] = d * light[c] * color[c] / 255;
    }
}

/* Appends facet record i of source `s` to the kernel under construction. */
static void add_facet(KERNEL_T *k, const rt_kernel_source *s, int i)
{
    const rt_facet_record *record = &s->facets[i];
    tri *f = &k->tris[k->count++];
    rt_vec3 a = s->vertices[record->vertex[0]],
            b = s->vertices[record->vertex[1]],
            c = s->vertices[record->vertex[2]];
    for (int j = 0; j < 3; j++)
        f->v[j] = record->vertex[j];
    f->normal = from_rt(s->normals != NULL ? s->normals[i]
                                           : rt__facet_normal(a, b, c));
    f->facet = i;
    f->material = record->material;
    k->transparent |= k->materials[record->material].t > 0;
    if (k->smooth != NULL) {
        int smooth = 1;
        for (int j = 0; j < 3; j++) {
            rt_vec3 n = s->vertex_normals[record->vertex[j]];
            smooth &= n.x != 0.0 || n.y != 0.0 || n.z != 0.0;
        }
        k->smooth[f - k->tris] = (unsigned char)smooth;
        k->shading |= smooth;
    }
}

/* The number of vertices of source `s` that its facets but the
 * degenerate ones reach: one more than the largest index they use. */
static int vertices_used(const rt_kernel_source *s)
{
    int count = 0;
    for (int i = 0; i < s->facet_count; i++)
        for (int j = 0; j < 3 && !s->facets[i].degenerate; j++)
            if (s->facets[i].vertex[j] >= count)
                count = s->facets[i].vertex[j] + 1;
    return count;
}

/* The kernel's arrays, sized for source `s`, and its vertices in this
 * precision; 0 when out of memory. */
static int allocate(KERNEL_T *k, const rt_kernel_source *s)
{
    k->tris = malloc((size_t)(s->facet_count > 0 ? s->facet_count : 1) *
                     sizeof *k->tris);
    k->vertex_count = vertices_used(s);
    k->vertices = malloc((size_t)(k->vertex_count > 0 ? k->vertex_count
                                                      : 1) *
                         sizeof *k->vertices);
    for (int v = 0; k->vertices != NULL && v < k->vertex_count; v++)
        k->vertices[v] = from_rt(s->vertices[v]);
    int more = s->light_count - 1;
    k->light_count = s->light_count;
    k->lights = malloc((size_t)s->light_count * sizeof *k->lights);
    k->materials = malloc((size_t)(s->material_count > 0 ? s->material_count
                                                         : 1) *
                          sizeof *k->materials);
    k->material_count = s->material_count;
    /* One light (the handout's case) needs no table. */
    size_t more_size = more > 0 && s->material_count > 0
                           ? (size_t)more * (size_t)s->material_count * 3
                           : 1;
    k->more_diffuse = malloc(more_size * sizeof *k->more_diffuse);
    k->light_colors = malloc((size_t)s->light_count * sizeof *k->light_colors);
    int normals_ok = 1;
    if (s->vertex_normals != NULL) {
        /* Only the vertices the kernel keeps; a scene without normals
         * holds neither array. */
        k->vertex_normals = malloc((size_t)(k->vertex_count > 0
                                                ? k->vertex_count
                                                : 1) *
                                   sizeof *k->vertex_normals);
        k->smooth = malloc((size_t)(s->facet_count > 0 ? s->facet_count
                                                       : 1));
        normals_ok = k->vertex_normals != NULL && k->smooth != NULL;
        for (int v = 0; normals_ok && v < k->vertex_count; v++)
            k->vertex_normals[v] = from_rt(s->vertex_normals[v]);
    }
    return k->tris != NULL && k->vertices != NULL && k->lights != NULL &&
           k->materials != NULL && k->more_diffuse != NULL &&
           k->light_colors != NULL && normals_ok;
}

/* The blocks of k's facets (from malloc, 32-byte aligned); NULL when out
 * of memory. */
static block *make_blocks(const KERNEL_T *k)
{
    block *blocks = aligned_alloc(32, (size_t)(k->block_count > 0
                                                   ? k->block_count
                                                   : 1) *
                                          sizeof *blocks);
    if (blocks != NULL)
        fill_blocks(blocks, k->vertices, k->tris, k->count, mk(0, 0, 0));
    return blocks;
}

static rt_kernel *kernel_create(const rt_kernel_source *s)
{
    KERNEL_T *k = calloc(1, sizeof *k);
    if (k == NULL)
        return NULL;
    k->base.ops = &KERNEL_OPS;
    atomic_init(&k->blocks, NULL);
    atomic_init(&k->tree, NULL);
    atomic_init(&k->kd, NULL);
    pthread_mutex_init(&k->tree_lock, NULL);
    if (!allocate(k, s)) {
        kernel_destroy(&k->base);
        return NULL;
    }
    for (int l = 0; l < s->light_count; l++) {
        k->lights[l] = from_rt(s->lights[l].position);
        k->light_colors[l] = mk(s->lights[l].color.r, s->lights[l].color.g,
                                s->lights[l].color.b);
    }
    k->light = k->lights[0];
    k->background[0] = s->background.r;
    k->background[1] = s->background.g;
    k->background[2] = s->background.b;
    for (int m = 0; m < s->material_count; m++)
        add_material(k, s, m);
    for (int i = 0; i < s->facet_count; i++) {
        if (i % RT_KERNEL_POLL == RT_KERNEL_POLL - 1 &&
            rt_cancel_requested(s->cancel)) {
            kernel_destroy(&k->base);
            return NULL;
        }
        if (!s->facets[i].degenerate)   /* never hit: not even stored */
            add_facet(k, s, i);
    }
    k->block_count = (k->count + BLOCK_LANES - 1) / BLOCK_LANES;
    k->avx2 = cpu_has_avx2();
    if (k->avx2 && k->count < RT_ACCEL_AUTO_FACETS) {
        block *blocks = make_blocks(k);
        if (blocks == NULL) {
            kernel_destroy(&k->base);
            return NULL;
        }
        atomic_store_explicit(&k->blocks, blocks, memory_order_relaxed);
    }
    if (k->avx2 && k->count > 0 && k->count <= PACKET_MAX_FACETS &&
        k->light_count <= KNOWN_LIGHTS && !packet_prepare_kernel(k)) {
        free(k->planes);        /* out of memory: no shadow packets */
        free(k->light_side);
        k->planes = NULL;
        k->light_side = NULL;
    }
    return &k->base;
}

static void kernel_destroy(rt_kernel *kernel)
{
    KERNEL_T *k = (KERNEL_T *)kernel;
    if (k != NULL) {
        free(k->tris);
        free(k->vertices);
        free(atomic_load(&k->blocks));
        free(k->lights);
        free(k->materials);
        free(k->more_diffuse);
        free(k->light_colors);
        free(k->vertex_normals);
        free(k->smooth);
        free(k->planes);
        free(k->light_side);
        octree_free(atomic_load(&k->tree));
        kdtree_free(atomic_load(&k->kd));
        pthread_mutex_destroy(&k->tree_lock);
    }
    free(k);
}

static rt_status kernel_prepare_blocks(const rt_kernel *kernel)
{
    const KERNEL_T *k = kernel_of(kernel);
    KERNEL_T *mutable = (KERNEL_T *)k;  /* only the lazy blocks change */
    if (!k->avx2 || blocks_of(k) != NULL)
        return RT_OK;
    pthread_mutex_lock(&mutable->tree_lock);
    block *blocks = atomic_load_explicit(&mutable->blocks,
                                         memory_order_relaxed);
    if (blocks == NULL) {
        blocks = make_blocks(k);
        atomic_store_explicit(&mutable->blocks, blocks, memory_order_release);
    }
    pthread_mutex_unlock(&mutable->tree_lock);
    return blocks != NULL ? RT_OK : RT_ERR_NOMEM;
}

static rt_status kernel_prepare_octree(const rt_kernel *kernel,
                                       const rt_cancel *cancel,
                                       rt_octree_info *info)
{
    const KERNEL_T *k = kernel_of(kernel);
    KERNEL_T *mutable = (KERNEL_T *)k;  /* only the lazy octree changes */
    const octree *t = octree_of(k);
    rt_status status = RT_OK;
    if (t == NULL) {
        pthread_mutex_lock(&mutable->tree_lock);
        t = atomic_load_explicit(&mutable->tree, memory_order_relaxed);
        if (t == NULL) {
            /* Stored only when complete: a cancelled or failed build
             * leaves NULL, and the next render builds it again. */
            octree *built = octree_build(k, cancel, &status);
            atomic_store_explicit(&mutable->tree, built,
                                  memory_order_release);
            t = built;
        }
        pthread_mutex_unlock(&mutable->tree_lock);
    }
    if (t == NULL)
        return status;
    if (info != NULL) {
        info->build_seconds = t->build_seconds;
        info->nodes = (uint64_t)t->node_count;
        info->leaves = (uint64_t)t->leaf_count;
        info->depth = t->depth;
        info->references = (uint64_t)t->ref_count;
        info->always = (uint64_t)t->always_count;
        info->slivers = (uint64_t)t->sliver_count;
        info->bytes = (uint64_t)t->bytes;
        info->digest = 0;
    }
    return RT_OK;
}

static rt_status kernel_prepare_kdtree(const rt_kernel *kernel,
                                       const rt_cancel *cancel,
                                       rt_workers *workers, int threads,
                                       rt_octree_info *info)
{
    const KERNEL_T *k = kernel_of(kernel);
    KERNEL_T *mutable = (KERNEL_T *)k;  /* only the lazy kd-tree changes */
    const kdtree *t = kdtree_of(k);
    rt_status status = RT_OK;
    if (t == NULL) {
        pthread_mutex_lock(&mutable->tree_lock);
        t = atomic_load_explicit(&mutable->kd, memory_order_relaxed);
        if (t == NULL) {
            /* stored only when complete, as the octree */
            kdtree *built = kdtree_build(k, cancel, workers, threads,
                                          &status);
            atomic_store_explicit(&mutable->kd, built, memory_order_release);
            t = built;
        }
        pthread_mutex_unlock(&mutable->tree_lock);
    }
    if (t == NULL)
        return status;
    if (info != NULL) {
        info->build_seconds = t->build_seconds;
        info->nodes = (uint64_t)t->node_count;
        info->leaves = (uint64_t)t->leaf_count;
        info->depth = t->depth;
        info->references = (uint64_t)t->ref_count;
        info->always = t->brute ? (uint64_t)k->count : 0;
        info->slivers = (uint64_t)t->sliver_count;
        info->bytes = (uint64_t)t->bytes;
        info->digest = t->digest;
    }
    return RT_OK;
}

static void kernel_eye_destroy(rt_kernel_eye *eye)
{
    KERNEL_EYE_T *e = (KERNEL_EYE_T *)eye;
    if (e != NULL) {
        free(e->blocks);
        free(e->edges);
    }
    free(e);
}

static rt_kernel_eye *kernel_eye_create(const rt_kernel *kernel,
                                        rt_vec3 origin)
{
    const KERNEL_T *k = kernel_of(kernel);
    KERNEL_EYE_T *eye = calloc(1, sizeof *eye);
    if (eye == NULL)
        return NULL;
    eye->origin = from_rt(origin);
    eye->blocks = aligned_alloc(32, (size_t)(k->block_count > 0
                                                 ? k->block_count
                                                 : 1) *
                                        sizeof *eye->blocks);
    if (eye->blocks == NULL) {
        free(eye);
        return NULL;
    }
    fill_blocks(eye->blocks, k->vertices, k->tris, k->count,
                eye->origin);
    eye->count = k->count;
    if (k->avx2 && k->count > 0 && k->count <= PACKET_MAX_FACETS) {
        eye->edges = malloc(edges_size(k->count) * sizeof *eye->edges);
        if (eye->edges == NULL) {
            kernel_eye_destroy((rt_kernel_eye *)eye);
            return NULL;
        }
        packet_prepare_eye(eye, k->count);
    }
    return (rt_kernel_eye *)eye;
}

static int kernel_nearest_hit(const rt_kernel *kernel, rt_ray query,
                              double t_max, rt_kernel_hit *out)
{
    const KERNEL_T *k = kernel_of(kernel);
    vec direction = from_rt(query.direction);
    REAL length = max3(direction.x, direction.y, direction.z);
    if (!isfinite(length) || length == 0)
        return 0;
    ray r = prepare(from_rt(query.origin), direction);
    hit h;
    rt_counters counters = {0};
    trace_ctx c = query_context(k, &counters);
    if (!nearest(&c, NULL, &r, (REAL)t_max, -1, &h))
        return 0;
    const tri *f = &k->tris[h.index];
    vec error_bound;
    out->t = h.t;
    out->facet = f->facet;
    out->point = to_rt(hit_point(k->vertices, f, &h, r.origin, direction,
                                 &error_bound));
    out->normal = to_rt(dot(f->normal, direction) > 0 ? neg(f->normal)
                                                      : f->normal);
    return 1;
}

static int kernel_occluded(const rt_kernel *kernel, rt_vec3 from, rt_vec3 to,
                           int skip_facet)
{
    const KERNEL_T *k = kernel_of(kernel);
    vec o = from_rt(from);
    vec d = sub(from_rt(to), o);
    REAL length = max3(d.x, d.y, d.z);
    if (!isfinite(length) || length == 0 || !isfinite(max3(o.x, o.y, o.z)))
        return 0;
    int skip = -1;
    for (int i = 0; skip_facet >= 0 && i < k->count; i++)
        if (k->tris[i].facet == skip_facet)
            skip = i;
    ray r = prepare(o, d);
    rt_counters counters = {0};
    trace_ctx c = query_context(k, &counters);
    int blocker;
    return any_hit(&c, &r, 1, skip, &blocker);
}

const rt_kernel_ops KERNEL_OPS = {
    .precision = REAL_IS_FLOAT ? RT_PRECISION_FLOAT : RT_PRECISION_DOUBLE,
    .create = kernel_create,
    .destroy = kernel_destroy,
    .eye_create = kernel_eye_create,
    .eye_destroy = kernel_eye_destroy,
    .prepare_blocks = kernel_prepare_blocks,
    .prepare_octree = kernel_prepare_octree,
    .prepare_kdtree = kernel_prepare_kdtree,
    .trace = kernel_trace,
    .trace_span = kernel_trace_span,
    .nearest_hit = kernel_nearest_hit,
    .occluded = kernel_occluded,
};
