/*
 * triangulate.c - polygons into triangles: fans and balanced cuts for
 * convex polygons, ear clipping under a work budget for the others
 * (triangulate.h says what each costs and why).
 *
 * Ear clipping keeps the corners left in a ring (next, prev) and the
 * corners that are not convex in a list of their own: only those can lie
 * inside a convex corner's triangle in a simple polygon, so testing a
 * corner costs the length of that list.  Each corner carries a flag "is an
 * ear", computed once for all and then again only for the two neighbours
 * of a clipped corner (the others cannot change in a simple polygon), and
 * checked again before a corner is clipped, so that a polygon that crosses
 * itself cannot make a stale flag cut outside it.  The search for the next
 * ear resumes at the corner before the one clipped (at the next one when
 * the clipped corner was the first left), as the readers' ear clipping
 * always did, so simple polygons are cut as before.
 */
#include "formats/triangulate.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/exact.h"
#include "base/vecmath.h"

#define PI 3.14159265358979323846

enum {
    CONVEX = 1,     /* turns left */
    FLAT = 2,       /* on a straight line with its neighbours (or a spike) */
    LISTED = 4,     /* in the list of corners that are not convex */
    EAR = 8         /* convex, with no listed corner in its triangle */
};

/* One call: the polygon and where its triangles go. */
typedef struct polygon {
    rt_triangulator *t;
    const rt_vec3 *points;
    const int *corners;
    int n;
    rt_tri_emit emit;
    void *user;
    rt_tri_result *result;
    int head;               /* first listed corner, or -1 */
} polygon;

void rt__tri_init(rt_triangulator *t, double work, const rt_cancel *cancel)
{
    memset(t, 0, sizeof *t);
    t->work_left = work;
    t->cancel = cancel;
}

void rt__tri_free(rt_triangulator *t)
{
    free(t->xy);
    free(t->next);
    free(t->prev);
    free(t->bnext);
    free(t->bprev);
    free(t->flags);
    t->xy = NULL;
    t->next = t->prev = t->bnext = t->bprev = NULL;
    t->flags = NULL;
    t->capacity = 0;
}

static int reserve(rt_triangulator *t, int n)
{
    if (n <= t->capacity)
        return 1;
    size_t m = (size_t)n;
    double *xy = realloc(t->xy, 2 * m * sizeof *xy);
    if (xy != NULL)
        t->xy = xy;
    int **ints[] = {&t->next, &t->prev, &t->bnext, &t->bprev};
    int ok = xy != NULL;
    for (size_t i = 0; i < sizeof ints / sizeof ints[0]; i++) {
        int *grown = realloc(*ints[i], m * sizeof *grown);
        if (grown != NULL)
            *ints[i] = grown;
        ok = ok && grown != NULL;
    }
    unsigned char *flags = realloc(t->flags, m);
    if (flags != NULL)
        t->flags = flags;
    if (!ok || flags == NULL)
        return 0;
    t->capacity = n;
    return 1;
}

static int id(const polygon *p, int i)
{
    return p->corners != NULL ? p->corners[i] : i;
}

static rt_vec3 corner(const polygon *p, int i)
{
    return p->points[id(p, i)];
}

/* Twice the signed area of corners a, b, c in the plane. */
static double turn(const polygon *p, int a, int b, int c)
{
    const double *xy = p->t->xy;
    return (xy[2 * b] - xy[2 * a]) * (xy[2 * c + 1] - xy[2 * a + 1]) -
           (xy[2 * b + 1] - xy[2 * a + 1]) * (xy[2 * c] - xy[2 * a]);
}

static int same_point(const polygon *p, int a, int b)
{
    const double *xy = p->t->xy;
    return xy[2 * a] == xy[2 * b] && xy[2 * a + 1] == xy[2 * b + 1];
}

/*
 * Fills t->xy with the corners projected onto the polygon's best-fit
 * plane: the Newell normal of the corners, on coordinates moved to the
 * first corner and scaled to at most 1 (no overflow at any size), and an
 * orthonormal pair (e1, e2) with e1 x e2 along it, so that the polygon
 * winds counter-clockwise.  This is the plane (and the arithmetic) the
 * OBJ reader always cut its polygons in, so its decisions, and the
 * triangles, stay those of every earlier release.  Returns 0 when the
 * polygon has no area.
 */
