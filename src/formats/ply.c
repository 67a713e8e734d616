/*
 * ply.c - Stanford polygon files (.ply), read from memory into an
 * rt_scene_desc and handed to the scene builder: the body of the elements
 * the header (ply_header.c) declared, ASCII or binary in either byte
 * order, the vertices' positions and colours, the faces cut into facets
 * as OBJ's are (mesh.h), the automatic camera and light of a mesh.  What
 * is read, what is ignored and why: docs/formats.md, section PLY.
 *
 * Counts in the header are claims: before an array is sized from one, the
 * bytes left must hold that many items at their smallest (binary: their
 * fixed bytes; ASCII: RT_PLY_ASCII_VALUE_BYTES a value), so memory stays
 * proportional to the file.  A binary body is read value by value with
 * memcpy and a byte swap, into arrays sized once; an ASCII body goes
 * through the lexer, one item a line, its numbers by the one rule
 * (rt__lex_number).  The first broken rule stops the read: "name:line:
 * column: expected ..." in ASCII, "name: byte N: expected ..." in binary.
 */
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/vecmath.h"
#include "formats/mesh.h"
#include "formats/ply.h"

static rt_status out_of_memory(reader *r)
{
    return rt__error_set(r->error, RT_ERR_NOMEM, r->name, 0, 0,
                         "out of memory");
}

static rt_status poll(reader *r)
{
    if (++r->items % RT_LOAD_POLL == 0 && rt__load_cancelled(r->options))
        return rt__load_cancel(r->error, r->name);
    return RT_OK;
}

/* How many items of element e the bytes left can hold at most. */
static long long room_for(const reader *r, const ply_element *e)
{
    /* ASCII: the last value needs no separator after it */
    size_t left = rt__ply_bytes_left(r) + (r->h.format == PLY_ASCII);
    long long least;
    if (r->h.format == PLY_ASCII) {
        least = (long long)(e->properties + (e->kind == KIND_FACE ? 3 : 0)) *
                RT_PLY_ASCII_VALUE_BYTES;
    } else {
        least = e->record;
        for (int i = e->first; i < e->first + e->properties; i++)
            if (r->h.property[i].role == ROLE_CORNERS)
                least += 3 * rt__ply_type_size(r->h.property[i].type);
    }
    return least > 0 ? (long long)(left / (size_t)least) : LLONG_MAX;
}

static rt_status claim(reader *r, const ply_element *e)
{
    if (e->count <= room_for(r, e))
        return RT_OK;
    char shown[RT_TOKEN_SHOWN_SIZE];
    return rt__error_set(
        r->error, RT_ERR_SYNTAX, r->name, e->name.line, e->name.column,
        "expected a count the file can hold, found %lld item%s of `%s` in %zu "
        "bytes left of the file",
        e->count, e->count == 1 ? "" : "s", rt__token_shown(&e->name, shown),
        rt__ply_bytes_left(r));
}

/* A colour value as a byte: integers are 0..255, floating values 0..1. */
static unsigned char colour_byte(reader *r, ply_type type, double v)
{
    double byte = type == PLY_FLOAT32 || type == PLY_FLOAT64
                      ? floor(v * 255.0 + 0.5)
                      : v;
    if (!(byte >= 0 && byte <= 255)) {
        if (r->clamped.count++ == 0)
            r->clamped.line = r->line;
        byte = byte > 255 ? 255 : 0;
    }
    return (unsigned char)byte;
}

