/*
 * explain.c - the ray tree of a pixel and the debug views (raytrace/explain.h).
 *
 * Nothing here computes a colour: a recorder (callbacks and their state,
 * kernel.h) is handed to the kernel's own trace, which tells it every ray
 * it casts and every term it adds, and the pixel is traced by the render's
 * own pixel loops (render_internal.h).  So the explained value is the
 * rendered one by construction; this file only stores what it is told,
 * sums the subtrees for reading, and maps the camera ray's hit to the
 * colours of the debug views.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "raytrace/explain.h"
#include "render_internal.h"
#include "scene/scene_internal.h"

/* What the recorder's callbacks fill: the nodes of one pixel's rays. */
typedef struct tree_builder {
    const rt_scene *scene;
    rt_ray_node *nodes;
    size_t count, capacity;
    size_t truncated;       /* rays not recorded: the tree was full */
    int next_sample;        /* the sample of the next camera ray */
    int out_of_memory;
} tree_builder;

struct rt_ray_tree {
    rt_ray_node *nodes;
    size_t count;
    size_t truncated;
    rt_color value;
};

/* A new node of `kind`, or NULL when the tree is full or memory short. */
static rt_ray_node *new_node(tree_builder *r)
{
    if (r->count == r->capacity) {
        if (r->capacity >= RT_RAY_TREE_MAX_NODES) {
            r->truncated++;
            return NULL;
        }
        size_t bigger = r->capacity == 0 ? 64 : r->capacity * 2;
        if (bigger > RT_RAY_TREE_MAX_NODES)
            bigger = RT_RAY_TREE_MAX_NODES;
        rt_ray_node *grown = realloc(r->nodes, bigger * sizeof *grown);
        if (grown == NULL) {
            r->out_of_memory = 1;
            r->truncated++;
            return NULL;
        }
        r->nodes = grown;
        r->capacity = bigger;
    }
    rt_ray_node *n = &r->nodes[r->count++];
    memset(n, 0, sizeof *n);
    n->facet = n->blocker = n->light = -1;
    return n;
}

static int record_ray(void *state, int kind, int parent, int depth,
                      rt_vec3 origin, rt_vec3 direction, double weight)
{
    tree_builder *r = state;
    if (kind != RT_RAY_CAMERA && parent < 0) {
        r->truncated++;     /* its parent was not recorded */
        return -1;
    }
    int sample = kind == RT_RAY_CAMERA ? r->next_sample++
                                       : r->nodes[parent].sample;
    rt_ray_node *n = new_node(r);
    if (n == NULL)
        return -1;
    n->kind = (rt_ray_kind)kind;
    n->parent = kind == RT_RAY_CAMERA ? -1 : parent;
    n->depth = depth;
    n->sample = sample;
    n->origin = origin;
    n->direction = direction;
    n->weight = weight;
    return (int)(r->count - 1);
}

static void record_hit(void *state, int node, int facet, double t,
                       rt_vec3 point, rt_vec3 normal, int smooth,
                       rt_vec3 shading_normal, rt_vec3 shading_point)
{
    tree_builder *r = state;
    if (node < 0)
        return;
    rt_ray_node *n = &r->nodes[node];
    const rt_facet_record *record = &r->scene->facets[facet];
    const rt_material *f = &r->scene->materials.items[record->material];
    n->hit = 1;
    n->facet = facet;
    n->line = record->line;
    n->t = t;
    n->point = point;
    n->normal = normal;
    n->reflection = f->reflection;
    n->transparency = f->transparency;
    n->diffuse = f->diffuse;
    n->smooth = smooth;
    n->shading_normal = shading_normal;
    n->shading_point = shading_point;
    n->highlight = f->highlight;
    n->highlight_exponent = f->exponent;
}

static void record_miss(void *state, int node, rt_color own)
{
    tree_builder *r = state;
    if (node >= 0)
        r->nodes[node].own = own;
}

