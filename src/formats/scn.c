/*
 * scn.c - the `.scn` scene format (docs/scene-format.md), read from
 * memory into an rt_scene_desc and handed to the scene builder.
 *
 * The reader goes record by record over the lines that hold something
 * (comments and blank lines are skipped; lexer.h), knows the line and
 * column of every token, and stops at the first broken rule of the format
 * with a message "name:line:column: expected ..., found ...".  The values
 * themselves (coordinates, k, t, n, d, s, p, the lens, the camera, the
 * number of lights) are the builder's to judge: it reports a refusal as data, and
 * locate() finds the token of the record and value it names.  Before
 * allocating for a count the reader checks that the file has that many
 * lines left, so a hostile count cannot make it allocate more than the
 * input's size justifies.  The load's cancellation flag is polled every
 * RT_LOAD_POLL records.
 */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "base/vecmath.h"
#include "formats/lexer.h"
#include "formats/reader.h"

#define MAX_VALUES 12       /* the longest record: a facet with highlights */

/* The grammar of .scn over the lexer: a record is a line, its values
 * separated by blanks and/or one comma. */
#define SCN_LEXER (RT_LEX_LINES | RT_LEX_COMMAS)

typedef struct parser {
    rt_lexer lex;
    rt_lexer start;         /* the lexer as opened, to find a record again */
    int vertex_count, facet_count;  /* as read, to number the records */
    const char *name;
    const rt_load_options *options;
    long records;           /* records read, for the cancellation poll */
    int record_lines_left;  /* lines with content from the cursor on */
    rt_error *error;
    /* the current record (and room for a token too many) */
    rt_token values[MAX_VALUES + 1];
    int value_count;
    int record_line;
} parser;

static rt_status fail_at(parser *p, rt_status status, const char *expected,
                         const rt_token *found)
{
    return rt__token_refuse(p->error, status, p->name, found, "%s", expected);
}

static int is_comma(const rt_token *t)
{
    return t->length == 1 && t->text[0] == ',';
}

/*
 * Reads the next line with content into values[]: values separated by
 * blanks and/or one comma.  Returns RT_OK, or an error; at the end of the
 * input sets value_count to -1.  The lexer writes each token straight into
 * its place (values[MAX_VALUES] takes the one too many, for the message):
 * a token copied just after the lexer wrote it waits for the store.
 */
static rt_status next_record(parser *p)
{
    rt_token *t = &p->values[0];
    if (!rt__lex_statement(&p->lex, t)) {
        p->value_count = -1;
        return RT_OK;
    }
    p->record_line = t->line;
    p->record_lines_left--;
    if (p->records++ % RT_LOAD_POLL == 0 && rt__load_cancelled(p->options))
        return rt__load_cancel(p->error, p->name);
    p->value_count = 0;
    int comma_allowed = 0;
    rt_token comma = {NULL, 0, 0, 0};   /* the last comma */
    do {
        if (is_comma(t)) {
            if (!comma_allowed)
                return fail_at(p, RT_ERR_SYNTAX, "a number", t);
            comma_allowed = 0;
            comma.text = t->text;
            comma.length = 1;
            comma.line = t->line;
            comma.column = t->column;
        } else {
            if (p->value_count == MAX_VALUES)
                return fail_at(p, RT_ERR_SYNTAX, "the end of the line", t);
            p->value_count++;
            comma_allowed = 1;
        }
        t = &p->values[p->value_count];
    } while (rt__lex_next(&p->lex, t));
    if (!comma_allowed)         /* a trailing comma */
        return fail_at(p, RT_ERR_SYNTAX, "a number after the comma", &comma);
    return RT_OK;
}

/*
 * Reads the next record, which must have `count` values, or up to `most`
 * (most >= count) for a record with optional values at its end; `what`
 * names it for messages ("the observer `x, y, z`").
 */
