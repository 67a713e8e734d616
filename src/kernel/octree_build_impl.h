/*
 * octree_build_impl.h - the construction of the octree of octree_impl.h
 * (part of kernel_impl.h, compiled once per precision; everything here is
 * static).
 *
 * Breadth first, level by level: a node's facets are placed in each child
 * whose box, grown by the margin, the triangle overlaps - Akenine-Moller's
 * separating-axis test ("Fast 3D Triangle-Box Overlap Testing", 2001) - so
 * a facet touching a face, or one that rounding moves a little, is in both
 * cells.  octree_impl.h lists the bounds that stop a split, each with its
 * reason; the build polls the cancellation flag as it goes and keeps
 * nothing half built.
 */

/* --- the triangle-box test ------------------------------------------- */

static double cross_axis(const double e[3], int axis, const double v[3])
{
    /* (e x unit(axis)) . v */
    int i = (axis + 1) % 3, j = (axis + 2) % 3;
    return e[j] * v[i] - e[i] * v[j];
}

/* The least and the greatest of three values, none NaN (no libm call:
 * this is the builds' inner loop). */
static inline double least3(double a, double b, double c)
{
    double m = a < b ? a : b;
    return m < c ? m : c;
}

static inline double greatest3(double a, double b, double c)
{
    double m = a > b ? a : b;
    return m > c ? m : c;
}

/* Non-zero when the triangle v[3] overlaps the box of centre c and half
 * sizes h (Akenine-Moller's 13 axes).  Zero only when a separating axis is
 * found with a gap; callers grow h by the margin to absorb rounding. */
static int triangle_box_overlap(const double c[3], const double h[3],
                                double tv[3][3])
{
    double v[3][3], e[3][3];
    for (int i = 0; i < 3; i++)
        for (int a = 0; a < 3; a++)
            v[i][a] = tv[i][a] - c[a];
    for (int a = 0; a < 3; a++) {
        e[0][a] = v[1][a] - v[0][a];
        e[1][a] = v[2][a] - v[1][a];
        e[2][a] = v[0][a] - v[2][a];
    }
    for (int a = 0; a < 3; a++) {       /* the box's faces */
        double low = least3(v[0][a], v[1][a], v[2][a]);
        double high = greatest3(v[0][a], v[1][a], v[2][a]);
        if (low > h[a] || high < -h[a])
            return 0;
    }
    for (int k = 0; k < 3; k++)         /* edge x box axis */
        for (int a = 0; a < 3; a++) {
            int i = (a + 1) % 3, j = (a + 2) % 3;
            double p0 = cross_axis(e[k], a, v[0]);
            double p1 = cross_axis(e[k], a, v[1]);
            double p2 = cross_axis(e[k], a, v[2]);
            double r = h[i] * fabs(e[k][j]) + h[j] * fabs(e[k][i]);
            if (least3(p0, p1, p2) > r || greatest3(p0, p1, p2) < -r)
                return 0;
        }
    double n[3] = {e[0][1] * e[1][2] - e[0][2] * e[1][1],     /* the plane */
                   e[0][2] * e[1][0] - e[0][0] * e[1][2],
                   e[0][0] * e[1][1] - e[0][1] * e[1][0]};
    double d = n[0] * v[0][0] + n[1] * v[0][1] + n[2] * v[0][2];
    double r = h[0] * fabs(n[0]) + h[1] * fabs(n[1]) + h[2] * fabs(n[2]);
    return !(d > r || d < -r);
}

/* --- construction ---------------------------------------------------- */

typedef struct builder {
    double (*v)[3][3];      /* each facet's vertices, in double */
    octree *tree;
    size_t node_capacity, ref_capacity;
    size_t frontier;        /* references of the leaves if building
                               stopped now */
    size_t budget;
    const rt_cancel *cancel;    /* NULL: the build cannot be cancelled */
    size_t work;            /* facet placements since the flag was read */
    rt_status status;       /* RT_OK, RT_ERR_NOMEM or RT_ERR_CANCELLED */
} builder;

/* Counts `amount` units of work (a facet placed or examined) and, every
 * OCTREE_POLL_WORK of them, reads the cancellation flag; non-zero once
 * the build must stop (cancelled, or out of memory before). */
static int stopped(builder *b, size_t amount)
{
    b->work += amount;
    if (b->work >= OCTREE_POLL_WORK) {
        b->work = 0;
        if (b->status == RT_OK && b->cancel != NULL &&
            rt_cancel_requested(b->cancel))
            b->status = RT_ERR_CANCELLED;
    }
    return b->status != RT_OK;
}

