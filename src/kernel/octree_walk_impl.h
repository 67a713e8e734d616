/*
 * octree_walk_impl.h - the front-to-back walk of a ray through the leaves
 * of the octree of octree_impl.h (part of kernel_impl.h, compiled once per
 * precision; everything here is static).
 *
 * An ordered stack traversal: the children a ray meets, by pbrt-v4's slab
 * test made conservative on both ends, pushed so the nearest comes out
 * first; a ray grazing a face visits both cells.  A ray from farther than
 * the margin covers walks cells grown by what the margin lacks
 * (fat_growth()).
 */

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
    uint64_t steps;         /* the nodes popped so far (accel_steps) */
} walk;

/*
 * The growth of the cells a ray must walk through a tree whose root is
 * lo..hi and whose margin covers the test's perturbation up to
 * reach_margin (docs/octree.md, steps 1 and 6; the kd-tree's walk uses it
 * too): 0 within that reach, the bound beyond it up to `limit`, and -1
 * past `limit` (brute force is cheaper).
 */
static double growth_for(const double lo[3], const double hi[3],
                         double reach_margin, double limit, const ray *r)
{
    double reach = 0;
    for (int a = 0; a < 3; a++) {
        double o = (double)get(r->origin, a);
        double below = fabs(lo[a] - o), above = fabs(hi[a] - o);
        /* comparisons, not libm's fmax: all finite here */
        reach = below > reach ? below : reach;
        reach = above > reach ? above : reach;
    }
    double bound = 16 * (double)gamma_bound(8) * reach;
    if (bound <= reach_margin)
        return 0;
    return bound <= limit ? bound : -1;
}

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
    return growth_for(t->lo, t->hi, t->reach_margin,
                      OCTREE_FAT_MAX * (t->hi[0] - t->lo[0]), r);
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
    w->steps = 0;
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
        w->steps++;
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
