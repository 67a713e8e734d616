/*
 * ply_header.c - the header of a PLY file (ply.h): `ply`, the `format`
 * line, `comment` and `obj_info` lines, the `element` and `property`
 * declarations up to `end_header`, each checked with its line and column.
 * The header is text even when the body is binary: the bytes up to the
 * line `end_header` are found first (at most RT_PLY_MAX_HEADER_BYTES) and
 * only they go through the lexer's checks (lexer.h), so that a binary body
 * is never taken for text.  Each property gets its part in the model
 * (position, normal, colour, corners, or none) here; what is declared but
 * not read gets one warning per element.
 */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "formats/ply.h"

/* The most tokens a header line is looked at for: `property list uchar
 * int vertex_indices` and one more, to refuse. */
#define MOST_WORDS 6

static const struct {
    const char *name;
    ply_type type;
} type_names[] = {
    {"char", PLY_INT8},      {"uchar", PLY_UINT8},    {"short", PLY_INT16},
    {"ushort", PLY_UINT16},  {"int", PLY_INT32},      {"uint", PLY_UINT32},
    {"float", PLY_FLOAT32},  {"double", PLY_FLOAT64}, {"int8", PLY_INT8},
    {"uint8", PLY_UINT8},    {"int16", PLY_INT16},    {"uint16", PLY_UINT16},
    {"int32", PLY_INT32},    {"uint32", PLY_UINT32},  {"float32", PLY_FLOAT32},
    {"float64", PLY_FLOAT64}};

#define TYPE_LIST                                                             \
    "char, uchar, short, ushort, int, uint, float, double, int8, uint8, "     \
    "int16, uint16, int32, uint32, float32 or float64"

int rt__ply_type_size(ply_type type)
{
    static const int size[] = {0, 1, 1, 2, 2, 4, 4, 4, 8};
    return size[type];
}

const char *rt__ply_type_name(ply_type type)
{
    static const char *const names[] = {"none",  "char",   "uchar",
                                        "short", "ushort", "int",
                                        "uint",  "float",  "double"};
    return names[type];
}

static int is_integer(ply_type type)
{
    return type != PLY_FLOAT32 && type != PLY_FLOAT64;
}

/* A header line: its first MOST_WORDS tokens, how many it has, and the
 * position just after its last. */
typedef struct words {
    rt_token w[MOST_WORDS];
    int count;
    int end_line, end_column;
} words;

typedef struct parser {
    const char *name;
    rt_lexer lex;
    ply_header *h;
    rt_notes *notes;
    rt_error *error;
    int format_seen;
    int property_capacity;
} parser;

static void read_words(parser *p, const rt_token *first, words *out)
{
    rt_token t = *first;
    out->count = 0;
    do {
        if (out->count < MOST_WORDS)
            out->w[out->count] = t;
        out->count += out->count < INT_MAX;
        out->end_line = t.line;
        out->end_column = t.column + (int)t.length;
    } while (rt__lex_next(&p->lex, &t));
}

/* "expected WHAT, found the end of the line" just after the line's last
 * token. */
static rt_status line_ends(parser *p, const words *w, const char *what)
{
    return rt__error_set(p->error, RT_ERR_SYNTAX, p->name, w->end_line,
                         w->end_column,
                         "expected %s, found the end of the line",
                         what);
}

static rt_status refuse(parser *p, rt_status status, const rt_token *t,
                        const char *what)
{
    return rt__token_refuse(p->error, status, p->name, t, "%s", what);
}

/* Refuses tokens past the first `most` of the line. */
static rt_status no_more(parser *p, const words *w, int most, const char *what)
{
    return w->count > most ? refuse(p, RT_ERR_SYNTAX, &w->w[most], what)
                           : RT_OK;
}

static ply_type type_of(const rt_token *t)
{
    for (size_t i = 0; i < sizeof type_names / sizeof type_names[0]; i++)
        if (rt__token_is(t, type_names[i].name))
            return type_names[i].type;
    return PLY_NONE;
}

static int same_token(const rt_token *a, const rt_token *b)
{
    return a->length == b->length && memcmp(a->text, b->text, a->length) == 0;
}

/* ---------------------------------------------------------------- lines */

