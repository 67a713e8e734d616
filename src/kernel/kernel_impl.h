/*
 * kernel_impl.h - the ray-tracing kernel, written once for any precision:
 * the kernel object (its data, its construction) and the order in which
 * its parts are compiled.
 *
 * Included by kernel_double.c and kernel_float.c with
 *     REAL       the floating-point type (double or float)
 *     REAL_EPS   its machine epsilon (DBL_EPSILON or FLT_EPSILON)
 *     REAL_MIN, REAL_TRUE_MIN  its smallest normal and subnormal numbers
 *     KERNEL(x)  the name of an exported symbol (rt__kernel_d_##x ...)
 *     KERNEL_T   the kernel's type (rt_kernel_d ...)
 * Everything else here is static.  The parts, each using only those before
 * it:
 *     real_impl.h       vector arithmetic and error bounds
 *     intersect_impl.h  the watertight test and the tie rule
 *     simd_impl.h       the exact AVX2 filter over blocks of eight facets
 *     octree_impl.h     the octree: construction and the walk of a ray
 *     query_impl.h      nearest hit and any hit: brute force or octree
 *     shade_impl.h      hit points, offsets, light and reflections
 *     packet_impl.h     camera rays in packets: a tile cull, SIMD across
 *                       rays
 */
#include <pthread.h>
#include <stdlib.h>
#include <tgmath.h>
#include <string.h>

#include <stdatomic.h>
#include <stdint.h>

#include "kernel.h"

#include "base/clock.h"
#include "base/fast_inv_sqrt.h"
#include "kernel/plane_crossing.h"
#include "real_impl.h"

/* A facet that can be hit, with what shading needs precomputed. */
typedef struct tri {
    vec a, b, c;
    vec normal;             /* unit, in the direction of (b-a) x (c-a) */
    REAL k;
    REAL diffuse[3];        /* d C_S C_F / 255 per channel, for the first
                               light (d = 1 - k - t in .scn files) */
    REAL t;                 /* transparency */
    REAL n;                 /* refractive index */
    REAL d;                 /* diffuse weight */
    int facet;              /* index of the facet record */
} tri;

typedef struct block block;     /* eight facets, simd_impl.h */
typedef struct octree octree;   /* octree_impl.h */

/* The vertices minus one ray origin, for the rays that start there, and
 * for a scene of few facets their edge functions for the packets. */
struct KERNEL_EYE_T {
    vec origin;
    block *blocks;
    int count;                  /* the kernel's facets */
    double *edges;          /* NULL, or the facets' edge functions by
                               frame (packet_impl.h) */
};

struct KERNEL_T {
    tri *tris;
    int count;
    block *blocks;          /* the same facets, eight by eight */
    int block_count;
    int avx2;               /* the processor runs the AVX2 loops */
    vec light;              /* the first light */
    vec *lights;            /* every light, the first included */
    int light_count;
    REAL *more_diffuse;     /* per facet, per further light l >= 1:
                               d C_S,l C_F / 255 at [(i (L-1) + l-1) 3 + c] */
    int transparent;        /* some facet has t > 0 */
    REAL background[3];
    struct shadow_plane *planes;    /* NULL, or per facet, and */
    REAL *light_side;       /* per light and facet: the shadow packets'
                               cull (packet_impl.h) */
    REAL extent;            /* the largest |coordinate| of a vertex or a
                               light */
    _Atomic(octree *) tree;     /* built on first use, then only read */
    pthread_mutex_t tree_lock;  /* serialises that construction */
};

#include "intersect_impl.h"
#include "simd_impl.h"
#include "octree_impl.h"

/* k's octree, once KERNEL(octree_prepare) has built it; else NULL. */
static const octree *octree_of(const KERNEL_T *k)
{
    return atomic_load_explicit((_Atomic(octree *) *)&k->tree,
                                memory_order_acquire);
}

#include "query_impl.h"
#include "shade_impl.h"
#include "packet_impl.h"