static int grow(void **array, size_t *capacity, size_t needed, size_t size)
{
    if (needed <= *capacity)
        return 1;
    size_t capacity2 = *capacity ? *capacity : 64;
    while (capacity2 < needed)
        capacity2 *= 2;
    void *p = realloc(*array, capacity2 * size);
    if (p == NULL)
        return 0;
    *array = p;
    *capacity = capacity2;
    return 1;
}

static void make_leaf(builder *b, int node, const int32_t *list, int n)
{
    octree *t = b->tree;
    if (n > 0) {            /* (an empty leaf may have no list at all) */
        if (!grow((void **)&t->refs, &b->ref_capacity,
                  t->ref_count + (size_t)n, sizeof *t->refs)) {
            b->status = RT_ERR_NOMEM;
            return;
        }
        memcpy(t->refs + t->ref_count, list, (size_t)n * sizeof *list);
    }
    t->nodes[node] = (onode){(int32_t)t->ref_count, n};
    t->ref_count += (size_t)n;
    t->leaf_count++;
}


/* A node to build: its box and its facets (in the level's list). */
typedef struct todo {
    double lo[3], hi[3];
    size_t list;            /* offset of its facets in the level's list */
    int n;
    int node;
} todo;

/* A level of the breadth-first construction. */
typedef struct level {
    todo *items;
    size_t count, capacity;
    int32_t *refs;
    size_t ref_count, ref_capacity;
} level;

/*
 * Splits node `d` (facets list[0 .. d->n)) into eight children appended to
 * `next`, or makes it a leaf when splitting would not pay: too few facets,
 * too deep, too many references for what it separates, or the budget
 * spent.  Breadth first, so a spent budget leaves the deepest level
 * unsplit, not half the scene.
 */
static void build_node(builder *b, const todo *d, const int32_t *list,
                       int depth, level *next)
{
    octree *t = b->tree;
    int n = d->n;
    if (depth > t->depth)
        t->depth = depth;
    if (n <= OCTREE_LEAF_FACETS || depth >= OCTREE_MAX_DEPTH) {
        make_leaf(b, d->node, list, n);
        return;
    }
    if (stopped(b, (size_t)n))
        return;         /* the level is thrown away */
    size_t need = next->ref_count + (size_t)n * 8;
    if (!grow((void **)&next->refs, &next->ref_capacity, need,
              sizeof *next->refs) ||
        !grow((void **)&next->items, &next->capacity, next->count + 8,
              sizeof *next->items)) {
        b->status = RT_ERR_NOMEM;
        return;
    }
    double mid[3];
    for (int a = 0; a < 3; a++)
        mid[a] = d->lo[a] + (d->hi[a] - d->lo[a]) * 0.5;
    size_t start = next->ref_count, total = 0;
    todo children[8];
    double centre[8][3], half[8][3];
    for (int c = 0; c < 8; c++) {
        todo *ch = &children[c];
        child_box(d->lo, d->hi, mid, c, ch->lo, ch->hi);
        for (int a = 0; a < 3; a++) {
            centre[c][a] = ch->lo[a] + (ch->hi[a] - ch->lo[a]) * 0.5;
            half[c][a] = (ch->hi[a] - ch->lo[a]) * 0.5 + t->margin;
        }
        ch->n = 0;
    }
    /* Child c collects its facets at start + c n, then the lists are
     * packed.  A child the facet's bounding box clearly misses (by twice
     * the margin: the overlap test would reject it too) is not tested. */
    int32_t *region = next->refs + start;
    for (int i = 0; i < n; i++) {
        if (i % OCTREE_POLL_WORK == OCTREE_POLL_WORK - 1 &&
            stopped(b, OCTREE_POLL_WORK))
            return;     /* a large node: looked at within it too */
        double (*v)[3] = b->v[list[i]];
        unsigned sides[3];  /* bit 0: may be in the lower half, 1: upper */
        for (int a = 0; a < 3; a++) {
            double low = fmin(v[0][a], fmin(v[1][a], v[2][a]));
            double high = fmax(v[0][a], fmax(v[1][a], v[2][a]));
            sides[a] = (low <= mid[a] + 2 * t->margin) |
                       (high >= mid[a] - 2 * t->margin) << 1;
        }
        for (int c = 0; c < 8; c++) {
            if (!((sides[0] >> (c & 1)) & (sides[1] >> ((c >> 1) & 1)) &
                  (sides[2] >> ((c >> 2) & 1)) & 1))
                continue;
            if (triangle_box_overlap(centre[c], half[c], v))
                region[(size_t)c * (size_t)n + (size_t)children[c].n++] =
                    list[i];
        }
    }
    for (int c = 0; c < 8; c++) {
        children[c].list = start + total;
        memmove(next->refs + start + total, region + (size_t)c * (size_t)n,
                (size_t)children[c].n * sizeof *region);
        total += (size_t)children[c].n;
    }
    if (total > (size_t)OCTREE_SPLIT_GROWTH * (size_t)n ||
        b->frontier + total - (size_t)n > b->budget) {
        make_leaf(b, d->node, list, n);
        return;
    }
    if (!grow((void **)&t->nodes, &b->node_capacity,
              (size_t)t->node_count + 8, sizeof *t->nodes)) {
        b->status = RT_ERR_NOMEM;
        return;
    }
    b->frontier += total - (size_t)n;
    next->ref_count += total;
    t->nodes[d->node] = (onode){t->node_count, -1};
    for (int c = 0; c < 8; c++) {
        children[c].node = t->node_count + c;
        next->items[next->count++] = children[c];
    }
    t->node_count += 8;
}

