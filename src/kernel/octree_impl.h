/*
 * octree_impl.h - an octree over a kernel's facets: its construction and
 * the front-to-back walk of a ray through its leaves (part of
 * kernel_impl.h, compiled once per precision; everything here is static).
 *
 * A subdivision of space, not a bounding volume hierarchy: the root is a
 * cube around every facet, each internal node splits its box at the middle
 * into eight children that share their faces exactly (one computed middle
 * per axis serves both sides), and a facet is listed in every leaf its
 * triangle overlaps.  Overlap is Akenine-Moller's separating-axis test
 * ("Fast 3D Triangle-Box Overlap Testing", 2001) on the leaf's box grown by
 * a margin, so a facet touching a face, or one that rounding moves a little,
 * is in both cells.  The walk is an ordered stack traversal: the children a
 * ray meets, by pbrt-v4's slab test made conservative on both ends, pushed
 * so the nearest comes out first; a ray grazing a face visits both cells.
 * docs/octree.md gives the argument that queries through it give exactly
 * the brute-force answers, and query_impl.h uses it.
 *
 * Everything here is in double, whatever REAL is: the float kernel's
 * vertices are exact in double, so the boxes and the overlap tests are the
 * same kind of computation in both precisions.
 *
 * Bounds, each with its reason:
 *   - a leaf holds at most OCTREE_LEAF_FACETS facets unless splitting stops
 *     for another reason: below that, testing them costs less than walking
 *     more nodes;
 *   - at most OCTREE_MAX_DEPTH levels: 2^-16 of the scene's size is below
 *     any useful cell, and the walk's stack is sized by it;
 *   - a split that lists the node's facets more than OCTREE_SPLIT_GROWTH
 *     times over (facets much bigger than the children) is not made: it
 *     would multiply references without separating anything;
 *   - the references of all leaves stay below OCTREE_REFERENCE_BUDGET times
 *     the facet count (plus a constant): the memory is linear in the scene
 *     whatever its distribution; the nodes that cannot split stay leaves,
 *     and a degenerate scene degrades towards brute force;
 *   - facets whose shape makes the test's rounding large (longest edge
 *     squared over twice the area above OCTREE_CONDITION_MAX: slivers) are
 *     listed in leaves like the others, after them, and every node whose
 *     subtree holds one is marked: the nearest-hit walk never leaves out a
 *     marked node, but beyond its stopping point tests only the slivers
 *     there (docs/octree.md, "Slivers");
 *   - the build looks at the render's cancellation flag every
 *     OCTREE_POLL_WORK facet placements: a cancelled build is thrown away
 *     within about a millisecond, never kept half built;
 *   - a ray from farther than the margin covers (see fat_growth()) walks
 *     cells grown by what the margin lacks, up to OCTREE_FAT_MAX of the
 *     root's side; beyond, brute force is cheaper and is used.
 */
#define OCTREE_LEAF_FACETS 8
#define OCTREE_MAX_DEPTH 16
#define OCTREE_SPLIT_GROWTH 4
#define OCTREE_REFERENCE_BUDGET RT_OCTREE_REFERENCE_BUDGET
#define OCTREE_CONDITION_MAX 4096.0
#define OCTREE_POLL_WORK 1024
#define OCTREE_FAT_MAX 0.0625
#define OCTREE_STACK (7 * OCTREE_MAX_DEPTH + 8)
#define OCTREE_ENLARGE 0.5234375    /* half the cube's side, in box sizes */
static const double OCTREE_OFFSET[3] = {0.0103, 0.0071, 0.0137};

/*
 * The margin leaf boxes grow by, relative to the root's size: far above
 * the rounding of the overlap and slab tests (a few ulps of double), and
 * above the perturbation under which the watertight test in REAL is exact
 * for rays from within its reach (2^16 root sizes in double, 2^6 in float;
 * see fat_growth() for farther ones).
 */
#if REAL_IS_FLOAT
#define OCTREE_MARGIN 0x1p-11
#else
#define OCTREE_MARGIN 0x1p-30
#endif

/*
 * The margin is at least this much of the largest coordinate of the root
 * too: the boxes the overlap test is given are computed from the cells'
 * bounds, and round by an ulp of those coordinates; for a scene far from
 * the coordinates' origin compared to its size (beyond 2^16 times its
 * size) that rounding would otherwise exceed the margin.  (64 ulps: the
 * part of the margin left once the test's perturbation is covered, 9/16
 * of it, is still 36 ulps of every coordinate.)
 */
