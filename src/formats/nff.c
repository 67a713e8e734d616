/*
 * nff.c - Eric Haines' Neutral File Format (the NFF.TXT of his Standard
 * Procedural Databases), read from memory into an rt_scene_desc and handed
 * to the scene builder.  What each entity becomes is in docs/formats.md.
 *
 * NFF is a stream of white-space separated values (the SPD generators put
 * a cone's eight values on one line or on two), so the reader goes token by
 * token, knows the line and column of each, and stops at the first broken
 * rule with "name:line:column: expected ..., found `token`".  It counts the
 * tokens of the file first, so a polygon's vertex count is checked against
 * the values left before anything is allocated for it.  Spheres and cones
 * are tessellated (tessellate.c) once the whole file is read, when the view
 * that sizes their facets is known: each as finely as it looks from the eye
 * (nothing finer than a pixel, the coarsest behind the eye), all of them
 * within a budget of facets proportional to the file's size.  The load's
 * cancellation flag is polled every RT_LOAD_POLL entities, vertices and
 * primitives.
 */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "formats/framing.h"
#include "formats/lexer.h"
#include "formats/reader.h"
#include "formats/tessellate.h"
#include "scene/scene_build.h"
#include "base/vecmath.h"

/* Ear clipping is quadratic or worse: non-convex polygons are limited. */
#define MAX_NONCONVEX_VERTICES 1024
/* The default tolerance keeps a silhouette within DEFAULT_PIXELS of the
 * true one at the file's resolution and facets about DEFAULT_FACET_PIXELS
 * across, within these bounds (docs/formats.md, "Tessellation"). */
#define DEFAULT_PIXELS 0.25
#define DEFAULT_FACET_PIXELS 5.0
#define DEFAULT_TOLERANCE_MIN 5e-5
#define DEFAULT_TOLERANCE_MAX 0.05
/* The coarsest cuts: an octahedron, a three-sided prism (or pyramid). */
#define COARSEST_BANDS 2
#define COARSEST_SEGMENTS 3

typedef rt_token token;

/* One warning of each kind per file. */
enum {
    ONCE_HITHER, ONCE_SHINE, ONCE_NORMALS, ONCE_INSIDE, ONCE_COLOR,
    ONCE_KT, ONCE_MATERIAL, ONCE_IRREGULAR, ONCE_ASPECT, ONCE_VIEW,
    ONCE_COUNT
};

/* A sphere (apex unused) or cone, tessellated at the end. */
typedef struct primitive {
    int cone;
    rt_vec3 base, apex;
    double r0, r1;          /* >= 0 */
    int inward;
    int material;           /* index into the materials */
    int line, column;
} primitive;

typedef struct nff_light {
    rt_vec3 position;
    rt_rgb8 color;
    int colored;
    token at;               /* its `l`, for the builder's refusals */
} nff_light;

typedef struct parser {
    rt_lexer lex;           /* NFF is a stream of tokens */
    const char *name;
    const rt_load_options *options;
    long polls;             /* items handled, for the cancellation poll */
    long token_count;       /* the tokens of the file */
    rt_error *error;
    rt_notes notes;
    int once[ONCE_COUNT];
    /* what the file says */
    int has_view;
    rt_vec3 from, at_point, up;
    double angle;
    rt_vec3 observer, screen_center, screen_right;  /* its frame */
    int width, height;
    rt_rgb8 background;
    nff_light *lights;
    int light_count, light_capacity;
    rt_facet_desc *materials;
    int material_count, material_capacity;
    primitive *primitives;
    int primitive_count, primitive_capacity;
    rt_vec3 *points;        /* a polygon's vertices */
    int point_capacity;
    rt_tess_mesh mesh;
} parser;

/* Non-zero when the load is cancelled, looked at on the first item and
 * every RT_LOAD_POLL items after it. */
static int poll_cancel(parser *p)
{
    return p->polls++ % RT_LOAD_POLL == 0 && rt__load_cancelled(p->options);
}

/* The next token; 0 at the end of the input. */
static int next_token(parser *p, token *t)
{
    return rt__lex_next(&p->lex, t);
}

/* The tokens of the file not read yet. */
static long tokens_left(const parser *p)
{
    return p->token_count - p->lex.tokens;
}

