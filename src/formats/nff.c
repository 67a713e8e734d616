/*
 * nff.c - Eric Haines' Neutral File Format (the NFF.TXT of his Standard
 * Procedural Databases), read from memory into an rt_scene_desc and handed
 * to the scene builder: the stream of values, the view and the lights,
 * and the description at the end (nff.h; the entities that make facets are
 * nff_shapes.c's, the cut of spheres and cones nff_cut.c's).  What each
 * entity becomes is in docs/formats.md.
 *
 * NFF is a stream of white-space separated values (the SPD generators put
 * a cone's eight values on one line or on two), so the reader goes token by
 * token through the lexer (lexer.h), knows the line and column of each, and
 * stops at the first broken rule with "name:line:column: expected ...,
 * found `token`".  It counts the tokens of the file first, so a polygon's
 * vertex count is checked against the values left before anything is
 * allocated for it.  The points it computes with before the build (the
 * view, polygons, centres and radii) it checks itself, in the builder's
 * words; the number of lights is the builder's to judge (locate() names
 * the `l` it refuses).  The load's cancellation flag is polled every
 * RT_LOAD_POLL entities, vertices and primitives.
 */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/vecmath.h"
#include "formats/framing.h"
#include "formats/nff.h"

/* Non-zero when the load is cancelled, looked at on the first item and
 * every RT_LOAD_POLL items after it. */
int rt__nff_poll_cancel(parser *p)
{
    return p->polls++ % RT_LOAD_POLL == 0 && rt__load_cancelled(p->options);
}

/* The next token; 0 at the end of the input. */
static int next_token(parser *p, token *t)
{
    return rt__lex_next(&p->lex, t);
}

/* The tokens of the file not read yet. */
long rt__nff_tokens_left(const parser *p)
{
    return p->token_count - p->lex.tokens;
}

rt_status rt__nff_fail(parser *p, rt_status status, const token *t,
                       const char *expected)
{
    return rt__token_refuse(p->error, status, p->name, t, "%s", expected);
}

/* The size of the file in bytes. */
size_t rt__nff_file_bytes(const parser *p)
{
    return (size_t)(p->lex.end - p->lex.start);
}

static rt_status unexpected_end(parser *p, const char *expected)
{
    int line, column;
    rt__lex_end(&p->lex, &line, &column);
    return rt__error_set(p->error, RT_ERR_SYNTAX, p->name, line, column,
                         "unexpected end of file: expected %s", expected);
}

static rt_status expect_token(parser *p, token *t, const char *expected)
{
    if (!next_token(p, t))
        return unexpected_end(p, expected);
    return RT_OK;
}

static int is_word(const token *t, const char *word)
{
    return rt__token_is(t, word);
}

/* What a number is for in a message: `what`, and with `axis` (x, y or
 * z; 0 for none) "what (axis)".  Made only for a message: a file of
 * millions of numbers formats none. */
static const char *number_for(const char *what, char axis, char out[128])
{
    if (axis == 0)
        return what;
    snprintf(out, 128, "%s (%c)", what, axis);
    return out;
}

/* A token as a finite number; `what` and `axis` name it ("the sphere's
 * radius"). */
static rt_status to_number(parser *p, const token *t, const char *what,
                           char axis, double *value)
{
    rt_status status = rt__lex_number(&p->lex, t, value);
    if (status == RT_OK || status == RT_ERR_LIMIT)
        return status == RT_OK
                   ? RT_OK
                   : rt__nff_fail(p, status, t, rt__number_expected(status));
    char expected[160], part[128];
    snprintf(expected, sizeof expected, "%s for %s",
             rt__number_expected(status), number_for(what, axis, part));
    return rt__nff_fail(p, status, t, expected);
}

/* The next token as a number for `what` (and `axis`), at *where when
 * `where` is not NULL. */
static rt_status next_number(parser *p, const char *what, char axis,
                             double *value, token *where)
{
    token t;
    if (!next_token(p, &t)) {
        char expected[160], part[128];
        snprintf(expected, sizeof expected, "a number for %s",
                 number_for(what, axis, part));
        return unexpected_end(p, expected);
    }
    if (where != NULL)
        *where = t;
    return to_number(p, &t, what, axis, value);
}

rt_status rt__nff_number(parser *p, const char *what, double *value,
                         token *where)
{
    return next_number(p, what, 0, value, where);
}

