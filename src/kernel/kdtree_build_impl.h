/*
 * kdtree_build_impl.h - the construction of the kd-tree of kdtree_impl.h
 * (part of kernel_impl.h, compiled once per precision; everything here is
 * static).
 *
 * Depth first, sequential.  Each facet is represented by its bounding box
 * grown by the margin and rounded outward to float ("plain" bounds, not
 * clipped to the cell: a superset of the clipped ones, so conservative).
 * A node's plane is chosen by the surface area heuristic over every bound
 * of its facets on each axis, by a sweep of the sorted bounds (O(n log n)
 * a node, O(N log^2 N) for the tree).  A facet goes below a plane p when
 * its box starts before p (or lies wholly at or below it), above when it
 * ends after p (or lies wholly at or above it); one whose box straddles p
 * goes to each side whose cell, grown by the octree's margin, the
 * triangle itself overlaps (the octree's triangle-box test), so a facet
 * crossing a cell's corner is not listed where only its box reaches (why
 * all this suffices: docs/kdtree.md, "Listing").  kdtree_impl.h lists the
 * bounds, each with its reason; the build polls the cancellation flag as
 * it goes and keeps nothing half built.
 */

typedef struct kd_builder {
    float (*lo)[3], (*hi)[3];   /* each facet's grown box, in float */
    double (*v)[3][3];      /* each facet's vertices, in double */
    double overlap_margin;  /* the octree's margin, for the overlap test */
    const unsigned char *sliver;
    kdtree *tree;
    size_t node_capacity, ref_capacity;
    int32_t *lists;         /* the lists of the nodes waiting, then the
                               one being split */
    size_t list_capacity;
    size_t stored;          /* references in tree->refs (a leaf of one
                               facet holds it in its node) */
    float *keys;            /* the sweep's sorted bounds: 3 n */
    size_t key_capacity;
    size_t limit;           /* references and nodes allowed */
    int cap;                /* the depth cap */
    const rt_cancel *cancel;    /* NULL: the build cannot be cancelled */
    size_t work;            /* units of work since the flag was read */
    int too_big;            /* the limit was passed: redo with a lower cap */
    rt_status status;       /* RT_OK, RT_ERR_NOMEM or RT_ERR_CANCELLED */
} kd_builder;

/* Counts `amount` units of work and, every KD_POLL_WORK of them, reads
 * the cancellation flag; non-zero once the build must stop. */
static int kd_stopped(kd_builder *b, size_t amount)
{
    b->work += amount;
    if (b->work >= KD_POLL_WORK) {
        b->work = 0;
        if (b->status == RT_OK && b->cancel != NULL &&
            rt_cancel_requested(b->cancel))
            b->status = RT_ERR_CANCELLED;
    }
    return b->status != RT_OK || b->too_big;
}

/* The largest float <= x, and the smallest float >= x (infinite beyond
 * float's range on the side that overflows). */
static float float_below(double x)
{
    float f = (float)x;
    return (double)f > x ? nextafterf(f, -INFINITY) : f;
}

static float float_above(double x)
{
    float f = (float)x;
    return (double)f < x ? nextafterf(f, INFINITY) : f;
}

