/*
 * measure.c - rt-bench's timed renders (see measure.h).
 */
#include "measure.h"

#include <stdio.h>
#include <string.h>

#include "cli_clock.h"
#include "metrics.h"

void bench_images_release(bench_images *im)
{
    rt_image_release(&im->reference);
    rt_image_release(&im->scratch);
    rt_image_release(&im->depth_reference);
    for (int i = 0; i < BENCH_MAX_CONFIGS; i++)
        rt_image_release(&im->kept[i]);
}

/* Renders with the options the user gave (size, lens, threads) and the
 * knobs `s`; *seconds is the wall-clock time of the call. */
static rt_status render(const rt_scene *scene, const bench_settings *s,
                        const rt_render_options *base, rt_image *image,
                        double *seconds, rt_error *error)
{
    rt_render_options options = *base;
    options.precision = s->precision;
    options.fast_inv_sqrt = s->fast_sqrt;
    options.samples = s->grid * s->grid;
    options.sampling = s->sampling;
    options.max_depth = s->depth;
    double start = cli_clock_seconds();
    rt_status status = rt_render(scene, &options, image, error);
    *seconds = cli_seconds_since(start);
    return status;
}

int bench_render(const rt_scene *scene, const bench_settings *s,
                 const rt_render_options *base, rt_image *image,
                 double *seconds)
{
    rt_error error;
    rt_status status = render(scene, s, base, image, seconds, &error);
    if (status != RT_OK)
        fprintf(stderr, "rt-bench: cannot render: %s\n", error.message);
    return status == RT_OK;
}

static void progress(int quiet, int round, int runs, int i, int count,
                     const char *label)
{
    if (!quiet)
        fprintf(stderr, "rt-bench: run %d/%d, setting %d/%d: %s\n",
                round + 1, runs, i + 1, count, label);
}

int bench_measure(const rt_scene *scene, const rt_render_options *base,
                  int runs, int quiet, bench_config *configs, int count,
                  bench_images *im)
{
    for (int round = 0; round < runs; round++) {
        /* double/exact settings first: the others' numerical error needs
         * their images */
        for (int pass = 0; pass < 2; pass++) {
            for (int i = 0; i < count; i++) {
                bench_config *c = &configs[i];
                int is_base = c->base == i;
                if ((pass == 0) != is_base)
                    continue;
                progress(quiet, round, runs, i, count, c->row.label);
                rt_image *image = round == 0 && is_base ? &im->kept[i]
                                                        : &im->scratch;
                if (image->pixels == NULL &&
                    rt_image_init(image, im->reference.width,
                                    im->reference.height, NULL) != RT_OK) {
                    fprintf(stderr, "rt-bench: out of memory\n");
                    return 0;
                }
                if (!bench_render(scene, &c->s, base, image,
                                  &c->times[round]))
                    return 0;
                unsigned long long hash = bench_image_hash(image);
                if (round == 0) {
                    c->hash = hash;
                    bench_compare(image, &im->reference, &c->row.total);
                    bench_compare(image, &im->kept[c->base],
                                  &c->row.numerical);
                } else if (hash != c->hash) {
                    fprintf(stderr, "rt-bench: %s: run %d gave a different "
                                    "image from run 1\n",
                            c->row.label, round + 1);
                    return 0;
                }
            }
        }
    }
    for (int i = 0; i < count; i++) {
        double sorted[BENCH_MAX_RUNS];
        memcpy(sorted, configs[i].times, sizeof sorted);
        configs[i].row.runs = runs;
        bench_summarize(sorted, runs, &configs[i].row.median,
                        &configs[i].row.minimum, &configs[i].row.maximum);
    }
    return 1;
}