static rt_status fail(parser *p, rt_status status, const token *t,
                      const char *expected)
{
    return rt__token_refuse(p->error, status, p->name, t, "%s", expected);
}

/* The size of the file in bytes. */
static size_t file_bytes(const parser *p)
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

/* A token as a finite number; `what` names it ("the sphere's radius"). */
static rt_status to_number(parser *p, const token *t, const char *what,
                           double *value)
{
    rt_status status = rt__lex_number(&p->lex, t, value);
    if (status == RT_OK || status == RT_ERR_LIMIT)
        return status == RT_OK ? RT_OK
                               : fail(p, status, t,
                                      rt__number_expected(status));
    char expected[160];
    snprintf(expected, sizeof expected, "%s for %s",
             rt__number_expected(status), what);
    return fail(p, status, t, expected);
}

static rt_status number(parser *p, const char *what, double *value,
                        token *where)
{
    token t;
    char expected[160];
    snprintf(expected, sizeof expected, "a number for %s", what);
    rt_status status = expect_token(p, &t, expected);
    if (status != RT_OK)
        return status;
    if (where != NULL)
        *where = t;
    return to_number(p, &t, what, value);
}

static rt_status integer(parser *p, const char *what, long min, long max,
                         int *value, token *where)
{
    double v;
    token t;
    rt_status status = number(p, what, &v, &t);
    if (status != RT_OK)
        return status;
    if (where != NULL)
        *where = t;
    if (v != floor(v) || v < (double)min || v > (double)max) {
        char expected[160];
        snprintf(expected, sizeof expected, "%s (a whole number in %ld..%ld)",
                 what, min, max);
        return fail(p, v != floor(v) ? RT_ERR_SYNTAX : RT_ERR_RANGE, &t,
                    expected);
    }
    *value = (int)v;
    return RT_OK;
}

/* Three numbers; `bounded`: each within RT_MAX_COORDINATE. */
static rt_status triple(parser *p, const char *what, int bounded,
                        rt_vec3 *out, token *where)
{
    double c[3];
    static const char axis[] = "xyz";
    for (int i = 0; i < 3; i++) {
        char part[128];
        snprintf(part, sizeof part, "%s (%c)", what, axis[i]);
        token t;
        rt_status status = number(p, part, &c[i], &t);
        if (status != RT_OK)
            return status;
        if (i == 0 && where != NULL)
            *where = t;
        if (bounded && fabs(c[i]) > RT_MAX_COORDINATE)
            return fail(p, RT_ERR_RANGE, &t,
                        "a coordinate of magnitude at most 1e152 (the "
                        "renderer's arithmetic overflows beyond)");
    }
    *out = v3(c[0], c[1], c[2]);
    return RT_OK;
}

static void warn_once(parser *p, int kind, const token *at, const char *text)
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
        warn_once(p, ONCE_COLOR, at,
                  "colour components outside [0, 1] are clamped to it (the "
                  "first is here)");
        v = v < 0 ? 0 : 1;
    }
    return (unsigned char)floor(v * 255.0 + 0.5);
}

static rt_status color(parser *p, const char *what, rt_rgb8 *out)
{
    rt_vec3 c;
    token t;
    rt_status status = triple(p, what, 0, &c, &t);
    if (status != RT_OK)
        return status;
    out->r = channel(p, c.x, &t);
    out->g = channel(p, c.y, &t);
    out->b = channel(p, c.z, &t);
    return RT_OK;
}

static int grow(void **array, int *capacity, int count, size_t size)
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

static rt_status out_of_memory(parser *p)
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
        status = fail(p, RT_ERR_SYNTAX, &t, expected);
    return status;
}

