/*
 * shade_impl.h - what happens at a hit: the hit point and its error bound,
 * the offset origin of secondary rays, the direct light and the reflections
 * of docs/rendering-model.md (part of kernel_impl.h, compiled once per
 * precision; everything here but KERNEL(trace) is static).
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
static inline vec hit_point(const tri *f, const hit *h, vec origin, vec direction,
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
        vec to_facet = sub(f->a, origin);
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
    vec pa = scale(f->a, h->b0), pb = scale(f->b, h->b1),
        pc = scale(f->c, h->b2);
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

/* Lights whose shadow rays a packet casts together (more: one by one). */
#define PACKET_MAX_LIGHTS 8

/* The shadow ray from `point` (its error bound, its normal facing the
 * ray that hit it) to the light at `light`, to_light = light - point:
 * from the offset origin, with the light at t = 1. */
HOT_INLINE ray shadow_ray(vec point, vec error_bound, vec normal, vec light,
                          vec to_light)
{
    vec origin = offset_origin(point, error_bound, normal, to_light);
    return prepare_leaving(origin, sub(light, origin), error_bound);
}

/* The terms d C_S,l C_F / 255 of facet `index` for light `l`. */
static const REAL *diffuse_of(const KERNEL_T *k, const tri *f, int index,
                              int l)
{
    if (l == 0)
        return f->diffuse;
    return &k->more_diffuse[((size_t)index * (size_t)(k->light_count - 1) +
                             (size_t)(l - 1)) * 3];
}

/* Tells the recorder about the shadow ray to light l of the hit recorded
 * as `node` (not on the renders' path: only when a recorder is set).  When
 * it was cast and blocked, the blocker is the nearest facet on it. */
static void record_light(const KERNEL_T *k, int simd, const octree *tree,
                         rt_trace_recorder *rec, int node, int l,
                         vec normal, vec to_light, int fast, const ray *shadow,
                         vec origin, int index, int cast, int blocked,
                         rt_color own)
{
    int blocker = -1;
    if (cast && blocked) {
        hit h;
        rt_counters scratch = {0};
        if (nearest(k, simd, tree, NULL, shadow, 1, index, &h, &scratch))
            blocker = k->tris[h.index].facet;
    }
    vec direction = cast ? sub(k->lights[l], origin) : to_light;
    rt_vec3 from = cast ? to_rt(origin) : to_rt(sub(k->lights[l], to_light));
    rt__record_shadow(rec, node, l, from, to_rt(direction),
                      (double)dot(normal, normalize(to_light, fast)), cast,
                      blocked, blocker, own);
}

/* Adds the direct light, weighted, to color: for each light l,
 * E_l (N.S_l) d C_S,l C_F / 255.  No shadow ray where it cannot matter:
 * d = 0 (k = 1 on a handout facet) or N.S_l <= 0.  With a recorder (NULL
 * in renders, where this code vanishes) each light is recorded under
 * `node`.  given[l], when given, l < PACKET_MAX_LIGHTS and given[l] >= 0,
 * is the answer of the shadow ray to light l, found already by a packet
 * (packet_impl.h). */
