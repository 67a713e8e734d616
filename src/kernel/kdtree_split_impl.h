/*
 * kdtree_split_impl.h - the kd-tree's build at one node and below it:
 * the sweep that chooses a node's plane by the surface area heuristic,
 * the split of its sorted lists into its children's, and the depth-first
 * build of a subtree (part of kernel_impl.h, compiled once per precision;
 * everything here is static).  kdtree_build_impl.h builds the whole tree
 * from these parts - the root's sort, the tasks on several threads, the
 * layout - and says why the result is exact and the same on any number of
 * threads.
 */


/*
 * A node of at most this many facets (or, in a scene of many, at most a
 * KD_TASK_SHARE-th of them) is built as one task: large enough that a
 * task's work dwarfs taking it, small enough that tasks outnumber the
 * threads many times over and the last ones end together.
 */
#define KD_TASK_FACETS 2048
#define KD_TASK_SHARE 256

/*
 * A node's facets, as the lists of one block of int32_t: first every
 * facet, ascending (the leaf's list); then, for each axis a, the facets
 * whose box has an extent on a ordered by their lower bound (s[a] of
 * them), the same ordered by their upper bound, and those flat on a
 * ordered by their bound (n - s[a]).
 */
typedef struct kd_shape {
    int n;
    int s[3];
} kd_shape;

static size_t kd_block_size(kd_shape sh)
{
    return 4 * (size_t)sh.n + (size_t)sh.s[0] + (size_t)sh.s[1] +
           (size_t)sh.s[2];
}

/* What every part of one build reads, and the counts it shares. */
typedef struct kd_shared {
    float (*lo)[3], (*hi)[3];   /* each facet's grown box, in float */
    const tri *tris;        /* the facets (their vertices: kd_corners) */
    unsigned char *sliver;
    double overlap_margin;  /* the octree's margin, for the overlap test */
    double traverse;        /* the SAH's K_T for this tree's size */
    int facets;
    int task_facets;        /* nodes at or below it are tasks */
    int cap;                /* the depth cap */
    size_t node_limit, ref_limit;
    const rt_cancel *cancel;    /* NULL: the build cannot be cancelled */
    atomic_size_t nodes_used, refs_used;
    atomic_int too_big;     /* a limit was passed: redo with a lower cap */
    atomic_int stop;        /* cancelled or out of memory somewhere */
} kd_shared;

struct kd_task;

/* One part of a build: the top, split on the calling thread, or a task's
 * subtree. */
typedef struct kd_builder {
    kd_shared *sh;
    kdnode *nodes;
    size_t node_count, node_capacity;
    int32_t *refs;          /* the leaves' lists of more than one facet */
    size_t stored, ref_capacity;
    int32_t *lists;         /* the blocks of the nodes waiting, then the
                               one being split (in pages) */
    size_t list_capacity;
    float *keys;            /* the sweep's bounds in order: 3 n */
    size_t key_capacity;
    unsigned char *side;    /* for each facet of the node being split: 1
                               below, 2 above, 3 both */
    int top;                /* the top: its leaves are tasks' roots */
    struct kd_task *tasks;
    size_t task_count, task_capacity;
    int depth;
    size_t work;            /* units of work since the flag was read */
    rt_status status;       /* RT_OK, RT_ERR_NOMEM or RT_ERR_CANCELLED */
} kd_builder;

/* A subtree to build: its node's block and cell; then what built it. */
typedef struct kd_task {
    int32_t *node_lists;    /* in pages (base/pages.h) */
    size_t list_capacity;
    kd_shape shape;
    double lo[3], hi[3];
    int depth;
    kd_builder b;
} kd_task;

/* Non-zero once this part must stop: cancelled, out of memory, or a limit
 * passed here or elsewhere.  Counts `amount` units of work and, every
 * KD_POLL_WORK of them, reads the cancellation flag. */
