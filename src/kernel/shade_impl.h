/*
 * shade_impl.h - what happens where a ray ends: the hit point and its
 * error bound, the offset origin of the rays it sends on, the direct light
 * and, for a ray that meets nothing, the background - the steps both
 * trace loops of trace_impl.h share, in shade_hit() (part of
 * kernel_impl.h, compiled once per precision; everything here is static).
 *
 * Secondary rays: the hit point is computed from barycentric weights with
 * its rounding-error bound, and the new ray starts just beyond that bound
 * along the normal (Pharr, Jakob, Humphreys, "Physically Based Rendering",
 * 4th ed., section 6.8.6).  The offset scales with the coordinates, so it
 * works for scenes at 1e-6 as at 1e6; the facet a ray leaves is also
 * skipped, which is exact (a flat facet cannot be met twice).
 */

/* The steps of every hit, inlined into both traces (the opaque one is the
 * hot loop of every handout scene). */
#if defined(__GNUC__)
#define HOT_INLINE static inline __attribute__((always_inline))
#else
#define HOT_INLINE static inline
#endif

/*
 * The hit point and its rounding-error bound per component: the
 * barycentric combination of the vertices (pbrt-v4's choice: whatever the
 * weights' errors, it lies on the facet's plane to within the bound), or,
 * when the error of the weights along the facet (the hit's point_error)
 * exceeds the error of intersecting the ray with the facet's plane (whose
 * normal is accurate for any shape, see scene.c), the plane's point.  The
 * weights' bound is a worst case, so the plane's point is the one taken
 * on almost every hit (over 99 % on the handout's scenes); on a sliver it
 * keeps the point from sliding along the facet.  `direction` is the ray's,
 * in the units of t.
 */
static inline vec hit_point(const vec *vertices, const tri *f,
                            const hit *h, vec origin, vec direction,
                            vec *error_bound)
{
    if (h->point_error < 0) {
        /* A crossing (intersect_impl.h): t is accurate, the point the
         * ray's. */
        vec step = scale(direction, h->t);
        *error_bound = add(scale(add(vabs(origin), vabs(step)),
                                 gamma_bound(2)),
                           scale(vabs(direction), h->t_error));
        return add(origin, step);
    }
    if (h->point_error > 0) {
        /* The plane's point first: on most facets it is the one taken,
         * and then the barycentric one need not be computed. */
        vec to_facet = sub(*corner(vertices, f, 0), origin);
        REAL along = dot(f->normal, to_facet),
             across = dot(f->normal, direction);
        REAL t = along / across;
        REAL condition =
            dot(vabs(f->normal), vabs(to_facet)) / fabs(along) +
            dot(vabs(f->normal), vabs(direction)) / fabs(across);
        REAL t_error = fabs(t) * gamma_bound(8) * condition;
        REAL length = max3(direction.x, direction.y, direction.z);
        if (t > 0 && isfinite(t_error) && t_error * length < h->point_error) {
            vec step = scale(direction, t);
            *error_bound = add(scale(add(vabs(origin), vabs(step)),
                                     gamma_bound(2)),
                               scale(vabs(direction), t_error));
            return add(origin, step);
        }
    }
    vec pa = scale(*corner(vertices, f, 0), h->b0),
        pb = scale(*corner(vertices, f, 1), h->b1),
        pc = scale(*corner(vertices, f, 2), h->b2);
    *error_bound = scale(add(vabs(pa), add(vabs(pb), vabs(pc))),
                         gamma_bound(7));
    return add(pa, add(pb, pc));
}


/* The origin of a ray leaving `point` towards `direction`: beyond the
 * point's error bound along the normal, rounded away from the surface. */
HOT_INLINE vec offset_origin(vec point, vec error_bound, vec normal,
                         vec direction)
{
    vec offset = scale(normal, dot(vabs(normal), error_bound));
    if (dot(direction, normal) < 0)
        offset = neg(offset);
    vec p = add(point, offset);
    return mk(step_away(p.x, offset.x), step_away(p.y, offset.y),
              step_away(p.z, offset.z));
}

/* The shadow ray from `point` (its error bound, its normal facing the
 * ray that hit it) to the light at `light`, to_light = light - point:
 * from the offset origin, with the light at t = 1. */
HOT_INLINE ray shadow_ray(vec point, vec error_bound, vec normal, vec light,
                          vec to_light)
{
    vec origin = offset_origin(point, error_bound, normal, to_light);
    return prepare_leaving(origin, sub(light, origin), error_bound);
}

/* The terms d C_S,l C_F / 255 of facet f's material for light `l`. */
static const REAL *diffuse_of(const KERNEL_T *k, const tri *f, int l)
{
    if (l == 0)
        return k->materials[f->material].diffuse;
    return &k->more_diffuse[((size_t)f->material *
                                 (size_t)(k->light_count - 1) +
                             (size_t)(l - 1)) * 3];
}

