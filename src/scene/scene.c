/*
 * scene.c - building a scene from a description, and asking it questions.
 *
 * rt_scene_create is the one way scenes are made (the `.scn` parser is a
 * client of it).  Building checks the rules the renderer relies on, works
 * out the camera, drops from what the renderer sees the facets no ray can
 * meet - zero-area facets (a warning each, the first few, then one that
 * counts the rest) and exact repeats of the facet before them (one
 * warning) - and precomputes per-facet data once.
 */
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "base/exact.h"
#include "base/sized.h"
#include "kernel/plane_crossing.h"
#include "scene_internal.h"
#include "base/vecmath.h"

_Static_assert(RT_MAX_LIGHTS == 64, "RT_RULE_LIGHTS says 64 lights");

/* Where a check reports what it refuses. */
typedef struct check {
    const char *name;       /* for messages; may be NULL */
    rt_error *error;
    rt_refusal *refusal;    /* may be NULL */
} check;

static rt_status refuse(const check *c, rt_status status, rt_item item,
                        int index, rt_field field, int part,
                        const char *expected, const char *fmt, ...)
    RT_PRINTF_LIKE(8, 9);

/* Fills the refusal (the token quoted: found "") and the error, whose
 * words `fmt` gives; returns `status`. */
static rt_status refuse(const check *c, rt_status status, rt_item item,
                        int index, rt_field field, int part,
                        const char *expected, const char *fmt, ...)
{
    if (c->refusal != NULL)
        *c->refusal = (rt_refusal){status, item, index, field, part,
                                   expected, ""};
    char words[RT_ERROR_MESSAGE_SIZE];
    va_list args;
    va_start(args, fmt);
    vsnprintf(words, sizeof words, fmt, args);
    va_end(args);
    return rt__error_set(c->error, status, c->name, 0, 0, "%s", words);
}

/* The point `field` of the camera. */
static rt_vec3 camera_point(const rt_scene_desc *d, rt_field field)
{
    return field == RT_FIELD_OBSERVER        ? d->observer
           : field == RT_FIELD_SCREEN_CENTER ? d->screen_center
                                             : d->screen_right;
}

/* The first coordinate of p that is not finite (`finite`) or beyond
 * RT_MAX_COORDINATE (not `finite`), or -1. */
static int bad_coordinate(rt_vec3 p, int finite)
{
    double c[3] = {p.x, p.y, p.z};
    for (int i = 0; i < 3; i++)
        if (finite ? !isfinite(c[i]) : fabs(c[i]) > RT_MAX_COORDINATE)
            return i;
    return -1;
}

static const rt_field camera_fields[3] = {
    RT_FIELD_OBSERVER, RT_FIELD_SCREEN_CENTER, RT_FIELD_SCREEN_RIGHT};

/* Every point finite: the camera's, the lights', the vertices'. */
static rt_status check_finite(const check *c, const rt_scene_desc *d)
{
    static const char words[] = "expected finite coordinates for %s";
    const char *expected = "finite coordinates";
    for (int i = 0; i < 3; i++) {
        int part = bad_coordinate(camera_point(d, camera_fields[i]), 1);
        if (part >= 0)
            return refuse(c, RT_ERR_RANGE, RT_ITEM_CAMERA, 0,
                          camera_fields[i], part, expected, words,
                          "the camera and the light");
    }
    for (int i = 0; i < d->light_count; i++) {
        int part = bad_coordinate(d->lights[i].position, 1);
        if (part >= 0)
            return refuse(c, RT_ERR_RANGE, RT_ITEM_LIGHT, i,
                          RT_FIELD_POSITION, part, expected, words,
                          i == 0 ? "the camera and the light"
                                 : "every light");
    }
    for (int i = 0; i < d->vertex_count; i++) {
        int part = bad_coordinate(d->vertices[i], 1);
        if (part >= 0)
            return refuse(c, RT_ERR_RANGE, RT_ITEM_VERTEX, i,
                          RT_FIELD_POSITION, part, expected, words,
                          "every vertex");
    }
    for (int i = 0; d->normals != NULL && i < d->vertex_count; i++) {
        int part = bad_coordinate(d->normals[i], 1);
        if (part >= 0)
            return refuse(c, RT_ERR_RANGE, RT_ITEM_VERTEX, i,
                          RT_FIELD_NORMAL, part, RT_RULE_NORMAL,
                          "vertex %d: expected %s, found %g", i,
                          RT_RULE_NORMAL,
                          part == 0 ? d->normals[i].x
                          : part == 1 ? d->normals[i].y
                                      : d->normals[i].z);
    }
    return RT_OK;
}

