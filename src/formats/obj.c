/*
 * obj.c - Wavefront OBJ meshes (.obj), read from memory into an
 * rt_scene_desc and handed to the scene builder: the statements, the
 * geometry and the automatic camera and light.  The material libraries are
 * mtl.c's, the lexer and the warnings obj_text.c's (obj.h), the polygons
 * the triangulator's (triangulate.h).  What is read, what is ignored and
 * why: docs/formats.md, section OBJ.
 *
 * The reader takes one statement at a time, knows the line and column of
 * every token, and stops at the first broken rule of the geometry with a
 * message "name:line:column: expected ..., found `token`".  What exporters
 * write beyond geometry (unknown statements, lines and points, a missing
 * or broken .mtl, an unknown material) gives warnings, not failures: a
 * mesh should render even when its decorations do not.  Every warning that
 * could repeat per element is counted and said once.  Arrays grow by
 * doubling with their sizes checked; every element costs at least one
 * byte of input, so no count can exceed the input's length.
 */
#include <ctype.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/exact.h"
#include "formats/mesh.h"
#include "formats/obj.h"
#include "base/vecmath.h"

static rt_status refuse(reader *r, rt_status status, const token *t,
                        int column_offset, const char *fmt, ...)
    RT_PRINTF_LIKE(5, 6);

/* "name:line:column: expected ..., found `token`", the column
 * `column_offset` bytes into the token. */
static rt_status refuse(reader *r, rt_status status, const token *t,
                        int column_offset, const char *fmt, ...)
{
    char expected[RT_ERROR_MESSAGE_SIZE];
    va_list args;
    va_start(args, fmt);
    vsnprintf(expected, sizeof expected, fmt, args);
    va_end(args);
    token at = *t;
    at.column += column_offset;
    return rt__token_refuse(r->error, status, r->name, &at, "%s", expected);
}

/* The position just after token t, for "found the end of ...". */
static void after(const token *t, int *line, int *column)
{
    *line = t->line;
    *column = t->column + (int)t->length;
}

/* The i-th kept token of the statement as a finite number. */
static rt_status number_at(reader *r, int i, double *value)
{
    const token *t = &r->lex.tokens[i];
    rt_status status = rt__obj_number(&r->lex, t, value);
    if (status != RT_OK)
        return refuse(r, status, t, 0, "%s", rt__number_expected(status));
    return RT_OK;
}

/* ---------------------------------------------------------------- geometry */

static rt_status vertex(reader *r)
{
    lexer *x = &r->lex;
    if (rt__obj_rest(x, 8) != 0)
        return rt__obj_out_of_memory(r);
    if (x->total < 4 || x->total > 8) {
        if (x->total > 8)
            return refuse(r, RT_ERR_SYNTAX, &x->tokens[8], 0,
                          "the end of the vertex `v x y z [w]`");
        int line, column;
        after(&x->last, &line, &column);
        return rt__error_set(r->error, RT_ERR_SYNTAX, r->name, line, column,
                             "expected 3 coordinates for the vertex `v x y z "
                             "[w]`, found %ld", x->total - 1);
    }
    double c[7];
    for (int i = 1; i < x->count; i++) {
        rt_status status = number_at(r, i, &c[i - 1]);
        if (status != RT_OK)
            return status;
        /* the triangulator computes with the vertices before the build */
        if (i <= 3 && fabs(c[i - 1]) > RT_MAX_COORDINATE)
            return refuse(r, RT_ERR_RANGE, &x->tokens[i], 0, "%s",
                          RT_RULE_COORDINATE);
    }
    if (x->count >= 7)
        rt__obj_warn_once(r, r->name, &x->tokens[0],
                          "with vertex colours are read as positions only: "
                          "the colours are ignored");
    int room = rt__obj_grow((void **)&r->vertices, &r->vertex_capacity,
                            r->vertex_count, sizeof *r->vertices, 64);
    if (room < 0)
        return refuse(r, RT_ERR_LIMIT, &x->tokens[0], 0,
                      "at most %d vertices", INT_MAX / 2);
    if (room == 0)
        return rt__obj_out_of_memory(r);
    if (r->position_of != NULL &&
        rt__obj_grow((void **)&r->position_of, &r->position_capacity,
                     r->obj_vertex_count, sizeof *r->position_of, 64) <= 0)
        return rt__obj_out_of_memory(r);
    if (r->position_of != NULL)
        r->position_of[r->obj_vertex_count] = r->vertex_count;
    r->vertices[r->vertex_count++] = v3(c[0], c[1], c[2]);
    r->obj_vertex_count++;
    if (!rt__obj_vertex_added(r))
        return rt__obj_out_of_memory(r);
    return RT_OK;
}