HOT_INLINE void add_direct_light(const KERNEL_T *k, const octree *tree,
                             const tri *f, int index, vec point,
                             vec error_bound, vec normal, REAL weight,
                             int fast, int simd, REAL color[3],
                             rt_counters *counters, rt_trace_recorder *rec,
                             int node, const signed char *given)
{
    int dark = f->d == 0;   /* k = 1 on a handout facet */
    const rt_color none = {0, 0, 0};
    for (int l = 0; l < k->light_count; l++) {
        vec light = k->lights[l];
        vec to_light = sub(light, point);
        if (dark || !(dot(normal, to_light) > 0)) {
            counters->shadow_rays_skipped++;
            if (rec != NULL)
                record_light(k, simd, tree, rec, node, l, normal, to_light,
                             fast, NULL, point, index, 0, 0, none);
            continue;
        }
        counters->shadow_rays++;
        ray shadow;
        int blocked;
        if (given != NULL && l < PACKET_MAX_LIGHTS && given[l] >= 0 &&
            rec == NULL) {
            blocked = given[l];
        } else {
            shadow = shadow_ray(point, error_bound, normal, light, to_light);
            blocked = any_hit(k, simd, tree, &shadow, 1, index, counters);
        }
        if (blocked) {
            if (rec != NULL)
                record_light(k, simd, tree, rec, node, l, normal, to_light,
                             fast, &shadow, shadow.origin, index, 1, 1,
                             none);
            continue;
        }
        REAL w = weight * dot(normal, normalize(to_light, fast));
        const REAL *diffuse = diffuse_of(k, f, index, l);
        for (int c = 0; c < 3; c++)
            color[c] += w * diffuse[c];
        if (rec != NULL)
            record_light(k, simd, tree, rec, node, l, normal, to_light, fast,
                         &shadow, shadow.origin, index, 1, 0,
                         (rt_color){w * diffuse[0], w * diffuse[1],
                                    w * diffuse[2]});
    }
}

/* What a packet of camera rays (packet_impl.h) found of one ray's first
 * bounce: the nearest hit (*h, when found), its point, error bound and
 * normal as trace_opaque() computes them, and for each light l whether the
 * shadow ray was blocked (1) or not (0); -1 leaves that ray to the
 * trace. */
typedef struct first_bounce {
    int found;
    const hit *h;
    vec point, error_bound, normal;
    signed char blocked[PACKET_MAX_LIGHTS];
} first_bounce;

/*
 * The opaque case (no facet with t > 0): the rendering model with the
 * recursion on C_R unrolled: the colour is the sum over bounces of each
 * hit's own term times the product of the k met before it, so any depth
 * runs in constant stack.  Work that cannot change the result is left out:
 * no shadow ray where N.S <= 0 or d = 0, no reflected ray from a facet with
 * k = 0.  `first` is NULL, or what a packet (packet_impl.h) found
 * already of the camera ray's first bounce.
 */
HOT_INLINE void trace_opaque(const KERNEL_T *k, vec origin, vec incoming,
                         const rt_trace_settings *settings, const octree *tree,
                         int simd, REAL color[3], rt_counters *counters,
                         rt_trace_recorder *rec, const first_bounce *first)
{
    REAL weight = 1;
    int skip = -1, fast = settings->fast_inv_sqrt, node = -1;
    vec origin_bound = mk(0, 0, 0);     /* of the point `origin` leaves */
    for (int bounce = 0;; bounce++) {
        if (rec != NULL)
            node = rt__record_ray(rec, bounce == 0 ? RT_RAY_CAMERA
                                                   : RT_RAY_REFLECTED,
                                  node, bounce, to_rt(origin),
                                  to_rt(incoming), (double)weight);
        hit h;
        int found;
        if (bounce == 0 && first != NULL) {
            found = first->found;
            if (found)
                h = *first->h;
        } else {
            ray r = prepare_leaving(origin, incoming, origin_bound);
            found = nearest(k, simd, tree, bounce == 0 ? settings->eye : NULL,
                            &r, INFINITY, skip, &h, counters);
        }
        if (!found) {
            for (int c = 0; c < 3; c++)
                color[c] += weight * k->background[c];
            if (rec != NULL)
                rt__record_miss(rec, node,
                                (rt_color){weight * k->background[0],
                                           weight * k->background[1],
                                           weight * k->background[2]});
            break;
        }
        const tri *f = &k->tris[h.index];
        vec error_bound, point, normal;
        if (bounce == 0 && first != NULL) {
            point = first->point;
            error_bound = first->error_bound;
            normal = first->normal;
        } else {
            point = hit_point(f, &h, origin, incoming, &error_bound);
            normal = dot(f->normal, incoming) > 0 ? neg(f->normal)
                                                  : f->normal;
        }
        if (rec != NULL)
            rt__record_hit(rec, node, f->facet, (double)h.t, to_rt(point),
                           to_rt(normal));
        add_direct_light(k, tree, f, h.index, point, error_bound, normal,
                         weight, fast, simd, color, counters, rec, node,
                         bounce == 0 && first != NULL ? first->blocked
                                                      : NULL);
        if (f->k == 0) {
            counters->reflection_rays_skipped += bounce < settings->max_depth;
            break;
        }
        if (bounce >= settings->max_depth)
            break;          /* a reflection past the limit is black */
        weight *= f->k;
        vec reflected = sub(incoming, scale(normal, 2 * dot(incoming, normal)));
        origin = offset_origin(point, error_bound, normal, reflected);
        origin_bound = error_bound;
        incoming = normalize(reflected, fast);
        skip = h.index;
        counters->reflection_rays++;
    }
}