static rt_status expect_values(parser *p, int count, int most,
                               const char *what)
{
    rt_status status = next_record(p);
    if (status != RT_OK)
        return status;
    if (p->value_count < 0) {
        int line, column;
        rt__lex_end(&p->lex, &line, &column);
        return rt__error_set(p->error, RT_ERR_SYNTAX, p->name, line, column,
                             "unexpected end of file: expected %s", what);
    }
    if (p->value_count > most) {
        char expected[160];
        snprintf(expected, sizeof expected, "%d value%s for %s", most,
                 most == 1 ? "" : "s", what);
        return fail_at(p, RT_ERR_SYNTAX, expected, &p->values[most]);
    }
    if (p->value_count < count) {
        const rt_token *last = &p->values[p->value_count - 1];
        int column = last->column + (int)last->length;
        return rt__error_set(p->error, RT_ERR_SYNTAX, p->name, p->record_line,
                             column, "expected %d value%s for %s, found %d",
                             count, count == 1 ? "" : "s", what,
                             p->value_count);
    }
    return RT_OK;
}

static rt_status expect_record(parser *p, int count, const char *what)
{
    return expect_values(p, count, count, what);
}

/* The i-th value of the current record as a finite number. */
static rt_status number(parser *p, int i, double *value)
{
    const rt_token *t = &p->values[i];
    rt_status status = rt__lex_number(&p->lex, t, value);
    if (status != RT_OK)
        return fail_at(p, status, rt__number_expected(status), t);
    return RT_OK;
}

/* The i-th value as a whole number in [min, max]; `what` describes it
 * ("a colour component"). */
static rt_status integer(parser *p, int i, long min, long max,
                         const char *what, int *value)
{
    double v;
    rt_status status = number(p, i, &v);
    if (status != RT_OK)
        return status;
    if (v != floor(v) || v < (double)min || v > (double)max) {
        char expected[160];
        snprintf(expected, sizeof expected, "%s (a whole number in %ld..%ld)",
                 what, min, max);
        return fail_at(p, v != floor(v) ? RT_ERR_SYNTAX : RT_ERR_RANGE,
                       expected, &p->values[i]);
    }
    *value = (int)v;
    return RT_OK;
}

/* A point: values first..first+2 (the builder judges their range). */
static rt_status point(parser *p, int first, rt_vec3 *out)
{
    double c[3];
    for (int i = 0; i < 3; i++) {
        rt_status status = number(p, first + i, &c[i]);
        if (status != RT_OK)
            return status;
    }
    *out = v3(c[0], c[1], c[2]);
    return RT_OK;
}

static rt_status color(parser *p, int first, rt_rgb8 *out)
{
    int c[3];
    for (int i = 0; i < 3; i++) {
        rt_status status =
            integer(p, first + i, 0, 255, "a colour component", &c[i]);
        if (status != RT_OK)
            return status;
    }
    *out = (rt_rgb8){(unsigned char)c[0], (unsigned char)c[1],
                     (unsigned char)c[2]};
    return RT_OK;
}

/* A count of lines to follow, at most the lines the file has left. */
static rt_status count(parser *p, const char *what, int *out)
{
    char description[96];
    snprintf(description, sizeof description, "the %s count `n`", what);
    rt_status status = expect_record(p, 1, description);
    if (status != RT_OK)
        return status;
    snprintf(description, sizeof description, "a %s count", what);
    if ((status = integer(p, 0, 0, INT_MAX, description, out)) != RT_OK)
        return status;
    if (*out > p->record_lines_left) {
        snprintf(description, sizeof description,
                 "a %s count of at most %d (the lines left in the file)",
                 what, p->record_lines_left);
        return fail_at(p, RT_ERR_LIMIT, description,
                       &p->values[0]);
    }
    return RT_OK;
}

/*
 * The optional `a, f` of the screen record (values 8 and 9): both or
 * neither.  The builder judges the lens, but for f = 0: a description's 0
 * stands for |AO|, which a file says by leaving `a, f` out, so the format
 * refuses a written 0 (with the builder's words).
 */
