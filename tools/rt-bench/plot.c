/*
 * plot.c - the SVG error-against-time plot of rt-bench (see plot.h).
 *
 * Geometry: a 960 x 640 canvas, the plot area on the left, the legend in a
 * column on the right.  Each axis maps log10 of its value linearly onto the
 * area; ranges are padded by 6% so that no point sits on a border.
 */
#include "plot.h"

#include <math.h>
#include <string.h>

#define WIDTH 960
#define HEIGHT 640
#define LEFT 84.0
#define RIGHT 700.0
#define TOP 70.0
#define BOTTOM 572.0

static const char *const fills[BENCH_COLOUR_COUNT] = {
    "#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b"};

/* A log10 axis from lo to hi (both log10 values) onto [a, b] pixels. */
typedef struct axis {
    double lo, hi;
    double a, b;
} axis;

static double place(const axis *ax, double value)
{
    return ax->a + (log10(value) - ax->lo) / (ax->hi - ax->lo) * (ax->b - ax->a);
}

/* Fits an axis to the positive values in [min, max] with some padding. */
static axis fit(double min, double max, double a, double b)
{
    double lo = log10(min), hi = log10(max);
    if (hi - lo < 0.5) {
        double mid = 0.5 * (lo + hi);
        lo = mid - 0.25;
        hi = mid + 0.25;
    }
    double pad = 0.06 * (hi - lo);
    return (axis){lo - pad, hi + pad, a, b};
}

static void write_escaped(FILE *f, const char *text)
{
    for (; text != NULL && *text != '\0'; text++) {
        if (*text == '&')
            fputs("&amp;", f);
        else if (*text == '<')
            fputs("&lt;", f);
        else if (*text == '>')
            fputs("&gt;", f);
        else
            fputc(*text, f);
    }
}

static void marker(FILE *f, int shape, double x, double y, double r,
                   const char *fill, const char *stroke, double stroke_width)
{
    switch (shape) {
    case BENCH_SHAPE_SQUARE:
        fprintf(f, "<rect x='%.1f' y='%.1f' width='%.1f' height='%.1f'",
                x - r * 0.85, y - r * 0.85, r * 1.7, r * 1.7);
        break;
    case BENCH_SHAPE_TRIANGLE:
        fprintf(f, "<polygon points='%.1f,%.1f %.1f,%.1f %.1f,%.1f'", x,
                y - r * 1.15, x - r, y + r * 0.75, x + r, y + r * 0.75);
        break;
    case BENCH_SHAPE_DIAMOND:
        fprintf(f, "<polygon points='%.1f,%.1f %.1f,%.1f %.1f,%.1f "
                   "%.1f,%.1f'",
                x, y - r * 1.2, x + r * 1.2, y, x, y + r * 1.2, x - r * 1.2,
                y);
        break;
    default:
        fprintf(f, "<circle cx='%.1f' cy='%.1f' r='%.1f'", x, y, r);
        break;
    }
    fprintf(f, " fill='%s' stroke='%s' stroke-width='%.1f'", fill, stroke,
            stroke_width);
}

/* Ticks and grid lines of one axis; `vertical` for the x axis. */
static void ticks(FILE *f, const axis *ax, int vertical)
{
    int dense = ax->hi - ax->lo <= 2.5;
    for (int e = (int)floor(ax->lo) - 1; e <= (int)ceil(ax->hi); e++) {
        for (int m = 1; m <= 9; m++) {
            double v = m * pow(10.0, e);
            double l = log10(v);
            if (l < ax->lo || l > ax->hi)
                continue;
            int labelled = m == 1 || (dense && (m == 2 || m == 5));
            double p = place(ax, v);
            if (vertical) {
                fprintf(f, "<line x1='%.1f' y1='%.1f' x2='%.1f' y2='%.1f' "
                           "stroke='%s'/>\n",
                        p, labelled ? TOP : BOTTOM - 4, p, BOTTOM,
                        labelled ? "#ddd" : "#999");
                if (labelled)
                    fprintf(f, "<text x='%.1f' y='%.1f' "
                               "text-anchor='middle'>%g</text>\n",
                            p, BOTTOM + 18, v);
            } else {
                fprintf(f, "<line x1='%.1f' y1='%.1f' x2='%.1f' y2='%.1f' "
                           "stroke='%s'/>\n",
                        LEFT, p, labelled ? RIGHT : LEFT + 4, p,
                        labelled ? "#ddd" : "#999");
                if (labelled)
                    fprintf(f, "<text x='%.1f' y='%.1f' "
                               "text-anchor='end'>%g</text>\n",
                            LEFT - 6, p + 4, v);
            }
        }
    }
}

