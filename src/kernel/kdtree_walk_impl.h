/*
 * kdtree_walk_impl.h - the front-to-back walk of a ray through the leaves
 * of the kd-tree of kdtree_impl.h (part of kernel_impl.h, compiled once
 * per precision; everything here is static).
 *
 * Havran's recursive traversal made iterative: at each node the ray's
 * interval [t0, t1] is cut at the plane's crossing, widened by more than
 * its roundings, into the near child's part and the far child's; the far
 * one waits on an explicit stack, the near one is entered at once, so
 * leaves come out front to back and nothing restarts from the root.  A ray
 * in a plane, or parallel to it within the cells' growth, is in both
 * children.  A ray from farther than the margin covers walks the cells
 * grown by g (growth_for(), octree_walk_impl.h): the part below a plane
 * ends at p + g, the part above starts at p - g.  No libm call: fabs and
 * comparisons only.
 */

#define KD_FAT_MAX OCTREE_FAT_MAX

/* A node waiting in the walk, with the ray's interval in it. */
typedef struct kd_pending {
    double t0, t1;
    uint32_t node;
} kd_pending;

/* The walk: the leaves of `t` the ray meets within [t_min, t_max], nearest
 * first.  Call kd_walk_start, then kd_walk_next until it returns -1.  A
 * node whose entry is beyond `cutoff` (which may shrink meanwhile) is not
 * entered unless a sliver is listed below it (KD_SLIVER): such a node is
 * walked on, and its leaves come out whole.  The smallest entry of a node
 * left out is kept in skipped. */
typedef struct kd_walk {
    const kdtree *t;
    oray q;
    double grow;            /* the cells' growth for this ray */
    kd_pending stack[KD_STACK];
    int top;
    double skipped;
    uint64_t steps;         /* the nodes taken up so far (accel_steps) */
} kd_walk;

/* The growth of the cells for ray r through t (growth_for()): 0, g > 0,
 * or -1 for brute force. */
static double kd_growth(const kdtree *t, const ray *r)
{
    double side = 0;
    for (int a = 0; a < 3; a++)
        side = t->hi[a] - t->lo[a] > side ? t->hi[a] - t->lo[a] : side;
    return growth_for(t->lo, t->hi, t->reach_margin, KD_FAT_MAX * side, r);
}

static void kd_walk_start(kd_walk *w, const kdtree *t, const ray *r,
                          double t_min, double t_max, double g)
{
    w->t = t;
    w->q = oray_make(r);
    w->grow = g;
    w->top = 0;
    w->skipped = INFINITY;
    w->steps = 0;
    kd_pending root = {t_min, t_max, 0};
    double lo[3], hi[3];
    for (int a = 0; a < 3; a++) {   /* outward: the sums round */
        lo[a] = g > 0 ? nextafter(t->lo[a] - g, -INFINITY) : t->lo[a];
        hi[a] = g > 0 ? nextafter(t->hi[a] + g, INFINITY) : t->hi[a];
    }
    if (slabs(&w->q, lo, hi, &root.t0, &root.t1))
        w->stack[w->top++] = root;
}

/* Non-zero for an empty leaf: nothing to visit there. */
static inline int kd_empty(const kdnode *n)
{
    return n->bits == KD_LEAF;
}

/* The next leaf, or -1. */
static int kd_walk_next(kd_walk *w, double cutoff)
{
    const kdnode *nodes = w->t->nodes;
    double slack = 2 * gamma_double(3), g = w->grow;
    uint64_t steps = w->steps;
    while (w->top > 0) {
        kd_pending cur = w->stack[--w->top];
        for (;;) {
            const kdnode *n = &nodes[cur.node];
            steps++;
            if (cur.t0 > cutoff && !(n->bits & KD_SLIVER)) {
                if (cur.t0 < w->skipped)
                    w->skipped = cur.t0;
                break;
            }
            if (kd_is_leaf(n)) {
                w->steps = steps;
                return (int)cur.node;
            }
            int a = (int)(n->bits & 3u);
            double p = (double)n->at.split;
            double o = w->q.origin[a], d = w->q.direction[a];
            if (g == 0 && d != 0) {
                /* the common case, the general one below with g = 0 and
                 * a finite crossing t: the near side's part ends at
                 * t + e, the far side's starts at t - e */
                double t = (p - o) * w->q.inverse[a];
                if (fabs(t) < INFINITY) {
                    double e = fabs(t) * slack;
                    uint32_t near_node = d > 0 ? cur.node + 1 : kd_payload(n);
                    uint32_t far_node = d > 0 ? kd_payload(n) : cur.node + 1;
                    int near_in = cur.t0 <= t + e &&
                                  !kd_empty(&nodes[near_node]);
                    if (t - e <= cur.t1 && !kd_empty(&nodes[far_node])) {
                        kd_pending far = {t - e > cur.t0 ? t - e : cur.t0,
                                          cur.t1, far_node};
                        if (!near_in) {
                            cur = far;
                            continue;
                        }
                        w->stack[w->top++] = far;
                    }
                    if (!near_in)
                        break;
                    cur.t1 = t + e < cur.t1 ? t + e : cur.t1;
                    cur.node = near_node;
                    continue;
                }
            }
            kd_pending below = {cur.t0, cur.t1, cur.node + 1};
            kd_pending above = {cur.t0, cur.t1, kd_payload(n)};
            int in_below = 1, in_above = 1;
            if (d == 0) {
                in_above = !(o < p - g);
                in_below = !(o > p + g);
            } else {
                /* where the ray leaves or enters the part below (p + g)
                 * and the part above (p - g): (p - o) +- g, one
                 * rounding each and the product's, relative to t; with
                 * g > 0 the absolute rounding of p - o is far inside the
                 * room g keeps over the perturbation */
                double tb = (p - o + g) * w->q.inverse[a];
                double ta = g > 0 ? (p - o - g) * w->q.inverse[a] : tb;
                if (tb == tb && ta == ta) {
                    double eb = fabs(tb) < INFINITY ? fabs(tb) * slack : 0;
                    double ea = fabs(ta) < INFINITY ? fabs(ta) * slack : 0;
                    if (d > 0) {
                        below.t1 = tb + eb < below.t1 ? tb + eb : below.t1;
                        above.t0 = ta - ea > above.t0 ? ta - ea : above.t0;
                    } else {
                        above.t1 = ta + ea < above.t1 ? ta + ea : above.t1;
                        below.t0 = tb - eb > below.t0 ? tb - eb : below.t0;
                    }
                }
            }
            in_below = in_below && below.t0 <= below.t1 &&
                       !kd_empty(&nodes[below.node]);
            in_above = in_above && above.t0 <= above.t1 &&
                       !kd_empty(&nodes[above.node]);
            const kd_pending *near = d < 0 ? &above : &below;
            const kd_pending *far = d < 0 ? &below : &above;
            int near_in = d < 0 ? in_above : in_below;
            int far_in = d < 0 ? in_below : in_above;
            if (far_in) {
                if (!near_in) {
                    cur = *far;
                    continue;
                }
                w->stack[w->top++] = *far;
            }
            if (!near_in)
                break;
            cur = *near;
        }
    }
    w->steps = steps;
    return -1;
}