static rt_status lens_values(parser *p, double *aperture, double *focal)
{
    if (p->value_count == 8)
        return RT_OK;
    if (p->value_count == 9) {
        const rt_token *last = &p->values[8];
        return rt__error_set(p->error, RT_ERR_SYNTAX, p->name, p->record_line,
                             last->column + (int)last->length,
                             "expected the focal distance `f` after the "
                             "aperture `a`, found the end of the line");
    }
    rt_status status = number(p, 8, aperture);
    if (status == RT_OK)
        status = number(p, 9, focal);
    if (status == RT_OK && *focal == 0.0)
        status = fail_at(p, RT_ERR_RANGE, RT_RULE_FOCAL, &p->values[9]);
    return status;
}

/* The optional `t [, n [, d [, s, p]]]` of a facet record (values 7 to
 * 11), judged by the builder but for n = 0 and p = 0: a description's 0
 * stands for 1, which a file says by leaving the value out.  s comes only
 * with p. */
static rt_status facet_options(parser *p, rt_facet_desc *f)
{
    rt_status status = RT_OK;
    if (p->value_count > 7)
        status = number(p, 7, &f->transparency);
    if (status == RT_OK && p->value_count > 8) {
        status = number(p, 8, &f->refractive_index);
        if (status == RT_OK && f->refractive_index == 0.0)
            status = fail_at(p, RT_ERR_RANGE, RT_RULE_N, &p->values[8]);
    }
    if (status == RT_OK && p->value_count > 9) {
        status = number(p, 9, &f->diffuse);
        f->diffuse_given = 1;
    }
    if (status == RT_OK && p->value_count == 11) {
        const rt_token *last = &p->values[10];
        return rt__error_set(p->error, RT_ERR_SYNTAX, p->name, p->record_line,
                             last->column + (int)last->length,
                             "expected the highlight exponent `p` after the "
                             "highlight weight `s`, found the end of the "
                             "line");
    }
    if (status == RT_OK && p->value_count > 11) {
        status = number(p, 10, &f->highlight);
        if (status == RT_OK)
            status = number(p, 11, &f->highlight_exponent);
        if (status == RT_OK && f->highlight_exponent == 0.0)
            status = fail_at(p, RT_ERR_RANGE, RT_RULE_P, &p->values[11]);
    }
    return status;
}

/*
 * A vertex record `x, y, z [, nx, ny, nz]` into vertex i; a normal, which
 * must not be zero (the description's zero stands for none, which a file
 * says by leaving it out), goes to *normals, allocated (zeroed) for
 * `count` vertices at the first.
 */
static rt_status vertex_record(parser *p, int i, int count, rt_vec3 *vertex,
                               rt_vec3 **normals)
{
    static const char what[] = "a vertex `x, y, z [, nx, ny, nz]`";
    rt_status status = expect_values(p, 3, 6, what);
    if (status == RT_OK)
        status = point(p, 0, vertex);
    if (status != RT_OK || p->value_count == 3)
        return status;
    /* Something that is not a number is named before the count. */
    for (int j = 3; j < p->value_count; j++) {
        double ignored;
        if ((status = number(p, j, &ignored)) != RT_OK)
            return status;
    }
    if (p->value_count < 6)
        return fail_at(p, RT_ERR_SYNTAX,
                       "3 values for a vertex `x, y, z`, or 6 with its "
                       "normal `x, y, z, nx, ny, nz`",
                       &p->values[3]);
    rt_vec3 n;
    if ((status = point(p, 3, &n)) != RT_OK)
        return status;
    if (n.x == 0.0 && n.y == 0.0 && n.z == 0.0)
        return fail_at(p, RT_ERR_RANGE,
                       "a non-zero vertex normal `nx, ny, nz`",
                       &p->values[3]);
    if (*normals == NULL) {
        *normals = calloc((size_t)count, sizeof **normals);
        if (*normals == NULL)
            return rt__error_set(p->error, RT_ERR_NOMEM, p->name, 0, 0,
                                 "out of memory");
    }
    (*normals)[i] = n;
    return RT_OK;
}

/* The token of value `value` (from 0, commas not counted) of the record
 * numbered `record` (from 0: the observer), read again from the start. */
static int record_value(const parser *p, long record, int value,
                        rt_token *token)
{
    rt_lexer lx = p->start;
    rt_token t;
    for (long r = 0; r <= record; r++)
        if (!rt__lex_statement(&lx, &t))
            return 0;
    for (int v = 0;;) {
        if (!is_comma(&t) && v++ == value) {
            *token = t;
            return 1;
        }
        if (!rt__lex_next(&lx, &t))
            return 0;
    }
}

