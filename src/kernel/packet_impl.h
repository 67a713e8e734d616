/*
 * packet_impl.h - camera rays in packets: kernel_trace_span(), the
 * table's trace_span (part of kernel_impl.h, compiled once per precision;
 * everything here is static).
 *
 * The camera rays of a few neighbouring pixels - a span of one row, cut
 * into chunks of at most CHUNK_RAYS rays - leave one point, the eye, in
 * nearly one direction.  Two things are shared among them, and nothing
 * else changes:
 *
 * 1. A tile cull.  For rays from the eye whose axis frame (kx, ky, kz and
 *    the winding swap of prepare()) is the same, each edge function of a
 *    facet is an affine function of the ray's shear (sx, sy):
 *        e(sx, sy) = e0 + sx ex + sy ey,
 *    where (ex, ey, e0) is the cross product of the edge's two vertices
 *    (minus the eye) in that frame (expand (px - sx pz)(qy - sy qz) -
 *    (py - sy pz)(qx - sx qz)).  The chunk's rays are prepared as a trace
 *    prepares them, and the box of the shears of those of one frame is
 *    taken from the shears themselves: each edge function stays in an
 *    interval over it.  Where one edge's interval is below -slack and
 *    another's above +slack, every ray of that frame has two edge
 *    functions of strictly opposite signs, as computed by the filter and
 *    by intersect(): `slack` bounds the distance between the computed and
 *    the affine values (see the facets' edge functions below), so the
 *    facet is left out for the whole chunk, as the exact filter would
 *    leave it out for each ray.  (A box from the span's corner rays would
 *    not do: the camera's rounding of the directions, which grows with the
 *    eye's distance from the origin, can put a ray's shear outside it.)
 * 2. SIMD across rays.  The facets the cull keeps are tested against
 *    several rays at a time: one facet broadcast, one ray per lane, through
 *    edges_filter() of simd_impl.h - the filter's own operations, so each
 *    lane is bit for bit what the filter computes for that pair - and the
 *    scalar intersect_sheared() decides every lane the filter passes,
 *    from the filter's values, facet by facet in index order, with each
 *    ray's own t_max and the tie rule of replaces().  So each ray gets the
 *    hit nearest_scalar() gives it.
 *
 * A ray whose frame is not the chunk's (its first ray's; they differ near
 * the diagonals where the dominant axis changes) is traced alone, as
 * kernel_trace() traces it.  The rest of each ray's path (shading, shadow
 * rays, reflections) is the one trace_opaque() of trace_impl.h, told what
 * the packet found of the first hit (a known_hit, shade_impl.h).  Only
 * renders of scenes with at most PACKET_MAX_FACETS facets, brute force,
 * the fast loops and no transparency take this path; the work it saves is
 * the filter's, which dominates there.
 */

#if HAVE_AVX2_KERNEL
#define PACKET_MAX_FACETS 64    /* a span's candidates fit a uint64_t */
#define FRAMES 6                /* kz = 0, 1, 2, without and with the swap */

/*
 * The facets' edge functions u (vertices c, b), v (a, c) and w (b, a) in
 * each frame, as affine functions of the shear, in double, by rows of
 * EDGE_LANES facets: eye->edges[(frame * EDGE_ROWS + row) * padded + i],
 * rows e0 (3, one per edge function), ex (3), ey (3), slack (3).  slack
 * bounds |computed - affine| for a ray of that frame (so |sx|, |sy| <= 1,
 * and so for every point of a box of such rays' shears): the shear values
 * px - sx pz carry at most about 2 eps (|px| + |pz|), the edge function
 * built from them at most 48 eps N_p N_q (N the 1-norm of a vertex minus
 * the eye, eps the kernel's REAL_EPS); the cull's own double arithmetic
 * adds under 8 eps N_p N_q.  slack = 1024 eps N_p N_q covers the sum
 * ten times over.
 * Where the products are subnormal the rounding errors are absolute, a
 * few times REAL_TRUE_MIN each: slack adds 64 of them.  It is infinite (no
 * cull) where a coefficient is not finite.  Padding lanes
 * have zeros, and are masked out.
 */
