/*
 * render_internal.h - what the parts of the renderer share (internal):
 * the options as a render takes them (options.c), the frame every pixel
 * of a render reads (prepared by render.c, read by pixel.c), and the
 * pixel loops (pixel.c) that render.c's rows and explain.c's single pixels
 * both run, so that an explained pixel is the rendered one bit for bit.
 */
#ifndef RAYTRACE_RENDER_INTERNAL_H
#define RAYTRACE_RENDER_INTERNAL_H

#include <stdatomic.h>

#include "base/cancel.h"
#include "base/sized.h"
#include "kernel/kernel.h"
#include "raytrace/render.h"

/* ---- the options (options.c) ---------------------------------------- */

/* A render's options once taken and checked, with what they imply. */
typedef struct rt_render_plan {
    rt_render_options options;  /* the caller's, defaults beyond its size;
                                   options.camera points at `camera` */
    rt_camera camera;           /* the render's: the caller's copy (checked
                                   by rt__render_check), else the scene's */
    int full_width, full_height;    /* the whole image */
    int width, height;          /* the output image: the region's */
    int grid;                   /* samples per side of a pixel */
} rt_render_plan;

/*
 * Takes `options` (NULL: the defaults) as a render of `scene` reads them,
 * field by field as far as their size reaches, and works out the image's
 * size; RT_OK with plan->options and the sizes filled, else
 * RT_ERR_ARGUMENT with the reason in *error (may be NULL).
 */
rt_status rt__render_take(const rt_scene *scene,
                          const rt_render_options *options,
                          rt_render_plan *plan, rt_error *error);

/* Checks every other field of the taken options (each in its domain, the
 * samples a square) and sets plan->grid; RT_OK, else RT_ERR_ARGUMENT with
 * the field and its value in *error. */
rt_status rt__render_check(rt_render_plan *plan, rt_error *error);

/* The least size of the caller's rt_render_stats: its layout of 0.3
 * (raytrace/render.h), whose last counter is refraction_rays_skipped. */
#define RT__RENDER_STATS_SIZE_0_3                                            \
    RT__FIELD_END(rt_render_stats, refraction_rays_skipped)

/* The RT_ERR_NOMEM every render step reports. */
rt_status rt__render_out_of_memory(rt_error *error);

/* ---- the frame (render.c) and the pixels (pixel.c) ------------------ */

/* What the pixel loops read of one render, set up once per call and then
 * only read, by every thread. */
typedef struct rt_frame {
    rt_camera camera;       /* the render's (rt_render_plan.camera), at
                               the render's image size */
    int x0, y0;             /* the region's top-left pixel in that image */
    int width;              /* the output image's width: the region's */
    int grid;               /* samples per side of a pixel */
    int stratified;         /* RT_SAMPLING_STRATIFIED */
    double aperture;        /* the lens radius of this render (0: pinhole) */
    double focal_distance;  /* the distance in focus, along AO */
    rt_vec3 view_axis;      /* unit O->A, for the lens (once per render) */
    rt_vec3 lens_right;     /* unit AB */
    rt_vec3 lens_up;        /* unit AC */
    const rt_kernel *kernel;    /* the scene's, in the render's precision */
    rt_trace_settings settings;
    rt_octree_info octree;  /* when settings.octree */
    rt_kernel_eye *own_eye; /* the eye of a camera other than the scene's,
                               made for this frame (rt__frame_release) */
    const rt_image_float *linear;   /* NULL, or where rt__frame_row also
                                       writes the linear colours (checked
                                       by rt__render_job) */
} rt_frame;

/* The float a linear image holds for a channel of value `value` (0..255
 * scale): the nearest float to value / 255, moved by one unit in the last
 * place towards `value` when that float would round to another byte, so
 * that rt_channel_to_byte(255.0 * (double)result) is always
 * rt_channel_to_byte(value). */
float rt__linear_channel(double value);