/*
 * any_hit() of the shadow ray r to light l, which leaves facet `skip`,
 * through the thread's last-blocker cache: the facet that blocked the last
 * shadow ray to l, if it was blocked, is tested first, by the test every
 * query makes of a facet (intersect() and blocks()), and when it blocks r
 * the answer is yes without a query.  Exact: a facet but `skip` that
 * blocks r is a blocker the query would find too, as any_hit() answers
 * whether there is one (which one it meets first does not matter).  A ray
 * that nothing blocks empties the entry, so a lit region costs no test
 * but at its edge (docs/kdtree.md, "The last-blocker cache", measured).
 */
HOT_INLINE int shadow_blocked(const trace_ctx *c, const ray *r, int l,
                              int skip)
{
    int32_t *last = &c->counters->last_blocker[l];
    int cached = *last - 1;
    /* any facet of this kernel is a valid first try, even one cached by
     * another kernel's trace with the same counters: in range suffices */
    if (cached >= 0 && cached < c->k->count && cached != skip) {
        hit ignored;
        c->counters->ray_facet_tests++;
        if (intersect(r, c->k->vertices, &c->k->tris[cached], 1,
                      &ignored) &&
            blocks(&ignored, 1)) {
            if (c->kd == NULL && c->tree == NULL)   /* as brute force */
                c->counters->early_exit_saved +=
                    (uint64_t)c->k->count - (skip >= 0) - 1;
            return 1;
        }
    }
    int blocker = -1;
    int blocked = any_hit(c, r, 1, skip, &blocker);
    *last = blocked ? blocker + 1 : 0;
    return blocked;
}

/* Lights whose shadow rays a caller may have answered before the trace
 * (known_hit.blocked); beyond, the trace casts them itself. */
#define KNOWN_LIGHTS 8

/* What a caller found already of a camera ray's first hit (the packets of
 * packet_impl.h): the nearest hit (*h, when found), its point, error bound
 * and normal as shade_hit() computes them, and for each light l whether
 * the shadow ray was blocked (1) or not (0); -1 leaves that ray to the
 * trace. */
typedef struct known_hit {
    int found;
    const hit *h;
    vec point, error_bound, normal;
    signed char blocked[KNOWN_LIGHTS];
} known_hit;

/* Where a ray met a facet, as the rays it sends on leave it. */
typedef struct surface {
    const tri *f;
    const material *m;      /* f's */
    int index;              /* of f in the kernel's tris */
    vec point, error_bound; /* the hit point and its rounding-error bound */
    vec normal;             /* unit, facing the ray that met it: N_g */
    int smooth;             /* f has vertex normals: the three below are
                               set (all four are set only where the
                               trace's context has `shading`; normal_s()
                               gives N_s in every case) */
    vec shading;            /* N_s, on the side of `normal` */
    vec shading_point;      /* P', where its shadow rays leave */
    vec shading_bound;      /* the rounding-error bound of P' */
    vec incoming;           /* the unit direction of the ray that met it
                               (set where the trace's context has
                               `shading`) */
} surface;

/* N_s of s: its own on a smooth facet, else N_g (a context without
 * `shading` has no smooth facet: N_g, with no test). */
static inline vec normal_s(const trace_ctx *c, const surface *s)
{
    return c->shading && s->smooth ? s->shading : s->normal;
}

/*
 * The shading normal of a smooth facet (docs/rendering-model.md, "Smooth
 * shading"): the vertex normals weighted by the hit's barycentric weights,
 * normalised and turned to the side of N_g = `normal`; N_g itself where
 * the sum is zero or not finite.
 */
static vec shading_normal(const KERNEL_T *k, const tri *f, const hit *h,
                          vec normal, int fast)
{
    const vec *n = k->vertex_normals;
    vec sum = add(scale(n[f->v[0]], h->b0),
                  add(scale(n[f->v[1]], h->b1), scale(n[f->v[2]], h->b2)));
    REAL m = max3(sum.x, sum.y, sum.z);
    if (!(m > 0) || !isfinite(m))
        return normal;
    vec unit = normalize(sum, fast);
    return dot(unit, normal) < 0 ? neg(unit) : unit;
}

/*
 * The shading point P' of Hanika's "Hacking the shadow terminator" (Ray
 * Tracing Gems II, ch. 4, 2021) for the hit `point` of a smooth facet: for
 * each corner v_i with normal n_i, the part of P - v_i below the tangent
 * plane of v_i, d_i = min(0, (P - v_i).n_i), is taken off; P' = P -
 * sum_i b_i d_i n_i, on the curved surface the normals describe (the
 * terms with (P - v_i) of the paper's form cancel, as the weights sum to
 * 1).  *bound is P's bound doubled (its error passes through the dot
 * products once) plus the rounding of the terms and of the sum.
 */