static rt_status format_line(parser *p, const words *w)
{
    static const char *const formats[] = {"ascii", "binary_little_endian",
                                          "binary_big_endian"};
    if (p->format_seen)
        return refuse(p, RT_ERR_SYNTAX, &w->w[0],
                      "one `format` line, and this is a second");
    if (w->count < 2)
        return line_ends(p, w,
                         "`ascii`, `binary_little_endian` or "
                         "`binary_big_endian`");
    int found = -1;
    for (int i = 0; i < 3; i++)
        if (rt__token_is(&w->w[1], formats[i]))
            found = i;
    if (found < 0)
        return refuse(p, RT_ERR_FORMAT, &w->w[1],
                      "`ascii`, `binary_little_endian` or "
                      "`binary_big_endian`");
    double version;
    if (w->count < 3)
        return line_ends(p, w, "the version `1.0`");
    if (rt__lex_number(&p->lex, &w->w[2], &version) != RT_OK || version != 1.0)
        return refuse(p, RT_ERR_FORMAT, &w->w[2], "the version `1.0`");
    p->format_seen = 1;
    p->h->format = (ply_format)found;
    return no_more(p, w, 3, "the end of the `format` line");
}

static ply_element *element_named(ply_header *h, const char *name)
{
    for (int i = 0; i < h->element_count; i++)
        if (rt__token_is(&h->element[i].name, name))
            return &h->element[i];
    return NULL;
}

static rt_status element_line(parser *p, const words *w)
{
    ply_header *h = p->h;
    if (w->count < 3)
        return line_ends(
            p, w, w->count < 2 ? "the element's name" : "the element's count");
    if (h->element_count == RT_PLY_MAX_ELEMENTS)
        return refuse(p, RT_ERR_LIMIT, &w->w[1],
                      "at most 64 elements (RT_PLY_MAX_ELEMENTS)");
    const rt_token *count = &w->w[2];
    long long value = 0;
    int digits = count->length > 0;
    for (size_t i = 0; i < count->length && digits; i++) {
        char c = count->text[i];
        digits = c >= '0' && c <= '9';
        if (digits && value <= INT_MAX)
            value = value * 10 + (c - '0');
    }
    if (!digits)
        return refuse(p, RT_ERR_SYNTAX, count,
                      "the element's count (a whole number)");
    if (value > INT_MAX / 2)
        return refuse(p, RT_ERR_LIMIT, count, "a count of at most 1073741823");
    for (int i = 0; i < h->element_count; i++)
        if (same_token(&h->element[i].name, &w->w[1]))
            return refuse(p, RT_ERR_SYNTAX, &w->w[1],
                          "an element name not declared before");
    ply_element *e = &h->element[h->element_count];
    memset(e, 0, sizeof *e);
    e->name = w->w[1];
    e->count = value;
    e->first = h->property_count;
    if (rt__token_is(&e->name, "vertex"))
        e->kind = KIND_VERTEX;
    if (rt__token_is(&e->name, "face")) {
        e->kind = KIND_FACE;
    } else if (e->kind == KIND_VERTEX && element_named(h, "face") != NULL) {
        return refuse(p, RT_ERR_SYNTAX, &e->name,
                      "the element `vertex` before the element `face` "
                      "(the faces refer to the vertices)");
    }
    h->element_count++;
    return no_more(p, w, 3, "the end of the `element` line");
}

