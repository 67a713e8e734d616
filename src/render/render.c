/*
 * render.c - rendering images: rows of pixels, shared among threads.
 *
 * Each pixel is independent, so threads take rows from a shared counter (a
 * row at a time, dynamically: rows cost very different amounts) and write
 * them into the caller's image.  A pixel's value does not depend on which
 * thread computed it, so the image is the same for any thread count.  The
 * row callback is serialised by a mutex; cancellation is a flag every thread
 * reads before each pixel.
 */
#include <float.h>
#include <stddef.h>
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "base/cancel.h"
#include "base/clock.h"
#include "base/error.h"
#include "raytrace/render.h"
#include "kernel/kernel.h"
#include "render_internal.h"
#include "scene/scene_internal.h"
#include "base/vecmath.h"

/* The kernel of the precision a render asked for. */
typedef struct kernel_ref {
    const rt_kernel_d *d;   /* exactly one of d and f is set */
    const rt_kernel_f *f;
} kernel_ref;

/* One render call, shared by its threads. */
typedef struct job {
    const rt_scene *scene;
    const rt_render_options *options;
    rt_camera camera;       /* the scene's, at the render's image size */
    int x0, y0;             /* the region's top-left pixel in that image */
    int width;              /* the output image's width: the region's */
    kernel_ref kernel;
    rt_trace_settings settings;
    int grid;               /* samples per side of a pixel */
    double aperture;        /* the lens radius of this render (0: pinhole) */
    double focal_distance;  /* the distance in focus, along AO */
    rt_vec3 view_axis;      /* unit O->A, for the lens (once per render) */
    rt_vec3 lens_right;     /* unit AB */
    rt_vec3 lens_up;        /* unit AC */
    rt_image *image;
    int row_end;
    atomic_int next_row;
    atomic_int cancelled;
    pthread_mutex_t callback_lock;
    pthread_mutex_t stats_lock;
    rt_counters totals;
    rt_octree_info octree;  /* when settings.octree */
} job;

/* Non-zero once the render must stop: its callback said so, or the caller
 * raised its cancellation flag (which is then remembered for the job). */
static int stopping(job *j)
{
    if (atomic_load_explicit(&j->cancelled, memory_order_relaxed))
        return 1;
    rt_cancel *cancel = j->options->cancel;
    if (cancel != NULL && rt__cancel_raised(cancel)) {
        atomic_store(&j->cancelled, 1);
        return 1;
    }
    return 0;
}

void rt_render_options_init(rt_render_options *options)
{
    if (options == NULL)
        return;
    memset(options, 0, sizeof *options);
    options->size = sizeof *options;
    options->max_depth = RT_DEFAULT_DEPTH;
    options->threads = 0;
    options->precision = RT_PRECISION_DOUBLE;
    options->samples = 1;
    options->sampling = RT_SAMPLING_REGULAR;
    options->accel = RT_ACCEL_AUTO;
    options->aperture = -1.0;           /* the scene's */
    options->focal_distance = 0.0;      /* the scene's */
}

unsigned char rt_channel_to_byte(double value)
{
    if (!(value > 0.0))     /* also NaN */
        return 0;
    if (value >= 255.0)
        return 255;
    return (unsigned char)(value + 0.5);    /* halves away from zero */
}

rt_color rt_trace(const rt_scene *scene, rt_ray ray, int max_depth)
{
    rt_counters counters = {0};
    rt_trace_settings settings = {max_depth, 0, RT_KERNEL_AUTO, NULL, 0,
                                  NULL};
    if (!RT__EXPECT(scene != NULL) || !v3_is_finite(ray.direction) || v3_max_abs(ray.direction) == 0.0 ||
        max_depth < 0)
        return (rt_color){0.0, 0.0, 0.0};
    return rt__kernel_d_trace(scene->kernel, ray.origin, ray.direction,
                              &settings, &counters);
}

/* A number in [0, 1) from a hash of three integers (a fixed function, so
 * stratified images are the same on every run and thread count). */
static double hash_unit(uint32_t a, uint32_t b, uint32_t c)
{
    uint32_t h = a * 0x9e3779b1u ^ (b + 0x7f4a7c15u) * 0x85ebca6bu ^
                 (c + 0x165667b1u) * 0xc2b2ae35u;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    return (h >> 8) * (1.0 / 16777216.0);
}

/* The primary ray through the point (x, y) of the image plane, in pixel
 * units from the top-left corner (docs/rendering-model.md, "The camera",
 * with i + 1/2 -> x). */
