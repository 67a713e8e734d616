/*
 * view_explain.c - a clicked pixel's ray tree as overlay segments and text
 * (see view_explain.h); the text is rt-export --explain's, from the one
 * formatter (apps/common/cli_explain.h).
 */
#include "view_explain.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli_explain.h"

/* A ray that hits nothing is drawn this many |AO| far. */
#define MISS_DISTANCE 1000.0

static rt_vec3 point_along(rt_vec3 origin, rt_vec3 direction, double t)
{
    rt_vec3 p = {origin.x + t * direction.x, origin.y + t * direction.y,
                 origin.z + t * direction.z};
    return p;
}

/* The tree's text, as rt-export --explain prints it (cli_explain.h), in a
 * new string; NULL when out of memory. */
static char *explanation_text(const rt_ray_tree *tree, const char *name,
                              int x, int y, int samples)
{
    char *data = NULL;
    size_t length = 0;
    FILE *out = open_memstream(&data, &length);
    if (out == NULL)
        return NULL;
    cli_explain_print_text(out, tree, name, x, y, samples);
    int failed = ferror(out);
    if (fclose(out) != 0 || failed) {
        free(data);
        return NULL;
    }
    return data;
}

/* The segment `node` draws, 0 when none (a shadow ray not cast). */
static int segment_of(const rt_scene *scene, double miss_distance,
                      const rt_ray_node *node, view_segment *segment)
{
    segment->from = node->origin;
    segment->mark = 0;
    switch (node->kind) {
    case RT_RAY_SHADOW:
        if (!node->cast)
            return 0;
        if (node->e > 0) {
            segment->kind = VIEW_RAY_SHADOW;
            segment->to = point_along(node->origin, node->direction, 1);
            return 1;
        }
        /* Up to the blocker: the nearest hit before the light. */
        segment->kind = VIEW_RAY_BLOCKED;
        rt_ray ray = {node->origin, node->direction};
        rt_hit hit;
        if (rt_scene_nearest_hit(scene, ray, 1.0, &hit)) {
            segment->to = hit.point;
            segment->mark = 1;
        } else {
            segment->to = point_along(node->origin, node->direction, 1);
        }
        return 1;
    case RT_RAY_CAMERA:
        segment->kind = VIEW_RAY_CAMERA;
        break;
    case RT_RAY_REFLECTED:
        segment->kind = VIEW_RAY_REFLECTED;
        break;
    case RT_RAY_REFRACTED:
        segment->kind = VIEW_RAY_REFRACTED;
        break;
    }
    if (node->hit) {
        segment->to = node->point;
        segment->mark = 1;
    } else {
        double length = sqrt(node->direction.x * node->direction.x +
                             node->direction.y * node->direction.y +
                             node->direction.z * node->direction.z);
        segment->to = point_along(node->origin, node->direction,
                                  miss_distance / (length > 0 ? length : 1));
    }
    return 1;
}

rt_status view_explain_pixel(const rt_scene *scene,
                             const rt_render_options *options,
                             const char *name, int x, int y,
                             view_explanation *out, rt_error *error)
{
    memset(out, 0, sizeof *out);
    rt_ray_tree *tree;
    rt_status status = rt_explain_pixel(scene, options, x, y, -1, &tree,
                                        error);
    if (status != RT_OK)
        return status;
    size_t count;
    const rt_ray_node *nodes = rt_ray_tree_nodes(tree, &count);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    rt_vec3 ao = {info.camera.screen_center.x - info.camera.observer.x,
                  info.camera.screen_center.y - info.camera.observer.y,
                  info.camera.screen_center.z - info.camera.observer.z};
    double miss_distance =
        MISS_DISTANCE * sqrt(ao.x * ao.x + ao.y * ao.y + ao.z * ao.z);

    out->segments = count ? malloc(sizeof *out->segments * count) : NULL;
    for (size_t i = 0; i < count && out->segments; i++)
        if (segment_of(scene, miss_distance, &nodes[i],
                       &out->segments[out->segment_count]))
            out->segment_count++;
    out->x = x;
    out->y = y;
    out->value = rt_ray_tree_value(tree);
    if (count)
        out->first = nodes[0];
    out->text = explanation_text(tree, name, x, y,
                                 options ? options->samples : 1);
    rt_ray_tree_destroy(tree);
    if (out->text == NULL || (count && out->segments == NULL)) {
        view_explanation_release(out);
        if (error) {
            memset(error, 0, sizeof *error);
            error->status = RT_ERR_NOMEM;
            snprintf(error->message, sizeof error->message,
                     "out of memory");
        }
        return RT_ERR_NOMEM;
    }
    return RT_OK;
}

void view_explanation_release(view_explanation *explanation)
{
    free(explanation->segments);
    free(explanation->text);
    memset(explanation, 0, sizeof *explanation);
}