/* A ray still to follow, with the weight its colour carries. */
typedef struct ray_task {
    vec origin, incoming;   /* incoming is unit */
    vec origin_bound;       /* the error bound of the point it leaves */
    REAL weight;
    int skip;               /* the facet it leaves, or -1 */
    int level;              /* 0 for the camera ray */
    int node;               /* its recorded node (-1: none) */
} ray_task;

/* Records a reflected or refracted ray about to be followed. */
static int record_task(rt_trace_recorder *rec, int kind, int parent,
                       const ray_task *task)
{
    return rt__record_ray(rec, kind, parent, task->level, to_rt(task->origin),
                          to_rt(task->incoming), (double)task->weight);
}

/* Rays a transparent trace keeps on its own stack; more go to the heap. */
#define RAY_TASKS_LOCAL 32

/*
 * The direction T of the ray refracted at a facet of winding normal n_w
 * and index n (Snell-Descartes, as the rendering model states it), or 0
 * for a total internal reflection.  `incoming` is unit.
 */
static int refract(vec incoming, vec n_w, REAL n, vec *out)
{
    int entering = dot(incoming, n_w) < 0;
    REAL eta = entering ? 1 / n : n;
    vec normal = entering ? n_w : neg(n_w);
    REAL c = -dot(incoming, normal);
    REAL q = 1 - eta * eta * (1 - c * c);
    if (q < 0)
        return 0;
    *out = add(scale(incoming, eta), scale(normal, eta * c - sqrt(q)));
    return 1;
}

/*
 * A scene with transparent facets: each hit may send a reflected ray
 * (k > 0) and a refracted one (t > 0), so the rays form a tree, walked
 * depth first with an explicit stack.  A total internal reflection sends
 * the mirror ray for both terms (weight k + t).  Returns 0 when the stack
 * cannot grow (out of memory); the colour is then incomplete.
 */