static rt_ray camera_ray_at(const rt_camera *camera, double x, double y)
{
    double w = camera->width, h = camera->height;
    double s = (2.0 * x - w) / w;
    double t = (h - 2.0 * y) / w;
    rt_vec3 p = v3_add(camera->screen_center,
                       v3_add(v3_scale(camera->right, s),
                              v3_scale(camera->up, t)));
    return (rt_ray){camera->observer, v3_sub(p, camera->observer)};
}

#define PI 3.14159265358979323846

/*
 * Shirley and Chiu's concentric map ("A Low Distortion Map Between Disk and
 * Square", JGT 2(3), 1997, section 3): the point (x, y) of the unit square
 * to the unit disk, strata to strata.
 */
static void square_to_disk(double x, double y, double *u, double *v)
{
    double p = 2.0 * x - 1.0, q = 2.0 * y - 1.0;
    if (p == 0.0 && q == 0.0) {
        *u = *v = 0.0;
        return;
    }
    double r, phi;
    if (fabs(p) > fabs(q)) {
        r = p;
        phi = (PI / 4.0) * (q / p);
    } else {
        r = q;
        phi = PI / 2.0 - (PI / 4.0) * (p / q);
    }
    *u = r * cos(phi);
    *v = r * sin(phi);
}

/*
 * The thin-lens ray of the rendering model: `pinhole` is the ray from the
 * observer O through the screen point P; (x, y) the point of the unit
 * square that picks the lens point.  The ray starts at
 * L = O + a (u AB/|AB| + v AC/|AC|), (u, v) = square_to_disk(x, y), and
 * goes towards the focus point F = O + (P - O) f / ((P - O).w), w the unit
 * vector from O to A.
 */
static rt_ray lens_ray(const job *j, rt_ray pinhole, double x, double y)
{
    const rt_camera *camera = &j->camera;
    double u, v;
    square_to_disk(x, y, &u, &v);
    rt_vec3 to_focus = v3_scale(pinhole.direction,
                                j->focal_distance /
                                    v3_dot(pinhole.direction, j->view_axis));
    rt_vec3 focus = v3_add(camera->observer, to_focus);
    rt_vec3 offset = v3_add(v3_scale(j->lens_right, u),
                            v3_scale(j->lens_up, v));
    rt_vec3 lens = v3_add(camera->observer, v3_scale(offset, j->aperture));
    return (rt_ray){lens, v3_sub(focus, lens)};
}

static rt_color trace(const job *j, rt_ray ray, rt_counters *counters)
{
    if (j->kernel.d != NULL)
        return rt__kernel_d_trace(j->kernel.d, ray.origin, ray.direction,
                                  &j->settings, counters);
    return rt__kernel_f_trace(j->kernel.f, ray.origin, ray.direction,
                              &j->settings, counters);
}

/* The camera ray of sample (sx, sy) of pixel (i, row) of the whole image
 * when there are n x n > 1 samples. */
static inline rt_ray sample_ray(const job *j, int i, int row, int sx, int sy)
{
    int n = j->grid;
    int stratified = j->options->sampling == RT_SAMPLING_STRATIFIED;
    uint32_t sample = (uint32_t)(sy * n + sx);
    double u = stratified ? hash_unit((uint32_t)i, (uint32_t)row, 2 * sample)
                          : 0.5;
    double v = stratified ? hash_unit((uint32_t)i, (uint32_t)row,
                                      2 * sample + 1)
                          : 0.5;
    rt_ray ray = camera_ray_at(&j->camera, i + (sx + u) / n,
                               row + (sy + v) / n);
    if (j->aperture > 0.0) {
        /* The lens stratum is the pixel's, transposed, so that where a
         * sample falls in the pixel and on the lens are not aligned;
         * jittered like it when stratified. */
        double lu = stratified ? hash_unit((uint32_t)i, (uint32_t)row,
                                           2 * (sample + n * n))
                               : 0.5;
        double lv = stratified ? hash_unit((uint32_t)i, (uint32_t)row,
                                           2 * (sample + n * n) + 1)
                               : 0.5;
        ray = lens_ray(j, ray, (sy + lu) / n, (sx + lv) / n);
    }
    return ray;
}

/* The camera ray of a pixel with one sample. */
static inline rt_ray centre_ray(const job *j, int i, int row)
{
    rt_ray ray = rt_camera_ray(&j->camera, i, row);
    if (j->aperture > 0.0)  /* one sample: the lens centre */
        ray = lens_ray(j, ray, 0.5, 0.5);
    return ray;
}

/* The colour of pixel (i, row) of the whole image: the mean of its
 * samples. */
