/*
 * simd_impl.h - the fast facet loops of query_impl.h: facets in blocks of
 * eight, structure of arrays, tested with AVX2 (included by kernel_impl.h;
 * everything here is static).
 *
 * The vector code is a filter, not a second intersection test.  For each
 * lane it computes the three edge functions u, v, w with exactly the
 * operations of intersect() in intersect_impl.h (same order, no FMA: the
 * build uses -ffp-contract=off and these functions are not compiled for
 * FMA), so each value is bit-for-bit the scalar one.  A lane where some edge
 * function is strictly negative and another strictly positive cannot be hit:
 * the scalar test rejects it too (a non-zero edge function is never
 * recomputed, and a NaN one always ends in a rejection).  Every other lane -
 * the ray's line passes through the facet, or an edge function is 0 or NaN -
 * goes to the scalar intersect() itself, in index order.  So the fast loops
 * give the same hits, the same t and the same ties as the scalar loops,
 * including the exact-sign fallback, while the scalar test runs only for the
 * few facets a ray's line actually meets.
 *
 * The AVX2 code is compiled only for x86-64 with GCC or Clang, as functions
 * with __attribute__((target("avx2"))), and chosen at run time when the
 * processor has AVX2; elsewhere only the scalar loops exist.
 */

#define BLOCK_LANES 8

/* Eight facets' vertices, structure of arrays: v[vertex][axis][lane] with
 * vertex a, b, c and axis x, y, z.  Lanes past the last facet hold zeros
 * and are masked out. */
typedef struct block {
    REAL v[3][3][BLOCK_LANES];
} block;

/* Fills blocks[0 .. ceil(count / 8)) from the facets' vertices minus
 * `origin`, rounded as intersect() rounds them (zero: the vertices). */
static void fill_blocks(block *blocks, const tri *tris, int count, vec origin)
{
    int block_count = (count + BLOCK_LANES - 1) / BLOCK_LANES;
    memset(blocks, 0, (size_t)block_count * sizeof *blocks);
    for (int i = 0; i < count; i++) {
        block *b = &blocks[i / BLOCK_LANES];
        int lane = i % BLOCK_LANES;
        const vec *vertex[3] = {&tris[i].a, &tris[i].b, &tris[i].c};
        for (int j = 0; j < 3; j++) {
            vec t = sub(*vertex[j], origin);
            b->v[j][0][lane] = t.x;
            b->v[j][1][lane] = t.y;
            b->v[j][2][lane] = t.z;
        }
    }
}

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define HAVE_AVX2_KERNEL 1
#include <immintrin.h>

#define AVX2 __attribute__((target("avx2")))

#if REAL_IS_FLOAT
typedef __m256 vreal;
#define VW 8
#define v_set1 _mm256_set1_ps
#define v_load _mm256_load_ps
#define v_store _mm256_store_ps
#define v_sub _mm256_sub_ps
#define v_add _mm256_add_ps
#define v_mul _mm256_mul_ps
#define v_min _mm256_min_ps
#define v_max _mm256_max_ps
#define v_and _mm256_and_ps
#define v_zero _mm256_setzero_ps
#define v_cmp _mm256_cmp_ps
#define v_movemask _mm256_movemask_ps
#else
typedef __m256d vreal;
#define VW 4
#define v_set1 _mm256_set1_pd
#define v_load _mm256_load_pd
#define v_store _mm256_store_pd
#define v_sub _mm256_sub_pd
#define v_add _mm256_add_pd
#define v_mul _mm256_mul_pd
#define v_min _mm256_min_pd
#define v_max _mm256_max_pd
#define v_and _mm256_and_pd
#define v_zero _mm256_setzero_pd
#define v_cmp _mm256_cmp_pd
#define v_movemask _mm256_movemask_pd
#endif

/* A prepared ray, broadcast to every lane. */
typedef struct vray {
    vreal ox, oy, oz;       /* the origin's kx, ky, kz coordinates */
    vreal sx, sy;           /* the shear */
    int kx, ky, kz;
} vray;

AVX2 static void broadcast(const ray *r, vray *q)
{
    q->ox = v_set1(get(r->origin, r->kx));
    q->oy = v_set1(get(r->origin, r->ky));
    q->oz = v_set1(get(r->origin, r->kz));
    q->sx = v_set1(r->sx);
    q->sy = v_set1(r->sy);
    q->kx = r->kx;
    q->ky = r->ky;
    q->kz = r->kz;
}

