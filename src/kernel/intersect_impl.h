/*
 * intersect_impl.h - the watertight ray-facet test and the tie rule between
 * two hits, nothing else (part of kernel_impl.h, compiled once per
 * precision; everything here is static).
 *
 * Intersection: Woop, Benthin and Wald, "Watertight Ray/Triangle
 * Intersection", JCGT 2(1), 2013.  The ray is mapped onto +z by an axis
 * permutation and a shear; the facet is then tested in 2D by three edge
 * functions.  An edge shared by two facets gets bit-for-bit equal or
 * opposite edge functions in both (the library is built with
 * -ffp-contract=off so products round as written), and an edge function
 * that rounds to zero is recomputed with its exact sign, so no ray can pass
 * between two facets that share an edge.
 */

/* The test is inlined into each loop that calls it (the brute-force loops
 * of a handful of facets call it for most rays). */
#if defined(__GNUC__)
#define INTERSECT_INLINE __attribute__((always_inline))
#else
#define INTERSECT_INLINE
#endif

/* A ray prepared for the watertight test. */
typedef struct ray {
    vec origin;
    vec direction;
    int kx, ky, kz;
    REAL sx, sy, sz;
    vec origin_bound;       /* zero for an origin given exactly (the eye);
                               for a ray leaving a hit, the error bound of
                               that hit point (shade_impl.h), which the
                               offset origin inherits */
} ray;