#define EDGE_ROWS 12
#define EDGE_LANES 4

static int edges_padded(int count)
{
    return (count + EDGE_LANES - 1) / EDGE_LANES * EDGE_LANES;
}

static size_t edges_size(int count)
{
    return (size_t)FRAMES * EDGE_ROWS * (size_t)edges_padded(count);
}

static int frame_index(int kz, int swapped) { return 2 * kz + swapped; }

/* The frame prepare() chose for *r (it swaps kx and ky when d_kz < 0). */
static int ray_frame(const ray *r)
{
    return frame_index(r->kz, r->kx != (r->kz + 1) % 3);
}

/* Fills eye->edges from eye->blocks (the vertices minus the eye, as the
 * filter reads them). */
static void packet_prepare_eye(KERNEL_EYE_T *eye, int count)
{
    int padded = edges_padded(count);
    memset(eye->edges, 0, edges_size(count) * sizeof *eye->edges);
    for (int kz = 0; kz < 3; kz++) {
        for (int swapped = 0; swapped < 2; swapped++) {
            int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
            if (swapped) {
                int t = kx;
                kx = ky;
                ky = t;
            }
            const int axis[3] = {kx, ky, kz};
            double *rows = &eye->edges[(size_t)frame_index(kz, swapped) *
                                       EDGE_ROWS * (size_t)padded];
            for (int i = 0; i < count; i++) {
                const block *b = &eye->blocks[i / BLOCK_LANES];
                int lane = i % BLOCK_LANES;
                double p[3][3], norm[3];    /* vertex, frame axis */
                for (int j = 0; j < 3; j++) {
                    norm[j] = 0;
                    for (int x = 0; x < 3; x++) {
                        p[j][x] = (double)b->v[j][axis[x]][lane];
                        norm[j] += fabs(p[j][x]);
                    }
                }
                static const int pair[3][2] = {{2, 1}, {0, 2}, {1, 0}};
                for (int f = 0; f < 3; f++) {
                    const double *q = p[pair[f][0]], *r = p[pair[f][1]];
                    double e0 = q[0] * r[1] - q[1] * r[0];
                    double ex = q[1] * r[2] - q[2] * r[1];
                    double ey = q[2] * r[0] - q[0] * r[2];
                    double slack = 1024 * (double)REAL_EPS *
                                       norm[pair[f][0]] * norm[pair[f][1]] +
                                   64 * REAL_TRUE_MIN;
                    if (!isfinite(e0) || !isfinite(ex) || !isfinite(ey))
                        slack = INFINITY;
                    rows[(0 + f) * padded + i] = e0;
                    rows[(3 + f) * padded + i] = ex;
                    rows[(6 + f) * padded + i] = ey;
                    rows[(9 + f) * padded + i] = slack;
                }
            }
        }
    }
}

/*
 * The shadow packets' cull.  A shadow ray from O to the light L cannot be
 * blocked by a facet whose plane has O and L strictly on one side: the
 * segment does not reach the plane.  Strictly means by more than what the
 * watertight test can move a point (its rounding of the translated and
 * sheared vertices and of the direction L - O, a few eps times the
 * coordinates, eps the kernel's REAL_EPS), plus the facet's own distance
 * from the plane computed here (`thick2`, twice the largest |n.v - c| of
 * its vertices, in case the normal of a sliver is inaccurate).  The margin
 * taken is 4096 eps 3 max(extent, |O|) - over a hundred times those
 * errors, and far below any distance that matters to the cull.  The
 * argument rests on the hit's t_error bounding the error of t (a blocking
 * hit has t_error < t < 1 - t_error, so the rounded segment crosses the
 * plane), as the watertight test's own exactness does.
 * light_side[l count + i] is +1 or -1, the side of light l, or NaN where
 * the light is within the margin of the plane (no cull).
 */
struct shadow_plane {
    REAL n[3];              /* unit normal */
    REAL c;                 /* n.a */
    REAL thick2;
};

static REAL shadow_margin(REAL extent)
{
    return 4096 * REAL_EPS * 3 * extent;
}

