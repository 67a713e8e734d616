/*
 * render.c - rendering images: a job of rows shared among threads,
 * cancellation, and the statistics of the job.
 *
 * Each pixel is independent, so threads take rows from a shared counter (a
 * row at a time, dynamically: rows cost very different amounts) and write
 * them into the caller's image through the pixel loops of pixel.c.  A
 * pixel's value does not depend on which thread computed it, so the image
 * is the same for any thread count.  The row callback is serialised by a
 * mutex; cancellation is a flag every thread reads before each pixel (or
 * span of pixels).
 *
 * What a render needs beyond its options is prepared once per scene and
 * kept with it (scene/prepared.c): the kernel of its precision, the
 * kernel's octree, the eye of the camera rays and the threads, so a
 * program rendering an image band by band (rt-export-mpi) pays for them
 * once, not per band.
 */
#include <math.h>
#include <limits.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "base/clock.h"
#include "base/error.h"
#include "base/vecmath.h"
#include "base/workers.h"
#include "render_internal.h"
#include "scene/scene_internal.h"

/* One render call, shared by its threads. */
typedef struct job {
    const rt_scene *scene;
    const rt_render_options *options;
    rt_frame frame;
    rt_image *image;
    const rt_row_work *work;    /* NULL: the picture */
    int row_end;
    atomic_int next_row;
    atomic_int cancelled;
    pthread_mutex_t callback_lock;
    pthread_mutex_t stats_lock;
    rt_counters totals;
} job;

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

/* What every thread of a job runs: rows until none is left or the render
 * stops. */