static rt_color render_pixel(const job *j, int i, int row,
                             rt_counters *counters)
{
    int n = j->grid;
    if (n == 1) {
        counters->camera_rays++;
        return trace(j, centre_ray(j, i, row), counters);
    }
    rt_color sum = {0.0, 0.0, 0.0};
    for (int sy = 0; sy < n; sy++) {
        for (int sx = 0; sx < n; sx++) {
            rt_color c = trace(j, sample_ray(j, i, row, sx, sy), counters);
            sum.r += c.r, sum.g += c.g, sum.b += c.b;
            counters->camera_rays++;
        }
    }
    double inv = 1.0 / (n * n);
    return (rt_color){sum.r * inv, sum.g * inv, sum.b * inv};
}

/* Rays a span of pixels traces at most (samples are at most 1024), and
 * its pixels at most: wide enough to share the kernel's tile cull among
 * many rays, narrow enough that the cull stays tight (32 was the best of
 * 8 to 128 in instructions per ray, tools/bench/ray-budget.sh). */
#define SPAN_RAYS 1024
#define SPAN_PIXELS 32

/*
 * Renders pixels i0 .. i1 - 1 of a row (the output image's columns) as one
 * span: their camera rays, all samples, go to the kernel together, and
 * each pixel is the mean of its samples in render_pixel()'s order.
 * Pinhole renders only: every ray leaves the observer.
 */
static void render_span(const job *j, int row, int i0, int i1,
                        unsigned char *out, rt_counters *counters)
{
    rt_vec3 directions[SPAN_RAYS];
    rt_color colors[SPAN_RAYS];
    int n = j->grid, m = 0, y = j->y0 + row;
    for (int i = i0; i < i1; i++)
        for (int sy = 0; sy < n; sy++)
            for (int sx = 0; sx < n; sx++)
                directions[m++] = (n == 1 ? centre_ray(j, j->x0 + i, y)
                                          : sample_ray(j, j->x0 + i, y, sx,
                                                       sy))
                                      .direction;
    if (j->kernel.d != NULL)
        rt__kernel_d_trace_span(j->kernel.d, j->camera.observer, directions,
                                m, &j->settings, counters, colors);
    else
        rt__kernel_f_trace_span(j->kernel.f, j->camera.observer, directions,
                                m, &j->settings, counters, colors);
    counters->camera_rays += (uint64_t)m;
    double inv = 1.0 / (n * n);
    for (int i = i0, k = 0; i < i1; i++) {
        rt_color c = colors[k++];
        if (n > 1) {
            for (int s = 1; s < n * n; s++) {
                c.r += colors[k].r, c.g += colors[k].g, c.b += colors[k].b;
                k++;
            }
            c = (rt_color){c.r * inv, c.g * inv, c.b * inv};
        }
        out[3 * i + 0] = rt_channel_to_byte(c.r);
        out[3 * i + 1] = rt_channel_to_byte(c.g);
        out[3 * i + 2] = rt_channel_to_byte(c.b);
    }
}

/* Renders one row; returns 0 if the render was cancelled meanwhile. */
static int render_row(job *j, int row, rt_counters *counters)
{
    unsigned char *out = rt_image_pixel(j->image, 0, row);
    if (j->settings.eye != NULL && j->aperture == 0.0) {
        int n = j->grid, per_span = SPAN_RAYS / (n * n);
        if (per_span > SPAN_PIXELS)
            per_span = SPAN_PIXELS;
        for (int i = 0; i < j->width; i += per_span) {
            if (stopping(j))
                return 0;
            int end = i + per_span < j->width ? i + per_span : j->width;
            render_span(j, row, i, end, out, counters);
        }
        return 1;
    }
    for (int i = 0; i < j->width; i++) {
        if (stopping(j))
            return 0;
        rt_color c = render_pixel(j, j->x0 + i, j->y0 + row, counters);
        out[3 * i + 0] = rt_channel_to_byte(c.r);
        out[3 * i + 1] = rt_channel_to_byte(c.g);
        out[3 * i + 2] = rt_channel_to_byte(c.b);
    }
    return 1;
}

/* Adds a thread's counters into the render's. */
static void add_counters(rt_counters *to, const rt_counters *from)
{
#define ADD_THREAD_(type, name) to->name += from->name;
#define ADD_RENDER_(type, name)
#define ADD_OCTREE_(type, name)
#define ADD_(type, name, origin, merge, group, key, title)                   \
    ADD_##origin##_(type, name)
    RT_STATS_MAP(ADD_)
#undef ADD_
#undef ADD_THREAD_
#undef ADD_RENDER_
#undef ADD_OCTREE_
    to->early_exit_saved += from->early_exit_saved;
    to->out_of_memory |= from->out_of_memory;
}

