/*
 * octree_impl.h - an octree over a kernel's facets: its nodes, its bounds
 * and what its construction (octree_build_impl.h) and its walk
 * (octree_walk_impl.h) share (part of kernel_impl.h, compiled once per
 * precision; everything here is static).
 *
 * A subdivision of space, not a bounding volume hierarchy: the root is a
 * cube around every facet, each internal node splits its box at the middle
 * into eight children that share their faces exactly (one computed middle
 * per axis serves both sides), and a facet is listed in every leaf its
 * triangle overlaps.  docs/octree.md gives the argument that queries
 * through it give exactly the brute-force answers, and
 * query_octree_impl.h makes them.
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

/* The box of child `child` of the node lo..hi split at mid (bit 0 of
 * the child: the upper half in x, bit 1 in y, bit 2 in z). */
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