/* Fills k->planes, k->light_side and k->extent; 0 when out of memory. */
static int packet_prepare_kernel(KERNEL_T *k)
{
    k->planes = malloc((size_t)k->count * sizeof *k->planes);
    k->light_side = malloc((size_t)k->count * (size_t)k->light_count *
                           sizeof *k->light_side);
    if (k->planes == NULL || k->light_side == NULL)
        return 0;
    double extent = 0;
    for (int i = 0; i < k->count; i++) {
        const vec *a = corner(k->vertices, &k->tris[i], 0),
                  *b = corner(k->vertices, &k->tris[i], 1),
                  *c = corner(k->vertices, &k->tris[i], 2);
        extent = fmax(extent, fmax(max3(a->x, a->y, a->z),
                                   fmax(max3(b->x, b->y, b->z),
                                        max3(c->x, c->y, c->z))));
    }
    for (int l = 0; l < k->light_count; l++)
        extent = fmax(extent, max3(k->lights[l].x, k->lights[l].y,
                                   k->lights[l].z));
    k->extent = (REAL)extent;
    double margin = (double)shadow_margin(k->extent);
    /* Below this scale the filter's products may be subnormal, and then
     * their rounding moves the watertight test's edges by more than any
     * margin relative to the coordinates: no cull at all. */
    int tiny = extent < 1024 * sqrt((double)REAL_MIN / (double)REAL_EPS);
    for (int i = 0; i < k->count; i++) {
        const tri *f = &k->tris[i];
        double v[3][3];
        for (int j = 0; j < 3; j++) {
            const vec *p = corner(k->vertices, f, j);
            v[j][0] = p->x;
            v[j][1] = p->y;
            v[j][2] = p->z;
        }
        double e1[3], e2[3];
        for (int x = 0; x < 3; x++) {
            e1[x] = v[1][x] - v[0][x];
            e2[x] = v[2][x] - v[0][x];
        }
        double n[3] = {e1[1] * e2[2] - e1[2] * e2[1],
                       e1[2] * e2[0] - e1[0] * e2[2],
                       e1[0] * e2[1] - e1[1] * e2[0]};
        double length = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        struct shadow_plane *p = &k->planes[i];
        for (int x = 0; x < 3; x++)
            p->n[x] = (REAL)(n[x] / length);
        p->c = (REAL)(p->n[0] * v[0][0] + p->n[1] * v[0][1] +
                      p->n[2] * v[0][2]);
        double thick = 0;
        for (int j = 0; j < 3; j++)
            thick = fmax(thick, fabs((double)p->n[0] * v[j][0] +
                                     (double)p->n[1] * v[j][1] +
                                     (double)p->n[2] * v[j][2] - p->c));
        double thick2 = 2 * thick * (1 + 0x1p-10);
        p->thick2 = (REAL)thick2;
        int usable = !tiny && isfinite(length) && length > 0 &&
                     isfinite(thick2) && (double)p->thick2 >= thick2;
        for (int l = 0; l < k->light_count; l++) {
            const vec *L = &k->lights[l];
            double side = (double)p->n[0] * L->x + (double)p->n[1] * L->y +
                          (double)p->n[2] * L->z - p->c;
            REAL sign = (REAL)NAN;
            if (usable && side > margin + thick2)
                sign = 1;
            else if (usable && side < -(margin + thick2))
                sign = -1;
            k->light_side[(size_t)l * (size_t)k->count + (size_t)i] = sign;
        }
    }
    return 1;
}

/* What the rays of a chunk of a span share: their frame and the facets
 * they may hit. */
typedef struct tile {
    int frame;
    int kx, ky, kz;
    uint64_t candidates;    /* bit i: facet i is not culled */
} tile;

/* The facets not culled for shears in the box lo..hi (bit i: facet i), in
 * frame `frame`: a facet is culled where one edge function's interval lies
 * below -slack and another's above +slack. */