static void worker(void *argument)
{
    job *j = argument;
    rt_counters counters = {0};
    const rt_stop stop = {&j->cancelled, j->options->cancel};
    const rt_row_work *work = j->work;
    void *thread = NULL;
    for (;;) {
        int row = atomic_fetch_add(&j->next_row, 1);
        if (row >= j->row_end)
            break;
        unsigned char *out = rt_image_pixel(j->image, 0, row);
        if (work != NULL ? !work->row(work->user, &j->frame, row, out, &stop,
                                      &counters, &thread)
                         : !rt__frame_row(&j->frame, row, out, &stop,
                                          &counters)) {
            if (counters.out_of_memory)
                atomic_store(&j->cancelled, 1);
            break;
        }
        counters.pixels += (uint64_t)j->frame.width;
        if (j->options->on_row != NULL &&
            (work == NULL || work->report_rows)) {
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
    if (work != NULL && work->thread_end != NULL)
        work->thread_end(work->user, thread);
    pthread_mutex_lock(&j->stats_lock);
    add_counters(&j->totals, &counters);
    pthread_mutex_unlock(&j->stats_lock);
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

uint64_t rt_render_stats_rays(const rt_render_stats *stats)
{
    if (!RT__EXPECT(stats != NULL &&
                    stats->size >= RT__RENDER_STATS_SIZE_0_3))
        return 0;
    uint64_t all = 0;
#define RAYS_(type, name, origin, merge, group, key, title)                  \
    if (strcmp(#group, "rays") == 0 &&                                       \
        RT__FIELD_END(rt_render_stats, name) <= stats->size)                 \
        all += (uint64_t)stats->name;
    RT_STATS_MAP(RAYS_)
#undef RAYS_
    return all;
}

/* Fills the caller's stats (its size checked with the options) as far as
 * its size reaches (base/sized.h). */
static void fill_stats(const job *j, double seconds, rt_render_stats *out)
{
    rt_render_stats all, *stats = &all;
    memset(stats, 0, sizeof *stats);
    stats->size = sizeof *stats;    /* whole, for rt_render_stats_rays */
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
                                     rt_render_stats_rays(stats) * dead +
                                     j->totals.early_exit_saved;
    if (j->frame.settings.octree || j->frame.settings.kdtree) {
        const rt_octree_info *octree = &j->frame.octree;
        stats->accel_used = 1;
        stats->accel_kdtree = j->frame.settings.kdtree;
        stats->accel_build_seconds = octree->build_seconds;
        stats->accel_nodes = octree->nodes;
        stats->accel_leaves = octree->leaves;
        stats->accel_depth = octree->depth;
        stats->accel_references = octree->references;
        stats->accel_always = octree->always;
        stats->accel_bytes = octree->bytes;
        stats->accel_facets = (uint64_t)j->scene->live_count;
    }
    rt__sized_fill(out, stats, sizeof *stats);
}

static rt_status cancelled(rt_error *error)
{
    return rt__error_set(error, RT_ERR_CANCELLED, NULL, 0, 0,
                         "the render was cancelled");
}

/* Builds (once per scene and precision) the octree or the kd-tree of the
 * frame's kernel when the render asks for one (the kd-tree on the
 * render's threads), polling `cancel` (may be NULL); RT_OK,
 * RT_ERR_NOMEM or RT_ERR_CANCELLED (nothing kept: the next render builds
 * it). */
static rt_status prepare_octree(rt_frame *f, const rt_scene *scene,
                                const rt_render_options *options,
                                const rt_cancel *cancel)
{
    rt_accel accel = options->accel;
    if (accel == RT_ACCEL_NONE ||
        (accel == RT_ACCEL_AUTO && scene->live_count < RT_ACCEL_AUTO_FACETS))
        return RT_OK;
    if (accel == RT_ACCEL_KDTREE || accel == RT_ACCEL_AUTO) {
        int threads = thread_count(options->threads, INT_MAX);
        rt_status status = rt__kernel_prepare_kdtree(
            f->kernel, cancel, threads > 1 ? rt__scene_workers(scene) : NULL,
            threads, &f->octree);
        if (status == RT_OK)
            f->settings.kdtree = 1;
        return status;
    }
    rt_status status = rt__kernel_prepare_octree(f->kernel, cancel,
                                                 &f->octree);
    if (status == RT_OK)
        f->settings.octree = 1;
    return status;
}

static int same_point(rt_vec3 a, rt_vec3 b)
{
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

rt_status rt__frame_prepare(rt_frame *f, const rt_scene *scene,
                            const rt_render_plan *plan,
                            const rt_cancel *cancel, rt_error *error)
{
    const rt_render_options *options = &plan->options;
    memset(f, 0, sizeof *f);
    const rt_camera *camera = &plan->camera;
    double aperture = options->aperture >= 0.0 ? options->aperture
                                               : camera->aperture;
    double focal_distance = options->focal_distance > 0.0
                                ? options->focal_distance
                                : camera->focal_distance;
    if (!isfinite(aperture) || !isfinite(focal_distance))
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "a lens of aperture %g and focus %g: expected "
                             "finite numbers", aperture, focal_distance);
    f->camera = *camera;
    f->x0 = options->region.x0;
    f->y0 = options->region.y0;
    f->width = plan->width;
    f->grid = plan->grid;
    f->stratified = options->sampling == RT_SAMPLING_STRATIFIED;
    f->aperture = aperture;
    f->focal_distance = focal_distance;
    f->view_axis = v3_normalize(v3_sub(camera->screen_center,
                                       camera->observer));
    f->lens_right = v3_normalize(camera->right);
    f->lens_up = v3_normalize(camera->up);
    f->settings = (rt_trace_settings){options->max_depth,
                                      options->fast_inv_sqrt != 0,
                                      options->kernel, NULL, 0, NULL, 0};
    rt_status status = rt__scene_check_precision_with(
        scene, camera, options->precision, error);
    if (status != RT_OK)
        return status;
    /* The float kernel is built by the first float render and kept with
     * the scene: a double-only user never pays for float data. */
    f->kernel = rt__scene_kernel(scene, options->precision, cancel);
    if (f->kernel == NULL)
        return rt_cancel_requested(cancel) ? cancelled(error)
                                           : rt__render_out_of_memory(error);
    status = prepare_octree(f, scene, options, cancel);
    if (status == RT_ERR_CANCELLED)
        return cancelled(error);
    if (status != RT_OK)
        return rt__render_out_of_memory(error);
    /* The facets eight by eight and the camera rays' origin subtracted
     * from every vertex, made once for the scene: only the fast
     * brute-force loops read them. */
    if (options->kernel != RT_KERNEL_SCALAR && !f->settings.octree &&
        !f->settings.kdtree) {
        if (rt__kernel_prepare_blocks(f->kernel) != RT_OK)
            return rt__render_out_of_memory(error);
        /* The scene's eye serves its own observer; another camera's is
         * made for this frame and released with it. */
        if (same_point(camera->observer, scene->camera.observer)) {
            f->settings.eye = rt__scene_eye(scene, options->precision);
        } else {
            f->own_eye = rt__kernel_eye_create(f->kernel, camera->observer);
            f->settings.eye = f->own_eye;
        }
        if (f->settings.eye == NULL)
            return rt__render_out_of_memory(error);
    }
    f->camera.width = plan->full_width;
    f->camera.height = plan->full_height;
    return RT_OK;
}

void rt__frame_release(rt_frame *frame)
{
    if (frame->own_eye != NULL)
        rt__kernel_eye_destroy(frame->kernel, frame->own_eye);
    frame->own_eye = NULL;
    frame->settings.eye = NULL;
}

rt_status rt__frame_setup(const rt_scene *scene,
                          const rt_render_options *options, rt_frame *frame,
                          int *width, int *height, int *samples,
                          rt_error *error)
{
    if (scene == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "no scene");
    rt_render_plan plan;
    rt_status status = rt__render_take(scene, options, &plan, error);
    if (status == RT_OK)
        status = rt__render_check(&plan, error);
    if (status == RT_OK)
        status = rt__frame_prepare(frame, scene, &plan, NULL, error);
    if (status != RT_OK)
        return status;
    *width = plan.width;
    *height = plan.height;
    *samples = plan.grid * plan.grid;
    return RT_OK;
}

/* The checks of rt_render_rows on the image and the band. */
static rt_status check_image(const rt_render_plan *plan, int row_begin,
                             int row_end, const rt_image *image,
                             rt_error *error)
{
    if (image->pixels == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "the image has no pixels (see rt_image_init)");
    if (image->width != plan->width || image->height != plan->height)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "the image is %d x %d but the render writes "
                             "%d x %d", image->width, image->height,
                             plan->width, plan->height);
    if (image->stride < (size_t)image->width * 3)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "the image's stride is %zu bytes, less than 3 "
                             "x its width %d", image->stride, image->width);
    if (row_begin < 0 || row_end > image->height || row_begin > row_end)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "rows %d..%d: expected a band within 0..%d",
                             row_begin, row_end, image->height);
    const rt_image_float *linear = plan->options.linear;
    if (linear != NULL &&
        (linear->pixels == NULL || linear->width != image->width ||
         linear->height != image->height ||
         linear->stride < (size_t)linear->width * 3))
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "the linear image is %d x %d (stride %zu "
                             "floats) but the render writes %d x %d",
                             linear->width, linear->height, linear->stride,
                             image->width, image->height);
    return RT_OK;
}