static void record_shadow(void *state, int parent, int light,
                          rt_vec3 origin, rt_vec3 direction, double n_dot_s,
                          int cast, int blocked, int blocker, rt_color own,
                          double r_dot_v, rt_color highlight)
{
    tree_builder *r = state;
    if (parent < 0) {
        r->truncated++;
        return;
    }
    rt_ray_node *n = new_node(r);
    if (n == NULL)
        return;
    const rt_ray_node *p = &r->nodes[parent];
    n->kind = RT_RAY_SHADOW;
    n->parent = parent;
    n->depth = p->depth;
    n->sample = p->sample;
    n->weight = p->weight;
    n->origin = origin;
    n->direction = direction;
    n->light = light;
    n->n_dot_s = n_dot_s;
    n->cast = cast;
    n->e = cast && !blocked ? 1.0 : 0.0;
    n->blocker = blocked ? blocker : -1;
    n->blocker_line = n->blocker >= 0 ? r->scene->facets[blocker].line : 0;
    n->own = own;
    n->r_dot_v = r_dot_v;
    n->highlight_own = highlight;
}

/* Each node's subtotal: its own term plus its descendants' (parents come
 * before their children, so one backward pass does it). */
static void sum_subtrees(rt_ray_node *nodes, size_t count)
{
    for (size_t i = count; i-- > 0;) {
        rt_ray_node *n = &nodes[i];
        n->subtotal.r += n->own.r;
        n->subtotal.g += n->own.g;
        n->subtotal.b += n->own.b;
        if (n->parent >= 0) {
            rt_ray_node *p = &nodes[n->parent];
            p->subtotal.r += n->subtotal.r;
            p->subtotal.g += n->subtotal.g;
            p->subtotal.b += n->subtotal.b;
        }
    }
}

/* Traces pixel (x, y) (or one sample) of `frame` into r, emptied first,
 * through the kernel's recorder callbacks. */
static rt_status record_pixel(const rt_frame *frame, tree_builder *r, int x,
                              int y, int sample, rt_color *value,
                              rt_counters *counted, rt_error *error)
{
    r->count = 0;
    r->truncated = 0;
    r->out_of_memory = 0;
    r->next_sample = sample < 0 ? 0 : sample;
    const rt_trace_recorder recorder = {r, record_ray, record_hit,
                                        record_miss, record_shadow};
    rt_frame recording = *frame;
    recording.settings.recorder = &recorder;
    rt_counters mine = {0}, *counters = counted != NULL ? counted : &mine;
    *value = rt__frame_pixel(&recording, x, y, sample, counters);
    if (counters->out_of_memory || r->out_of_memory)
        return rt__error_set(error, RT_ERR_NOMEM, NULL, 0, 0,
                             "out of memory for the ray tree of pixel "
                             "%d,%d", x, y);
    return RT_OK;
}

rt_status rt_explain_pixel(const rt_scene *scene,
                           const rt_render_options *options, int x, int y,
                           int sample, rt_ray_tree **tree, rt_error *error)
{
    if (tree == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "expected a pointer to fill");
    *tree = NULL;
    rt_frame frame;
    int width, height, samples;
    rt_status status = rt__frame_setup(scene, options, &frame, &width,
                                       &height, &samples, error);
    if (status != RT_OK)
        return status;
    if (x < 0 || x >= width || y < 0 || y >= height)
        status = rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                               "pixel %d,%d is outside the %d x %d image",
                               x, y, width, height);
    else if (sample < -1 || sample >= samples)
        status = rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                               "sample %d of a pixel of %d samples: "
                               "expected -1 (all) or 0..%d", sample,
                               samples, samples - 1);
    tree_builder r = {.scene = scene};
    rt_color value = {0, 0, 0};
    if (status == RT_OK)
        status = record_pixel(&frame, &r, x, y, sample, &value, NULL, error);
    rt__frame_release(&frame);
    rt_ray_tree *t = NULL;
    if (status == RT_OK && (t = malloc(sizeof *t)) == NULL)
        status = rt__error_set(error, RT_ERR_NOMEM, NULL, 0, 0,
                               "out of memory for a ray tree");
    if (status != RT_OK) {
        free(r.nodes);
        return status;
    }
    sum_subtrees(r.nodes, r.count);
    *t = (rt_ray_tree){r.nodes, r.count, r.truncated, value};
    *tree = t;
    return RT_OK;
}

void rt_ray_tree_destroy(rt_ray_tree *tree)
{
    if (tree == NULL)
        return;
    free(tree->nodes);
    free(tree);
}