AVX2 static uint64_t cull(const KERNEL_EYE_T *eye, int frame,
                          const double lo[2], const double hi[2])
{
    int padded = edges_padded(eye->count);
    const double *rows =
        &eye->edges[(size_t)frame * EDGE_ROWS * (size_t)padded];
    const __m256d lo_x = _mm256_set1_pd(lo[0]), hi_x = _mm256_set1_pd(hi[0]);
    const __m256d lo_y = _mm256_set1_pd(lo[1]), hi_y = _mm256_set1_pd(hi[1]);
    const __m256d zero = _mm256_setzero_pd();
    uint64_t kept = 0;
    for (int i = 0; i < padded; i += EDGE_LANES) {
        __m256d below = zero, above = zero;
        for (int f = 0; f < 3; f++) {
            __m256d e0 = _mm256_loadu_pd(&rows[(0 + f) * padded + i]);
            __m256d ex = _mm256_loadu_pd(&rows[(3 + f) * padded + i]);
            __m256d ey = _mm256_loadu_pd(&rows[(6 + f) * padded + i]);
            __m256d slack = _mm256_loadu_pd(&rows[(9 + f) * padded + i]);
            __m256d x0 = _mm256_mul_pd(lo_x, ex), x1 = _mm256_mul_pd(hi_x, ex);
            __m256d y0 = _mm256_mul_pd(lo_y, ey), y1 = _mm256_mul_pd(hi_y, ey);
            __m256d low = _mm256_add_pd(
                _mm256_add_pd(e0, _mm256_min_pd(x0, x1)), _mm256_min_pd(y0, y1));
            __m256d high = _mm256_add_pd(
                _mm256_add_pd(e0, _mm256_max_pd(x0, x1)), _mm256_max_pd(y0, y1));
            below = _mm256_or_pd(below, _mm256_cmp_pd(_mm256_add_pd(high, slack),
                                                      zero, _CMP_LT_OQ));
            above = _mm256_or_pd(above, _mm256_cmp_pd(_mm256_sub_pd(low, slack),
                                                      zero, _CMP_GT_OQ));
        }
        unsigned culled = (unsigned)_mm256_movemask_pd(_mm256_and_pd(below, above));
        kept |= (uint64_t)(~culled & 0xfu) << i;
    }
    return eye->count == 64 ? kept : kept & (((uint64_t)1 << eye->count) - 1);
}

/*
 * The nearest hits of the n <= VW rays *r[] (all from the eye, all of the
 * tile's frame) among the tile's candidates: found[l] and h[l] as
 * nearest_scalar() gives them to r[l], the same tests counted.
 */
AVX2 static void packet_nearest(const KERNEL_T *k, const KERNEL_EYE_T *eye,
                                const tile *t, const ray *const *r, int n,
                                hit *h,
                                int *found, uint64_t *tests)
{
    _Alignas(32) REAL shear_x[VW], shear_y[VW];
    REAL t_max[VW];
    for (int l = 0; l < VW; l++) {
        shear_x[l] = r[l < n ? l : 0]->sx;
        shear_y[l] = r[l < n ? l : 0]->sy;
        t_max[l] = INFINITY;
        found[l] = 0;
    }
    vreal sx = v_load(shear_x), sy = v_load(shear_y);
    const int axis[3] = {t->kx, t->ky, t->kz};
    unsigned live = (1u << n) - 1;
    lanes_kept keep;
    for (uint64_t left = t->candidates; left != 0; left &= left - 1) {
        int i = __builtin_ctzll(left);
        const block *b = &eye->blocks[i / BLOCK_LANES];
        int lane = i % BLOCK_LANES;
        vreal a[3], bb[3], c[3];
        for (int j = 0; j < 3; j++) {
            a[j] = v_set1(b->v[0][axis[j]][lane]);
            bb[j] = v_set1(b->v[1][axis[j]][lane]);
            c[j] = v_set1(b->v[2][axis[j]][lane]);
        }
        unsigned m = edges_filter(a, bb, c, sx, sy, live, &keep, 0) & live;
        for (; m != 0; m &= m - 1) {
            int l = __builtin_ctz(m);
            hit candidate;
            sheared s = kept_lane(&keep, l);
            if (intersect_sheared(&s, k->vertices, &k->tris[i], r[l],
                                  t_max[l], &candidate))
                keep_nearer(k, i, &candidate, &h[l], &t_max[l], &found[l]);
        }
    }
    *tests += (uint64_t)n * (uint64_t)k->count;
}