/* `vt`: numbers, counted for the faces' references, not used. */
static rt_status attribute(reader *r, int *count, int least, int most)
{
    lexer *x = &r->lex;
    if (rt__obj_rest(x, most + 1) != 0)
        return rt__obj_out_of_memory(r);
    if (x->total - 1 < least || x->total - 1 > most) {
        char buffer[RT_TOKEN_SHOWN_SIZE];
        int line, column;
        after(&x->last, &line, &column);
        if (x->total - 1 > most)
            return refuse(r, RT_ERR_SYNTAX, &x->tokens[most + 1], 0,
                          "at most %d values for `%s`", most,
                          rt__token_shown(&x->tokens[0], buffer));
        return rt__error_set(r->error, RT_ERR_SYNTAX, r->name, line, column,
                             "expected %d values for `%s`, found %ld", least,
                             rt__token_shown(&x->tokens[0], buffer),
                             x->total - 1);
    }
    for (int i = 1; i < x->count; i++) {
        double ignored;
        rt_status status = number_at(r, i, &ignored);
        if (status != RT_OK)
            return status;
    }
    if (*count == INT_MAX)
        return refuse(r, RT_ERR_LIMIT, &x->tokens[0], 0, "fewer statements");
    (*count)++;
    return RT_OK;
}

/*
 * Reads one index of a face reference at t->text[*at...] into a 0-based
 * index among `count` ("vertex", "texture coordinate", "normal") in *out
 * (may be NULL).  For texture coordinates and normals (`lenient`) an index
 * out of range is a warning, not a refusal, and *out is -1; 0 is refused
 * always.
 */
static rt_status index_at(reader *r, const token *t, size_t *at, int count,
                          const char *what, int lenient, int *out)
{
    size_t i = *at;
    int negative = 0;
    if (i < t->length && (t->text[i] == '-' || t->text[i] == '+'))
        negative = t->text[i++] == '-';
    size_t digits_start = i;
    long long value = 0;
    while (i < t->length && isdigit((unsigned char)t->text[i])) {
        if (value < 100000000000LL)
            value = value * 10 + (t->text[i] - '0');
        i++;
    }
    int column = (int)*at;
    if (i == digits_start || (i < t->length && t->text[i] != '/'))
        return refuse(r, RT_ERR_SYNTAX, t, i == digits_start ? column : (int)i,
                      "a face vertex `v`, `v/vt`, `v//vn` or `v/vt/vn` with "
                      "a whole %s index", what);
    long long resolved = negative ? count - value : value - 1;
    if (value == 0 || resolved < 0 || resolved >= count) {
        char buffer[RT_TOKEN_SHOWN_SIZE];
        token part = {t->text + *at, i - *at, t->line, t->column + column};
        if (lenient && value != 0) {
            /* Exporters that leave texture coordinates or normals out but
             * keep the references still render. */
            const char *key = what[0] == 't' ? "@vt" : "@vn";
            if (rt__obj_first_time(r, key, strlen(key)) > 0)
                rt__obj_warn(r, r->name, part.line, part.column,
                             "`%s` refers to no %s read so far; it is "
                             "ignored%s (said once)",
                             rt__token_shown(&part, buffer), what,
                             what[0] == 't' ? ""
                                            : " and the face is flat");
            *at = i;
            if (out != NULL)
                *out = -1;
            return RT_OK;
        }
        if (count == 0)
            return rt__error_set(r->error, RT_ERR_RANGE, r->name, part.line,
                                 part.column,
                                 "expected a %s index, found `%s` before any "
                                 "%s is defined", what,
                                 rt__token_shown(&part, buffer), what);
        return rt__error_set(r->error, RT_ERR_RANGE, r->name, part.line,
                             part.column,
                             "expected a %s index in 1..%d or -%d..-1 (%d "
                             "defined so far; 0 names none), found `%s`",
                             what, count, count, count,
                             rt__token_shown(&part, buffer));
    }
    *at = i;
    if (out != NULL)
        *out = (int)resolved;
    return RT_OK;
}