static void *worker(void *argument)
{
    job *j = argument;
    rt_counters counters = {0};
    for (;;) {
        int row = atomic_fetch_add(&j->next_row, 1);
        if (row >= j->row_end)
            break;
        if (!render_row(j, row, &counters))
            break;
        counters.pixels += (uint64_t)j->width;
        if (j->options->on_row != NULL) {
            pthread_mutex_lock(&j->callback_lock);
            int go_on = atomic_load(&j->cancelled) ||
                        j->options->on_row(j->options->user, row);
            pthread_mutex_unlock(&j->callback_lock);
            if (!go_on) {
                atomic_store(&j->cancelled, 1);
                break;
            }
        }
    }
    pthread_mutex_lock(&j->stats_lock);
    add_counters(&j->totals, &counters);
    pthread_mutex_unlock(&j->stats_lock);
    return NULL;
}

static int thread_count(int requested, int rows)
{
    int n = requested;
    if (n <= 0) {
        long online = sysconf(_SC_NPROCESSORS_ONLN);
        n = online > 0 ? (int)online : 1;
    }
    if (n > rows)
        n = rows;
    return n < 1 ? 1 : n;
}

/* The rays a render cast: the sum of RT_STATS_MAP's group `rays`. */
static uint64_t rays_cast(const rt_render_stats *s)
{
    uint64_t all = 0;
#define RAYS_(type, name, origin, merge, group, key, title)                  \
    if (strcmp(#group, "rays") == 0)                                         \
        all += (uint64_t)s->name;
    RT_STATS_MAP(RAYS_)
#undef RAYS_
    return all;
}

static void fill_stats(const job *j, double seconds, rt_render_stats *stats)
{
    memset(stats, 0, sizeof *stats);
    /* the THREAD counters, summed over the threads */
#define COPY_THREAD_(type, name) stats->name = j->totals.name;
#define COPY_RENDER_(type, name)
#define COPY_OCTREE_(type, name)
#define COPY_(type, name, origin, merge, group, key, title)                  \
    COPY_##origin##_(type, name)
    RT_STATS_MAP(COPY_)
#undef COPY_
#undef COPY_THREAD_
#undef COPY_RENDER_
#undef COPY_OCTREE_
    stats->seconds = seconds;
    /* what a renderer that skips nothing would test on top */
    uint64_t live = (uint64_t)j->scene->live_count;
    uint64_t dead = (uint64_t)(j->scene->facet_count - j->scene->live_count);
    uint64_t skipped_rays = stats->shadow_rays_skipped +
                            stats->reflection_rays_skipped;
    stats->ray_facet_tests_skipped = skipped_rays * (live + dead) +
                                     rays_cast(stats) * dead +
                                     j->totals.early_exit_saved;
    if (j->settings.octree) {
        stats->accel_used = 1;
        stats->accel_build_seconds = j->octree.build_seconds;
        stats->accel_nodes = j->octree.nodes;
        stats->accel_leaves = j->octree.leaves;
        stats->accel_depth = j->octree.depth;
        stats->accel_references = j->octree.references;
        stats->accel_always = j->octree.always;
        stats->accel_bytes = j->octree.bytes;
        stats->accel_facets = (uint64_t)j->scene->live_count;
    }
}

/* Builds (once per scene and precision) the octree of the render's kernel
 * when the render asks for one, polling `cancel` (may be NULL); RT_OK,
 * RT_ERR_NOMEM or RT_ERR_CANCELLED (nothing kept: the next render builds
 * it). */
static rt_status prepare_octree(job *j, const rt_scene *scene,
                                const rt_cancel *cancel)
{
    rt_accel accel = j->options->accel;
    if (accel == RT_ACCEL_NONE ||
        (accel == RT_ACCEL_AUTO && scene->live_count < RT_ACCEL_AUTO_FACETS))
        return RT_OK;
    rt_status status =
        j->kernel.d != NULL
            ? rt__kernel_d_octree_prepare(j->kernel.d, cancel, &j->octree)
            : rt__kernel_f_octree_prepare(j->kernel.f, cancel, &j->octree);
    if (status == RT_OK)
        j->settings.octree = 1;
    return status;
}

/* RT_OK for a precision rt_precision names, else the refusal. */
static rt_status check_precision(rt_precision precision, rt_error *error)
{
    if (precision != RT_PRECISION_DOUBLE && precision != RT_PRECISION_FLOAT)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "a precision of %d: expected RT_PRECISION_DOUBLE "
                             "or RT_PRECISION_FLOAT", (int)precision);
    return RT_OK;
}

rt_status rt_scene_check_precision(const rt_scene *scene,
                                   rt_precision precision, rt_error *error)
{
    if (scene == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "expected a scene");
    rt_status status = check_precision(precision, error);
    if (status != RT_OK || precision == RT_PRECISION_DOUBLE)
        return status;
    const rt_camera *c = &scene->camera;
    double largest = fmax(v3_max_abs(c->observer),
                          v3_max_abs(v3_add(c->screen_center,
                                            v3_add(v3_abs(c->right),
                                                   v3_abs(c->up)))));
    double lights = 0;
    for (int i = 0; i < scene->light_count; i++)
        lights = fmax(lights, v3_max_abs(scene->lights[i].position));
    rt_vec3 low = {INFINITY, INFINITY, INFINITY}, high = v3_scale(low, -1);
    for (int i = 0; i < scene->vertex_count; i++) {
        rt_vec3 v = scene->vertices[i];
        largest = fmax(largest, v3_max_abs(v));
        low = v3(fmin(low.x, v.x), fmin(low.y, v.y), fmin(low.z, v.z));
        high = v3(fmax(high.x, v.x), fmax(high.y, v.y), fmax(high.z, v.z));
    }
    if (!(fmax(largest, lights) < FLT_MAX))
        return rt__error_set(error, RT_ERR_RANGE, scene->name, 0, 0,
                             "a float render cannot hold coordinates of "
                             "%g (float ends at %g): render in double",
                             fmax(largest, lights), (double)FLT_MAX);
    if (largest > RT_FLOAT_MAX_COORDINATE)
        return rt__error_set(error, RT_ERR_RANGE, scene->name, 0, 0,
                             "a float render cannot hold vertex or camera "
                             "coordinates of %g: its intersection test "
                             "overflows beyond %g: render in double",
                             largest, RT_FLOAT_MAX_COORDINATE);
    double extent = scene->vertex_count > 1 ? v3_max_abs(v3_sub(high, low))
                                            : 0;
    if (extent > 0 && largest > RT_FLOAT_SPREAD_MAX * extent)
        return rt__error_set(error, RT_ERR_RANGE, scene->name, 0, 0,
                             "a float render cannot resolve this scene: its "
                             "coordinates reach %g while its vertices span "
                             "%g, more than %d times less (float keeps 24 "
                             "bits: its steps at %g are %g, too coarse for "
                             "the scene): render in double",
                             largest, extent, (int)RT_FLOAT_SPREAD_MAX,
                             largest, largest * FLT_EPSILON);
    return RT_OK;
}

/*
 * Copies the caller's options into *out, field by field, as far as the
 * caller's size reaches; the fields beyond keep their defaults (the rule of
 * raytrace/render.h for growing option structs).  NULL: the defaults.
 */
static rt_status take_options(const rt_render_options *in,
                              rt_render_options *out, rt_error *error)
{
    rt_render_options_init(out);
    if (in == NULL)
        return RT_OK;
    if (in->size == 0 || in->size > sizeof *out)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "render options of %zu bytes: expected 1..%zu "
                             "(set by rt_render_options_init)",
                             in->size, sizeof *out);
#define TAKE(field)                                                          \
    if (offsetof(rt_render_options, field) + sizeof in->field <= in->size)    \
        out->field = in->field;
    TAKE(max_depth) TAKE(threads) TAKE(precision) TAKE(fast_inv_sqrt)
    TAKE(samples) TAKE(sampling) TAKE(on_row) TAKE(cancel) TAKE(user)
    TAKE(stats) TAKE(kernel) TAKE(accel) TAKE(aperture) TAKE(focal_distance)
    TAKE(width) TAKE(height) TAKE(region)
#undef TAKE
    return RT_OK;
}