static vec shading_point(const KERNEL_T *k, const tri *f, const hit *h,
                         vec point, vec error_bound, vec *bound)
{
    REAL b[3] = {h->b0, h->b1, h->b2};
    vec moved = mk(0, 0, 0), moved_error = mk(0, 0, 0);
    for (int j = 0; j < 3; j++) {
        const vec *v = corner(k->vertices, f, j);
        vec n = k->vertex_normals[f->v[j]];
        REAL along = dot(sub(point, *v), n);
        if (!(along < 0))
            continue;
        moved = sub(moved, scale(n, b[j] * along));
        REAL size = dot(add(vabs(point), vabs(*v)), vabs(n));
        moved_error = add(moved_error,
                          scale(vabs(n), fabs(b[j]) * size * gamma_bound(8)));
    }
    vec p = add(point, moved);
    *bound = add(scale(error_bound, 2),
                 add(moved_error, scale(add(vabs(p), vabs(moved)),
                                        gamma_bound(2))));
    return p;
}

/* The mirror direction R = I - 2 (I.N_s) N_s of s (unnormalised), or
 * with N_g where N_s gives one below the facet. */
static inline vec mirror_direction(const trace_ctx *c, const surface *s,
                                   vec incoming)
{
    vec n = normal_s(c, s);
    vec r = sub(incoming, scale(n, 2 * dot(incoming, n)));
    if (c->shading && s->smooth && !(dot(r, s->normal) > 0))
        r = sub(incoming, scale(s->normal, 2 * dot(incoming, s->normal)));
    return r;
}

/* The highlight of light l at s: max(0, R_l.V)^p, R_l = 2 (N_s.S) N_s -
 * S, V = -I (Phong; Whitted 1980), S the unit direction to the light;
 * *r_dot_v gets R_l.V. */
static inline REAL highlight_of(const trace_ctx *c, const surface *s,
                                vec unit_to_light, REAL *r_dot_v)
{
    vec n = normal_s(c, s);
    REAL ns = dot(n, unit_to_light);
    vec r = sub(scale(n, 2 * ns), unit_to_light);
    REAL rv = -dot(r, s->incoming);
    *r_dot_v = rv;
    if (!(rv > 0))
        return 0;
    return (REAL)pow((double)rv, (double)s->m->p);
}

/* Tells the recorder about the shadow ray to light l of the hit recorded
 * as `node` (not on the renders' path: only when a recorder is set):
 * `shadow` is the ray cast (NULL: none, N.S <= 0 or d = 0) and `blocked`
 * its answer; when it was blocked, the blocker is the nearest facet on
 * it. */
static void record_light(trace_ctx c, const surface *s, int node, int l,
                         vec to_light, const ray *shadow, int blocked,
                         rt_color own, double r_dot_v, rt_color highlight)
{
    const KERNEL_T *k = c.k;
    int blocker = -1;
    if (shadow != NULL && blocked) {
        hit h;
        rt_counters scratch = {0};
        c.counters = &scratch;      /* the search is not the render's work */
        if (nearest(&c, NULL, shadow, 1, s->index, &h))
            blocker = k->tris[h.index].facet;
    }
    vec origin = shadow != NULL ? shadow->origin : s->point;
    vec direction = shadow != NULL ? sub(k->lights[l], origin) : to_light;
    rt_vec3 from = shadow != NULL ? to_rt(origin)
                                  : to_rt(sub(k->lights[l], to_light));
    c.rec->on_shadow(c.rec->state, node, l, from, to_rt(direction),
                     (double)dot(normal_s(&c, s), normalize(to_light, c.fast)),
                     shadow != NULL, blocked, blocker, own, r_dot_v,
                     highlight);
}

/* Adds the direct light, weighted, to color: for each light l,
 * E_l (N.S_l) d C_S,l C_F / 255.  No shadow ray where it cannot matter:
 * d = 0 (k = 1 on a handout facet) or N.S_l <= 0.  With a recorder (NULL
 * in renders, where this code vanishes) each light is recorded under
 * `node`.  given[l], when given, l < KNOWN_LIGHTS and given[l] >= 0, is
 * the answer of the shadow ray to light l, found already. */