/* Builds the tree under the root (facets list[0 .. n)), level by level. */
static void build_levels(builder *b, int32_t *list, int n)
{
    level cur = {0}, next = {0};
    cur.items = malloc(sizeof *cur.items);
    if (cur.items == NULL) {
        free(list);
        b->status = RT_ERR_NOMEM;
        return;
    }
    cur.capacity = 1;
    cur.count = 1;
    cur.refs = list;
    cur.ref_count = cur.ref_capacity = (size_t)n;
    cur.items[0] = (todo){{b->tree->lo[0], b->tree->lo[1], b->tree->lo[2]},
                          {b->tree->hi[0], b->tree->hi[1], b->tree->hi[2]},
                          0, n, 0};
    for (int depth = 0; cur.count > 0 && b->status == RT_OK; depth++) {
        next.count = 0;
        next.ref_count = 0;
        for (size_t i = 0; i < cur.count && b->status == RT_OK; i++)
            build_node(b, &cur.items[i], cur.refs + cur.items[i].list, depth,
                       &next);
        level swap = cur;
        cur = next;
        next = swap;
    }
    free(cur.items);
    free(cur.refs);
    free(next.items);
    free(next.refs);
}

/* Longest edge squared over twice the area: 1/sin of about the smallest
 * angle; large for slivers. */
static double condition(double v[3][3])
{
    double e[3][3], longest = 0;
    for (int k = 0; k < 3; k++) {
        double s = 0;
        for (int a = 0; a < 3; a++) {
            e[k][a] = v[(k + 1) % 3][a] - v[k][a];
            s += e[k][a] * e[k][a];
        }
        longest = fmax(longest, s);
    }
    double n[3] = {e[0][1] * e[1][2] - e[0][2] * e[1][1],
                   e[0][2] * e[1][0] - e[0][0] * e[1][2],
                   e[0][0] * e[1][1] - e[0][1] * e[1][0]};
    double area2 = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    return area2 > 0 ? longest / area2 : INFINITY;
}

/*
 * Marks the slivers (sliver[i] non-zero for facet i): puts them last in
 * each leaf's list (both parts keep their ascending order), counts them
 * per leaf and marks every internal node above one.  Children come after
 * their parent in t->nodes, so one pass from the end sees them first.
 * Returns 0 when out of memory.
 */
static int mark_slivers(octree *t, const unsigned char *sliver)
{
    t->slivers = calloc((size_t)t->node_count, sizeof *t->slivers);
    int32_t largest = 0;
    for (int i = 0; i < t->node_count; i++)
        if (t->nodes[i].count > largest)
            largest = t->nodes[i].count;
    int32_t *scratch = malloc((size_t)(largest > 0 ? largest : 1) *
                              sizeof *scratch);
    if (t->slivers == NULL || scratch == NULL) {
        free(scratch);
        return 0;
    }
    for (int i = t->node_count - 1; i >= 0; i--) {
        const onode *node = &t->nodes[i];
        if (node->count < 0) {
            int32_t any = 0;
            for (int c = 0; c < 8; c++)
                any |= t->slivers[node->first + c] != 0;
            t->slivers[i] = any;
            continue;
        }
        int32_t *list = t->refs + node->first;
        int32_t kept = 0, moved = 0;
        for (int32_t j = 0; j < node->count; j++) {
            if (sliver[list[j]])
                scratch[moved++] = list[j];
            else
                list[kept++] = list[j];
        }
        memcpy(list + kept, scratch, (size_t)moved * sizeof *list);
        t->slivers[i] = moved;
    }
    free(scratch);
    return 1;
}