/* Skips a list (its count read as `n`) of `type` items. */
static rt_status skip_list(reader *r, const ply_property *prop, const place *w,
                           double n)
{
    char shown[RT_ERROR_MESSAGE_SIZE];
    if (n < 0)
        return rt__ply_refuse_value(r, RT_ERR_SYNTAX, n,
                                    "a count of 0 or more for %s",
                                    rt__ply_what(w, shown, sizeof shown));
    if (r->h.format != PLY_ASCII) {
        if (n > (double)(r->end - r->at) / rt__ply_type_size(prop->type))
            return rt__ply_refuse_value(
                r, RT_ERR_SYNTAX, n,
                "a count of items the rest of the file holds for %s",
                rt__ply_what(w, shown, sizeof shown));
        r->at += (size_t)n * (size_t)rt__ply_type_size(prop->type);
        return RT_OK;
    }
    place item = *w;
    item.in_list = 1;
    for (double i = 0; i < n; i++) {
        double ignored;
        rt_status status = rt__ply_value(r, prop->type, &item, 0, &ignored);
        if (status != RT_OK)
            return status;
    }
    return RT_OK;
}

static rt_status vertex(reader *r, const ply_element *e, long long item)
{
    rt_vec3 *p = &r->vertices[item];
    for (int i = 0; i < e->properties; i++) {
        const ply_property *prop = &r->h.property[e->first + i];
        place w = {e, prop, item};
        double v;
        rt_status status = rt__ply_value(
            r, prop->count_type != PLY_NONE ? prop->count_type : prop->type,
            &w, i == 0, &v);
        if (status != RT_OK)
            return status;
        switch (prop->role) {
        case ROLE_X:
        case ROLE_Y:
        case ROLE_Z:
            /* the triangulator computes with the vertices before the
             * build */
            if (!(fabs(v) <= RT_MAX_COORDINATE)) {
                char shown[RT_ERROR_MESSAGE_SIZE];
                return rt__ply_refuse_value(
                    r, RT_ERR_RANGE, v, "%s for %s", RT_RULE_COORDINATE,
                    rt__ply_what(&w, shown, sizeof shown));
            }
            (&p->x)[prop->role - ROLE_X] = v;
            break;
        case ROLE_NX:
        case ROLE_NY:
        case ROLE_NZ:
            if (r->normals != NULL)
                (&r->normals[item].x)[prop->role - ROLE_NX] = v;
            break;
        case ROLE_RED:
        case ROLE_GREEN:
        case ROLE_BLUE:
            r->colours[3 * item + (prop->role - ROLE_RED)] =
                colour_byte(r, prop->type, v);
            break;
        default:
            if (prop->count_type != PLY_NONE) {
                status = skip_list(r, prop, &w, v);
                if (status != RT_OK)
                    return status;
            }
            break;
        }
    }
    return RT_OK;
}

/*
 * Binary vertices without lists, the common case at speed: each a record
 * of e->record bytes (the claim, checked, holds them all), the values of
 * the roles at fixed offsets in it.  An item with a coordinate out of range
 * is read again by vertex(), which names it.
 */
static rt_status binary_vertices(reader *r, const ply_element *e)
{
    int at[ROLE_CORNERS + 1] = {0}, size = 0;
    ply_type type[ROLE_CORNERS + 1] = {PLY_NONE};
    for (int i = 0; i < e->properties; i++) {
        const ply_property *prop = &r->h.property[e->first + i];
        at[prop->role] = size;
        type[prop->role] = prop->type;
        size += rt__ply_type_size(prop->type);
    }
    int colours = r->colours != NULL, normals = r->normals != NULL;
    for (long long i = 0; i < e->count; i++, r->at += size) {
        rt_status status = poll(r);
        if (status != RT_OK)
            return status;
        const unsigned char *p = r->at;
        double x = ply_load(p + at[ROLE_X], type[ROLE_X], r->swap);
        double y = ply_load(p + at[ROLE_Y], type[ROLE_Y], r->swap);
        double z = ply_load(p + at[ROLE_Z], type[ROLE_Z], r->swap);
        if (!(fabs(x) <= RT_MAX_COORDINATE) ||
            !(fabs(y) <= RT_MAX_COORDINATE) || !(fabs(z) <= RT_MAX_COORDINATE))
            return vertex(r, e, i);
        r->vertices[i] = (rt_vec3){x, y, z};
        for (int c = 0; c < 3 && colours; c++)
            r->colours[3 * i + c] = colour_byte(
                r, type[ROLE_RED + c],
                ply_load(p + at[ROLE_RED + c], type[ROLE_RED + c], r->swap));
        for (int c = 0; c < 3 && normals; c++)
            (&r->normals[i].x)[c] =
                ply_load(p + at[ROLE_NX + c], type[ROLE_NX + c], r->swap);
    }
    return RT_OK;
}

