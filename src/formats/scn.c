/*
 * scn.c - the `.scn` scene format (docs/scene-format.md), read from
 * memory into an rt_scene_desc and handed to the scene builder.
 *
 * The reader goes record by record over the lines that hold something
 * (comments and blank lines are skipped), knows the line and column of
 * every token, and stops at the first broken rule with a message
 * "name:line:column: expected ..., found ...".  Before allocating for a
 * count it checks that the file has that many lines left, so a hostile count
 * cannot make it allocate more than the input's size justifies.  The load's
 * cancellation flag is polled every RT_LOAD_POLL records.
 */
#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <locale.h>
#include <stdio.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "formats/formats.h"
#include "formats/reader.h"
#include "scene/scene_internal.h"
#include "base/vecmath.h"

#define MAX_VALUES 10       /* the longest record: the screen with a lens */
#define MAX_NUMBER_LENGTH 256

/* A token of the current line. */
typedef struct token {
    const char *text;
    size_t length;
    int column;
} token;

typedef struct parser {
    const char *at, *end;
    const char *name;
    const rt_load_options *options;
    long records;           /* records read, for the cancellation poll */
    int line;               /* line of the next line to read */
    int record_lines_left;  /* lines with content from `at` on */
    locale_t c_locale;
    rt_error *error;
    /* the current record */
    token values[MAX_VALUES];
    int value_count;
    int record_line;
} parser;

/* Prints a token for a message: at most 40 bytes, non-printables as '?'. */
static const char *show(const token *t, char *buffer, size_t size)
{
    size_t n = t->length < 40 ? t->length : 40;
    if (n > size - 4)
        n = size - 4;
    for (size_t i = 0; i < n; i++) {
        unsigned char c = (unsigned char)t->text[i];
        buffer[i] = isprint(c) ? (char)c : '?';
    }
    strcpy(buffer + n, t->length > n ? "..." : "");
    return buffer;
}

static rt_status fail_at(parser *p, rt_status status, int column,
                         const char *expected, const token *found)
{
    char shown[48];
    if (found != NULL)
        return rt__error_set(p->error, status, p->name, p->record_line, column,
                             "expected %s, found `%s`", expected,
                             show(found, shown, sizeof shown));
    return rt__error_set(p->error, status, p->name, p->record_line, column,
                         "%s", expected);
}

/* The end of a line's content: before a comment, a CR, or the newline. */
static const char *content_end(const char *line, const char *end)
{
    const char *c = line;
    while (c < end && *c != '\n' && *c != '#')
        c++;
    while (c > line && (c[-1] == '\r' || c[-1] == ' ' || c[-1] == '\t'))
        c--;
    return c;
}

static const char *line_end(const char *line, const char *end)
{
    const char *nl = memchr(line, '\n', (size_t)(end - line));
    return nl ? nl : end;
}

