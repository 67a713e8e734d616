/*
 * query_impl.h - nearest hit and any hit over a kernel's facets: the only
 * place that chooses between the loops (scalar or the AVX2 filter of
 * simd_impl.h).  Part of kernel_impl.h, compiled once per precision;
 * everything here is static.
 */

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