rt_status rt__nff_integer(parser *p, const char *what, long min, long max,
                          int *value, token *where)
{
    double v;
    token t;
    rt_status status = rt__nff_number(p, what, &v, &t);
    if (status != RT_OK)
        return status;
    if (where != NULL)
        *where = t;
    if (v != floor(v) || v < (double)min || v > (double)max) {
        char expected[160];
        snprintf(expected, sizeof expected, "%s (a whole number in %ld..%ld)",
                 what, min, max);
        return rt__nff_fail(p, v != floor(v) ? RT_ERR_SYNTAX : RT_ERR_RANGE,
                            &t, expected);
    }
    *value = (int)v;
    return RT_OK;
}

/* Three numbers; `bounded`: each within RT_MAX_COORDINATE. */
rt_status rt__nff_triple(parser *p, const char *what, int bounded,
                         rt_vec3 *out, token *where)
{
    double c[3];
    static const char axis[] = "xyz";
    for (int i = 0; i < 3; i++) {
        token t;
        rt_status status = next_number(p, what, axis[i], &c[i], &t);
        if (status != RT_OK)
            return status;
        if (i == 0 && where != NULL)
            *where = t;
        if (bounded && fabs(c[i]) > RT_MAX_COORDINATE)
            return rt__nff_fail(p, RT_ERR_RANGE, &t, RT_RULE_COORDINATE);
    }
    *out = v3(c[0], c[1], c[2]);
    return RT_OK;
}

void rt__nff_warn_once(parser *p, int kind, const token *at, const char *text)
{
    if (p->once[kind])
        return;
    p->once[kind] = 1;
    rt__notes_add(&p->notes, p->name, at->line, at->column, "%s", text);
}

/* A colour component of NFF (0..1) as a byte, rounded; outside [0, 1]
 * clamped with a warning. */
static unsigned char channel(parser *p, double v, const token *at)
{
    if (v < 0 || v > 1) {
        rt__nff_warn_once(
            p, ONCE_COLOR, at,
            "colour components outside [0, 1] are clamped to it (the "
            "first is here)");
        v = v < 0 ? 0 : 1;
    }
    return (unsigned char)floor(v * 255.0 + 0.5);
}

rt_status rt__nff_color(parser *p, const char *what, rt_rgb8 *out)
{
    rt_vec3 c;
    token t;
    rt_status status = rt__nff_triple(p, what, 0, &c, &t);
    if (status != RT_OK)
        return status;
    out->r = channel(p, c.x, &t);
    out->g = channel(p, c.y, &t);
    out->b = channel(p, c.z, &t);
    return RT_OK;
}

int rt__nff_grow(void **array, int *capacity, int count, size_t size)
{
    if (count < *capacity)
        return 0;
    if (*capacity > INT_MAX / 2)
        return -1;
    int bigger = *capacity ? 2 * *capacity : 16;
    void *grown = realloc(*array, (size_t)bigger * size);
    if (grown == NULL)
        return -1;
    *array = grown;
    *capacity = bigger;
    return 0;
}

rt_status rt__nff_out_of_memory(parser *p)
{
    return rt__error_set(p->error, RT_ERR_NOMEM, p->name, 0, 0,
                         "out of memory");
}

static rt_status keyword(parser *p, const char *word)
{
    token t;
    char expected[64];
    snprintf(expected, sizeof expected, "`%s`", word);
    rt_status status = expect_token(p, &t, expected);
    if (status == RT_OK && !is_word(&t, word))
        status = rt__nff_fail(p, RT_ERR_SYNTAX, &t, expected);
    return status;
}

