/*
 * parse.c - parse() of the IN 104 handout (raytracer.h): a .scn file into
 * the handout's scene struct.
 *
 * The file is read by libraytrace's own loader (rt_scene_load), so parse
 * accepts exactly the files the library accepts and rejects the others with
 * the same message; this file only copies the loaded scene into the
 * handout's arrays and prints the loader's messages on stderr.
 */
#include "raytracer.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "frame.h"
#include "raytrace/raytrace.h"

static color to_color(rt_rgb8 c)
{
    color result = {c.r, c.g, c.b};
    return result;
}

static void release(scene *s)
{
    free(s->points);
    free(s->facets);
    memset(s, 0, sizeof *s);
}

/* Copies vertices and facets of `loaded` into s; 0 when out of memory. */
static int copy_geometry(const rt_scene *loaded, const rt_scene_info *info,
                         scene *s)
{
    if (info->vertex_count > 0) {
        s->points = malloc((size_t)info->vertex_count * sizeof *s->points);
        if (s->points == NULL)
            return 0;
    }
    if (info->facet_count > 0) {
        s->facets = malloc((size_t)info->facet_count * sizeof *s->facets);
        if (s->facets == NULL)
            return 0;
    }
    s->nbPoints = info->vertex_count;
    s->nbFacets = info->facet_count;
    for (int i = 0; i < info->vertex_count; i++)
        s->points[i] = in104_point(rt_scene_vertex(loaded, i));
    for (int i = 0; i < info->facet_count; i++) {
        rt_facet_info record = {.size = sizeof record};
        rt_scene_facet(loaded, i, &record);
        facet *f = &s->facets[i];
        f->a = s->points[record.vertex[0]];
        f->b = s->points[record.vertex[1]];
        f->c = s->points[record.vertex[2]];
        f->k = record.reflection;
        f->cp = to_color(record.color);
        /* The normal createFacet() gives, so both agree to the last bit. */
        in104_frame frame;
        in104__frame_make(&frame, f->a, f->b, f->c);
        f->n = in104_point(frame.unit);
    }
    return 1;
}

/* What of the model beyond the handout the facets and vertices use (the
 * handout's facet has k and a colour, d = 1 - k, and flat normals): bits
 * 1 a diffuse weight of its own, 2 a highlight, 4 a vertex normal. */
static int model_extensions(const rt_scene *loaded, const rt_scene_info *info)
{
    int used = 0;
    for (int i = 0; i < info->facet_count; i++) {
        rt_facet_info f = {.size = sizeof f};
        rt_scene_facet(loaded, i, &f);
        if (f.diffuse != 1.0 - f.reflection - f.transparency)
            used |= 1;
        if (f.highlight != 0.0 || f.highlight_exponent != 1.0)
            used |= 2;
    }
    for (int i = 0; i < info->vertex_count && !(used & 4); i++) {
        rt_vec3 n = rt_scene_vertex_normal(loaded, i);
        if (n.x != 0.0 || n.y != 0.0 || n.z != 0.0)
            used |= 4;
    }
    return used;
}

int parse(char *fname, scene *s)
{
    if (s != NULL)
        memset(s, 0, sizeof *s);
    if (s == NULL || fname == NULL) {
        fprintf(stderr, "parse: %s\n",
                s == NULL ? "no scene to fill (NULL)" : "no file name (NULL)");
        return RT_ERR_ARGUMENT;
    }

    rt_scene *loaded = NULL;
    rt_error error;
    rt_status status = rt_scene_load(fname, NULL, &loaded, &error);
    if (status != RT_OK) {
        fprintf(stderr, "%s\n", error.message);
        return (int)status;
    }

    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(loaded, &info);
    int used = model_extensions(loaded, &info);
    if (info.light_count > 1 || info.transparent_facet_count > 0 ||
        info.camera.aperture > 0.0 || used != 0) {
        fprintf(stderr,
                "%s: uses extensions beyond the handout (%s%s%s%s%s%s); the "
                "course's scene has one light, no transparency, a pinhole "
                "camera, d = 1 - k, no highlights and flat facets: render "
                "it with rt-export\n",
                fname, info.light_count > 1 ? "several lights " : "",
                info.transparent_facet_count > 0 ? "transparent facets " : "",
                info.camera.aperture > 0.0 ? "a lens aperture " : "",
                used & 1 ? "diffuse weights " : "",
                used & 2 ? "highlights " : "",
                used & 4 ? "vertex normals" : "");
        rt_scene_destroy(loaded);
        return RT_ERR_FORMAT;
    }
    for (int i = 0; i < info.warning_count; i++)
        fprintf(stderr, "%s\n", rt_scene_warning(loaded, i)->message);

    if (!copy_geometry(loaded, &info, s)) {
        release(s);
        rt_scene_destroy(loaded);
        fprintf(stderr, "%s: %s\n", fname, rt_status_string(RT_ERR_NOMEM));
        return RT_ERR_NOMEM;
    }
    s->width = info.width;
    s->height = info.height;
    s->back = to_color(info.background);
    s->obs = in104_point(info.camera.observer);
    s->screenA = in104_point(info.camera.screen_center);
    s->screenB = in104_point(v3_add(info.camera.screen_center,
                                    info.camera.right));
    rt_light light;
    rt_scene_light(loaded, 0, &light);
    s->s.p = in104_point(light.position);
    s->s.cp = to_color(light.color);
    rt_scene_destroy(loaded);
    return 0;
}
