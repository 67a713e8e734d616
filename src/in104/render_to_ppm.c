/*
 * render_to_ppm.c - renderToPPM(), the extension of raytracer.h that renders
 * a handout scene with libraytrace and saves it as a P3 image.
 *
 * There is no second renderer: the scene struct is turned into an
 * rt_scene_desc (each facet gets its own three vertices, taken from its a,
 * b, c, so the facets array alone is the truth), built with
 * rt_scene_create, and rendered with rt_render.
 */
#include "raytracer.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>

#include "frame.h"
#include "raytrace/raytrace.h"

static rt_rgb8 to_rgb8(color c)
{
    rt_rgb8 result = {c.r, c.g, c.b};
    return result;
}

static int fail(rt_status status, const char *message)
{
    fprintf(stderr, "renderToPPM: %s\n", message);
    return (int)status;
}

/* Builds the core scene from s; prints and returns a status on failure. */
static rt_status build(const scene *s, rt_scene **built)
{
    int count = s->nbFacets;
    rt_vec3 *vertices = NULL;
    rt_facet_desc *facets = NULL;
    if (count > 0) {
        vertices = malloc((size_t)count * 3 * sizeof *vertices);
        facets = calloc((size_t)count, sizeof *facets);
        if (vertices == NULL || facets == NULL) {
            free(vertices);
            free(facets);
            return (rt_status)fail(RT_ERR_NOMEM, "out of memory");
        }
    }
    for (int i = 0; i < count; i++) {
        const facet *f = &s->facets[i];
        vertices[3 * i] = in104_vec(f->a);
        vertices[3 * i + 1] = in104_vec(f->b);
        vertices[3 * i + 2] = in104_vec(f->c);
        facets[i].vertex[0] = 3 * i;
        facets[i].vertex[1] = 3 * i + 1;
        facets[i].vertex[2] = 3 * i + 2;
        facets[i].reflection = f->k;
        facets[i].color = to_rgb8(f->cp);
    }

    rt_scene_desc desc = {0};
    desc.observer = in104_vec(s->obs);
    desc.screen_center = in104_vec(s->screenA);
    desc.screen_right = in104_vec(s->screenB);
    desc.width = s->width;
    desc.height = s->height;
    desc.vertices = vertices;
    desc.vertex_count = 3 * count;
    desc.facets = facets;
    desc.facet_count = count;
    desc.background = to_rgb8(s->back);
    rt_light light = {in104_vec(s->s.p), to_rgb8(s->s.cp)};
    desc.lights = &light;
    desc.light_count = 1;

    rt_error error;
    rt_status status = rt_scene_create(&desc, built, &error);
    free(vertices);
    free(facets);
    if (status != RT_OK)
        fail(status, error.message);
    return status;
}

int renderToPPM(const scene *s, const char *ppmFile)
{
    if (s == NULL || ppmFile == NULL)
        return fail(RT_ERR_ARGUMENT, s == NULL ? "no scene (NULL)"
                                               : "no file name (NULL)");
    if (s->nbFacets < 0 || s->nbFacets > INT_MAX / 3
        || (s->nbFacets > 0 && s->facets == NULL))
        return fail(RT_ERR_ARGUMENT, "nbFacets does not match facets");

    rt_scene *built = NULL;
    rt_status status = build(s, &built);
    if (status != RT_OK)
        return (int)status;

    rt_image image;
    status = rt_image_init(&image, s->width, s->height, NULL);
    if (status == RT_OK)
        status = rt_render(built, NULL, &image, NULL);
    rt_error error;
    if (status == RT_OK) {
        /* The course's programs are ended by Ctrl-C as any other: the
         * termination signals are held while the temporary file exists, so
         * that the old file stays and no temporary one is left behind. */
        rt_save_options save;
        rt_save_options_init(&save);
        save.hold_termination_signals = 1;
        status = rt_image_save(ppmFile, &image, RT_IMAGE_P3, &save, &error);
        if (status != RT_OK)
            fail(status, error.message);
    } else {
        fail(status, rt_status_string(status));
    }
    rt_image_release(&image);
    rt_scene_destroy(built);
    return (int)status;
}