/* A coordinate beyond RT_MAX_COORDINATE, as item `item` names it. */
static rt_status refuse_far(const check *c, rt_item item, int index,
                            rt_field field, int part, double value)
{
    return refuse(c, RT_ERR_RANGE, item, index, field, part,
                  RT_RULE_COORDINATE,
                  "expected coordinates of magnitude at most %g, found %g: "
                  "the arithmetic of the renderer cannot hold such a scene",
                  RT_MAX_COORDINATE, value);
}

static double coordinate(rt_vec3 p, int part)
{
    return part == 0 ? p.x : part == 1 ? p.y : p.z;
}

/* The camera's points within RT_MAX_COORDINATE, the lens, and a camera
 * that sees something, computed into *camera. */
static rt_status check_camera(const check *c, const rt_scene_desc *d,
                              rt_camera *camera)
{
    for (int i = 0; i < 3; i++) {
        rt_vec3 p = camera_point(d, camera_fields[i]);
        int part = bad_coordinate(p, 0);
        if (part >= 0)
            return refuse_far(c, RT_ITEM_CAMERA, 0, camera_fields[i], part,
                              coordinate(p, part));
    }
    if (!(d->aperture >= 0.0 && isfinite(d->aperture)))
        return refuse(c, RT_ERR_RANGE, RT_ITEM_LENS, 0, RT_FIELD_APERTURE, 0,
                      RT_RULE_APERTURE, "expected %s, found %g",
                      RT_RULE_APERTURE, d->aperture);
    if (!(d->focal_distance >= 0.0 && isfinite(d->focal_distance)))
        return refuse(c, RT_ERR_RANGE, RT_ITEM_LENS, 0,
                      RT_FIELD_FOCAL_DISTANCE, 0, RT_RULE_FOCAL,
                      "expected %s (or 0 for |AO|), found %g", RT_RULE_FOCAL,
                      d->focal_distance);
    rt_field field;
    const char *reason = rt__camera_make(d->observer, d->screen_center,
                                         d->screen_right, d->width, d->height,
                                         camera, &field);
    if (reason == NULL)
        return RT_OK;
    rt_status status = refuse(c, RT_ERR_CAMERA, RT_ITEM_CAMERA, 0, field, 0,
                              RT_RULE_CAMERA, "expected %s, found that %s",
                              RT_RULE_CAMERA, reason);
    if (c->refusal != NULL)
        snprintf(c->refusal->found, sizeof c->refusal->found, "that %s",
                 reason);
    return status;
}

static rt_status check_facet(const check *c, const rt_scene_desc *d, int i)
{
    const rt_facet_desc *f = &d->facets[i];
    for (int j = 0; j < 3; j++)
        if (f->vertex[j] < 0 || f->vertex[j] >= d->vertex_count)
            return refuse(c, RT_ERR_RANGE, RT_ITEM_FACET, i, RT_FIELD_CORNER,
                          j, "a vertex index of the description",
                          "facet %d: expected a vertex index in 0..%d, "
                          "found %d", i, d->vertex_count - 1, f->vertex[j]);
    static const char words[] = "facet %d: expected %s, found %g";
    if (!(f->reflection >= 0.0 && f->reflection <= 1.0))
        return refuse(c, RT_ERR_RANGE, RT_ITEM_FACET, i, RT_FIELD_K, 0,
                      RT_RULE_K, words, i, RT_RULE_K, f->reflection);
    if (!(f->transparency >= 0.0 && f->transparency <= 1.0 - f->reflection)) {
        const char *rule = f->transparency >= 0.0 ? RT_RULE_T : RT_RULE_T_SIGN;
        return refuse(c, RT_ERR_RANGE, RT_ITEM_FACET, i, RT_FIELD_T, 0, rule,
                      words, i, rule, f->transparency);
    }
    if (!(f->refractive_index >= 0.0 && isfinite(f->refractive_index)))
        return refuse(c, RT_ERR_RANGE, RT_ITEM_FACET, i, RT_FIELD_N, 0,
                      RT_RULE_N, words, i, RT_RULE_N, f->refractive_index);
    if (f->diffuse_given && !(f->diffuse >= 0.0 && isfinite(f->diffuse)))
        return refuse(c, RT_ERR_RANGE, RT_ITEM_FACET, i, RT_FIELD_D, 0,
                      RT_RULE_D, words, i, RT_RULE_D, f->diffuse);
    if (!(f->highlight >= 0.0 && isfinite(f->highlight)))
        return refuse(c, RT_ERR_RANGE, RT_ITEM_FACET, i, RT_FIELD_S, 0,
                      RT_RULE_S, words, i, RT_RULE_S, f->highlight);
    if (!((f->highlight_exponent >= 1.0 || f->highlight_exponent == 0.0) &&
          isfinite(f->highlight_exponent)))
        return refuse(c, RT_ERR_RANGE, RT_ITEM_FACET, i, RT_FIELD_P, 0,
                      RT_RULE_P, words, i, RT_RULE_P, f->highlight_exponent);
    return RT_OK;
}

