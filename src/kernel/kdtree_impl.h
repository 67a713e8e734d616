/*
 * kdtree_impl.h - a kd-tree over a kernel's facets: its 8-byte nodes, its
 * bounds and what its construction (kdtree_build_impl.h) and its walk
 * (kdtree_walk_impl.h) share (part of kernel_impl.h, compiled once per
 * precision; everything here is static).
 *
 * A binary subdivision of space by axis-aligned planes, not a bounding
 * volume hierarchy: the root is the facets' box grown by the margin, each
 * internal node cuts its cell by one plane chosen by the surface area
 * heuristic, and a facet is listed in every leaf its box, grown by the
 * margin and rounded outward to float, reaches into - unless the triangle
 * itself misses the leaf's cell grown by the octree's margin.
 * docs/kdtree.md gives the argument that the queries through it
 * (query_kdtree_impl.h) give exactly the brute-force answers.
 *
 * Everything here is in double (the float kernel's vertices are exact in
 * double) but the split planes, which are floats: a node is 8 bytes, as in
 * pbrt-v3's KdTreeAccel, and a plane is the same float to both children,
 * to the build and to the walk.
 *
 * Bounds, each with its reason:
 *   - the SAH's cost constants KD_COST_TRAVERSE and KD_COST_INTERSECT,
 *     fitted to this kernel: a traversal step measured at 0.27 to 0.37 of
 *     a facet test through the AVX2 filter (profiles of balls-s2,
 *     gears-s2 and tetra-s6, docs/kdtree.md), rounded up to 0.4 for what
 *     a leaf visit costs beyond its tests (the mailbox, the batch): K_T =
 *     8 for K_I = 20, the fastest of 4, 6, 8 and 15 over the SPD scenes
 *     (Wald and Havran's were 15 and 20); for a tree of
 *     KD_LARGE_FACETS facets or more, whose nodes outgrow the caches (at
 *     about 100 bytes a facet, 13 MB and up against this machine's 32 MB
 *     L3), K_T = KD_COST_TRAVERSE_LARGE = 30: the same trace time within
 *     the noise on the 200 k and 1 M facet terrains, a build 30-50 %
 *     faster and a tree 2.5 times smaller (docs/kdtree.md, "Large
 *     trees"); and KD_EMPTY_BONUS (their
 *     lambda = 0.8 for a side left empty): a node is split only when the
 *     split's cost is below the leaf's;
 *   - a depth cap of KD_DEPTH_BASE + KD_DEPTH_SLOPE log2(N) levels
 *     (pbrt-v3's 8 + 1.3 log2 N), at most KD_MAX_DEPTH: past it the SAH's
 *     gains are noise, and the walk's stack is sized by it;
 *   - at most KD_REFERENCE_LIMIT references per facet (+ KD_REFERENCE_EXTRA)
 *     in all leaves: a build that would list more - only a hostile scene,
 *     facets crossing everything - is redone with the depth cap lowered by
 *     KD_DEPTH_RETRY, so the memory stays linear in the scene (this never
 *     stops a build halfway: the tree is always the SAH's within its cap);
 *   - the build reads the cancellation flag every KD_POLL_WORK units of
 *     work (a facet sorted or classified): a cancelled build is thrown
 *     away, never kept half built;
 *   - at most KD_MAX_FACETS facets (the node's 29-bit fields); above, the
 *     build reports RT_ERR_NOMEM (such a scene needs tens of gigabytes).
 */
#define KD_COST_TRAVERSE 8.0
#define KD_COST_TRAVERSE_LARGE 30.0
#define KD_LARGE_FACETS (1 << 17)
#define KD_COST_INTERSECT 20.0
#define KD_EMPTY_BONUS 0.8
#define KD_DEPTH_BASE 8
#define KD_DEPTH_SLOPE 1.3
#define KD_MAX_DEPTH RT_KDTREE_MAX_DEPTH
#define KD_REFERENCE_LIMIT RT_KDTREE_REFERENCE_LIMIT
#define KD_REFERENCE_EXTRA RT_KDTREE_REFERENCE_EXTRA
#define KD_DEPTH_RETRY 4
#define KD_POLL_WORK 4096
#define KD_MAX_FACETS (1 << 29)
#define KD_STACK (KD_MAX_DEPTH + 2)

/*
 * The margin facet boxes grow by: the octree's (octree_impl.h), for the
 * same reason - above the perturbation under which the watertight test
 * in REAL is exact for rays from within its reach.  No rounding term is
 * added: the kd-tree's listing compares exact values (float planes with
 * float bounds), it rounds nothing.
 */
#define KD_MARGIN OCTREE_MARGIN

/*
 * A node, 8 bytes.  `bits`: bits 0-1 the axis of the plane (0, 1, 2) or
 * 3 for a leaf; bit 2 set when a sliver is listed in the node's subtree;
 * bits 3-31 the index of the child above the plane (the child below
 * follows its parent) or, for a leaf, its facet count.  The other word:
 * the plane, or the leaf's first reference in refs - for a leaf of one
 * facet, that facet's index itself.
 */
typedef struct kdnode {
    union {
        float split;
        uint32_t first;
    } at;
    uint32_t bits;
} kdnode;

#define KD_LEAF 3u
#define KD_SLIVER 4u

static inline int kd_is_leaf(const kdnode *n)
{
    return (n->bits & 3u) == KD_LEAF;
}

static inline uint32_t kd_payload(const kdnode *n)
{
    return n->bits >> 3;
}

typedef struct kdtree {
    double lo[3], hi[3];    /* the root cell */
    double reach_margin;    /* the margin: size * KD_MARGIN */
    kdnode *nodes;
    int32_t *refs;          /* facet indices; ascending within a leaf */
    int brute;              /* coordinates leave no room for cells: every
                               query goes to brute force */
    int node_count;
    int leaf_count;
    int depth;
    int sliver_count;
    size_t ref_count;       /* references in all leaves */
    size_t bytes;
    uint64_t digest;        /* FNV-1a of the nodes and the references */
    double build_seconds;
} kdtree;

/* The facet indices of leaf n: *count of them from the returned pointer
 * (a leaf of one facet holds it in the node). */
static inline const int32_t *kd_leaf_facets(const kdtree *t, const kdnode *n,
                                            int *count)
{
    *count = (int)kd_payload(n);
    if (*count == 1)
        return (const int32_t *)&n->at.first;
    return t->refs + n->at.first;
}

static void kdtree_free(kdtree *t)
{
    if (t != NULL) {
        free(t->nodes);
        free(t->refs);
    }
    free(t);
}
