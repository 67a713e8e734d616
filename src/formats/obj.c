/*
 * obj.c - Wavefront OBJ meshes (.obj) with their material libraries (.mtl),
 * read from memory into an rt_scene_desc and handed to the scene builder.
 * What is read, what is ignored and why, the triangulation, the material
 * mapping, the automatic camera and light: docs/formats.md, section OBJ.
 *
 * The reader takes one statement at a time (a line, joined with the next
 * ones while it ends with a backslash), knows the line and column of every
 * token, and stops at the first broken rule of the geometry with a message
 * "name:line:column: expected ..., found `token`".  What exporters write
 * beyond geometry (unknown statements, lines and points, a missing or
 * broken .mtl, an unknown material) gives warnings, not failures: a mesh
 * should render even when its decorations do not.  Arrays grow by
 * doubling with their sizes checked; every element costs at least one byte
 * of input, so no count can exceed the input's length.
 */
#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <locale.h>
#include <math.h>
#include <stdint.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "error.h"
#include "file.h"
#include "formats/formats.h"
#include "formats/reader.h"
#include "scene_internal.h"
#include "vecmath.h"

/* The automatic view (docs/formats.md): from the front (+z), to the right
 * (+x) and above (+y, OBJ's usual up), the horizontal field of view. */
#define VIEW_X 0.5
#define VIEW_Y 0.5
#define VIEW_Z 1.0
#define VIEW_FOV_DEGREES 40.0
#define VIEW_MARGIN 1.05
#define DEFAULT_SIDE 512
#define DEFAULT_GREY 204    /* 0.8 * 255: Kd of the default material */
#define MAX_EAR_CLIPPED 1024 /* larger polygons are fanned (with a warning):
                               ear clipping costs up to n^3 */
#define MAX_KEYWORDS_NOTED 32
#define MAX_TOKEN_SHOWN 40

typedef struct token {
    const char *text;
    size_t length;
    int line, column;
} token;

/* Splits a text into statements. */
typedef struct lexer {
    const char *at, *end;
    int line;                   /* line of `at` */
    token *tokens;
    int count, capacity;
} lexer;

/* Names to numbers (materials, libraries read): open addressing over a
 * power-of-two array kept at most half full, so that a file with many
 * names costs linear time, not quadratic. */
typedef struct name_entry {
    char *name;                 /* NULL: an empty slot */
    size_t length;
    int value;
} name_entry;

typedef struct name_table {
    name_entry *entries;
    size_t size, used;
} name_table;

/* A material as the .mtl gives it. */
typedef struct material {
    const char *name;           /* owned by the reader's name table */
    double kd[3], ks[3];
    int illum;
    double dissolve, tr, ni;
    int has_d, has_tr;
    int unknown;                /* named by usemtl, found in no library */
    rt_facet_desc look;         /* what a facet of this material gets */
} material;

typedef struct reader {
    const char *name;           /* the OBJ, for messages */
    const char *path;           /* NULL: no folder to read .mtl files from */
    locale_t c_locale;
    rt_error *error;
    rt_notes notes;
    lexer lex;
    rt_vec3 *vertices;
    int vertex_count, vertex_capacity;
    int texture_count, normal_count;
    rt_facet_desc *facets;
    int *facet_lines;
    int facet_count, facet_capacity;
    material *materials;
    int material_count, material_capacity;
    name_table material_names;  /* name -> its last definition */
    name_table libraries;       /* the libraries already read */
    int current;                /* material of new facets; -1: default */
    /* polygon scratch */
    int *polygon, *order;
    double *plane;              /* u, v pairs */
    int polygon_capacity;
    /* once-only warnings */
    char keywords[MAX_KEYWORDS_NOTED][16];
    int keyword_count;
    int keywords_overflowed;
    int fanned, fanned_line, fanned_column;
    int dropped, dropped_line, dropped_column;
} reader;

/* ---------------------------------------------------------------- lexing */