/* What the filter computed for its lanes, kept for intersect_sheared():
 * value (in the order of the fields of `sheared`) by lane. */
typedef struct lanes_kept {
    _Alignas(32) REAL v[12][BLOCK_LANES];
} lanes_kept;

static inline sheared kept_lane(const lanes_kept *keep, int lane)
{
    const REAL(*v)[BLOCK_LANES] = keep->v;
    return (sheared){v[0][lane], v[1][lane], v[2][lane],  v[3][lane],
                     v[4][lane], v[5][lane], v[6][lane],  v[7][lane],
                     v[8][lane], v[9][lane], v[10][lane], v[11][lane]};
}

/*
 * The heart of the filter, one lane a (ray, facet) pair: a, b, c are the
 * facet's vertices minus the ray's origin on the axes kx, ky, kz, (sx, sy)
 * the ray's shear.  Bit i set when lane i may be hit: all but the lanes
 * whose edge functions u, v, w - the operations of intersect(), in its
 * order - have strictly opposite signs.  When one of the lanes in `live`
 * may be hit, the values of all lanes go to keep->v[..][at + lane].  The
 * facet loops below put eight facets in the lanes and one ray in all; the
 * packets of packet_impl.h one facet in all and several rays.
 */
AVX2 static inline __attribute__((always_inline)) unsigned
edges_filter(const vreal a[3], const vreal b[3], const vreal c[3], vreal sx,
             vreal sy, unsigned live, lanes_kept *keep, int at)
{
    vreal ax = v_sub(a[0], v_mul(sx, a[2]));
    vreal ay = v_sub(a[1], v_mul(sy, a[2]));
    vreal bx = v_sub(b[0], v_mul(sx, b[2]));
    vreal by = v_sub(b[1], v_mul(sy, b[2]));
    vreal cx = v_sub(c[0], v_mul(sx, c[2]));
    vreal cy = v_sub(c[1], v_mul(sy, c[2]));
    vreal u = v_sub(v_mul(cx, by), v_mul(cy, bx));
    vreal v = v_sub(v_mul(ax, cy), v_mul(ay, cx));
    vreal w = v_sub(v_mul(bx, ay), v_mul(by, ax));
    vreal low = v_min(u, v_min(v, w)), high = v_max(u, v_max(v, w));
    vreal outside = v_and(v_cmp(low, v_zero(), _CMP_LT_OQ),
                          v_cmp(high, v_zero(), _CMP_GT_OQ));
    unsigned in = ~(unsigned)v_movemask(outside) & ((1u << VW) - 1);
    if ((in & live) != 0) {
        const vreal value[12] = {ax, ay, bx, by, cx, cy,
                                 a[2], b[2], c[2], u, v, w};
        for (int j = 0; j < 12; j++)
            v_store(&keep->v[j][at], value[j]);
    }
    return in;
}

/*
 * Bit i set when lane i of *b may be hit (edges_filter(), the values of
 * the lanes of `live` kept in *keep).  When `translated` (a constant), *b
 * holds the vertices minus the ray's origin, already rounded as
 * intersect() rounds them.
 */
AVX2 static inline __attribute__((always_inline)) unsigned
block_candidates(const block *b, const vray *q, int translated,
                 unsigned live, lanes_kept *keep)
{
    unsigned mask = 0;
    for (int h = 0; h < BLOCK_LANES; h += VW) {
        vreal a[3], bb[3], c[3];    /* by axis kx, ky, kz */
        const int axis[3] = {q->kx, q->ky, q->kz};
        const vreal origin[3] = {q->ox, q->oy, q->oz};
        for (int j = 0; j < 3; j++) {
            a[j] = v_load(&b->v[0][axis[j]][h]);
            bb[j] = v_load(&b->v[1][axis[j]][h]);
            c[j] = v_load(&b->v[2][axis[j]][h]);
            if (!translated) {
                a[j] = v_sub(a[j], origin[j]);
                bb[j] = v_sub(bb[j], origin[j]);
                c[j] = v_sub(c[j], origin[j]);
            }
        }
        mask |= edges_filter(a, bb, c, q->sx, q->sy, live >> h, keep, h)
                << h;
    }
    return mask & live;
}

/* The lanes of block `b` that hold facets. */
static inline unsigned block_lanes(const KERNEL_T *k, int b)
{
    int left = k->count - b * BLOCK_LANES;
    return left >= BLOCK_LANES ? 0xffu : (1u << left) - 1;
}