KERNEL_T *KERNEL(create)(const rt_kernel_source *s)
{
    KERNEL_T *k = calloc(1, sizeof *k);
    if (k == NULL)
        return NULL;
    atomic_init(&k->tree, NULL);
    pthread_mutex_init(&k->tree_lock, NULL);
    k->tris = malloc((size_t)(s->facet_count > 0 ? s->facet_count : 1) *
                     sizeof *k->tris);
    if (k->tris == NULL) {
        free(k);
        return NULL;
    }
    int block_count = (s->facet_count + BLOCK_LANES - 1) / BLOCK_LANES;
    k->blocks = aligned_alloc(32, (size_t)(block_count > 0 ? block_count : 1) *
                                      sizeof *k->blocks);
    if (k->blocks == NULL) {
        free(k->tris);
        free(k);
        return NULL;
    }
    int more = s->light_count - 1;
    k->light_count = s->light_count;
    k->lights = malloc((size_t)s->light_count * sizeof *k->lights);
    /* One light (the handout's case) needs no table. */
    size_t more_size = more > 0 && s->facet_count > 0
                           ? (size_t)more * (size_t)s->facet_count * 3
                           : 1;
    k->more_diffuse = malloc(more_size * sizeof *k->more_diffuse);
    if (k->lights == NULL || k->more_diffuse == NULL) {
        KERNEL(free)(k);
        return NULL;
    }
    for (int l = 0; l < s->light_count; l++)
        k->lights[l] = from_rt(s->lights[l].position);
    k->light = k->lights[0];
    k->background[0] = s->background.r;
    k->background[1] = s->background.g;
    k->background[2] = s->background.b;
    for (int i = 0; i < s->facet_count; i++) {
        if (i % RT_KERNEL_POLL == RT_KERNEL_POLL - 1 &&
            rt_cancel_requested(s->cancel)) {
            KERNEL(free)(k);
            return NULL;
        }
        const rt_facet_info *info = &s->facets[i];
        if (info->degenerate)
            continue;       /* never hit: not even stored */
        tri *f = &k->tris[k->count++];
        f->a = from_rt(s->vertices[info->vertex[0]]);
        f->b = from_rt(s->vertices[info->vertex[1]]);
        f->c = from_rt(s->vertices[info->vertex[2]]);
        f->normal = from_rt(info->normal);
        f->k = (REAL)info->k;
        f->t = (REAL)info->t;
        f->n = (REAL)info->n;
        /* The file's rule d = 1 - k - t in this precision (so a handout
         * facet gets exactly the (1 - k) of section 3); else the given d. */
        REAL d = info->d == 1.0 - info->k - info->t ? 1 - f->k - f->t
                                                     : (REAL)info->d;
        f->d = d;
        k->transparent |= f->t > 0;
        REAL color[3] = {info->color.r, info->color.g, info->color.b};
        for (int l = 0; l < s->light_count; l++) {
            const rt_rgb8 *c8 = &s->lights[l].color;
            REAL light[3] = {c8->r, c8->g, c8->b};
            REAL *out = l == 0 ? f->diffuse
                               : &k->more_diffuse[((size_t)(k->count - 1) *
                                                       (size_t)more +
                                                   (size_t)(l - 1)) * 3];
            for (int c = 0; c < 3; c++)
                out[c] = d * light[c] * color[c] / 255;
        }
        f->facet = i;
    }
    k->block_count = (k->count + BLOCK_LANES - 1) / BLOCK_LANES;
    fill_blocks(k->blocks, k->tris, k->count, mk(0, 0, 0));
    k->avx2 = cpu_has_avx2();
    if (k->avx2 && k->count > 0 && k->count <= PACKET_MAX_FACETS &&
        k->light_count <= PACKET_MAX_LIGHTS && !packet_prepare_kernel(k)) {
        free(k->planes);        /* out of memory: no shadow packets */
        free(k->light_side);
        k->planes = NULL;
        k->light_side = NULL;
    }
    return k;
}

void KERNEL(free)(KERNEL_T *k)
{
    if (k != NULL) {
        free(k->tris);
        free(k->blocks);
        free(k->lights);
        free(k->more_diffuse);
        free(k->planes);
        free(k->light_side);
        octree_free(atomic_load(&k->tree));
        pthread_mutex_destroy(&k->tree_lock);
    }
    free(k);
}

rt_status KERNEL(octree_prepare)(const KERNEL_T *k, const rt_cancel *cancel,
                                 rt_octree_info *info)
{
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
    }
    return RT_OK;
}

KERNEL_EYE_T *KERNEL(eye_create)(const KERNEL_T *k, rt_vec3 origin)
{
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
    fill_blocks(eye->blocks, k->tris, k->count, eye->origin);
    eye->count = k->count;
    if (k->avx2 && k->count > 0 && k->count <= PACKET_MAX_FACETS) {
        eye->edges = malloc(edges_size(k->count) * sizeof *eye->edges);
        if (eye->edges == NULL) {
            KERNEL(eye_free)(eye);
            return NULL;
        }
        packet_prepare_eye(eye, k->count);
    }
    return eye;
}

void KERNEL(eye_free)(KERNEL_EYE_T *eye)
{
    if (eye != NULL) {
        free(eye->blocks);
        free(eye->edges);
    }
    free(eye);
}

int KERNEL(nearest_hit)(const KERNEL_T *k, rt_ray query, double t_max,
                        rt_kernel_hit *out)
{
    vec direction = from_rt(query.direction);
    REAL length = max3(direction.x, direction.y, direction.z);
    if (!isfinite(length) || length == 0)
        return 0;
    ray r = prepare(from_rt(query.origin), direction);
    hit h;
    rt_counters counters = {0};
    if (!nearest(k, k->avx2, octree_of(k), NULL, &r, (REAL)t_max, -1, &h,
                 &counters))
        return 0;
    const tri *f = &k->tris[h.index];
    vec error_bound;
    out->t = h.t;
    out->facet = f->facet;
    out->point = to_rt(hit_point(f, &h, r.origin, direction, &error_bound));
    out->normal = to_rt(dot(f->normal, direction) > 0 ? neg(f->normal)
                                                      : f->normal);
    return 1;
}

int KERNEL(occluded)(const KERNEL_T *k, rt_vec3 from, rt_vec3 to,
                     int skip_facet)
{
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
    return any_hit(k, k->avx2, octree_of(k), &r, 1, skip, &counters);
}

