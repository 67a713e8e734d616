/*
 * kernel_impl.h - the ray-tracing kernel, written once for any precision.
 *
 * Included by kernel_double.c and kernel_float.c with
 *     REAL       the floating-point type (double or float)
 *     REAL_EPS   its machine epsilon (DBL_EPSILON or FLT_EPSILON)
 *     KERNEL(x)  the name of an exported symbol (rt__kernel_d_##x ...)
 *     KERNEL_T   the kernel's type (rt_kernel_d ...)
 * Everything else here is static.
 *
 * Intersection: Woop, Benthin and Wald, "Watertight Ray/Triangle
 * Intersection", JCGT 2(1), 2013.  The ray is mapped onto +z by an axis
 * permutation and a shear; the facet is then tested in 2D by three edge
 * functions.  An edge shared by two facets gets bit-for-bit equal or
 * opposite edge functions in both (the library is built with
 * -ffp-contract=off so products round as written), and an edge function
 * that rounds to zero is recomputed with its exact sign, so no ray can pass
 * between two facets that share an edge.
 *
 * Secondary rays: the hit point is computed from barycentric weights with
 * its rounding-error bound, and the new ray starts just beyond that bound
 * along the normal (Pharr, Jakob, Humphreys, "Physically Based Rendering",
 * 4th ed., section 6.8.6).  The offset scales with the coordinates, so it
 * works for scenes at 1e-6 as at 1e6; the facet a ray leaves is also
 * skipped, which is exact (a flat facet cannot be met twice).
 */
#include <stdlib.h>
#include <tgmath.h>
#include <string.h>

#include <stdint.h>

#include "kernel.h"

typedef struct vec {
    REAL x, y, z;
} vec;

/* A facet that can be hit, with what shading needs precomputed. */
typedef struct tri {
    vec a, b, c;
    vec normal;             /* unit, in the direction of (b-a) x (c-a) */
    REAL k;
    REAL diffuse[3];        /* (1 - k) C_S C_F / 255 per channel */
    int facet;              /* index of the facet record */
} tri;

typedef struct block block;     /* eight facets, kernel_simd_impl.h */

/* The vertices minus one ray origin, for the rays that start there. */
struct KERNEL_EYE_T {
    vec origin;
    block *blocks;
};

struct KERNEL_T {
    tri *tris;
    int count;
    block *blocks;          /* the same facets, eight by eight */
    int block_count;
    int avx2;               /* the processor runs the AVX2 loops */
    vec light;
    REAL background[3];
};

