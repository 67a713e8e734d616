/*
 * metrics.h - how far an image is from another, and which of a set
 * of (time, error) points are worth having.
 *
 * The error of a test image against a reference image of the same size,
 * both RGB8: the root mean square of the channel differences (every
 * channel of every pixel counts once), the PSNR it gives against a peak of
 * 255, the largest channel difference, and two pixel counts that an average
 * hides: pixels where some channel differs at all, and pixels where some
 * channel differs by more than 2 levels (precision errors show up as a few
 * full flips at edges and shadow boundaries, not as a uniform haze).
 * Timing summaries (median, minimum, maximum of repeated runs) and the
 * Pareto front of a set of points complete the module.
 * None of these functions allocates or fails; all are thread-safe on
 * distinct arguments.
 */
#ifndef RT_BENCH_METRICS_H
#define RT_BENCH_METRICS_H

#include <stddef.h>

#include "raytrace/image.h"

/* Levels of difference above which a pixel counts as "changed much". */
#define BENCH_MUCH_LEVELS 2

typedef struct bench_error {
    double rmse;            /* sqrt(mean of squared channel differences) */
    double psnr;            /* 20 log10(255 / rmse) dB; INFINITY if rmse 0 */
    int max_error;          /* largest |difference| of one channel, 0..255 */
    long pixels;            /* pixels compared: width * height */
    long differing;         /* pixels with some channel different */
    long differing_much;    /* pixels with some channel off by > 2 levels */
} bench_error;

/* Fills `error` with the error of `test` against `reference`; both must
 * have the same width and height (asserted). */
void bench_compare(const rt_image *test, const rt_image *reference,
                   bench_error *error);

/* 100 * count / pixels, or 0 for an empty image. */
double bench_percent(long count, long pixels);

/* Median (the mean of the two middle values for an even count), minimum
 * and maximum of `count` >= 1 values; `values` is sorted in place. */
void bench_summarize(double *values, int count, double *median,
                     double *minimum, double *maximum);

/*
 * Marks the Pareto front of `count` points (x[i], y[i]), smaller being
 * better on both axes: on_front[i] is set to 1 when no other point is at
 * least as good on both axes and strictly better on one, else 0.  Equal
 * points are all on the front.  Returns how many points are on it.
 */
int bench_pareto_front(const double *x, const double *y, int count,
                       int *on_front);

/*
 * The truncation bound of the reflection depth (docs/accuracy.md): every
 * colour a ray carries is at most `peak`; a hit passes on k + t of what its
 * reflected and refracted rays carry; two hits in a row are never on the
 * same plane, so the rays n hits deep weigh at most
 * pair^(n/2) k_max^(n%2).
 */
typedef struct bench_depth_bound {
    double peak;        /* largest colour any ray can carry (may be inf) */
    double k_max;       /* largest k + t of a facet that can be hit */
    double pair;        /* largest (k+t)_i (k+t)_j, facets not coplanar */
} bench_depth_bound;

/* The peak a facet needs so that its colour, (k + t) times what its rays
 * carry plus a local term of at most `local`, stays within the peak:
 * local / (1 - carried), with carried = k + t; 0 when local is 0, INFINITY
 * when carried >= 1 and local > 0 (no finite peak). */
double bench_peak_needed(double local, double carried);

/* B(depth) = peak * pair^((depth+1)/2) * k_max^((depth+1)%2) levels,
 * capped at 255 (the format's range); exactly 0 when the weight is 0, even
 * for an infinite peak. */
double bench_truncation_bound(const bench_depth_bound *bound, int depth);

/* A 64-bit FNV-1a hash of the pixels (not the padding), to check that
 * repeated renders gave the same image without keeping every one. */
unsigned long long bench_image_hash(const rt_image *image);

#endif /* RT_BENCH_METRICS_H */