/*
 * The one validator of a description (raytrace/scene.h, rt_scene_desc):
 * its shape first (sizes, arrays, finite values), then its rules in the
 * order a file states them, so that a reader's first refusal is the first
 * it met.  Computes the camera into *camera.
 */
static rt_status check_desc(const check *c, const rt_scene_desc *d,
                            rt_camera *camera)
{
    if (d->width < 1 || d->width > RT_MAX_IMAGE_SIDE || d->height < 1 ||
        d->height > RT_MAX_IMAGE_SIDE)
        return refuse(c, RT_ERR_RANGE, RT_ITEM_IMAGE, 0,
                      d->width < 1 || d->width > RT_MAX_IMAGE_SIDE
                          ? RT_FIELD_WIDTH
                          : RT_FIELD_HEIGHT,
                      0, "an image size in 1..16384",
                      "expected an image size in 1..%d, found %dx%d",
                      RT_MAX_IMAGE_SIDE, d->width, d->height);
    if (d->vertex_count < 0 || d->facet_count < 0 ||
        (d->vertex_count > 0 && d->vertices == NULL) ||
        (d->facet_count > 0 && d->facets == NULL))
        return refuse(c, RT_ERR_ARGUMENT, RT_ITEM_NONE, 0, RT_FIELD_NONE, 0,
                      "vertex and facet arrays",
                      "expected vertex and facet arrays");
    if (d->light_count < 0 || (d->light_count > 0 && d->lights == NULL))
        return refuse(c, RT_ERR_ARGUMENT, RT_ITEM_NONE, 0, RT_FIELD_NONE, 0,
                      "an array of lights", "expected an array of lights");
    if (d->light_count == 0) {
        rt_status status = refuse(c, RT_ERR_RANGE, RT_ITEM_LIGHT, 0,
                                  RT_FIELD_NONE, 0, RT_RULE_A_LIGHT,
                                  "expected %s, found none", RT_RULE_A_LIGHT);
        if (c->refusal != NULL)
            snprintf(c->refusal->found, sizeof c->refusal->found, "none");
        return status;
    }
    rt_status status = check_finite(c, d);
    if (status == RT_OK)
        status = check_camera(c, d, camera);
    for (int i = 0; status == RT_OK && i < d->vertex_count; i++) {
        int part = bad_coordinate(d->vertices[i], 0);
        if (part >= 0)
            status = refuse_far(c, RT_ITEM_VERTEX, i, RT_FIELD_POSITION, part,
                                coordinate(d->vertices[i], part));
    }
    for (int i = 0; status == RT_OK && i < d->facet_count; i++)
        status = check_facet(c, d, i);
    if (status == RT_OK && d->light_count > RT_MAX_LIGHTS) {
        status = refuse(c, RT_ERR_LIMIT, RT_ITEM_LIGHT, RT_MAX_LIGHTS,
                        RT_FIELD_NONE, 0, RT_RULE_LIGHTS,
                        "expected %s, found %d", RT_RULE_LIGHTS,
                        d->light_count);
        if (c->refusal != NULL)
            snprintf(c->refusal->found, sizeof c->refusal->found,
                     "light %d", RT_MAX_LIGHTS + 1);
    }
    return status;
}

/* The kind of the builder's warning for each zero-area facet. */
static const char zero_area_kind[] = "zero-area facets";

static void add_degenerate_warning(rt_notes *notes, const char *name,
                                   int facet, int line)
{
    rt__notes_add_kind(notes, zero_area_kind, name, line, 1,
                       "facet %d has zero area (its vertices are "
                       "collinear); it is never hit", facet + 1);
}