static int compare_floats(const void *a, const void *b)
{
    float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

/* Surface area of a box of extents d, up to the factor 2. */
static double half_area(const double d[3])
{
    return d[0] * d[1] + d[1] * d[2] + d[2] * d[0];
}

/* The best plane on axis a of the cell lo..hi for facets list[0 .. n),
 * if cheaper than *cost: *cost, *axis and *split updated. */
static void sweep(kd_builder *b, const int32_t *list, int n,
                  const double lo[3], const double hi[3], int a,
                  double *cost, int *axis, float *split)
{
    float *starts = b->keys, *ends = b->keys + n, *flat = b->keys + 2 * n;
    int ns = 0, nf = 0;
    for (int j = 0; j < n; j++) {
        float l = b->lo[list[j]][a], h = b->hi[list[j]][a];
        if (l == h) {
            flat[nf++] = l;
        } else {
            starts[ns] = l;
            ends[ns++] = h;
        }
    }
    qsort(starts, (size_t)ns, sizeof *starts, compare_floats);
    qsort(ends, (size_t)ns, sizeof *ends, compare_floats);
    qsort(flat, (size_t)nf, sizeof *flat, compare_floats);
    double d[3] = {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
    double area = half_area(d);
    int cs = 0, ce = 0, cf = 0;
    while (cs < ns || ce < ns || cf < nf) {
        float p = INFINITY;
        if (cs < ns && starts[cs] < p)
            p = starts[cs];
        if (ce < ns && ends[ce] < p)
            p = ends[ce];
        if (cf < nf && flat[cf] < p)
            p = flat[cf];
        int starts_before = cs, flat_before = cf;
        while (cs < ns && starts[cs] == p)
            cs++;
        while (ce < ns && ends[ce] == p)
            ce++;
        while (cf < nf && flat[cf] == p)
            cf++;
        if (!((double)p > lo[a] && (double)p < hi[a]))
            continue;
        /* below: boxes starting before p, flat ones at or before it;
         * above: boxes ending after p, flat ones at or after it */
        int below = starts_before + cf;
        int above = (ns - ce) + (nf - flat_before);
        double db[3] = {d[0], d[1], d[2]}, da[3] = {d[0], d[1], d[2]};
        db[a] = (double)p - lo[a];
        da[a] = hi[a] - (double)p;
        double c = (half_area(db) * below + half_area(da) * above) / area;
        if (below == 0 || above == 0)
            c *= KD_EMPTY_BONUS;
        c = KD_COST_TRAVERSE + KD_COST_INTERSECT * c;
        if (c < *cost) {
            *cost = c;
            *axis = a;
            *split = p;
        }
    }
}

static int kd_grow(void **array, size_t *capacity, size_t needed,
                   size_t size, kd_builder *b)
{
    if (grow(array, capacity, needed, size))
        return 1;
    b->status = RT_ERR_NOMEM;
    return 0;
}

/* A new node (its fields set later); -1 when out of memory or past the
 * limit. */
static int kd_new_node(kd_builder *b)
{
    kdtree *t = b->tree;
    if ((size_t)t->node_count >= b->limit) {
        b->too_big = 1;
        return -1;
    }
    if (!kd_grow((void **)&t->nodes, &b->node_capacity,
                 (size_t)t->node_count + 1, sizeof *t->nodes, b))
        return -1;
    return t->node_count++;
}

static void kd_make_leaf(kd_builder *b, int node, const int32_t *list, int n)
{
    kdtree *t = b->tree;
    uint32_t sliver = 0;
    for (int j = 0; j < n; j++)
        sliver |= b->sliver[list[j]];
    t->nodes[node].bits = (uint32_t)n << 3 | (sliver ? KD_SLIVER : 0) |
                          KD_LEAF;
    t->leaf_count++;
    if (n == 1) {
        t->nodes[node].at.first = (uint32_t)list[0];
    } else {
        if (t->ref_count + (size_t)n > b->limit) {
            b->too_big = 1;
            return;
        }
        if (n > 0 && !kd_grow((void **)&t->refs, &b->ref_capacity,
                              b->stored + (size_t)n, sizeof *t->refs, b))
            return;
        if (n > 0)
            memcpy(t->refs + b->stored, list, (size_t)n * sizeof *list);
        t->nodes[node].at.first = (uint32_t)b->stored;
        b->stored += (size_t)n;
    }
    t->ref_count += (size_t)n;
}

/*
 * Builds the subtree of the cell lo..hi whose facets are
 * b->lists[off .. off + n), the last list there.  The children's lists
 * go after it and are then moved down, the one above the plane first, so
 * that while the subtree below is built the list above waits beneath it:
 * the lists waiting hold at most the references their subtrees' leaves
 * will hold (each facet of a node is in one child at least).
 */
static void kd_build_node(kd_builder *b, size_t off, int n,
                          const double lo[3], const double hi[3], int depth)
{
    int node = kd_new_node(b);
    if (node < 0 || kd_stopped(b, (size_t)n))
        return;
    kdtree *t = b->tree;
    if (depth > t->depth)
        t->depth = depth;
    double cost = KD_COST_INTERSECT * n;
    int axis = -1;
    float split = 0;
    if (n > 0 && depth < b->cap) {
        if (!kd_grow((void **)&b->keys, &b->key_capacity, 3 * (size_t)n,
                     sizeof *b->keys, b))
            return;
        for (int a = 0; a < 3; a++)
            if (hi[a] > lo[a]) {
                sweep(b, b->lists + off, n, lo, hi, a, &cost, &axis, &split);
                if (kd_stopped(b, (size_t)n))
                    return;
            }
    }
    if (axis < 0) {
        kd_make_leaf(b, node, b->lists + off, n);
        return;
    }
    size_t top = off + (size_t)n;
    if (!kd_grow((void **)&b->lists, &b->list_capacity, top + 2 * (size_t)n,
                 sizeof *b->lists, b))
        return;
    int32_t *list = b->lists + off, *below = b->lists + top,
            *above = b->lists + top + n;
    int nb = 0, na = 0;
    double p = (double)split;
    double cut_hi[3] = {hi[0], hi[1], hi[2]}, cut_lo[3] = {lo[0], lo[1], lo[2]};
    cut_hi[axis] = p;
    cut_lo[axis] = p;
    /* the children's cells grown by the octree's margin, for the
     * triangle-box test of the facets whose boxes straddle the plane */
    double c_below[3], h_below[3], c_above[3], h_above[3];
    int finite = 1;
    for (int a = 0; a < 3; a++) {
        c_below[a] = lo[a] + (cut_hi[a] - lo[a]) * 0.5;
        h_below[a] = (cut_hi[a] - lo[a]) * 0.5 + b->overlap_margin;
        c_above[a] = cut_lo[a] + (hi[a] - cut_lo[a]) * 0.5;
        h_above[a] = (hi[a] - cut_lo[a]) * 0.5 + b->overlap_margin;
        finite &= isfinite(h_below[a]) && isfinite(h_above[a]) &&
                  isfinite(c_below[a]) && isfinite(c_above[a]);
    }
    for (int j = 0; j < n; j++) {
        double l = b->lo[list[j]][axis], h = b->hi[list[j]][axis];
        int in_below = l < p || h <= p, in_above = h > p || l >= p;
        if (in_below && in_above && finite) {
            /* a box that straddles the plane: the facet itself may miss
             * one side (Akenine-Moller's test, as the octree's listing) */
            in_below = triangle_box_overlap(c_below, h_below, b->v[list[j]]);
            in_above = triangle_box_overlap(c_above, h_above, b->v[list[j]]);
            if (!in_below && !in_above)
                in_below = in_above = 1;    /* rounding: keep both */
        }
        if (in_below)
            below[nb++] = list[j];
        if (in_above)
            above[na++] = list[j];
    }
    if (kd_stopped(b, (size_t)n))
        return;
    memmove(list, above, (size_t)na * sizeof *list);
    memmove(list + na, below, (size_t)nb * sizeof *list);
    kd_build_node(b, off + (size_t)na, nb, lo, cut_hi, depth + 1);
    if (b->status != RT_OK || b->too_big)
        return;
    int upper = t->node_count;
    kd_build_node(b, off, na, cut_lo, hi, depth + 1);
    if (b->status != RT_OK || b->too_big)
        return;
    uint32_t sliver = (t->nodes[node + 1].bits | t->nodes[upper].bits) &
                      KD_SLIVER;
    t->nodes[node].at.split = split;
    t->nodes[node].bits = (uint32_t)upper << 3 | sliver | (uint32_t)axis;
}

/*
 * Each facet's box grown by `margin`, rounded outward to float, into
 * b->lo and b->hi, its sliver mark into sliver[], and the exact box of
 * all facets into lo..hi; 0 when cancelled.
 */
static int kd_facet_boxes(kd_builder *b, const KERNEL_T *k, double margin,
                          unsigned char *sliver)
{
    for (int i = 0; i < k->count; i++) {
        if (i % KD_POLL_WORK == 0 && kd_stopped(b, KD_POLL_WORK))
            return 0;
        const vec *p[3] = {&k->tris[i].a, &k->tris[i].b, &k->tris[i].c};
        double (*v)[3] = b->v[i];
        for (int j = 0; j < 3; j++) {
            v[j][0] = (double)p[j]->x;
            v[j][1] = (double)p[j]->y;
            v[j][2] = (double)p[j]->z;
        }
        sliver[i] = !(condition(v) <= OCTREE_CONDITION_MAX);
        for (int a = 0; a < 3; a++) {
            double low = v[0][a], high = v[0][a];
            for (int j = 1; j < 3; j++) {
                low = v[j][a] < low ? v[j][a] : low;
                high = v[j][a] > high ? v[j][a] : high;
            }
            /* one step outward covers the rounding of the sum */
            b->lo[i][a] = float_below(nextafter(low - margin, -INFINITY));
            b->hi[i][a] = float_above(nextafter(high + margin, INFINITY));
        }
    }
    return 1;
}

/*
 * The kd-tree of k's facets, with *status RT_OK; or NULL with *status
 * RT_ERR_NOMEM, or RT_ERR_CANCELLED once `cancel` (may be NULL) was
 * raised: a cancelled build frees what it made.
 */
static kdtree *kdtree_build(const KERNEL_T *k, const rt_cancel *cancel,
                            rt_status *status)
{
    double start = rt__clock_seconds();
    *status = RT_ERR_NOMEM;
    if (k->count >= KD_MAX_FACETS)
        return NULL;
    kdtree *t = calloc(1, sizeof *t);
    if (t == NULL)
        return NULL;
    kd_builder b = {0};
    size_t n = (size_t)k->count;
    b.tree = t;
    b.cancel = cancel;
    b.lo = malloc((n ? n : 1) * sizeof *b.lo);
    b.hi = malloc((n ? n : 1) * sizeof *b.hi);
    b.v = malloc((n ? n : 1) * sizeof *b.v);
    unsigned char *sliver = malloc(n ? n : 1);
    b.sliver = sliver;
    double size = 0, box_lo[3], box_hi[3];
    for (int a = 0; a < 3; a++) {
        box_lo[a] = INFINITY;
        box_hi[a] = -INFINITY;
    }
    for (int i = 0; i < k->count; i++) {
        const vec *p[3] = {&k->tris[i].a, &k->tris[i].b, &k->tris[i].c};
        for (int j = 0; j < 3; j++)
            for (int a = 0; a < 3; a++) {
                double x = (double)get(*p[j], a);
                box_lo[a] = x < box_lo[a] ? x : box_lo[a];
                box_hi[a] = x > box_hi[a] ? x : box_hi[a];
            }
    }
    for (int a = 0; a < 3 && k->count > 0; a++)
        size = box_hi[a] - box_lo[a] > size ? box_hi[a] - box_lo[a] : size;
    t->reach_margin = size * KD_MARGIN;
    double extent = 0;
    for (int a = 0; a < 3 && k->count > 0; a++) {
        extent = fabs(box_lo[a]) > extent ? fabs(box_lo[a]) : extent;
        extent = fabs(box_hi[a]) > extent ? fabs(box_hi[a]) : extent;
    }
    /* the octree's margin, rounding term included: the overlap test
     * computes the cells' centres (octree_impl.h, OCTREE_ROUNDING) */
    b.overlap_margin = fmax(t->reach_margin,
                            (extent + size) * OCTREE_ROUNDING);
    if (b.lo == NULL || b.hi == NULL || b.v == NULL || sliver == NULL)
        b.status = RT_ERR_NOMEM;
    else if (k->count == 0 || !(size * 4 < INFINITY))
        t->brute = 1;   /* nothing to list, or no room for cells */
    else if (kd_facet_boxes(&b, k, t->reach_margin, sliver)) {
        for (int a = 0; a < 3; a++) {
            t->lo[a] = INFINITY;
            t->hi[a] = -INFINITY;
        }
        for (int i = 0; i < k->count; i++)
            for (int a = 0; a < 3; a++) {
                t->lo[a] = b.lo[i][a] < t->lo[a] ? b.lo[i][a] : t->lo[a];
                t->hi[a] = b.hi[i][a] > t->hi[a] ? b.hi[i][a] : t->hi[a];
                t->sliver_count += a == 0 && sliver[i];
            }
        b.cap = (int)(KD_DEPTH_BASE + KD_DEPTH_SLOPE * log2((double)n));
        if (b.cap > KD_MAX_DEPTH)
            b.cap = KD_MAX_DEPTH;
        b.limit = (size_t)KD_REFERENCE_LIMIT * n + KD_REFERENCE_EXTRA;
        for (;;) {
            t->node_count = t->leaf_count = t->depth = 0;
            t->ref_count = 0;
            b.stored = 0;
            b.too_big = 0;
            if (!kd_grow((void **)&b.lists, &b.list_capacity, n,
                         sizeof *b.lists, &b))
                break;
            for (size_t i = 0; i < n; i++)
                b.lists[i] = (int32_t)i;
            kd_build_node(&b, 0, (int)n, t->lo, t->hi, 0);
            if (!b.too_big || b.status != RT_OK)
                break;
            b.cap = b.cap > KD_DEPTH_RETRY ? b.cap - KD_DEPTH_RETRY : 0;
        }
    }
    free(b.lo);
    free(b.hi);
    free(b.v);
    free(sliver);
    free(b.lists);
    free(b.keys);
    if (b.status == RT_OK && !(b.too_big)) {
        t->bytes = sizeof *t + (size_t)t->node_count * sizeof *t->nodes +
                   b.stored * sizeof *t->refs;
        t->build_seconds = rt__clock_seconds() - start;
        *status = RT_OK;
        return t;
    }
    *status = b.status == RT_OK ? RT_ERR_NOMEM : b.status;
    kdtree_free(t);
    return NULL;
}