static ray prepare(vec origin, vec direction)
{
    ray r;
    r.origin = origin;
    r.origin_bound = mk(0, 0, 0);
    r.direction = direction;
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

/* A ray from the offset origin of a hit point whose error bound is
 * `point_bound` (offset_origin in shade_impl.h). */
static inline ray prepare_leaving(vec origin, vec direction, vec point_bound)
{
    ray r = prepare(origin, direction);
    r.origin_bound = point_bound;
    return r;
}

/* x*w - y*z with the exact sign, for when it rounds to zero in REAL. */
static REAL edge_exact(REAL x, REAL w, REAL y, REAL z)
{
    if (sizeof(REAL) == sizeof(float))  /* float products are exact in double */
        return (REAL)((double)x * (double)w - (double)y * (double)z);
    /* Kahan's difference of products: error below 2 ulps, so the sign is
     * exact. */
    double yz = (double)y * (double)z;
    double err = fma(-(double)y, (double)z, yz);
    return (REAL)(fma((double)x, (double)w, -yz) + err);
}

/* A rounded edge function e = x*w - y*z as computed, made exact in sign
 * when it rounded to zero. */
static inline REAL edge_signed(REAL e, REAL x, REAL w, REAL y, REAL z)
{
    return e != 0 ? e : edge_exact(x, w, y, z);
}

/*
 * A facet in a ray's sheared frame: its vertices minus the ray's origin,
 * sheared (x, y) and on the kz axis before scaling (z), and the rounded
 * edge functions u, v, w - the values the filter of simd_impl.h computes
 * too, operation for operation, so it can hand them over.
 */
typedef struct sheared {
    REAL ax, ay, bx, by, cx, cy;
    REAL az, bz, cz;
    REAL u, v, w;
} sheared;

typedef struct hit {
    REAL t;
    REAL t_error;           /* bound on the rounding error of t */
    REAL point_error;       /* estimate of the error of the point the
                               barycentric weights give, along the facet;
                               negative for a crossing (below): the hit
                               point is then the ray's at t */
    REAL b0, b1, b2;        /* barycentric weights of a, b, c */
    int index;              /* into the kernel's tris */
} hit;

/*
 * A hit whose t the watertight test cannot tell from 0 - the facet far
 * larger than the ray's distance to its plane, so that t's sum of
 * barycentric terms cancels (a ground of half-size 1e6 seen from 1.7
 * above) - decided instead by where the ray's line crosses the facet's
 * plane, computed to about 30 digits with a rigorous bound
 * (plane_crossing.c): a hit when that t provably exceeds 0 and lies
 * below t_max.  Not inlined: it is met on a tiny fraction of tests.
 */
#if defined(__GNUC__)
__attribute__((noinline, cold))
#endif
static int crossing(const vec *vertices, const tri *f, const ray *r,
                    REAL t_max, hit *h)
{
    const vec *pa = corner(vertices, f, 0), *pb = corner(vertices, f, 1),
              *pc = corner(vertices, f, 2);
    double a[3] = {pa->x, pa->y, pa->z}, b[3] = {pb->x, pb->y, pb->z},
           c[3] = {pc->x, pc->y, pc->z};
    double o[3] = {r->origin.x, r->origin.y, r->origin.z},
           d[3] = {r->direction.x, r->direction.y, r->direction.z};
    /* How far the origin may lie from the point the ray really leaves:
     * the hit point's bound, the offset (at most sqrt(3) times as much
     * per component) and the two roundings of adding it; a facet whose
     * plane passes within that distance is the ray's own surface or a
     * neighbour through the same point, never a hit. */
    double origin_error =
        2 * (2.8 * (double)max3(r->origin_bound.x, r->origin_bound.y,
                                r->origin_bound.z) +
             2 * REAL_EPS * (double)max3(r->origin.x, r->origin.y,
                                         r->origin.z));
    double t, error;
    if (!rt__plane_crossing(a, b, c, o, d, origin_error, &t, &error))
        return 0;
    REAL t_real = (REAL)t;
    /* |exact - t_real| <= error + |t - t_real|, rounded up into REAL */
    double bound = (error + fabs(t - (double)t_real)) * (1 + 4 * REAL_EPS);
    REAL t_error = (REAL)bound;
    if (!(t_real > t_error && t_real < t_max))
        return 0;
    h->t = t_real;
    h->t_error = t_error;
    h->point_error = -1;
    return 1;
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
 * The fast loops (simd_impl.h) repeat the computation of the sheared
 * vertices and the edge functions u, v, w of intersect(), operation for
 * operation, skip the facets where two of them have strictly opposite
 * signs and hand the values of the others to intersect_sheared(): keep
 * both in step, and keep that rejection the first thing this test does
 * with u, v, w.
 */
static inline INTERSECT_INLINE int intersect_sheared(const sheared *s,
                                                     const vec *vertices,
                                                     const tri *f,
                                                     const ray *r,
                                                     REAL t_max, hit *h)
{
    REAL ax = s->ax, ay = s->ay, bx = s->bx, by = s->by, cx = s->cx,
         cy = s->cy, az = s->az, bz = s->bz, cz = s->cz;
    REAL u = edge_signed(s->u, cx, by, cy, bx);
    REAL v = edge_signed(s->v, ax, cy, ay, cx);
    REAL w = edge_signed(s->w, bx, ay, by, ax);
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
    if (!(t < t_max))
        return 0;   /* beyond the nearest so far (or NaN) */
    if (!(t > 0) && !(az > 0 || bz > 0 || cz > 0))
        return 0;   /* the facet wholly behind the origin (the signs of
                       the scaled z are exact): the common case */

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
    if (!(t > t_error)) {
        /* t cannot be told from 0: provably behind the origin (or NaN),
         * or decided by the crossing of the facet's plane */
        if (!(t >= -t_error) || !crossing(vertices, f, r, t_max, h))
            return 0;
    } else {
        h->t = t;
        h->t_error = t_error;
        h->point_error = edge_error * (max_x + max_y);
    }
    h->b0 = b0;
    h->b1 = b1;
    h->b2 = b2;
    return 1;
}

static inline INTERSECT_INLINE int intersect(const ray *r,
                                             const vec *vertices,
                                             const tri *f, REAL t_max,
                                             hit *h)
{
    vec a = sub(*corner(vertices, f, 0), r->origin),
        b = sub(*corner(vertices, f, 1), r->origin),
        c = sub(*corner(vertices, f, 2), r->origin);
    sheared s;
    s.az = get(a, r->kz);
    s.bz = get(b, r->kz);
    s.cz = get(c, r->kz);
    s.ax = get(a, r->kx) - r->sx * s.az;
    s.ay = get(a, r->ky) - r->sy * s.az;
    s.bx = get(b, r->kx) - r->sx * s.bz;
    s.by = get(b, r->ky) - r->sy * s.bz;
    s.cx = get(c, r->kx) - r->sx * s.cz;
    s.cy = get(c, r->ky) - r->sy * s.cz;
    s.u = s.cx * s.by - s.cy * s.bx;
    s.v = s.ax * s.cy - s.ay * s.cx;
    s.w = s.bx * s.ay - s.by * s.ax;
    return intersect_sheared(&s, vertices, f, r, t_max, h);
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

/*
 * The step of every nearest-hit loop: facet `i`'s hit `c` becomes the
 * nearest so far (*h, with *t_max its distance and *found set) unless one
 * is kept that replaces() says stays.
 */
static inline void keep_nearer(const KERNEL_T *k, int i, hit *c, hit *h,
                               REAL *t_max, int *found)
{
    c->index = i;
    if (*found && !replaces(k, h, c))
        return;
    *h = *c;
    *t_max = c->t;
    *found = 1;
}


/* Non-zero when a hit of a shadow ray towards a light at t = t_max blocks
 * it: the facet is provably before the light. */
static int blocks(const hit *h, REAL t_max)
{
    return h->t + h->t_error < t_max;
}