/* Whether facet f has the vertex positions of facet g, in the same order
 * (bit for bit: the intersection test then computes the same for both). */
static int same_corners(const rt_scene_desc *d, const rt_facet_desc *f,
                        const rt_facet_desc *g)
{
    for (int j = 0; j < 3; j++)
        if (memcmp(&d->vertices[f->vertex[j]], &d->vertices[g->vertex[j]],
                   sizeof(rt_vec3)) != 0)
            return 0;
    return 1;
}

/* The warning's kind: a facet's plane through the eye (or too near). */
static const char edge_on_kind[] = "facets in a plane through the eye";

/*
 * Warns when the eye lies in the plane of the facet (a, b, c), or so near
 * it that the renderer cannot tell its side: within about 1e-30 of the
 * facet's size, the limit of the crossing test (docs/robustness.md,
 * "Facets far larger than their distance"), in either precision.  Camera
 * rays never meet such a facet.  Plain double first: a distance well above
 * its rounding needs nothing more.
 */
static void check_edge_on(rt_notes *notes, const char *name, int facet,
                          int line, rt_vec3 normal, rt_vec3 a, rt_vec3 b,
                          rt_vec3 c, rt_vec3 eye)
{
    rt_vec3 to_a = v3_sub(a, eye);
    double reach = fabs(to_a.x) + fabs(to_a.y) + fabs(to_a.z);
    if (fabs(v3_dot(normal, to_a)) > 64 * DBL_EPSILON * reach)
        return;
    double pa[3] = {a.x, a.y, a.z}, pb[3] = {b.x, b.y, b.z},
           pc[3] = {c.x, c.y, c.z}, o[3] = {eye.x, eye.y, eye.z};
    if (rt__plane_side(pa, pb, pc, o) != 0)
        return;
    rt__notes_add_kind(notes, edge_on_kind, name, line, 1,
                       "facet %d lies in a plane through the eye (or within "
                       "1e-30 of its size from it): camera rays never meet "
                       "it", facet + 1);
}

/* The repeats found: how many, and the first. */
typedef struct repeats {
    int count;
    int first, first_line, of;      /* facet, its line, the one it repeats */
} repeats;

static void add_repeat_warning(rt_notes *notes, const char *name,
                               const repeats *r)
{
    if (r->count == 0)
        return;
    int line = r->first_line;
    if (r->count == 1)
        rt__notes_add(notes, name, line, 1,
                      "facet %d repeats facet %d exactly (the same vertices "
                      "in the same order): it is never hit and changes no "
                      "pixel", r->first + 1, r->of + 1);
    else
        rt__notes_add(notes, name, line, 1,
                      "%d facets repeat the facet just before them exactly "
                      "(the same vertices in the same order), the first "
                      "facet %d: they are never hit and change no pixel",
                      r->count, r->first + 1);
}

/* Fills the facet records, the materials they share and the counts,
 * sorting out the facets no ray can meet (docs/robustness-input.md,
 * "Facets no ray meets"); their warnings go to `notes`, each facet's
 * normal to normals[i].  RT_OK, RT_ERR_CANCELLED or RT_ERR_NOMEM. */
static rt_status add_facets(rt_scene *s, const rt_scene_desc *d,
                            const char *name, const int *facet_lines,
                            rt_notes *notes, const rt_cancel *cancel,
                            rt_vec3 *normals)
{
    repeats r = {0, 0, 0, 0};
    int previous = -1;      /* the last facet the renderer keeps */
    for (int i = 0; i < d->facet_count; i++) {
        if (i % RT_LOAD_POLL == RT_LOAD_POLL - 1 &&
            rt_cancel_requested(cancel))
            return RT_ERR_CANCELLED;
        const rt_facet_desc *f = &d->facets[i];
        rt_facet_record *record = &s->facets[i];
        rt_vec3 a = d->vertices[f->vertex[0]], b = d->vertices[f->vertex[1]],
                c = d->vertices[f->vertex[2]];
        rt_material m = {
            f->reflection, f->transparency,
            f->refractive_index > 0.0 ? f->refractive_index : 1.0,
            f->diffuse_given ? f->diffuse
                             : 1.0 - f->reflection - f->transparency,
            f->color, f->highlight,
            f->highlight_exponent > 0.0 ? f->highlight_exponent : 1.0};
        memset(record, 0, sizeof *record);
        memcpy(record->vertex, f->vertex, sizeof record->vertex);
        if ((record->material = rt__materials_add(&s->materials, &m)) < 0)
            return RT_ERR_NOMEM;
        record->line = facet_lines ? facet_lines[i] : 0;
        rt_vec3 normal = normals[i] = rt__facet_normal(a, b, c);
        if (v3_max_abs(normal) == 0.0) {
            record->degenerate = RT_FACET_ZERO_AREA;
            add_degenerate_warning(notes, name, i, record->line);
            continue;
        }
        if (previous >= 0 && same_corners(d, f, &d->facets[previous])) {
            record->degenerate = RT_FACET_REPEATED;
            if (r.count++ == 0)
                r.first = i, r.first_line = record->line, r.of = previous;
            continue;
        }
        previous = i;
        check_edge_on(notes, name, i, record->line, normal, a, b, c,
                      d->observer);
        s->live_count++;
        s->reflective_count += f->reflection > 0.0;
        s->transparent_count += f->transparency > 0.0;
        s->highlight_count += f->highlight > 0.0;
        s->smooth_count += rt__scene_facet_smooth(s, record);
    }
    add_repeat_warning(notes, name, &r);
    rt__materials_end(&s->materials);
    return RT_OK;
}