static int kd_stopped(kd_builder *b, size_t amount)
{
    b->work += amount;
    if (b->work >= KD_POLL_WORK) {
        b->work = 0;
        if (b->status == RT_OK && b->sh->cancel != NULL &&
            rt_cancel_requested(b->sh->cancel))
            b->status = RT_ERR_CANCELLED;
        if (b->status != RT_OK)
            atomic_store_explicit(&b->sh->stop, 1, memory_order_relaxed);
    }
    return b->status != RT_OK ||
           atomic_load_explicit(&b->sh->stop, memory_order_relaxed) ||
           atomic_load_explicit(&b->sh->too_big, memory_order_relaxed);
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

/* Facet i's vertices in double (exact in either precision), as the
 * overlap tests read them. */
static void kd_corners(const kd_shared *s, int32_t i, double v[3][3])
{
    const tri *f = &s->tris[i];
    const vec *p[3] = {&f->a, &f->b, &f->c};
    for (int c = 0; c < 3; c++) {
        v[c][0] = (double)p[c]->x;
        v[c][1] = (double)p[c]->y;
        v[c][2] = (double)p[c]->z;
    }
}

static int kd_fail(kd_builder *b)
{
    b->status = RT_ERR_NOMEM;
    atomic_store_explicit(&b->sh->stop, 1, memory_order_relaxed);
    return 0;
}

/* Grows a builder's nodes, references or lists, the big arrays a build
 * holds until its layout copies them (or its task ends): in pages of
 * their own (base/pages.h), so that each gives its memory back at once. */
static int kd_grow_pages(void **array, size_t *capacity, size_t needed,
                         size_t size, kd_builder *b)
{
    return rt__pages_grow(array, capacity, needed, size) || kd_fail(b);
}

static int kd_grow(void **array, size_t *capacity, size_t needed,
                   size_t size, kd_builder *b)
{
    if (grow(array, capacity, needed, size))
        return 1;
    b->status = RT_ERR_NOMEM;
    atomic_store_explicit(&b->sh->stop, 1, memory_order_relaxed);
    return 0;
}

/* What a sweep on one axis of one cell keeps: the cell, its areas, the
 * best plane so far. */
typedef struct kd_sweep {
    double lo, hi;          /* the cell on the axis */
    double other_sum, other_product;    /* of the other two extents */
    double scale;           /* K_I over the cell's half area */
    double traverse;        /* K_T (kd_shared) */
    double *cost;
    int *axis;
    float *split;
    int a;
} kd_sweep;

/* The SAH's cost of plane p with `below` and `above` facets on its sides,
 * kept if below *cost. */
static inline void kd_consider(kd_sweep *w, float p, int below, int above)
{
    double x = (double)p;
    if (!(x > w->lo && x < w->hi))
        return;
    double below_area = (x - w->lo) * w->other_sum + w->other_product;
    double above_area = (w->hi - x) * w->other_sum + w->other_product;
    double c = (below_area * below + above_area * above) * w->scale;
    if (below == 0 || above == 0)
        c *= KD_EMPTY_BONUS;
    c += w->traverse;
    if (c < *w->cost) {
        *w->cost = c;
        *w->axis = w->a;
        *w->split = p;
    }
}

/*
 * The best plane on axis a of the cell lo..hi for the node's facets
 * (node_lists, shape sh), if cheaper than *cost: *cost, *axis and *split
 * updated.  The block's lists for a are in order, so one pass over them
 * sees every bound from the lowest up.  Below a plane p: the boxes
 * starting before p and the flat ones at or before it; above: the boxes
 * ending after p and the flat ones at or after it.
 */
static void sweep(kd_builder *b, const int32_t *node_lists, kd_shape sh,
                  const double lo[3], const double hi[3], int a,
                  double *cost, int *axis, float *split)
{
    const int32_t *list = node_lists + sh.n;
    for (int e = 0; e < a; e++)
        list += sh.n + sh.s[e];
    int ns = sh.s[a], nf = sh.n - ns;
    float *starts = b->keys, *ends = b->keys + ns, *flat = b->keys + 2 * ns;
    for (int j = 0; j < ns; j++) {
        starts[j] = b->sh->lo[list[j]][a];
        ends[j] = b->sh->hi[list[ns + j]][a];
    }
    for (int j = 0; j < nf; j++)
        flat[j] = b->sh->lo[list[2 * ns + j]][a];
    int a1 = (a + 1) % 3, a2 = (a + 2) % 3;
    double d1 = hi[a1] - lo[a1], d2 = hi[a2] - lo[a2], da = hi[a] - lo[a];
    kd_sweep w = {lo[a], hi[a], d1 + d2, d1 * d2,
                  KD_COST_INTERSECT / (da * (d1 + d2) + d1 * d2),
                  b->sh->traverse, cost, axis, split, a};
    int cs = 0, ce = 0, cf = 0;
    if (nf == 0) {
        /* no flat box (the usual case): two lists; every box ends after
         * it starts, so the ends are the last to run out */
        while (ce < ns) {
            float p = cs < ns && starts[cs] < ends[ce] ? starts[cs]
                                                       : ends[ce];
            int starts_before = cs;
            while (cs < ns && starts[cs] == p)
                cs++;
            while (ce < ns && ends[ce] == p)
                ce++;
            kd_consider(&w, p, starts_before, ns - ce);
        }
        return;
    }
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
        kd_consider(&w, p, starts_before + cf, (ns - ce) + (nf - flat_before));
    }
}

