/*
 * obj_normals.c - an OBJ's vertex normals (obj.h; docs/formats.md, OBJ,
 * "Vertex normals").  A scene's normal belongs to a vertex, an OBJ's to a
 * corner (`v//vn`): the first normal a vertex is used with is its own, and
 * a corner that uses it with another (or with none after one, or one after
 * none) gets a copy of the vertex at the end of the array, found again by
 * a hash of its (v, vn) pair.  Positions never change, so neither does the
 * geometry.  Nothing here is allocated before the first `vn`: a file
 * without normals gives the scene it always gave, vertex for vertex.
 *
 * Memory: 24 bytes a `vn` (at least 7 bytes of input each), 4 bytes a
 * vertex for its normal, and for the copies 24 + 4 bytes each, 4 a vertex
 * for where it is, and 12 bytes (at most twice) in the hash; a copy costs
 * at least a corner of a face, 4 bytes of input (`1//2`).
 */
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/vecmath.h"
#include "formats/obj.h"

#define NOT_USED (-2)           /* slot: the vertex is in no face yet */

struct obj_pair {
    int v, vn;                  /* the `v` (0-based) and its `vn` or -1 */
    int position;               /* its copy in vertices[]; -1: empty */
};

/* A unit normal, or zero for the zero vector (scaled first by its largest
 * component, so that tiny and huge ones keep a length). */
static rt_vec3 unit(rt_vec3 v)
{
    double m = v3_max_abs(v);
    if (!(m > 0.0) || !isfinite(m))
        return v3(0, 0, 0);
    rt_vec3 w = v3_scale(v, 1.0 / m);
    return v3_scale(w, 1.0 / v3_length(w));
}

/* The first `vn`: every vertex gets a slot, and those of the faces read
 * so far (without normals) have none. */
static int open_slots(reader *r)
{
    int capacity = r->vertex_capacity > 0 ? r->vertex_capacity : 64;
    r->slot = malloc((size_t)capacity * sizeof *r->slot);
    if (r->slot == NULL)
        return 0;
    r->slot_capacity = capacity;
    for (int i = 0; i < capacity; i++)
        r->slot[i] = NOT_USED;
    for (int i = 0; i < r->facet_count; i++)
        for (int j = 0; j < 3; j++)
            r->slot[r->facets[i].vertex[j]] = -1;
    return 1;
}

rt_status rt__obj_normal(reader *r)
{
    lexer *x = &r->lex;
    if (rt__obj_rest(x, 4) != 0)
        return rt__obj_out_of_memory(r);
    if (x->total != 4) {
        char buffer[RT_TOKEN_SHOWN_SIZE];
        if (x->total > 4)
            return rt__token_refuse(r->error, RT_ERR_SYNTAX, r->name,
                                    &x->tokens[4], "at most 3 values for "
                                    "`%s`",
                                    rt__token_shown(&x->tokens[0], buffer));
        return rt__error_set(r->error, RT_ERR_SYNTAX, r->name, x->last.line,
                             x->last.column + (int)x->last.length,
                             "expected 3 values for `%s`, found %ld",
                             rt__token_shown(&x->tokens[0], buffer),
                             x->total - 1);
    }
    double c[3];
    int finite = 1;
    for (int i = 1; i < 4; i++) {
        rt_status status = rt__obj_number(x, &x->tokens[i], &c[i - 1]);
        if (status == RT_ERR_RANGE) {
            finite = 0;         /* nan, inf, 1e400: a warning below */
            c[i - 1] = 0.0;
        } else if (status != RT_OK) {
            return rt__token_refuse(r->error, status, r->name, &x->tokens[i],
                                    "%s", rt__number_expected(status));
        }
    }
    rt_vec3 n = finite ? unit(v3(c[0], c[1], c[2])) : v3(0, 0, 0);
    if (v3_max_abs(n) == 0.0)
        rt__obj_count(&r->bad_normal, r->name, x->tokens[0].line,
                      x->tokens[0].column,
                      "this vertex normal %s: the corners that use it have "
                      "none, and their faces are flat",
                      finite ? "has zero length" : "is not finite");
    if (r->normal_count == INT_MAX / 2)
        return rt__token_refuse(r->error, RT_ERR_LIMIT, r->name,
                                &x->tokens[0], "at most %d normals",
                                INT_MAX / 2);
    if (r->slot == NULL && !open_slots(r))
        return rt__obj_out_of_memory(r);
    if (rt__obj_grow((void **)&r->normal_values, &r->normal_capacity,
                     r->normal_count, sizeof *r->normal_values, 64) <= 0)
        return rt__obj_out_of_memory(r);
    r->normal_values[r->normal_count++] = n;
    return RT_OK;
}

/* Room for vertex r->vertex_count in the arrays that follow it. */
int rt__obj_vertex_added(reader *r)
{
    int i = r->vertex_count - 1;            /* the vertex just added */
    if (r->slot != NULL) {
        if (rt__obj_grow((void **)&r->slot, &r->slot_capacity, i,
                         sizeof *r->slot, 64) <= 0)
            return 0;
        r->slot[i] = NOT_USED;
    }
    return 1;
}

static unsigned pair_hash(int v, int vn)
{
    unsigned h = (unsigned)v * 2654435761u;
    h ^= (unsigned)(vn + 1) * 2246822519u;
    return h ^ (h >> 15);
}