rt_status rt__scene_check(const rt_scene_desc *d, const char *name,
                          rt_error *error, rt_refusal *refusal)
{
    if (refusal != NULL)
        memset(refusal, 0, sizeof *refusal);
    check c = {name, error, refusal};
    rt_camera camera;
    return check_desc(&c, d, &camera);
}

rt_status rt__scene_build(const rt_scene_desc *d, const char *name,
                          const int *facet_lines, const rt_notes *notes,
                          const rt_cancel *cancel, rt_scene **out,
                          rt_error *error, rt_refusal *refusal)
{
    return rt__scene_build_releasing(d, name, facet_lines, notes, cancel,
                                     NULL, out, error, refusal);
}

rt_status rt__scene_build_releasing(const rt_scene_desc *d, const char *name,
                                    const int *facet_lines,
                                    const rt_notes *notes,
                                    const rt_cancel *cancel,
                                    const rt_scene_release *release,
                                    rt_scene **out, rt_error *error,
                                    rt_refusal *refusal)
{
    *out = NULL;
    if (refusal != NULL)
        memset(refusal, 0, sizeof *refusal);
    check c = {name, error, refusal};
    rt_camera camera;
    rt_status status = check_desc(&c, d, &camera);
    if (status != RT_OK)
        return status;
    rt_scene *s = calloc(1, sizeof *s);
    if (s == NULL)
        return rt__error_set(error, RT_ERR_NOMEM, name, 0, 0, "out of memory");
    rt__scene_prepared_init(s);
    s->camera = camera;
    size_t nv = (size_t)d->vertex_count, nf = (size_t)d->facet_count;
    s->name = name ? strdup(name) : NULL;
    s->vertices = malloc((nv ? nv : 1) * sizeof *s->vertices);
    s->facets = malloc((nf ? nf : 1) * sizeof *s->facets);
    s->light_count = d->light_count;
    s->lights = malloc((size_t)s->light_count * sizeof *s->lights);
    if ((name && !s->name) || !s->vertices || !s->facets || !s->lights) {
        rt_scene_destroy(s);
        return rt__error_set(error, RT_ERR_NOMEM, name, 0, 0, "out of memory");
    }
    if (nv > 0)
        memcpy(s->vertices, d->vertices, nv * sizeof *s->vertices);
    if (d->normals != NULL && !rt__scene_copy_normals(s, d)) {
        rt_scene_destroy(s);
        return rt__error_set(error, RT_ERR_NOMEM, name, 0, 0, "out of memory");
    }
    s->vertex_count = d->vertex_count;
    s->facet_count = d->facet_count;
    s->background = d->background;
    memcpy(s->lights, d->lights, (size_t)s->light_count * sizeof *s->lights);
    if (d->aperture > 0.0)
        s->camera.aperture = d->aperture;
    if (d->focal_distance > 0.0)
        s->camera.focal_distance = d->focal_distance;
    s->focus_given = d->focal_distance > 0.0;
    s->up.axis = d->up_axis, s->up.cue = d->up_cue;
    s->up.line = d->up_cue_line;

    /* The reader's warnings, then the builder's, stored as they come. */
    rt_notes warnings;
    memset(&warnings, 0, sizeof warnings);
    rt__notes_append(&warnings, notes);
    /* The normals serve the warnings and the double kernel's build, then
     * go: the kernel keeps its own, the records none. */
    rt_vec3 *normals = malloc((nf ? nf : 1) * sizeof *normals);
    status = normals == NULL ? RT_ERR_NOMEM
                             : add_facets(s, d, name, facet_lines, &warnings,
                                          cancel, normals);
    if (status != RT_OK) {
        free(normals);
        rt__notes_free(&warnings);
        rt_scene_destroy(s);
        if (status == RT_ERR_CANCELLED)
            return rt__error_set(error, RT_ERR_CANCELLED, name, 0, 0,
                                 "the load was cancelled");
        return rt__error_set(error, RT_ERR_NOMEM, name, 0, 0,
                             "out of memory");
    }
    rt__notes_settle(&warnings);
    if (warnings.count > 0 && warnings.count < warnings.capacity) {
        rt_warning *fitted = realloc(warnings.items, (size_t)warnings.count *
                                                         sizeof *fitted);
        if (fitted != NULL)
            warnings.items = fitted;
    }
    s->warnings = warnings.items;
    s->warning_count = warnings.count;
    warnings.items = NULL;
    int failed = warnings.failed;
    rt__notes_free(&warnings);
    if (failed) {
        free(normals);
        rt_scene_destroy(s);
        return rt__error_set(error, RT_ERR_NOMEM, name, 0, 0, "out of memory");
    }
    /* The records hold all the kernel needs: the description can go. */
    if (release != NULL && release->release != NULL)
        release->release(release->user);
    rt_kernel_source source;
    rt__scene_kernel_source(s, &source);
    source.cancel = cancel;
    source.normals = normals;
    s->kernel = rt__kernel_double_ops.create(&source);
    free(normals);
    if (s->kernel == NULL) {
        rt_scene_destroy(s);
        if (rt_cancel_requested(cancel))
            return rt__error_set(error, RT_ERR_CANCELLED, name, 0, 0,
                                 "the load was cancelled");
        return rt__error_set(error, RT_ERR_NOMEM, name, 0, 0, "out of memory");
    }
    *out = s;
    return RT_OK;
}