static void legend(FILE *f, const bench_plot *plot, int any_zero)
{
    double x = RIGHT + 24, y = TOP + 4;
    fprintf(f, "<text x='%.1f' y='%.1f' font-weight='bold'>arithmetic"
               "</text>\n", x, y);
    for (int i = 0; i < plot->colour_count; i++) {
        y += 20;
        marker(f, BENCH_SHAPE_CIRCLE, x + 6, y - 4, 5, fills[i], "#333", 0.8);
        fputs("/>\n", f);
        fprintf(f, "<text x='%.1f' y='%.1f'>", x + 18, y);
        write_escaped(f, plot->colour_names[i]);
        fputs("</text>\n", f);
    }
    y += 34;
    fprintf(f, "<text x='%.1f' y='%.1f' font-weight='bold'>pixel sampling"
               "</text>\n", x, y);
    for (int i = 0; i < plot->shape_count; i++) {
        y += 20;
        marker(f, i, x + 6, y - 4, 5, "#bbb", "#333", 0.8);
        fputs("/>\n", f);
        fprintf(f, "<text x='%.1f' y='%.1f'>", x + 18, y);
        write_escaped(f, plot->shape_names[i]);
        fputs("</text>\n", f);
    }
    y += 34;
    fprintf(f, "<line x1='%.1f' y1='%.1f' x2='%.1f' y2='%.1f' "
               "stroke='#000' stroke-width='1.5' stroke-dasharray='6 3'/>\n",
            x, y - 4, x + 14, y - 4);
    fprintf(f, "<text x='%.1f' y='%.1f'>Pareto front (labelled)</text>\n",
            x + 18, y);
    y += 20;
    fprintf(f, "<line x1='%.1f' y1='%.1f' x2='%.1f' y2='%.1f' "
               "stroke='#555' stroke-width='1.2'/>\n",
            x, y - 4, x + 14, y - 4);
    fprintf(f, "<text x='%.1f' y='%.1f'>time: min to max of runs</text>\n",
            x + 18, y);
    if (any_zero) {
        y += 20;
        fprintf(f, "<text x='%.1f' y='%.1f'>on the bottom edge: error 0"
                   "</text>\n", x, y);
    }
}

