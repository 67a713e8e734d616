/*
 * mtl.c - an OBJ's materials (obj.h): `mtllib` reads material libraries
 * (.mtl) through the load's list of files (resolve.h), `usemtl` picks a
 * material for the facets that follow, and at the end of the file the
 * facets whose material was named before a library defined it get it (as
 * Blender and MeshLab do).  The mapping from MTL to the rendering model:
 * docs/formats.md, section OBJ, "Materials".
 *
 * A library is untrusted twice over: it may not be a library at all.
 * Nothing it holds before its first `newmtl` is quoted (one counted
 * remark instead), a file with no `newmtl` gets one message, and every
 * remark that could repeat per statement is counted and said once.  A
 * material name costs its bytes (names.h), an unknown one a number and a
 * range of facets, whatever the number of names.
 */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "formats/obj.h"

/* What a `newmtl` block says, while it is read. */
typedef struct mtl_state {
    double kd[3], ks[3];
    int illum;
    double dissolve, tr, ni, ns;
    int has_d, has_tr;
    int material;               /* its index in r->materials; -1: none */
    int line;                   /* of its `newmtl` */
    token name;
} mtl_state;

static void mtl_defaults(mtl_state *m)
{
    m->kd[0] = m->kd[1] = m->kd[2] = DEFAULT_GREY / 255.0;
    m->ks[0] = m->ks[1] = m->ks[2] = 0.0;
    m->illum = 2;
    m->dissolve = 1.0;
    m->tr = 0.0;
    m->ni = 1.0;
    m->ns = 0.0;
    m->has_d = m->has_tr = 0;
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

/* The illumination models with a highlight: 2 "highlight on" and every
 * model above it (whose formulas in the MTL specification all have the
 * Ks highlight term); 0 and 1 have none. */
static int highlight_model(int illum)
{
    return illum >= 2;
}

/* The facet the block gives its material (docs/formats.md): colour Kd,
 * k = max(Ks) for a mirror model, t = 1 - d (or Tr), n = Ni, d = 1 - k - t,
 * and for a model with a highlight s = max(Ks), p = max(1, Ns). */
static void finish_block(reader *r, const char *library, mtl_state *m)
{
    if (m->material < 0)
        return;
    rt_facet_desc *f = &r->materials[m->material].look;
    memset(f, 0, sizeof *f);
    f->color = (rt_rgb8){to_byte(m->kd[0]), to_byte(m->kd[1]),
                         to_byte(m->kd[2])};
    if (mirror_model(m->illum))
        f->reflection = clamp01(fmax(m->ks[0], fmax(m->ks[1], m->ks[2])));
    f->transparency = m->has_d    ? 1.0 - clamp01(m->dissolve)
                      : m->has_tr ? clamp01(m->tr)
                                  : 0.0;
    if (f->reflection + f->transparency > 1.0) {
        char buffer[RT_TOKEN_SHOWN_SIZE];
        rt__obj_count(&r->lowered, library, m->line, 1,
                      "material `%s`: mirror reflection %g and transparency "
                      "%g add up to more than 1; the reflection is lowered "
                      "to %g", rt__token_shown(&m->name, buffer),
                      f->reflection, f->transparency, 1.0 - f->transparency);
        f->reflection = 1.0 - f->transparency;
    }
    f->refractive_index = m->ni;
    if (highlight_model(m->illum)) {
        f->highlight = fmax(0.0, fmax(m->ks[0], fmax(m->ks[1], m->ks[2])));
        f->highlight_exponent = fmax(1.0, m->ns);
    }
    m->material = -1;
}

/* The number of `name` among the material names, with room for what it
 * is defined as (-1 when new); -1 when out of memory. */
static int name_id(reader *r, const char *name, size_t length)
{
    int id = rt__names_put(&r->names, name, length, NULL);
    if (id < 0)
        return -1;
    if (id >= r->defined_capacity) {
        int bigger = r->defined_capacity ? 2 * r->defined_capacity : 16;
        int *grown = realloc(r->defined, (size_t)bigger * sizeof *grown);
        if (grown == NULL)
            return -1;
        for (int i = r->defined_capacity; i < bigger; i++)
            grown[i] = -1;
        r->defined = grown;
        r->defined_capacity = bigger;
    }
    return id;
}

/* A new material under `name` (a later definition of a name replaces the
 * earlier one for the facets that follow); its index or -1 (out of
 * memory). */
static int material_add(reader *r, const char *name, size_t length)
{
    int id = name_id(r, name, length);
    if (id < 0 || rt__obj_grow((void **)&r->materials, &r->material_capacity,
                               r->material_count, sizeof *r->materials,
                               8) <= 0)
        return -1;
    r->defined[id] = r->material_count;
    return r->material_count++;
}

/* Up to three numbers of a colour statement (one gives a grey). */
static int mtl_color(reader *r, const lexer *x, const char *library,
                     double out[3])
{
    char buffer[RT_TOKEN_SHOWN_SIZE];
    const token *k = &x->tokens[0];
    if (x->total != 2 && x->total != 4) {
        rt__obj_count(&r->bad_values, library, k->line, k->column,
                      "`%s` with %ld values ignored: only `r g b` or one "
                      "grey value are read", rt__token_shown(k, buffer),
                      x->total - 1);
        return 0;
    }
    double v[3];
    for (int i = 1; i < x->count; i++)
        if (rt__obj_number(x, &x->tokens[i], &v[i - 1]) != RT_OK) {
            rt__obj_count(&r->bad_values, library, x->tokens[i].line,
                          x->tokens[i].column,
                          "expected a number, found `%s`; the statement is "
                          "ignored", rt__token_shown(&x->tokens[i], buffer));
            return 0;
        }
    for (int i = 0; i < 3; i++)
        out[i] = x->total == 2 ? v[0] : v[i];
    return 1;
}

/* The one number of a statement: its last token (`d -halo x`). */
static int mtl_value(reader *r, const lexer *x, const char *library,
                     double *out)
{
    char keyword[RT_TOKEN_SHOWN_SIZE], found[RT_TOKEN_SHOWN_SIZE];
    const token *k = &x->tokens[0], *t = &x->last;
    if (x->total < 2) {
        rt__obj_count(&r->bad_values, library, k->line, k->column,
                      "expected a number after `%s`; the statement is "
                      "ignored", rt__token_shown(k, keyword));
        return 0;
    }
    if (rt__obj_number(x, t, out) != RT_OK) {
        rt__obj_count(&r->bad_values, library, t->line, t->column,
                      "expected a number after `%s`, found `%s`; the "
                      "statement is ignored", rt__token_shown(k, keyword),
                      rt__token_shown(t, found));
        return 0;
    }
    return 1;
}

/* Statements of an MTL file that have no place in the model (silent). */
static int mtl_ignored(const token *k)
{
    static const char *const words[] = {
        "Ka", "Ke", "Tf", "sharpness", "bump", "disp", "decal",
        "refl", "norm", "Pr", "Pm", "Ps", "Pc", "Pcr", "aniso", "anisor"};
    for (size_t i = 0; i < sizeof words / sizeof words[0]; i++)
        if (rt__token_is(k, words[i]))
            return 1;
    return k->length > 4 && memcmp(k->text, "map_", 4) == 0;
}

/* One statement inside a `newmtl` block. */
static rt_status mtl_statement(reader *r, lexer *x, const char *library,
                               mtl_state *m)
{
    const token *k = &x->tokens[0];
    double v[3];
    int colour = rt__token_is(k, "Kd") || rt__token_is(k, "Ks");
    if (colour || rt__token_is(k, "illum") || rt__token_is(k, "d") ||
        rt__token_is(k, "Tr") || rt__token_is(k, "Ni") ||
        rt__token_is(k, "Ns")) {
        if (rt__obj_rest(x, colour ? 4 : 0) != 0)
            return RT_ERR_NOMEM;
        k = &x->tokens[0];
    }
    if (rt__token_is(k, "Kd")) {
        if (mtl_color(r, x, library, v))
            memcpy(m->kd, v, sizeof v);
    } else if (rt__token_is(k, "Ks")) {
        if (mtl_color(r, x, library, v))
            memcpy(m->ks, v, sizeof v);
    } else if (rt__token_is(k, "illum")) {
        if (mtl_value(r, x, library, v) && v[0] == floor(v[0]) &&
            fabs(v[0]) < 100)
            m->illum = (int)v[0];
    } else if (rt__token_is(k, "d")) {
        if (mtl_value(r, x, library, v)) {
            m->dissolve = v[0];
            m->has_d = 1;
        }
    } else if (rt__token_is(k, "Tr")) {
        if (mtl_value(r, x, library, v)) {
            m->tr = v[0];
            m->has_tr = 1;
        }
    } else if (rt__token_is(k, "Ni")) {
        if (mtl_value(r, x, library, v)) {
            if (v[0] > 0.0)
                m->ni = v[0];
            else
                rt__obj_count(&r->bad_values, library, x->last.line,
                              x->last.column,
                              "expected a refractive index Ni > 0, found %g; "
                              "1 is used", v[0]);
        }
    } else if (rt__token_is(k, "Ns")) {
        if (mtl_value(r, x, library, v))
            m->ns = v[0];
    } else if (rt__token_is(k, "map_Kd")) {
        rt__obj_warn_once(r, library, k,
                          "are ignored: textures are not drawn, the colour "
                          "is Kd");
    } else if (!mtl_ignored(k)) {
        rt__obj_warn_once(r, library, k,
                          "are not understood and are ignored");
    }
    return RT_OK;
}

/* Parses a material library's statements (x, opened); its problems are
 * warnings.  What comes before its first `newmtl` is counted, never
 * quoted. */
static rt_status mtl_parse(reader *r, lexer *x, const char *library)
{
    mtl_state m;
    memset(&m, 0, sizeof m);
    m.material = -1;
    long statements = 0, before = 0, blocks = 0;
    token first = {NULL, 0, 0, 0};
    rt_status status = RT_OK;
    int more;
    while (status == RT_OK && (more = rt__obj_next_statement(x)) > 0) {
        statements++;
        if ((status = rt__obj_poll(r)) != RT_OK)
            break;
        if (!rt__token_is(&x->tokens[0], "newmtl")) {
            if (m.material < 0 && blocks == 0 && before++ == 0)
                first = x->tokens[0];
            if (m.material >= 0)
                status = mtl_statement(r, x, library, &m);
            continue;
        }
        finish_block(r, library, &m);
        blocks++;
        token keyword = x->tokens[0];
        if (rt__obj_rest(x, 1) != 0) {
            status = RT_ERR_NOMEM;
            break;
        }
        if (x->count < 2) {
            rt__obj_count(&r->no_name, library, keyword.line, keyword.column,
                          "expected a material name after `newmtl`; the "
                          "block is ignored");
            continue;
        }
        const char *name;
        size_t name_length;
        rt__obj_statement_name(x, &name, &name_length);
        mtl_defaults(&m);
        m.line = keyword.line;
        m.name = (token){name, name_length, x->tokens[1].line,
                         x->tokens[1].column};
        if ((m.material = material_add(r, name, name_length)) < 0)
            status = RT_ERR_NOMEM;
    }
    if (more < 0)
        status = RT_ERR_NOMEM;
    if (status == RT_OK) {
        finish_block(r, library, &m);
        if (blocks == 0 && statements > 0)
            rt__obj_warn(r, library, first.line, first.column,
                         "defines no material (it has no `newmtl`): its %ld "
                         "statements are ignored", statements);
        else if (before > 0)
            rt__obj_warn(r, library, first.line, first.column,
                         "%ld statements before the first `newmtl` are "
                         "ignored", before);
    }
    return status;
}

/* A library not read: its message (which names it), then the default. */
static void library_refused(reader *r, const token *where, const char *why)
{
    if (r->libraries_refused++ < MAX_LIBRARY_WARNINGS)
        rt__obj_warn(r, r->name, where->line, where->column,
                     "material library %s; its materials get the default "
                     "grey", why);
    else
        rt__obj_count(&r->more_refused, r->name, where->line, where->column,
                      "material library %s", why);
}

/* Opens and reads the library `reference` named at `where`.  With `quiet`
 * a refusal says nothing and leaves *read 0. */
static rt_status open_library(reader *r, const char *reference,
                              const token *where, int quiet, int *read)
{
    rt_found found;
    char *data;
    size_t length;
    const char *library;
    rt_error why;
    memset(&why, 0, sizeof why);
    *read = 0;
    rt_status status = rt__files_open(r->files, reference, &found, &data,
                                      &length, &library, &why);
    if (status == RT_ERR_NOMEM)
        return rt__obj_out_of_memory(r);
    if (status != RT_OK || found == RT_FOUND_REFUSED) {
        if (!quiet && status != RT_OK)
            library_refused(r, where, why.message);
        *read = !quiet;
        return RT_OK;
    }
    *read = 1;
    if (found == RT_FOUND_SCENE) {
        char buffer[RT_TOKEN_SHOWN_SIZE];
        token t = {reference, strlen(reference), where->line, where->column};
        rt__obj_count(&r->self_library, r->name, where->line, where->column,
                      "the material library `%s` is this OBJ file itself: "
                      "its lines are not read as materials",
                      rt__token_shown(&t, buffer));
    }
    if (found != RT_FOUND_NEW)
        return RT_OK;
    lexer x;
    status = rt__obj_lexer_open(&x, data, length, library, &why);
    if (status == RT_OK) {
        status = mtl_parse(r, &x, library);
        rt__obj_lexer_close(&x);
    } else if (status != RT_ERR_NOMEM) {
        char message[2 * RT_ERROR_MESSAGE_SIZE];
        char *shown = rt__shown_name(reference);
        snprintf(message, sizeof message, "`%s` is not read: %s",
                 shown ? shown : "?", why.message);
        free(shown);
        library_refused(r, where, message);
        status = RT_OK;
    }
    free(data);
    if (status == RT_ERR_NOMEM)
        return rt__obj_out_of_memory(r);
    return status;
}

/* A library's name from the statement's text: "\ " stands for a space.
 * Malloc'd, NUL-terminated; NULL out of memory. */
static char *unescaped(const char *text, size_t length)
{
    char *name = malloc(length + 1);
    if (name == NULL)
        return NULL;
    size_t n = 0;
    for (size_t i = 0; i < length; i++)
        if (!(text[i] == '\\' && i + 1 < length && text[i + 1] == ' '))
            name[n++] = text[i];
    name[n] = '\0';
    return name;
}

static rt_status library_at(reader *r, const token *where, int quiet,
                            int *read)
{
    char *reference = unescaped(where->text, where->length);
    if (reference == NULL)
        return rt__obj_out_of_memory(r);
    rt_status status = open_library(r, reference, where, quiet, read);
    free(reference);
    return status;
}

/* `mtllib` names one or more files, relative to the OBJ's folder: the
 * whole rest of the line when that is a file (exporters write names with
 * spaces as they are), else each name (with "\ " for a space). */
rt_status rt__obj_read_libraries(reader *r)
{
    lexer *x = &r->lex;
    if (rt__obj_rest(x, RT_RESOLVE_MAX_NAMES + 1) != 0)
        return rt__obj_out_of_memory(r);
    const token *k = &x->tokens[0];
    if (x->count < 2) {
        rt__obj_count(&r->no_library_name, r->name, k->line, k->column,
                      "`mtllib` without a file name is ignored");
        return RT_OK;
    }
    if (!rt__files_can_open(r->files)) {
        if (r->unread_warned++ == 0)
            rt__obj_warn(r, r->name, k->line, k->column,
                         "material libraries are not read: the scene was "
                         "parsed from memory without a resolver "
                         "(rt_load_options.resolve), and such a parse reads "
                         "no file; facets get the default material (said "
                         "once)");
        return RT_OK;
    }
    int read = 0;
    rt_status status = RT_OK;
    if (x->total > 2 && x->tokens[1].line == x->last.line) {
        token whole = x->tokens[1];
        rt__obj_statement_name(x, &whole.text, &whole.length);
        status = library_at(r, &whole, 1, &read);
    }
    for (int i = 1; i < x->count && status == RT_OK && !read; i++) {
        token name = x->tokens[i];
        while (name.text[name.length - 1] == '\\' && i + 1 < x->count &&
               x->tokens[i + 1].text == name.text + name.length + 1 &&
               name.text[name.length] == ' ')
            name.length += 1 + x->tokens[++i].length;
        int ignored;
        status = library_at(r, &name, 0, &ignored);
    }
    if (x->total > x->count && status == RT_OK && !read)
        rt__obj_count(&r->more_refused, r->name, x->last.line, x->last.column,
                      "material library names beyond the first %d of a "
                      "statement are not read", RT_RESOLVE_MAX_NAMES);
    return status;
}

/* Ends the range of facets waiting for a material, if one is open. */
static void close_wait(reader *r)
{
    if (r->open_wait >= 0)
        r->waits[r->open_wait].end = r->facet_count;
    r->open_wait = -1;
}

rt_status rt__obj_use_material(reader *r)
{
    lexer *x = &r->lex;
    if (rt__obj_rest(x, 1) != 0)
        return rt__obj_out_of_memory(r);
    close_wait(r);
    r->current = -1;
    const token *k = &x->tokens[0];
    if (x->count < 2) {
        rt__obj_count(&r->no_argument, r->name, k->line, k->column,
                      "`usemtl` without a name: the default material is "
                      "used");
        return RT_OK;
    }
    const char *name;
    size_t length;
    rt__obj_statement_name(x, &name, &length);
    int id = name_id(r, name, length);
    if (id < 0)
        return rt__obj_out_of_memory(r);
    if (r->defined[id] >= 0) {
        r->current = r->defined[id];
        return RT_OK;
    }
    /* No library read so far defines it: the facets that follow wait
     * for one read later, with the default material meanwhile. */
    if (rt__obj_grow((void **)&r->waits, &r->wait_capacity, r->wait_count,
                     sizeof *r->waits, 8) <= 0)
        return rt__obj_out_of_memory(r);
    r->waits[r->wait_count] = (waiting){r->facet_count, -1, id,
                                        x->tokens[1].line,
                                        x->tokens[1].column};
    r->open_wait = r->wait_count++;
    return RT_OK;
}

/* "`a`", "`a`, `b`", ... for the first names never defined. */
static void list_names(const reader *r, const int *ids, int count,
                       char *out, size_t size)
{
    size_t used = 0;
    out[0] = '\0';
    for (int i = 0; i < count && used < size; i++) {
        token t = {rt__names_text(&r->names, ids[i]),
                   rt__names_length(&r->names, ids[i]), 0, 0};
        char buffer[RT_TOKEN_SHOWN_SIZE];
        int n = snprintf(out + used, size - used, "%s`%s`",
                         i == 0 ? "" : ", ", rt__token_shown(&t, buffer));
        used += n > 0 ? (size_t)n : 0;
    }
}

rt_status rt__obj_finish_materials(reader *r)
{
    close_wait(r);
    int unknown = 0, shown[MAX_NAMES_SHOWN], line = 0, column = 0;
    for (int i = 0; i < r->wait_count; i++) {
        const waiting *w = &r->waits[i];
        int m = r->defined[w->name];
        if (m >= 0) {
            for (int f = w->first; f < w->end; f++) {
                rt_facet_desc look = r->materials[m].look;
                memcpy(look.vertex, r->facets[f].vertex, sizeof look.vertex);
                r->facets[f] = look;
            }
        } else if (m == -1) {
            r->defined[w->name] = -2;       /* counted */
            if (unknown == 0)
                line = w->line, column = w->column;
            if (unknown < MAX_NAMES_SHOWN)
                shown[unknown] = w->name;
            unknown++;
        }
    }
    if (unknown == 0)
        return RT_OK;
    char names[MAX_NAMES_SHOWN * (RT_TOKEN_SHOWN_SIZE + 4)];
    list_names(r, shown, unknown < MAX_NAMES_SHOWN ? unknown : MAX_NAMES_SHOWN,
               names, sizeof names);
    if (unknown == 1)
        rt__obj_warn(r, r->name, line, column,
                     "material %s is defined in no material library read; "
                     "its facets get the default grey", names);
    else if (unknown <= MAX_NAMES_SHOWN)
        rt__obj_warn(r, r->name, line, column,
                     "materials %s are defined in no material library read; "
                     "their facets get the default grey (the first is "
                     "named here)", names);
    else
        rt__obj_warn(r, r->name, line, column,
                     "materials %s and %d more are defined in no material "
                     "library read; their facets get the default grey (the "
                     "first is named here)", names, unknown - MAX_NAMES_SHOWN);
    return RT_OK;
}

void rt__obj_free_materials(reader *r)
{
    free(r->materials);
    free(r->defined);
    free(r->waits);
    rt__names_free(&r->names);
}
