/*
 * images.c - images in the tests (see images.h).
 */
#include "images.h"

#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "files.h"

rt_image rt_test_render_with(const rt_scene *scene,
                             const rt_render_options *options)
{
    int width, height;
    rt_error error;
    ck_assert_msg(rt_render_image_size(scene, options, &width, &height,
                                       &error) == RT_OK,
                  "%s", error.message);
    rt_image image;
    ck_assert_int_eq(rt_image_init(&image, width, height, NULL), RT_OK);
    ck_assert_int_eq(rt_render(scene, options, &image, NULL), RT_OK);
    return image;
}

rt_image rt_test_render(const rt_scene *scene, int max_depth, int threads)
{
    rt_render_options options;
    rt_render_options_init(&options);
    options.max_depth = max_depth;
    options.threads = threads;
    return rt_test_render_with(scene, &options);
}

long rt_test_image_diff(const rt_image *a, const rt_image *b, int *max_diff)
{
    ck_assert_int_eq(a->width, b->width);
    ck_assert_int_eq(a->height, b->height);
    long count = 0;
    int worst = 0;
    for (int y = 0; y < a->height; y++) {
        for (int x = 0; x < a->width; x++) {
            const unsigned char *p = rt_image_pixel(a, x, y);
            const unsigned char *q = rt_image_pixel(b, x, y);
            int differs = 0;
            for (int c = 0; c < 3; c++) {
                int d = abs((int)p[c] - (int)q[c]);
                if (d > worst)
                    worst = d;
                differs |= d != 0;
            }
            count += differs;
        }
    }
    if (max_diff)
        *max_diff = worst;
    return count;
}

void rt_test_assert_same_image(const rt_image *actual,
                               const rt_image *expected, const char *name)
{
    int max_diff;
    long differ = rt_test_image_diff(actual, expected, &max_diff);
    if (differ != 0) {
        char path[256];
        snprintf(path, sizeof path, "%s-actual.ppm", name);
        rt_image_save(path, actual, RT_IMAGE_P6, NULL, NULL);
        snprintf(path, sizeof path, "%s-expected.ppm", name);
        rt_image_save(path, expected, RT_IMAGE_P6, NULL, NULL);
    }
    ck_assert_msg(differ == 0,
                  "%s: %ld pixels differ (by up to %d), images written to "
                  "%s-*.ppm",
                  name, differ, max_diff, name);
}

void rt_test_assert_color(rt_color c, double r, double g, double b,
                          double tol, const char *what)
{
    ck_assert_msg(fabs(c.r - r) <= tol && fabs(c.g - g) <= tol &&
                      fabs(c.b - b) <= tol,
                  "%s: (%.12g, %.12g, %.12g), expected (%.12g, %.12g, %.12g) "
                  "within %g",
                  what, c.r, c.g, c.b, r, g, b, tol);
}

void rt_test_fill_pattern(rt_image *image)
{
    for (int y = 0; y < image->height; y++)
        for (int x = 0; x < image->width; x++) {
            unsigned char *p = rt_image_pixel(image, x, y);
            p[0] = (unsigned char)(x * 37 + y * 11);
            p[1] = (unsigned char)(x == y ? 255 : x * y);
            p[2] = (unsigned char)((x + y) % 3 ? 255 - x : y);
        }
}

rt_status rt_test_make_pattern(rt_image *image, int width, int height)
{
    rt_status status = rt_image_init(image, width, height, NULL);
    if (status == RT_OK)
        rt_test_fill_pattern(image);
    return status;
}

rt_image rt_test_pattern(int width, int height)
{
    rt_image image;
    ck_assert_int_eq(rt_test_make_pattern(&image, width, height), RT_OK);
    return image;
}

int rt_test_bytes_add(void *user, const void *data, size_t size)
{
    rt_test_bytes *b = user;
    if (b->size + size > b->capacity) {
        size_t capacity = 2 * (b->size + size) + 256;
        unsigned char *grown = realloc(b->data, capacity);
        if (grown == NULL)
            return 0;
        b->data = grown;
        b->capacity = capacity;
    }
    memcpy(b->data + b->size, data, size);
    b->size += size;
    return 1;
}

rt_test_bytes rt_test_encode(const rt_image *image, rt_image_format format)
{
    rt_test_bytes b = {NULL, 0, 0};
    rt_error error = {0};
    rt_status status = rt_image_write_to(rt_test_bytes_add, &b, image,
                                         format, &error);
    ck_assert_msg(status == RT_OK, "rt_image_write_to: %s", error.message);
    return b;
}

void rt_test_save_ok(const char *path, const rt_image *image,
                     rt_image_format format)
{
    rt_error error = {0};
    rt_status status = rt_image_save(path, image, format, NULL, &error);
    ck_assert_msg(status == RT_OK, "saving to %s returned %s: %s", path,
                  rt_status_string(status), error.message);
}

void rt_test_save_refused(const char *path, const char *reason,
                          rt_error *error)
{
    rt_image image = rt_test_pattern(6, 4);
    memset(error, 0, sizeof *error);
    rt_status status = rt_image_save(path, &image, RT_IMAGE_P6, NULL, error);
    rt_image_release(&image);
    ck_assert_msg(status == RT_ERR_IO, "saving to %s returned %s, expected "
                  "an input/output error", path, rt_status_string(status));
    ck_assert_int_eq(error->status, RT_ERR_IO);
    ck_assert_msg(strstr(error->message, path) != NULL,
                  "the message does not name %s: %s", path, error->message);
    ck_assert_msg(strstr(error->message, reason) != NULL,
                  "the message does not say `%s`: %s", reason,
                  error->message);
}

const char rt_test_previous_ppm[sizeof RT_TEST_PREVIOUS_PPM] =
    RT_TEST_PREVIOUS_PPM;

void rt_test_assert_previous_intact(const char *path)
{
    size_t size;
    char *data = rt_test_read_file(path, &size);
    ck_assert_msg(data != NULL, "%s: the previous file is gone", path);
    ck_assert_msg(size == sizeof rt_test_previous_ppm - 1 &&
                      memcmp(data, rt_test_previous_ppm, size) == 0,
                  "%s: the previous file was changed (now %zu bytes)", path,
                  size);
    free(data);
}
