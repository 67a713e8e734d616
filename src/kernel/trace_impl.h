/*
 * trace_impl.h - the colour a ray carries (docs/rendering-model.md, "What
 * a ray sees"): the loop of an opaque scene, the ray tree of a scene with
 * transparent facets, and kernel_trace(), the table's trace, which picks
 * one (part of kernel_impl.h, compiled once per precision; everything here
 * is static).  Both loops end each ray with shade_hit() of shade_impl.h
 * and differ only in the rays they send on.
 */

/*
 * The opaque case (no facet with t > 0): the rendering model with the
 * recursion on C_R unrolled: the colour is the sum over bounces of each
 * hit's own term times the product of the k met before it, so any depth
 * runs in constant stack.  Work that cannot change the result is left out:
 * no shadow ray where N.S <= 0 or d = 0, no reflected ray from a facet with
 * k = 0.  `known` is NULL, or what a packet (packet_impl.h) found already
 * of the camera ray's first hit.
 */
HOT_INLINE void trace_opaque(const trace_ctx *c, vec origin, vec incoming,
                             const known_hit *known, REAL color[3])
{
    REAL weight = 1;
    int skip = -1, node = -1;
    vec origin_bound = mk(0, 0, 0);     /* of the point `origin` leaves */
    for (int bounce = 0;; bounce++) {
        if (c->rec != NULL)
            node = c->rec->on_ray(c->rec->state,
                                  bounce == 0 ? RT_RAY_CAMERA
                                              : RT_RAY_REFLECTED,
                                  node, bounce, to_rt(origin),
                                  to_rt(incoming), (double)weight);
        const known_hit *given = bounce == 0 ? known : NULL;
        hit h;
        int found;
        if (given != NULL) {
            found = given->found;
            if (found)
                h = *given->h;
        } else {
            ray r = prepare_leaving(origin, incoming, origin_bound);
            found = nearest(c, bounce == 0 ? c->eye : NULL, &r, INFINITY,
                            skip, &h);
        }
        surface s;
        if (!shade_hit(c, found, &h, origin, incoming, weight, node, given,
                       color, &s))
            break;
        if (s.m->k == 0) {
            c->counters->reflection_rays_skipped += bounce < c->max_depth;
            break;
        }
        if (bounce >= c->max_depth)
            break;          /* a reflection past the limit is black */
        weight *= s.m->k;
        vec reflected = mirror_direction(c, &s, incoming);
        origin = offset_origin(s.point, s.error_bound, s.normal, reflected);
        origin_bound = s.error_bound;
        incoming = normalize(reflected, c->fast);
        skip = s.index;
        c->counters->reflection_rays++;
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
static int record_task(const rt_trace_recorder *rec, int kind, int parent,
                       const ray_task *task)
{
    return rec->on_ray(rec->state, kind, parent, task->level,
                       to_rt(task->origin), to_rt(task->incoming),
                       (double)task->weight);
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
 * refract() at a smooth facet: whether the ray enters or leaves is the
 * winding normal's to say, as at a flat facet, and Snell's law is applied
 * with N_s (which faces the ray, as N_t does).  A direction that does not
 * go below the facet (judged with N_g) is computed with N_g instead; a
 * total internal reflection (with N_s) is 0, as refract()'s.
 */
static int refract_smooth(const surface *s, REAL n, vec *out)
{
    vec incoming = s->incoming;
    REAL eta = dot(incoming, s->f->normal) < 0 ? 1 / n : n;
    REAL c = -dot(incoming, s->shading);
    REAL q = 1 - eta * eta * (1 - c * c);
    if (q < 0)
        return 0;
    *out = add(scale(incoming, eta), scale(s->shading, eta * c - sqrt(q)));
    if (dot(*out, s->normal) < 0)
        return 1;
    return refract(incoming, s->f->normal, n, out);
}

/* Makes room for two more tasks on the stack (*stack, *capacity: moved
 * to the heap, or to a larger block there); 0 when out of memory. */
static int reserve_tasks(ray_task **stack, int *capacity, int used,
                         const ray_task *local)
{
    if (used + 2 <= *capacity)
        return 1;
    int bigger = *capacity * 2;
    ray_task *grown = malloc((size_t)bigger * sizeof *grown);
    if (grown == NULL)
        return 0;
    memcpy(grown, *stack, (size_t)used * sizeof **stack);
    if (*stack != local)
        free(*stack);
    *stack = grown;
    *capacity = bigger;
    return 1;
}

/*
 * A scene with transparent facets: each hit may send a reflected ray
 * (k > 0) and a refracted one (t > 0), so the rays form a tree, walked
 * depth first with an explicit stack.  A total internal reflection sends
 * the mirror ray for both terms (weight k + t).  Returns 0 when the stack
 * cannot grow (out of memory); the colour is then incomplete.
 */
HOT_INLINE int trace_transparent(const trace_ctx *c, vec origin,
                                 vec incoming, REAL color[3])
{
    const rt_trace_recorder *rec = c->rec;
    rt_counters *counters = c->counters;
    ray_task local[RAY_TASKS_LOCAL], *stack = local;
    int used = 0, capacity = RAY_TASKS_LOCAL;
    int camera = rec == NULL ? -1
                             : rec->on_ray(rec->state, RT_RAY_CAMERA, -1, 0,
                                           to_rt(origin), to_rt(incoming),
                                           1.0);
    stack[used++] = (ray_task){origin, incoming, mk(0, 0, 0), 1, -1, 0,
                               camera};
    int ok = 1;
    while (used > 0) {
        ray_task p = stack[--used];
        ray r = prepare_leaving(p.origin, p.incoming, p.origin_bound);
        hit h;
        int found = nearest(c, p.level == 0 ? c->eye : NULL, &r, INFINITY,
                            p.skip, &h);
        surface s;
        if (!shade_hit(c, found, &h, p.origin, p.incoming, p.weight, p.node,
                       NULL, color, &s))
            continue;
        const tri *f = s.f;
        const material *m = s.m;
        int deeper = p.level < c->max_depth;
        if (m->k == 0)
            counters->reflection_rays_skipped += deeper;
        if (!deeper) {
            counters->refraction_rays_skipped += m->t > 0;
            continue;       /* past the limit: black */
        }
        vec mirror = mirror_direction(c, &s, p.incoming);
        REAL mirror_weight = m->k;
        vec refracted = mk(0, 0, 0);   /* set when refracts */
        int refracts = m->t > 0 &&
                       (c->shading && s.smooth ? refract_smooth(&s, m->n, &refracted)
                                 : refract(p.incoming, f->normal, m->n,
                                           &refracted));
        if (m->t > 0 && !refracts) {
            mirror_weight += m->t;  /* total internal reflection */
            counters->refraction_rays_skipped++;
        }
        if (!reserve_tasks(&stack, &capacity, used, local)) {
            ok = 0;
            break;
        }
        if (refracts) {
            ray_task task = {
                offset_origin(s.point, s.error_bound, s.normal, refracted),
                normalize(refracted, c->fast), s.error_bound,
                p.weight * m->t, s.index, p.level + 1, -1};
            if (rec != NULL)
                task.node = record_task(rec, RT_RAY_REFRACTED, p.node, &task);
            stack[used++] = task;
            counters->refraction_rays++;
        }
        if (mirror_weight > 0) {
            ray_task task = {
                offset_origin(s.point, s.error_bound, s.normal, mirror),
                normalize(mirror, c->fast), s.error_bound,
                p.weight * mirror_weight, s.index, p.level + 1, -1};
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
static rt_color kernel_trace(const rt_kernel *kernel, rt_vec3 origin_d,
                             rt_vec3 direction_d,
                             const rt_trace_settings *settings,
                             rt_counters *counters)
{
    const KERNEL_T *k = kernel_of(kernel);
    REAL color[3] = {0, 0, 0};
    vec origin = from_rt(origin_d);
    vec incoming = normalize(from_rt(direction_d), settings->fast_inv_sqrt);
    const rt_trace_recorder *rec = settings->recorder;
    /* Each loop twice: the renders' copy, whose context records nothing
     * (a constant NULL recorder: its recording code is compiled away), and
     * the copy rt_explain_pixel records with. */
    int complete = 1;
    if (rec == NULL && !k->shading) {
        /* no smooth facet, no highlight: the shading of section 7 alone */
        trace_ctx c = trace_context(k, settings, counters, NULL);
        c.shading = 0;
        const trace_ctx flat = c;
        if (k->transparent)
            complete = trace_transparent(&flat, origin, incoming, color);
        else
            trace_opaque(&flat, origin, incoming, NULL, color);
    } else if (rec == NULL) {
        const trace_ctx c = trace_context(k, settings, counters, NULL);
        if (k->transparent)
            complete = trace_transparent(&c, origin, incoming, color);
        else
            trace_opaque(&c, origin, incoming, NULL, color);
    } else {
        const trace_ctx c = trace_context(k, settings, counters, rec);
        if (k->transparent)
            complete = trace_transparent(&c, origin, incoming, color);
        else
            trace_opaque(&c, origin, incoming, NULL, color);
    }
    if (!complete)
        counters->out_of_memory = 1;
    return (rt_color){color[0], color[1], color[2]};
}
