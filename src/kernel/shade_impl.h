/*
 * shade_impl.h - what happens at a hit: the hit point and its error bound,
 * the offset origin of secondary rays, the direct light and the reflections
 * of SPEC.md section 3 (part of kernel_impl.h, compiled once per precision;
 * everything here but KERNEL(trace) is static).
 *
 * Secondary rays: the hit point is computed from barycentric weights with
 * its rounding-error bound, and the new ray starts just beyond that bound
 * along the normal (Pharr, Jakob, Humphreys, "Physically Based Rendering",
 * 4th ed., section 6.8.6).  The offset scales with the coordinates, so it
 * works for scenes at 1e-6 as at 1e6; the facet a ray leaves is also
 * skipped, which is exact (a flat facet cannot be met twice).
 */

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
static void add_direct_light(const KERNEL_T *k, const octree *tree,
                             const tri *f, int index, vec point,
                             vec error_bound, vec normal, REAL weight,
                             int fast, int simd, REAL color[3],
                             rt_counters *counters)
{
    vec to_light = sub(k->light, point);
    if (f->k == 1 || !(dot(normal, to_light) > 0)) {
        counters->shadow_rays_skipped++;
        return;
    }
    vec origin = offset_origin(point, error_bound, normal, to_light);
    ray shadow = prepare(origin, sub(k->light, origin));
    counters->shadow_rays++;
    if (any_hit(k, simd, tree, &shadow, 1, index, counters))
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
    const octree *tree = settings->octree ? octree_of(k) : NULL;
    vec origin = from_rt(origin_d);
    vec incoming = normalize(from_rt(direction_d), fast);
    for (int bounce = 0;; bounce++) {
        ray r = prepare(origin, incoming);
        hit h;
        if (!nearest(k, simd, tree, bounce == 0 ? settings->eye : NULL, &r,
                     INFINITY, skip, &h, counters)) {
            for (int c = 0; c < 3; c++)
                color[c] += weight * k->background[c];
            break;
        }
        const tri *f = &k->tris[h.index];
        vec error_bound;
        vec point = hit_point(f, &h, origin, incoming, &error_bound);
        vec normal = dot(f->normal, incoming) > 0 ? neg(f->normal) : f->normal;
        add_direct_light(k, tree, f, h.index, point, error_bound, normal,
                         weight, fast, simd, color, counters);
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