/*
 * The token a refusal of the builder names (rt_locate_func).  The records
 * are numbered from 0: the observer, the screen, the vertex count, the
 * vertices, the facet count, the facets, the background, the light, the
 * further lights.
 */
static int locate(void *user, const rt_refusal *r, rt_token *token)
{
    const parser *p = user;
    long vertices = 3, facets = 4 + (long)p->vertex_count;
    long lights = 5 + (long)p->vertex_count + p->facet_count;
    switch (r->item) {
    case RT_ITEM_CAMERA:
        if (r->field == RT_FIELD_OBSERVER)
            return record_value(p, 0, r->part, token);
        return record_value(p, 1,
                            (r->field == RT_FIELD_SCREEN_RIGHT ? 3 : 0) +
                                r->part,
                            token);
    case RT_ITEM_LENS:
        return record_value(p, 1, r->field == RT_FIELD_APERTURE ? 8 : 9,
                            token);
    case RT_ITEM_VERTEX:
        return record_value(p, vertices + r->index,
                            (r->field == RT_FIELD_NORMAL ? 3 : 0) + r->part,
                            token);
    case RT_ITEM_FACET: {
        int value = r->field == RT_FIELD_CORNER ? r->part
                    : r->field == RT_FIELD_K    ? 3
                    : r->field == RT_FIELD_T    ? 7
                    : r->field == RT_FIELD_N    ? 8
                    : r->field == RT_FIELD_D    ? 9
                    : r->field == RT_FIELD_S    ? 10
                    : r->field == RT_FIELD_P    ? 11
                                                : -1;
        return value >= 0 && record_value(p, facets + r->index, value, token);
    }
    case RT_ITEM_LIGHT:
        return record_value(p, lights + r->index,
                            r->field == RT_FIELD_POSITION ? r->part : 0,
                            token);
    default:
        return 0;
    }
}

#define TRY(call)                                                            \
    do {                                                                     \
        if ((status = (call)) != RT_OK)                                      \
            goto done;                                                       \
    } while (0)

/* The description's arrays: the build frees them (release_arrays) once
 * the scene's records are made, before its kernel. */
typedef struct scn_arrays {
    rt_vec3 *vertices;
    rt_vec3 *normals;       /* NULL until a vertex has one */
    rt_facet_desc *facets;
    int *facet_lines;
} scn_arrays;

static void release_arrays(void *user)
{
    scn_arrays *a = user;
    free(a->vertices);
    free(a->normals);
    free(a->facets);
    free(a->facet_lines);
    a->vertices = NULL;
    a->normals = NULL;
    a->facets = NULL;
    a->facet_lines = NULL;
}