/* Adds the facet (a, b, c) of the face being read. */
static rt_status add_facet(void *user, int a, int b, int c)
{
    reader *r = user;
    if (r->facet_count == r->facet_capacity) {
        if (r->facet_capacity > INT_MAX / 4)
            return rt__error_set(r->error, RT_ERR_LIMIT, r->name, 0, 0,
                                 "expected at most %d facets", INT_MAX / 2);
        int bigger = r->facet_capacity ? 2 * r->facet_capacity : 64;
        rt_facet_desc *grown =
            realloc(r->facets, (size_t)bigger * sizeof *grown);
        if (grown == NULL)
            return out_of_memory(r);
        r->facets = grown;
        if (r->h.format == PLY_ASCII) {
            int *lines =
                realloc(r->facet_lines, (size_t)bigger * sizeof *lines);
            if (lines == NULL)
                return out_of_memory(r);
            r->facet_lines = lines;
        }
        r->facet_capacity = bigger;
    }
    rt_facet_desc *f = &r->facets[r->facet_count];
    *f = r->look;
    if (r->h.face_colours) {
        f->color = r->face_colour;
    } else if (r->colours != NULL) {
        /* the mean of the corners' colours, rounded */
        const unsigned char *ca = &r->colours[3 * a], *cb = &r->colours[3 * b];
        const unsigned char *cc = &r->colours[3 * c];
        f->color.r = (unsigned char)((ca[0] + cb[0] + cc[0] + 1) / 3);
        f->color.g = (unsigned char)((ca[1] + cb[1] + cc[1] + 1) / 3);
        f->color.b = (unsigned char)((ca[2] + cb[2] + cc[2] + 1) / 3);
    }
    f->vertex[0] = a;
    f->vertex[1] = b;
    f->vertex[2] = c;
    if (r->facet_lines != NULL)
        r->facet_lines[r->facet_count] = r->line;
    r->facet_count++;
    return RT_OK;
}

/* The corners of a face: a list of `n` indices of `type`. */
static rt_status corners(reader *r, const place *w, double n, int *count)
{
    ply_type type = w->property->type;
    double most = (double)rt__ply_bytes_left(r) /
                  (r->h.format == PLY_ASCII ? RT_PLY_ASCII_VALUE_BYTES
                                            : rt__ply_type_size(type));
    if (n < 3)
        return rt__ply_refuse_value(
            r, RT_ERR_SYNTAX, n, "at least 3 vertices for face %lld", w->item);
    /* binary: the bytes must hold every index (they are then read
     * unchecked); ASCII: the last value may end the file */
    if (n > (r->h.format == PLY_ASCII ? most + 1 : most) || n > INT_MAX / 2)
        return rt__ply_refuse_value(r, RT_ERR_SYNTAX, n,
                                    "the count of the vertices of face "
                                    "%lld, which the rest of the file can "
                                    "hold",
                                    w->item);
    if ((int)n > r->polygon_capacity) {
        int *grown = realloc(r->polygon, (size_t)n * sizeof *grown);
        if (grown == NULL)
            return out_of_memory(r);
        r->polygon = grown;
        r->polygon_capacity = (int)n;
    }
    place item = *w;
    item.in_list = 1;
    int size = rt__ply_type_size(type);
    for (int i = 0; i < (int)n; i++) {
        double index;
        if (r->h.format != PLY_ASCII) {
            /* the bytes are there: n is within what is left */
            index = ply_load(r->at, type, r->swap);
            r->last_at = rt__ply_offset(r);
            r->at += size;
        } else {
            rt_status status = rt__ply_value(r, type, &item, 0, &index);
            if (status != RT_OK)
                return status;
        }
        if (index < 0 || index >= r->vertex_count)
            return rt__ply_refuse_value(r, RT_ERR_RANGE, index,
                                        "a vertex index in 0..%d for face "
                                        "%lld",
                                        r->vertex_count - 1, w->item);
        r->polygon[i] = (int)index;
    }
    *count = (int)n;
    return RT_OK;
}

