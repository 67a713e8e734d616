/*
 * scene.c - building a scene from a description, and asking it questions.
 *
 * rt_scene_create is the one way scenes are made (the `.scn` parser is a
 * client of it).  Building checks the rules the renderer relies on, works
 * out the camera, drops zero-area facets from what the renderer sees (with a
 * warning), and precomputes per-facet data once.
 */
#include <assert.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "exact.h"
#include "formats/reader.h"
#include "scene_internal.h"
#include "vecmath.h"

/* Unit normal in the direction of (b - a) x (c - a), accurate for any
 * shape (slivers and needles included); zero for a zero-area facet. */
static rt_vec3 facet_normal(rt_vec3 a, rt_vec3 b, rt_vec3 c)
{
    return v3_normalize(rt__exact_cross(a, b, c));
}

static rt_status check_desc(const rt_scene_desc *d, rt_error *error)
{
    const char *what = NULL;
    if (d->width < 1 || d->width > RT_MAX_IMAGE_SIDE || d->height < 1 ||
        d->height > RT_MAX_IMAGE_SIDE)
        return rt__error_set(error, RT_ERR_RANGE, NULL, 0, 0,
                             "expected an image size in 1..%d, found %dx%d",
                             RT_MAX_IMAGE_SIDE, d->width, d->height);
    if (d->vertex_count < 0 || d->facet_count < 0 ||
        (d->vertex_count > 0 && d->vertices == NULL) ||
        (d->facet_count > 0 && d->facets == NULL))
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "expected vertex and facet arrays");
    if (d->more_light_count < 0 ||
        (d->more_light_count > 0 && d->more_lights == NULL))
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "expected an array of further lights");
    if (!v3_is_finite(d->observer) || !v3_is_finite(d->screen_center) ||
        !v3_is_finite(d->screen_right) || !v3_is_finite(d->light_position))
        what = "the camera and the light";
    for (int i = 0; what == NULL && i < d->more_light_count; i++)
        if (!v3_is_finite(d->more_lights[i].position))
            what = "every light";
    for (int i = 0; what == NULL && i < d->vertex_count; i++)
        if (!v3_is_finite(d->vertices[i]))
            what = "every vertex";
    if (what != NULL)
        return rt__error_set(error, RT_ERR_RANGE, NULL, 0, 0,
                             "expected finite coordinates for %s", what);
    double largest = fmax(v3_max_abs(d->observer),
                          fmax(v3_max_abs(d->screen_center),
                               v3_max_abs(d->screen_right)));
    for (int i = 0; i < d->vertex_count; i++)
        largest = fmax(largest, v3_max_abs(d->vertices[i]));
    if (largest > RT_MAX_COORDINATE)
        return rt__error_set(error, RT_ERR_RANGE, NULL, 0, 0,
                             "expected coordinates of magnitude at most %g, "
                             "found %g: the arithmetic of the renderer "
                             "cannot hold such a scene", RT_MAX_COORDINATE,
                             largest);
    for (int i = 0; i < d->facet_count; i++) {
        const rt_facet_desc *f = &d->facets[i];
        for (int j = 0; j < 3; j++)
            if (f->vertex[j] < 0 || f->vertex[j] >= d->vertex_count)
                return rt__error_set(error, RT_ERR_RANGE, NULL, 0, 0,
                                     "facet %d: expected a vertex index in "
                                     "0..%d, found %d",
                                     i, d->vertex_count - 1, f->vertex[j]);
        if (!(f->k >= 0.0 && f->k <= 1.0))
            return rt__error_set(error, RT_ERR_RANGE, NULL, 0, 0,
                                 "facet %d: expected k in [0, 1], found %g",
                                 i, f->k);
        if (!(f->t >= 0.0 && f->t <= 1.0 - f->k))
            return rt__error_set(error, RT_ERR_RANGE, NULL, 0, 0,
                                 "facet %d: expected a transparency t in "
                                 "[0, 1 - k] = [0, %g], found %g",
                                 i, 1.0 - f->k, f->t);
        if (!(f->n >= 0.0 && isfinite(f->n)))
            return rt__error_set(error, RT_ERR_RANGE, NULL, 0, 0,
                                 "facet %d: expected a refractive index "
                                 "n > 0, found %g", i, f->n);
        if (f->d_given && !(f->d >= 0.0 && isfinite(f->d)))
            return rt__error_set(error, RT_ERR_RANGE, NULL, 0, 0,
                                 "facet %d: expected a diffuse weight "
                                 "d >= 0, found %g", i, f->d);
    }
    if (!(d->aperture >= 0.0 && isfinite(d->aperture)))
        return rt__error_set(error, RT_ERR_RANGE, NULL, 0, 0,
                             "expected an aperture a >= 0, found %g",
                             d->aperture);
    if (!(d->focal_distance >= 0.0 && isfinite(d->focal_distance)))
        return rt__error_set(error, RT_ERR_RANGE, NULL, 0, 0,
                             "expected a focal distance f > 0 (or 0 for "
                             "|AO|), found %g", d->focal_distance);
    return RT_OK;
}