/* nearest() over `blocks` (the kernel's, or an eye's when `translated`):
 * same result, same test count. */
AVX2 static inline __attribute__((always_inline)) int
nearest_blocks(const KERNEL_T *k, const block *blocks, int translated,
               const ray *r, REAL t_max, int skip, hit *h, uint64_t *tests)
{
    vray q;
    broadcast(r, &q);
    int found = 0;
    hit candidate;
    lanes_kept keep;
    for (int b = 0; b < k->block_count; b++) {
        unsigned m = block_candidates(&blocks[b], &q, translated,
                                      block_lanes(k, b), &keep);
        while (m != 0) {
            int lane = __builtin_ctz(m), i = b * BLOCK_LANES + lane;
            m &= m - 1;
            sheared s = kept_lane(&keep, lane);
            if (i != skip &&
                intersect_sheared(&s, &k->tris[i], r, t_max, &candidate))
                keep_nearer(k, i, &candidate, h, &t_max, &found);
        }
    }
    *tests += (uint64_t)k->count - (skip >= 0);
    return found;
}

AVX2 static int nearest_avx2(const KERNEL_T *k, const block *blocks,
                             const ray *r, REAL t_max, int skip, hit *h,
                             uint64_t *tests)
{
    return nearest_blocks(k, blocks, 0, r, t_max, skip, h, tests);
}

/* For a ray from the eye's origin (a camera ray: no facet to skip). */
AVX2 static int nearest_eye_avx2(const KERNEL_T *k, const block *translated,
                                 const ray *r, REAL t_max, hit *h,
                                 uint64_t *tests)
{
    return nearest_blocks(k, translated, 1, r, t_max, -1, h, tests);
}

/* any_hit() with the AVX2 filter; stops after the block of the first hit
 * and counts the facets of the blocks it went through. */
AVX2 static int any_hit_avx2(const KERNEL_T *k, const block *facet_blocks,
                             const ray *r, REAL t_max, int skip,
                             uint64_t *tests, uint64_t *saved, int *blocker)
{
    vray q;
    broadcast(r, &q);
    hit ignored;
    lanes_kept keep;
    int b;
    for (b = 0; b < k->block_count; b++) {
        unsigned m = block_candidates(&facet_blocks[b], &q, 0,
                                      block_lanes(k, b), &keep);
        while (m != 0) {
            int lane = __builtin_ctz(m), i = b * BLOCK_LANES + lane;
            m &= m - 1;
            sheared s = kept_lane(&keep, lane);
            if (i != skip &&
                intersect_sheared(&s, &k->tris[i], r, t_max, &ignored) &&
                blocks(&ignored, t_max)) {
                int made = (b + 1) * BLOCK_LANES;
                if (made > k->count)
                    made = k->count;
                *tests += (uint64_t)made - (skip >= 0 && skip < made);
                *saved += (uint64_t)(k->count - made) - (skip >= made);
                *blocker = i;
                return 1;
            }
        }
    }
    *tests += (uint64_t)k->count - (skip >= 0);
    return 0;
}

/*
 * The exact filter over facets picked by index (an octree leaf's): bit j
 * set when facet ids[j] (j < n <= BLOCK_LANES) may be hit.  The vertices
 * are gathered into a block as fill_blocks() lays them out, so every lane
 * computes what intersect() computes.
 */
AVX2 static unsigned gathered_candidates(const KERNEL_T *k, const ray *r,
                                         const int *ids, int n)
{
    _Alignas(32) block b;
    memset(&b, 0, sizeof b);
    for (int lane = 0; lane < n; lane++) {
        const tri *f = &k->tris[ids[lane]];
        const vec *vertex[3] = {&f->a, &f->b, &f->c};
        for (int j = 0; j < 3; j++) {
            b.v[j][0][lane] = vertex[j]->x;
            b.v[j][1][lane] = vertex[j]->y;
            b.v[j][2][lane] = vertex[j]->z;
        }
    }
    vray q;
    broadcast(r, &q);
    lanes_kept unused;  /* the octree's loops call intersect() */
    return block_candidates(&b, &q, 0, (1u << n) - 1, &unused);
}

/* Non-zero when this processor runs the AVX2 loops. */
static int cpu_has_avx2(void)
{
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") != 0;
}

#else /* no AVX2 kernel: the scalar loops only */
#define HAVE_AVX2_KERNEL 0
static int cpu_has_avx2(void) { return 0; }
#endif