/* The part of property `prop` of element `e` in the model. */
static rt_status give_role(parser *p, const ply_element *e, ply_property *prop)
{
    static const struct {
        const char *name;
        ply_kind kind;
        ply_role role;
    } roles[] = {{"x", KIND_VERTEX, ROLE_X},
                 {"y", KIND_VERTEX, ROLE_Y},
                 {"z", KIND_VERTEX, ROLE_Z},
                 {"nx", KIND_VERTEX, ROLE_NX},
                 {"ny", KIND_VERTEX, ROLE_NY},
                 {"nz", KIND_VERTEX, ROLE_NZ},
                 {"red", KIND_VERTEX, ROLE_RED},
                 {"green", KIND_VERTEX, ROLE_GREEN},
                 {"blue", KIND_VERTEX, ROLE_BLUE},
                 {"red", KIND_FACE, ROLE_RED},
                 {"green", KIND_FACE, ROLE_GREEN},
                 {"blue", KIND_FACE, ROLE_BLUE},
                 {"vertex_indices", KIND_FACE, ROLE_CORNERS},
                 {"vertex_index", KIND_FACE, ROLE_CORNERS}};
    prop->role = ROLE_NONE;
    for (size_t i = 0; i < sizeof roles / sizeof roles[0]; i++)
        if (roles[i].kind == e->kind &&
            rt__token_is(&prop->name, roles[i].name))
            prop->role = roles[i].role;
    int list = prop->count_type != PLY_NONE;
    if (prop->role == ROLE_CORNERS) {
        if (!list)
            return refuse(p, RT_ERR_SYNTAX, &prop->name,
                          "the vertex indices as a list (`property list "
                          "uchar int vertex_indices`)");
        if (!is_integer(prop->type))
            return refuse(p, RT_ERR_SYNTAX, &prop->name,
                          "vertex indices of an integer type");
        for (int i = e->first; i < e->first + e->properties; i++)
            if (p->h->property[i].role == ROLE_CORNERS)
                return refuse(p, RT_ERR_SYNTAX, &prop->name,
                              "one list of vertex indices in the element "
                              "`face`");
    } else if (prop->role >= ROLE_X && prop->role <= ROLE_Z && list) {
        return refuse(p, RT_ERR_SYNTAX, &prop->name,
                      "a coordinate that is a value, not a list");
    } else if (list) {
        prop->role = ROLE_NONE; /* a list of colours is no colour */
    }
    return RT_OK;
}

static rt_status property_line(parser *p, const words *w)
{
    ply_header *h = p->h;
    if (h->element_count == 0)
        return refuse(p, RT_ERR_SYNTAX, &w->w[0],
                      "an `element` line before its properties");
    ply_element *e = &h->element[h->element_count - 1];
    if (w->count < 2)
        return line_ends(p, w, "a property type");
    ply_property prop;
    memset(&prop, 0, sizeof prop);
    int at = 1;
    if (rt__token_is(&w->w[1], "list")) {
        if (w->count < 3)
            return line_ends(p, w, "the type of the list's count");
        prop.count_type = type_of(&w->w[2]);
        if (prop.count_type == PLY_NONE)
            return refuse(p, RT_ERR_SYNTAX, &w->w[2],
                          "a property type (" TYPE_LIST ")");
        if (!is_integer(prop.count_type))
            return refuse(p, RT_ERR_SYNTAX, &w->w[2],
                          "an integer type for the list's count");
        at = 3;
    }
    if (w->count <= at)
        return line_ends(p, w, "a property type");
    prop.type = type_of(&w->w[at]);
    if (prop.type == PLY_NONE)
        return refuse(p, RT_ERR_SYNTAX, &w->w[at],
                      at == 1 ? "a property type (" TYPE_LIST ") or `list`"
                              : "a property type (" TYPE_LIST ")");
    if (w->count <= at + 1)
        return line_ends(p, w, "the property's name");
    prop.name = w->w[at + 1];
    for (int i = e->first; i < e->first + e->properties; i++)
        if (same_token(&h->property[i].name, &prop.name))
            return refuse(p, RT_ERR_SYNTAX, &prop.name,
                          "a property name not declared before in its "
                          "element");
    rt_status status = no_more(p, w, at + 2,
                               "the end of the `property` line");
    if (status == RT_OK)
        status = give_role(p, e, &prop);
    if (status != RT_OK)
        return status;
    if (h->property_count == RT_PLY_MAX_PROPERTIES)
        return refuse(p, RT_ERR_LIMIT, &prop.name,
                      "at most 1024 properties (RT_PLY_MAX_PROPERTIES)");
    if (h->property_count == p->property_capacity) {
        int bigger = p->property_capacity ? 2 * p->property_capacity : 16;
        ply_property *grown =
            realloc(h->property, (size_t)bigger * sizeof *grown);
        if (grown == NULL)
            return rt__error_set(p->error, RT_ERR_NOMEM, p->name, 0, 0,
                                 "out of memory");
        h->property = grown;
        p->property_capacity = bigger;
    }
    h->property[h->property_count++] = prop;
    e->properties++;
    if (prop.count_type != PLY_NONE) {
        e->lists++;
        e->record += rt__ply_type_size(prop.count_type);
    } else {
        e->record += rt__ply_type_size(prop.type);
    }
    return RT_OK;
}