/*
 * any_hit() for the n <= VW shadow rays r[] to light `light` (all of one
 * frame; ray l leaves facet skip[l]): blocked[l] as any_hit_avx2() answers
 * for r[l], its tests counted as it counts them.  Facets are taken in
 * index order, each against the rays still unblocked that the plane cull
 * keeps, through the filter and intersect_sheared().
 */
AVX2 static void packet_any_hit(const KERNEL_T *k, int light, const ray *r,
                                const int *skip, int n, signed char *blocked,
                                rt_counters *counters)
{
    _Alignas(32) REAL origin[3][VW], world[3][VW], margin[VW];
    _Alignas(32) REAL shear_x[VW], shear_y[VW];
    const int axis[3] = {r[0].kx, r[0].ky, r[0].kz};
    int blocker[VW];
    for (int l = 0; l < VW; l++) {
        const ray *q = &r[l < n ? l : 0];
        for (int j = 0; j < 3; j++)
            origin[j][l] = get(q->origin, axis[j]);
        world[0][l] = q->origin.x;
        world[1][l] = q->origin.y;
        world[2][l] = q->origin.z;
        REAL size = max3(q->origin.x, q->origin.y, q->origin.z);
        margin[l] = shadow_margin(k->extent > size ? k->extent : size);
        shear_x[l] = q->sx;
        shear_y[l] = q->sy;
        blocker[l] = -1;
    }
    vreal o[3], w[3];
    for (int j = 0; j < 3; j++) {
        o[j] = v_load(origin[j]);
        w[j] = v_load(world[j]);
    }
    vreal sx = v_load(shear_x), sy = v_load(shear_y), room = v_load(margin);
    unsigned live = (1u << n) - 1;
    const REAL *side = &k->light_side[(size_t)light * (size_t)k->count];
    lanes_kept keep;
    hit ignored;
    unsigned char leaves[PACKET_MAX_FACETS] = {0};  /* lanes by facet left */
    for (int l = 0; l < n; l++)
        if (skip[l] >= 0)
            leaves[skip[l]] |= (unsigned char)(1u << l);
    for (int i = 0; i < k->count && live != 0; i++) {
        unsigned m = live & ~(unsigned)leaves[i];
        if (side[i] == side[i] && m != 0) {
            const struct shadow_plane *p = &k->planes[i];
            vreal s = v_sub(v_add(v_add(v_mul(v_set1(p->n[0]), w[0]),
                                        v_mul(v_set1(p->n[1]), w[1])),
                                  v_mul(v_set1(p->n[2]), w[2])),
                            v_set1(p->c));
            vreal culled = v_cmp(v_mul(s, v_set1(side[i])),
                                 v_add(room, v_set1(p->thick2)), _CMP_GT_OQ);
            m &= ~(unsigned)v_movemask(culled);
        }
        if (m == 0)
            continue;
        const tri *f = &k->tris[i];
        vec fa = *corner(k->vertices, f, 0), fb = *corner(k->vertices, f, 1),
            fc = *corner(k->vertices, f, 2);
        vreal a[3], b[3], c[3];
        for (int j = 0; j < 3; j++) {
            a[j] = v_sub(v_set1(get(fa, axis[j])), o[j]);
            b[j] = v_sub(v_set1(get(fb, axis[j])), o[j]);
            c[j] = v_sub(v_set1(get(fc, axis[j])), o[j]);
        }
        m &= edges_filter(a, b, c, sx, sy, m, &keep, 0);
        for (; m != 0; m &= m - 1) {
            int l = __builtin_ctz(m);
            sheared s = kept_lane(&keep, l);
            if (intersect_sheared(&s, k->vertices, f, &r[l], 1, &ignored) &&
                blocks(&ignored, 1)) {
                blocker[l] = i;
                live &= ~(1u << l);
            }
        }
    }
    for (int l = 0; l < n; l++) {
        int skipped = skip[l];
        blocked[l] = blocker[l] >= 0;
        if (blocker[l] < 0) {
            counters->ray_facet_tests += (uint64_t)k->count - (skipped >= 0);
            continue;
        }
        int made = (blocker[l] / BLOCK_LANES + 1) * BLOCK_LANES;
        if (made > k->count)
            made = k->count;
        counters->ray_facet_tests +=
            (uint64_t)made - (skipped >= 0 && skipped < made);
        counters->early_exit_saved +=
            (uint64_t)(k->count - made) - (skipped >= made);
    }
}

