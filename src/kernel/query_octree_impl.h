/*
 * query_octree_impl.h - nearest hit and any hit through the octree of
 * octree_impl.h (part of kernel_impl.h, compiled once per precision;
 * everything here is static).
 *
 * Through the octree a ray meets the facets in another order than the
 * brute-force loops (index order), yet the answer must be the same bit for
 * bit, ties included.  Nearest hit keeps every hit it finds (a handful) and
 * ends with the brute-force fold over those that can matter, in index
 * order; docs/octree.md proves that this is the brute-force answer as long
 * as the walk stops only past `reach` (see near_reach()).  A ray the walk
 * cannot serve (from too far, or with too many hits) falls back to the
 * brute force of query_brute_impl.h.
 */

/* The facets a query has tested, on the stack: a facet listed in several
 * leaves is tested once.  A short list, searched linearly (a ray tests a
 * handful of facets); once it is full, further facets are not remembered
 * (tested again if met again: the same answer, only slower). */
#define TESTED_MAX 64
typedef struct tested {
    int32_t facet[TESTED_MAX];
    int count;
} tested;

static void tested_clear(tested *s)
{
    s->count = 0;
}

/* Non-zero when i was not in the list (it is now, if there was room). */
static int tested_add(tested *s, int32_t i)
{
    for (int j = 0; j < s->count; j++)
        if (s->facet[j] == i)
            return 0;
    if (s->count < TESTED_MAX)
        s->facet[s->count++] = i;
    return 1;
}

#if REAL_IS_FLOAT
#define OCTREE_SLACK 0x1p-6
#else
#define OCTREE_SLACK 0x1p-16
#endif
#define NEAR_HITS 32

/* Non-zero when hit x cannot tie with, nor come before, any hit that ends
 * by `reach` (t + t_error <= reach); the 8 eps terms cover the rounding of
 * this test and of replaces(). */
static int far_from(const hit *x, REAL reach)
{
    return (x->t - x->t_error) - 8 * REAL_EPS * (x->t + x->t_error) >
           reach * (1 + 8 * REAL_EPS);
}

/* The smallest reach such that every hit not far_from() it ends by it:
 * grown from the nearest hit's t + t_error until nothing changes. */
static REAL near_reach(const hit *found, int n)
{
    int m = 0;
    for (int i = 1; i < n; i++)
        if (found[i].t < found[m].t)
            m = i;
    REAL reach = found[m].t + found[m].t_error;
    for (int changed = 1; changed;) {
        changed = 0;
        for (int i = 0; i < n; i++)
            if (!far_from(&found[i], reach) &&
                found[i].t + found[i].t_error > reach) {
                reach = found[i].t + found[i].t_error;
                changed = 1;
            }
    }
    return reach;
}

/* The entry beyond which a node cannot hold a hit that is not far_from()
 * `reach` (docs/octree.md: a facet met beyond the entry e has
 * t - t_error >= e (1 - OCTREE_SLACK / 2)). */
static double cutoff(REAL reach, int found)
{
    if (!found)
        return INFINITY;
    return (double)reach * (1 + 16 * (double)REAL_EPS) / (1 - OCTREE_SLACK);
}

/* The hits a nearest-hit query through the octree has found so far. */
typedef struct collector {
    hit found[NEAR_HITS];
    int n;
    REAL reach;             /* near_reach() of found, when n > 0 */
    uint64_t made;          /* facets tested */
} collector;

/* Tests facet i; 0 when the hit does not fit any more. */
static int collect(collector *c, const KERNEL_T *k, const ray *r,
                   REAL t_max, int i)
{
    c->made++;
    if (!intersect(r, k->vertices, &k->tris[i], t_max, &c->found[c->n]))
        return 1;
    c->found[c->n].index = i;
    if (++c->n == NEAR_HITS)
        return 0;
    c->reach = near_reach(c->found, c->n);
    return 1;
}

/* The lanes of facets ids[0..n) worth the full test: all of them, or
 * those the AVX2 filter cannot rule out. */