static int is_blank(int c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

/* The lines with content; -1 when the load is cancelled meanwhile. */
static int count_record_lines(const char *at, const char *end,
                              const rt_load_options *options)
{
    int count = 0;
    for (long lines = 0; at < end; lines++) {
        if (lines % (16 * RT_LOAD_POLL) == 0 && rt__load_cancelled(options))
            return -1;
        const char *eol = line_end(at, end);
        const char *c = at;
        while (c < eol && is_blank(*c))
            c++;
        count += c < eol && *c != '#';
        at = eol < end ? eol + 1 : end;
    }
    return count;
}

/*
 * Splits the next line with content into tokens.  Values are separated by
 * white space and/or one comma.  Returns RT_OK, or an error; at the end of
 * the input sets value_count to -1.
 */
static rt_status next_record(parser *p)
{
    for (;;) {
        if (p->at >= p->end) {
            p->value_count = -1;
            return RT_OK;
        }
        const char *eol = line_end(p->at, p->end);
        const char *content = content_end(p->at, eol);
        const char *start = p->at;
        int line = p->line;
        p->at = eol < p->end ? eol + 1 : p->end;
        p->line++;
        const char *c = start;
        while (c < content && is_blank(*c))
            c++;
        if (c == content)
            continue;
        p->record_line = line;
        p->record_lines_left--;
        if (p->records++ % RT_LOAD_POLL == 0 && rt__load_cancelled(p->options))
            return rt__load_cancel(p->error, p->name);
        p->value_count = 0;
        int comma_allowed = 0;
        c = start;
        while (c < content) {
            if (is_blank(*c)) {
                c++;
                continue;
            }
            int column = (int)(c - start) + 1;
            if (*c == ',') {
                if (!comma_allowed) {
                    token t = {c, 1, column};
                    return fail_at(p, RT_ERR_SYNTAX, column, "a number", &t);
                }
                comma_allowed = 0;
                c++;
                continue;
            }
            const char *s = c;
            while (c < content && !is_blank(*c) && *c != ',')
                c++;
            token t = {s, (size_t)(c - s), column};
            if (p->value_count == MAX_VALUES)
                return fail_at(p, RT_ERR_SYNTAX, column,
                               "the end of the line", &t);
            p->values[p->value_count++] = t;
            comma_allowed = 1;
        }
        if (p->value_count > 0 && !comma_allowed) {
            /* a trailing comma */
            const char *comma = content - 1;
            while (*comma != ',')
                comma--;
            token t = {comma, 1, (int)(comma - start) + 1};
            return fail_at(p, RT_ERR_SYNTAX, t.column,
                           "a number after the comma", &t);
        }
        return RT_OK;
    }
}

/* Position of the end of the input, for "unexpected end of file". */
static void end_position(const parser *p, const char *text, int *line,
                         int *column)
{
    const char *last = p->end;
    while (last > text && last[-1] != '\n')
        last--;
    if (last == text && p->end - text >= 3 &&
        memcmp(text, "\xEF\xBB\xBF", 3) == 0)
        last += 3;
    int newlines = 0;
    for (const char *c = text; c < p->end; c++)
        newlines += *c == '\n';
    *line = newlines + 1;
    *column = (int)(p->end - last) + 1;
}

/*
 * Reads the next record, which must have `count` values, or up to `most`
 * (most >= count) for a record with optional values at its end; `what`
 * names it for messages ("the observer `x, y, z`").
 */
static rt_status expect_values(parser *p, const char *text, int count,
                               int most, const char *what)
{
    rt_status status = next_record(p);
    if (status != RT_OK)
        return status;
    if (p->value_count < 0) {
        int line, column;
        end_position(p, text, &line, &column);
        return rt__error_set(p->error, RT_ERR_SYNTAX, p->name, line, column,
                             "unexpected end of file: expected %s", what);
    }
    if (p->value_count > most) {
        char expected[160];
        snprintf(expected, sizeof expected, "%d value%s for %s", most,
                 most == 1 ? "" : "s", what);
        return fail_at(p, RT_ERR_SYNTAX, p->values[most].column, expected,
                       &p->values[most]);
    }
    if (p->value_count < count) {
        const token *last = &p->values[p->value_count - 1];
        int column = last->column + (int)last->length;
        return rt__error_set(p->error, RT_ERR_SYNTAX, p->name, p->record_line,
                             column, "expected %d value%s for %s, found %d",
                             count, count == 1 ? "" : "s", what,
                             p->value_count);
    }
    return RT_OK;
}

static rt_status expect_record(parser *p, const char *text, int count,
                               const char *what)
{
    return expect_values(p, text, count, count, what);
}

/* The i-th value of the current record as a finite number. */
static rt_status number(parser *p, int i, double *value)
{
    const token *t = &p->values[i];
    const char *s = t->text;
    if (!rt__number_syntax(s, t->length)) {
        char lower[8] = "";
        for (size_t k = 0; k < t->length && k < 7; k++)
            lower[k] = (char)tolower((unsigned char)s[k]);
        const char *word = lower[0] == '+' || lower[0] == '-' ? lower + 1
                                                             : lower;
        if (strncmp(word, "nan", 3) == 0 || strncmp(word, "inf", 3) == 0)
            return fail_at(p, RT_ERR_RANGE, t->column, "a finite number", t);
        return fail_at(p, RT_ERR_SYNTAX, t->column, "a number", t);
    }
    if (t->length > MAX_NUMBER_LENGTH)
        return fail_at(p, RT_ERR_LIMIT, t->column,
                       "a number of at most 256 characters", t);
    char copy[MAX_NUMBER_LENGTH + 1];
    memcpy(copy, s, t->length);
    copy[t->length] = '\0';
    locale_t previous = uselocale(p->c_locale);
    double v = strtod(copy, NULL);
    uselocale(previous);
    if (!isfinite(v))
        return fail_at(p, RT_ERR_RANGE, t->column, "a finite number", t);
    *value = v;
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
                       p->values[i].column, expected, &p->values[i]);
    }
    *value = (int)v;
    return RT_OK;
}

