/*
 * pixel.c - the colour of a pixel: its camera rays (the pinhole camera of
 * docs/rendering-model.md, the samples of a pixel, the thin lens), traced
 * through the frame's kernel one by one or as a span of a row, and their
 * mean rounded to bytes.  render.c runs these loops over rows and
 * threads, explain.c over single pixels; nothing here knows the kernel's
 * precision.
 */
#include <math.h>
#include <stdint.h>

#include "base/error.h"
#include "base/vecmath.h"
#include "render_internal.h"
#include "scene/scene_internal.h"

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
    if (!RT__EXPECT(scene != NULL) || !v3_is_finite(ray.direction) ||
        v3_max_abs(ray.direction) == 0.0 || max_depth < 0)
        return (rt_color){0.0, 0.0, 0.0};
    return rt__kernel_trace(scene->kernel, ray.origin, ray.direction,
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
static rt_ray lens_ray(const rt_frame *f, rt_ray pinhole, double x, double y)
{
    const rt_camera *camera = &f->camera;
    double u, v;
    square_to_disk(x, y, &u, &v);
    rt_vec3 to_focus = v3_scale(pinhole.direction,
                                f->focal_distance /
                                    v3_dot(pinhole.direction, f->view_axis));
    rt_vec3 focus = v3_add(camera->observer, to_focus);
    rt_vec3 offset = v3_add(v3_scale(f->lens_right, u),
                            v3_scale(f->lens_up, v));
    rt_vec3 lens = v3_add(camera->observer, v3_scale(offset, f->aperture));
    return (rt_ray){lens, v3_sub(focus, lens)};
}

static rt_color trace(const rt_frame *f, rt_ray ray, rt_counters *counters)
{
    counters->camera_rays++;
    return rt__kernel_trace(f->kernel, ray.origin, ray.direction,
                            &f->settings, counters);
}

/* The camera ray of sample (sx, sy) of pixel (i, row) of the whole image
 * when there are n x n > 1 samples. */
static inline rt_ray sample_ray(const rt_frame *f, int i, int row, int sx,
                                int sy)
{
    int n = f->grid;
    int stratified = f->stratified;
    uint32_t sample = (uint32_t)(sy * n + sx);
    double u = stratified ? hash_unit((uint32_t)i, (uint32_t)row, 2 * sample)
                          : 0.5;
    double v = stratified ? hash_unit((uint32_t)i, (uint32_t)row,
                                      2 * sample + 1)
                          : 0.5;
    rt_ray ray = camera_ray_at(&f->camera, i + (sx + u) / n,
                               row + (sy + v) / n);
    if (f->aperture > 0.0) {
        /* The lens stratum is the pixel's, transposed, so that where a
         * sample falls in the pixel and on the lens are not aligned;
         * jittered like it when stratified. */
        double lu = stratified ? hash_unit((uint32_t)i, (uint32_t)row,
                                           2 * (sample + n * n))
                               : 0.5;
        double lv = stratified ? hash_unit((uint32_t)i, (uint32_t)row,
                                           2 * (sample + n * n) + 1)
                               : 0.5;
        ray = lens_ray(f, ray, (sy + lu) / n, (sx + lv) / n);
    }
    return ray;
}

/* The camera ray of a pixel with one sample. */
static inline rt_ray centre_ray(const rt_frame *f, int i, int row)
{
    rt_ray ray = rt_camera_ray(&f->camera, i, row);
    if (f->aperture > 0.0)  /* one sample: the lens centre */
        ray = lens_ray(f, ray, 0.5, 0.5);
    return ray;
}

/* The colour of pixel (i, row) of the whole image: the mean of its
 * samples. */
static rt_color pixel_mean(const rt_frame *f, int i, int row,
                           rt_counters *counters)
{
    int n = f->grid;
    if (n == 1)
        return trace(f, centre_ray(f, i, row), counters);
    rt_color sum = {0.0, 0.0, 0.0};
    for (int sy = 0; sy < n; sy++) {
        for (int sx = 0; sx < n; sx++) {
            rt_color c = trace(f, sample_ray(f, i, row, sx, sy), counters);
            sum.r += c.r, sum.g += c.g, sum.b += c.b;
        }
    }
    double inv = 1.0 / (n * n);
    return (rt_color){sum.r * inv, sum.g * inv, sum.b * inv};
}

float rt__linear_channel(double value)
{
    float f = (float)(value / 255.0);
    unsigned char want = rt_channel_to_byte(value);
    /* At most a step or two: float keeps 24 bits, a byte needs 8. */
    for (int i = 0; i < 4; i++) {
        unsigned char got = rt_channel_to_byte(255.0 * (double)f);
        if (got == want)
            break;
        f = nextafterf(f, got < want ? INFINITY : -INFINITY);
    }
    return f;
}

/* Writes pixel c as bytes at `out` and, when `linear` is not NULL, as
 * linear floats there. */
static void put_pixel(unsigned char *out, float *linear, rt_color c)
{
    out[0] = rt_channel_to_byte(c.r);
    out[1] = rt_channel_to_byte(c.g);
    out[2] = rt_channel_to_byte(c.b);
    if (linear != NULL) {
        linear[0] = rt__linear_channel(c.r);
        linear[1] = rt__linear_channel(c.g);
        linear[2] = rt__linear_channel(c.b);
    }
}

/* The first linear float of row `row` of the output image, NULL when the
 * render writes none. */
static float *linear_row(const rt_frame *f, int row)
{
    return f->linear != NULL ? rt_image_float_pixel(f->linear, 0, row)
                             : NULL;
}

/* Rays a span of pixels traces at most (samples are at most 1024), and
 * its pixels at most: wide enough to share the kernel's tile cull among
 * many rays, narrow enough that the cull stays tight (32 was the best of
 * 8 to 128 in instructions per ray, tools/bench/ray-budget.sh). */
#define SPAN_RAYS 1024
#define SPAN_PIXELS 32

/* Non-zero when the frame's camera rays go to the kernel as spans: the
 * fast loops with an eye, and a pinhole (every ray leaves the observer). */
static int spans(const rt_frame *f)
{
    return f->settings.eye != NULL && f->aperture == 0.0;
}

/* The pixels of a span (rendered between two polls of the stop flags). */
static int span_width(const rt_frame *f)
{
    int per_span = SPAN_RAYS / (f->grid * f->grid);
    return per_span > SPAN_PIXELS ? SPAN_PIXELS : per_span;
}

/*
 * Renders pixels i0 .. i1 - 1 of a row (the output image's columns) as one
 * span: their camera rays, all samples, go to the kernel together, and
 * each pixel is the mean of its samples in pixel_mean()'s order.
 */
static void render_span(const rt_frame *f, int row, int i0, int i1,
                        unsigned char *out, float *linear,
                        rt_counters *counters)
{
    rt_vec3 directions[SPAN_RAYS];
    rt_color colors[SPAN_RAYS];
    if (i1 <= i0)
        return;
    int n = f->grid, m = 0, y = f->y0 + row;
    for (int i = i0; i < i1; i++)
        for (int sy = 0; sy < n; sy++)
            for (int sx = 0; sx < n; sx++)
                directions[m++] = (n == 1 ? centre_ray(f, f->x0 + i, y)
                                          : sample_ray(f, f->x0 + i, y, sx,
                                                       sy))
                                      .direction;
    rt__kernel_trace_span(f->kernel, f->camera.observer, directions, m,
                          &f->settings, counters, colors);
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
        put_pixel(&out[3 * i], linear != NULL ? &linear[3 * i] : NULL, c);
    }
}

int rt__frame_row(const rt_frame *f, int row, unsigned char *out,
                  const rt_stop *stop, rt_counters *counters)
{
    rt__counters_forget_blockers(counters);
    float *linear = linear_row(f, row);
    if (spans(f)) {
        int per_span = span_width(f);
        for (int i = 0; i < f->width; i += per_span) {
            if (rt__stop_now(stop))
                return 0;
            int end = i + per_span < f->width ? i + per_span : f->width;
            render_span(f, row, i, end, out, linear, counters);
        }
        return 1;
    }
    for (int i = 0; i < f->width; i++) {
        if (rt__stop_now(stop))
            return 0;
        put_pixel(&out[3 * i], linear != NULL ? &linear[3 * i] : NULL,
                  pixel_mean(f, f->x0 + i, f->y0 + row, counters));
    }
    return 1;
}

rt_color rt__frame_pixel(const rt_frame *f, int x, int y, int sample,
                         rt_counters *counters)
{
    int i = f->x0 + x, row = f->y0 + y, n = f->grid;
    if (sample < 0)
        return pixel_mean(f, i, row, counters);
    if (n == 1)
        return trace(f, centre_ray(f, i, row), counters);
    return trace(f, sample_ray(f, i, row, sample % n, sample / n), counters);
}