/* The checks of rt_render_image_size; fills the whole image's size too. */
static rt_status image_size(const rt_scene *scene,
                            const rt_render_options *options, int *full_width,
                            int *full_height, int *width, int *height,
                            rt_error *error)
{
    *width = *height = *full_width = *full_height = 0;
    if (scene == NULL || options == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "no scene or no render options");
    int w = options->width != 0 ? options->width : scene->camera.width;
    int h = options->height != 0 ? options->height : scene->camera.height;
    if (w < 1 || w > RT_MAX_IMAGE_SIDE || h < 1 || h > RT_MAX_IMAGE_SIDE)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "an image of %d x %d pixels: each side must be "
                             "in 1..%d", w, h, RT_MAX_IMAGE_SIDE);
    *full_width = w;
    *full_height = h;
    rt_region r = options->region;
    if (r.x0 == 0 && r.y0 == 0 && r.x1 == 0 && r.y1 == 0) {
        *width = w;
        *height = h;
        return RT_OK;
    }
    if (r.x0 < 0 || r.y0 < 0 || r.x1 > w || r.y1 > h || r.x0 >= r.x1 ||
        r.y0 >= r.y1)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "the region %d,%d,%d,%d is %s of the %d x %d "
                             "image (columns x0 <= x < x1, rows y0 <= y < "
                             "y1)", r.x0, r.y0, r.x1, r.y1,
                             r.x0 >= r.x1 || r.y0 >= r.y1 ? "an empty part"
                                                          : "not inside",
                             w, h);
    *width = r.x1 - r.x0;
    *height = r.y1 - r.y0;
    return RT_OK;
}