static unsigned batch_candidates(const KERNEL_T *k, int simd, const ray *r,
                                 const int *ids, int n)
{
#if HAVE_AVX2_KERNEL
    if (simd)
        return gathered_candidates(k, r, ids, n);
#else
    (void)k;
    (void)simd;
    (void)r;
    (void)ids;
#endif
    return (1u << n) - 1;
}

/* collect() over a batch of a leaf's facets (n <= BLOCK_LANES); every
 * facet counts as tested, filtered out or not, as in the brute-force
 * loops.  0 when the hits do not fit any more. */
static int collect_batch(collector *c, const KERNEL_T *k, int simd,
                         const ray *r, REAL t_max, const int *ids, int n)
{
    unsigned candidates = batch_candidates(k, simd, r, ids, n);
    for (int j = 0; j < n; j++) {
        if (!(candidates >> j & 1))
            c->made++;
        else if (!collect(c, k, r, t_max, ids[j]))
            return 0;
    }
    return 1;
}

/* Non-zero when one of the facets ids[0..n) blocks a shadow ray; counts
 * in *made the facets up to the blocker, as the scalar loop does. */
static int blocked_batch(const KERNEL_T *k, int simd, const ray *r,
                         REAL t_max, const int *ids, int n, uint64_t *made,
                         int *blocker)
{
    unsigned candidates = batch_candidates(k, simd, r, ids, n);
    hit ignored;
    for (int j = 0; j < n; j++) {
        (*made)++;
        if ((candidates >> j & 1) &&
            intersect(r, k->vertices, &k->tris[ids[j]], t_max, &ignored) &&
            blocks(&ignored, t_max)) {
            *blocker = ids[j];
            return 1;
        }
    }
    return 0;
}

/* The brute-force fold (nearest_scalar()) over the hits that are not
 * far_from() the reach, in index order; non-zero when there is one. */
static int fold_near(const KERNEL_T *k, const collector *c, hit *h)
{
    const hit *near[NEAR_HITS];
    int m = 0;
    for (int j = 0; j < c->n; j++) {
        if (far_from(&c->found[j], c->reach))
            continue;
        int i = m++;
        while (i > 0 && near[i - 1]->index > c->found[j].index) {
            near[i] = near[i - 1];
            i--;
        }
        near[i] = &c->found[j];
    }
    const hit *best = NULL;
    for (int j = 0; j < m; j++)
        if (best == NULL || replaces(k, best, near[j]))
            best = near[j];
    if (best != NULL)
        *h = *best;
    return best != NULL;
}

/* A nearest-hit query a structure cannot serve, by brute force. */
static int nearest_fallback(const KERNEL_T *k, int simd, const ray *r,
                            REAL t_max, int skip, hit *h,
                            rt_counters *counters)
{
    counters->accel_fallbacks++;
    return nearest_brute(k, simd, NULL, r, t_max, skip, h,
                         &counters->ray_facet_tests);
}

/* The end of a nearest-hit query through a structure (the octree, the
 * kd-tree): its tests counted, then the fold over the hits that matter -
 * or brute force when the hits overflowed (`complete` 0) or the reach
 * grew past the smallest entry of a node left out (`skipped`). */
static int nearest_finish(const KERNEL_T *k, int simd,
                          const collector *found, int complete,
                          double skipped, const ray *r, REAL t_max, int skip,
                          hit *h, rt_counters *counters)
{
    counters->ray_facet_tests += found->made;
    if (complete) {
        counters->accel_facet_tests += found->made;
        counters->accel_queries++;
        if (found->n == 0)
            return 0;
        if (skipped > cutoff(found->reach, found->n))
            return fold_near(k, found, h);
    }
    return nearest_fallback(k, simd, r, t_max, skip, h, counters);
}

/* The part of leaf `leaf` the walk asks for: all its facets, or when it
 * lies beyond the stopping point only its slivers (the last ones). */
static void leaf_part(const octree *tree, const walk *w, int leaf,
                      int *first, int *count)
{
    const onode *node = &tree->nodes[leaf];
    *first = node->first;
    *count = node->count;
    if (w->slivers_only) {
        *first += node->count - tree->slivers[leaf];
        *count = tree->slivers[leaf];
    }
}