/* A point; `bounded`: a vertex or a camera point, whose coordinates must
 * stay within RT_MAX_COORDINATE (a light's need not). */
static rt_status point_within(parser *p, int first, int bounded,
                              rt_vec3 *out)
{
    double c[3];
    for (int i = 0; i < 3; i++) {
        rt_status status = number(p, first + i, &c[i]);
        if (status != RT_OK)
            return status;
        if (bounded && fabs(c[i]) > RT_MAX_COORDINATE)
            return fail_at(p, RT_ERR_RANGE, p->values[first + i].column,
                           "a coordinate of magnitude at most 1e152 (the "
                           "renderer's arithmetic overflows beyond)",
                           &p->values[first + i]);
    }
    *out = v3(c[0], c[1], c[2]);
    return RT_OK;
}

static rt_status point(parser *p, int first, rt_vec3 *out)
{
    return point_within(p, first, 1, out);
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
static rt_status count(parser *p, const char *text, const char *what,
                       int *out)
{
    char description[96];
    snprintf(description, sizeof description, "the %s count `n`", what);
    rt_status status = expect_record(p, text, 1, description);
    if (status != RT_OK)
        return status;
    snprintf(description, sizeof description, "a %s count", what);
    if ((status = integer(p, 0, 0, INT_MAX, description, out)) != RT_OK)
        return status;
    if (*out > p->record_lines_left) {
        snprintf(description, sizeof description,
                 "a %s count of at most %d (the lines left in the file)",
                 what, p->record_lines_left);
        return fail_at(p, RT_ERR_LIMIT, p->values[0].column, description,
                       &p->values[0]);
    }
    return RT_OK;
}

/* The optional `a, f` of the screen record (values 8 and 9): both or
 * neither, a >= 0, f > 0. */
static rt_status lens_values(parser *p, double *aperture, double *focal)
{
    if (p->value_count == 8)
        return RT_OK;
    if (p->value_count == 9) {
        const token *last = &p->values[8];
        return rt__error_set(p->error, RT_ERR_SYNTAX, p->name, p->record_line,
                             last->column + (int)last->length,
                             "expected the focal distance `f` after the "
                             "aperture `a`, found the end of the line");
    }
    rt_status status = number(p, 8, aperture);
    if (status == RT_OK && !(*aperture >= 0.0))
        status = fail_at(p, RT_ERR_RANGE, p->values[8].column,
                         "an aperture a >= 0", &p->values[8]);
    if (status == RT_OK)
        status = number(p, 9, focal);
    if (status == RT_OK && !(*focal > 0.0))
        status = fail_at(p, RT_ERR_RANGE, p->values[9].column,
                         "a focal distance f > 0", &p->values[9]);
    return status;
}

/* The optional `t [, n]` of a facet record (values 7 and 8). */
static rt_status transparency(parser *p, rt_facet_desc *f)
{
    rt_status status = RT_OK;
    if (p->value_count > 7) {
        status = number(p, 7, &f->t);
        if (status == RT_OK && !(f->t >= 0.0 && f->t <= 1.0 - f->k))
            status = fail_at(p, RT_ERR_RANGE, p->values[7].column,
                             f->t >= 0.0 ? "a transparency t with k + t <= 1"
                                         : "a transparency t >= 0",
                             &p->values[7]);
    }
    if (status == RT_OK && p->value_count > 8) {
        status = number(p, 8, &f->n);
        if (status == RT_OK && !(f->n > 0.0))
            status = fail_at(p, RT_ERR_RANGE, p->values[8].column,
                             "a refractive index n > 0", &p->values[8]);
    }
    return status;
}

#define TRY(call)                                                            \
    do {                                                                     \
        if ((status = (call)) != RT_OK)                                      \
            goto done;                                                       \
    } while (0)

static rt_status parse(parser *p, const char *text,
                       const rt_load_options *options, rt_scene **scene)
{
    rt_status status;
    rt_scene_desc d;
    memset(&d, 0, sizeof d);
    rt_vec3 *vertices = NULL;
    rt_facet_desc *facets = NULL;
    int *facet_lines = NULL;
    rt_light *lights = NULL;

    TRY(expect_record(p, text, 3, "the observer `x, y, z`"));
    TRY(point(p, 0, &d.observer));
    TRY(expect_values(p, text, 8, 10,
                      "the screen `xA, yA, zA, xB, yB, zB, w, h [, a, f]`"));
    TRY(point(p, 0, &d.screen_center));
    TRY(point(p, 3, &d.screen_right));
    TRY(integer(p, 6, 1, RT_MAX_IMAGE_SIDE, "an image width", &d.width));
    TRY(integer(p, 7, 1, RT_MAX_IMAGE_SIDE, "an image height", &d.height));
    TRY(lens_values(p, &d.aperture, &d.focal_distance));
    rt_camera camera;
    const char *reason = rt__camera_make(d.observer, d.screen_center,
                                         d.screen_right, d.width, d.height,
                                         &camera);
    if (reason != NULL) {
        int column = strstr(reason, "observer") ? p->values[0].column
                                                : p->values[3].column;
        status = rt__error_set(p->error, RT_ERR_CAMERA, p->name,
                               p->record_line, column,
                               "expected a camera that sees something, "
                               "found that %s", reason);
        goto done;
    }
    TRY(count(p, text, "vertex", &d.vertex_count));
    vertices = malloc((size_t)(d.vertex_count ? d.vertex_count : 1) *
                      sizeof *vertices);
    if (vertices == NULL)
        goto nomem;
    for (int i = 0; i < d.vertex_count; i++) {
        TRY(expect_record(p, text, 3, "a vertex `x, y, z`"));
        TRY(point(p, 0, &vertices[i]));
    }
    d.vertices = vertices;

    TRY(count(p, text, "facet", &d.facet_count));
    size_t m = (size_t)(d.facet_count ? d.facet_count : 1);
    facets = calloc(m, sizeof *facets);
    facet_lines = malloc(m * sizeof *facet_lines);
    if (facets == NULL || facet_lines == NULL)
        goto nomem;
    for (int i = 0; i < d.facet_count; i++) {
        rt_facet_desc *f = &facets[i];
        TRY(expect_values(p, text, 7, 9,
                          "a facet `a, b, c, k, R, G, B [, t [, n]]`"));
        for (int j = 0; j < 3; j++) {
            int vertex = 0;
            TRY(integer(p, j, 1, d.vertex_count, "a vertex index", &vertex));
            f->vertex[j] = vertex - 1;
        }
        TRY(number(p, 3, &f->k));
        if (!(f->k >= 0.0 && f->k <= 1.0)) {
            status = fail_at(p, RT_ERR_RANGE, p->values[3].column,
                             "a reflection coefficient k in [0, 1]",
                             &p->values[3]);
            goto done;
        }
        TRY(color(p, 4, &f->color));
        TRY(transparency(p, f));
        facet_lines[i] = p->record_line;
    }
    d.facets = facets;

    TRY(expect_record(p, text, 3, "the background colour `R, G, B`"));
    TRY(color(p, 0, &d.background));
    TRY(expect_record(p, text, 6, "the light source `x, y, z, R, G, B`"));
    TRY(point_within(p, 0, 0, &d.light_position));
    TRY(color(p, 3, &d.light_color));

    /* Further lights, one a line, to the end of the file. */
    if (p->record_lines_left > 0) {
        lights = malloc((size_t)p->record_lines_left * sizeof *lights);
        if (lights == NULL)
            goto nomem;
    }
    while (p->record_lines_left > 0) {
        rt_light *light = &lights[d.more_light_count];
        static const char what[] = "a further light `x, y, z, R, G, B`";
        TRY(expect_values(p, text, 1, 6, what));
        if (d.more_light_count == RT_MAX_LIGHTS - 1) {
            status = rt__error_set(p->error, RT_ERR_LIMIT, p->name,
                                   p->record_line, p->values[0].column,
                                   "expected at most %d lights (each one "
                                   "costs every hit a shadow ray), found "
                                   "light %d", RT_MAX_LIGHTS,
                                   RT_MAX_LIGHTS + 1);
            goto done;
        }
        /* Something that is not a number is named before any count. */
        for (int i = 0; i < p->value_count; i++) {
            double ignored;
            TRY(number(p, i, &ignored));
        }
        if (p->value_count < 6) {
            const token *last = &p->values[p->value_count - 1];
            status = rt__error_set(p->error, RT_ERR_SYNTAX, p->name,
                                   p->record_line,
                                   last->column + (int)last->length,
                                   "expected 6 values for %s, found %d",
                                   what, p->value_count);
            goto done;
        }
        TRY(point_within(p, 0, 0, &light->position));
        TRY(color(p, 3, &light->color));
        d.more_light_count++;
    }
    d.more_lights = lights;
    if (rt__load_cancelled(options)) {
        status = rt__load_cancel(p->error, p->name);
        goto done;
    }
    status = rt__reader_finish(&d, p->name, facet_lines, NULL, options, scene,
                               p->error);
    goto done;
nomem:
    status = rt__error_set(p->error, RT_ERR_NOMEM, p->name, 0, 0,
                           "out of memory");
done:
    free(vertices);
    free(facets);
    free(facet_lines);
    free(lights);
    return status;
}

rt_status rt__scn_parse(const char *text, size_t length, const char *name,
                        const rt_load_options *options, rt_scene **scene,
                        rt_error *error)
{
    if (scene == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, name, 0, 0,
                             "expected a pointer to fill with the scene");
    *scene = NULL;
    if (text == NULL && length > 0)
        return rt__error_set(error, RT_ERR_ARGUMENT, name, 0, 0,
                             "expected scene text");
    if (text == NULL)
        text = "";
    rt_status checked = rt__text_check(text, length, name ? name : "<memory>",
                                       error);
    if (checked != RT_OK)
        return checked;
    parser p;
    memset(&p, 0, sizeof p);
    p.at = text;
    p.end = text + length;
    p.name = name ? name : "<memory>";
    p.line = 1;
    p.error = error;
    if (length >= 3 && memcmp(text, "\xEF\xBB\xBF", 3) == 0)
        p.at += 3;          /* a UTF-8 byte-order mark: not a column */
    p.options = options;
    p.record_lines_left = count_record_lines(p.at, p.end, options);
    if (p.record_lines_left < 0)
        return rt__load_cancel(error, p.name);
    p.c_locale = newlocale(LC_ALL_MASK, "C", (locale_t)0);
    if (p.c_locale == (locale_t)0)
        return rt__error_set(error, RT_ERR_NOMEM, p.name, 0, 0,
                             "cannot create the C locale");
    rt_status status = parse(&p, text, options, scene);
    freelocale(p.c_locale);
    return status;
}

rt_status rt_scene_parse(const char *text, size_t length, const char *name,
                         rt_scene **scene, rt_error *error)
{
    return rt__scn_parse(text, length, name, NULL, scene, error);
}
