/*
 * view_scene.c - loading a scene at another resolution and naming the image
 * saved beside it (see view_scene.h).  Only the library's public API is
 * used: the scene is read back through rt_scene_get_info, rt_scene_vertex and
 * rt_scene_facet and rebuilt with rt_scene_create.
 */
#include "view_scene.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static rt_status fail(rt_error *error, rt_status status, const char *name,
                      const char *message)
{
    if (error) {
        error->status = status;
        error->line = 0;
        error->column = 0;
        snprintf(error->message, sizeof error->message, "%s: %s",
                 name ? name : "<scene>", message);
    }
    return status;
}

/* Turns error->message into "name: message", truncated to fit. */
static void prefix_message(rt_error *error, const char *name)
{
    char message[RT_ERROR_MESSAGE_SIZE];
    memcpy(message, error->message, sizeof message);
    message[sizeof message - 1] = '\0';
    size_t size = sizeof error->message;
    size_t used = strlen(name);
    if (used > size - 3)
        used = size - 3;
    memcpy(error->message, name, used);
    memcpy(error->message + used, ": ", 2);
    used += 2;
    size_t rest = strlen(message);
    if (rest > size - 1 - used)
        rest = size - 1 - used;
    memcpy(error->message + used, message, rest);
    error->message[used + rest] = '\0';
}

static int scaled_side(int side, double scale)
{
    double value = floor((double)side * scale + 0.5);
    if (value < 1.0)
        return 1;
    if (value > (double)RT_MAX_IMAGE_SIDE + 1.0)
        return RT_MAX_IMAGE_SIDE + 1;
    return (int)value;
}

rt_status view_scene_rescale(const rt_scene *scene, const char *name,
                             double scale, rt_scene **scaled, rt_error *error)
{
    *scaled = NULL;
    if (!(scale >= VIEW_MIN_SCALE && scale <= VIEW_MAX_SCALE))
        return fail(error, RT_ERR_ARGUMENT, name, "scale out of range");
    rt_scene_info info;
    rt_scene_get_info(scene, &info);
    int width = scaled_side(info.width, scale);
    int height = scaled_side(info.height, scale);
    if (width > RT_MAX_IMAGE_SIDE || height > RT_MAX_IMAGE_SIDE) {
        char message[160];
        snprintf(message, sizeof message,
                 "%gx the size %dx%d exceeds the limit of %d pixels a side",
                 scale, info.width, info.height, RT_MAX_IMAGE_SIDE);
        return fail(error, RT_ERR_LIMIT, name, message);
    }

    rt_vec3 *vertices = malloc(sizeof *vertices *
                               (size_t)(info.vertex_count + 1));
    rt_facet_desc *facets = malloc(sizeof *facets *
                                   (size_t)(info.facet_count + 1));
    if (vertices == NULL || facets == NULL) {
        free(vertices);
        free(facets);
        return fail(error, RT_ERR_NOMEM, name, "out of memory");
    }
    for (int i = 0; i < info.vertex_count; i++)
        vertices[i] = rt_scene_vertex(scene, i);
    for (int i = 0; i < info.facet_count; i++) {
        rt_facet_info facet;
        rt_scene_facet(scene, i, &facet);
        memcpy(facets[i].vertex, facet.vertex, sizeof facets[i].vertex);
        facets[i].k = facet.k;
        facets[i].color = facet.color;
        facets[i].t = facet.t;
        facets[i].n = facet.n;
        facets[i].d = facet.d;
        facets[i].d_given = 1;
    }
    rt_light *more_lights =
        malloc((size_t)(info.light_count > 1 ? info.light_count - 1 : 1) *
               sizeof *more_lights);
    if (more_lights == NULL) {
        free(vertices);
        free(facets);
        return fail(error, RT_ERR_NOMEM, name, "out of memory");
    }
    for (int i = 1; i < info.light_count; i++)
        rt_scene_light(scene, i, &more_lights[i - 1]);
    const rt_camera *camera = &info.camera;
    rt_scene_desc desc = {
        .observer = camera->observer,
        .screen_center = camera->screen_center,
        .screen_right = {camera->screen_center.x + camera->right.x,
                         camera->screen_center.y + camera->right.y,
                         camera->screen_center.z + camera->right.z},
        .width = width,
        .height = height,
        .vertices = vertices,
        .vertex_count = info.vertex_count,
        .facets = facets,
        .facet_count = info.facet_count,
        .background = info.background,
        .light_position = info.light_position,
        .light_color = info.light_color,
        .more_lights = more_lights,
        .more_light_count = info.light_count - 1,
        .aperture = camera->aperture,
        .focal_distance = camera->focal_distance,
    };
    rt_status status = rt_scene_create(&desc, scaled, error);
    free(vertices);
    free(facets);
    free(more_lights);
    if (status != RT_OK && error)
        prefix_message(error, name ? name : "<scene>");
    return status;
}

rt_status view_scene_load(const char *path, double scale, rt_scene **scene,
                          rt_error *error)
{
    return view_scene_load_with(path, scale, NULL, scene, error);
}

rt_status view_scene_load_with(const char *path, double scale,
                               const rt_load_options *options,
                               rt_scene **scene, rt_error *error)
{
    *scene = NULL;
    if (!(scale >= VIEW_MIN_SCALE && scale <= VIEW_MAX_SCALE))
        return fail(error, RT_ERR_ARGUMENT, path, "scale out of range");
    rt_scene *loaded = NULL;
    rt_status status = rt_scene_load_with(path, options, &loaded, error);
    if (status != RT_OK || scale == 1.0) {
        *scene = loaded;
        return status;
    }
    status = view_scene_rescale(loaded, path, scale, scene, error);
    rt_scene_free(loaded);
    return status;
}

int view_scene_image_path(const char *scene_path, const char *extension,
                          char *buffer, size_t size)
{
    const char *slash = strrchr(scene_path, '/');
    const char *base = slash ? slash + 1 : scene_path;
    const char *dot = strrchr(base, '.');
    size_t keep = strlen(scene_path);
    if (dot && dot != base && strcmp(dot, ".scn") == 0)
        keep = (size_t)(dot - scene_path);
    int written = snprintf(buffer, size, "%.*s%s", (int)keep, scene_path,
                           extension);
    return written >= 0 && (size_t)written < size;
}
