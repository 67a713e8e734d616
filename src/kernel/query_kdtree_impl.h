/*
 * query_kdtree_impl.h - nearest hit and any hit through the kd-tree of
 * kdtree_impl.h (part of kernel_impl.h, compiled once per precision;
 * everything here is static).
 *
 * The octree's queries (query_octree_impl.h) over another walk, sharing
 * their parts: nearest hit keeps every hit it finds (collect_batch()),
 * stops the walk past the cutoff of the reach (cutoff(), near_reach()),
 * and ends with the brute-force fold in index order over the hits that
 * can matter (fold_near()); any hit stops at the first blocker.  A facet
 * listed in several leaves is tested once per ray by a mailbox.
 * docs/kdtree.md gives the argument that the answers are the brute-force
 * ones; what the walk cannot serve (origins too far, too many hits, a
 * reach grown past a node left out) goes to brute force.
 */

/* A per-ray mailbox: direct-mapped, facet i in slot i mod KD_MAILBOX.  A
 * facet found in its slot was tested by this ray; one evicted meanwhile
 * is tested again, which gives the same hit (a duplicate the fold does not
 * keep: replaces() wants a strictly nearer t).  O(1) a look, against the
 * octree's linear list. */
#define KD_MAILBOX 64
typedef struct mailbox {
    int32_t facet[KD_MAILBOX];
} mailbox;

static void mailbox_clear(mailbox *m)
{
    for (int j = 0; j < KD_MAILBOX; j++)
        m->facet[j] = -1;
}

/* Non-zero the first time facet i is seen (as far as the slot knows). */
static inline int mailbox_first(mailbox *m, int32_t i)
{
    int32_t *slot = &m->facet[(uint32_t)i % KD_MAILBOX];
    if (*slot == i)
        return 0;
    *slot = i;
    return 1;
}

static int nearest_kdtree(const KERNEL_T *k, int simd, const kdtree *tree,
                          const ray *r, REAL t_max, int skip, hit *h,
                          rt_counters *counters)
{
    double grow = tree->brute ? -1 : kd_growth(tree, r);
    if (grow < 0)
        return nearest_fallback(k, simd, r, t_max, skip, h, counters);
    int stops = grow == 0;      /* far origins walk to t_max */
    collector found;
    found.n = 0;
    found.reach = 0;
    found.made = 0;
    mailbox seen;
    mailbox_clear(&seen);
    kd_walk w;
    kd_walk_start(&w, tree, r, 0, (double)t_max, grow);
    int leaf;
    while ((leaf = kd_walk_next(&w, stops ? cutoff(found.reach, found.n)
                                          : INFINITY)) >= 0) {
        int count;
        const int32_t *ids = kd_leaf_facets(tree, &tree->nodes[leaf], &count);
        counters->accel_leaves_visited++;
        int batch[BLOCK_LANES], n = 0;
        for (int j = 0; j < count; j++) {
            int i = ids[j];
            if (i == skip || !mailbox_first(&seen, i))
                continue;
            batch[n++] = i;
            if (n == BLOCK_LANES) {
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

/* any_hit_brute() through the kd-tree: the same answer, as every facet
 * that can block is listed in a leaf the segment meets; stops at the
 * first blocker. */
static int any_hit_kdtree(const KERNEL_T *k, int simd, const kdtree *tree,
                          const ray *r, REAL t_max, int skip,
                          rt_counters *counters)
{
    double grow = tree->brute ? -1 : kd_growth(tree, r);
    if (grow < 0) {
        counters->accel_fallbacks++;
        return any_hit_brute(k, simd, r, t_max, skip, counters);
    }
    uint64_t made = 0;
    int found = 0;
    mailbox seen;
    mailbox_clear(&seen);
    kd_walk w;
    kd_walk_start(&w, tree, r, 0, (double)t_max, grow);
    int leaf;
    while (!found && (leaf = kd_walk_next(&w, INFINITY)) >= 0) {
        int count;
        const int32_t *ids = kd_leaf_facets(tree, &tree->nodes[leaf], &count);
        counters->accel_leaves_visited++;
        int batch[BLOCK_LANES], n = 0;
        for (int j = 0; j < count && !found; j++) {
            int i = ids[j];
            if (i == skip || !mailbox_first(&seen, i))
                continue;
            batch[n++] = i;
            if (n == BLOCK_LANES) {
                found = blocked_batch(k, simd, r, t_max, batch, n, &made);
                n = 0;
            }
        }
        if (!found && n > 0)
            found = blocked_batch(k, simd, r, t_max, batch, n, &made);
    }
    counters->ray_facet_tests += made;
    counters->accel_facet_tests += made;
    counters->accel_steps += w.steps;
    counters->accel_queries++;
    return found;
}