#define OCTREE_ROUNDING 0x1p-46

/* A node: a leaf when count >= 0 (facets refs[first .. first + count)),
 * else internal with children nodes[first .. first + 8), child bit 0 the
 * upper half in x, bit 1 in y, bit 2 in z. */
typedef struct onode {
    int32_t first;
    int32_t count;
} onode;

typedef struct octree {
    double lo[3], hi[3];    /* the root cube */
    double margin;          /* absolute */
    double reach_margin;    /* the part of it that covers the watertight
                               test's perturbation: size * OCTREE_MARGIN */
    onode *nodes;
    int32_t *refs;          /* facet indices; within a leaf the ordinary
                               ones, then the slivers, each ascending */
    int32_t *slivers;       /* NULL when there are none; else per node:
                               for a leaf, how many of its facets (the
                               last ones) are slivers; for an internal
                               node, non-zero when a leaf below holds one */
    int32_t *always;        /* facets every ray tests: all of them when the
                               coordinates leave no room for cells */
    int node_count;
    int leaf_count;
    int depth;
    int always_count;
    int sliver_count;
    size_t ref_count;
    size_t bytes;
    double build_seconds;
} octree;

/* --- the triangle-box test ------------------------------------------- */

static double cross_axis(const double e[3], int axis, const double v[3])
{
    /* (e x unit(axis)) . v */
    int i = (axis + 1) % 3, j = (axis + 2) % 3;
    return e[j] * v[i] - e[i] * v[j];
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
        double low = fmin(v[0][a], fmin(v[1][a], v[2][a]));
        double high = fmax(v[0][a], fmax(v[1][a], v[2][a]));
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
            if (fmin(p0, fmin(p1, p2)) > r || fmax(p0, fmax(p1, p2)) < -r)
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

static void child_box(const double lo[3], const double hi[3],
                      const double mid[3], int child, double clo[3],
                      double chi[3])
{
    for (int a = 0; a < 3; a++) {
        int upper = (child >> a) & 1;
        clo[a] = upper ? mid[a] : lo[a];
        chi[a] = upper ? hi[a] : mid[a];
    }
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

static void octree_free(octree *t)
{
    if (t != NULL) {
        free(t->nodes);
        free(t->refs);
        free(t->slivers);
        free(t->always);
    }
    free(t);
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
        const vec *p[3] = {&k->tris[i].a, &k->tris[i].b, &k->tris[i].c};
        for (int j = 0; j < 3; j++) {
            b.v[i][j][0] = (double)p[j]->x;
            b.v[i][j][1] = (double)p[j]->y;
            b.v[i][j][2] = (double)p[j]->z;
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

/* --- the walk -------------------------------------------------------- */

/* Higham's gamma(n) in double: the slab test runs in double. */
static double gamma_double(int n)
{
    double u = DBL_EPSILON / 2;
    return n * u / (1 - n * u);
}

/* A ray as the walk reads it, in double. */
typedef struct oray {
    double origin[3], direction[3], inverse[3];
} oray;

static oray oray_make(const ray *r)
{
    oray q;
    for (int a = 0; a < 3; a++) {
        q.origin[a] = (double)get(r->origin, a);
        q.direction[a] = (double)get(r->direction, a);
        q.inverse[a] = 1 / q.direction[a];
    }
    return q;
}

/*
 * pbrt-v4's slab test, conservative at both ends: non-zero when the ray
 * may meet the box within [*t0, *t1], which it narrows to a superset of
 * the true interval.  The entry is lowered and the exit raised by more than
 * the three roundings of (bound - origin) * inverse.
 */
static int slabs(const oray *q, const double lo[3], const double hi[3],
                 double *t0, double *t1)
{
    double grow = 1 + 2 * gamma_double(3), shrink = 1 - 2 * gamma_double(3);
    for (int a = 0; a < 3; a++) {
        if (q->direction[a] == 0) {
            if (q->origin[a] < lo[a] || q->origin[a] > hi[a])
                return 0;
            continue;
        }
        double near = (lo[a] - q->origin[a]) * q->inverse[a];
        double far = (hi[a] - q->origin[a]) * q->inverse[a];
        if (near > far) {
            double swap = near;
            near = far;
            far = swap;
        }
        if (near != near)
            near = -INFINITY;
        if (far != far)
            far = INFINITY;
        near *= near > 0 ? shrink : grow;
        far *= far > 0 ? grow : shrink;
        if (near > *t0)
            *t0 = near;
        if (far < *t1)
            *t1 = far;
        if (*t0 > *t1)
            return 0;
    }
    return 1;
}

/*
 * For each axis, the ray's t in the lower half of a node split at mid
 * ([low0, low1]) and in the upper half ([up0, up1]), before clipping to the
 * node's own interval: the plane's t, widened by more than its three
 * roundings, bounds both.  A ray in the plane is in both halves; one
 * parallel to it beside the plane is in its own half only.
 */
static void split_axes(const oray *q, const double mid[3], double low0[3],
                       double low1[3], double up0[3], double up1[3])
{
    double slack = 2 * gamma_double(3);
    for (int a = 0; a < 3; a++) {
        low0[a] = up0[a] = -INFINITY;
        low1[a] = up1[a] = INFINITY;
        if (q->direction[a] == 0) {
            if (q->origin[a] < mid[a])
                up0[a] = INFINITY;          /* never in the upper half */
            else if (q->origin[a] > mid[a])
                low0[a] = INFINITY;
            continue;
        }
        double t = (mid[a] - q->origin[a]) * q->inverse[a];
        if (t != t)
            continue;                       /* both halves, all along */
        double lo = t, hi = t;
        if (fabs(t) < INFINITY) {
            lo -= fabs(t) * slack;
            hi += fabs(t) * slack;
        }
        if (q->direction[a] > 0) {          /* lower half first */
            low1[a] = hi;
            up0[a] = lo;
        } else {
            up1[a] = hi;
            low0[a] = lo;
        }
    }
}

/* The same for the halves grown by g > 0 beyond the middle (the walk of a
 * ray from far away, see fat_growth()): the lower half ends at mid + g,
 * the upper one starts at mid - g. */
static void split_axes_grown(const oray *q, const double mid[3], double g,
                             double low0[3], double low1[3], double up0[3],
                             double up1[3])
{
    double slack = 2 * gamma_double(3);
    for (int a = 0; a < 3; a++) {
        low0[a] = up0[a] = -INFINITY;
        low1[a] = up1[a] = INFINITY;
        if (q->direction[a] == 0) {
            if (q->origin[a] < mid[a] - g)
                up0[a] = INFINITY;
            else if (q->origin[a] > mid[a] + g)
                low0[a] = INFINITY;
            continue;
        }
        /* where the ray crosses the lower half's end and the upper half's
         * start */
        double t_low = (mid[a] + g - q->origin[a]) * q->inverse[a];
        double t_up = (mid[a] - g - q->origin[a]) * q->inverse[a];
        if (t_low != t_low || t_up != t_up)
            continue;
        double low_lo = t_low, low_hi = t_low, up_lo = t_up, up_hi = t_up;
        if (fabs(t_low) < INFINITY) {
            low_lo -= fabs(t_low) * slack;
            low_hi += fabs(t_low) * slack;
        }
        if (fabs(t_up) < INFINITY) {
            up_lo -= fabs(t_up) * slack;
            up_hi += fabs(t_up) * slack;
        }
        if (q->direction[a] > 0) {
            low1[a] = low_hi;
            up0[a] = up_lo;
        } else {
            up1[a] = up_hi;
            low0[a] = low_lo;
        }
    }
}

/* A node waiting in the walk, with its box and the ray's interval in it. */
typedef struct pending {
    double lo[3], hi[3];
    double t0, t1;
    int node;
} pending;

/* The walk: the leaves of `t` the ray meets within [t_min, t_max], nearest
 * first.  Call walk_start, then walk_next until it returns -1.  A node
 * whose entry is beyond `cutoff` (which may shrink meanwhile) is not
 * entered, unless slivers are below it (t->slivers): such a node is
 * walked on, and its leaves come out with slivers_only set - only their
 * slivers are to be tested.  The smallest entry of a node whose facets
 * were left out (all of them, or a leaf's ordinary ones) is kept in
 * skipped. */
typedef struct walk {
    const octree *t;
    oray q;
    double grow;            /* the cells' growth for this ray */
    pending stack[OCTREE_STACK];
    int top;
    int slivers_only;       /* of the leaf walk_next returned */
    double skipped;         /* smallest entry of a node left out */
} walk;

/*
 * The growth of the cells a ray must walk (docs/octree.md, steps 1 and 6).
 * The watertight test in REAL is exact for vertices moved by about
 * 4 gamma(8) times their distance to the ray's origin, which 16 gamma(8) R
 * bounds with room (R: the origin's distance to the root's farthest
 * corner, per axis).  Within the margin's reach (that bound below
 * reach_margin) the cells need no growth: 0.  Beyond, they are grown by
 * the whole bound; and when that exceeds OCTREE_FAT_MAX of the root's side
 * (the ray would walk much of the tree), -1: brute force is cheaper.
 */
static double fat_growth(const octree *t, const ray *r)
{
    double reach = 0;
    for (int a = 0; a < 3; a++) {
        double o = (double)get(r->origin, a);
        reach = fmax(reach, fmax(fabs(t->lo[a] - o), fabs(t->hi[a] - o)));
    }
    double bound = 16 * (double)gamma_bound(8) * reach;
    if (bound <= t->reach_margin)
        return 0;
    return bound <= OCTREE_FAT_MAX * (t->hi[0] - t->lo[0]) ? bound : -1;
}

/* Starts the walk of ray r with cells grown by g >= 0 (fat_growth()). */
static void walk_start(walk *w, const octree *t, const ray *r, double t_min,
                       double t_max, double g)
{
    w->t = t;
    w->q = oray_make(r);
    w->grow = g;
    w->top = 0;
    w->slivers_only = 0;
    w->skipped = INFINITY;
    pending root = {{t->lo[0], t->lo[1], t->lo[2]},
                    {t->hi[0], t->hi[1], t->hi[2]}, t_min, t_max, 0};
    double lo[3] = {t->lo[0] - g, t->lo[1] - g, t->lo[2] - g};
    double hi[3] = {t->hi[0] + g, t->hi[1] + g, t->hi[2] + g};
    if (slabs(&w->q, lo, hi, &root.t0, &root.t1))
        w->stack[w->top++] = root;
}

/* The next leaf, or -1. */
static int walk_next(walk *w, double cutoff)
{
    while (w->top > 0) {
        const pending *p = &w->stack[--w->top];
        if (p->t0 > cutoff) {
            if (w->t->slivers == NULL || !w->t->slivers[p->node]) {
                if (p->t0 < w->skipped)
                    w->skipped = p->t0;
                continue;
            }
            const onode *marked = &w->t->nodes[p->node];
            if (marked->count >= 0) {   /* a leaf: its slivers only */
                if (marked->count > w->t->slivers[p->node] &&
                    p->t0 < w->skipped)
                    w->skipped = p->t0;
                w->slivers_only = 1;
                return p->node;
            }
        }
        const onode *n = &w->t->nodes[p->node];
        if (n->count >= 0) {
            w->slivers_only = 0;
            return p->node;
        }
        double lo[3], hi[3], mid[3], t0 = p->t0, t1 = p->t1;
        for (int a = 0; a < 3; a++) {
            lo[a] = p->lo[a];
            hi[a] = p->hi[a];
            mid[a] = lo[a] + (hi[a] - lo[a]) * 0.5;
        }
        /* per axis, the interval of t in the lower half and in the upper
         * half of the node (bit 0 and 1 of the child) */
        double low0[3], low1[3], up0[3], up1[3];
        if (w->grow == 0)
            split_axes(&w->q, mid, low0, low1, up0, up1);
        else
            split_axes_grown(&w->q, mid, w->grow, low0, low1, up0, up1);
        double enter[8], leave[8];
        int order[8], m = 0;
        const onode *kids = &w->t->nodes[n->first];
        for (int c = 0; c < 8; c++) {
            if (kids[c].count == 0)
                continue;   /* an empty leaf: nothing to visit */
            double c0 = t0, c1 = t1;
            for (int a = 0; a < 3; a++) {
                int upper = (c >> a) & 1;
                double e = upper ? up0[a] : low0[a];
                double l = upper ? up1[a] : low1[a];
                c0 = e > c0 ? e : c0;
                c1 = l < c1 ? l : c1;
            }
            if (c0 > c1)
                continue;
            enter[c] = c0;
            leave[c] = c1;
            int j = m++;    /* farthest first, so the nearest pops first */
            while (j > 0 && enter[order[j - 1]] < c0) {
                order[j] = order[j - 1];
                j--;
            }
            order[j] = c;
        }
        for (int j = 0; j < m; j++) {
            int c = order[j];
            pending *ch = &w->stack[w->top++];
            child_box(lo, hi, mid, c, ch->lo, ch->hi);
            ch->t0 = enter[c];
            ch->t1 = leave[c];
            ch->node = n->first + c;
        }
    }
    return -1;
}

/* --- the facets a ray has tested ------------------------------------- */

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