HOT_INLINE void add_direct_light(const trace_ctx *c, const surface *s,
                                 REAL weight, int node,
                                 const signed char *given, REAL color[3])
{
    const KERNEL_T *k = c->k;
    const tri *f = s->f;
    /* k = 1 on a handout facet: d = 0, and no highlight */
    int dark = s->m->d == 0 && (!c->shading || s->m->s == 0);
    const rt_color none = {0, 0, 0};
    for (int l = 0; l < k->light_count; l++) {
        vec light = k->lights[l];
        vec to_light = sub(light, s->point);
        if (dark || !(dot(normal_s(c, s), to_light) > 0)) {
            c->counters->shadow_rays_skipped++;
            if (c->rec != NULL)
                record_light(*c, s, node, l, to_light, NULL, 0, none, 0,
                             none);
            continue;
        }
        c->counters->shadow_rays++;
        ray shadow;
        int blocked;
        if (given != NULL && l < KNOWN_LIGHTS && given[l] >= 0 &&
            c->rec == NULL) {
            blocked = given[l];
        } else {
            if (c->shading && s->smooth)   /* from P': the terminator */
                shadow = shadow_ray(s->shading_point, s->shading_bound,
                                    s->normal, light,
                                    sub(light, s->shading_point));
            else
                shadow = shadow_ray(s->point, s->error_bound, s->normal,
                                    light, to_light);
            blocked = shadow_blocked(c, &shadow, l, s->index);
        }
        if (blocked) {
            if (c->rec != NULL)
                record_light(*c, s, node, l, to_light, &shadow, 1, none, 0,
                             none);
            continue;
        }
        vec unit = normalize(to_light, c->fast);
        REAL w = weight * dot(normal_s(c, s), unit);
        const REAL *diffuse = diffuse_of(k, f, l);
        for (int ch = 0; ch < 3; ch++)
            color[ch] += w * diffuse[ch];
        REAL r_dot_v = 0, spot[3] = {0, 0, 0};
        if (c->shading && s->m->s > 0) {
            REAL h = weight * s->m->s * highlight_of(c, s, unit, &r_dot_v);
            vec cs = k->light_colors[l];
            spot[0] = h * cs.x;
            spot[1] = h * cs.y;
            spot[2] = h * cs.z;
            for (int ch = 0; ch < 3; ch++)
                color[ch] += spot[ch];
        }
        if (c->rec != NULL)
            record_light(*c, s, node, l, to_light, &shadow, 0,
                         (rt_color){w * diffuse[0] + spot[0],
                                    w * diffuse[1] + spot[1],
                                    w * diffuse[2] + spot[2]},
                         (double)r_dot_v,
                         (rt_color){spot[0], spot[1], spot[2]});
    }
}

/*
 * The steps every ray takes where it ends, in both trace loops.  The ray
 * leaves `origin` along `incoming` with `weight`, recorded as `node`.
 * When it met nothing (found 0), its term is the background; when it met
 * *h, *s is filled - the hit point, its error bound and the normal facing
 * the ray, or those of `known` (may be NULL) - and recorded, and its term
 * is the direct light there.  Adds the term, weighted, to color; returns
 * found.
 */
HOT_INLINE int shade_hit(const trace_ctx *c, int found, const hit *h,
                         vec origin, vec incoming, REAL weight, int node,
                         const known_hit *known, REAL color[3], surface *s)
{
    const KERNEL_T *k = c->k;
    if (!found) {
        for (int ch = 0; ch < 3; ch++)
            color[ch] += weight * k->background[ch];
        if (c->rec != NULL)
            c->rec->on_miss(c->rec->state, node,
                            (rt_color){weight * k->background[0],
                                       weight * k->background[1],
                                       weight * k->background[2]});
        return 0;
    }
    s->f = &k->tris[h->index];
    s->m = &k->materials[s->f->material];
    s->index = h->index;
    if (known != NULL) {
        s->point = known->point;
        s->error_bound = known->error_bound;
        s->normal = known->normal;
    } else {
        s->point = hit_point(k->vertices, s->f, h, origin, incoming,
                             &s->error_bound);
        s->normal = dot(s->f->normal, incoming) > 0 ? neg(s->f->normal)
                                                    : s->f->normal;
    }
    if (c->shading) {
        s->incoming = incoming;
        s->smooth = k->smooth != NULL && k->smooth[h->index];
        if (s->smooth) {
            s->shading = shading_normal(k, s->f, h, s->normal, c->fast);
            s->shading_point =
                shading_point(k, s->f, h, s->point, s->error_bound,
                              &s->shading_bound);
        }
    }
    if (c->rec != NULL)
        c->rec->on_hit(c->rec->state, node, s->f->facet, (double)h->t,
                       to_rt(s->point), to_rt(s->normal),
                       c->shading && s->smooth, to_rt(normal_s(c, s)),
                       to_rt(c->shading && s->smooth ? s->shading_point
                                                     : s->point));
    add_direct_light(c, s, weight, node, known != NULL ? known->blocked : NULL,
                     color);
    return 1;
}
