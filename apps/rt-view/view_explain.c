/*
 * view_explain.c - a clicked pixel's ray tree as overlay segments and text
 * (see view_explain.h).
 */
#include "view_explain.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli_explain.h"

/* A ray that hits nothing is drawn this many |AO| far. */
#define MISS_DISTANCE 1000.0

/* A growing string. */
typedef struct text {
    char *data;
    size_t length, capacity;
    int failed;
} text;

static void append(text *t, const char *format, ...)
{
    if (t->failed)
        return;
    for (;;) {
        va_list args;
        va_start(args, format);
        int n = vsnprintf(t->data ? t->data + t->length : NULL,
                          t->data ? t->capacity - t->length : 0, format,
                          args);
        va_end(args);
        if (n < 0) {
            t->failed = 1;
            return;
        }
        if (t->data && t->length + (size_t)n < t->capacity) {
            t->length += (size_t)n;
            return;
        }
        size_t capacity = (t->capacity + (size_t)n + 1) * 2;
        char *data = realloc(t->data, capacity);
        if (data == NULL) {
            t->failed = 1;
            return;
        }
        t->data = data;
        t->capacity = capacity;
    }
}

static rt_vec3 point_along(rt_vec3 origin, rt_vec3 direction, double t)
{
    rt_vec3 p = {origin.x + t * direction.x, origin.y + t * direction.y,
                 origin.z + t * direction.z};
    return p;
}

static void describe_facet(text *t, int facet, int line)
{
    if (line > 0)
        append(t, "facet %d (line %d)", facet, line);
    else
        append(t, "facet %d", facet);
}

/* One line of the text for node i (its name as cli_explain_ray_name
 * gives it: the mirror ray of a total internal reflection is "totally
 * reflected", the t C_T term, not a k C_R one). */
static void describe(text *t, const rt_ray_node *nodes, size_t count,
                     size_t i)
{
    const rt_ray_node *node = &nodes[i];
    int indent = 2 * node->depth + (node->kind == RT_RAY_SHADOW ? 2 : 0);
    append(t, "%*s%s", indent, "", cli_explain_ray_name(nodes, count, i));
    if (node->kind == RT_RAY_SHADOW) {
        append(t, " to light %d: N.S %.4g", node->light, node->n_dot_s);
        if (!node->cast)
            append(t, ", not cast (faces away or d = 0): E 0\n");
        else if (node->e > 0)
            append(t, ", E %g: lit, adds (%.4g %.4g %.4g)\n", node->e,
                   node->own.r, node->own.g, node->own.b);
        else if (node->blocker >= 0) {
            append(t, ", E 0: shadowed by ");
            describe_facet(t, node->blocker, node->blocker_line);
            append(t, "\n");
        } else
            append(t, ", E 0\n");
        return;
    }
    if (cli_explain_total_reflection(nodes, count, i))
        append(t, " (weight %.4g, for k C_R + t C_T: a total internal "
                  "reflection)", node->weight);
    else if (node->weight != 1)
        append(t, " (weight %.4g)", node->weight);
    if (!node->hit) {
        append(t, ": hits nothing, background adds (%.4g %.4g %.4g)\n",
               node->own.r, node->own.g, node->own.b);
        return;
    }
    append(t, ": hits ");
    describe_facet(t, node->facet, node->line);
    append(t, " at t %.4g, point (%.4g %.4g %.4g), N (%.3f %.3f %.3f)",
           node->t, node->point.x, node->point.y, node->point.z,
           node->normal.x, node->normal.y, node->normal.z);
    if (node->k > 0 || node->transmission > 0)
        append(t, ", k %.3g t %.3g", node->k, node->transmission);
    append(t, "; carries (%.4g %.4g %.4g)\n", node->subtotal.r,
           node->subtotal.g, node->subtotal.b);
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
    rt_scene_info info;
    rt_scene_get_info(scene, &info);
    rt_vec3 ao = {info.camera.screen_center.x - info.camera.observer.x,
                  info.camera.screen_center.y - info.camera.observer.y,
                  info.camera.screen_center.z - info.camera.observer.z};
    double miss_distance =
        MISS_DISTANCE * sqrt(ao.x * ao.x + ao.y * ao.y + ao.z * ao.z);

    rt_color value = rt_ray_tree_value(tree);
    text t = {NULL, 0, 0, 0};
    append(&t, "%s pixel (%d, %d): (%.4g %.4g %.4g) -> (%d %d %d)\n", name,
           x, y, value.r, value.g, value.b, rt_channel_to_byte(value.r),
           rt_channel_to_byte(value.g), rt_channel_to_byte(value.b));
    out->segments = count ? malloc(sizeof *out->segments * count) : NULL;
    for (size_t i = 0; i < count; i++) {
        describe(&t, nodes, count, i);
        if (out->segments &&
            segment_of(scene, miss_distance, &nodes[i],
                       &out->segments[out->segment_count]))
            out->segment_count++;
    }
    if (rt_ray_tree_truncated(tree))
        append(&t, "(%zu more rays not recorded)\n",
               rt_ray_tree_truncated(tree));
    out->x = x;
    out->y = y;
    out->value = value;
    if (count)
        out->first = nodes[0];
    out->text = t.data;
    rt_ray_tree_destroy(tree);
    if (t.failed || (count && out->segments == NULL)) {
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
