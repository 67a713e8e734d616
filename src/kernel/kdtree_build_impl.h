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
 * the cancellation flag as it goes and keeps nothing half built.  The
 * work at one node - the sweep, the split, a subtree - is
 * kdtree_split_impl.h's.
 */

/* The facets a thread prepares at a time (their boxes), a job. */
#define KD_BOX_CHUNK 16384

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
        double v[3][3];
        kd_corners(s, (int32_t)i, v);
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
    b->list_capacity = task->list_capacity;
    task->node_lists = NULL;
    task->list_capacity = 0;
    kd_build_node(b, 0, task->shape, task->lo, task->hi, task->depth);
    rt__pages_free(b->lists, b->list_capacity, sizeof *b->lists);
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
    if (src->top && kd_is_leaf(n)) {
        kd_builder *task = &src->tasks[n->at.first].b;
        uint32_t root = kd_emit(t, stored, task, 0);
        /* copied: its pages go back now, so the tree is never held
         * twice */
        kd_builder_release(task);
        return root;
    }
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
        !kd_grow_pages((void **)&top.lists, &top.list_capacity, at,
                 sizeof *top.lists, &top))
        goto done;
    w->root = top.lists;
    for (size_t i = 0; i < n; i++)
        w->root[i] = (int32_t)i;
    kd_jobs sorts = {kd_root_job, w, 3, 2 * n * sizeof(uint64_t)};
    if (!kd_run(workers, threads, &sorts))
        goto done;
    kd_build_node(&top, 0, w->shape, t->lo, t->hi, 0);
    rt__pages_free(top.lists, top.list_capacity, sizeof *top.lists);
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
    /* The facets' boxes serve the splits only: freed before the layout's
     * copy (the peak of a big build). */
    free(s->lo);
    free(s->hi);
    free(s->sliver);
    s->lo = s->hi = NULL;
    s->sliver = NULL;
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
    s->tris = k->tris;
    s->traverse = n >= KD_LARGE_FACETS ? KD_COST_TRAVERSE_LARGE
                                       : KD_COST_TRAVERSE;
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
    if (s->lo == NULL || s->hi == NULL || s->sliver == NULL) {
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