static int is_space(int c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

static int lexer_push(lexer *x, const char *text, size_t length, int line,
                      int column)
{
    if (x->count == x->capacity) {
        int bigger = x->capacity ? 2 * x->capacity : 16;
        if (x->capacity > INT_MAX / 2)
            return 0;
        token *grown = realloc(x->tokens, (size_t)bigger * sizeof *grown);
        if (grown == NULL)
            return 0;
        x->tokens = grown;
        x->capacity = bigger;
    }
    x->tokens[x->count++] = (token){text, length, line, column};
    return 1;
}

/*
 * Reads the next statement into x->tokens: the tokens of a line up to a
 * `#`, and of the following lines while the last token ends with a
 * backslash (which is removed).  Returns 1 with x->count > 0, 0 at the end
 * of the text, -1 when out of memory.
 */
static int next_statement(lexer *x)
{
    x->count = 0;
    while (x->at < x->end) {
        const char *start = x->at;
        const char *eol = memchr(start, '\n', (size_t)(x->end - start));
        if (eol == NULL)
            eol = x->end;
        int line = x->line;
        x->at = eol < x->end ? eol + 1 : x->end;
        x->line++;
        int first = x->count;
        for (const char *c = start; c < eol && *c != '#';) {
            if (is_space((unsigned char)*c)) {
                c++;
                continue;
            }
            const char *s = c;
            while (c < eol && !is_space((unsigned char)*c) && *c != '#')
                c++;
            if (!lexer_push(x, s, (size_t)(c - s), line, (int)(s - start) + 1))
                return -1;
        }
        token *last = x->count > first ? &x->tokens[x->count - 1] : NULL;
        if (last != NULL && last->text[last->length - 1] == '\\') {
            if (--last->length == 0)
                x->count--;
            continue;               /* the statement goes on */
        }
        if (x->count > 0)
            return 1;
    }
    return x->count > 0;
}

static int token_is(const token *t, const char *word)
{
    size_t n = strlen(word);
    return t->length == n && memcmp(t->text, word, n) == 0;
}

/* A token for a message: at most 40 bytes, non-printables as '?'. */
static const char *shown(const token *t, char buffer[MAX_TOKEN_SHOWN + 4])
{
    size_t n = t->length < MAX_TOKEN_SHOWN ? t->length : MAX_TOKEN_SHOWN;
    for (size_t i = 0; i < n; i++)
        buffer[i] = isprint((unsigned char)t->text[i]) ? t->text[i] : '?';
    strcpy(buffer + n, t->length > n ? "..." : "");
    return buffer;
}

static rt_status refuse(reader *r, rt_status status, const token *t,
                        int column_offset, const char *fmt, ...)
    RT_PRINTF_LIKE(5, 6);

/* "name:line:column: expected ..., found `token`". */
static rt_status refuse(reader *r, rt_status status, const token *t,
                        int column_offset, const char *fmt, ...)
{
    char expected[200], buffer[MAX_TOKEN_SHOWN + 4];
    va_list args;
    va_start(args, fmt);
    vsnprintf(expected, sizeof expected, fmt, args);
    va_end(args);
    return rt__error_set(r->error, status, r->name, t->line,
                         t->column + column_offset, "expected %s, found `%s`",
                         expected, shown(t, buffer));
}

/* The position just after the last token, for "found the end of ...". */
static void after_last(const lexer *x, int *line, int *column)
{
    const token *t = &x->tokens[x->count - 1];
    *line = t->line;
    *column = t->column + (int)t->length;
}

/* ---------------------------------------------------------------- numbers */

/*
 * Reads `t` as a decimal number in the C locale: [+-] digits [. digits]
 * [e [+-] digits] with at least one digit (no hexadecimal, no inf or nan).
 * Returns 0 with *value set; 1 for something else; 2 for a number that is
 * not finite.
 */
static int decimal(locale_t c_locale, const token *t, double *value)
{
    char copy[128];
    if (t->length == 0 || t->length >= sizeof copy)
        return 1;
    int digits = 0;
    for (size_t i = 0; i < t->length; i++) {
        char c = t->text[i];
        if (isdigit((unsigned char)c))
            digits++;
        else if (!strchr("+-.eE", c))
            return 1;
        copy[i] = c;
    }
    copy[t->length] = '\0';
    if (digits == 0)
        return 1;
    char *stop;
    locale_t previous = uselocale(c_locale);
    errno = 0;
    double v = strtod(copy, &stop);
    uselocale(previous);
    if (*stop != '\0' || (copy[0] == '.' && !isdigit((unsigned char)copy[1])))
        return 1;
    if (!isfinite(v))
        return 2;
    *value = v;
    return 0;
}

/* The i-th token of the statement as a finite number. */
static rt_status number_at(reader *r, int i, double *value)
{
    const token *t = &r->lex.tokens[i];
    switch (decimal(r->c_locale, t, value)) {
    case 0:
        return RT_OK;
    case 2:
        return refuse(r, RT_ERR_RANGE, t, 0, "a finite number");
    default:
        return refuse(r, RT_ERR_SYNTAX, t, 0, "a number");
    }
}

/* --------------------------------------------------------------- warnings */

static void warn(reader *r, const char *name, int line, int column,
                 const char *fmt, ...) RT_PRINTF_LIKE(5, 6);

static void warn(reader *r, const char *name, int line, int column,
                 const char *fmt, ...)
{
    char message[RT_ERROR_MESSAGE_SIZE];
    va_list args;
    va_start(args, fmt);
    vsnprintf(message, sizeof message, fmt, args);
    va_end(args);
    rt__notes_add(&r->notes, name, line, column, "%s", message);
}

/* Non-zero the first time `key` (a keyword, or "@something" for other
 * once-only remarks, which no keyword can be) is seen. */
static int first_time(reader *r, const char *key, size_t length)
{
    if (length >= sizeof r->keywords[0])
        length = sizeof r->keywords[0] - 1;
    for (int i = 0; i < r->keyword_count; i++)
        if (strlen(r->keywords[i]) == length &&
            memcmp(r->keywords[i], key, length) == 0)
            return 0;
    if (r->keyword_count == MAX_KEYWORDS_NOTED) {
        int first = !r->keywords_overflowed;
        r->keywords_overflowed = 1;
        return first ? -1 : 0;
    }
    memcpy(r->keywords[r->keyword_count], key, length);
    r->keywords[r->keyword_count++][length] = '\0';
    return 1;
}

/* Warns once per keyword: `what` says how it is treated. */
static void warn_once(reader *r, const char *name, const token *keyword,
                      const char *what)
{
    char buffer[MAX_TOKEN_SHOWN + 4];
    int first = first_time(r, keyword->text, keyword->length);
    if (first > 0)
        warn(r, name, keyword->line, keyword->column,
             "`%s` statements %s (said once)", shown(keyword, buffer), what);
    else if (first < 0)
        warn(r, name, keyword->line, keyword->column,
             "more kinds of statements than are listed are ignored");
}

/* ---------------------------------------------------------------- names */

static size_t name_hash(const char *name, size_t length)
{
    size_t h = 2166136261u;         /* FNV-1a */
    for (size_t i = 0; i < length; i++)
        h = (h ^ (unsigned char)name[i]) * 16777619u;
    return h;
}

/* The entry of `name`, or the empty one where it would go (t->size > 0). */
static name_entry *name_slot(const name_table *t, const char *name,
                             size_t length)
{
    size_t i = name_hash(name, length) & (t->size - 1);
    for (;; i = (i + 1) & (t->size - 1)) {
        name_entry *e = &t->entries[i];
        if (e->name == NULL ||
            (e->length == length && memcmp(e->name, name, length) == 0))
            return e;
    }
}

static const name_entry *name_find(const name_table *t, const char *name,
                                   size_t length)
{
    if (t->size == 0)
        return NULL;
    const name_entry *e = name_slot(t, name, length);
    return e->name != NULL ? e : NULL;
}

/* The entry of `name`, added (value -1) when new; NULL when out of
 * memory. */
static name_entry *name_put(name_table *t, const char *name, size_t length)
{
    if (2 * (t->used + 1) > t->size) {
        size_t bigger = t->size ? 2 * t->size : 16;
        if (bigger > SIZE_MAX / 2 / sizeof(name_entry))
            return NULL;
        name_entry *entries = calloc(bigger, sizeof *entries);
        if (entries == NULL)
            return NULL;
        name_table grown = {entries, bigger, t->used};
        for (size_t i = 0; i < t->size; i++)
            if (t->entries[i].name != NULL)
                *name_slot(&grown, t->entries[i].name,
                           t->entries[i].length) = t->entries[i];
        free(t->entries);
        *t = grown;
    }
    name_entry *e = name_slot(t, name, length);
    if (e->name == NULL) {
        char *copy = malloc(length + 1);
        if (copy == NULL)
            return NULL;
        memcpy(copy, name, length);
        copy[length] = '\0';
        *e = (name_entry){copy, length, -1};
        t->used++;
    }
    return e;
}

static void name_table_free(name_table *t)
{
    for (size_t i = 0; i < t->size; i++)
        free(t->entries[i].name);
    free(t->entries);
    memset(t, 0, sizeof *t);
}

/* ---------------------------------------------------------------- materials */

static void material_defaults(material *m)
{
    m->kd[0] = m->kd[1] = m->kd[2] = DEFAULT_GREY / 255.0;
    m->ks[0] = m->ks[1] = m->ks[2] = 0.0;
    m->illum = 2;
    m->dissolve = 1.0;
    m->tr = 0.0;
    m->ni = 1.0;
}

static unsigned char to_byte(double x)
{
    x = x < 0.0 ? 0.0 : x > 1.0 ? 1.0 : x;
    return (unsigned char)floor(x * 255.0 + 0.5);
}

static double clamp01(double x)
{
    return x < 0.0 ? 0.0 : x > 1.0 ? 1.0 : x;
}

/* The illumination models that trace a mirror ray (MTL specification:
 * 3 "reflection on, ray trace on", 4 glass, 5 Fresnel, 6 and 7
 * refraction). */
static int mirror_model(int illum)
{
    return illum >= 3 && illum <= 7;
}

/* The facet a material gives (docs/formats.md): colour Kd, k = max(Ks)
 * for a mirror model, t = 1 - d (or Tr), n = Ni, d = 1 - k - t. */
static void material_look(reader *r, const char *library, int line,
                          material *m)
{
    rt_facet_desc *f = &m->look;
    memset(f, 0, sizeof *f);
    f->color = (rt_rgb8){to_byte(m->kd[0]), to_byte(m->kd[1]),
                         to_byte(m->kd[2])};
    if (mirror_model(m->illum))
        f->k = clamp01(fmax(m->ks[0], fmax(m->ks[1], m->ks[2])));
    f->t = m->has_d ? 1.0 - clamp01(m->dissolve)
                    : m->has_tr ? clamp01(m->tr) : 0.0;
    if (f->k + f->t > 1.0) {
        warn(r, library, line, 1,
             "material `%s`: mirror reflection %g and transparency %g add "
             "up to more than 1; the reflection is lowered to %g",
             m->name, f->k, f->t, 1.0 - f->t);
        f->k = 1.0 - f->t;
    }
    f->n = m->ni;
}

/* Adds a material with the default values under `name` (a later
 * definition of a name replaces the earlier one). */
static material *material_add(reader *r, const char *name, size_t length)
{
    if (r->material_count == r->material_capacity) {
        if (r->material_capacity > INT_MAX / 2)
            return NULL;
        int bigger = r->material_capacity ? 2 * r->material_capacity : 8;
        material *grown = realloc(r->materials,
                                  (size_t)bigger * sizeof *grown);
        if (grown == NULL)
            return NULL;
        r->materials = grown;
        r->material_capacity = bigger;
    }
    name_entry *entry = name_put(&r->material_names, name, length);
    if (entry == NULL)
        return NULL;
    material *m = &r->materials[r->material_count];
    memset(m, 0, sizeof *m);
    m->name = entry->name;
    material_defaults(m);
    entry->value = r->material_count++;
    return m;
}

/* A name spanning the statement's tokens from the second on (names may
 * hold spaces when they stay on one line). */
static void rest_of_statement(const lexer *x, const char **text,
                              size_t *length)
{
    const token *a = &x->tokens[1], *b = &x->tokens[x->count - 1];
    *text = a->text;
    *length = a->line == b->line ? (size_t)(b->text + b->length - a->text)
                                 : a->length;
}

/* Reads up to three numbers of an mtl colour statement (one gives grey). */
static int mtl_color(reader *r, const lexer *x, const char *library,
                     double out[3])
{
    char buffer[MAX_TOKEN_SHOWN + 4];
    if (x->count != 2 && x->count != 4) {
        warn(r, library, x->tokens[0].line, x->tokens[0].column,
             "`%s` with %d values ignored: only `r g b` or one grey value "
             "are read", shown(&x->tokens[0], buffer), x->count - 1);
        return 0;
    }
    double v[3];
    for (int i = 1; i < x->count; i++)
        if (decimal(r->c_locale, &x->tokens[i], &v[i - 1]) != 0) {
            warn(r, library, x->tokens[i].line, x->tokens[i].column,
                 "expected a number, found `%s`; the statement is ignored",
                 shown(&x->tokens[i], buffer));
            return 0;
        }
    for (int i = 0; i < 3; i++)
        out[i] = x->count == 2 ? v[0] : v[i];
    return 1;
}

/* Reads the one number of an mtl statement (the last token: `d -halo x`). */
static int mtl_value(reader *r, const lexer *x, const char *library,
                     double *out)
{
    char keyword[MAX_TOKEN_SHOWN + 4], found[MAX_TOKEN_SHOWN + 4];
    const token *k = &x->tokens[0], *t = &x->tokens[x->count - 1];
    if (x->count < 2) {
        warn(r, library, k->line, k->column,
             "expected a number after `%s`; the statement is ignored",
             shown(k, keyword));
        return 0;
    }
    if (decimal(r->c_locale, t, out) != 0) {
        warn(r, library, t->line, t->column,
             "expected a number after `%s`, found `%s`; the statement is "
             "ignored", shown(k, keyword), shown(t, found));
        return 0;
    }
    return 1;
}

/* Statements of an mtl file that have no place in the model (silent). */
static int mtl_ignored(const token *k)
{
    static const char *const words[] = {
        "Ka", "Ke", "Ns", "Tf", "sharpness", "bump", "disp", "decal",
        "refl", "norm", "Pr", "Pm", "Ps", "Pc", "Pcr", "aniso", "anisor"};
    for (size_t i = 0; i < sizeof words / sizeof words[0]; i++)
        if (token_is(k, words[i]))
            return 1;
    return k->length > 4 && memcmp(k->text, "map_", 4) == 0;
}

/* Parses a material library's text; its problems are warnings. */
static rt_status mtl_parse(reader *r, const char *text, size_t length,
                           const char *library)
{
    lexer x = {text, text + length, 1, NULL, 0, 0};
    if (length >= 3 && memcmp(text, "\xEF\xBB\xBF", 3) == 0)
        x.at += 3;
    char buffer[MAX_TOKEN_SHOWN + 4];
    material *m = NULL;
    int m_line = 0, status;
    while ((status = next_statement(&x)) > 0) {
        const token *k = &x.tokens[0];
        double v[3];
        if (token_is(k, "newmtl")) {
            if (m != NULL)
                material_look(r, library, m_line, m);
            m = NULL;
            if (x.count < 2) {
                warn(r, library, k->line, k->column,
                     "expected a material name after `newmtl`");
                continue;
            }
            const char *name;
            size_t name_length;
            rest_of_statement(&x, &name, &name_length);
            if ((m = material_add(r, name, name_length)) == NULL) {
                free(x.tokens);
                return RT_ERR_NOMEM;
            }
            m_line = k->line;
            continue;
        }
        if (m == NULL) {
            warn(r, library, k->line, k->column,
                 "`%s` outside a material (before any `newmtl`) ignored",
                 shown(k, buffer));
            continue;
        }
        if (token_is(k, "Kd")) {
            if (mtl_color(r, &x, library, v)) {
                memcpy(m->kd, v, sizeof v);
            }
        } else if (token_is(k, "Ks")) {
            if (mtl_color(r, &x, library, v))
                memcpy(m->ks, v, sizeof v);
        } else if (token_is(k, "illum")) {
            if (mtl_value(r, &x, library, v) && v[0] == floor(v[0]) &&
                fabs(v[0]) < 100)
                m->illum = (int)v[0];
        } else if (token_is(k, "d")) {
            if (mtl_value(r, &x, library, v)) {
                m->dissolve = v[0];
                m->has_d = 1;
            }
        } else if (token_is(k, "Tr")) {
            if (mtl_value(r, &x, library, v)) {
                m->tr = v[0];
                m->has_tr = 1;
            }
        } else if (token_is(k, "Ni")) {
            if (mtl_value(r, &x, library, v)) {
                if (v[0] > 0.0) {
                    m->ni = v[0];
                } else {
                    warn(r, library, x.tokens[1].line, x.tokens[1].column,
                         "expected a refractive index Ni > 0, found %g; "
                         "1 is used", v[0]);
                }
            }
        } else if (token_is(k, "map_Kd")) {
            warn_once(r, library, k,
                      "are ignored: textures are not drawn, the colour is Kd");
        } else if (!mtl_ignored(k)) {
            warn_once(r, library, k, "are not understood and are ignored");
        }
    }
    if (m != NULL)
        material_look(r, library, m_line, m);
    free(x.tokens);
    return status < 0 ? RT_ERR_NOMEM : RT_OK;
}

/* Non-zero when the statement has an argument; else warns "`keyword`
 * <consequence>". */
static int has_argument(reader *r, const char *consequence)
{
    const token *k = &r->lex.tokens[0];
    char buffer[MAX_TOKEN_SHOWN + 4];
    if (r->lex.count >= 2)
        return 1;
    warn(r, r->name, k->line, k->column, "`%s` %s", shown(k, buffer),
         consequence);
    return 0;
}

/* The path of a library named by text[0..length), relative to the OBJ's
 * folder unless absolute; "\ " stands for a space. */
static char *library_path(const reader *r, const char *text, size_t length)
{
    const char *slash = strrchr(r->path, '/');
    size_t prefix = text[0] == '/' || slash == NULL
                        ? 0
                        : (size_t)(slash - r->path) + 1;
    char *path = malloc(prefix + length + 1);
    if (path == NULL)
        return NULL;
    memcpy(path, r->path, prefix);
    size_t n = prefix;
    for (size_t i = 0; i < length; i++)
        if (!(text[i] == '\\' && i + 1 < length && text[i + 1] == ' '))
            path[n++] = text[i];
    path[n] = '\0';
    return path;
}

static int regular_file(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

/* Reads the library at `path` (named by `where` in the OBJ) once; what
 * goes wrong is a warning.  Only regular files are read (a FIFO or a
 * terminal would block).  Takes `path`. */
static rt_status read_library(reader *r, char *path, const token *where)
{
    name_entry *seen = name_put(&r->libraries, path, strlen(path));
    if (seen == NULL || seen->value++ >= 0) {       /* read already */
        free(path);
        return seen == NULL ? RT_ERR_NOMEM : RT_OK;
    }
    char *text = NULL;
    size_t length = 0;
    rt_error why;
    memset(&why, 0, sizeof why);
    struct stat st;
    if (stat(path, &st) != 0)
        snprintf(why.message, sizeof why.message, "%s", strerror(errno));
    else if (!S_ISREG(st.st_mode))
        snprintf(why.message, sizeof why.message, "not a regular file");
    else if (rt__read_text_file(path, &text, &length, &why) == RT_OK &&
             rt__text_check(text, length, path, &why) == RT_OK)
        why.message[0] = '\0';
    rt_status status = why.status == RT_ERR_NOMEM ? RT_ERR_NOMEM : RT_OK;
    if (status == RT_OK && why.message[0] != '\0') {
        char buffer[MAX_TOKEN_SHOWN + 4];
        warn(r, r->name, where->line, where->column,
             "material library `%s` not read (%s); its materials get the "
             "default grey", shown(where, buffer), why.message);
    } else if (status == RT_OK) {
        status = mtl_parse(r, text, length, path);
    }
    free(text);
    free(path);
    return status;
}

/* `mtllib` names one or more files, relative to the OBJ's folder: the
 * whole rest of the line when that is a file (exporters write names with
 * spaces as they are), else each name (with "\ " for a space). */
static rt_status read_libraries(reader *r)
{
    lexer *x = &r->lex;
    const token *k = &x->tokens[0];
    if (!has_argument(r, "without a file name is ignored"))
        return RT_OK;
    if (r->path == NULL) {
        warn(r, r->name, k->line, k->column,
             "material libraries are not read for a scene given without a "
             "path; facets get the default material");
        return RT_OK;
    }
    if (x->count > 2 && x->tokens[1].line == x->tokens[x->count - 1].line) {
        token whole = x->tokens[1];
        rest_of_statement(x, &whole.text, &whole.length);
        char *path = library_path(r, whole.text, whole.length);
        if (path == NULL)
            return RT_ERR_NOMEM;
        if (regular_file(path))
            return read_library(r, path, &whole);
        free(path);
    }
    for (int i = 1; i < x->count; i++) {
        token name = x->tokens[i];
        while (name.text[name.length - 1] == '\\' && i + 1 < x->count &&
               x->tokens[i + 1].text == name.text + name.length + 1 &&
               name.text[name.length] == ' ')
            name.length += 1 + x->tokens[++i].length;
        char *path = library_path(r, name.text, name.length);
        if (path == NULL)
            return RT_ERR_NOMEM;
        rt_status status = read_library(r, path, &name);
        if (status != RT_OK)
            return status;
    }
    return RT_OK;
}

static rt_status use_material(reader *r)
{
    lexer *x = &r->lex;
    const token *k = &x->tokens[0];
    if (!has_argument(r, "without a name: the default material is used")) {
        r->current = -1;
        return RT_OK;
    }
    const char *name;
    size_t length;
    rest_of_statement(x, &name, &length);
    const name_entry *known = name_find(&r->material_names, name, length);
    if (known != NULL) {
        r->current = known->value;
        return RT_OK;
    }
    material *m = material_add(r, name, length);
    if (m == NULL)
        return RT_ERR_NOMEM;
    m->unknown = 1;
    material_look(r, r->name, k->line, m);
    r->current = r->material_count - 1;
    char buffer[MAX_TOKEN_SHOWN + 4];
    token t = {name, length, x->tokens[1].line, x->tokens[1].column};
    warn(r, r->name, t.line, t.column,
         "material `%s` is defined in no material library read; its facets "
         "get the default grey", shown(&t, buffer));
    return RT_OK;
}

/* ---------------------------------------------------------------- geometry */

static rt_status out_of_memory(reader *r)
{
    return rt__error_set(r->error, RT_ERR_NOMEM, r->name, 0, 0,
                         "out of memory");
}

static rt_status vertex(reader *r)
{
    lexer *x = &r->lex;
    if (x->count < 4 || x->count > 8) {
        if (x->count > 8)
            return refuse(r, RT_ERR_SYNTAX, &x->tokens[8], 0,
                          "the end of the vertex `v x y z [w]`");
        int line, column;
        after_last(x, &line, &column);
        return rt__error_set(r->error, RT_ERR_SYNTAX, r->name, line, column,
                             "expected 3 coordinates for the vertex `v x y z "
                             "[w]`, found %d", x->count - 1);
    }
    double c[7];
    for (int i = 1; i < x->count; i++) {
        rt_status status = number_at(r, i, &c[i - 1]);
        if (status != RT_OK)
            return status;
        if (i <= 3 && fabs(c[i - 1]) > RT_MAX_COORDINATE)
            return refuse(r, RT_ERR_RANGE, &x->tokens[i], 0,
                          "a coordinate of magnitude at most 1e152 (the "
                          "renderer's arithmetic overflows beyond)");
    }
    if (x->count >= 7)
        warn_once(r, r->name, &x->tokens[0],
                  "with vertex colours are read as positions only: the "
                  "colours are ignored");
    if (r->vertex_count == r->vertex_capacity) {
        if (r->vertex_capacity > INT_MAX / 2)
            return refuse(r, RT_ERR_LIMIT, &x->tokens[0], 0,
                          "at most %d vertices", INT_MAX / 2);
        int bigger = r->vertex_capacity ? 2 * r->vertex_capacity : 64;
        rt_vec3 *grown = realloc(r->vertices, (size_t)bigger * sizeof *grown);
        if (grown == NULL)
            return out_of_memory(r);
        r->vertices = grown;
        r->vertex_capacity = bigger;
    }
    r->vertices[r->vertex_count++] = v3(c[0], c[1], c[2]);
    return RT_OK;
}

/* `vt` and `vn`: numbers, counted for the faces' references, not used. */
static rt_status attribute(reader *r, int *count, int least, int most)
{
    lexer *x = &r->lex;
    if (x->count - 1 < least || x->count - 1 > most) {
        char buffer[MAX_TOKEN_SHOWN + 4];
        int line, column;
        after_last(x, &line, &column);
        if (x->count - 1 > most)
            return refuse(r, RT_ERR_SYNTAX, &x->tokens[most + 1], 0,
                          "at most %d values for `%s`", most,
                          shown(&x->tokens[0], buffer));
        return rt__error_set(r->error, RT_ERR_SYNTAX, r->name, line, column,
                             "expected %d values for `%s`, found %d", least,
                             shown(&x->tokens[0], buffer), x->count - 1);
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
 * index among `count` ("vertex", "texture coordinate", "normal").  With
 * `out` NULL (texture coordinates and normals, which are not used) an
 * index out of range is a warning, not a refusal; 0 is refused always.
 */
static rt_status index_at(reader *r, const token *t, size_t *at, int count,
                          const char *what, int *out)
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
        char buffer[MAX_TOKEN_SHOWN + 4];
        token part = {t->text + *at, i - *at, t->line, t->column + column};
        if (out == NULL && value != 0) {
            /* Texture coordinates and normals are not used: exporters
             * that leave them out but keep the references still render. */
            const char *key = what[0] == 't' ? "@vt" : "@vn";
            if (first_time(r, key, strlen(key)) > 0)
                warn(r, r->name, part.line, part.column,
                     "`%s` refers to no %s read so far; %s indices are not "
                     "used, this one is ignored (said once)",
                     shown(&part, buffer), what, what);
            *at = i;
            return RT_OK;
        }
        if (count == 0)
            return rt__error_set(r->error, RT_ERR_RANGE, r->name, part.line,
                                 part.column,
                                 "expected a %s index, found `%s` before any "
                                 "%s is defined", what, shown(&part, buffer),
                                 what);
        return rt__error_set(r->error, RT_ERR_RANGE, r->name, part.line,
                             part.column,
                             "expected a %s index in 1..%d or -%d..-1 (%d "
                             "defined so far; 0 names none), found `%s`",
                             what, count, count, count, shown(&part, buffer));
    }
    *at = i;
    if (out != NULL)
        *out = (int)resolved;
    return RT_OK;
}

/* One vertex of a face: v, v/vt, v//vn or v/vt/vn. */
static rt_status face_vertex(reader *r, const token *t, int *out)
{
    size_t at = 0;
    rt_status status = index_at(r, t, &at, r->vertex_count, "vertex", out);
    if (status != RT_OK || at == t->length)
        return status;
    at++;                                       /* the first '/' */
    if (at < t->length && t->text[at] != '/') {
        status = index_at(r, t, &at, r->texture_count, "texture coordinate",
                          NULL);
        if (status != RT_OK || at == t->length)
            return status;
    }
    if (at == t->length || t->text[at] != '/' || ++at == t->length)
        return refuse(r, RT_ERR_SYNTAX, t, 0,
                      "a face vertex `v`, `v/vt`, `v//vn` or `v/vt/vn`");
    status = index_at(r, t, &at, r->normal_count, "normal", NULL);
    if (status == RT_OK && at != t->length)
        return refuse(r, RT_ERR_SYNTAX, t, 0,
                      "a face vertex `v`, `v/vt`, `v//vn` or `v/vt/vn`");
    return status;
}

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
            return out_of_memory(r);
        r->facets = grown;
        int *lines = realloc(r->facet_lines, (size_t)bigger * sizeof *lines);
        if (lines == NULL)
            return out_of_memory(r);
        r->facet_lines = lines;
        r->facet_capacity = bigger;
    }
    rt_facet_desc *f = &r->facets[r->facet_count];
    if (r->current >= 0) {
        *f = r->materials[r->current].look;
    } else {
        memset(f, 0, sizeof *f);
        f->color = (rt_rgb8){DEFAULT_GREY, DEFAULT_GREY, DEFAULT_GREY};
    }
    f->vertex[0] = a;
    f->vertex[1] = b;
    f->vertex[2] = c;
    r->facet_lines[r->facet_count++] = line;
    return RT_OK;
}