rt_status rt_render_image_size(const rt_scene *scene,
                               const rt_render_options *options, int *width,
                               int *height, rt_error *error)
{
    rt_render_options taken;
    int full_width, full_height;
    if (width == NULL || height == NULL) {
        if (width != NULL)
            *width = 0;
        if (height != NULL)
            *height = 0;
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "expected a width and a height to fill");
    }
    *width = *height = 0;
    rt_status status = take_options(options, &taken, error);
    if (status != RT_OK)
        return status;
    return image_size(scene, &taken, &full_width, &full_height, width,
                      height, error);
}

static rt_status out_of_memory(rt_error *error)
{
    return rt__error_set(error, RT_ERR_NOMEM, NULL, 0, 0,
                         "out of memory while preparing or running the "
                         "render");
}

static rt_status check_options(const rt_render_options *options,
                                rt_error *error);

/* The checks of rt_render_rows that image_size does not make. */
static rt_status check_render(const rt_render_options *options, int width,
                              int height, int row_begin, int row_end,
                              const rt_image *image, rt_error *error)
{
    if (image->pixels == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "the image has no pixels (see rt_image_init)");
    if (image->width != width || image->height != height)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "the image is %d x %d but the render writes "
                             "%d x %d", image->width, image->height, width,
                             height);
    if (image->stride < (size_t)image->width * 3)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "the image's stride is %zu bytes, less than 3 "
                             "x its width %d", image->stride, image->width);
    if (row_begin < 0 || row_end > image->height || row_begin > row_end)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "rows %d..%d: expected a band within 0..%d",
                             row_begin, row_end, image->height);
    return check_options(options, error);
}

/* The checks of the options alone: every field in its domain (the image
 * size and region are image_size's, the samples sample_grid's). */
static rt_status check_options(const rt_render_options *options,
                               rt_error *error)
{
    if (options->max_depth < 0)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "a depth of %d: expected 0 or more",
                             options->max_depth);
    if (options->threads < 0)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "%d threads: expected 0 (one per core) or more",
                             options->threads);
    rt_status status = check_precision(options->precision, error);
    if (status != RT_OK)
        return status;
    if (options->sampling != RT_SAMPLING_REGULAR &&
        options->sampling != RT_SAMPLING_STRATIFIED)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "a sampling of %d: expected RT_SAMPLING_REGULAR "
                             "or RT_SAMPLING_STRATIFIED",
                             (int)options->sampling);
    if (options->kernel != RT_KERNEL_AUTO &&
        options->kernel != RT_KERNEL_SCALAR)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "a kernel of %d: expected RT_KERNEL_AUTO or "
                             "RT_KERNEL_SCALAR", (int)options->kernel);
    if (options->accel != RT_ACCEL_AUTO && options->accel != RT_ACCEL_NONE &&
        options->accel != RT_ACCEL_OCTREE)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "an accel of %d: expected RT_ACCEL_AUTO, "
                             "RT_ACCEL_NONE or RT_ACCEL_OCTREE",
                             (int)options->accel);
    if (!isfinite(options->aperture))
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "an aperture of %g: expected a finite lens "
                             "radius >= 0 (negative: the scene's)",
                             options->aperture);
    if (!(options->focal_distance >= 0.0) ||
        !isfinite(options->focal_distance))
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "a focal distance of %g: expected a finite "
                             "distance > 0 (0: the scene's)",
                             options->focal_distance);
    return RT_OK;
}

/* The number of samples per side for `samples`, or 0 when it is not a
 * square in 1..1024 (with the message in *error). */
static int sample_grid(int samples, rt_error *error)
{
    int grid = 1;
    while (grid * grid < samples && grid < 32)
        grid++;
    if (grid * grid != samples) {
        rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                      "%d samples per pixel: expected a square n x n in "
                      "1..1024 (1, 4, 9, ...)", samples);
        return 0;
    }
    return grid;
}