static rt_status face(reader *r, const ply_element *e, long long item)
{
    int n = 0;
    unsigned char rgb[3] = {RT_MESH_GREY, RT_MESH_GREY, RT_MESH_GREY};
    for (int i = 0; i < e->properties; i++) {
        const ply_property *prop = &r->h.property[e->first + i];
        place w = {e, prop, item};
        double v;
        int list = prop->count_type != PLY_NONE;
        rt_status status = rt__ply_value(
            r, list ? prop->count_type : prop->type, &w, i == 0, &v);
        if (status != RT_OK)
            return status;
        if (prop->role == ROLE_CORNERS)
            status = corners(r, &w, v, &n);
        else if (list)
            status = skip_list(r, prop, &w, v);
        else if (prop->role >= ROLE_RED && prop->role <= ROLE_BLUE)
            rgb[prop->role - ROLE_RED] = colour_byte(r, prop->type, v);
        if (status != RT_OK)
            return status;
    }
    if (r->h.format == PLY_ASCII) {
        rt_status status = rt__ply_line_end(r, e, item);
        if (status != RT_OK)
            return status;
    }
    r->face_colour = (rt_rgb8){rgb[0], rgb[1], rgb[2]};
    rt_face_outcome outcome;
    rt_status status = rt__mesh_face(&r->triangulator, r->vertices, r->polygon,
                                     n, add_facet, r, &outcome);
    if (status == RT_ERR_NOMEM)
        return out_of_memory(r);
    if (status == RT_ERR_CANCELLED)
        return rt__load_cancel(r->error, r->name);
    if (status == RT_OK && outcome != RT_FACE_DRAWN &&
        r->outcomes[outcome].count++ == 0) {
        r->outcomes[outcome].line = r->line;
        r->outcomes[outcome].face = item;
    }
    return status;
}

/* Any element, item by item. */
static rt_status element(reader *r, const ply_element *e)
{
    rt_status status = claim(r, e);
    if (status != RT_OK)
        return status;
    if (e->kind == KIND_VERTEX) {
        r->vertex_count = (int)e->count;
        size_t n = e->count > 0 ? (size_t)e->count : 1;
        r->vertices = malloc(n * sizeof *r->vertices);
        if (r->h.vertex_colours)
            r->colours = malloc(3 * n);
        if (r->h.has_normals)
            r->normals = malloc(n * sizeof *r->normals);
        if (r->vertices == NULL || (r->h.vertex_colours && !r->colours) ||
            (r->h.has_normals && !r->normals))
            return out_of_memory(r);
    } else if (e->kind == KIND_FACE && e->count > 0) {
        r->facet_capacity = (int)e->count;
        r->facets = malloc((size_t)e->count * sizeof *r->facets);
        if (r->h.format == PLY_ASCII)
            r->facet_lines = malloc((size_t)e->count * sizeof *r->facet_lines);
        if (r->facets == NULL ||
            (r->h.format == PLY_ASCII && r->facet_lines == NULL))
            return out_of_memory(r);
    } else if (e->kind == KIND_OTHER && e->lists == 0 &&
               r->h.format != PLY_ASCII) {
        r->at += (size_t)e->count * (size_t)e->record; /* claimed above */
        return RT_OK;
    }
    if (e->properties == 0)
        return RT_OK; /* an item of nothing takes no byte */
    if (e->kind == KIND_VERTEX && e->lists == 0 && r->h.format != PLY_ASCII)
        return binary_vertices(r, e);
    for (long long item = 0; item < e->count; item++) {
        status = poll(r);
        if (status == RT_OK && e->kind == KIND_VERTEX)
            status = vertex(r, e, item);
        else if (status == RT_OK && e->kind == KIND_FACE)
            status = face(r, e, item);
        else if (status == RT_OK)
            for (int i = 0; i < e->properties && status == RT_OK; i++) {
                const ply_property *prop = &r->h.property[e->first + i];
                place w = {e, prop, item};
                double v;
                int list = prop->count_type != PLY_NONE;
                status = rt__ply_value(r, list ? prop->count_type : prop->type,
                                       &w, i == 0, &v);
                if (status == RT_OK && list)
                    status = skip_list(r, prop, &w, v);
            }
        if (status == RT_OK && e->kind != KIND_FACE &&
            r->h.format == PLY_ASCII)
            status = rt__ply_line_end(r, e, item);
        if (status != RT_OK)
            return status;
    }
    return RT_OK;
}