/*
 * The first bounce of the n <= VW camera rays whose nearest hits (found[l],
 * h[l]) a packet found: hit points and normals as shade_hit() computes
 * them, and the shadow rays to each light cast in packets of one frame
 * (the rays of another frame are left to the trace).
 */
static void packet_first_bounce(const KERNEL_T *k, vec origin,
                                const vec *incoming, const int *found,
                                const hit *h, int n, known_hit *out,
                                rt_counters *counters)
{
    for (int l = 0; l < n; l++) {
        known_hit *b = &out[l];
        b->found = found[l];
        memset(b->blocked, -1, sizeof b->blocked);
        if (!found[l])
            continue;
        b->h = &h[l];
        const tri *f = &k->tris[h[l].index];
        b->point = hit_point(k->vertices, f, &h[l], origin, incoming[l],
                             &b->error_bound);
        b->normal = dot(f->normal, incoming[l]) > 0 ? neg(f->normal)
                                                    : f->normal;
    }
    if (k->planes == NULL)
        return;
    for (int light = 0; light < k->light_count; light++) {
        ray shadow[VW];
        int skip[VW], lane[VW], m = 0, frame = -1;
        for (int l = 0; l < n; l++) {
            const known_hit *b = &out[l];
            /* A smooth facet's shadow rays leave its shading point
             * (shade_hit): left to the trace. */
            if (!b->found ||
                k->materials[k->tris[b->h->index].material].d == 0 ||
                (k->smooth != NULL && k->smooth[b->h->index]))
                continue;
            vec to_light = sub(k->lights[light], b->point);
            if (!(dot(b->normal, to_light) > 0))
                continue;
            ray *q = &shadow[m];
            *q = shadow_ray(b->point, b->error_bound, b->normal,
                            k->lights[light], to_light);
            int its = ray_frame(q);
            if (frame < 0)
                frame = its;
            if (its != frame)
                continue;
            skip[m] = b->h->index;
            lane[m++] = l;
        }
        if (m == 0)
            continue;
        signed char blocked[VW];
        packet_any_hit(k, light, shadow, skip, m, blocked, counters);
        for (int j = 0; j < m; j++)
            out[lane[j]].blocked[light] = blocked[j];
    }
}

/* One camera ray traced alone, as kernel_trace() traces it, `known` (may
 * be NULL) its first hit. */
HOT_INLINE rt_color trace_alone(const trace_ctx *c, vec origin,
                                vec incoming, const known_hit *known,
                                int shading)
{
    /* Packets run by brute force with the AVX2 loops, unrecorded: a
     * context that says so in constants, so that the loop's octree,
     * scalar and recording code is compiled away, and with `shading` a
     * constant of the two copies below. */
    const trace_ctx plain = {c->k,    NULL,         c->eye,      1,
                             c->fast, c->max_depth, c->counters, NULL,
                             NULL,    shading};
    REAL color[3] = {0, 0, 0};
    trace_opaque(&plain, origin, incoming, known, color);
    return (rt_color){color[0], color[1], color[2]};
}

/* The copy for kernels without smooth facets or highlights. */
static rt_color trace_alone_flat(const trace_ctx *c, vec origin,
                                 vec incoming, const known_hit *known)
{
    return trace_alone(c, origin, incoming, known, 0);
}