static void add_degenerate_warning(rt_scene *s, int facet, int line)
{
    rt_warning *w = &s->warnings[s->warning_count++];
    w->line = line;
    w->column = line > 0 ? 1 : 0;
    const char *name = s->name ? s->name : "<memory>";
    if (line > 0)
        snprintf(w->message, sizeof w->message,
                 "%s:%d:1: warning: facet %d has zero area (its vertices are "
                 "collinear); it is never hit",
                 name, line, facet + 1);
    else
        snprintf(w->message, sizeof w->message,
                 "%s: warning: facet %d has zero area (its vertices are "
                 "collinear); it is never hit",
                 name, facet + 1);
}

rt_status rt__scene_build(const rt_scene_desc *d, const char *name,
                          const int *facet_lines, const rt_notes *notes,
                          rt_scene **out, rt_error *error)
{
    *out = NULL;
    rt_status status = check_desc(d, error);
    if (status != RT_OK)
        return status;
    rt_scene *s = calloc(1, sizeof *s);
    if (s == NULL)
        return rt__error_set(error, RT_ERR_NOMEM, name, 0, 0, "out of memory");
    atomic_init(&s->kernel_f, NULL);
    pthread_mutex_init(&s->kernel_lock, NULL);
    const char *reason = rt__camera_make(d->observer, d->screen_center,
                                         d->screen_right, d->width, d->height,
                                         &s->camera);
    if (reason != NULL) {
        rt_scene_destroy(s);
        return rt__error_set(error, RT_ERR_CAMERA, name, 0, 0,
                             "expected a camera, found that %s", reason);
    }
    size_t nv = (size_t)d->vertex_count, nf = (size_t)d->facet_count;
    s->name = name ? strdup(name) : NULL;
    s->vertices = malloc((nv ? nv : 1) * sizeof *s->vertices);
    s->facets = malloc((nf ? nf : 1) * sizeof *s->facets);
    size_t noted = notes ? (size_t)notes->count : 0;
    s->warnings = malloc((nf + noted ? nf + noted : 1) * sizeof *s->warnings);
    s->light_count = 1 + d->more_light_count;
    s->lights = malloc((size_t)s->light_count * sizeof *s->lights);
    if ((name && !s->name) || !s->vertices || !s->facets ||
        !s->warnings || !s->lights) {
        rt_scene_destroy(s);
        return rt__error_set(error, RT_ERR_NOMEM, name, 0, 0, "out of memory");
    }
    if (nv > 0)
        memcpy(s->vertices, d->vertices, nv * sizeof *s->vertices);
    s->vertex_count = d->vertex_count;
    s->facet_count = d->facet_count;
    if (noted > 0)
        memcpy(s->warnings, notes->items, noted * sizeof *s->warnings);
    s->warning_count = (int)noted;
    s->background = d->background;
    s->lights[0] = (rt_light){d->light_position, d->light_color};
    for (int i = 0; i < d->more_light_count; i++)
        s->lights[1 + i] = d->more_lights[i];
    if (d->aperture > 0.0)
        s->camera.aperture = d->aperture;
    if (d->focal_distance > 0.0)
        s->camera.focal_distance = d->focal_distance;

    for (int i = 0; i < d->facet_count; i++) {
        const rt_facet_desc *f = &d->facets[i];
        rt_facet_info *info = &s->facets[i];
        rt_vec3 a = d->vertices[f->vertex[0]], b = d->vertices[f->vertex[1]],
                c = d->vertices[f->vertex[2]];
        memcpy(info->vertex, f->vertex, sizeof info->vertex);
        info->k = f->k;
        info->t = f->t;
        info->n = f->n > 0.0 ? f->n : 1.0;
        info->d = f->d_given ? f->d : 1.0 - f->k - f->t;
        info->color = f->color;
        info->line = facet_lines ? facet_lines[i] : 0;
        info->normal = facet_normal(a, b, c);
        info->degenerate = v3_max_abs(info->normal) == 0.0;
        if (info->degenerate) {
            add_degenerate_warning(s, i, info->line);
            continue;
        }
        s->live_count++;
        s->reflective_count += f->k > 0.0;
        s->transparent_count += f->t > 0.0;
    }
    rt_kernel_source source;
    rt__scene_kernel_source(s, &source);
    s->kernel = rt__kernel_d_create(&source);
    if (s->kernel == NULL) {
        rt_scene_destroy(s);
        return rt__error_set(error, RT_ERR_NOMEM, name, 0, 0, "out of memory");
    }
    *out = s;
    return RT_OK;
}