/* ---------------------------------------------------------------- reading */

/* The description's arrays (and what else the reader holds per vertex or
 * facet), freed once the scene's records are made (rt_reading.release). */
static void release_arrays(void *user)
{
    reader *r = user;
    free(r->vertices);
    free(r->colours);
    free(r->normals);
    free(r->facets);
    free(r->facet_lines);
    r->vertices = NULL;
    r->colours = NULL;
    r->normals = NULL;
    r->facets = NULL;
    r->facet_lines = NULL;
}

/* Opens the body: the lexer over the whole text (ASCII), its cursor past
 * the header's lines; the bytes after the header (binary). */
static rt_status open_body(reader *r)
{
    if (r->h.format != PLY_ASCII) {
        static const uint16_t one = 1;
        int little = *(const unsigned char *)&one == 1;
        r->swap = (r->h.format == PLY_BINARY_LE) != little;
        r->at = (const unsigned char *)r->text + r->h.length;
        r->end = (const unsigned char *)r->text + r->length;
        return RT_OK;
    }
    rt_status status = rt__lex_open(&r->lex, r->text, r->length, r->name,
                                    RT_LEX_LINES, r->error);
    if (status != RT_OK)
        return status;
    rt_token t;
    while (rt__lex_statement(&r->lex, &t))
        if (t.line > r->h.end_line) {
            r->pending = t;
            r->has_pending = 1;
            break;
        }
    return RT_OK;
}

static void say(reader *r)
{
    char words[RT_ERROR_MESSAGE_SIZE];
    for (int i = RT_FACE_DRAWN + 1; i <= RT_FACE_CROSSING; i++) {
        const counted *c = &r->outcomes[i];
        if (c->count == 0)
            continue;
        const char *text =
            rt__mesh_face_remark((rt_face_outcome)i, words, sizeof words);
        char more[64] = "";
        if (c->count > 1)
            snprintf(more, sizeof more, " (and %d more like it)",
                     c->count - 1);
        rt__notes_add(&r->notes, r->name, c->line, c->line > 0 ? 1 : 0,
                      "face %lld: %s%s", c->face, text, more);
    }
    if (r->clamped.count > 0)
        rt__notes_add(&r->notes, r->name, r->clamped.line, 0,
                      "%d colour values are outside 0..255 (integers) or "
                      "0..1 (floating) and are clamped",
                      r->clamped.count);
    if (r->facet_count == 0)
        rt__notes_add(&r->notes, r->name, 0, 0,
                      "the file has no face to draw: the picture is the "
                      "background");
}

/* A vertex normal that is not finite (a binary NaN or infinity) is none
 * (zero, as a zero normal is), with one warning for them all. */