static int nearest_octree(const KERNEL_T *k, int simd, const octree *tree,
                          const ray *r, REAL t_max, int skip, hit *h,
                          rt_counters *counters)
{
    double grow = fat_growth(tree, r);
    if (grow < 0)
        return nearest_fallback(k, simd, r, t_max, skip, h, counters);
    /* The stopping rule (docs/octree.md, step 5) only for rays within the
     * margin's reach: a farther one walks every cell to t_max. */
    int stops = grow == 0;
    collector found;
    found.n = 0;
    found.reach = 0;
    found.made = 0;
    tested seen;
    tested_clear(&seen);
    walk w;
    walk_start(&w, tree, r, 0, (double)t_max, grow);
    for (int j = 0; j < tree->always_count; j++)
        if (tree->always[j] != skip &&
            !collect(&found, k, r, t_max, tree->always[j]))
            goto overflow;
    int leaf;
    while ((leaf = walk_next(&w, stops ? cutoff(found.reach, found.n)
                                       : INFINITY)) >= 0) {
        int first, count;
        leaf_part(tree, &w, leaf, &first, &count);
        counters->accel_leaves_visited++;
        int batch[BLOCK_LANES], n = 0;
        for (int j = 0; j < count; j++) {
            int i = tree->refs[first + j];
            if (i == skip || !tested_add(&seen, i))
                continue;
            batch[n++] = i;
            if (n == BLOCK_LANES || j == count - 1) {
                if (!collect_batch(&found, k, simd, r, t_max, batch, n))
                    goto overflow;
                n = 0;
            }
        }
        if (n > 0 && !collect_batch(&found, k, simd, r, t_max, batch, n))
            goto overflow;
    }
    counters->accel_steps += w.steps;
    return nearest_finish(k, simd, &found, 1, w.skipped, r, t_max, skip, h,
                          counters);
overflow:
    counters->accel_steps += w.steps;
    return nearest_finish(k, simd, &found, 0, INFINITY, r, t_max, skip, h,
                          counters);
}

/* any_hit_brute() through the octree: the same answer, as the facets that
 * can block are listed in the leaves the segment meets (walked with the
 * cells grown for far origins, as nearest_octree() does). */
static int any_hit_octree(const KERNEL_T *k, int simd, const octree *tree,
                          const ray *r, REAL t_max, int skip,
                          rt_counters *counters, int *blocker)
{
    double grow = fat_growth(tree, r);
    if (grow < 0) {
        counters->accel_fallbacks++;
        return any_hit_brute(k, simd, r, t_max, skip, counters, blocker);
    }
    hit ignored;
    uint64_t made = 0;
    int found = 0;
    for (int j = 0; j < tree->always_count && !found; j++) {
        int i = tree->always[j];
        if (i == skip)
            continue;
        made++;
        found = intersect(r, k->vertices, &k->tris[i], t_max, &ignored) &&
                blocks(&ignored, t_max);
        if (found)
            *blocker = i;
    }
    tested seen;
    tested_clear(&seen);
    walk w;
    walk_start(&w, tree, r, 0, (double)t_max, grow);
    int leaf;
    while (!found && (leaf = walk_next(&w, INFINITY)) >= 0) {
        const onode *node = &tree->nodes[leaf];
        counters->accel_leaves_visited++;
        int batch[BLOCK_LANES], n = 0;
        for (int j = 0; j < node->count && !found; j++) {
            int i = tree->refs[node->first + j];
            if (i == skip || !tested_add(&seen, i))
                continue;
            batch[n++] = i;
            if (n == BLOCK_LANES) {
                found = blocked_batch(k, simd, r, t_max, batch, n, &made,
                                      blocker);
                n = 0;
            }
        }
        if (!found && n > 0)
            found = blocked_batch(k, simd, r, t_max, batch, n, &made,
                                  blocker);
    }
    counters->ray_facet_tests += made;
    counters->accel_facet_tests += made;
    counters->accel_steps += w.steps;
    counters->accel_queries++;
    return found;
}