static int project(polygon *p)
{
    rt_vec3 origin = corner(p, 0);
    double scale = 0.0;
    for (int i = 1; i < p->n; i++)
        scale = fmax(scale, v3_max_abs(v3_sub(corner(p, i), origin)));
    if (!(scale > 0.0) || !isfinite(scale))
        return 0;
    rt_vec3 normal = v3(0, 0, 0);
    for (int i = 0; i < p->n; i++) {
        rt_vec3 a = v3_scale(v3_sub(corner(p, i), origin), 1.0 / scale);
        rt_vec3 b = v3_scale(v3_sub(corner(p, (i + 1) % p->n), origin),
                             1.0 / scale);
        normal.x += (a.y - b.y) * (a.z + b.z);
        normal.y += (a.z - b.z) * (a.x + b.x);
        normal.z += (a.x - b.x) * (a.y + b.y);
    }
    if (!(v3_max_abs(normal) > 0.0))
        return 0;
    rt_vec3 w = v3_normalize(normal);
    /* e1 perpendicular to w, along the axis w leans on least. */
    rt_vec3 axis = fabs(w.x) <= fabs(w.y) && fabs(w.x) <= fabs(w.z)
                       ? v3(1, 0, 0)
                       : fabs(w.y) <= fabs(w.z) ? v3(0, 1, 0) : v3(0, 0, 1);
    rt_vec3 e1 = v3_normalize(v3_cross(axis, w));
    rt_vec3 e2 = v3_cross(w, e1);       /* (e1, e2, w) right-handed */
    for (int i = 0; i < p->n; i++) {
        rt_vec3 q = v3_scale(v3_sub(corner(p, i), origin), 1.0 / scale);
        p->t->xy[2 * i] = v3_dot(q, e1);
        p->t->xy[2 * i + 1] = v3_dot(q, e2);
    }
    return 1;
}

/* What the corners' turns make of a polygon. */
typedef enum shape {
    NOT_CONVEX,
    ALL_TURNING,        /* convex, every corner turning left */
    SOME_STRAIGHT,      /* convex, some corners going straight on */
    DENTED              /* convex but for corners turning right by a dent
                           of at most RT_TRI_DENT of the extent */
} shape;

/* The turns add up to one turn (not a star that winds twice), one left
 * turn at least, and no corner turns right by more than a dent. */
static shape convexity(const polygon *p)
{
    const double *xy = p->t->xy;
    double winding = 0.0;
    int left = 0, flat = 0, dented = 0;
    for (int i = 0; i < p->n; i++) {
        int a = i, b = (i + 1) % p->n, c = (i + 2) % p->n;
        double cross = turn(p, a, b, c);
        if (cross < 0.0) {
            /* b's distance inside the chord a-c; the coordinates are
             * scaled to the polygon's extent */
            double chord = hypot(xy[2 * c] - xy[2 * a],
                                 xy[2 * c + 1] - xy[2 * a + 1]);
            if (!(-cross <= RT_TRI_DENT * chord))
                return NOT_CONVEX;
            dented = 1;
        }
        left |= cross > 0.0;
        flat |= cross == 0.0;
        double dot = (xy[2 * b] - xy[2 * a]) * (xy[2 * c] - xy[2 * b]) +
                     (xy[2 * b + 1] - xy[2 * a + 1]) *
                         (xy[2 * c + 1] - xy[2 * b + 1]);
        winding += atan2(cross, dot);
    }
    if (!left || !(fabs(winding - 2.0 * PI) < 1.0))
        return NOT_CONVEX;
    return dented ? DENTED : flat ? SOME_STRAIGHT : ALL_TURNING;
}

/* Emits corners (a, b, c) when they bound an area. */
static rt_status triangle(polygon *p, int a, int b, int c)
{
    if (!rt__triangle_has_area(corner(p, a), corner(p, b), corner(p, c))) {
        p->result->dropped++;
        return RT_OK;
    }
    p->result->facets++;
    return p->emit(p->user, id(p, a), id(p, b), id(p, c));
}

static rt_status poll(rt_triangulator *t)
{
    if (t->since_poll < RT_TRI_POLL_WORK)
        return RT_OK;
    t->since_poll = 0;
    return t->cancel != NULL && rt_cancel_requested(t->cancel)
               ? RT_ERR_CANCELLED
               : RT_OK;
}

/* A fan from the last corner, as ear clipping from corner 0 cuts a
 * convex polygon: (n-1, i, i+1), and the three corners left last in their
 * order, (n-3, n-2, n-1). */
static rt_status fan_from_last(polygon *p)
{
    rt_status status = RT_OK;
    for (int i = 0; i + 3 < p->n && status == RT_OK; i++)
        status = triangle(p, p->n - 1, i, i + 1);
    if (status == RT_OK)
        status = triangle(p, p->n - 3, p->n - 2, p->n - 1);
    return status;
}