/* v from .. at .. up .. angle .. hither .. resolution .. */
static rt_status view(parser *p, const token *v)
{
    rt_status status;
    token from_t, at_t, up_t, angle_t, t;
    double hither;
    if (p->has_view)
        warn_once(p, ONCE_VIEW, v,
                  "a second viewpoint `v` replaces the first");
    if ((status = keyword(p, "from")) != RT_OK ||
        (status = triple(p, "`from`", 1, &p->from, &from_t)) != RT_OK ||
        (status = keyword(p, "at")) != RT_OK ||
        (status = triple(p, "`at`", 1, &p->at_point, &at_t)) != RT_OK ||
        (status = keyword(p, "up")) != RT_OK ||
        (status = triple(p, "`up`", 0, &p->up, &up_t)) != RT_OK ||
        (status = keyword(p, "angle")) != RT_OK ||
        (status = number(p, "`angle`", &p->angle, &angle_t)) != RT_OK)
        return status;
    /* hither came with NFF 2.7: older files go on with the resolution */
    if ((status = expect_token(p, &t, "`hither` or `resolution`")) != RT_OK)
        return status;
    if (is_word(&t, "hither")) {
        if ((status = number(p, "`hither`", &hither, &t)) != RT_OK)
            return status;
        warn_once(p, ONCE_HITHER, &t,
                  "`hither` has no place in the rendering model (it sees "
                  "from the eye on): ignored");
        status = keyword(p, "resolution");
    } else if (!is_word(&t, "resolution")) {
        status = fail(p, RT_ERR_SYNTAX, &t, "`hither` or `resolution`");
    }
    if (status != RT_OK ||
        (status = integer(p, "the image width", 1, RT_MAX_IMAGE_SIDE,
                          &p->width, &t)) != RT_OK ||
        (status = integer(p, "the image height", 1, RT_MAX_IMAGE_SIDE,
                          &p->height, NULL)) != RT_OK)
        return status;
    if (p->width != p->height)
        warn_once(p, ONCE_ASPECT, &t,
                  "the resolution is not square: the angle is taken "
                  "horizontally (pixels stay square, so the vertical angle "
                  "is smaller or larger than NFF's)");
    /* NFF's angle spans the centres of the first and last columns. */
    rt_view frame = {p->from, p->at_point, p->up, p->angle, p->width, 1};
    switch (rt__frame_view(&frame, &p->observer, &p->screen_center,
                           &p->screen_right)) {
    case RT_FRAME_FOV:
        return fail(p, RT_ERR_RANGE, &angle_t,
                    "an angle in (0, 180) degrees");
    case RT_FRAME_SAME_POINT:
        return fail(p, RT_ERR_CAMERA, &at_t,
                    "`at` apart from `from` (a direction to look in)");
    case RT_FRAME_UP_ALONG_VIEW:
        return fail(p, RT_ERR_CAMERA, &up_t,
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
    if (grow((void **)&p->lights, &p->light_capacity, p->light_count,
             sizeof *p->lights) != 0)
        return out_of_memory(p);
    nff_light *light = &p->lights[p->light_count];
    memset(light, 0, sizeof *light);
    light->at = *l;
    rt_status status = triple(p, "the light's position", 0, &light->position,
                              NULL);
    if (status != RT_OK)
        return status;
    /* (a token on the line of `l` follows the position on that line) */
    token t;
    if (rt__lex_peek(&p->lex, &t) && t.line == l->line &&
        rt__number_syntax(t.text, t.length)) {
        if ((status = color(p, "the light's colour", &light->color)) != RT_OK)
            return status;
        light->colored = 1;
    }
    p->light_count++;
    return RT_OK;
}

/* f r g b Kd Ks Shine T index */
static rt_status material(parser *p, const token *f)
{
    rt_status status;
    if (grow((void **)&p->materials, &p->material_capacity,
             p->material_count, sizeof *p->materials) != 0)
        return out_of_memory(p);
    rt_facet_desc m;
    memset(&m, 0, sizeof m);
    double kd, ks, shine, tr, index;
    token kd_t, ks_t, tr_t, index_t, shine_t;
    if ((status = color(p, "the colour", &m.color)) != RT_OK ||
        (status = number(p, "`Kd`", &kd, &kd_t)) != RT_OK ||
        (status = number(p, "`Ks`", &ks, &ks_t)) != RT_OK ||
        (status = number(p, "`Shine`", &shine, &shine_t)) != RT_OK ||
        (status = number(p, "`T`", &tr, &tr_t)) != RT_OK ||
        (status = number(p, "the index of refraction", &index, &index_t)) !=
            RT_OK)
        return status;
    if (!(kd >= 0))
        return fail(p, RT_ERR_RANGE, &kd_t, "a diffuse weight Kd >= 0");
    if (!(ks >= 0))
        return fail(p, RT_ERR_RANGE, &ks_t, "a specular weight Ks >= 0");
    if (!(tr >= 0))
        return fail(p, RT_ERR_RANGE, &tr_t, "a transmittance T >= 0");
    if (tr > 0 && !(index > 0))
        return fail(p, RT_ERR_RANGE, &index_t,
                    "an index of refraction > 0 for a transmitting "
                    "material (T > 0)");
    (void)f;
    warn_once(p, ONCE_SHINE, &shine_t,
              "`Shine` (the Phong exponent) has no place in the rendering "
              "model, which has no highlights: ignored");
    if (ks + tr > 1) {
        char text[200];
        double sum = ks + tr;
        if (isfinite(sum)) {
            snprintf(text, sizeof text,
                     "Ks + T = %g is more than 1 (the model needs k + t <= "
                     "1): both scaled by 1/%g (the first is here)", sum, sum);
        } else {
            /* Both near DBL_MAX: halved first (exactly), so that the sum
             * and the ratios stay finite. */
            snprintf(text, sizeof text,
                     "Ks + T = %g + %g is more than 1 (the model needs k + t "
                     "<= 1): both scaled by 1/(Ks + T) (the first is here)",
                     ks, tr);
            ks *= 0.5;
            tr *= 0.5;
            sum = ks + tr;
        }
        warn_once(p, ONCE_KT, &ks_t, text);
        ks /= sum;
        tr /= sum;
    }
    m.k = ks;
    m.t = tr <= 1.0 - m.k ? tr : 1.0 - m.k;
    m.n = tr > 0 ? index : 1.0;
    m.d = kd;
    m.d_given = 1;
    p->materials[p->material_count++] = m;
    return RT_OK;
}

static int current_material(parser *p, const token *at)
{
    if (p->material_count == 0) {
        warn_once(p, ONCE_MATERIAL, at,
                  "an object before any `f`: white, Kd = 1, Ks = T = 0");
        rt_facet_desc m;
        memset(&m, 0, sizeof m);
        m.color = (rt_rgb8){255, 255, 255};
        m.n = 1.0;
        m.d = 1.0;
        m.d_given = 1;
        if (grow((void **)&p->materials, &p->material_capacity, 0,
                 sizeof *p->materials) != 0)
            return -1;
        p->materials[p->material_count++] = m;
    }
    return p->material_count - 1;
}

static rt_status add_primitive(parser *p, const primitive *prim)
{
    if (grow((void **)&p->primitives, &p->primitive_capacity,
             p->primitive_count, sizeof *p->primitives) != 0)
        return out_of_memory(p);
    p->primitives[p->primitive_count++] = *prim;
    return RT_OK;
}

/* A radius: non-zero, and the centre +- it within RT_MAX_COORDINATE. */
static rt_status radius(parser *p, const char *what, rt_vec3 center,
                        int zero_allowed, double *r, token *t)
{
    rt_status status = number(p, what, r, t);
    if (status != RT_OK)
        return status;
    if (!zero_allowed && *r == 0)
        return fail(p, RT_ERR_RANGE, t, "a radius other than 0");
    if (v3_max_abs(center) + fabs(*r) > RT_MAX_COORDINATE)
        return fail(p, RT_ERR_RANGE, t,
                    "a radius that keeps the surface within coordinates of "
                    "magnitude 1e152 (the renderer's arithmetic overflows "
                    "beyond)");
    /* The spacing of doubles at the centre: a smaller radius moves no
     * coordinate of it, so no surface is there to cut. */
    double largest = v3_max_abs(center);
    double spacing = nextafter(largest, INFINITY) - largest;
    if (*r != 0 && fabs(*r) < spacing) {
        char expected[200];
        snprintf(expected, sizeof expected,
                 "a radius of at least %g, the spacing of doubles at its "
                 "centre (a smaller surface cannot be represented)",
                 spacing);
        return fail(p, RT_ERR_RANGE, t, expected);
    }
    return RT_OK;
}

static void inside_warning(parser *p, const token *t)
{
    warn_once(p, ONCE_INSIDE, t,
              "a negative radius (only the inside visible): the facets are "
              "wound inward, but the model sees facets from both sides");
}

static rt_status sphere(parser *p, const token *s)
{
    primitive prim;
    memset(&prim, 0, sizeof prim);
    token r_t;
    rt_status status = triple(p, "the sphere's centre", 1, &prim.base, NULL);
    if (status == RT_OK)
        status = radius(p, "the sphere's radius", prim.base, 0, &prim.r0,
                        &r_t);
    if (status != RT_OK)
        return status;
    if (prim.r0 < 0) {
        inside_warning(p, &r_t);
        prim.r0 = -prim.r0;
        prim.inward = 1;
    }
    if ((prim.material = current_material(p, s)) < 0)
        return out_of_memory(p);
    prim.line = s->line;
    prim.column = s->column;
    return add_primitive(p, &prim);
}

static rt_status cone(parser *p, const token *c)
{
    primitive prim;
    memset(&prim, 0, sizeof prim);
    prim.cone = 1;
    token r0_t, r1_t, apex_t;
    rt_status status;
    if ((status = triple(p, "the cone's base", 1, &prim.base, NULL)) !=
            RT_OK ||
        (status = radius(p, "the base radius", prim.base, 1, &prim.r0,
                         &r0_t)) != RT_OK ||
        (status = triple(p, "the cone's apex", 1, &prim.apex, &apex_t)) !=
            RT_OK ||
        (status = radius(p, "the apex radius", prim.apex, 1, &prim.r1,
                         &r1_t)) != RT_OK)
        return status;
    if ((prim.r0 < 0 && prim.r1 > 0) || (prim.r0 > 0 && prim.r1 < 0))
        return fail(p, RT_ERR_RANGE, &r1_t,
                    "an apex radius of the base radius's sign (both "
                    "negative: only the inside visible)");
    if (prim.r0 == 0 && prim.r1 == 0)
        return fail(p, RT_ERR_RANGE, &r1_t,
                    "a radius other than 0 at the base or the apex");
    if (v3_length(v3_sub(prim.apex, prim.base)) == 0)
        return fail(p, RT_ERR_RANGE, &apex_t, "an apex apart from the base");
    if (prim.r0 < 0 || prim.r1 < 0) {
        inside_warning(p, &r0_t);
        prim.r0 = fabs(prim.r0);
        prim.r1 = fabs(prim.r1);
        prim.inward = 1;
    }
    if ((prim.material = current_material(p, c)) < 0)
        return out_of_memory(p);
    prim.line = c->line;
    prim.column = c->column;
    return add_primitive(p, &prim);
}

/* p n, n vertices; pp n, n vertices each with its normal. */
static rt_status polygon(parser *p, const token *entity, int patch)
{
    int n;
    token count_t;
    rt_status status = integer(p, "the vertex count", 3, INT_MAX, &n,
                               &count_t);
    if (status != RT_OK)
        return status;
    long per_vertex = patch ? 6 : 3;
    if (n > tokens_left(p) / per_vertex) {
        char expected[160];
        snprintf(expected, sizeof expected,
                 "a vertex count of at most %ld (the values left in the "
                 "file)", tokens_left(p) / per_vertex);
        return fail(p, RT_ERR_LIMIT, &count_t, expected);
    }
    if (n > p->point_capacity) {
        rt_vec3 *grown = realloc(p->points, (size_t)n * sizeof *grown);
        if (grown == NULL)
            return out_of_memory(p);
        p->points = grown;
        p->point_capacity = n;
    }
    for (int i = 0; i < n; i++) {
        if (i % RT_LOAD_POLL == RT_LOAD_POLL - 1 &&
            rt__load_cancelled(p->options))
            return rt__load_cancel(p->error, p->name);
        if ((status = triple(p, "a vertex", 1, &p->points[i], NULL)) != RT_OK)
            return status;
        if (patch) {
            rt_vec3 normal;
            token t;
            if ((status = triple(p, "a vertex normal", 0, &normal, &t)) !=
                RT_OK)
                return status;
            warn_once(p, ONCE_NORMALS, &t,
                      "the normals of `pp` patches are ignored (the model's "
                      "facets are flat)");
        }
    }
    if (n > MAX_NONCONVEX_VERTICES &&
        !rt__tess_polygon_convex(p->points, n)) {
        char expected[160];
        snprintf(expected, sizeof expected,
                 "a convex polygon, or a non-convex one of at most %d "
                 "vertices", MAX_NONCONVEX_VERTICES);
        return fail(p, RT_ERR_LIMIT, &count_t, expected);
    }
    int m = current_material(p, entity);
    if (m < 0)
        return out_of_memory(p);
    if (p->mesh.facet_count + (double)n - 2 > RT_TESS_MAX_FACETS)
        return fail(p, RT_ERR_LIMIT, &count_t,
                    "at most 16777216 facets in all");
    int irregular = 0;
    if (rt__tess_polygon(&p->mesh, p->points, n, &p->materials[m],
                         entity->line, &irregular) != 0)
        return out_of_memory(p);
    if (irregular)
        warn_once(p, ONCE_IRREGULAR, entity,
                  "a polygon that is not simple (self-intersecting, or "
                  "degenerate): cut into triangles corner by corner (the "
                  "first is here)");
    return RT_OK;
}

/* The tolerance that keeps a silhouette of radius rho pixels within
 * DEFAULT_PIXELS of the true one and facets about DEFAULT_FACET_PIXELS
 * across where they face the eye, within the default bounds. */
static double smooth_tolerance(double rho)
{
    double tol = DEFAULT_PIXELS / rho;
    /* facets about DEFAULT_FACET_PIXELS across where they face the eye
     * (a band of angle pi / bands ~ sqrt(2) acos(1 - tol)): flat shading
     * then changes in steps too small to be seen as bands */
    double across = 1.0 - cos(DEFAULT_FACET_PIXELS / (sqrt(2.0) * rho));
    if (across < tol)
        tol = across;
    if (!(tol >= DEFAULT_TOLERANCE_MIN))
        tol = DEFAULT_TOLERANCE_MIN;
    if (tol > DEFAULT_TOLERANCE_MAX)
        tol = DEFAULT_TOLERANCE_MAX;
    return tol;
}

/* How a primitive is cut: a tolerance, or 0 for the coarsest cut; and at
 * most `most_facets` facets (0: no cap but the budget). */
typedef struct cut {
    double tolerance;
    double most_facets;
} cut;

/*
 * The default cut of a primitive from the file's view (docs/formats.md,
 * "Tessellation"), with r its radius (a cone's larger one) and `center`
 * its centre (a cone's midpoint):
 * - in front of the eye (its nearest depth along the view, at least a
 *   tenth of r, is positive): sized by its radius in pixels there, rho; the
 *   coarsest when it is smaller than a pixel (2 rho < 1);
 * - entirely behind the eye (its bounding sphere behind the plane of the
 *   eye): the coarsest, as only reflections can show it;
 * - otherwise (around or beside the eye): as if seen from the distance of
 *   its farthest point, so rho is at most the focal length in pixels, and
 *   at most as many facets as the image has pixels.
 */
static cut default_cut(const parser *p, const primitive *prim)
{
    cut c = {0.0, 0.0};
    double r = prim->r0 > prim->r1 ? prim->r0 : prim->r1;
    rt_vec3 center = prim->cone ? v3_scale(v3_add(prim->base, prim->apex), 0.5)
                                : prim->base;
    rt_vec3 w = v3_normalize(v3_sub(p->at_point, p->from));
    double along = v3_dot(v3_sub(center, p->from), w);
    double depth = along - r;
    if (depth > 0) {
        if (!(depth > 0.1 * r))
            depth = 0.1 * r;
        double half_width = depth * rt__frame_tan_half(p->angle);
        double pixels_per_unit = 0.5 * p->width / half_width;
        double rho = pixels_per_unit * r;  /* the radius in pixels */
        if (2.0 * rho >= 1.0)
            c.tolerance = smooth_tolerance(rho);
        return c;
    }
    double reach = r;       /* the radius of a sphere holding the primitive */
    if (prim->cone) {
        double half = 0.5 * v3_length(v3_sub(prim->apex, prim->base));
        reach = sqrt(half * half + r * r);
    }
    if (!(along + reach > 0))
        return c;
    double farthest = v3_length(v3_sub(center, p->from)) + reach;
    double focal = 0.5 * p->width / rt__frame_tan_half(p->angle);
    c.tolerance = smooth_tolerance(focal * r / farthest);
    c.most_facets = (double)p->width * (double)p->height;
    return c;
}

/* The bands of a sphere cut by `c` (tol_bands: the bands its tolerance
 * gives, 0 when it needs too many). */
static int sphere_bands(const cut *c, int tol_bands)
{
    if (c->tolerance == 0)
        return COARSEST_BANDS;
    if (tol_bands == 0 || c->most_facets == 0 ||
        rt__tess_sphere_facet_count(tol_bands) <= c->most_facets)
        return tol_bands;
    /* the most bands b with 4 b (b - 1) <= most_facets */
    int most = (int)floor(0.5 * (1.0 + sqrt(1.0 + c->most_facets)));
    while (most > COARSEST_BANDS && rt__tess_sphere_facet_count(most) >
                                        c->most_facets)
        most--;
    return most > COARSEST_BANDS ? most : COARSEST_BANDS;
}

static int cone_segments(const cut *c, int tol_segments, const primitive *p)
{
    if (c->tolerance == 0)
        return COARSEST_SEGMENTS;
    if (tol_segments == 0 || c->most_facets == 0 ||
        rt__tess_cone_facet_count(tol_segments, p->r0, p->r1) <=
            c->most_facets)
        return tol_segments;
    double per_segment = rt__tess_cone_facet_count(1, p->r0, p->r1);
    double most = floor(c->most_facets / per_segment);
    return most > COARSEST_SEGMENTS ? (int)most : COARSEST_SEGMENTS;
}

static rt_status too_many(parser *p, const primitive *prim, double facets,
                          double budget, double tolerance)
{
    char tol[48] = "", total[48];
    if (tolerance > 0)
        snprintf(tol, sizeof tol, " (now %g for this %s)", tolerance,
                 prim->cone ? "cone" : "sphere");
    if (p->mesh.facet_count + facets > RT_TESS_MAX_FACETS)
        snprintf(total, sizeof total, "more than %d", RT_TESS_MAX_FACETS);
    else
        snprintf(total, sizeof total, "%.0f", p->mesh.facet_count + facets);
    return rt__error_set(p->error, RT_ERR_LIMIT, p->name, prim->line,
                         prim->column,
                         "expected at most %.0f facets in all for a file of "
                         "%zu bytes (%d + %d a byte, at most %d), found that "
                         "this %s brings them to %s: give a larger "
                         "tessellation tolerance (--tessellate)%s",
                         budget, file_bytes(p),
                         RT_TESS_BUDGET_BASE, RT_TESS_BUDGET_PER_BYTE,
                         RT_TESS_MAX_FACETS, prim->cone ? "cone" : "sphere",
                         total, tol);
}

/* Cuts primitive `prim` into the mesh: 0, -1 (out of memory) or
 * RT_TESS_CANCELLED, after checking its facets against `budget`. */
static rt_status cut_primitive(parser *p, const primitive *prim,
                               const cut *c, int bands, int segments,
                               double budget)
{
    const rt_facet_desc *m = &p->materials[prim->material];
    double facets;
    if (prim->cone)
        facets = segments == 0 ? 1e300
                               : rt__tess_cone_facet_count(segments, prim->r0,
                                                           prim->r1);
    else
        facets = bands == 0 ? 1e300 : rt__tess_sphere_facet_count(bands);
    if (p->mesh.facet_count + facets > budget)
        return too_many(p, prim, facets, budget, c->tolerance);
    int done = prim->cone
                   ? rt__tess_cone(&p->mesh, prim->base, prim->r0, prim->apex,
                                   prim->r1, prim->inward, segments, m,
                                   prim->line)
                   : rt__tess_sphere(&p->mesh, prim->base, prim->r0,
                                     prim->inward, bands, m, prim->line);
    if (done == RT_TESS_CANCELLED)
        return rt__load_cancel(p->error, p->name);
    return done == 0 ? RT_OK : out_of_memory(p);
}

static rt_status tessellate(parser *p, double option)
{
    double budget = rt__tess_budget(file_bytes(p));
    double last_tol = -1;
    int last_bands = 0, last_segments = 0;
    const primitive *first_dropped = NULL;
    p->mesh.cancel = p->options->cancel;
    for (int i = 0; i < p->primitive_count; i++) {
        const primitive *prim = &p->primitives[i];
        if (poll_cancel(p))
            return rt__load_cancel(p->error, p->name);
        cut c = {option, 0.0};
        if (!(option > 0))
            c = default_cut(p, prim);
        if (c.tolerance > 0 && c.tolerance != last_tol) {
            last_tol = c.tolerance;
            last_bands = rt__tess_sphere_bands(c.tolerance);
            last_segments = rt__tess_circle_segments(c.tolerance);
        }
        int dropped = p->mesh.dropped;
        rt_status status =
            cut_primitive(p, prim, &c, sphere_bands(&c, last_bands),
                          cone_segments(&c, last_segments, prim), budget);
        if (status != RT_OK)
            return status;
        if (dropped == 0 && p->mesh.dropped > 0)
            first_dropped = prim;
    }
    if (first_dropped != NULL)
        rt__notes_add(&p->notes, p->name, first_dropped->line,
                      first_dropped->column,
                      "%d facets of zero area left out of spheres and cones "
                      "(their vertices round together: the radius is small "
                      "for the coordinates of the centre; the first such "
                      "%s is here)", p->mesh.dropped,
                      first_dropped->cone ? "cone" : "sphere");
    return RT_OK;
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
        if (poll_cancel(p))
            return rt__load_cancel(p->error, p->name);
        if (is_word(&t, "v"))
            status = view(p, &t);
        else if (is_word(&t, "b"))
            status = color(p, "the background colour", &p->background);
        else if (is_word(&t, "l"))
            status = light(p, &t);
        else if (is_word(&t, "f"))
            status = material(p, &t);
        else if (is_word(&t, "s"))
            status = sphere(p, &t);
        else if (is_word(&t, "c"))
            status = cone(p, &t);
        else if (is_word(&t, "p"))
            status = polygon(p, &t, 0);
        else if (is_word(&t, "pp"))
            status = polygon(p, &t, 1);
        else
            status = fail(p, RT_ERR_SYNTAX, &t,
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
    if ((status = tessellate(p, options->tessellation)) != RT_OK)
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
    d.vertex_count = p->mesh.vertex_count;
    d.facets = p->mesh.facets;
    d.facet_count = p->mesh.facet_count;

    rt_light *lights = NULL;
    int light_count = p->light_count;
    if (light_count == 0) {
        rt__notes_add(&p->notes, p->name, 0, 0,
                      "no light `l` in the file: a white light at the eye "
                      "(`from`)");
        d.light_position = p->from;
        d.light_color = (rt_rgb8){255, 255, 255};
    } else {
        /* Lights without a colour share a total of about one white light:
         * 1/sqrt(count) each. */
        unsigned char grey =
            (unsigned char)floor(255.0 / sqrt((double)light_count) + 0.5);
        lights = malloc((size_t)light_count * sizeof *lights);
        if (lights == NULL)
            return out_of_memory(p);
        for (int i = 0; i < light_count; i++) {
            lights[i].position = p->lights[i].position;
            lights[i].color = p->lights[i].colored
                                  ? p->lights[i].color
                                  : (rt_rgb8){grey, grey, grey};
        }
        d.light_position = lights[0].position;
        d.light_color = lights[0].color;
        d.more_lights = lights + 1;
        d.more_light_count = light_count - 1;
    }
    if (p->notes.failed)
        status = out_of_memory(p);
    else if (rt__load_cancelled(options))
        status = rt__load_cancel(p->error, p->name);
    else {
        rt_reading reading = {p->name, p->mesh.facet_lines, &p->notes,
                              options, locate, p};
        status = rt__reader_finish(&d, &reading, scene, p->error);
    }
    free(lights);
    return status;
}

rt_status rt__nff_parse(const char *text, size_t length, const char *name,
                        const rt_load_options *options, rt_scene **scene,
                        rt_error *error)
{
    if (scene == NULL)
        return RT_ERR_ARGUMENT;
    *scene = NULL;
    const char *shown = name ? name : "<memory>";
    if (text == NULL && length > 0)
        return rt__error_set(error, RT_ERR_ARGUMENT, shown, 0, 0,
                             "expected scene text");
    rt_load_options defaults;
    if (options == NULL) {
        rt_load_options_init(&defaults);
        options = &defaults;
    }
    if (options->tessellation != 0 &&
        !(options->tessellation > 0 && options->tessellation < 1))
        return rt__error_set(error, RT_ERR_ARGUMENT, shown, 0, 0,
                             "expected a tessellation tolerance in (0, 1), "
                             "found %g", options->tessellation);
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
