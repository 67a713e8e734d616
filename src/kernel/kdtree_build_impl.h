/*
 * kdtree_build_impl.h - the construction of the kd-tree of kdtree_impl.h
 * (part of kernel_impl.h, compiled once per precision; everything here is
 * static).
 *
 * Each facet is represented by its bounding box grown by the margin and
 * rounded outward to float ("plain" bounds, not clipped to the cell: a
 * superset of the clipped ones, so conservative).  A node's plane is
 * chosen by the surface area heuristic over every bound of its facets on
 * each axis, by a sweep of the bounds in order.  A facet goes below a
 * plane p when its box starts before p (or lies wholly at or below it),
 * above when it ends after p (or lies wholly at or above it); one whose
 * box straddles p goes to each side whose cell, grown by the octree's
 * margin, the triangle itself overlaps (the octree's triangle-box test),
 * so a facet crossing a cell's corner is not listed where only its box
 * reaches (why all this suffices: docs/kdtree.md, "Listing").
 *
 * O(N log N), after Wald and Havran (2006, section 4.3): the bounds are
 * sorted once, at the root, on each axis (a radix sort); a node's sorted
 * lists are split into its children's by a stable filter, so they stay
 * sorted and a node costs time linear in its facets.  The plain bounds
 * make this exact: a facet's bounds are the same in every cell it is
 * listed in, so the filtered lists are the ones a sort would give.
 *
 * In parallel, the same tree for any thread count: the nodes of more than
 * KD_TASK_FACETS facets are split first, on the calling thread; each node
 * at or below that size is then a task, whose subtree the threads build
 * on their own, taking tasks in turn; the subtrees are finally laid out in
 * the order a depth-first build gives.  What a task builds depends only on
 * its facets and cell, never on the thread that takes it or when.
 * kdtree_impl.h lists the bounds, each with its reason; the build polls
 * the cancellation flag as it goes and keeps nothing half built.
 */

/*
 * A node of at most this many facets (or, in a scene of many, at most a
 * KD_TASK_SHARE-th of them) is built as one task: large enough that a
 * task's work dwarfs taking it, small enough that tasks outnumber the
 * threads many times over and the last ones end together.
 */
#define KD_TASK_FACETS 2048
#define KD_TASK_SHARE 256
/* The facets a thread prepares at a time (their boxes), a job. */
#define KD_BOX_CHUNK 16384

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
    double (*v)[3][3];      /* each facet's vertices, in double */
    unsigned char *sliver;
    double overlap_margin;  /* the octree's margin, for the overlap test */
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
                               one being split */
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
    int32_t *node_lists;
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