/* The copy for the others. */
static rt_color trace_alone_shaded(const trace_ctx *c, vec origin,
                                   vec incoming, const known_hit *known)
{
    return trace_alone(c, origin, incoming, known, 1);
}
#else /* no AVX2 kernel: no packets, and nothing prepared for them */
#define PACKET_MAX_FACETS 0
static size_t edges_size(int count) { (void)count; return 0; }
static void packet_prepare_eye(KERNEL_EYE_T *eye, int count)
{
    (void)eye;
    (void)count;
}
static int packet_prepare_kernel(KERNEL_T *k) { (void)k; return 1; }
#endif

/* Rays of a span that share one tile cull at most. */
#define CHUNK_RAYS 64

static void kernel_trace_span(const rt_kernel *kernel, rt_vec3 origin_d,
                              const rt_vec3 *directions, int count,
                              const rt_trace_settings *settings,
                              rt_counters *counters, rt_color *colors)
{
#if HAVE_AVX2_KERNEL
    const KERNEL_T *k = kernel_of(kernel);
    const trace_ctx c = trace_context(k, settings, counters, NULL);
    const KERNEL_EYE_T *eye = c.eye;
    vec origin = from_rt(origin_d);
    int packets = c.simd && eye != NULL && eye->edges != NULL &&
                  !k->transparent && !settings->octree && !settings->kdtree &&
                  settings->recorder == NULL &&
                  memcmp(&eye->origin, &origin, sizeof origin) == 0;
#else
    int packets = 0;
#endif
    if (!packets) {
        for (int j = 0; j < count; j++)
            colors[j] = kernel_trace(kernel, origin_d, directions[j],
                                     settings, counters);
        return;
    }
#if HAVE_AVX2_KERNEL
    int fast = c.fast;
    rt_color (*const alone)(const trace_ctx *, vec, vec, const known_hit *) =
        k->shading ? trace_alone_shaded : trace_alone_flat;
    for (int begin = 0; begin < count; begin += CHUNK_RAYS) {
        int end = begin + CHUNK_RAYS < count ? begin + CHUNK_RAYS : count;
        /* The chunk's rays as a trace prepares them; the tile's frame is
         * the first ray's, its box of shears the hull of the shears of the
         * rays of that frame - so every ray packed below lies in it. */
        ray q[CHUNK_RAYS];
        vec in[CHUNK_RAYS];
        tile t = {-1, 0, 0, 0, 0};   /* set by the first ray */
        double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
        for (int j = begin; j < end; j++) {
            ray *r = &q[j - begin];
            in[j - begin] = normalize(from_rt(directions[j]), fast);
            *r = prepare(origin, in[j - begin]);
            int frame = ray_frame(r);
            if (j == begin) {
                t.frame = frame;
                t.kx = r->kx;
                t.ky = r->ky;
                t.kz = r->kz;
            }
            if (frame != t.frame)
                continue;
            double s[2] = {(double)r->sx, (double)r->sy};
            for (int a = 0; a < 2; a++) {
                lo[a] = s[a] < lo[a] ? s[a] : lo[a];
                hi[a] = s[a] > hi[a] ? s[a] : hi[a];
            }
        }
        t.candidates = cull(eye, t.frame, lo, hi);
        const ray *r[VW];
        vec incoming[VW];
        int slot[VW], n = 0;
        for (int j = begin; j <= end; j++) {
            if (j < end) {
                const ray *p = &q[j - begin];
                if (ray_frame(p) != t.frame) {
                    colors[j] = alone(&c, origin, in[j - begin], NULL);
                    continue;
                }
                r[n] = p;
                incoming[n] = in[j - begin];
                slot[n++] = j;
                if (n < VW)
                    continue;
            }
            if (n == 0)
                continue;
            hit h[VW];
            int found[VW];
            packet_nearest(k, eye, &t, r, n, h, found,
                           &counters->ray_facet_tests);
            known_hit first[VW];
            packet_first_bounce(k, origin, incoming, found, h, n, first,
                                counters);
            for (int l = 0; l < n; l++)
                colors[slot[l]] = alone(&c, origin, incoming[l],
                                              &first[l]);
            n = 0;
        }
    }
#endif
}