static inline vec mk(REAL x, REAL y, REAL z) { return (vec){x, y, z}; }
static inline vec add(vec a, vec b) { return mk(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline vec sub(vec a, vec b) { return mk(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline vec scale(vec a, REAL s) { return mk(a.x * s, a.y * s, a.z * s); }
static inline vec neg(vec a) { return mk(-a.x, -a.y, -a.z); }
static inline vec vabs(vec a) { return mk(fabs(a.x), fabs(a.y), fabs(a.z)); }
static inline REAL dot(vec a, vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline REAL get(vec a, int axis) { return axis == 0 ? a.x : axis == 1 ? a.y : a.z; }
static inline vec from_rt(rt_vec3 v) { return mk((REAL)v.x, (REAL)v.y, (REAL)v.z); }
static inline rt_vec3 to_rt(vec v) { return (rt_vec3){v.x, v.y, v.z}; }

/* The handout's fastInvSqrt: a bit-level first guess refined by one Newton
 * step (Lomont, "Fast Inverse Square Root", 2003, gives the constants). */
static REAL fast_inv_sqrt(REAL x)
{
    if (sizeof(REAL) == sizeof(float)) {
        float f = (float)x;
        uint32_t i;
        memcpy(&i, &f, sizeof i);
        i = 0x5f3759dfu - (i >> 1);
        memcpy(&f, &i, sizeof f);
        return (REAL)(f * (1.5f - 0.5f * (float)x * f * f));
    }
    double d = (double)x;
    uint64_t i;
    memcpy(&i, &d, sizeof i);
    i = 0x5fe6eb50c7b537a9u - (i >> 1);
    memcpy(&d, &i, sizeof d);
    return (REAL)(d * (1.5 - 0.5 * (double)x * d * d));
}

/* a / |a| without overflow or underflow; zero stays zero. */
static vec normalize(vec a, int fast)
{
    REAL m = fmax(fabs(a.x), fmax(fabs(a.y), fabs(a.z)));
    if (m == 0)
        return a;
    vec s = scale(a, 1 / m);
    REAL n = dot(s, s);
    return scale(s, fast ? fast_inv_sqrt(n) : 1 / sqrt(n));
}

/* A ray prepared for the watertight test. */
typedef struct ray {
    vec origin;
    int kx, ky, kz;
    REAL sx, sy, sz;
} ray;

static ray prepare(vec origin, vec direction)
{
    ray r;
    r.origin = origin;
    vec d = vabs(direction);
    r.kz = d.x >= d.y ? (d.x >= d.z ? 0 : 2) : (d.y >= d.z ? 1 : 2);
    r.kx = (r.kz + 1) % 3;
    r.ky = (r.kx + 1) % 3;
    REAL dz = get(direction, r.kz);
    if (dz < 0) {           /* keep the winding of the projection */
        int swap = r.kx;
        r.kx = r.ky;
        r.ky = swap;
    }
    r.sx = get(direction, r.kx) / dz;
    r.sy = get(direction, r.ky) / dz;
    r.sz = 1 / dz;
    return r;
}

/* x*w - y*z with the exact sign even when it rounds to zero in REAL. */
static REAL edge(REAL x, REAL w, REAL y, REAL z)
{
    REAL e = x * w - y * z;
    if (e != 0)
        return e;
    if (sizeof(REAL) == sizeof(float))  /* float products are exact in double */
        return (REAL)((double)x * (double)w - (double)y * (double)z);
    /* Kahan's difference of products: error below 2 ulps, so the sign is
     * exact. */
    double yz = (double)y * (double)z;
    double err = fma(-(double)y, (double)z, yz);
    return (REAL)(fma((double)x, (double)w, -yz) + err);
}

typedef struct hit {
    REAL t;
    REAL t_error;           /* bound on the rounding error of t */
    REAL point_error;       /* estimate of the error of the point the
                               barycentric weights give, along the facet */
    REAL b0, b1, b2;        /* barycentric weights of a, b, c */
    int index;              /* into the kernel's tris */
} hit;

/* Higham's gamma(n) = n u / (1 - n u), u the unit roundoff. */
static REAL gamma_bound(int n)
{
    REAL u = REAL_EPS / 2;
    return n * u / (1 - n * u);
}

static REAL max3(REAL a, REAL b, REAL c)
{
    return fmax(fabs(a), fmax(fabs(b), fabs(c)));
}

/*
 * The watertight test: non-zero when the ray meets *f at a t in (0, t_max)
 * that provably exceeds 0: t must exceed its own rounding-error bound, so a
 * ray never meets a facet through its own origin (a camera lying on a facet
 * does not see it).  Shadow rays also ask that t plus the bound stays below
 * the light (blocks()), so a facet through the light does not shadow it.  The bound is
 * pbrt-v4's (Pharr, Jakob, Humphreys, section 6.8.4), with the products
 * regrouped so that none grows like the cube of the coordinates: t is
 * computed from the barycentric weights, and the bound from ratios to the
 * determinant, so coordinates from 1e-150 to 1e150 neither overflow nor
 * underflow.
 *
 * The fast loops (kernel_simd_impl.h) repeat the computation of the edge
 * functions u, v, w below, operation for operation, and skip the facets
 * where two of them have strictly opposite signs: keep both in step, and
 * keep that rejection the first thing this test does with u, v, w.
 */
static int intersect(const ray *r, const tri *f, REAL t_max, hit *h)
{
    vec a = sub(f->a, r->origin), b = sub(f->b, r->origin),
        c = sub(f->c, r->origin);
    REAL az = get(a, r->kz), bz = get(b, r->kz), cz = get(c, r->kz);
    REAL ax = get(a, r->kx) - r->sx * az, ay = get(a, r->ky) - r->sy * az;
    REAL bx = get(b, r->kx) - r->sx * bz, by = get(b, r->ky) - r->sy * bz;
    REAL cx = get(c, r->kx) - r->sx * cz, cy = get(c, r->ky) - r->sy * cz;
    REAL u = edge(cx, by, cy, bx);
    REAL v = edge(ax, cy, ay, cx);
    REAL w = edge(bx, ay, by, ax);
    if ((u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0))
        return 0;
    REAL det = u + v + w;
    if (det == 0 || !isfinite(det))
        return 0;
    REAL b0 = u / det, b1 = v / det, b2 = w / det;
    /* The shear's error comes with the unscaled z; t's with the scaled z
     * (pbrt-v4 does not tell them apart, as its directions are near unit
     * length; ours may be of any length). */
    REAL shear_z = max3(az, bz, cz);
    az *= r->sz;
    bz *= r->sz;
    cz *= r->sz;
    REAL t = b0 * az + b1 * bz + b2 * cz;

    REAL abs_det = fabs(det);
    REAL max_x = max3(ax, bx, cx), max_y = max3(ay, by, cy);
    REAL max_z = max3(az, bz, cz);
    REAL dx = gamma_bound(5) * (max_x + shear_z);
    REAL dy = gamma_bound(5) * (max_y + shear_z);
    REAL dz = gamma_bound(3) * max_z;
    REAL edge_error = 2 * (gamma_bound(2) * max_x * (max_y / abs_det) +
                           dy * (max_x / abs_det) + dx * (max_y / abs_det));
    REAL edge_ratio = max3(u, v, w) / abs_det;  /* <= 1: all of one sign */
    REAL t_error = 4 * (gamma_bound(3) * edge_ratio * max_z +
                        edge_error * max_z + dz * edge_ratio);
    if (!(t > t_error && t < t_max))
        return 0;
    h->t = t;
    h->t_error = t_error;
    h->point_error = edge_error * (max_x + max_y);
    h->b0 = b0;
    h->b1 = b1;
    h->b2 = b2;
    return 1;
}

/*
 * Non-zero when hit `c` (a later facet) replaces the nearest so far, `b`:
 * it is nearer, unless both facets lie in one plane and their distances
 * differ by less than their error bounds - coincident facets, whose order
 * rounding would otherwise decide - where the facet first in the file
 * stays.
 */
static int replaces(const KERNEL_T *k, const hit *b, const hit *c)
{
    if (!(c->t < b->t))
        return 0;
    if (b->t - c->t > b->t_error + c->t_error)
        return 1;
    REAL cosine = dot(k->tris[b->index].normal, k->tris[c->index].normal);
    return fabs(cosine) < 1 - 16 * REAL_EPS;
}

/* Nearest hit, all facets but `skip` (ties: see replaces()). */
static int nearest_scalar(const KERNEL_T *k, const ray *r, REAL t_max,
                          int skip, hit *h, uint64_t *tests)
{
    int found = 0;
    hit candidate;
    for (int i = 0; i < k->count; i++) {
        if (i != skip && intersect(r, &k->tris[i], t_max, &candidate)) {
            candidate.index = i;
            if (found && !replaces(k, h, &candidate))
                continue;
            *h = candidate;
            t_max = candidate.t;
            found = 1;
        }
    }
    *tests += (uint64_t)k->count - (skip >= 0);
    return found;
}

/* Non-zero when a hit of a shadow ray towards a light at t = t_max blocks
 * it: the facet is provably before the light. */
static int blocks(const hit *h, REAL t_max)
{
    return h->t + h->t_error < t_max;
}

/* Any hit in (0, t_max), all facets but `skip`; stops at the first. */
static int any_hit_scalar(const KERNEL_T *k, const ray *r, REAL t_max,
                          int skip, uint64_t *tests, uint64_t *saved)
{
    hit ignored;
    uint64_t made = 0;
    int found = 0;
    for (int i = 0; i < k->count && !found; i++) {
        if (i == skip)
            continue;
        made++;
        found = intersect(r, &k->tris[i], t_max, &ignored) &&
                blocks(&ignored, t_max);
    }
    *tests += made;
    *saved += (uint64_t)k->count - (skip >= 0) - made;
    return found;
}

#include "kernel_simd_impl.h"

/* The loops a trace uses: AVX2 when the processor has it and the caller
 * did not ask for the scalar ones.  Both give the same hits. */
static int nearest(const KERNEL_T *k, int simd, const KERNEL_EYE_T *eye,
                   const ray *r, REAL t_max, int skip, hit *h,
                   uint64_t *tests)
{
#if HAVE_AVX2_KERNEL
    if (simd && eye != NULL && skip < 0 &&
        memcmp(&eye->origin, &r->origin, sizeof eye->origin) == 0)
        return nearest_eye_avx2(k, eye->blocks, r, t_max, h, tests);
    if (simd)
        return nearest_avx2(k, r, t_max, skip, h, tests);
#else
    (void)simd;
    (void)eye;
#endif
    return nearest_scalar(k, r, t_max, skip, h, tests);
}

static int any_hit(const KERNEL_T *k, int simd, const ray *r, REAL t_max,
                   int skip, uint64_t *tests, uint64_t *saved)
{
#if HAVE_AVX2_KERNEL
    if (simd)
        return any_hit_avx2(k, r, t_max, skip, tests, saved);
#else
    (void)simd;
#endif
    return any_hit_scalar(k, r, t_max, skip, tests, saved);
}


/*
 * The hit point and its rounding-error bound per component.  Normally the
 * point is the barycentric combination of the vertices (pbrt-v4's choice:
 * whatever the weights' errors, it lies on the facet's plane to within the
 * bound).  On a sliver the weights themselves are inaccurate - the point
 * may slide along the facet by a large fraction of it - so when that error
 * exceeds the error of intersecting the ray with the facet's plane (whose
 * normal is accurate for any shape, see scene.c), the plane's point is
 * used instead.  `direction` is the ray's, in the units of t.
 */
static vec hit_point(const tri *f, const hit *h, vec origin, vec direction,
                     vec *error_bound)
{
    vec pa = scale(f->a, h->b0), pb = scale(f->b, h->b1),
        pc = scale(f->c, h->b2);
    *error_bound = scale(add(vabs(pa), add(vabs(pb), vabs(pc))),
                         gamma_bound(7));
    vec point = add(pa, add(pb, pc));
    if (!(h->point_error > 0))
        return point;
    vec to_facet = sub(f->a, origin);
    REAL along = dot(f->normal, to_facet), across = dot(f->normal, direction);
    REAL t = along / across;
    REAL condition = dot(vabs(f->normal), vabs(to_facet)) / fabs(along) +
                     dot(vabs(f->normal), vabs(direction)) / fabs(across);
    REAL t_error = fabs(t) * gamma_bound(8) * condition;
    REAL length = max3(direction.x, direction.y, direction.z);
    if (!(t > 0 && isfinite(t_error) && t_error * length < h->point_error))
        return point;
    vec step = scale(direction, t);
    *error_bound = add(scale(add(vabs(origin), vabs(step)), gamma_bound(2)),
                       scale(vabs(direction), t_error));
    return add(origin, step);
}

static REAL step_away(REAL x, REAL direction)
{
    if (direction > 0)
        return nextafter(x, (REAL)INFINITY);
    if (direction < 0)
        return nextafter(x, -(REAL)INFINITY);
    return x;
}

/* The origin of a ray leaving `point` towards `direction`: beyond the
 * point's error bound along the normal, rounded away from the surface. */
static vec offset_origin(vec point, vec error_bound, vec normal,
                         vec direction)
{
    vec offset = scale(normal, dot(vabs(normal), error_bound));
    if (dot(direction, normal) < 0)
        offset = neg(offset);
    vec p = add(point, offset);
    return mk(step_away(p.x, offset.x), step_away(p.y, offset.y),
              step_away(p.z, offset.z));
}

/* Adds E (N.S) (1 - k) C_S C_F / 255, weighted, to color. */
static void add_direct_light(const KERNEL_T *k, const tri *f, int index,
                             vec point, vec error_bound, vec normal,
                             REAL weight, int fast, int simd,
                             REAL color[3], rt_counters *counters)
{
    vec to_light = sub(k->light, point);
    if (f->k == 1 || !(dot(normal, to_light) > 0)) {
        counters->shadow_rays_skipped++;
        return;
    }
    vec origin = offset_origin(point, error_bound, normal, to_light);
    ray shadow = prepare(origin, sub(k->light, origin));
    counters->shadow_rays++;
    if (any_hit(k, simd, &shadow, 1, index, &counters->tests,
                &counters->early_exit_saved))
        return;
    REAL w = weight * dot(normal, normalize(to_light, fast));
    for (int c = 0; c < 3; c++)
        color[c] += w * f->diffuse[c];
}

/*
 * SPEC.md section 3, with the recursion on C_R unrolled: the colour is the
 * sum over bounces of each hit's own term times the product of the k met
 * before it, so any depth runs in constant stack.  Work that cannot change
 * the result is left out: no shadow ray where N.S <= 0 or k = 1, no
 * reflected ray from a facet with k = 0.
 */
rt_color KERNEL(trace)(const KERNEL_T *k, rt_vec3 origin_d,
                       rt_vec3 direction_d, const rt_trace_settings *settings,
                       rt_counters *counters)
{
    REAL color[3] = {0, 0, 0};
    REAL weight = 1;
    int skip = -1, fast = settings->fast_inv_sqrt;
    int simd = k->avx2 && settings->kernel != RT_KERNEL_SCALAR;
    vec origin = from_rt(origin_d);
    vec incoming = normalize(from_rt(direction_d), fast);
    for (int bounce = 0;; bounce++) {
        ray r = prepare(origin, incoming);
        hit h;
        if (!nearest(k, simd, bounce == 0 ? settings->eye : NULL, &r,
                     INFINITY, skip, &h, &counters->tests)) {
            for (int c = 0; c < 3; c++)
                color[c] += weight * k->background[c];
            break;
        }
        const tri *f = &k->tris[h.index];
        vec error_bound;
        vec point = hit_point(f, &h, origin, incoming, &error_bound);
        vec normal = dot(f->normal, incoming) > 0 ? neg(f->normal) : f->normal;
        add_direct_light(k, f, h.index, point, error_bound, normal, weight,
                         fast, simd, color, counters);
        if (f->k == 0) {
            counters->reflection_rays_skipped += bounce < settings->max_depth;
            break;
        }
        if (bounce >= settings->max_depth)
            break;          /* a reflection past the limit is black */
        weight *= f->k;
        vec reflected = sub(incoming, scale(normal, 2 * dot(incoming, normal)));
        origin = offset_origin(point, error_bound, normal, reflected);
        incoming = normalize(reflected, fast);
        skip = h.index;
        counters->reflection_rays++;
    }
    return (rt_color){color[0], color[1], color[2]};
}

KERNEL_T *KERNEL(create)(const rt_kernel_source *s)
{
    KERNEL_T *k = calloc(1, sizeof *k);
    if (k == NULL)
        return NULL;
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
    k->light = from_rt(s->light_position);
    REAL light[3] = {s->light_color.r, s->light_color.g, s->light_color.b};
    k->background[0] = s->background.r;
    k->background[1] = s->background.g;
    k->background[2] = s->background.b;
    for (int i = 0; i < s->facet_count; i++) {
        const rt_facet_info *info = &s->facets[i];
        if (info->degenerate)
            continue;       /* never hit: not even stored */
        tri *f = &k->tris[k->count++];
        f->a = from_rt(s->vertices[info->vertex[0]]);
        f->b = from_rt(s->vertices[info->vertex[1]]);
        f->c = from_rt(s->vertices[info->vertex[2]]);
        f->normal = from_rt(info->normal);
        f->k = (REAL)info->k;
        REAL color[3] = {info->color.r, info->color.g, info->color.b};
        for (int c = 0; c < 3; c++)
            f->diffuse[c] = (1 - f->k) * light[c] * color[c] / 255;
        f->facet = i;
    }
    k->block_count = (k->count + BLOCK_LANES - 1) / BLOCK_LANES;
    fill_blocks(k->blocks, k->tris, k->count, mk(0, 0, 0));
    k->avx2 = cpu_has_avx2();
    return k;
}

void KERNEL(free)(KERNEL_T *k)
{
    if (k != NULL) {
        free(k->tris);
        free(k->blocks);
    }
    free(k);
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
    return eye;
}

void KERNEL(eye_free)(KERNEL_EYE_T *eye)
{
    if (eye != NULL)
        free(eye->blocks);
    free(eye);
}

int KERNEL(live_count)(const KERNEL_T *k)
{
    return k->count;
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
    uint64_t tests = 0;
    if (!nearest(k, k->avx2, NULL, &r, (REAL)t_max, -1, &h, &tests))
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
    uint64_t tests = 0, saved = 0;
    return any_hit(k, k->avx2, &r, 1, skip, &tests, &saved);
}