static rt_status parse(parser *p, const rt_load_options *options,
                       rt_scene **scene)
{
    rt_status status;
    rt_scene_desc d;
    memset(&d, 0, sizeof d);
    scn_arrays a = {NULL, NULL, NULL, NULL};
    rt_light *lights = NULL;

    TRY(expect_record(p, 3, "the observer `x, y, z`"));
    TRY(point(p, 0, &d.observer));
    TRY(expect_values(p, 8, 10,
                      "the screen `xA, yA, zA, xB, yB, zB, w, h [, a, f]`"));
    TRY(point(p, 0, &d.screen_center));
    TRY(point(p, 3, &d.screen_right));
    TRY(integer(p, 6, 1, RT_MAX_IMAGE_SIDE, "an image width", &d.width));
    TRY(integer(p, 7, 1, RT_MAX_IMAGE_SIDE, "an image height", &d.height));
    TRY(lens_values(p, &d.aperture, &d.focal_distance));
    TRY(count(p, "vertex", &d.vertex_count));
    p->vertex_count = d.vertex_count;
    a.vertices = malloc((size_t)(d.vertex_count ? d.vertex_count : 1) *
                        sizeof *a.vertices);
    if (a.vertices == NULL)
        goto nomem;
    for (int i = 0; i < d.vertex_count; i++)
        TRY(vertex_record(p, i, d.vertex_count, &a.vertices[i], &a.normals));
    d.vertices = a.vertices;
    d.normals = a.normals;

    TRY(count(p, "facet", &d.facet_count));
    p->facet_count = d.facet_count;
    size_t m = (size_t)(d.facet_count ? d.facet_count : 1);
    a.facets = calloc(m, sizeof *a.facets);
    a.facet_lines = malloc(m * sizeof *a.facet_lines);
    if (a.facets == NULL || a.facet_lines == NULL)
        goto nomem;
    for (int i = 0; i < d.facet_count; i++) {
        rt_facet_desc *f = &a.facets[i];
        TRY(expect_values(p, 7, 12,
                          "a facet `a, b, c, k, R, G, B [, t [, n [, d "
                          "[, s, p]]]]`"));
        for (int j = 0; j < 3; j++) {
            int vertex = 0;
            TRY(integer(p, j, 1, d.vertex_count, "a vertex index", &vertex));
            f->vertex[j] = vertex - 1;
        }
        TRY(number(p, 3, &f->reflection));
        TRY(color(p, 4, &f->color));
        TRY(facet_options(p, f));
        a.facet_lines[i] = p->record_line;
    }
    d.facets = a.facets;

    TRY(expect_record(p, 3, "the background colour `R, G, B`"));
    TRY(color(p, 0, &d.background));
    TRY(expect_record(p, 6, "the light source `x, y, z, R, G, B`"));
    rt_light first;
    TRY(point(p, 0, &first.position));
    TRY(color(p, 3, &first.color));

    /* Further lights, one a line, to the end of the file. */
    lights = malloc((1 + (size_t)p->record_lines_left) * sizeof *lights);
    if (lights == NULL)
        goto nomem;
    lights[0] = first;
    d.light_count = 1;
    while (p->record_lines_left > 0) {
        rt_light *light = &lights[d.light_count];
        static const char what[] = "a further light `x, y, z, R, G, B`";
        TRY(expect_values(p, 1, 6, what));
        /* Something that is not a number is named before any count. */
        for (int i = 0; i < p->value_count; i++) {
            double ignored;
            TRY(number(p, i, &ignored));
        }
        if (p->value_count < 6) {
            const rt_token *last = &p->values[p->value_count - 1];
            status = rt__error_set(p->error, RT_ERR_SYNTAX, p->name,
                                   p->record_line,
                                   last->column + (int)last->length,
                                   "expected 6 values for %s, found %d",
                                   what, p->value_count);
            goto done;
        }
        TRY(point(p, 0, &light->position));
        TRY(color(p, 3, &light->color));
        d.light_count++;
    }
    d.lights = lights;
    if (rt__load_cancelled(options)) {
        status = rt__load_cancel(p->error, p->name);
        goto done;
    }
    rt_reading reading = {p->name, a.facet_lines, NULL, options, locate, p,
                          release_arrays, &a};
    status = rt__reader_finish(&d, &reading, scene, p->error);
    goto done;
nomem:
    status = rt__error_set(p->error, RT_ERR_NOMEM, p->name, 0, 0,
                           "out of memory");
done:
    release_arrays(&a);
    free(lights);
    return status;
}

rt_status rt__scn_parse(const char *text, size_t length, const char *name,
                        const rt_load_options *options, rt_scene **scene,
                        rt_error *error)
{
    parser p;
    memset(&p, 0, sizeof p);
    p.name = name ? name : "<memory>";
    p.error = error;
    p.options = options;
    rt_status status = rt__lex_open(&p.lex, text, length, p.name, SCN_LEXER,
                                    error);
    if (status != RT_OK)
        return status;
    p.start = p.lex;
    /* (a record costs at least two bytes: fewer than INT_MAX of them) */
    long records = rt__lex_count(&p.lex, 1, options ? options->cancel : NULL);
    if (records < 0)
        status = rt__load_cancel(error, p.name);
    if (status == RT_OK) {
        p.record_lines_left = (int)records;
        status = parse(&p, options, scene);
    }
    rt__lex_close(&p.lex);
    return status;
}