/* v from .. at .. up .. angle .. hither .. resolution .. */
static rt_status view(parser *p, const token *v)
{
    rt_status status;
    token from_t, at_t, up_t, angle_t, t;
    double hither;
    if (p->has_view)
        rt__nff_warn_once(p, ONCE_VIEW, v,
                          "a second viewpoint `v` replaces the first");
    if ((status = keyword(p, "from")) != RT_OK ||
        (status = rt__nff_triple(p, "`from`", 1, &p->from, &from_t)) !=
            RT_OK ||
        (status = keyword(p, "at")) != RT_OK ||
        (status = rt__nff_triple(p, "`at`", 1, &p->at_point, &at_t)) !=
            RT_OK ||
        (status = keyword(p, "up")) != RT_OK ||
        (status = rt__nff_triple(p, "`up`", 0, &p->up, &up_t)) != RT_OK ||
        (status = keyword(p, "angle")) != RT_OK ||
        (status = rt__nff_number(p, "`angle`", &p->angle, &angle_t)) != RT_OK)
        return status;
    /* hither came with NFF 2.7: older files go on with the resolution */
    if ((status = expect_token(p, &t, "`hither` or `resolution`")) != RT_OK)
        return status;
    if (is_word(&t, "hither")) {
        if ((status = rt__nff_number(p, "`hither`", &hither, &t)) != RT_OK)
            return status;
        rt__nff_warn_once(
            p, ONCE_HITHER, &t,
            "`hither` has no place in the rendering model (it sees "
            "from the eye on): ignored");
        status = keyword(p, "resolution");
    } else if (!is_word(&t, "resolution")) {
        status =
            rt__nff_fail(p, RT_ERR_SYNTAX, &t, "`hither` or `resolution`");
    }
    if (status != RT_OK ||
        (status = rt__nff_integer(p, "the image width", 1, RT_MAX_IMAGE_SIDE,
                                  &p->width, &t)) != RT_OK ||
        (status = rt__nff_integer(p, "the image height", 1, RT_MAX_IMAGE_SIDE,
                                  &p->height, NULL)) != RT_OK)
        return status;
    if (p->width != p->height)
        rt__nff_warn_once(
            p, ONCE_ASPECT, &t,
            "the resolution is not square: the angle is taken "
            "horizontally (pixels stay square, so the vertical angle "
            "is smaller or larger than NFF's)");
    /* NFF's angle spans the centres of the first and last columns. */
    rt_view frame = {p->from, p->at_point, p->up, p->angle, p->width, 1};
    switch (rt__frame_view(&frame, &p->observer, &p->screen_center,
                           &p->screen_right)) {
    case RT_FRAME_FOV:
        return rt__nff_fail(p, RT_ERR_RANGE, &angle_t,
                            "an angle in (0, 180) degrees");
    case RT_FRAME_SAME_POINT:
        return rt__nff_fail(p, RT_ERR_CAMERA, &at_t,
                            "`at` apart from `from` (a direction to look in)");
    case RT_FRAME_UP_ALONG_VIEW:
        return rt__nff_fail(
            p, RT_ERR_CAMERA, &up_t,
            "an `up` vector not along the view (from `from` to "
            "`at`)");
    case RT_FRAME_OK:
        break;
    }
    p->has_view = 1;
    return RT_OK;
}

/* l x y z [r g b]: the colour only on the same line. */
static rt_status light(parser *p, const token *l)
{
    if (rt__nff_grow((void **)&p->lights, &p->light_capacity, p->light_count,
                     sizeof *p->lights) != 0)
        return rt__nff_out_of_memory(p);
    nff_light *light = &p->lights[p->light_count];
    memset(light, 0, sizeof *light);
    light->at = *l;
    rt_status status =
        rt__nff_triple(p, "the light's position", 0, &light->position, NULL);
    if (status != RT_OK)
        return status;
    /* (a token on the line of `l` follows the position on that line) */
    token t;
    if (rt__lex_peek(&p->lex, &t) && t.line == l->line &&
        rt__number_syntax(t.text, t.length)) {
        if ((status = rt__nff_color(p, "the light's colour", &light->color)) !=
            RT_OK)
            return status;
        light->colored = 1;
    }
    p->light_count++;
    return RT_OK;
}

/* The description's arrays, freed once the scene's records are made
 * (rt_reading.release). */
static void release_mesh(void *user)
{
    rt__tess_mesh_free(user);
}

/* The token a refusal of the builder names (rt_locate_func): NFF's
 * lights are its own; the points it computes with (the view, polygons,
 * centres) it checks itself. */
static int locate(void *user, const rt_refusal *r, token *at)
{
    const parser *p = user;
    if (r->item != RT_ITEM_LIGHT || r->index >= p->light_count)
        return 0;
    *at = p->lights[r->index].at;
    return 1;
}

