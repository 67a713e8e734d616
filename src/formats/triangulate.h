/*
 * triangulate.h - the one polygon triangulator of the readers (internal):
 * OBJ faces and NFF polygons become triangles here (docs/formats.md,
 * "Polygons into facets").
 *
 * A polygon of n corners is projected onto its best-fit plane (the plane
 * of its Newell normal), where it winds counter-clockwise; its convexity
 * and its ears are decided there in floating point, as the OBJ reader
 * always decided them, so that the meshes of every earlier release are cut
 * into the same triangles.  Whether a triangle has an area is decided
 * exactly (exact.h, the scene builder's own test), and no triangle without
 * one is ever emitted (the builder would keep it as a zero-area facet):
 *
 * - a convex polygon costs O(n): a fan from its last corner when it has at
 *   most RT_TRI_FAN_MAX_CORNERS corners, every corner turning (the
 *   triangles, corners in the same order, that ear clipping starting at
 *   corner 0 finds: (n-1, i, i+1), then (n-3, n-2, n-1); with corners on a
 *   straight line, ear clipping itself), else a balanced triangulation
 *   (each chain split at its middle corner), so that the thin triangles
 *   are short and near the boundary instead of n slivers meeting at one
 *   corner.  Convex here allows dents of at most RT_TRI_DENT of the
 *   polygon's extent: a circle written with 6 or 9 decimals is not
 *   convex to the last bit;
 * - any other polygon is cut by ear clipping, O(n r) for r corners that
 *   are not convex (O(n^2) at worst), under the work budget of the
 *   triangulator, shared by every polygon of a load; what is left of a
 *   polygon when the budget is spent is cut balanced, one that has no ear
 *   left (it crosses itself) or no area at all as a fan from its first
 *   remaining corner (as the OBJ reader always did).
 *
 * Every triangle keeps the polygon's winding: (b - a) x (c - a) points
 * where its Newell normal does.
 */
#ifndef RAYTRACE_TRIANGULATE_H
#define RAYTRACE_TRIANGULATE_H

#include "raytrace/render.h"
#include "raytrace/scene.h"

/* Convex polygons of at most this many corners are fans (the shape every
 * earlier release gave them, so their images do not change); larger ones
 * are triangulated balanced. */
#define RT_TRI_FAN_MAX_CORNERS 64

/* The ear-clipping budget of an OBJ load, in corner tests (a point tested
 * against a triangle, or a step of the search for an ear; about 10 ns
 * each): RT_TRI_WORK_PER_BYTE per byte of the file plus RT_TRI_WORK_FLOOR,
 * so that a megabyte of non-convex polygons costs at most about 3 s, and
 * a polygon of up to a few thousand corners is always clipped whole. */
#define RT_TRI_WORK_PER_BYTE 256
#define RT_TRI_WORK_FLOOR (1 << 25)

/* The deepest dent a convex polygon may have, relative to its extent: the
 * rounding of coordinates written with 6 significant digits (5e-7), with
 * room.  Below a millionth of a polygon's size a dent is no pixel of any
 * image up to 16384 pixels wide seeing it whole, and cutting across it is
 * O(n) instead of ear clipping's O(n^2). */
#define RT_TRI_DENT 1e-6

/* How often the cancel flag is polled: every this many corner tests. */
#define RT_TRI_POLL_WORK (1 << 16)

/* What one call did. */
typedef struct rt_tri_result {
    int facets;         /* triangles emitted */
    int dropped;        /* triangles without area left out */
    int crossing;       /* non-zero: no ear was left (the polygon crosses
                           itself) or it had no area; the rest is a fan */
    int over_budget;    /* non-zero: the budget was spent; the rest (or
                           all) is cut balanced, without looking for
                           ears */
} rt_tri_result;

/* A triangulator: its scratch memory, its budget and the cancel flag. */
typedef struct rt_triangulator {
    double work_left;           /* corner tests still allowed */
    const rt_cancel *cancel;    /* may be NULL */
    double since_poll;          /* work since the flag was last polled */
    /* scratch, for `capacity` corners */
    double *xy;
    int *next, *prev, *bnext, *bprev;
    unsigned char *flags;
    int capacity;
} rt_triangulator;

/* A triangulator with `work` corner tests to spend and `cancel` (may be
 * NULL) to poll.  rt__tri_free releases its scratch. */
void rt__tri_init(rt_triangulator *t, double work, const rt_cancel *cancel);
void rt__tri_free(rt_triangulator *t);

/* Called with each triangle, as three entries of the polygon's `corners`
 * (or positions when corners is NULL); returns RT_OK or a status that
 * stops the triangulation (and is returned). */
typedef rt_status (*rt_tri_emit)(void *user, int a, int b, int c);

/*
 * Triangulates the polygon whose i-th corner is points[corners[i]]
 * (points[i] when `corners` is NULL), n >= 3, calling `emit` with each
 * triangle; fills *result (may be NULL).  Returns RT_OK, RT_ERR_NOMEM
 * (scratch memory), RT_ERR_CANCELLED (the flag was raised) or what `emit`
 * returned.  Corners repeated next to each other are the caller's to
 * remove (they are harmless: their triangles have no area).
 */
rt_status rt__triangulate(rt_triangulator *t, const rt_vec3 *points,
                          const int *corners, int n, rt_tri_emit emit,
                          void *user, rt_tri_result *result);

/* Non-zero when the polygon is convex in the plane of its Newell normal
 * (corners on a straight line and dents of at most RT_TRI_DENT allowed,
 * not a star that winds twice): rt__triangulate cuts it in O(n).  0 also
 * when out of memory.  O(n). */
int rt__tri_is_convex(rt_triangulator *t, const rt_vec3 *points,
                      const int *corners, int n);

#endif /* RAYTRACE_TRIANGULATE_H */