int bench_plot_write_svg(FILE *f, const bench_plot *plot)
{
    double x_min = INFINITY, x_max = 0, y_min = INFINITY, y_max = 0;
    int any_zero = 0;
    for (int i = 0; i < plot->count; i++) {
        const bench_plot_point *p = &plot->points[i];
        x_min = fmin(x_min, fmin(p->x, p->x_low));
        x_max = fmax(x_max, fmax(p->x, p->x_high));
        if (p->y > 0) {
            y_min = fmin(y_min, p->y);
            y_max = fmax(y_max, p->y);
        } else {
            any_zero = 1;
        }
    }
    if (!(x_min > 0 && x_max >= x_min))
        x_min = 1e-3, x_max = 1;
    if (y_max == 0)
        y_min = 1e-2, y_max = 1;
    double y_floor = y_min / 3;
    axis ax = fit(x_min, x_max, LEFT, RIGHT);
    axis ay = fit(any_zero ? y_floor : y_min, y_max, BOTTOM, TOP);

    fprintf(f, "<?xml version='1.0' encoding='UTF-8'?>\n"
               "<svg xmlns='http://www.w3.org/2000/svg' width='%d' "
               "height='%d' viewBox='0 0 %d %d' font-family='sans-serif' "
               "font-size='12'>\n"
               "<rect width='100%%' height='100%%' fill='white'/>\n",
            WIDTH, HEIGHT, WIDTH, HEIGHT);
    fprintf(f, "<text x='%.1f' y='26' font-size='17' font-weight='bold'>",
            LEFT);
    write_escaped(f, plot->title);
    fputs("</text>\n", f);
    if (plot->subtitle != NULL) {
        fprintf(f, "<text x='%.1f' y='46' fill='#444'>", LEFT);
        write_escaped(f, plot->subtitle);
        fputs("</text>\n", f);
    }
    ticks(f, &ax, 1);
    ticks(f, &ay, 0);
    fprintf(f, "<rect x='%.1f' y='%.1f' width='%.1f' height='%.1f' "
               "fill='none' stroke='#333'/>\n",
            LEFT, TOP, RIGHT - LEFT, BOTTOM - TOP);
    fprintf(f, "<text x='%.1f' y='%.1f' text-anchor='middle'>",
            0.5 * (LEFT + RIGHT), BOTTOM + 42);
    write_escaped(f, plot->x_label);
    fprintf(f, "</text>\n<text transform='translate(%.1f %.1f) rotate(-90)' "
               "text-anchor='middle'>",
            22.0, 0.5 * (TOP + BOTTOM));
    write_escaped(f, plot->y_label);
    fputs("</text>\n", f);

    /* The front: a polyline through its points in order of time. */
    fputs("<polyline fill='none' stroke='#000' stroke-width='1.5' "
          "stroke-dasharray='6 3' points='", f);
    double last = -INFINITY;
    for (;;) {
        int next = -1;
        for (int i = 0; i < plot->count; i++) {
            const bench_plot_point *p = &plot->points[i];
            if (p->on_front && p->x > last &&
                (next < 0 || p->x < plot->points[next].x))
                next = i;
        }
        if (next < 0)
            break;
        const bench_plot_point *p = &plot->points[next];
        fprintf(f, "%.1f,%.1f ", place(&ax, p->x),
                place(&ay, p->y > 0 ? p->y : y_floor));
        last = p->x;
    }
    fputs("'/>\n", f);

    int labelled = 0;
    for (int i = 0; i < plot->count; i++) {
        const bench_plot_point *p = &plot->points[i];
        double px = place(&ax, p->x);
        double py = place(&ay, p->y > 0 ? p->y : y_floor);
        const char *fill = fills[p->colour % BENCH_COLOUR_COUNT];
        fprintf(f, "<g><title>");
        write_escaped(f, p->tooltip != NULL ? p->tooltip : p->label);
        fputs("</title>\n", f);
        if (p->x_high > p->x_low)
            fprintf(f, "<line x1='%.1f' y1='%.1f' x2='%.1f' y2='%.1f' "
                       "stroke='%s' stroke-width='1.2'/>\n",
                    place(&ax, p->x_low), py, place(&ax, p->x_high), py,
                    fill);
        marker(f, p->shape, px, py, p->on_front ? 6 : 4.5, fill,
               p->on_front ? "#000" : "#333", p->on_front ? 1.6 : 0.6);
        fputs(" fill-opacity='0.85'/>\n", f);
        if (p->on_front && p->label != NULL) {
            fprintf(f, "<text x='%.1f' y='%.1f' font-size='11'>", px + 8,
                    py + (labelled % 2 ? 14 : -7));
            write_escaped(f, p->label);
            fputs("</text>\n", f);
            labelled++;
        }
        fputs("</g>\n", f);
    }
    legend(f, plot, any_zero);
    fputs("</svg>\n", f);
    return !ferror(f);
}