rt_status rt_scene_create(const rt_scene_desc *desc, rt_scene **scene,
                          rt_error *error)
{
    if (scene == NULL)
        return RT_ERR_ARGUMENT;
    *scene = NULL;
    if (desc == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "expected a scene description");
    return rt__scene_build(desc, NULL, NULL, NULL, scene, error);
}

void rt_scene_destroy(rt_scene *scene)
{
    if (scene == NULL)
        return;
    free(scene->name);
    free(scene->vertices);
    free(scene->facets);
    free(scene->lights);
    rt__kernel_d_free(scene->kernel);
    rt__kernel_f_free(atomic_load(&scene->kernel_f));
    pthread_mutex_destroy(&scene->kernel_lock);
    free(scene->warnings);
    for (int i = 0; i < scene->source_count; i++)
        free((char *)scene->sources[i].name);
    free(scene->sources);
    free(scene);
}

void rt_scene_get_info(const rt_scene *s, rt_scene_info *info)
{
    memset(info, 0, sizeof *info);
    info->width = s->camera.width;
    info->height = s->camera.height;
    info->vertex_count = s->vertex_count;
    info->facet_count = s->facet_count;
    info->live_facet_count = s->live_count;
    info->reflective_facet_count = s->reflective_count;
    info->warning_count = s->warning_count;
    info->background = s->background;
    info->light_position = s->lights[0].position;
    info->light_color = s->lights[0].color;
    info->camera = s->camera;
    info->light_count = s->light_count;
    info->transparent_facet_count = s->transparent_count;
}

rt_vec3 rt_scene_vertex(const rt_scene *scene, int i)
{
    return scene->vertices[i];
}

void rt_scene_facet(const rt_scene *scene, int i, rt_facet_info *facet)
{
    *facet = scene->facets[i];
}

void rt_scene_light(const rt_scene *scene, int i, rt_light *light)
{
    *light = scene->lights[i];
}

int rt_scene_source_count(const rt_scene *scene)
{
    return scene != NULL ? scene->source_count : 0;
}

const rt_scene_source *rt_scene_source_at(const rt_scene *scene, int i)
{
    assert(scene != NULL && i >= 0 && i < scene->source_count);
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
    return &scene->warnings[i];
}

void rt__scene_kernel_source(const rt_scene *s, rt_kernel_source *source)
{
    source->vertices = s->vertices;
    source->facets = s->facets;
    source->facet_count = s->facet_count;
    source->lights = s->lights;
    source->light_count = s->light_count;
    source->background = s->background;
}

const rt_kernel_f *rt__scene_kernel_f(const rt_scene *scene)
{
    rt_scene *s = (rt_scene *)scene;   /* only the lazy kernel changes */
    rt_kernel_f *k = atomic_load_explicit(&s->kernel_f, memory_order_acquire);
    if (k != NULL)
        return k;
    pthread_mutex_lock(&s->kernel_lock);
    k = atomic_load_explicit(&s->kernel_f, memory_order_relaxed);
    if (k == NULL) {
        rt_kernel_source source;
        rt__scene_kernel_source(scene, &source);
        k = rt__kernel_f_create(&source);
        atomic_store_explicit(&s->kernel_f, k, memory_order_release);
    }
    pthread_mutex_unlock(&s->kernel_lock);
    return k;
}

int rt_scene_nearest_hit(const rt_scene *scene, rt_ray ray, double t_max,
                         rt_hit *hit)
{
    rt_kernel_hit h;
    if (!rt__kernel_d_nearest_hit(scene->kernel, ray, t_max, &h))
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
    return rt__kernel_d_occluded(scene->kernel, from, to, skip_facet);
}