/* ------------------------------------------------------------- the end */

/* Whether element e has the three properties of roles first..first+2;
 * *missing names the first it lacks. */
static int has_three(const ply_header *h, const ply_element *e, ply_role first,
                     int *missing)
{
    int seen[3] = {0, 0, 0};
    for (int i = e->first; i < e->first + e->properties; i++) {
        ply_role role = h->property[i].role;
        if (role >= first && role < first + 3)
            seen[role - first] = 1;
    }
    for (int i = 0; i < 3; i++)
        if (!seen[i]) {
            *missing = i;
            return 0;
        }
    return 1;
}

/* Forgets the roles first..first+2 of element e (an incomplete colour or
 * normal): they are skipped like any other. */
static void drop_roles(ply_header *h, const ply_element *e, ply_role first)
{
    for (int i = e->first; i < e->first + e->properties; i++)
        if (h->property[i].role >= first && h->property[i].role < first + 3)
            h->property[i].role = ROLE_NONE;
}

/* Warns once per element about what it declares and is not read. */
static void say_skipped(parser *p, const ply_element *e)
{
    char names[200] = "";
    size_t used = 0;
    int skipped = 0;
    const ply_header *h = p->h;
    char shown[RT_TOKEN_SHOWN_SIZE];
    for (int i = e->first; i < e->first + e->properties; i++) {
        const ply_property *prop = &h->property[i];
        if (prop->role != ROLE_NONE)
            continue;
        if (skipped++ < 4 && used < sizeof names)
            used += (size_t)snprintf(names + used, sizeof names - used,
                                     "%s`%s`", skipped > 1 ? ", " : "",
                                     rt__token_shown(&prop->name, shown));
    }
    if (skipped > 0)
        rt__notes_add(
            p->notes, p->name, e->name.line, e->name.column,
            "%d propert%s of the element `%s` %s not read: %s%s", skipped,
            skipped > 1 ? "ies" : "y", rt__token_shown(&e->name, shown),
            skipped > 1 ? "are" : "is", names, skipped > 4 ? ", ..." : "");
}

static rt_status end_header(parser *p, const words *w)
{
    ply_header *h = p->h;
    if (!p->format_seen)
        return refuse(p, RT_ERR_SYNTAX, &w->w[0],
                      "a `format` line before `end_header`");
    rt_status status = no_more(p, w, 1, "the end of the line `end_header`");
    if (status != RT_OK)
        return status;
    h->end_line = w->w[0].line;
    char shown[RT_TOKEN_SHOWN_SIZE];
    for (int i = 0; i < h->element_count; i++) {
        ply_element *e = &h->element[i];
        int missing;
        if (e->kind == KIND_VERTEX) {
            static const char *const axes[] = {"x", "y", "z"};
            if (!has_three(h, e, ROLE_X, &missing))
                return rt__error_set(p->error, RT_ERR_SYNTAX, p->name,
                                     e->name.line, e->name.column,
                                     "expected the properties `x`, `y` "
                                     "and `z` of the element `vertex`, "
                                     "found no `%s`",
                                     axes[missing]);
            h->has_normals = has_three(h, e, ROLE_NX, &missing);
            if (!h->has_normals)
                drop_roles(h, e, ROLE_NX);
            h->vertex_colours = has_three(h, e, ROLE_RED, &missing);
            if (!h->vertex_colours)
                drop_roles(h, e, ROLE_RED);
        } else if (e->kind == KIND_FACE) {
            int corners = 0;
            for (int j = e->first; j < e->first + e->properties; j++)
                corners |= h->property[j].role == ROLE_CORNERS;
            if (!corners)
                return rt__error_set(p->error, RT_ERR_SYNTAX, p->name,
                                     e->name.line, e->name.column,
                                     "expected a list `vertex_indices` in "
                                     "the element `face`, found none");
            h->face_colours = has_three(h, e, ROLE_RED, &missing);
            if (!h->face_colours)
                drop_roles(h, e, ROLE_RED);
        } else {
            rt__notes_add(p->notes, p->name, e->name.line, e->name.column,
                          "the element `%s` (%lld item%s) is not read: only "
                          "`vertex` and `face` are",
                          rt__token_shown(&e->name, shown), e->count,
                          e->count == 1 ? "" : "s");
            continue;
        }
        say_skipped(p, e);
    }
    return RT_OK;
}