rt_status rt_render_rows(const rt_scene *scene,
                         const rt_render_options *options, int row_begin,
                         int row_end, rt_image *image, rt_error *error)
{
    return rt__render_job(scene, options, row_begin, row_end, image, NULL,
                          -1, error);
}

rt_status rt__render_job(const rt_scene *scene,
                         const rt_render_options *caller_options,
                         int row_begin, int row_end, rt_image *image,
                         const rt_row_work *work, int max_depth,
                         rt_error *error)
{
    if (scene == NULL || image == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "no scene or no image");
    rt_render_plan plan;
    rt_status status = rt__render_take(scene, caller_options, &plan, error);
    if (status == RT_OK)
        status = check_image(&plan, row_begin, row_end, image, error);
    if (status == RT_OK && work != NULL && plan.options.linear != NULL)
        status = rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                               "a debug view has no linear colours: "
                               "expected no linear image");
    if (status == RT_OK)
        status = rt__render_check(&plan, error);
    if (status != RT_OK)
        return status;
    const rt_render_options *options = &plan.options;

    double start = rt__clock_seconds();
    job j = {.scene = scene, .options = options, .image = image,
             .work = work, .row_end = row_end};
    status = rt__frame_prepare(&j.frame, scene, &plan, options->cancel,
                               error);
    if (status != RT_OK)
        return status;
    if (max_depth >= 0)
        j.frame.settings.max_depth = max_depth;
    j.frame.linear = options->linear;
    atomic_init(&j.next_row, row_begin);
    atomic_init(&j.cancelled, 0);
    pthread_mutex_init(&j.callback_lock, NULL);
    pthread_mutex_init(&j.stats_lock, NULL);
    int n = thread_count(options->threads, row_end - row_begin);
    rt__workers_run(n > 1 ? rt__scene_workers(scene) : NULL, n, worker, &j);
    pthread_mutex_destroy(&j.callback_lock);
    pthread_mutex_destroy(&j.stats_lock);
    rt__frame_release(&j.frame);

    if (options->stats != NULL)
        fill_stats(&j, rt__clock_seconds() - start, options->stats);
    if (j.totals.out_of_memory)
        return rt__render_out_of_memory(error);
    if (atomic_load(&j.cancelled))
        return cancelled(error);
    return RT_OK;
}

rt_status rt_render(const rt_scene *scene, const rt_render_options *options,
                    rt_image *image, rt_error *error)
{
    if (scene == NULL || image == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "no scene or no image");
    return rt_render_rows(scene, options, 0, image->height, image, error);
}