static int trace_transparent(const KERNEL_T *k, vec origin, vec incoming,
                             const rt_trace_settings *settings,
                             const octree *tree, int simd, REAL color[3],
                             rt_counters *counters, rt_trace_recorder *rec)
{
    ray_task local[RAY_TASKS_LOCAL], *stack = local;
    int used = 0, capacity = RAY_TASKS_LOCAL, fast = settings->fast_inv_sqrt;
    int camera = rec == NULL ? -1
                             : rt__record_ray(rec, RT_RAY_CAMERA, -1, 0,
                                              to_rt(origin), to_rt(incoming),
                                              1.0);
    stack[used++] = (ray_task){origin, incoming, mk(0, 0, 0), 1, -1, 0,
                               camera};
    int ok = 1;
    while (used > 0) {
        ray_task p = stack[--used];
        ray r = prepare_leaving(p.origin, p.incoming, p.origin_bound);
        hit h;
        if (!nearest(k, simd, tree, p.level == 0 ? settings->eye : NULL, &r,
                     INFINITY, p.skip, &h, counters)) {
            for (int c = 0; c < 3; c++)
                color[c] += p.weight * k->background[c];
            if (rec != NULL)
                rt__record_miss(rec, p.node,
                                (rt_color){p.weight * k->background[0],
                                           p.weight * k->background[1],
                                           p.weight * k->background[2]});
            continue;
        }
        const tri *f = &k->tris[h.index];
        vec error_bound;
        vec point = hit_point(f, &h, p.origin, p.incoming, &error_bound);
        vec normal = dot(f->normal, p.incoming) > 0 ? neg(f->normal)
                                                    : f->normal;
        if (rec != NULL)
            rt__record_hit(rec, p.node, f->facet, (double)h.t, to_rt(point),
                           to_rt(normal));
        add_direct_light(k, tree, f, h.index, point, error_bound, normal,
                         p.weight, fast, simd, color, counters, rec, p.node,
                         NULL);
        int deeper = p.level < settings->max_depth;
        if (f->k == 0)
            counters->reflection_rays_skipped += deeper;
        if (!deeper) {
            counters->refraction_rays_skipped += f->t > 0;
            continue;       /* past the limit: black */
        }
        vec mirror = sub(p.incoming, scale(normal, 2 * dot(p.incoming,
                                                           normal)));
        REAL mirror_weight = f->k;
        vec refracted = mk(0, 0, 0);   /* set when refracts */
        int refracts = f->t > 0 && refract(p.incoming, f->normal, f->n,
                                           &refracted);
        if (f->t > 0 && !refracts) {
            mirror_weight += f->t;  /* total internal reflection */
            counters->refraction_rays_skipped++;
        }
        if (used + 2 > capacity) {
            int bigger = capacity * 2;
            ray_task *grown = malloc((size_t)bigger * sizeof *grown);
            if (grown == NULL) {
                ok = 0;
                break;
            }
            memcpy(grown, stack, (size_t)used * sizeof *stack);
            if (stack != local)
                free(stack);
            stack = grown;
            capacity = bigger;
        }
        if (refracts) {
            ray_task task = {
                offset_origin(point, error_bound, normal, refracted),
                normalize(refracted, fast), error_bound, p.weight * f->t,
                h.index,
                p.level + 1, -1};
            if (rec != NULL)
                task.node = record_task(rec, RT_RAY_REFRACTED, p.node, &task);
            stack[used++] = task;
            counters->refraction_rays++;
        }
        if (mirror_weight > 0) {
            ray_task task = {
                offset_origin(point, error_bound, normal, mirror),
                normalize(mirror, fast), error_bound,
                p.weight * mirror_weight, h.index,
                p.level + 1, -1};
            if (rec != NULL)
                task.node = record_task(rec, RT_RAY_REFLECTED, p.node, &task);
            stack[used++] = task;
            counters->reflection_rays++;
        }
    }
    if (stack != local)
        free(stack);
    return ok;
}

/*
 * The colour a ray carries (the rendering model's formula, up to
 * max_depth reflected or refracted rays after it).  A scene without
 * transparent facets takes the constant-stack loop of the handout's model.
 */
rt_color KERNEL(trace)(const KERNEL_T *k, rt_vec3 origin_d,
                       rt_vec3 direction_d, const rt_trace_settings *settings,
                       rt_counters *counters)
{
    REAL color[3] = {0, 0, 0};
    int simd = k->avx2 && settings->kernel != RT_KERNEL_SCALAR;
    const octree *tree = settings->octree ? octree_of(k) : NULL;
    vec origin = from_rt(origin_d);
    vec incoming = normalize(from_rt(direction_d), settings->fast_inv_sqrt);
    /* Two copies of the opaque loop: the renders' without a recorder
     * (its recording code compiled away), and the one rt_explain_pixel
     * records; the arithmetic is the same source. */
    if (!k->transparent && settings->recorder == NULL)
        trace_opaque(k, origin, incoming, settings, tree, simd, color,
                     counters, NULL, NULL);
    else if (!k->transparent)
        trace_opaque(k, origin, incoming, settings, tree, simd, color,
                     counters, settings->recorder, NULL);
    else if (!trace_transparent(k, origin, incoming, settings, tree, simd,
                                color, counters, settings->recorder))
        counters->out_of_memory = 1;
    return (rt_color){color[0], color[1], color[2]};
}