static void finite_normals(reader *r)
{
    int bad = 0, first = -1;
    for (int i = 0; r->normals != NULL && i < r->vertex_count; i++) {
        rt_vec3 *n = &r->normals[i];
        if (isfinite(n->x) && isfinite(n->y) && isfinite(n->z))
            continue;
        if (bad++ == 0)
            first = i;
        *n = (rt_vec3){0.0, 0.0, 0.0};
    }
    if (bad > 0)
        rt__notes_add(&r->notes, r->name, 0, 0,
                      "vertex %d: its normal is not finite, so it has none "
                      "(its facets are flat)%s", first,
                      bad > 1 ? " (and more like it)" : "");
}

static rt_status read_ply(reader *r, rt_scene **scene)
{
    rt_status status = rt__ply_header_read(r->text, r->length, r->name, &r->h,
                                           &r->notes, r->error);
    if (status == RT_OK)
        status = open_body(r);
    for (int i = 0; status == RT_OK && i < r->h.element_count; i++)
        status = element(r, &r->h.element[i]);
    if (status != RT_OK)
        return status;
    if (r->h.format == PLY_ASCII && r->has_pending) {
        rt__notes_add(&r->notes, r->name, r->pending.line, r->pending.column,
                      "the lines after the last element are ignored");
    } else if (r->h.format == PLY_ASCII) {
        rt_token t;
        if (rt__lex_statement(&r->lex, &t))
            rt__notes_add(&r->notes, r->name, t.line, t.column,
                          "the lines after the last element are ignored");
    } else if (r->at < r->end) {
        rt__notes_add(&r->notes, r->name, 0, 0,
                      "byte %zu: the %zu bytes "
                      "after the last element are ignored",
                      rt__ply_offset(r), (size_t)(r->end - r->at));
    }
    say(r);
    finite_normals(r);
    if (r->notes.failed)
        return out_of_memory(r);
    rt_scene_desc d;
    memset(&d, 0, sizeof d);
    rt_light light;
    rt__mesh_up(r->text, r->length, 1, r->options, &d);
    status =
        rt__mesh_auto_view(r->name, r->vertices, r->vertex_count, r->facets,
                           r->facet_count, r->options, &d, &light, r->error);
    if (status != RT_OK)
        return status;
    d.vertices = r->vertices;
    d.vertex_count = r->vertex_count;
    d.facets = r->facets;
    d.facet_count = r->facet_count;
    d.normals = r->normals;
    rt_reading reading = {r->name,    r->facet_lines, &r->notes,
                          r->options, NULL,           NULL,
                          release_arrays, r};
    return rt__reader_finish(&d, &reading, scene, r->error);
}

rt_status rt__ply_parse(const char *text, size_t length, const char *name,
                        const rt_load_options *options, rt_scene **scene,
                        rt_error *error)
{
    const char *shown_name = name ? name : "<memory>";
    if (length > RT_MAX_SCENE_BYTES)
        return rt__error_set(error, RT_ERR_LIMIT, shown_name, 0, 0,
                             "expected at most %zu bytes, found %zu",
                             RT_MAX_SCENE_BYTES, length);
    reader r;
    memset(&r, 0, sizeof r);
    r.name = shown_name;
    r.error = error;
    r.options = options;
    r.text = text;
    r.length = length;
    rt__mesh_default_look(&r.look);
    double budget = RT_TRI_WORK_FLOOR + (double)RT_TRI_WORK_PER_BYTE * length;
    rt__tri_init(&r.triangulator, budget, options->cancel);
    rt_status status = read_ply(&r, scene);
    if (r.h.format == PLY_ASCII && r.lex.start != NULL)
        rt__lex_close(&r.lex);
    rt__tri_free(&r.triangulator);
    rt__ply_header_free(&r.h);
    release_arrays(&r);
    free(r.polygon);
    rt__notes_free(&r.notes);
    return status;
}