size_t rt__scene_bytes(const rt_scene *s)
{
    return sizeof *s + (s->name ? strlen(s->name) + 1 : 0) +
           (size_t)s->vertex_count * sizeof *s->vertices *
               (s->vertex_normals != NULL ? 2 : 1) +
           (size_t)s->facet_count * sizeof *s->facets +
           (size_t)s->materials.count * sizeof *s->materials.items +
           (size_t)s->warning_count * sizeof *s->warnings +
           (size_t)s->light_count * sizeof *s->lights;
}

rt_status rt_scene_create(const rt_scene_desc *desc, rt_scene **scene,
                          rt_error *error)
{
    if (scene == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "expected a pointer to fill with the scene");
    *scene = NULL;
    if (desc == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "expected a scene description");
    return rt__scene_build(desc, NULL, NULL, NULL, NULL, scene, error, NULL);
}

void rt_scene_destroy(rt_scene *scene)
{
    if (scene == NULL)
        return;
    free(scene->name);
    free(scene->vertices);
    free(scene->vertex_normals);
    free(scene->facets);
    rt__materials_free(&scene->materials);
    free(scene->lights);
    rt__scene_prepared_free(scene);
    free(scene->warnings);
    for (int i = 0; i < scene->source_count; i++)
        free((char *)scene->sources[i].name);
    free(scene->sources);
    free(scene);
}

/* The least sizes of the filled structs: their layouts of 0.3
 * (raytrace/scene.h, above rt_facet_info). */
#define SCENE_INFO_SIZE_0_3                                                  \
    RT__FIELD_END(rt_scene_info, transparent_facet_count)
#define FACET_INFO_SIZE_0_3 RT__FIELD_END(rt_facet_info, diffuse)

