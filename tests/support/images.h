/*
 * images.h - images in the tests: a render at the size the options ask
 * for, the pixels two images differ by, a colour within a stated
 * tolerance, a pattern whose every channel takes many values, the bytes an
 * encoder writes, and the "previous" file a failed save must leave as it
 * was.  Part of the support library (tests/support/); the functions fail
 * the test (Check) when they cannot do their job, except
 * rt_test_make_pattern, which is safe in a forked child.
 */
#ifndef RAYTRACE_TEST_IMAGES_H
#define RAYTRACE_TEST_IMAGES_H

#include <stddef.h>

#include "raytrace/raytrace.h"

/* Renders `scene` with `options` into a new image of the size they ask
 * for; fails the test if the render does not succeed. */
rt_image rt_test_render_with(const rt_scene *scene,
                             const rt_render_options *options);

/* Renders `scene` with the given depth and thread count into a new image. */
rt_image rt_test_render(const rt_scene *scene, int max_depth, int threads);

/* Number of pixels that differ between two images of the same size, and the
 * largest channel difference (through *max_diff when not NULL). */
long rt_test_image_diff(const rt_image *a, const rt_image *b, int *max_diff);

/* Fails the test when the two images differ, after writing both beside
 * the suite as <name>-actual.ppm and <name>-expected.ppm. */
void rt_test_assert_same_image(const rt_image *actual,
                               const rt_image *expected, const char *name);

/* Fails the test unless every channel of `c` is within `tol` of (r, g, b);
 * `what` names the colour in the message. */
void rt_test_assert_color(rt_color c, double r, double g, double b,
                          double tol, const char *what);

/* Fills `image` (any stride) with a pattern where every channel takes
 * many values, 0 and 255 among them. */
void rt_test_fill_pattern(rt_image *image);

/* A new width x height image of that pattern; a status, for a child. */
rt_status rt_test_make_pattern(rt_image *image, int width, int height);

/* The same, failing the test when out of memory. */
rt_image rt_test_pattern(int width, int height);

/* A growing buffer of bytes and the rt_write_func that appends to it
 * (`user`: the rt_test_bytes, zeroed to start); free `data` when done. */
typedef struct rt_test_bytes {
    unsigned char *data;
    size_t size, capacity;
} rt_test_bytes;
int rt_test_bytes_add(void *user, const void *data, size_t size);

/* The bytes rt_image_write_to writes for `image` in `format`. */
rt_test_bytes rt_test_encode(const rt_image *image, rt_image_format format);

/* Saves `image` at `path` (rt_image_save); fails the test, with the
 * status and message, unless it succeeds. */
void rt_test_save_ok(const char *path, const rt_image *image,
                     rt_image_format format);

/* Saves a small image at `path`, which must fail with RT_ERR_IO and a
 * message (in *error) that names `path` and says `reason`. */
void rt_test_save_refused(const char *path, const char *reason,
                          rt_error *error);

/* A PPM file that is recognisably "the previous one", for the tests of
 * saves that must leave it as it was (sizeof gives its length + 1). */
#define RT_TEST_PREVIOUS_PPM "P3\n1 1\n255\n1 2 3\n"
extern const char rt_test_previous_ppm[sizeof RT_TEST_PREVIOUS_PPM];

/* Fails the test unless `path` still holds rt_test_previous_ppm. */
void rt_test_assert_previous_intact(const char *path);

#endif /* RAYTRACE_TEST_IMAGES_H */
