/*
 * plot.h - an SVG scatter plot of error against time, log-log, with
 * the Pareto front drawn as a polyline.
 *
 * Written by hand (no plotting library) so that rt-bench has no dependency
 * beyond libraytrace: log axes with ticks at 1, 2, 5 x 10^k (decades only
 * when the range is wide), grid lines, one point per configuration whose
 * fill colour and shape are chosen by the caller and explained in a legend,
 * a horizontal bar for the spread of the timing, labels next to the points
 * on the front, and a tooltip (<title>) on every point.  Values must be
 * positive; an error of 0 (exactly the reference) is drawn on the bottom
 * edge and the legend says so.  Thread-safe on distinct files.
 */
#ifndef RT_BENCH_PLOT_H
#define RT_BENCH_PLOT_H

#include <stdio.h>

/* Marker shapes (index into bench_plot.shape_names). */
enum { BENCH_SHAPE_CIRCLE, BENCH_SHAPE_SQUARE, BENCH_SHAPE_TRIANGLE,
       BENCH_SHAPE_DIAMOND, BENCH_SHAPE_COUNT };

/* Fill colours available (index into bench_plot.colour_names). */
#define BENCH_COLOUR_COUNT 6

typedef struct bench_plot_point {
    double x, x_low, x_high;    /* time: median and its spread, > 0 */
    double y;                   /* error, >= 0 */
    int colour;                 /* 0..colour_count - 1 */
    int shape;                  /* 0..shape_count - 1 */
    int on_front;               /* part of the Pareto front */
    const char *label;          /* short name, shown for front points */
    const char *tooltip;        /* longer text for <title>; may be NULL */
} bench_plot_point;

typedef struct bench_plot {
    const char *title;
    const char *subtitle;       /* may be NULL */
    const char *x_label;
    const char *y_label;
    const char *const *colour_names;    /* legend text per colour */
    int colour_count;                   /* <= BENCH_COLOUR_COUNT */
    const char *const *shape_names;     /* legend text per shape */
    int shape_count;                    /* <= BENCH_SHAPE_COUNT */
    const bench_plot_point *points;
    int count;
} bench_plot;

/* Writes the plot as a standalone SVG document; returns 1 on success, 0 if
 * writing failed. */
int bench_plot_write_svg(FILE *file, const bench_plot *plot);

#endif /* RT_BENCH_PLOT_H */