void rt_scene_get_info(const rt_scene *s, rt_scene_info *info)
{
    if (!RT__EXPECT(info != NULL && info->size >= SCENE_INFO_SIZE_0_3))
        return;
    rt_scene_info full = {0};
    if (RT__EXPECT(s != NULL))
        full = (rt_scene_info){
            .width = s->camera.width,
            .height = s->camera.height,
            .vertex_count = s->vertex_count,
            .facet_count = s->facet_count,
            .live_facet_count = s->live_count,
            .reflective_facet_count = s->reflective_count,
            .warning_count = s->warning_count,
            .background = s->background,
            .camera = s->camera,
            .light_count = s->light_count,
            .transparent_facet_count = s->transparent_count,
            .smooth_facet_count = s->smooth_count,
            .highlight_facet_count = s->highlight_count, .up_axis = s->up.axis,
            .up_cue = s->up.cue, .up_cue_line = s->up.line};
    rt__sized_fill(info, &full, sizeof full);
}

/* The accessors' index rule: `i` in 0..count-1 of a scene (raytrace/scene.h:
 * asserted; with NDEBUG, a zero value instead). */
#define INDEX_OK(scene, i, count)                                            \
    RT__EXPECT((scene) != NULL && (i) >= 0 && (i) < (scene)->count)

rt_vec3 rt_scene_vertex(const rt_scene *scene, int i)
{
    if (!INDEX_OK(scene, i, vertex_count))
        return (rt_vec3){0.0, 0.0, 0.0};
    return scene->vertices[i];
}

void rt_scene_facet(const rt_scene *scene, int i, rt_facet_info *facet)
{
    if (!RT__EXPECT(facet != NULL && facet->size >= FACET_INFO_SIZE_0_3))
        return;
    rt_facet_info full = {0};
    if (INDEX_OK(scene, i, facet_count))
        rt__scene_facet_info(scene, i, &full);
    rt__sized_fill(facet, &full, sizeof *facet);
}

void rt__scene_facet_info(const rt_scene *s, int i, rt_facet_info *info)
{
    const rt_facet_record *record = &s->facets[i];
    const rt_material *m = &s->materials.items[record->material];
    memset(info, 0, sizeof *info);
    info->size = sizeof *info;
    memcpy(info->vertex, record->vertex, sizeof info->vertex);
    info->reflection = m->reflection;
    info->color = m->color;
    info->normal = rt__facet_normal(s->vertices[record->vertex[0]],
                                    s->vertices[record->vertex[1]],
                                    s->vertices[record->vertex[2]]);
    info->degenerate = record->degenerate;
    info->line = record->line;
    info->transparency = m->transparency;
    info->refractive_index = m->refractive_index;
    info->diffuse = m->diffuse;
    info->highlight = m->highlight;
    info->highlight_exponent = m->exponent;
    info->smooth = rt__scene_facet_smooth(s, record);
    for (int j = 0; j < 3 && info->smooth; j++)
        info->vertex_normal[j] = s->vertex_normals[record->vertex[j]];
}

void rt_scene_light(const rt_scene *scene, int i, rt_light *light)
{
    if (!RT__EXPECT(light != NULL))
        return;
    if (!INDEX_OK(scene, i, light_count)) {
        memset(light, 0, sizeof *light);
        return;
    }
    *light = scene->lights[i];
}

int rt_scene_source_count(const rt_scene *scene)
{
    return scene != NULL ? scene->source_count : 0;
}

const rt_scene_source *rt_scene_source_at(const rt_scene *scene, int i)
{
    if (!INDEX_OK(scene, i, source_count))
        return NULL;
    return &scene->sources[i];
}

void rt__scene_take_sources(rt_scene *scene, rt_scene_source *sources,
                            int count)
{
    for (int i = 0; i < scene->source_count; i++)
        free((char *)scene->sources[i].name);
    free(scene->sources);
    scene->sources = sources;
    scene->source_count = count;
}

const rt_warning *rt_scene_warning(const rt_scene *scene, int i)
{
    if (!INDEX_OK(scene, i, warning_count))
        return NULL;
    return &scene->warnings[i];
}

int rt_scene_nearest_hit(const rt_scene *scene, rt_ray ray, double t_max,
                         rt_hit *hit)
{
    rt_kernel_hit h;
    if (!RT__EXPECT(scene != NULL && hit != NULL) ||
        !rt__kernel_nearest_hit(scene->kernel, ray, t_max, &h))
        return 0;
    hit->t = h.t;
    hit->facet = h.facet;
    hit->point = h.point;
    hit->normal = h.normal;
    return 1;
}

int rt_scene_occluded(const rt_scene *scene, rt_vec3 from, rt_vec3 to,
                      int skip_facet)
{
    if (!RT__EXPECT(scene != NULL))
        return 0;
    return rt__kernel_occluded(scene->kernel, from, to, skip_facet);
}