/* Surface area of a box of extents d, up to the factor 2. */
static double half_area(const double d[3])
{
    return d[0] * d[1] + d[1] * d[2] + d[2] * d[0];
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

/*
 * The best plane on axis a of the cell lo..hi for the node's facets
 * (node_lists, shape sh), if cheaper than *cost: *cost, *axis and *split
 * updated.  The block's lists for a are in order, so one pass over them
 * sees every bound from the lowest up.
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

/* A new node (its fields set later); -1 when out of memory or past the
 * limit. */
static int kd_new_node(kd_builder *b)
{
    if (atomic_fetch_add_explicit(&b->sh->nodes_used, 1,
                                  memory_order_relaxed) >= b->sh->node_limit) {
        atomic_store_explicit(&b->sh->too_big, 1, memory_order_relaxed);
        return -1;
    }
    if (!kd_grow((void **)&b->nodes, &b->node_capacity, b->node_count + 1,
                 sizeof *b->nodes, b))
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
        if (n > 0 && !kd_grow((void **)&b->refs, &b->ref_capacity,
                              b->stored + (size_t)n, sizeof *b->refs, b))
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
    task->node_lists = malloc((size ? size : 1) * sizeof *node_lists);
    if (task->node_lists == NULL) {
        b->status = RT_ERR_NOMEM;
        return;
    }
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
            in_below = vertex_inside(c_below, h_below, s->v[i]) ||
                       triangle_box_overlap(c_below, h_below, s->v[i]);
            in_above = vertex_inside(c_above, h_above, s->v[i]) ||
                       triangle_box_overlap(c_above, h_above, s->v[i]);
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
    if (!kd_grow((void **)&b->lists, &b->list_capacity, top + 2 * size,
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

static void kd_builder_free(kd_builder *b)
{
    free(b->nodes);
    free(b->refs);
    free(b->lists);
    free(b->keys);
    free(b->side);
    for (size_t j = 0; j < b->task_count; j++) {
        free(b->tasks[j].node_lists);
        kd_builder_free(&b->tasks[j].b);
    }
    free(b->tasks);
}

/*
 * Jobs for the threads of one build step: job(argument, j) for every j in
 * [0, count), each run once, by whichever thread takes it first.  The
 * results must not depend on which thread ran a job.
 */
typedef struct kd_jobs {
    void (*job)(void *argument, size_t j, unsigned char *scratch);
    void *argument;
    size_t count;
    size_t scratch;         /* bytes of scratch each thread gets */
    atomic_size_t next;
} kd_jobs;

static void kd_jobs_thread(void *argument)
{
    kd_jobs *jobs = argument;
    unsigned char *scratch = NULL;
    if (jobs->scratch > 0 && (scratch = malloc(jobs->scratch)) == NULL)
        return;     /* the other threads take the jobs */
    size_t j;
    while ((j = atomic_fetch_add(&jobs->next, 1)) < jobs->count)
        jobs->job(jobs->argument, j, scratch);
    free(scratch);
}

/* Runs the jobs on `threads` threads of `workers` (base/workers.h) and
 * waits for them; 0 when some could not run (out of memory). */
static int kd_run(rt_workers *workers, int threads, kd_jobs *jobs)
{
    atomic_init(&jobs->next, 0);
    if ((size_t)threads > jobs->count)
        threads = jobs->count > 0 ? (int)jobs->count : 1;
    rt__workers_run(threads > 1 ? workers : NULL, threads, kd_jobs_thread,
                    jobs);
    /* every thread without scratch: jobs left untaken */
    return atomic_load(&jobs->next) >= jobs->count;
}

/* The build of a whole tree: its shared inputs and what the jobs fill. */
typedef struct kd_build {
    kd_shared sh;
    const KERNEL_T *k;
    double margin;
    int32_t *root;          /* the root's block */
    kd_shape shape;         /* the root's */
    size_t offset[3];       /* where the root's lists of each axis start */
    kd_builder *top;
} kd_build;

/* Job j of the boxes: facets j * KD_BOX_CHUNK on, their vertices, boxes
 * grown by the margin and rounded outward to float, and sliver marks. */
static void kd_boxes_job(void *argument, size_t j, unsigned char *scratch)
{
    (void)scratch;
    kd_build *w = argument;
    kd_shared *s = &w->sh;
    size_t end = (j + 1) * KD_BOX_CHUNK;
    if (end > (size_t)s->facets)
        end = (size_t)s->facets;
    if (s->cancel != NULL && rt_cancel_requested(s->cancel)) {
        atomic_store(&s->stop, 1);
        return;
    }
    for (size_t i = j * KD_BOX_CHUNK; i < end; i++) {
        const KERNEL_T *k = w->k;
        const vec *p[3] = {&k->tris[i].a, &k->tris[i].b, &k->tris[i].c};
        double (*v)[3] = s->v[i];
        for (int c = 0; c < 3; c++) {
            v[c][0] = (double)p[c]->x;
            v[c][1] = (double)p[c]->y;
            v[c][2] = (double)p[c]->z;
        }
        s->sliver[i] = !(condition(v) <= OCTREE_CONDITION_MAX);
        for (int a = 0; a < 3; a++) {
            double low = v[0][a], high = v[0][a];
            for (int c = 1; c < 3; c++) {
                low = v[c][a] < low ? v[c][a] : low;
                high = v[c][a] > high ? v[c][a] : high;
            }
            /* one step outward covers the rounding of the sum */
            s->lo[i][a] = float_below(nextafter(low - w->margin, -INFINITY));
            s->hi[i][a] = float_above(nextafter(high + w->margin, INFINITY));
        }
    }
}

/* A float's bits as an unsigned key in the floats' order. */
static uint32_t float_key(float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    return u & 0x80000000u ? ~u : u | 0x80000000u;
}

/* Sorts ids[0 .. n) by box[id][a], stably: an LSD radix sort of the
 * pairs (key, id), a byte of the key a pass; tmp holds 2 n pairs. */
static void kd_sort(int32_t *ids, uint64_t *tmp, size_t n,
                    float (*box)[3], int a)
{
    uint64_t *from = tmp, *to = tmp + n;
    if (n == 0)
        return;
    for (size_t j = 0; j < n; j++)
        from[j] = (uint64_t)float_key(box[ids[j]][a]) << 32 |
                  (uint32_t)ids[j];
    for (int shift = 32; shift < 64; shift += 8) {
        size_t count[257] = {0};
        for (size_t j = 0; j < n; j++)
            count[(from[j] >> shift & 255u) + 1]++;
        if (count[(from[0] >> shift & 255u) + 1] == n)
            continue;       /* one byte for all: the pass changes nothing */
        for (int d = 0; d < 256; d++)
            count[d + 1] += count[d];
        for (size_t j = 0; j < n; j++)
            to[count[from[j] >> shift & 255u]++] = from[j];
        uint64_t *swap = from;
        from = to;
        to = swap;
    }
    for (size_t j = 0; j < n; j++)
        ids[j] = (int32_t)(uint32_t)from[j];
}

/* Job a of the root: its lists on axis a, at their place in the root's
 * block (w->offset[a]), made in order of facet and then sorted. */
static void kd_root_job(void *argument, size_t a, unsigned char *scratch)
{
    kd_build *w = argument;
    kd_shared *s = &w->sh;
    size_t n = (size_t)s->facets, ns = (size_t)w->shape.s[a];
    int32_t *starts = w->root + w->offset[a], *ends = starts + ns,
            *flat = ends + ns;
    uint64_t *tmp = (uint64_t *)(void *)scratch;
    size_t js = 0, jf = 0;
    for (size_t i = 0; i < n; i++) {
        if (s->lo[i][a] != s->hi[i][a])
            starts[js++] = (int32_t)i;
        else
            flat[jf++] = (int32_t)i;
    }
    memcpy(ends, starts, ns * sizeof *ends);
    kd_sort(starts, tmp, ns, s->lo, (int)a);
    kd_sort(ends, tmp, ns, s->hi, (int)a);
    kd_sort(flat, tmp, jf, s->lo, (int)a);
}

/* Job j of the subtrees: task j built by this thread, its builder's
 * scratch freed (its nodes and references kept for the layout). */
static void kd_task_job(void *argument, size_t j, unsigned char *scratch)
{
    kd_build *w = argument;
    kd_task *task = &w->top->tasks[j];
    kd_builder *b = &task->b;
    b->sh = &w->sh;
    b->side = scratch;
    b->lists = task->node_lists;         /* the block is the builder's now */
    b->list_capacity = kd_block_size(task->shape);
    task->node_lists = NULL;
    kd_build_node(b, 0, task->shape, task->lo, task->hi, task->depth);
    free(b->lists);
    free(b->keys);
    b->lists = NULL;
    b->keys = NULL;
    b->side = NULL;
}

/*
 * Lays out node i of src (a task's root, when src is the top and node i
 * one of its leaves) and its subtree at t's next node, depth first with
 * the subtree below a node right after it: the layout a build on one
 * thread gives.  Returns the node's index in t.
 */
static uint32_t kd_emit(kdtree *t, size_t *stored, const kd_builder *src,
                        uint32_t i)
{
    const kdnode *n = &src->nodes[i];
    if (src->top && kd_is_leaf(n))
        return kd_emit(t, stored, &src->tasks[n->at.first].b, 0);
    uint32_t out = (uint32_t)t->node_count++;
    if (kd_is_leaf(n)) {
        uint32_t count = kd_payload(n);
        t->nodes[out] = *n;
        if (count > 1) {
            memcpy(t->refs + *stored, src->refs + n->at.first,
                   count * sizeof *t->refs);
            t->nodes[out].at.first = (uint32_t)*stored;
            *stored += count;
        }
        t->leaf_count++;
        t->ref_count += count;
        return out;
    }
    kd_emit(t, stored, src, i + 1);
    uint32_t upper = kd_emit(t, stored, src, kd_payload(n));
    t->nodes[out].at.split = n->at.split;
    t->nodes[out].bits = upper << 3 |
                         ((t->nodes[out + 1].bits | t->nodes[upper].bits) &
                          KD_SLIVER) |
                         (n->bits & 3u);
    return out;
}

/* FNV-1a over `size` bytes from `data`, from `hash` on: the tree's
 * fingerprint, by which tests see the same tree for any thread count. */
static uint64_t kd_digest(const void *data, size_t size, uint64_t hash)
{
    const unsigned char *byte = data;
    for (size_t j = 0; j < size; j++)
        hash = (hash ^ byte[j]) * 0x100000001b3u;
    return hash;
}

/* The status of a build's parts together: cancelled first, then out of
 * memory. */
static rt_status kd_status(const kd_builder *top)
{
    rt_status status = top->status;
    for (size_t j = 0; j < top->task_count; j++) {
        rt_status s = top->tasks[j].b.status;
        if (s == RT_ERR_CANCELLED || status == RT_OK)
            status = s == RT_OK ? status : s;
    }
    return status;
}

/*
 * One build of the tree under the depth cap w->sh.cap into t: RT_OK,
 * RT_ERR_NOMEM, RT_ERR_CANCELLED, or RT_OK with w->sh.too_big set when a
 * limit was passed (t then holds nothing).
 */
static rt_status kd_build_once(kd_build *w, kdtree *t, rt_workers *workers,
                               int threads)
{
    kd_shared *s = &w->sh;
    size_t n = (size_t)s->facets;
    atomic_init(&s->nodes_used, 0);
    atomic_init(&s->refs_used, 0);
    atomic_init(&s->too_big, 0);
    kd_builder top = {0};
    top.sh = s;
    top.top = 1;
    rt_status status = RT_ERR_NOMEM;
    w->shape.n = (int)n;
    size_t at = n;
    for (int a = 0; a < 3; a++) {
        size_t ns = 0;
        for (size_t i = 0; i < n; i++)
            ns += s->lo[i][a] != s->hi[i][a];
        w->shape.s[a] = (int)ns;
        w->offset[a] = at;
        at += n + ns;
    }
    top.side = malloc(n);
    if (top.side == NULL ||
        !kd_grow((void **)&top.lists, &top.list_capacity, at,
                 sizeof *top.lists, &top))
        goto done;
    w->root = top.lists;
    for (size_t i = 0; i < n; i++)
        w->root[i] = (int32_t)i;
    kd_jobs sorts = {kd_root_job, w, 3, 2 * n * sizeof(uint64_t)};
    if (!kd_run(workers, threads, &sorts))
        goto done;
    kd_build_node(&top, 0, w->shape, t->lo, t->hi, 0);
    free(top.lists);
    free(top.keys);
    top.lists = NULL;
    top.keys = NULL;
    w->top = &top;
    if (kd_status(&top) == RT_OK && !atomic_load(&s->too_big)) {
        kd_jobs tasks = {kd_task_job, w, top.task_count, n};
        if (!kd_run(workers, threads, &tasks))
            goto done;
    }
    status = kd_status(&top);
    if (status != RT_OK || atomic_load(&s->too_big))
        goto done;
    size_t nodes = top.node_count, refs = 0;
    t->depth = top.depth;
    for (size_t j = 0; j < top.task_count; j++) {
        const kd_builder *b = &top.tasks[j].b;
        nodes += b->node_count - 1;     /* less its stub in the top */
        refs += b->stored;
        t->depth = b->depth > t->depth ? b->depth : t->depth;
    }
    t->nodes = malloc(nodes * sizeof *t->nodes);
    t->refs = malloc((refs ? refs : 1) * sizeof *t->refs);
    if (t->nodes == NULL || t->refs == NULL) {
        status = RT_ERR_NOMEM;
        goto done;
    }
    size_t stored = 0;
    kd_emit(t, &stored, &top, 0);
    t->digest = kd_digest(t->nodes, nodes * sizeof *t->nodes,
                          kd_digest(t->refs, refs * sizeof *t->refs,
                                    0xcbf29ce484222325u));
    t->bytes = sizeof *t + nodes * sizeof *t->nodes + refs * sizeof *t->refs;
done:
    kd_builder_free(&top);
    w->top = NULL;
    return status;
}

/*
 * The kd-tree of k's facets, built on `threads` threads of `workers`
 * (may be NULL: threads of the call's own), the same tree for any count,
 * with *status RT_OK; or NULL with *status RT_ERR_NOMEM, or
 * RT_ERR_CANCELLED once `cancel` (may be NULL) was raised: a cancelled
 * build frees what it made.
 */
static kdtree *kdtree_build(const KERNEL_T *k, const rt_cancel *cancel,
                            rt_workers *workers, int threads,
                            rt_status *status)
{
    double start = rt__clock_seconds();
    *status = RT_ERR_NOMEM;
    if (k->count >= KD_MAX_FACETS)
        return NULL;
    kdtree *t = calloc(1, sizeof *t);
    kd_build *w = calloc(1, sizeof *w);
    if (t == NULL || w == NULL) {
        free(t);
        free(w);
        return NULL;
    }
    size_t n = (size_t)k->count;
    kd_shared *s = &w->sh;
    w->k = k;
    s->facets = k->count;
    s->cancel = cancel;
    atomic_init(&s->stop, 0);
    s->lo = malloc((n ? n : 1) * sizeof *s->lo);
    s->hi = malloc((n ? n : 1) * sizeof *s->hi);
    s->v = malloc((n ? n : 1) * sizeof *s->v);
    s->sliver = malloc(n ? n : 1);
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
    w->margin = t->reach_margin;
    double extent = 0;
    for (int a = 0; a < 3 && k->count > 0; a++) {
        extent = fabs(box_lo[a]) > extent ? fabs(box_lo[a]) : extent;
        extent = fabs(box_hi[a]) > extent ? fabs(box_hi[a]) : extent;
    }
    /* the octree's margin, rounding term included: the overlap test
     * computes the cells' centres (octree_impl.h, OCTREE_ROUNDING) */
    s->overlap_margin = fmax(t->reach_margin,
                             (extent + size) * OCTREE_ROUNDING);
    rt_status result = RT_OK;
    if (s->lo == NULL || s->hi == NULL || s->v == NULL || s->sliver == NULL) {
        result = RT_ERR_NOMEM;
    } else if (k->count == 0 || !(size * 4 < INFINITY)) {
        t->brute = 1;   /* nothing to list, or no room for cells */
    } else {
        kd_jobs boxes = {kd_boxes_job, w,
                         (n + KD_BOX_CHUNK - 1) / KD_BOX_CHUNK, 0};
        if (!kd_run(workers, threads, &boxes))
            result = RT_ERR_NOMEM;
        else if (atomic_load(&s->stop))
            result = RT_ERR_CANCELLED;
    }
    if (result == RT_OK && !t->brute) {
        for (int a = 0; a < 3; a++) {
            t->lo[a] = INFINITY;
            t->hi[a] = -INFINITY;
        }
        for (size_t i = 0; i < n; i++)
            for (int a = 0; a < 3; a++) {
                t->lo[a] = s->lo[i][a] < t->lo[a] ? s->lo[i][a] : t->lo[a];
                t->hi[a] = s->hi[i][a] > t->hi[a] ? s->hi[i][a] : t->hi[a];
            }
        for (size_t i = 0; i < n; i++)
            t->sliver_count += s->sliver[i];
        s->task_facets = (int)(n / KD_TASK_SHARE);
        if (s->task_facets < KD_TASK_FACETS)
            s->task_facets = KD_TASK_FACETS;
        s->cap = (int)(KD_DEPTH_BASE + KD_DEPTH_SLOPE * log2((double)n));
        if (s->cap > KD_MAX_DEPTH)
            s->cap = KD_MAX_DEPTH;
        size_t limit = (size_t)KD_REFERENCE_LIMIT * n + KD_REFERENCE_EXTRA;
        /* the nodes' 29-bit indices and the leaves' 32-bit offsets */
        s->node_limit = limit < KD_MAX_FACETS ? limit : KD_MAX_FACETS - 1;
        s->ref_limit = limit < UINT32_MAX ? limit : UINT32_MAX;
        for (;;) {
            result = kd_build_once(w, t, workers, threads);
            if (result != RT_OK || !atomic_load(&s->too_big))
                break;
            s->cap = s->cap > KD_DEPTH_RETRY ? s->cap - KD_DEPTH_RETRY : 0;
        }
    }
    free(s->lo);
    free(s->hi);
    free(s->v);
    free(s->sliver);
    free(w);
    if (result == RT_OK) {
        if (t->brute)
            t->bytes = sizeof *t;
        t->build_seconds = rt__clock_seconds() - start;
        *status = RT_OK;
        return t;
    }
    *status = result;
    kdtree_free(t);
    return NULL;
}
