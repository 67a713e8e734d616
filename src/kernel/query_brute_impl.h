/*
 * query_brute_impl.h - nearest hit and any hit by brute force: every facet
 * but the one a ray leaves, in index order, by the scalar loops or the
 * AVX2 filter of simd_impl.h (part of kernel_impl.h, compiled once per
 * precision; everything here is static).  query_impl.h chooses between
 * these and the octree's queries.
 */

/* Nearest hit, all facets but `skip` (ties: see replaces()). */
static int nearest_scalar(const KERNEL_T *k, const ray *r, REAL t_max,
                          int skip, hit *h, uint64_t *tests)
{
    int found = 0;
    hit candidate;
    for (int i = 0; i < k->count; i++) {
        if (i != skip && intersect(r, &k->tris[i], t_max, &candidate))
            keep_nearer(k, i, &candidate, h, &t_max, &found);
    }
    *tests += (uint64_t)k->count - (skip >= 0);
    return found;
}


/* Any hit in (0, t_max), all facets but `skip`; stops at the first,
 * whose index goes to *blocker. */
static int any_hit_scalar(const KERNEL_T *k, const ray *r, REAL t_max,
                          int skip, uint64_t *tests, uint64_t *saved,
                          int *blocker)
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
        if (found)
            *blocker = i;
    }
    *tests += made;
    *saved += (uint64_t)k->count - (skip >= 0) - made;
    return found;
}


/* The loops a trace uses: AVX2 when the processor has it and the caller
 * did not ask for the scalar ones (simd 0), with the vertices of `eye`
 * (may be NULL) for a ray from its origin with no facet to skip, else
 * the kernel's blocks once made (prepare_blocks).  All give the same
 * hits. */
static inline int nearest_brute(const KERNEL_T *k, int simd,
                                const KERNEL_EYE_T *eye, const ray *r,
                                REAL t_max, int skip, hit *h, uint64_t *tests)
{
#if HAVE_AVX2_KERNEL
    if (simd && eye != NULL && skip < 0 &&
        memcmp(&eye->origin, &r->origin, sizeof eye->origin) == 0)
        return nearest_eye_avx2(k, eye->blocks, r, t_max, h, tests);
    const block *facet_blocks = simd ? blocks_of(k) : NULL;
    if (facet_blocks != NULL)
        return nearest_avx2(k, facet_blocks, r, t_max, skip, h, tests);
#else
    (void)simd;
    (void)eye;
#endif
    return nearest_scalar(k, r, t_max, skip, h, tests);
}

/* Any hit by the loops nearest_brute() picks; the blocker's index goes to
 * *blocker. */
static inline int any_hit_brute(const KERNEL_T *k, int simd, const ray *r,
                                REAL t_max, int skip, rt_counters *counters,
                                int *blocker)
{
#if HAVE_AVX2_KERNEL
    const block *facet_blocks = simd ? blocks_of(k) : NULL;
    if (facet_blocks != NULL)
        return any_hit_avx2(k, facet_blocks, r, t_max, skip,
                            &counters->ray_facet_tests,
                            &counters->early_exit_saved, blocker);
#else
    (void)simd;
#endif
    return any_hit_scalar(k, r, t_max, skip, &counters->ray_facet_tests,
                          &counters->early_exit_saved, blocker);
}