/* One vertex of a face: v, v/vt, v//vn or v/vt/vn; its `v` (0-based)
 * into *out, its `vn` or -1 into *normal. */
static rt_status face_vertex(reader *r, const token *t, int *out,
                             int *normal)
{
    size_t at = 0;
    *normal = -1;
    rt_status status = index_at(r, t, &at, r->obj_vertex_count, "vertex", 0,
                                out);
    if (status != RT_OK || at == t->length)
        return status;
    at++;                                       /* the first '/' */
    if (at < t->length && t->text[at] != '/') {
        status = index_at(r, t, &at, r->texture_count, "texture coordinate",
                          1, NULL);
        if (status != RT_OK || at == t->length)
            return status;
    }
    if (at == t->length || t->text[at] != '/' || ++at == t->length)
        return refuse(r, RT_ERR_SYNTAX, t, 0,
                      "a face vertex `v`, `v/vt`, `v//vn` or `v/vt/vn`");
    status = index_at(r, t, &at, r->normal_count, "normal", 1, normal);
    if (status == RT_OK && at != t->length)
        return refuse(r, RT_ERR_SYNTAX, t, 0,
                      "a face vertex `v`, `v/vt`, `v//vn` or `v/vt/vn`");
    return status;
}

/* Adds the facet (a, b, c) of the current material, read on `line`. */
static rt_status add_facet(reader *r, int a, int b, int c, int line)
{
    if (r->facet_count == r->facet_capacity) {
        if (r->facet_capacity > INT_MAX / 2)
            return rt__error_set(r->error, RT_ERR_LIMIT, r->name, line, 1,
                                 "expected at most %d facets", INT_MAX / 2);
        int bigger = r->facet_capacity ? 2 * r->facet_capacity : 64;
        rt_facet_desc *grown = realloc(r->facets,
                                       (size_t)bigger * sizeof *grown);
        if (grown == NULL)
            return rt__obj_out_of_memory(r);
        r->facets = grown;
        int *lines = realloc(r->facet_lines, (size_t)bigger * sizeof *lines);
        if (lines == NULL)
            return rt__obj_out_of_memory(r);
        r->facet_lines = lines;
        r->facet_capacity = bigger;
    }
    rt_facet_desc *f = &r->facets[r->facet_count];
    if (r->current >= 0) {
        *f = r->materials[r->current].look;
    } else {
        rt__mesh_default_look(f);
    }
    f->vertex[0] = a;
    f->vertex[1] = b;
    f->vertex[2] = c;
    r->facet_lines[r->facet_count++] = line;
    return RT_OK;
}

/* Where the triangulator's triangles go: the face's keyword. */
typedef struct face_sink {
    reader *r;
    int line;
} face_sink;

static rt_status emit_facet(void *user, int a, int b, int c)
{
    face_sink *sink = user;
    return add_facet(sink->r, a, b, c, sink->line);
}