/* A new node (its fields set later); -1 when out of memory or past the
 * limit. */
static int kd_new_node(kd_builder *b)
{
    if (atomic_fetch_add_explicit(&b->sh->nodes_used, 1,
                                  memory_order_relaxed) >= b->sh->node_limit) {
        atomic_store_explicit(&b->sh->too_big, 1, memory_order_relaxed);
        return -1;
    }
    if (!kd_grow_pages((void **)&b->nodes, &b->node_capacity,
                       b->node_count + 1, sizeof *b->nodes, b))
        return -1;
    return (int)b->node_count++;
}

static void kd_make_leaf(kd_builder *b, int node, const int32_t *list, int n)
{
    uint32_t sliver = 0;
    for (int j = 0; j < n; j++)
        sliver |= b->sh->sliver[list[j]];
    b->nodes[node].bits = (uint32_t)n << 3 | (sliver ? KD_SLIVER : 0) |
                          KD_LEAF;
    if (atomic_fetch_add_explicit(&b->sh->refs_used, (size_t)n,
                                  memory_order_relaxed) +
            (size_t)n > b->sh->ref_limit) {
        atomic_store_explicit(&b->sh->too_big, 1, memory_order_relaxed);
        return;
    }
    if (n == 1) {
        b->nodes[node].at.first = (uint32_t)list[0];
    } else {
        if (n > 0 && !kd_grow_pages((void **)&b->refs, &b->ref_capacity,
                                    b->stored + (size_t)n, sizeof *b->refs,
                                    b))
            return;
        if (n > 0)
            memcpy(b->refs + b->stored, list, (size_t)n * sizeof *list);
        b->nodes[node].at.first = (uint32_t)b->stored;
        b->stored += (size_t)n;
    }
}

/* Makes node a task's root: its block copied out, its cell kept. */
static void kd_make_task(kd_builder *b, int node, const int32_t *node_lists,
                         kd_shape sh, const double lo[3], const double hi[3],
                         int depth)
{
    if (!kd_grow((void **)&b->tasks, &b->task_capacity, b->task_count + 1,
                 sizeof *b->tasks, b))
        return;
    kd_task *task = &b->tasks[b->task_count];
    memset(task, 0, sizeof *task);
    size_t size = kd_block_size(sh);
    void *pages = NULL;
    if (!kd_grow_pages(&pages, &task->list_capacity, size ? size : 1,
                       sizeof *node_lists, b))
        return;
    task->node_lists = pages;
    memcpy(task->node_lists, node_lists, size * sizeof *node_lists);
    task->shape = sh;
    memcpy(task->lo, lo, sizeof task->lo);
    memcpy(task->hi, hi, sizeof task->hi);
    task->depth = depth;
    b->nodes[node].bits = KD_LEAF;  /* in the top, a leaf is a task */
    b->nodes[node].at.first = (uint32_t)b->task_count++;
}

