/*
 * render_internal.h - single pixels traced as a render would (internal).
 *
 * A pixel tracer holds one render's setup (options, camera, lens, kernel,
 * octree) so that explain.c can trace any pixel, or one sample of it, with
 * a recorder attached and get the value rt_render computes for it, bit for
 * bit: the same render_pixel runs.  Not thread-safe: one caller at a time.
 */
#ifndef RAYTRACE_RENDER_INTERNAL_H
#define RAYTRACE_RENDER_INTERNAL_H

#include "kernel/kernel.h"
#include "raytrace/render.h"

typedef struct rt_pixel_tracer rt_pixel_tracer;

/* The setup of a render of `scene` with `options` (NULL: defaults); the
 * statuses and messages of rt_render for bad options. */
rt_status rt__pixel_tracer_create(const rt_scene *scene,
                                  const rt_render_options *options,
                                  rt_pixel_tracer **tracer, rt_error *error);
void rt__pixel_tracer_destroy(rt_pixel_tracer *tracer); /* NULL: no-op */

/* The output image's size and the samples per pixel. */
void rt__pixel_tracer_size(const rt_pixel_tracer *tracer, int *width,
                           int *height, int *samples);

/* The value of pixel (x, y) of the output image (sample -1: the mean of
 * all, as rendered) or of one sample, recording into `recorder` (may be
 * NULL); *out_of_memory non-zero when a ray tree could not grow. */
rt_color rt__pixel_tracer_trace(rt_pixel_tracer *tracer, int x, int y,
                                int sample, rt_trace_recorder *recorder,
                                int *out_of_memory);

#endif /* RAYTRACE_RENDER_INTERNAL_H */