/* Twice the signed area of the 2D triangle (a, b, c). */
static double orient(const double *a, const double *b, const double *c)
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/* Non-zero when p lies inside or on the 2D triangle (a, b, c), counter-
 * clockwise. */
static int inside(const double *a, const double *b, const double *c,
                  const double *p)
{
    return orient(a, b, p) >= 0 && orient(b, c, p) >= 0 &&
           orient(c, a, p) >= 0;
}

static int same_point(const double *a, const double *b)
{
    return a[0] == b[0] && a[1] == b[1];
}

/*
 * Projects the polygon (r->polygon, n vertex indices) onto its best-fit
 * plane: the Newell normal of the vertices, on coordinates moved to the
 * first vertex and scaled to at most 1 (no overflow at any scale).  Fills
 * r->plane with (u, v) pairs, counter-clockwise when the polygon winds
 * around the normal.  Returns 0 when the polygon has no area.
 */
static int project(reader *r, int n)
{
    rt_vec3 origin = r->vertices[r->polygon[0]];
    double scale = 0.0;
    for (int i = 1; i < n; i++)
        scale = fmax(scale, v3_max_abs(v3_sub(r->vertices[r->polygon[i]],
                                              origin)));
    if (!(scale > 0.0) || !isfinite(scale))
        return 0;
    rt_vec3 normal = v3(0, 0, 0);
    for (int i = 0; i < n; i++) {
        rt_vec3 p = v3_scale(v3_sub(r->vertices[r->polygon[i]], origin),
                             1.0 / scale);
        rt_vec3 q = v3_scale(v3_sub(r->vertices[r->polygon[(i + 1) % n]],
                                    origin), 1.0 / scale);
        normal.x += (p.y - q.y) * (p.z + q.z);
        normal.y += (p.z - q.z) * (p.x + q.x);
        normal.z += (p.x - q.x) * (p.y + q.y);
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
    for (int i = 0; i < n; i++) {
        rt_vec3 p = v3_scale(v3_sub(r->vertices[r->polygon[i]], origin),
                             1.0 / scale);
        r->plane[2 * i] = v3_dot(p, e1);
        r->plane[2 * i + 1] = v3_dot(p, e2);
    }
    return 1;
}

static int convex_corner(const reader *r, const int *order, int m, int i)
{
    const double *a = &r->plane[2 * order[(i + m - 1) % m]];
    const double *b = &r->plane[2 * order[i]];
    const double *c = &r->plane[2 * order[(i + 1) % m]];
    return orient(a, b, c) > 0;
}

/* Non-zero when corner i of the remaining polygon is an ear: convex, and
 * no other remaining corner inside or on it. */
static int is_ear(const reader *r, const int *order, int m, int i)
{
    if (!convex_corner(r, order, m, i))
        return 0;
    int ia = order[(i + m - 1) % m], ib = order[i], ic = order[(i + 1) % m];
    const double *a = &r->plane[2 * ia], *b = &r->plane[2 * ib],
                 *c = &r->plane[2 * ic];
    for (int j = 0; j < m; j++) {
        int o = order[j];
        if (o == ia || o == ib || o == ic)
            continue;
        const double *p = &r->plane[2 * o];
        if (same_point(p, a) || same_point(p, b) || same_point(p, c))
            continue;
        if (!convex_corner(r, order, m, j) && inside(a, b, c, p))
            return 0;
    }
    return 1;
}

static void note_fan(reader *r, const token *keyword)
{
    if (r->fanned++ == 0) {
        r->fanned_line = keyword->line;
        r->fanned_column = keyword->column;
    }
}

/* Triangulates the polygon of n >= 4 corners (docs/formats.md): ear
 * clipping in its best-fit plane; a fan when it has no area, crosses
 * itself or is too large. */
static rt_status triangulate(reader *r, int n, const token *keyword)
{
    int *p = r->polygon, line = keyword->line;
    rt_status status = RT_OK;
    if (n > MAX_EAR_CLIPPED || !project(r, n)) {
        note_fan(r, keyword);
        for (int i = 1; i + 1 < n && status == RT_OK; i++)
            status = add_facet(r, p[0], p[i], p[i + 1], line);
        return status;
    }
    int *order = r->order, m = n;
    for (int i = 0; i < n; i++)
        order[i] = i;
    /* Corner indices below are positions in r->polygon / r->plane; the
     * search for the next ear starts where the last one was clipped. */
    int start = 0;
    while (m > 3 && status == RT_OK) {
        int clipped = -1;
        for (int step = 0; step < m && clipped < 0; step++) {
            int i = (start + step) % m;
            if (!is_ear(r, order, m, i))
                continue;
            status = add_facet(r, p[order[(i + m - 1) % m]], p[order[i]],
                               p[order[(i + 1) % m]], line);
            clipped = i;
        }
        /* Else a corner on a straight line (or a spike) bounds no area:
         * drop it. */
        for (int i = 0; i < m && clipped < 0; i++)
            if (orient(&r->plane[2 * order[(i + m - 1) % m]],
                       &r->plane[2 * order[i]],
                       &r->plane[2 * order[(i + 1) % m]]) == 0)
                clipped = i;
        if (clipped >= 0) {
            memmove(&order[clipped], &order[clipped + 1],
                    (size_t)(m - clipped - 1) * sizeof *order);
            m--;
            start = clipped > 0 ? clipped - 1 : 0;
            continue;
        }
        /* No ear: the polygon crosses itself. */
        note_fan(r, keyword);
        for (int i = 1; i + 1 < m && status == RT_OK; i++)
            status = add_facet(r, p[order[0]], p[order[i]], p[order[i + 1]],
                               line);
        return status;
    }
    if (status == RT_OK && m == 3) {
        const double *a = &r->plane[2 * order[0]], *b = &r->plane[2 * order[1]],
                     *c = &r->plane[2 * order[2]];
        if (orient(a, b, c) != 0)
            status = add_facet(r, p[order[0]], p[order[1]], p[order[2]], line);
    }
    return status;
}

static rt_status face(reader *r)
{
    lexer *x = &r->lex;
    const token *keyword = &x->tokens[0];
    int n = x->count - 1;
    if (n > r->polygon_capacity) {
        int bigger = n < 16 ? 16 : n;
        int *polygon = realloc(r->polygon, (size_t)bigger * sizeof *polygon);
        if (polygon != NULL)
            r->polygon = polygon;
        int *order = realloc(r->order, (size_t)bigger * sizeof *order);
        if (order != NULL)
            r->order = order;
        double *plane = realloc(r->plane, (size_t)bigger * 2 * sizeof *plane);
        if (plane != NULL)
            r->plane = plane;
        if (polygon == NULL || order == NULL || plane == NULL)
            return out_of_memory(r);
        r->polygon_capacity = bigger;
    }
    for (int i = 0; i < n; i++) {
        rt_status status = face_vertex(r, &x->tokens[i + 1], &r->polygon[i]);
        if (status != RT_OK)
            return status;
    }
    if (n < 3) {
        int line, column;
        after_last(x, &line, &column);
        return rt__error_set(r->error, RT_ERR_SYNTAX, r->name, line, column,
                             "expected at least 3 vertices for the face, "
                             "found %d", n);
    }
    if (n == 3)
        return add_facet(r, r->polygon[0], r->polygon[1], r->polygon[2],
                         keyword->line);
    /* A corner repeated next to itself bounds nothing. */
    int m = 0;
    for (int i = 0; i < n; i++)
        if (m == 0 || r->polygon[i] != r->polygon[m - 1])
            r->polygon[m++] = r->polygon[i];
    while (m > 1 && r->polygon[m - 1] == r->polygon[0])
        m--;
    if (m < 3) {
        if (r->dropped++ == 0) {
            r->dropped_line = keyword->line;
            r->dropped_column = keyword->column;
        }
        return RT_OK;
    }
    if (m == 3)
        return add_facet(r, r->polygon[0], r->polygon[1], r->polygon[2],
                         keyword->line);
    return triangulate(r, m, keyword);
}

/* ---------------------------------------------------------------- the view */

#define PI 3.14159265358979323846

/* The i-th vertex the camera frames: those of the facets, or all vertices
 * when there is no facet. */
static rt_vec3 framed(const reader *r, int i)
{
    return r->vertices[r->facet_count > 0 ? r->facets[i / 3].vertex[i % 3]
                                          : i];
}

/*
 * The automatic camera and light (docs/formats.md): seen from the
 * direction (0.5, 0.5, 1), at the nearest distance where every vertex
 * drawn (every vertex when no face is drawn) is inside the image with a
 * 5% margin, the picture centred; a white light above and to the left of
 * the camera.
 */
static rt_status auto_view(reader *r, const rt_load_options *o,
                           rt_scene_desc *d)
{
    d->width = o->width > 0 ? o->width : o->height > 0 ? o->height
                                                       : DEFAULT_SIDE;
    d->height = o->height > 0 ? o->height : d->width;
    if (d->width > RT_MAX_IMAGE_SIDE || d->height > RT_MAX_IMAGE_SIDE ||
        o->width < 0 || o->height < 0)
        return rt__error_set(r->error, RT_ERR_RANGE, r->name, 0, 0,
                             "expected an image size in 1..%d, found %dx%d",
                             RT_MAX_IMAGE_SIDE, o->width, o->height);
    int n = r->facet_count > 0 ? 3 * r->facet_count : r->vertex_count;
    rt_vec3 lo = n > 0 ? framed(r, 0) : v3(0, 0, 0), hi = lo;
    for (int i = 1; i < n; i++) {
        rt_vec3 p = framed(r, i);
        lo = v3(fmin(lo.x, p.x), fmin(lo.y, p.y), fmin(lo.z, p.z));
        hi = v3(fmax(hi.x, p.x), fmax(hi.y, p.y), fmax(hi.z, p.z));
    }
    rt_vec3 center = v3_add(v3_scale(lo, 0.5), v3_scale(hi, 0.5));
    double radius = v3_length(v3_sub(v3_scale(hi, 0.5), v3_scale(lo, 0.5)));
    if (!(radius > 0.0))
        radius = fmax(1.0, v3_max_abs(center) * 1e-3);
    rt_vec3 view = v3_normalize(v3(VIEW_X, VIEW_Y, VIEW_Z));
    rt_vec3 right = v3_normalize(v3_cross(v3(0, 1, 0), view));
    rt_vec3 image_up = v3_cross(view, right);
    /* A vertex at (x, y) across the view and z towards the camera is
     * inside the image when |x| <= (D - z) tan_x and |y| <= (D - z) tan_y,
     * D the camera's distance from the point it looks at.  The first fit
     * looks at the box's centre; the second at the point that centres the
     * first picture, and its fit is again exact. */
    double half = VIEW_FOV_DEGREES * PI / 360.0;
    double tan_x = tan(half), tan_y = tan_x * d->height / d->width;
    double distance = 0.0;
    for (int pass = 0; pass < 2; pass++) {
        double low_x = 0, high_x = 0, low_y = 0, high_y = 0;
        distance = 0.05 * radius;
        for (int i = 0; i < n; i++) {
            rt_vec3 q = v3_sub(framed(r, i), center);
            double x = v3_dot(q, right), y = v3_dot(q, image_up);
            double z = v3_dot(q, view);
            distance = fmax(distance, z + 0.05 * radius);
            distance = fmax(distance, z + VIEW_MARGIN *
                                              fmax(fabs(x) / tan_x,
                                                   fabs(y) / tan_y));
        }
        for (int i = 0; i < n && pass == 0; i++) {
            rt_vec3 q = v3_sub(framed(r, i), center);
            double depth = distance - v3_dot(q, view);
            double x = v3_dot(q, right) / depth, y = v3_dot(q, image_up) / depth;
            low_x = fmin(low_x, x), high_x = fmax(high_x, x);
            low_y = fmin(low_y, y), high_y = fmax(high_y, y);
        }
        center = v3_add(center, v3_add(
            v3_scale(right, distance * (low_x + high_x) / 2),
            v3_scale(image_up, distance * (low_y + high_y) / 2)));
    }
    d->observer = v3_add(center, v3_scale(view, distance));
    d->screen_center = center;
    d->screen_right = v3_add(center, v3_scale(right, distance * tan_x));
    if (!(v3_max_abs(d->observer) <= RT_MAX_COORDINATE) ||
        !(v3_max_abs(d->screen_right) <= RT_MAX_COORDINATE))
        return rt__error_set(r->error, RT_ERR_RANGE, r->name, 0, 0,
                             "expected a model the automatic camera can "
                             "frame, found one of radius %g centred at "
                             "(%g, %g, %g): the camera would stand beyond "
                             "coordinates of 1e152 (give --look-from)",
                             radius, center.x, center.y, center.z);
    rt_vec3 toward_light = v3_normalize(v3_add(
        view, v3_add(v3_scale(right, -0.5), v3_scale(image_up, 1.0))));
    d->light_position = v3_add(center,
                               v3_scale(toward_light, 2.0 * distance));
    d->light_color = (rt_rgb8){255, 255, 255};
    d->background = (rt_rgb8){32, 32, 32};
    return RT_OK;
}

/* ---------------------------------------------------------------- reading */

static rt_status statement(reader *r)
{
    lexer *x = &r->lex;
    const token *k = &x->tokens[0];
    if (token_is(k, "v"))
        return vertex(r);
    if (token_is(k, "f") || token_is(k, "fo"))
        return face(r);
    if (token_is(k, "vt"))
        return attribute(r, &r->texture_count, 1, 3);
    if (token_is(k, "vn")) {
        if (r->normal_count == 0)
            warn(r, r->name, k->line, k->column,
                 "vertex normals (`vn`) are ignored: facets are shaded flat "
                 "(said once)");
        return attribute(r, &r->normal_count, 3, 3);
    }
    if (token_is(k, "o") || token_is(k, "g") || token_is(k, "s"))
        return RT_OK;
    if (token_is(k, "mtllib")) {
        rt_status status = read_libraries(r);
        return status == RT_ERR_NOMEM ? out_of_memory(r) : status;
    }
    if (token_is(k, "usemtl")) {
        rt_status status = use_material(r);
        return status == RT_ERR_NOMEM ? out_of_memory(r) : status;
    }
    if (token_is(k, "l") || token_is(k, "p")) {
        warn_once(r, r->name, k,
                  "(lines and points) are ignored: only faces are drawn");
        return RT_OK;
    }
    warn_once(r, r->name, k, "are not understood and are ignored");
    return RT_OK;
}

static rt_status read_obj(reader *r, const rt_load_options *options,
                          rt_scene **scene)
{
    rt_status status = RT_OK;
    int more;
    while (status == RT_OK && (more = next_statement(&r->lex)) != 0)
        status = more < 0 ? out_of_memory(r) : statement(r);
    if (status != RT_OK)
        return status;
    if (r->fanned > 0)
        warn(r, r->name, r->fanned_line, r->fanned_column,
             "this polygon crosses itself, has no area or has more than %d "
             "corners: it is triangulated as a fan from its first corner, "
             "which may cover what it does not (%d polygon%s in all)",
             MAX_EAR_CLIPPED, r->fanned, r->fanned == 1 ? "" : "s");
    if (r->dropped > 0)
        warn(r, r->name, r->dropped_line, r->dropped_column,
             "this face has fewer than 3 distinct corners and is left out "
             "(%d face%s in all)", r->dropped, r->dropped == 1 ? "" : "s");
    if (r->facet_count == 0)
        warn(r, r->name, 0, 0,
             "the file has no face to draw: the picture is the background");
    if (r->notes.failed)
        return out_of_memory(r);
    rt_scene_desc d;
    memset(&d, 0, sizeof d);
    status = auto_view(r, options, &d);
    if (status != RT_OK)
        return status;
    d.vertices = r->vertices;
    d.vertex_count = r->vertex_count;
    d.facets = r->facets;
    d.facet_count = r->facet_count;
    return rt__reader_finish(&d, r->name, r->facet_lines, &r->notes, options,
                             scene, r->error);
}

rt_status rt__obj_parse(const char *text, size_t length, const char *name,
                        const rt_load_options *options, rt_scene **scene,
                        rt_error *error)
{
    if (scene == NULL)
        return RT_ERR_ARGUMENT;
    *scene = NULL;
    const char *shown_name = name ? name : "<memory>";
    if (text == NULL && length > 0)
        return rt__error_set(error, RT_ERR_ARGUMENT, shown_name, 0, 0,
                             "expected scene text");
    if (text == NULL)
        text = "";
    rt_status status = rt__text_check(text, length, shown_name, error);
    if (status != RT_OK)
        return status;
    rt_load_options defaults;
    if (options == NULL) {
        rt_load_options_init(&defaults);
        options = &defaults;
    }
    reader r;
    memset(&r, 0, sizeof r);
    r.name = shown_name;
    r.path = name;
    r.error = error;
    r.current = -1;
    r.lex.at = text;
    r.lex.end = text + length;
    r.lex.line = 1;
    if (length >= 3 && memcmp(text, "\xEF\xBB\xBF", 3) == 0)
        r.lex.at += 3;      /* a UTF-8 byte-order mark: not a column */
    r.c_locale = newlocale(LC_ALL_MASK, "C", (locale_t)0);
    if (r.c_locale == (locale_t)0)
        return rt__error_set(error, RT_ERR_NOMEM, shown_name, 0, 0,
                             "cannot create the C locale");
    status = read_obj(&r, options, scene);
    freelocale(r.c_locale);
    free(r.materials);
    name_table_free(&r.material_names);
    name_table_free(&r.libraries);
    free(r.lex.tokens);
    free(r.vertices);
    free(r.facets);
    free(r.facet_lines);
    free(r.polygon);
    free(r.order);
    free(r.plane);
    rt__notes_free(&r.notes);
    return status;
}