/* Non-zero when a vertex of the triangle v lies in the box of centre c
 * and half sizes h: the triangle overlaps the box, and the test costs a
 * fraction of the separating axes' (a listing it adds is a true one, so
 * it can only list more, never less). */
static int vertex_inside(const double c[3], const double h[3],
                         double v[3][3])
{
    for (int j = 0; j < 3; j++)
        if (fabs(v[j][0] - c[0]) <= h[0] && fabs(v[j][1] - c[1]) <= h[1] &&
            fabs(v[j][2] - c[2]) <= h[2])
            return 1;
    return 0;
}

/*
 * The children's blocks of the node (node_lists, shape sh) split at `split` on
 * `axis`: below's at `below`, above's at `above`, their shapes in *sb and
 * *sa.  Each list is filtered in order, so each stays in its order.
 */
static void kd_partition(kd_builder *b, const int32_t *node_lists, kd_shape sh,
                         int axis, float split, const double lo[3],
                         const double hi[3], int32_t *below, kd_shape *sb,
                         int32_t *above, kd_shape *sa)
{
    const kd_shared *s = b->sh;
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
        h_below[a] = (cut_hi[a] - lo[a]) * 0.5 + s->overlap_margin;
        c_above[a] = cut_lo[a] + (hi[a] - cut_lo[a]) * 0.5;
        h_above[a] = (hi[a] - cut_lo[a]) * 0.5 + s->overlap_margin;
        finite &= isfinite(h_below[a]) && isfinite(h_above[a]) &&
                  isfinite(c_below[a]) && isfinite(c_above[a]);
    }
    int nb = 0, na = 0;
    for (int j = 0; j < sh.n; j++) {
        int32_t i = node_lists[j];
        double l = s->lo[i][axis], h = s->hi[i][axis];
        int in_below = l < p || h <= p, in_above = h > p || l >= p;
        if (in_below && in_above && finite) {
            /* a box that straddles the plane: the facet itself may miss
             * one side (Akenine-Moller's test, as the octree's listing) */
            double v[3][3];
            kd_corners(s, i, v);
            in_below = vertex_inside(c_below, h_below, v) ||
                       triangle_box_overlap(c_below, h_below, v);
            in_above = vertex_inside(c_above, h_above, v) ||
                       triangle_box_overlap(c_above, h_above, v);
            if (!in_below && !in_above)
                in_below = in_above = 1;    /* rounding: keep both */
        }
        b->side[i] = (unsigned char)(in_below | in_above << 1);
        if (in_below)
            below[nb++] = i;
        if (in_above)
            above[na++] = i;
    }
    sb->n = nb;
    sa->n = na;
    int32_t *wb = below + nb, *wa = above + na;
    const int32_t *list = node_lists + sh.n;
    for (int a = 0; a < 3; a++) {
        int counts[3] = {sh.s[a], sh.s[a], sh.n - sh.s[a]};
        for (int part = 0; part < 3; part++) {
            int kb = 0, ka = 0;
            for (int j = 0; j < counts[part]; j++) {
                int32_t i = list[j];
                wb[kb] = i;
                kb += b->side[i] & 1;
                wa[ka] = i;
                ka += b->side[i] >> 1;
            }
            if (part == 0) {
                sb->s[a] = kb;
                sa->s[a] = ka;
            }
            list += counts[part];
            wb += kb;
            wa += ka;
        }
    }
}