/* Each chain lo..hi (hi - lo >= 2) of the corners order[0..m) (0..m
 * when order is NULL) gives (lo, mid, hi) and is split at its middle
 * corner, depth first; the first chain is the whole ring.  The stack
 * holds at most two chains a level. */
static rt_status balanced(polygon *p, const int *order, int m)
{
    int stack[2 * 64][2], depth = 0;
    stack[depth][0] = 0;
    stack[depth++][1] = m - 1;
    rt_status status = RT_OK;
    while (depth > 0 && status == RT_OK) {
        int lo = stack[depth - 1][0], hi = stack[depth - 1][1];
        depth--;
        if (hi - lo < 2)
            continue;
        int mid = lo + (hi - lo) / 2;
        status = order ? triangle(p, order[lo], order[mid], order[hi])
                       : triangle(p, lo, mid, hi);
        p->t->since_poll += 1;
        if (status == RT_OK)
            status = poll(p->t);
        stack[depth][0] = mid;
        stack[depth++][1] = hi;
        stack[depth][0] = lo;
        stack[depth++][1] = mid;
    }
    return status;
}

/* The `left` corners of the ring from `first`, cut balanced: what the
 * budget leaves of a polygon. */
static rt_status balanced_ring(polygon *p, int first, int left)
{
    int *order = p->t->bprev;   /* the list of corners is done with */
    for (int i = 0, b = first; i < left; i++, b = p->t->next[b])
        order[i] = b;
    p->result->over_budget = 1;
    return balanced(p, order, left);
}

/* The corners left, as a fan from `first`. */
static rt_status fan_ring(polygon *p, int first)
{
    const int *next = p->t->next;
    rt_status status = RT_OK;
    for (int b = next[first]; next[b] != first && status == RT_OK;
         b = next[b])
        status = triangle(p, first, b, next[b]);
    return status;
}

static void list_add(polygon *p, int b)
{
    rt_triangulator *t = p->t;
    t->bnext[b] = p->head;
    t->bprev[b] = -1;
    if (p->head >= 0)
        t->bprev[p->head] = b;
    p->head = b;
    t->flags[b] |= LISTED;
}

static void list_remove(polygon *p, int b)
{
    rt_triangulator *t = p->t;
    if (t->bprev[b] >= 0)
        t->bnext[t->bprev[b]] = t->bnext[b];
    else
        p->head = t->bnext[b];
    if (t->bnext[b] >= 0)
        t->bprev[t->bnext[b]] = t->bprev[b];
    t->flags[b] &= (unsigned char)~LISTED;
}

/* Sets corner b's kind from its neighbours, and lists it when it is not
 * convex. */
static void classify(polygon *p, int b)
{
    rt_triangulator *t = p->t;
    double cross = turn(p, t->prev[b], b, t->next[b]);
    unsigned char f = t->flags[b] & (unsigned char)~(CONVEX | FLAT);
    f |= cross > 0.0 ? CONVEX : cross == 0.0 ? FLAT : 0;
    t->flags[b] = f;
    if (cross <= 0.0 && !(f & LISTED))
        list_add(p, b);
    else if (cross > 0.0 && (f & LISTED))
        list_remove(p, b);
}

/* Non-zero when corner b is convex and no listed corner lies in its
 * triangle or on its edges (those at its corners' places excepted). */
static int is_ear(polygon *p, int b)
{
    rt_triangulator *t = p->t;
    if (!(t->flags[b] & CONVEX))
        return 0;
    int a = t->prev[b], c = t->next[b];
    for (int q = p->head; q >= 0; q = t->bnext[q]) {
        t->work_left -= 1;
        t->since_poll += 1;
        if (q == a || q == c || same_point(p, q, a) || same_point(p, q, b) ||
            same_point(p, q, c))
            continue;
        if (turn(p, a, b, q) >= 0 && turn(p, b, c, q) >= 0 &&
            turn(p, c, a, q) >= 0)
            return 0;
    }
    return 1;
}

static void mark_ear(polygon *p, int b)
{
    if (is_ear(p, b))
        p->t->flags[b] |= EAR;
    else
        p->t->flags[b] &= (unsigned char)~EAR;
}

