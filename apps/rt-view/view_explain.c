/*
 * view_explain.c - a clicked pixel's ray tree as overlay segments and text,
 * one sample drawn at a time, and the text panel's part of it (see
 * view_explain.h); the text is rt-export --explain's, from the one
 * formatter (apps/common/cli_explain.h).
 */
#include "view_explain.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli_explain.h"

/* A ray that hits nothing is drawn this many |AO| far. */
#define MISS_DISTANCE 1000.0

/* Squared distances (in pixels) closer than this are equally near: a
 * sample's point is read back from its ray, a few ulps off the grid, and
 * the centre of a pixel of a regular 2 x 2 grid must give sample 0, not
 * whichever rounding favours. */
#define NEAR_TIE 1e-9

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

static rt_status out_of_memory(rt_error *error)
{
    if (error) {
        memset(error, 0, sizeof *error);
        error->status = RT_ERR_NOMEM;
        snprintf(error->message, sizeof error->message, "out of memory");
    }
    return RT_ERR_NOMEM;
}

/* How far the overlay draws a ray that hits nothing: MISS_DISTANCE |AO|. */
static double miss_distance_of(const view_projection *projection)
{
    const rt_camera *camera = &projection->camera;
    rt_vec3 ao = {camera->screen_center.x - camera->observer.x,
                  camera->screen_center.y - camera->observer.y,
                  camera->screen_center.z - camera->observer.z};
    return MISS_DISTANCE * sqrt(ao.x * ao.x + ao.y * ao.y + ao.z * ao.z);
}

/* Makes `tree` (one sample's, or the pixel's when it has one sample) the
 * one drawn; `tree` stays the caller's.  0 when out of memory (then the
 * explanation is as it was). */
static int take_sample_tree(const rt_scene *scene,
                            const view_projection *projection,
                            const char *name, const rt_ray_tree *tree,
                            int sample, view_explanation *e)
{
    size_t count;
    const rt_ray_node *nodes = rt_ray_tree_nodes(tree, &count);
    double miss_distance = miss_distance_of(projection);
    view_segment *segments =
        count ? malloc(sizeof *segments * count) : NULL;
    int segment_count = 0;
    for (size_t i = 0; i < count && segments; i++)
        if (segment_of(scene, miss_distance, &nodes[i],
                       &segments[segment_count]))
            segment_count++;
    char *text = explanation_text(tree, name, e->x, e->y, e->samples);
    if (text == NULL || (count && segments == NULL)) {
        free(segments);
        free(text);
        return 0;
    }
    free(e->segments);
    free(e->sample_text);
    free(e->panel);
    e->panel = NULL;
    e->segments = segments;
    e->segment_count = segment_count;
    e->sample_text = text;
    e->sample = sample;
    e->sample_value = rt_ray_tree_value(tree);
    memset(&e->first, 0, sizeof e->first);
    if (count)
        e->first = nodes[0];
    return 1;
}

/* points[k] from sample k's camera ray (the pixel's centre should the ray
 * not go forwards). */
static void set_point(const view_projection *projection,
                      const rt_ray_node *ray, view_explanation *e)
{
    int k = ray->sample;
    if (k < 0 || k >= e->samples)
        return;
    if (!view_project_camera_ray(projection, ray->origin, ray->direction,
                                 &e->points[k][0], &e->points[k][1])) {
        e->points[k][0] = e->x + 0.5;
        e->points[k][1] = e->y + 0.5;
    }
}

/* Each sample's point, from the camera rays of the pixel's tree; a sample
 * whose camera ray the tree had no room for (a tree cut at
 * RT_RAY_TREE_MAX_NODES) is traced alone, at depth 0, for its camera ray.
 * 0 when out of memory; a failed trace leaves the pixel's centre. */