const rt_ray_node *rt_ray_tree_nodes(const rt_ray_tree *tree, size_t *count)
{
    int given = RT__EXPECT(tree != NULL);
    if (count != NULL)
        *count = given ? tree->count : 0;
    return given ? tree->nodes : NULL;
}

rt_color rt_ray_tree_value(const rt_ray_tree *tree)
{
    if (!RT__EXPECT(tree != NULL))
        return (rt_color){0.0, 0.0, 0.0};
    return tree->value;
}

size_t rt_ray_tree_truncated(const rt_ray_tree *tree)
{
    return RT__EXPECT(tree != NULL) ? tree->truncated : 0;
}

rt_rgb8 rt_debug_facet_color(int index)
{
    uint32_t h = (uint32_t)index * 0x9e3779b1u + 0x7f4a7c15u;
    h ^= h >> 16;
    h *= 0x85ebca6bu;
    h ^= h >> 13;
    h *= 0xc2b2ae35u;
    h ^= h >> 16;
    return (rt_rgb8){(unsigned char)(64 + (h & 0xff) % 192),
                     (unsigned char)(64 + ((h >> 8) & 0xff) % 192),
                     (unsigned char)(64 + ((h >> 16) & 0xff) % 192)};
}

/* The shadow ray to light `light` of the camera ray's hit, or NULL. */
static const rt_ray_node *camera_shadow(const tree_builder *r, int light)
{
    for (size_t i = 1; i < r->count; i++)
        if (r->nodes[i].kind == RT_RAY_SHADOW && r->nodes[i].parent == 0 &&
            r->nodes[i].light == light)
            return &r->nodes[i];
    return NULL;
}

static void put(unsigned char *p, double r, double g, double b)
{
    p[0] = rt_channel_to_byte(r);
    p[1] = rt_channel_to_byte(g);
    p[2] = rt_channel_to_byte(b);
}

/* The colour of one pixel in `view` (all but RT_VIEW_DEPTH) from its
 * recorded first sample. */
static void view_pixel(const tree_builder *r, rt_debug_view view,
                       int light, int max_depth, unsigned char *p)
{
    const rt_ray_node *camera = &r->nodes[0];
    put(p, 0, 0, 0);
    if (!camera->hit)
        return;
    const rt_ray_node *s = camera_shadow(r, light);
    switch (view) {
    case RT_VIEW_NORMAL:
        put(p, (camera->normal.x + 1) / 2 * 255,
            (camera->normal.y + 1) / 2 * 255,
            (camera->normal.z + 1) / 2 * 255);
        break;
    case RT_VIEW_SHADING_NORMAL:
        put(p, (camera->shading_normal.x + 1) / 2 * 255,
            (camera->shading_normal.y + 1) / 2 * 255,
            (camera->shading_normal.z + 1) / 2 * 255);
        break;
    case RT_VIEW_FACET: {
        rt_rgb8 c = rt_debug_facet_color(camera->facet);
        p[0] = c.r, p[1] = c.g, p[2] = c.b;
        break;
    }
    case RT_VIEW_SHADOW:
        if (s == NULL || !s->cast)
            put(p, 0, 0, 128);
        else if (s->e > 0)
            put(p, 255, 255, 255);
        else
            put(p, 128, 0, 0);
        break;
    case RT_VIEW_NS: {
        double v = s != NULL && s->n_dot_s > 0 ? 255 * s->n_dot_s : 0;
        put(p, v, v, v);
        break;
    }
    case RT_VIEW_BOUNCES: {
        int deepest = 0;
        for (size_t i = 0; i < r->count; i++)
            if (r->nodes[i].kind != RT_RAY_SHADOW &&
                r->nodes[i].depth > deepest)
                deepest = r->nodes[i].depth;
        double v = max_depth > 0 ? 255.0 * deepest / max_depth : 0;
        put(p, v, v, v);
        break;
    }
    default:
        break;
    }
}

/* One debug view rendered as a job of rows (render.c): what every thread
 * reads, and for RT_VIEW_DEPTH the t of every pixel until the greys are
 * known. */
typedef struct view_job {
    const rt_scene *scene;
    rt_debug_view view;
    int light;
    int max_depth;          /* the render's, for RT_VIEW_BOUNCES */
    int width;
    double *depth;          /* RT_VIEW_DEPTH: t per pixel, -1 for none */
} view_job;

