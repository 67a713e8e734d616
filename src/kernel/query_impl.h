/*
 * query_impl.h - the queries a trace makes, nearest hit and any hit: the
 * only place that chooses how - through the kd-tree when the trace has one
 * (query_kdtree_impl.h), else through the octree when it has one
 * (query_octree_impl.h), else brute force (query_brute_impl.h), which
 * itself picks the scalar loops or the AVX2 filter.  Part of
 * kernel_impl.h, compiled once per precision; everything here is static.
 *
 * The queries below this one take the few values they read one by one,
 * not the trace context: nothing a trace loop inlines hands its context's
 * address to a function it does not inline, so the compiler keeps the
 * context's fields in registers (and a constant NULL recorder or octree
 * removes their code).
 */

/* The nearest hit of r within (0, t_max), every facet but `skip` (-1:
 * none); non-zero and *h filled when there is one.  `eye` is NULL, or the
 * trace's eye (c->eye) for a camera ray: a ray from the eye's origin with
 * no facet to skip reads the eye's vertices. */
static inline int nearest(const trace_ctx *c, const KERNEL_EYE_T *eye,
                          const ray *r, REAL t_max, int skip, hit *h)
{
    if (c->kd != NULL)
        return nearest_kdtree(c->k, c->simd, c->kd, r, t_max, skip, h,
                              c->counters);
    if (c->tree != NULL)
        return nearest_octree(c->k, c->simd, c->tree, r, t_max, skip, h,
                              c->counters);
    return nearest_brute(c->k, c->simd, eye, r, t_max, skip, h,
                         &c->counters->ray_facet_tests);
}

/* Non-zero when some facet but `skip` blocks r within (0, t_max); the
 * index of the blocker found (the first one each loop meets, not
 * necessarily the nearest) goes to *blocker. */
static inline int any_hit(const trace_ctx *c, const ray *r, REAL t_max,
                          int skip, int *blocker)
{
    if (c->kd != NULL)
        return any_hit_kdtree(c->k, c->simd, c->kd, r, t_max, skip,
                              c->counters, blocker);
    if (c->tree != NULL)
        return any_hit_octree(c->k, c->simd, c->tree, r, t_max, skip,
                              c->counters, blocker);
    return any_hit_brute(c->k, c->simd, r, t_max, skip, c->counters,
                         blocker);
}