/*
 * Sets up *frame for a render of `scene` by `plan`: camera, lens, the
 * scene's kernel in the plan's precision, its octree when the render takes
 * one and the eye of the camera rays (the kernel, octree and eye are the
 * scene's, built by the first render that needs them and kept).  The
 * constructions poll `cancel` (may be NULL): RT_ERR_CANCELLED when it was
 * raised before they were complete; also RT_ERR_RANGE (a float render of
 * a scene float cannot hold) and RT_ERR_NOMEM, with *error filled.
 */
rt_status rt__frame_prepare(rt_frame *frame, const rt_scene *scene,
                            const rt_render_plan *plan,
                            const rt_cancel *cancel, rt_error *error);

/* Frees what rt__frame_prepare made for this frame alone (the eye of a
 * camera other than the scene's); every frame prepared, successfully or
 * not, is released.  Idempotent. */
void rt__frame_release(rt_frame *frame);

/* The frame of a render of `scene` with `options` (NULL: the defaults),
 * taken, checked and prepared as rt_render does it (the same statuses and
 * messages; cancellation not polled), with the output image's size and
 * the samples per pixel: what single pixels are traced with. */
rt_status rt__frame_setup(const rt_scene *scene,
                          const rt_render_options *options, rt_frame *frame,
                          int *width, int *height, int *samples,
                          rt_error *error);

/* What the pixel loops of a render poll before each pixel (or span of
 * pixels): the job's flag, raised once the render must stop (its row
 * callback said so, or a poll saw the caller's flag), and the caller's
 * cancellation flag (may be NULL). */
typedef struct rt_stop {
    atomic_int *stopped;
    const rt_cancel *cancel;
} rt_stop;

/* Non-zero once the render must stop; a raised caller's flag is then
 * remembered in *stop->stopped. */
static inline int rt__stop_now(const rt_stop *stop)
{
    if (atomic_load_explicit(stop->stopped, memory_order_relaxed))
        return 1;
    if (stop->cancel != NULL && rt__cancel_raised(stop->cancel)) {
        atomic_store(stop->stopped, 1);
        return 1;
    }
    return 0;
}

/* Renders row `row` of the output image into `out` (its first pixel),
 * polling `stop` before each pixel or span, its work added to
 * *counters; 0 when it stopped before the row was complete. */
int rt__frame_row(const rt_frame *frame, int row, unsigned char *out,
                  const rt_stop *stop, rt_counters *counters);

/* The value of pixel (x, y) of the output image: sample -1, the mean of
 * all its samples as rendered; else that one sample. */
rt_color rt__frame_pixel(const rt_frame *frame, int x, int y, int sample,
                         rt_counters *counters);

/* ---- jobs of rows (render.c) ---------------------------------------- */

/*
 * What a job of rows computes in each row, when it is not the picture
 * (rt__frame_row): a debug view's pixels (explain.c).  `row` renders row
 * `row` of the output image into `out`, polling `stop` before each pixel
 * and adding its work to *counters; 0 when it stopped (or ran out of
 * memory: counters->out_of_memory set).  *thread is the calling thread's
 * own state, NULL at its first row; `thread_end` (may be NULL) frees it
 * when the thread leaves the job.  With `report_rows` 0, on_row is not
 * called by the job (the caller reports the rows itself once written).
 */
typedef struct rt_row_work {
    int (*row)(void *user, const rt_frame *frame, int row, unsigned char *out,
               const rt_stop *stop, rt_counters *counters, void **thread);
    void (*thread_end)(void *user, void *thread);
    void *user;
    int report_rows;
} rt_row_work;

/* rt_render_rows with `work` in each row (NULL: the picture) and the
 * frame's depth replaced by `max_depth` when it is >= 0 (a view that reads
 * only the camera ray's hit traces no bounce).  The same checks, threads,
 * cancellation, statistics and statuses. */
rt_status rt__render_job(const rt_scene *scene,
                         const rt_render_options *options, int row_begin,
                         int row_end, rt_image *image,
                         const rt_row_work *work, int max_depth,
                         rt_error *error);

#endif /* RAYTRACE_RENDER_INTERNAL_H */