static void view_thread_end(void *user, void *thread)
{
    (void)user;
    tree_builder *r = thread;
    if (r != NULL)
        free(r->nodes);
    free(r);
}

/* A row of the view: each pixel's first sample recorded, then coloured
 * (or its t kept, for the depth view). */
static int view_row(void *user, const rt_frame *frame, int row,
                    unsigned char *out, const rt_stop *stop,
                    rt_counters *counters, void **thread)
{
    view_job *v = user;
    tree_builder *r = *thread;
    if (r == NULL) {
        if ((r = calloc(1, sizeof *r)) == NULL) {
            counters->out_of_memory = 1;
            return 0;
        }
        r->scene = v->scene;
        *thread = r;
    }
    for (int x = 0; x < v->width; x++) {
        if (rt__stop_now(stop))
            return 0;
        rt_color value;
        if (record_pixel(frame, r, x, row, 0, &value, counters, NULL) !=
                RT_OK ||
            r->count == 0) {
            counters->out_of_memory = 1;
            return 0;
        }
        if (v->depth != NULL)
            v->depth[(size_t)row * (size_t)v->width + (size_t)x] =
                r->nodes[0].hit ? r->nodes[0].t : -1;
        else
            view_pixel(r, v->view, v->light, v->max_depth, &out[3 * x]);
    }
    return 1;
}

/* Depth: t of each camera hit, then near (255) .. far (0). */
static void depth_view(const double *t, rt_image *image, int width,
                       int height)
{
    double near = INFINITY, far = -INFINITY;
    for (int i = 0; i < width * height; i++)
        if (t[i] >= 0) {
            near = fmin(near, t[i]);
            far = fmax(far, t[i]);
        }
    for (int y = 0; y < height; y++) {
        unsigned char *row = rt_image_pixel(image, 0, y);
        for (int x = 0; x < width; x++) {
            double d = t[y * width + x], v = 0;
            if (d >= 0)
                v = far > near ? 255 * (far - d) / (far - near) : 255;
            put(&row[3 * x], v, v, v);
        }
    }
}

rt_status rt_render_view(const rt_scene *scene,
                         const rt_render_options *options, rt_debug_view view,
                         int light, rt_image *image, rt_error *error)
{
    if (scene == NULL || image == NULL || image->pixels == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "no scene or no image");
    if (image->stride < (size_t)image->width * 3)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "the image's stride is %zu bytes, less than 3 "
                             "x its width %d", image->stride, image->width);
    if (view < RT_VIEW_NORMAL || view > RT_VIEW_SHADING_NORMAL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "a debug view of %d: expected RT_VIEW_NORMAL.."
                             "RT_VIEW_SHADING_NORMAL", (int)view);
    if ((view == RT_VIEW_SHADOW || view == RT_VIEW_NS) &&
        (light < 0 || light >= scene->light_count))
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "light %d: the scene has lights 0..%d", light,
                             scene->light_count - 1);
    rt_render_plan plan;
    rt_status status = rt__render_take(scene, options, &plan, error);
    if (status != RT_OK)
        return status;
    int width = plan.width, height = plan.height;
    view_job v = {scene, view, light, plan.options.max_depth, width, NULL};
    if (view == RT_VIEW_DEPTH &&
        (v.depth = malloc((size_t)width * (size_t)height *
                          sizeof *v.depth)) == NULL)
        return rt__error_set(error, RT_ERR_NOMEM, NULL, 0, 0,
                             "out of memory for a depth view");
    /* Only the bounces view reads more than the camera ray's hit and its
     * shadow rays: the others trace no reflection or refraction. */
    const rt_row_work work = {view_row, view_thread_end, &v,
                              view != RT_VIEW_DEPTH};
    status = rt__render_job(scene, options, 0, height, image, &work,
                            view == RT_VIEW_BOUNCES ? -1 : 0, error);
    if (status == RT_OK && v.depth != NULL) {
        depth_view(v.depth, image, width, height);
        for (int y = 0; y < height && plan.options.on_row != NULL; y++)
            if (!plan.options.on_row(plan.options.user, y)) {
                status = rt__error_set(error, RT_ERR_CANCELLED, NULL, 0, 0,
                                       "the render was cancelled");
                break;
            }
    }
    free(v.depth);
    return status;
}