static rt_status parse(parser *p, const rt_load_options *options,
                       rt_scene **scene)
{
    rt_status status = RT_OK;
    token t;
    while (status == RT_OK && next_token(p, &t)) {
        if (rt__nff_poll_cancel(p))
            return rt__load_cancel(p->error, p->name);
        if (is_word(&t, "v"))
            status = view(p, &t);
        else if (is_word(&t, "b"))
            status = rt__nff_color(p, "the background colour", &p->background);
        else if (is_word(&t, "l"))
            status = light(p, &t);
        else if (is_word(&t, "f"))
            status = rt__nff_material(p, &t);
        else if (is_word(&t, "s"))
            status = rt__nff_sphere(p, &t);
        else if (is_word(&t, "c"))
            status = rt__nff_cone(p, &t);
        else if (is_word(&t, "p"))
            status = rt__nff_polygon(p, &t, 0);
        else if (is_word(&t, "pp"))
            status = rt__nff_polygon(p, &t, 1);
        else
            status = rt__nff_fail(p, RT_ERR_SYNTAX, &t,
                                  "an entity (v, b, l, f, c, s, p or pp)");
    }
    if (status != RT_OK)
        return status;
    if (!p->has_view) {
        int line, column;
        rt__lex_end(&p->lex, &line, &column);
        return rt__error_set(p->error, RT_ERR_CAMERA, p->name, line, column,
                             "expected a viewpoint `v` (from, at, up, angle, "
                             "hither, resolution), found none in the file");
    }
    if ((status = rt__nff_tessellate(p, options->tessellation)) != RT_OK)
        return status;

    rt_scene_desc d;
    memset(&d, 0, sizeof d);
    d.observer = p->observer;
    d.screen_center = p->screen_center;
    d.screen_right = p->screen_right;
    d.width = p->width;
    d.height = p->height;
    d.background = p->background;
    d.vertices = p->mesh.vertices;
    d.normals = p->mesh.normals;
    d.vertex_count = p->mesh.vertex_count;
    d.facets = p->mesh.facets;
    d.facet_count = p->mesh.facet_count;

    rt_light *lights = NULL;
    rt_light eye_light = {p->from, {255, 255, 255}};
    int light_count = p->light_count;
    if (light_count == 0) {
        rt__notes_add(&p->notes, p->name, 0, 0,
                      "no light `l` in the file: a white light at the eye "
                      "(`from`)");
        d.lights = &eye_light;
        d.light_count = 1;
    } else {
        /* Lights without a colour share a total of about one white light:
         * 1/sqrt(count) each. */
        unsigned char grey =
            (unsigned char)floor(255.0 / sqrt((double)light_count) + 0.5);
        lights = malloc((size_t)light_count * sizeof *lights);
        if (lights == NULL)
            return rt__nff_out_of_memory(p);
        for (int i = 0; i < light_count; i++) {
            lights[i].position = p->lights[i].position;
            lights[i].color = p->lights[i].colored
                                  ? p->lights[i].color
                                  : (rt_rgb8){grey, grey, grey};
        }
        d.lights = lights;
        d.light_count = light_count;
    }
    if (p->notes.failed)
        status = rt__nff_out_of_memory(p);
    else if (rt__load_cancelled(options))
        status = rt__load_cancel(p->error, p->name);
    else {
        rt_reading reading = {p->name,      p->mesh.facet_lines,
                              &p->notes,    options,
                              locate,       p,
                              release_mesh, &p->mesh};
        status = rt__reader_finish(&d, &reading, scene, p->error);
    }
    free(lights);
    return status;
}

rt_status rt__nff_parse(const char *text, size_t length, const char *name,
                        const rt_load_options *options, rt_scene **scene,
                        rt_error *error)
{
    const char *shown = name ? name : "<memory>";
    parser p;
    memset(&p, 0, sizeof p);
    p.name = shown;
    p.error = error;
    p.options = options;
    rt_status status = rt__lex_open(&p.lex, text, length, shown, 0, error);
    if (status != RT_OK)
        return status;
    p.token_count = rt__lex_count(&p.lex, 0, options->cancel);
    if (p.token_count < 0) {
        rt__lex_close(&p.lex);
        return rt__load_cancel(error, shown);
    }
    status = parse(&p, options, scene);
    rt__lex_close(&p.lex);
    rt__notes_free(&p.notes);
    free(p.lights);
    free(p.materials);
    free(p.primitives);
    free(p.points);
    rt__tess_mesh_free(&p.mesh);
    return status;
}