/* Every corner's ear flag, or 0 when that would overspend the budget. */
static int mark_every_ear(polygon *p, int first, int left)
{
    rt_triangulator *t = p->t;
    double convex_count = 0, listed = 0;
    int b = first;
    for (int i = 0; i < left; i++, b = t->next[b]) {
        convex_count += (t->flags[b] & CONVEX) != 0;
        listed += (t->flags[b] & LISTED) != 0;
    }
    if (convex_count * listed > t->work_left)
        return 0;
    for (int i = 0; i < left; i++, b = t->next[b])
        mark_ear(p, b);
    return 1;
}

/* Ear clipping of the projected polygon (docs/formats.md). */
static rt_status clip_ears(polygon *p)
{
    rt_triangulator *t = p->t;
    int n = p->n;
    for (int i = 0; i < n; i++) {
        t->next[i] = (i + 1) % n;
        t->prev[i] = (i + n - 1) % n;
        t->flags[i] = 0;
    }
    p->head = -1;
    for (int i = 0; i < n; i++)
        classify(p, i);
    int first = 0, cur = 0, left = n;
    if (!mark_every_ear(p, first, left))
        return balanced_ring(p, first, left);
    rt_status status = RT_OK;
    while (left > 3 && status == RT_OK) {
        if ((status = poll(t)) != RT_OK)
            break;
        if (t->work_left < 0)
            return balanced_ring(p, first, left);
        int b = cur, found = -1;
        for (int step = 0; step < left && found < 0; step++) {
            t->work_left -= 1;
            if ((t->flags[b] & EAR) && is_ear(p, b))
                found = b;
            else
                t->flags[b] &= (unsigned char)~EAR;
            b = found < 0 ? t->next[b] : b;
        }
        int dropped_flat = 0;
        if (found < 0) {
            /* No ear: a corner on a straight line bounds no area and goes
             * without a facet (the first such in the polygon's order),
             * after which every flag is computed again; without one, the
             * polygon crosses itself. */
            b = first;
            for (int step = 0; step < left && found < 0; step++) {
                t->work_left -= 1;
                found = (t->flags[b] & FLAT) ? b : -1;
                b = t->next[b];
            }
            if (found < 0) {
                p->result->crossing = 1;
                return fan_ring(p, first);
            }
            dropped_flat = 1;
        } else {
            status = triangle(p, t->prev[found], found, t->next[found]);
        }
        int a = t->prev[found], c = t->next[found];
        t->next[a] = c;
        t->prev[c] = a;
        if (t->flags[found] & LISTED)
            list_remove(p, found);
        cur = found == first ? c : a;
        first = found == first ? c : first;
        left--;
        classify(p, a);
        classify(p, c);
        if (dropped_flat) {
            if (!mark_every_ear(p, first, left))
                return balanced_ring(p, first, left);
        } else {
            mark_ear(p, a);
            mark_ear(p, c);
        }
    }
    if (status == RT_OK && left == 3)
        status = triangle(p, first, t->next[first], t->next[t->next[first]]);
    return status;
}

rt_status rt__triangulate(rt_triangulator *t, const rt_vec3 *points,
                          const int *corners, int n, rt_tri_emit emit,
                          void *user, rt_tri_result *result)
{
    rt_tri_result ignored;
    if (result == NULL)
        result = &ignored;
    memset(result, 0, sizeof *result);
    if (!reserve(t, n))
        return RT_ERR_NOMEM;
    polygon p = {t, points, corners, n, emit, user, result, -1};
    t->since_poll += n;
    rt_status status = poll(t);
    if (status != RT_OK)
        return status;
    if (!project(&p)) {
        /* No area: a fan, of which only triangles with an area stay (a
         * figure eight whose halves cancel has some). */
        for (int i = 0; i < n; i++)
            t->next[i] = (i + 1) % n;
        status = fan_ring(&p, 0);
        result->crossing = result->facets > 0;
        return status;
    }
    shape s = convexity(&p);
    if (s != NOT_CONVEX && n > RT_TRI_FAN_MAX_CORNERS)
        return balanced(&p, NULL, n);
    /* Small convex polygons: the fan, which is what ear clipping finds when
     * every corner turns; with corners on a straight line (which are no
     * ears) or dents, ear clipping itself, for the triangles it gave. */
    if (s == ALL_TURNING)
        return fan_from_last(&p);
    return clip_ears(&p);
}

int rt__tri_is_convex(rt_triangulator *t, const rt_vec3 *points,
                      const int *corners, int n)
{
    if (n < 3 || !reserve(t, n))
        return 0;
    rt_tri_result result;
    polygon p = {t, points, corners, n, NULL, NULL, &result, -1};
    return project(&p) && convexity(&p) != NOT_CONVEX;
}
