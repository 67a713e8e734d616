/*
 * measure.h - rt-bench's timed renders (docs/accuracy.md): each setting of
 * the sweep rendered `runs` times in rounds, the settings taking turns so
 * that a slow period of the machine spreads over all of them; the first
 * round measures the errors (against the converged reference, and against
 * the same setting in double with the exact square root), the later ones
 * must give the same image.  Progress lines go to stderr unless quiet.
 */
#ifndef RT_BENCH_MEASURE_H
#define RT_BENCH_MEASURE_H

#include "raytrace/raytrace.h"
#include "sweep.h"

/* The images of a run, released together. */
typedef struct bench_images {
    rt_image reference, scratch, depth_reference;
    rt_image kept[BENCH_MAX_CONFIGS];   /* round one's double/exact images */
} bench_images;

void bench_images_release(bench_images *im);

/* Renders with the options the user gave (`base`: size, lens, threads)
 * and the knobs `s` into `image`; *seconds is the wall-clock time of the
 * call.  Returns 1, or 0 after "rt-bench: cannot render: REASON". */
int bench_render(const rt_scene *scene, const bench_settings *s,
                 const rt_render_options *base, rt_image *image,
                 double *seconds);

/* Renders every config `runs` times and fills its row (errors, median,
 * minimum and maximum time).  im->reference must hold the reference.
 * Returns 0 (after a message) if a render failed or a repeat differed. */
int bench_measure(const rt_scene *scene, const rt_render_options *base,
                  int runs, int quiet, bench_config *configs, int count,
                  bench_images *im);

#endif /* RT_BENCH_MEASURE_H */