static struct obj_pair *pair_find(reader *r, int v, int vn)
{
    unsigned mask = (unsigned)r->pair_capacity - 1;
    for (unsigned i = pair_hash(v, vn) & mask;; i = (i + 1) & mask) {
        struct obj_pair *p = &r->pairs[i];
        if (p->position < 0 || (p->v == v && p->vn == vn))
            return p;
    }
}

/* Room for one more pair: the table at most half full.  0: no memory. */
static int pair_room(reader *r)
{
    if (2 * (r->pair_count + 1) <= r->pair_capacity)
        return 1;
    if (r->pair_capacity > INT_MAX / 4)
        return 0;
    int bigger = r->pair_capacity ? 2 * r->pair_capacity : 64;
    struct obj_pair *old = r->pairs;
    int old_capacity = r->pair_capacity;
    r->pairs = malloc((size_t)bigger * sizeof *r->pairs);
    if (r->pairs == NULL) {
        r->pairs = old;
        return 0;
    }
    r->pair_capacity = bigger;
    for (int i = 0; i < bigger; i++)
        r->pairs[i].position = -1;
    for (int i = 0; i < old_capacity; i++)
        if (old[i].position >= 0)
            *pair_find(r, old[i].v, old[i].vn) = old[i];
    free(old);
    return 1;
}

/* Where the `v` numbered v (0-based) is used with `vn` (or -1): its own
 * position, or a copy.  -1: out of memory; -2: past INT_MAX / 2. */
static int position(reader *r, int v, int vn)
{
    int p = r->position_of != NULL ? r->position_of[v] : v;
    if (r->slot[p] == NOT_USED)
        r->slot[p] = vn;
    if (r->slot[p] == vn)
        return p;
    if (!pair_room(r))
        return -1;
    struct obj_pair *pair = pair_find(r, v, vn);
    if (pair->position >= 0)
        return pair->position;
    if (r->position_of == NULL) {
        /* the first copy: from now on a `v`'s number and its place part */
        int capacity = r->vertex_capacity;
        r->position_of = malloc((size_t)capacity * sizeof *r->position_of);
        if (r->position_of == NULL)
            return -1;
        r->position_capacity = capacity;
        for (int i = 0; i < r->obj_vertex_count; i++)
            r->position_of[i] = i;
    }
    int room = rt__obj_grow((void **)&r->vertices, &r->vertex_capacity,
                            r->vertex_count, sizeof *r->vertices, 64);
    if (room <= 0)
        return room < 0 ? -2 : -1;
    int copy = r->vertex_count++;
    r->vertices[copy] = r->vertices[p];
    if (!rt__obj_vertex_added(r))
        return -1;
    r->slot[copy] = vn;
    *pair = (struct obj_pair){v, vn, copy};
    r->pair_count++;
    return copy;
}

rt_status rt__obj_corners(reader *r, int *count)
{
    if (r->slot == NULL)
        return RT_OK;                   /* no `vn`: numbers are places */
    /* A corner that repeats the `v` before it is dropped here, as
     * rt__mesh_face drops it without normals, whatever their normals. */
    int n = 0;
    for (int i = 0; i < *count; i++)
        if (n == 0 || r->polygon[i] != r->polygon[n - 1]) {
            r->polygon[n] = r->polygon[i];
            r->corner_normals[n++] = r->corner_normals[i];
        }
    while (n > 1 && r->polygon[n - 1] == r->polygon[0])
        n--;
    *count = n;
    /* A face is smooth only when every corner has a usable normal. */
    int flat = 0;
    for (int i = 0; i < n && !flat; i++)
        flat = r->corner_normals[i] < 0 ||
               v3_max_abs(r->normal_values[r->corner_normals[i]]) == 0.0;
    for (int i = 0; i < n; i++) {
        int p = position(r, r->polygon[i], flat ? -1 : r->corner_normals[i]);
        if (p == -2)
            return rt__error_set(r->error, RT_ERR_LIMIT, r->name,
                                 r->lex.last.line, 1,
                                 "expected at most %d vertices with their "
                                 "normals", INT_MAX / 2);
        if (p < 0)
            return rt__obj_out_of_memory(r);
        r->polygon[i] = p;
    }
    return RT_OK;
}

rt_vec3 *rt__obj_normals(reader *r, int *failed)
{
    *failed = 0;
    int any = 0;
    for (int i = 0; r->slot != NULL && i < r->vertex_count && !any; i++)
        any = r->slot[i] >= 0;
    if (!any)
        return NULL;
    rt_vec3 *normals = malloc((size_t)r->vertex_count * sizeof *normals);
    if (normals == NULL) {
        *failed = 1;
        return NULL;
    }
    for (int i = 0; i < r->vertex_count; i++)
        normals[i] = r->slot[i] >= 0 ? r->normal_values[r->slot[i]]
                                     : v3(0, 0, 0);
    return normals;
}

void rt__obj_free_normals(reader *r)
{
    free(r->normal_values);
    free(r->slot);
    free(r->position_of);
    free(r->pairs);
    free(r->corner_normals);
    r->normal_values = NULL;
    r->slot = NULL;
    r->position_of = NULL;
    r->pairs = NULL;
    r->corner_normals = NULL;
}