/*
 * The octree of k's facets, with *status RT_OK; or NULL with *status
 * RT_ERR_NOMEM, or RT_ERR_CANCELLED once `cancel` (may be NULL) was
 * raised: a cancelled build frees what it made.
 */
static octree *octree_build(const KERNEL_T *k, const rt_cancel *cancel,
                            rt_status *status)
{
    double start = rt__clock_seconds();
    *status = RT_ERR_NOMEM;
    octree *t = calloc(1, sizeof *t);
    if (t == NULL)
        return NULL;
    builder b = {0};
    size_t n = (size_t)k->count;
    b.tree = t;
    b.cancel = cancel;
    b.v = malloc((n ? n : 1) * sizeof *b.v);
    int32_t *list = malloc((n ? n : 1) * sizeof *list);
    unsigned char *sliver = malloc(n ? n : 1);
    t->always = malloc((n ? n : 1) * sizeof *t->always);
    t->nodes = malloc(sizeof *t->nodes);
    if (b.v == NULL || list == NULL || sliver == NULL || t->always == NULL ||
        t->nodes == NULL) {
        free(b.v);
        free(list);
        free(sliver);
        octree_free(t);
        return NULL;
    }
    b.node_capacity = 1;
    t->node_count = 1;
    double lo[3] = {INFINITY, INFINITY, INFINITY};
    double hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    int listed = 0, slivers = 0;
    for (int i = 0; i < k->count; i++) {
        if (i % OCTREE_POLL_WORK == 0 && stopped(&b, OCTREE_POLL_WORK))
            break;
        for (int j = 0; j < 3; j++) {
            const vec *p = corner(k->vertices, &k->tris[i], j);
            b.v[i][j][0] = (double)p->x;
            b.v[i][j][1] = (double)p->y;
            b.v[i][j][2] = (double)p->z;
        }
        sliver[i] = !(condition(b.v[i]) <= OCTREE_CONDITION_MAX);
        slivers += sliver[i];
        list[listed++] = i;
        for (int j = 0; j < 3; j++)
            for (int a = 0; a < 3; a++) {
                lo[a] = fmin(lo[a], b.v[i][j][a]);
                hi[a] = fmax(hi[a], b.v[i][j][a]);
            }
    }
    double size = 0, extent = 0;
    for (int a = 0; listed > 0 && a < 3; a++) {
        size = fmax(size, hi[a] - lo[a]);
        extent = fmax(extent, fmax(fabs(lo[a]), fabs(hi[a])));
    }
    if (b.status == RT_OK && !(size * 2 < INFINITY)) {
        /* coordinates near double's limit: no cell arithmetic would be
         * safe; every facet goes to the list every ray tests */
        for (int i = 0; i < listed; i++)
            t->always[t->always_count++] = list[i];
        listed = 0;
        slivers = 0;
        size = extent = 0;
    }
    t->reach_margin = size * OCTREE_MARGIN;
    t->margin = fmax(t->reach_margin, (extent + size) * OCTREE_ROUNDING);
    /* A cube a little larger than the facets' box and off its centre, so
     * that the cells' faces do not fall on the round coordinates modelled
     * scenes put their vertices on (a facet on a face is listed on both
     * sides); grown by the margin. */
    for (int a = 0; a < 3; a++) {
        double centre = listed > 0 ? lo[a] + (hi[a] - lo[a]) * 0.5 : 0;
        centre += size * OCTREE_OFFSET[a];
        t->lo[a] = centre - size * OCTREE_ENLARGE - 2 * t->margin;
        t->hi[a] = centre + size * OCTREE_ENLARGE + 2 * t->margin;
    }
    b.frontier = (size_t)listed;
    b.budget = (size_t)OCTREE_REFERENCE_BUDGET * (size_t)listed +
               RT_OCTREE_REFERENCE_EXTRA;
    if (b.status == RT_OK)
        build_levels(&b, list, listed);    /* frees list */
    else
        free(list);
    free(b.v);
    if (b.status == RT_OK && slivers > 0 && !mark_slivers(t, sliver))
        b.status = RT_ERR_NOMEM;
    free(sliver);
    if (b.status == RT_OK) {     /* complete: kept even if cancelled now */
        t->bytes = sizeof *t + (size_t)t->node_count * sizeof *t->nodes +
                   t->ref_count * sizeof *t->refs +
                   (size_t)k->count * sizeof *t->always +
                   (t->slivers ? (size_t)t->node_count * sizeof *t->slivers
                               : 0);
        t->build_seconds = rt__clock_seconds() - start;
        t->sliver_count = slivers;
        *status = RT_OK;
        return t;
    }
    *status = b.status;
    octree_free(t);
    return NULL;
}

