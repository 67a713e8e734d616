/*
 * metrics.c - image error metrics, timing summaries and the Pareto
 * front for rt-bench (see metrics.h).
 */
#include "metrics.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>

void bench_compare(const rt_image *test, const rt_image *reference,
                   bench_error *error)
{
    assert(test->width == reference->width &&
           test->height == reference->height);
    double sum = 0.0;
    int max_error = 0;
    long differing = 0, differing_much = 0;
    for (int y = 0; y < test->height; y++) {
        const unsigned char *a = rt_image_pixel(test, 0, y);
        const unsigned char *b = rt_image_pixel(reference, 0, y);
        for (int x = 0; x < test->width; x++) {
            int worst = 0;
            for (int c = 0; c < 3; c++) {
                int d = abs((int)a[3 * x + c] - (int)b[3 * x + c]);
                sum += (double)d * d;
                if (d > worst)
                    worst = d;
            }
            differing += worst > 0;
            differing_much += worst > BENCH_MUCH_LEVELS;
            if (worst > max_error)
                max_error = worst;
        }
    }
    long pixels = (long)test->width * test->height;
    error->pixels = pixels;
    error->rmse = pixels > 0 ? sqrt(sum / (3.0 * (double)pixels)) : 0.0;
    error->psnr = error->rmse > 0 ? 20.0 * log10(255.0 / error->rmse)
                                  : INFINITY;
    error->max_error = max_error;
    error->differing = differing;
    error->differing_much = differing_much;
}

double bench_percent(long count, long pixels)
{
    return pixels > 0 ? 100.0 * (double)count / (double)pixels : 0.0;
}

static int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

void bench_summarize(double *values, int count, double *median,
                     double *minimum, double *maximum)
{
    assert(count >= 1);
    qsort(values, (size_t)count, sizeof *values, compare_doubles);
    *minimum = values[0];
    *maximum = values[count - 1];
    *median = count % 2 ? values[count / 2]
                        : 0.5 * (values[count / 2 - 1] + values[count / 2]);
}

int bench_pareto_front(const double *x, const double *y, int count,
                       int *on_front)
{
    int front = 0;
    for (int i = 0; i < count; i++) {
        on_front[i] = 1;
        for (int j = 0; j < count && on_front[i]; j++) {
            if (x[j] <= x[i] && y[j] <= y[i] && (x[j] < x[i] || y[j] < y[i]))
                on_front[i] = 0;
        }
        front += on_front[i];
    }
    return front;
}

double bench_peak_needed(double local, double carried)
{
    if (!(local > 0.0))
        return 0.0;
    return carried < 1.0 ? local / (1.0 - carried) : INFINITY;
}

double bench_truncation_bound(const bench_depth_bound *bound, int depth)
{
    int hits = depth + 1;
    double weight = pow(bound->pair, hits / 2) *
                    (hits % 2 ? bound->k_max : 1.0);
    return weight == 0.0 ? 0.0 : fmin(bound->peak * weight, 255.0);
}

unsigned long long bench_image_hash(const rt_image *image)
{
    unsigned long long h = 14695981039346656037ull;
    for (int y = 0; y < image->height; y++) {
        const unsigned char *row = rt_image_pixel(image, 0, y);
        for (size_t i = 0; i < (size_t)image->width * 3; i++) {
            h ^= row[i];
            h *= 1099511628211ull;
        }
    }
    return h;
}