static int find_points(const rt_scene *scene,
                       const rt_render_options *options,
                       const view_projection *projection,
                       const rt_ray_tree *tree, view_explanation *e)
{
    e->points = malloc(sizeof *e->points * (size_t)e->samples);
    char *found = calloc((size_t)e->samples, 1);
    if (e->points == NULL || found == NULL) {
        free(found);
        return 0;
    }
    size_t count;
    const rt_ray_node *nodes = rt_ray_tree_nodes(tree, &count);
    for (size_t i = 0; i < count; i++)
        if (nodes[i].kind == RT_RAY_CAMERA && nodes[i].sample >= 0 &&
            nodes[i].sample < e->samples) {
            set_point(projection, &nodes[i], e);
            found[nodes[i].sample] = 1;
        }
    rt_render_options shallow;
    rt_render_options_init(&shallow);
    if (options)
        shallow = *options;
    shallow.max_depth = 0;
    for (int k = 0; k < e->samples; k++) {
        if (found[k])
            continue;
        e->points[k][0] = e->x + 0.5;
        e->points[k][1] = e->y + 0.5;
        rt_ray_tree *alone;
        if (rt_explain_pixel(scene, &shallow, e->x, e->y, k, &alone, NULL) !=
            RT_OK)
            continue;
        size_t n;
        const rt_ray_node *ray = rt_ray_tree_nodes(alone, &n);
        if (n && ray[0].kind == RT_RAY_CAMERA)
            set_point(projection, &ray[0], e);
        rt_ray_tree_destroy(alone);
    }
    free(found);
    return 1;
}

/* The pixel (floor) of an image coordinate; -1 when it is none (NaN, or
 * beyond any image: rt_explain_pixel then refuses the pixel). */
static int pixel_of(double coordinate)
{
    if (!(coordinate >= 0) || coordinate >= (double)INT_MAX)
        return -1;
    return (int)floor(coordinate);
}

rt_status view_explain_point(const rt_scene *scene,
                             const rt_render_options *options,
                             const char *name, double px, double py,
                             view_explanation *out, rt_error *error)
{
    memset(out, 0, sizeof *out);
    int x = pixel_of(px), y = pixel_of(py);
    rt_ray_tree *tree;
    rt_status status = rt_explain_pixel(scene, options, x, y, -1, &tree,
                                        error);
    if (status != RT_OK)
        return status;
    rt_render_options defaults;
    rt_render_options_init(&defaults);
    if (options == NULL)
        options = &defaults;
    view_projection projection;
    view_projection_init(&projection, scene, options);
    out->x = x;
    out->y = y;
    out->samples = options->samples > 1 ? options->samples : 1;
    out->value = rt_ray_tree_value(tree);
    out->text = explanation_text(tree, name, x, y, out->samples);
    int ok = out->text != NULL &&
             find_points(scene, options, &projection, tree, out);
    if (ok && out->samples == 1)
        ok = take_sample_tree(scene, &projection, name, tree, 0, out);
    rt_ray_tree_destroy(tree);
    if (ok && out->samples > 1) {
        int sample = view_explanation_nearest_sample(out, px, py);
        status = view_explanation_show_sample(scene, options, name, out,
                                              sample, error);
        if (status != RT_OK) {
            view_explanation_release(out);
            return status;
        }
    }
    if (!ok) {
        view_explanation_release(out);
        return out_of_memory(error);
    }
    return RT_OK;
}

rt_status view_explain_pixel(const rt_scene *scene,
                             const rt_render_options *options,
                             const char *name, int x, int y,
                             view_explanation *out, rt_error *error)
{
    return view_explain_point(scene, options, name, x + 0.5, y + 0.5, out,
                              error);
}

rt_status view_explanation_show_sample(const rt_scene *scene,
                                       const rt_render_options *options,
                                       const char *name,
                                       view_explanation *explanation,
                                       int sample, rt_error *error)
{
    rt_ray_tree *tree;
    rt_status status = rt_explain_pixel(scene, options, explanation->x,
                                        explanation->y, sample, &tree,
                                        error);
    if (status != RT_OK)
        return status;
    rt_render_options defaults;
    rt_render_options_init(&defaults);
    view_projection projection;
    view_projection_init(&projection, scene, options ? options : &defaults);
    int ok = take_sample_tree(scene, &projection, name, tree, sample,
                              explanation);
    rt_ray_tree_destroy(tree);
    return ok ? RT_OK : out_of_memory(error);
}

int view_explanation_nearest_sample(const view_explanation *explanation,
                                    double px, double py)
{
    int nearest = 0;
    double best = INFINITY;
    for (int k = 0; k < explanation->samples && explanation->points; k++) {
        double dx = explanation->points[k][0] - px;
        double dy = explanation->points[k][1] - py;
        double d = dx * dx + dy * dy;
        if (d < best - NEAR_TIE) {
            best = d;
            nearest = k;
        }
    }
    return nearest;
}