/* The corners of a face, read one by one (no token is kept). */
static rt_status read_corners(reader *r, int *n)
{
    token t;
    *n = 0;
    while (rt__obj_token(&r->lex, &t)) {
        int room = rt__obj_grow((void **)&r->polygon, &r->polygon_capacity,
                                *n, sizeof *r->polygon, 16);
        if (room < 0)
            return refuse(r, RT_ERR_LIMIT, &t, 0, "fewer corners");
        if (room == 0)
            return rt__obj_out_of_memory(r);
        if (r->slot != NULL &&
            rt__obj_grow((void **)&r->corner_normals,
                         &r->corner_normal_capacity, *n,
                         sizeof *r->corner_normals, 16) <= 0)
            return rt__obj_out_of_memory(r);
        int normal;
        rt_status status = face_vertex(r, &t, &r->polygon[*n], &normal);
        if (r->slot != NULL)
            r->corner_normals[*n] = normal;
        (*n)++;
        if (status != RT_OK)
            return status;
    }
    return RT_OK;
}

static rt_status face(reader *r)
{
    token keyword = r->lex.tokens[0];
    int n;
    rt_status status = read_corners(r, &n);
    if (status != RT_OK)
        return status;
    if (n < 3) {
        int line, column;
        after(&r->lex.last, &line, &column);
        return rt__error_set(r->error, RT_ERR_SYNTAX, r->name, line, column,
                             "expected at least 3 vertices for the face, "
                             "found %d", n);
    }
    status = rt__obj_corners(r, &n);
    if (status != RT_OK)
        return status;
    face_sink sink = {r, keyword.line};
    rt_face_outcome outcome;
    status = rt__mesh_face(&r->triangulator, r->vertices, r->polygon, n,
                           emit_facet, &sink, &outcome);
    if (status == RT_ERR_NOMEM)
        return rt__obj_out_of_memory(r);
    if (status == RT_ERR_CANCELLED)
        return rt__error_set(r->error, RT_ERR_CANCELLED, r->name,
                             keyword.line, keyword.column,
                             "the load was cancelled");
    if (status != RT_OK)
        return status;
    counted *remarks[] = {NULL,          &r->few_corners, &r->no_area,
                          &r->no_area,   &r->over_budget, &r->fanned};
    if (outcome != RT_FACE_DRAWN) {
        char buffer[RT_ERROR_MESSAGE_SIZE];
        rt__obj_count(remarks[outcome], r->name, keyword.line,
                      keyword.column, "%s",
                      rt__mesh_face_remark(outcome, buffer, sizeof buffer));
    }
    return RT_OK;
}

/* The description's arrays, freed once the scene's records are made
 * (rt_reading.release). */
static void release_arrays(void *user)
{
    reader *r = user;
    free(r->vertices);
    free(r->facets);
    free(r->facet_lines);
    free(r->scene_normals);
    r->vertices = NULL;
    r->facets = NULL;
    r->facet_lines = NULL;
    r->scene_normals = NULL;
}

/* ---------------------------------------------------------------- reading */

static rt_status statement(reader *r)
{
    lexer *x = &r->lex;
    const token *k = &x->tokens[0];
    rt_status status = rt__obj_poll(r);
    if (status != RT_OK)
        return status;
    if (rt__token_is(k, "v"))
        return vertex(r);
    if (rt__token_is(k, "f") || rt__token_is(k, "fo"))
        return face(r);
    if (rt__token_is(k, "vt"))
        return attribute(r, &r->texture_count, 1, 3);
    if (rt__token_is(k, "vn"))
        return rt__obj_normal(r);
    if (rt__token_is(k, "o") || rt__token_is(k, "g") ||
        rt__token_is(k, "s"))
        return RT_OK;
    if (rt__token_is(k, "mtllib"))
        return rt__obj_read_libraries(r);
    if (rt__token_is(k, "usemtl"))
        return rt__obj_use_material(r);
    if (rt__token_is(k, "l") || rt__token_is(k, "p")) {
        rt__obj_warn_once(r, r->name, k,
                          "(lines and points) are ignored: only faces are "
                          "drawn");
        return RT_OK;
    }
    rt__obj_warn_once(r, r->name, k, "are not understood and are ignored");
    return RT_OK;
}