/*
 * Sets up *j for a render of `scene` with the (taken and checked) options:
 * camera, lens, kernel, octree and the eye, which *eye_d / *eye_f own
 * (free them with release_job).  `full_width` x `full_height` is the whole
 * image's size.  The octree's construction polls `cancel` (may be NULL):
 * RT_ERR_CANCELLED when it was raised before the octree was complete.
 */
static rt_status prepare_job(job *j, const rt_scene *scene,
                             const rt_render_options *options, int grid,
                             int full_width, int full_height,
                             const rt_cancel *cancel,
                             rt_kernel_eye_d **eye_d, rt_kernel_eye_f **eye_f,
                             rt_error *error)
{
    *eye_d = NULL;
    *eye_f = NULL;
    double aperture = options->aperture >= 0.0 ? options->aperture
                                               : scene->camera.aperture;
    double focal_distance = options->focal_distance > 0.0
                                ? options->focal_distance
                                : scene->camera.focal_distance;
    if (!isfinite(aperture) || !isfinite(focal_distance))
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "a lens of aperture %g and focus %g: expected "
                             "finite numbers", aperture, focal_distance);
    j->scene = scene;
    j->options = options;
    j->camera = scene->camera;
    j->x0 = options->region.x0;
    j->y0 = options->region.y0;
    j->grid = grid;
    j->aperture = aperture;
    j->focal_distance = focal_distance;
    j->view_axis = v3_normalize(v3_sub(scene->camera.screen_center,
                                       scene->camera.observer));
    j->lens_right = v3_normalize(scene->camera.right);
    j->lens_up = v3_normalize(scene->camera.up);
    j->settings = (rt_trace_settings){options->max_depth,
                                      options->fast_inv_sqrt != 0,
                                      options->kernel, NULL, 0, NULL};
    /* The float kernel is built by the first float render and kept with
     * the scene: a double-only user never pays for float data. */
    if (options->precision == RT_PRECISION_FLOAT) {
        rt_status status = rt_scene_check_precision(scene, RT_PRECISION_FLOAT,
                                                    error);
        if (status != RT_OK)
            return status;
        j->kernel.f = rt__scene_kernel_f(scene, cancel);
        if (j->kernel.f == NULL && rt_cancel_requested(cancel))
            return rt__error_set(error, RT_ERR_CANCELLED, NULL, 0, 0,
                                 "the render was cancelled");
        if (j->kernel.f == NULL)
            return out_of_memory(error);
    } else {
        j->kernel.d = scene->kernel;
    }
    rt_status built = prepare_octree(j, scene, cancel);
    if (built == RT_ERR_CANCELLED)
        return rt__error_set(error, RT_ERR_CANCELLED, NULL, 0, 0,
                             "the render was cancelled");
    if (built != RT_OK)
        return out_of_memory(error);
    /* The camera rays' origin, subtracted from every vertex once for the
     * whole render (only the fast brute-force loops read it). */
    if (options->kernel != RT_KERNEL_SCALAR && !j->settings.octree) {
        if (j->kernel.d != NULL)
            j->settings.eye = *eye_d = rt__kernel_d_eye_create(
                j->kernel.d, scene->camera.observer);
        else
            j->settings.eye = *eye_f = rt__kernel_f_eye_create(
                j->kernel.f, scene->camera.observer);
        if (j->settings.eye == NULL)
            return out_of_memory(error);
    }
    j->camera.width = full_width;
    j->camera.height = full_height;
    return RT_OK;
}