/* ---------------------------------------------------------------- reading */

/* The bytes of the header: up to and with the line `end_header` (*found
 * set), else up to the first NUL byte or the budget. */
static size_t header_extent(const char *text, size_t length, int *found)
{
    size_t limit =
        length < RT_PLY_MAX_HEADER_BYTES ? length : RT_PLY_MAX_HEADER_BYTES;
    size_t line = 0;
    *found = 0;
    while (line < limit) {
        const char *newline = memchr(text + line, '\n', limit - line);
        size_t end = newline ? (size_t)(newline - text) : limit;
        size_t s = line, e = end;
        while (s < e && (text[s] == ' ' || text[s] == '\t'))
            s++;
        while (e > s && (text[e - 1] == '\r' || text[e - 1] == ' ' ||
                         text[e - 1] == '\t'))
            e--;
        if (e - s == 10 && memcmp(text + s, "end_header", 10) == 0) {
            *found = 1;
            return newline ? end + 1 : end;
        }
        if (newline == NULL)
            break;
        line = end + 1;
    }
    const char *nul = limit > 0 ? memchr(text, '\0', limit) : NULL;
    return nul ? (size_t)(nul - text) : limit;
}

static rt_status header_lines(parser *p, size_t extent, int found,
                              size_t length)
{
    rt_token first;
    words w;
    int line = 0;
    while (rt__lex_statement(&p->lex, &first)) {
        read_words(p, &first, &w);
        rt_status status = RT_OK;
        if (line++ == 0) {
            if (!rt__token_is(&w.w[0], "ply") || w.w[0].line != 1)
                return refuse(p, RT_ERR_FORMAT, &w.w[0],
                              "`ply` (the first line of a PLY file)");
            status = no_more(p, &w, 1, "the end of the line `ply`");
        } else if (rt__token_is(&w.w[0], "format")) {
            status = format_line(p, &w);
        } else if (rt__token_is(&w.w[0], "comment") ||
                   rt__token_is(&w.w[0], "obj_info")) {
            continue;
        } else if (rt__token_is(&w.w[0], "element")) {
            status = element_line(p, &w);
        } else if (rt__token_is(&w.w[0], "property")) {
            status = property_line(p, &w);
        } else if (rt__token_is(&w.w[0], "end_header")) {
            return end_header(p, &w);
        } else {
            status = refuse(p, RT_ERR_SYNTAX, &w.w[0],
                            "a header line (`format`, `comment`, "
                            "`obj_info`, `element`, `property` or "
                            "`end_header`)");
        }
        if (status != RT_OK)
            return status;
    }
    int end_line, end_column;
    rt__lex_end(&p->lex, &end_line, &end_column);
    const char *found_what = line == 0 ? "the end of the file"
                             : found || extent == length
                                 ? "the end of the file"
                             : extent == RT_PLY_MAX_HEADER_BYTES
                                 ? "more than 1048576 bytes of header "
                                   "(RT_PLY_MAX_HEADER_BYTES)"
                                 : "a NUL byte (binary data)";
    return rt__error_set(p->error, line == 0 ? RT_ERR_FORMAT : RT_ERR_SYNTAX,
                         p->name, end_line, end_column,
                         "expected %s, found %s",
                         line == 0 ? "`ply` (the first line of a PLY file)"
                                   : "`end_header`",
                         found_what);
}

rt_status rt__ply_header_read(const char *text, size_t length,
                              const char *name, ply_header *h, rt_notes *notes,
                              rt_error *error)
{
    memset(h, 0, sizeof *h);
    int found;
    size_t extent = header_extent(text, length, &found);
    parser p;
    memset(&p, 0, sizeof p);
    p.name = name;
    p.h = h;
    p.notes = notes;
    p.error = error;
    rt_status status =
        rt__lex_open(&p.lex, text, extent, name, RT_LEX_LINES, error);
    if (status != RT_OK)
        return status;
    status = header_lines(&p, extent, found, length);
    rt__lex_close(&p.lex);
    h->length = extent;
    return status;
}

void rt__ply_header_free(ply_header *h)
{
    free(h->property);
    h->property = NULL;
}