/* The rows one line of `length` bytes takes wrapped at `columns`. */
static int line_rows(const char *line, size_t length, int columns)
{
    int used = 0, rows = 1;
    size_t i = 0;
    while (i < length) {
        size_t spaces = 0, word = 0;
        while (i + spaces < length && line[i + spaces] == ' ')
            spaces++;
        while (i + spaces + word < length && line[i + spaces + word] != ' ')
            word++;
        int need = (int)(spaces + word);
        if (used > 0 && used + need > columns) {
            rows++;                 /* the word starts a row, unspaced */
            used = 0;
            need = (int)word;
        }
        while (need > columns) {    /* a word wider than a row */
            rows++;
            need -= columns;
        }
        used += need;
        i += spaces + word;
    }
    return rows;
}

/* The length of the line at `p` (without its newline), and where the next
 * one starts in *next. */
static size_t line_at(const char *p, const char **next)
{
    size_t length = strcspn(p, "\n");
    *next = p + length + (p[length] == '\n');
    return length;
}

int view_text_rows(const char *text, int columns)
{
    if (columns < 1)
        columns = 1;
    int rows = 0;
    for (const char *p = text, *next; *p; p = next) {
        size_t length = line_at(p, &next);
        rows += line_rows(p, length, columns);
    }
    return rows;
}

char *view_explanation_panel(const view_explanation *e, int columns,
                             int rows)
{
    if (e->sample_text == NULL)
        return NULL;
    if (columns < 1)
        columns = 1;
    char *data = NULL;
    size_t size = 0;
    FILE *out = open_memstream(&data, &size);
    if (out == NULL)
        return NULL;
    /* rt-view's lines, then those of the sample's own tree after its
     * camera ray (drawn as the clicked point): the formatter's line 0 is
     * the formula, line 1 (with several samples: "sample K:", which
     * rt-view's line replaces) or 2 the camera ray; with several samples
     * the last, the value line, is left out too: rt-view's first line
     * gives the pixel's, the value rt-export's text gives. */
    char head[256];
    if (e->samples > 1)
        snprintf(head, sizeof head,
                 "pixel %d,%d: bytes %d %d %d (mean of %d samples)\n"
                 "sample %d of %d (Tab: next, Shift+Tab: previous):\n",
                 e->x, e->y, rt_channel_to_byte(e->value.r),
                 rt_channel_to_byte(e->value.g),
                 rt_channel_to_byte(e->value.b), e->samples, e->sample,
                 e->samples);
    else
        snprintf(head, sizeof head, "pixel %d,%d: bytes %d %d %d\n", e->x,
                 e->y, rt_channel_to_byte(e->value.r),
                 rt_channel_to_byte(e->value.g),
                 rt_channel_to_byte(e->value.b));
    fputs(head, out);
    int used = view_text_rows(head, columns);
    int count = 0, total = 0;
    int first = e->samples > 1 ? 3 : 2;
    for (const char *p = e->sample_text, *next; *p; p = next, count++)
        line_at(p, &next);
    int last = e->samples > 1 ? count - 1 : count;  /* exclusive */
    int i = 0;
    for (const char *p = e->sample_text, *next; *p; p = next, i++) {
        size_t length = line_at(p, &next);
        if (i >= first && i < last)
            total += line_rows(p, length, columns);
    }
    int fits = used + total <= rows;
    i = 0;
    for (const char *p = e->sample_text, *next; *p && i < last;
         p = next, i++) {
        size_t length = line_at(p, &next);
        if (i < first)
            continue;
        int need = line_rows(p, length, columns);
        char more[96];
        snprintf(more, sizeof more, "... %d more lines on standard output",
                 last - i);
        if (!fits && used + need + view_text_rows(more, columns) > rows) {
            fprintf(out, "%s\n", more);
            break;
        }
        fwrite(p, 1, length, out);
        fputc('\n', out);
        used += need;
    }
    int failed = ferror(out);
    if (fclose(out) != 0 || failed) {
        free(data);
        return NULL;
    }
    return data;
}

void view_explanation_release(view_explanation *explanation)
{
    free(explanation->points);
    free(explanation->segments);
    free(explanation->text);
    free(explanation->sample_text);
    free(explanation->panel);
    memset(explanation, 0, sizeof *explanation);
}