rt_status rt_render_rows(const rt_scene *scene,
                         const rt_render_options *caller_options,
                         int row_begin, int row_end, rt_image *image,
                         rt_error *error)
{
    if (scene == NULL || image == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "no scene or no image");
    rt_render_options taken;
    rt_status status = take_options(caller_options, &taken, error);
    if (status != RT_OK)
        return status;
    const rt_render_options *options = &taken;
    int full_width, full_height, width, height;
    status = image_size(scene, options, &full_width, &full_height, &width,
                        &height, error);
    if (status == RT_OK)
        status = check_render(options, width, height, row_begin, row_end,
                              image, error);
    if (status != RT_OK)
        return status;
    int grid = sample_grid(options->samples, error);
    if (grid == 0)
        return RT_ERR_ARGUMENT;

    double start = rt__clock_seconds();
    job j = {.width = width, .image = image, .row_end = row_end};
    rt_kernel_eye_d *eye_d;
    rt_kernel_eye_f *eye_f;
    status = prepare_job(&j, scene, options, grid, full_width, full_height,
                         options->cancel, &eye_d, &eye_f, error);
    if (status != RT_OK) {
        rt__kernel_d_eye_free(eye_d);
        rt__kernel_f_eye_free(eye_f);
        return status;
    }
    atomic_init(&j.next_row, row_begin);
    atomic_init(&j.cancelled, 0);
    pthread_mutex_init(&j.callback_lock, NULL);
    pthread_mutex_init(&j.stats_lock, NULL);

    int n = thread_count(options->threads, row_end - row_begin);
    pthread_t *threads = n > 1 ? malloc((size_t)(n - 1) * sizeof *threads)
                               : NULL;
    int started = 0;
    if (n > 1 && threads == NULL)
        status = RT_ERR_NOMEM;
    for (int t = 0; status == RT_OK && t < n - 1; t++) {
        if (pthread_create(&threads[t], NULL, worker, &j) != 0)
            break;          /* fewer threads: still correct */
        started++;
    }
    if (status == RT_OK)
        worker(&j);         /* the calling thread works too */
    for (int t = 0; t < started; t++)
        pthread_join(threads[t], NULL);
    free(threads);
    pthread_mutex_destroy(&j.callback_lock);
    pthread_mutex_destroy(&j.stats_lock);
    rt__kernel_d_eye_free(eye_d);
    rt__kernel_f_eye_free(eye_f);

    if (options->stats != NULL)
        fill_stats(&j, rt__clock_seconds() - start, options->stats);
    if (status == RT_OK && atomic_load(&j.cancelled))
        return rt__error_set(error, RT_ERR_CANCELLED, NULL, 0, 0,
                             "the render was cancelled");
    if (status == RT_ERR_NOMEM || j.totals.out_of_memory)
        return out_of_memory(error);
    return status;
}

/* One render's setup kept for tracing single pixels (render_internal.h). */
struct rt_pixel_tracer {
    rt_render_options options;
    job j;
    rt_kernel_eye_d *eye_d;
    rt_kernel_eye_f *eye_f;
    int width, height;      /* the output image's */
};

rt_status rt__pixel_tracer_create(const rt_scene *scene,
                                  const rt_render_options *options,
                                  rt_pixel_tracer **tracer, rt_error *error)
{
    *tracer = NULL;
    if (scene == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "no scene");
    rt_pixel_tracer *p = calloc(1, sizeof *p);
    if (p == NULL)
        return out_of_memory(error);
    int full_width, full_height, grid = 0;
    rt_status status = take_options(options, &p->options, error);
    if (status == RT_OK)
        status = image_size(scene, &p->options, &full_width, &full_height,
                            &p->width, &p->height, error);
    if (status == RT_OK)
        status = check_options(&p->options, error);
    if (status == RT_OK && (grid = sample_grid(p->options.samples,
                                               error)) == 0)
        status = RT_ERR_ARGUMENT;
    if (status == RT_OK)
        status = prepare_job(&p->j, scene, &p->options, grid, full_width,
                             full_height, NULL, &p->eye_d, &p->eye_f, error);
    if (status != RT_OK) {
        rt__pixel_tracer_destroy(p);
        return status;
    }
    *tracer = p;
    return RT_OK;
}

void rt__pixel_tracer_destroy(rt_pixel_tracer *tracer)
{
    if (tracer == NULL)
        return;
    rt__kernel_d_eye_free(tracer->eye_d);
    rt__kernel_f_eye_free(tracer->eye_f);
    free(tracer);
}

void rt__pixel_tracer_size(const rt_pixel_tracer *tracer, int *width,
                           int *height, int *samples)
{
    *width = tracer->width;
    *height = tracer->height;
    *samples = tracer->j.grid * tracer->j.grid;
}

rt_color rt__pixel_tracer_trace(rt_pixel_tracer *tracer, int x, int y,
                                int sample, rt_trace_recorder *recorder,
                                int *out_of_memory)
{
    job *j = &tracer->j;
    rt_counters counters = {0};
    int i = j->x0 + x, row = j->y0 + y, n = j->grid;
    j->settings.recorder = recorder;
    rt_color c;
    if (sample < 0)
        c = render_pixel(j, i, row, &counters);
    else if (n == 1)
        c = trace(j, centre_ray(j, i, row), &counters);
    else
        c = trace(j, sample_ray(j, i, row, sample % n, sample / n),
                  &counters);
    j->settings.recorder = NULL;
    *out_of_memory = counters.out_of_memory;
    return c;
}

rt_status rt_render(const rt_scene *scene, const rt_render_options *options,
                    rt_image *image, rt_error *error)
{
    if (scene == NULL || image == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "no scene or no image");
    return rt_render_rows(scene, options, 0, image->height, image, error);
}