static rt_status read_obj(reader *r, rt_scene **scene)
{
    rt_status status = RT_OK;
    int more;
    while (status == RT_OK && (more = rt__obj_next_statement(&r->lex)) != 0)
        status = more < 0 ? rt__obj_out_of_memory(r) : statement(r);
    if (status == RT_OK)
        status = rt__obj_finish_materials(r);
    if (status != RT_OK)
        return status;
    const counted *summaries[] = {&r->fanned,       &r->over_budget,
                                  &r->no_area,      &r->few_corners,
                                  &r->self_library, &r->more_refused,
                                  &r->bad_values,   &r->lowered,
                                  &r->no_name,      &r->no_argument,
                                  &r->no_library_name, &r->bad_normal};
    for (size_t i = 0; i < sizeof summaries / sizeof summaries[0]; i++)
        rt__obj_say(r, summaries[i]);
    if (r->facet_count == 0)
        rt__obj_warn(r, r->name, 0, 0,
                     "the file has no face to draw: the picture is the "
                     "background");
    if (r->notes.failed)
        return rt__obj_out_of_memory(r);
    rt_scene_desc d;
    memset(&d, 0, sizeof d);
    rt_light light;
    rt__mesh_up(r->lex.text.start,
                (size_t)(r->lex.text.end - r->lex.text.start), 0, r->options,
                &d);
    status = rt__mesh_auto_view(r->name, r->vertices, r->vertex_count,
                                r->facets, r->facet_count, r->options, &d,
                                &light, r->error);
    if (status != RT_OK)
        return status;
    d.vertices = r->vertices;
    d.vertex_count = r->vertex_count;
    d.facets = r->facets;
    d.facet_count = r->facet_count;
    int failed;
    r->scene_normals = rt__obj_normals(r, &failed);
    if (failed)
        return rt__obj_out_of_memory(r);
    d.normals = r->scene_normals;
    rt_reading reading = {r->name, r->facet_lines, &r->notes, r->options,
                          NULL,    NULL,           release_arrays, r};
    return rt__reader_finish(&d, &reading, scene, r->error);
}

rt_status rt__obj_parse(const char *text, size_t length, const char *name,
                        const rt_load_options *options, rt_files *files,
                        rt_scene **scene, rt_error *error)
{
    /* The name as given: messages escape it (rt__error_set, notes). */
    const char *raw = name ? name : "<memory>";
    char *shown_name = malloc(strlen(raw) + 1);
    if (shown_name != NULL)
        memcpy(shown_name, raw, strlen(raw) + 1);
    if (shown_name == NULL)
        return rt__error_set(error, RT_ERR_NOMEM, NULL, 0, 0,
                             "out of memory");
    reader r;
    memset(&r, 0, sizeof r);
    rt_status status = rt__obj_lexer_open(&r.lex, text, length, shown_name,
                                          error);
    if (status != RT_OK) {
        free(shown_name);
        return status;
    }
    r.name = shown_name;
    r.error = error;
    r.options = options;
    r.files = files;
    r.current = -1;
    r.open_wait = -1;
    double budget = RT_TRI_WORK_FLOOR + (double)RT_TRI_WORK_PER_BYTE * length;
    rt__tri_init(&r.triangulator, budget, options->cancel);
    status = read_obj(&r, scene);
    rt__obj_free_materials(&r);
    rt__obj_free_normals(&r);
    rt__tri_free(&r.triangulator);
    rt__obj_lexer_close(&r.lex);
    release_arrays(&r);
    free(r.polygon);
    rt__notes_free(&r.notes);
    free(shown_name);
    return status;
}