/*
 * Builds the subtree of the cell lo..hi whose facets are the block at
 * b->lists + off, the last block there.  The children's blocks go after
 * it and are then moved down, the one above the plane first, so that
 * while the subtree below is built the block above waits beneath it.  In
 * the top, a node of at most task_facets facets, or one that would be a
 * leaf, becomes a task instead.
 */
static void kd_build_node(kd_builder *b, size_t off, kd_shape sh,
                          const double lo[3], const double hi[3], int depth)
{
    int node = kd_new_node(b);
    if (node < 0 || kd_stopped(b, (size_t)sh.n))
        return;
    if (b->top && sh.n <= b->sh->task_facets) {
        kd_make_task(b, node, b->lists + off, sh, lo, hi, depth);
        return;
    }
    if (depth > b->depth)
        b->depth = depth;
    double cost = KD_COST_INTERSECT * sh.n;
    int axis = -1;
    float split = 0;
    if (sh.n > 0 && depth < b->sh->cap) {
        if (!kd_grow((void **)&b->keys, &b->key_capacity, 3 * (size_t)sh.n,
                     sizeof *b->keys, b))
            return;
        for (int a = 0; a < 3; a++)
            if (hi[a] > lo[a]) {
                sweep(b, b->lists + off, sh, lo, hi, a, &cost, &axis,
                      &split);
                if (kd_stopped(b, (size_t)sh.n))
                    return;
            }
    }
    if (axis < 0) {
        if (b->top)
            kd_make_task(b, node, b->lists + off, sh, lo, hi, depth);
        else
            kd_make_leaf(b, node, b->lists + off, sh.n);
        return;
    }
    size_t size = kd_block_size(sh), top = off + size;
    if (!kd_grow_pages((void **)&b->lists, &b->list_capacity, top + 2 * size,
                 sizeof *b->lists, b))
        return;
    kd_shape sb, sa;
    int32_t *below = b->lists + top, *above = b->lists + top + size;
    kd_partition(b, b->lists + off, sh, axis, split, lo, hi, below, &sb,
                 above, &sa);
    if (kd_stopped(b, 4 * (size_t)sh.n))
        return;
    size_t size_a = kd_block_size(sa), size_b = kd_block_size(sb);
    memmove(b->lists + off, above, size_a * sizeof *above);
    memmove(b->lists + off + size_a, below, size_b * sizeof *below);
    double cut_hi[3] = {hi[0], hi[1], hi[2]}, cut_lo[3] = {lo[0], lo[1], lo[2]};
    cut_hi[axis] = (double)split;
    cut_lo[axis] = (double)split;
    kd_build_node(b, off + size_a, sb, lo, cut_hi, depth + 1);
    if (kd_stopped(b, 0))
        return;
    int upper = (int)b->node_count;
    kd_build_node(b, off, sa, cut_lo, hi, depth + 1);
    if (kd_stopped(b, 0))
        return;
    b->nodes[node].at.split = split;
    b->nodes[node].bits = (uint32_t)upper << 3 | (uint32_t)axis;
}

/* Gives back a builder's nodes and references (after the layout). */
static void kd_builder_release(kd_builder *b)
{
    rt__pages_free(b->nodes, b->node_capacity, sizeof *b->nodes);
    rt__pages_free(b->refs, b->ref_capacity, sizeof *b->refs);
    b->nodes = NULL;
    b->refs = NULL;
    b->node_capacity = b->ref_capacity = 0;
}

static void kd_builder_free(kd_builder *b)
{
    kd_builder_release(b);
    rt__pages_free(b->lists, b->list_capacity, sizeof *b->lists);
    free(b->keys);
    free(b->side);
    for (size_t j = 0; j < b->task_count; j++) {
        rt__pages_free(b->tasks[j].node_lists, b->tasks[j].list_capacity,
                       sizeof *b->tasks[j].node_lists);
        kd_builder_free(&b->tasks[j].b);
    }
    free(b->tasks);
}

