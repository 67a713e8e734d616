/*
 * testutil.h - what every Check suite of the project shares: a main that
 * runs one suite, paths to the project's files, and image helpers.
 */
#ifndef RAYTRACE_TESTUTIL_H
#define RAYTRACE_TESTUTIL_H

#include <check.h>
#include <stddef.h>

#include "raytrace/raytrace.h"

/* UNDER_ASAN: 1 in a build with AddressSanitizer (the programs the suites
 * start run some 30 times slower there), else 0. */
#if defined(__SANITIZE_ADDRESS__)
#define UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define UNDER_ASAN 1
#endif
#endif
#ifndef UNDER_ASAN
#define UNDER_ASAN 0
#endif

/* Runs `suite_fn()` and exits non-zero when a test failed. */
int rt_test_run_suite(Suite *suite);

#define RT_CHECK_MAIN(suite_fn)                                              \
    int main(void) { return rt_test_run_suite(suite_fn()); }

/* ctest's SKIP_RETURN_CODE for a check whose input is absent. */
#define RT_TEST_SKIPPED 77

/* The main of a suite whose checks on the course's scenes (../shared) are a
 * ctest entry of their own: `prog` runs main_fn's suite; `prog shared` runs
 * shared_fn's suite, or exits RT_TEST_SKIPPED when ../shared is absent. */
int rt_test_main_with_shared(int argc, char **argv, Suite *(*main_fn)(void),
                             Suite *(*shared_fn)(void));

#define RT_CHECK_MAIN_WITH_SHARED(main_fn, shared_fn)                        \
    int main(int argc, char **argv)                                          \
    {                                                                        \
        return rt_test_main_with_shared(argc, argv, main_fn, shared_fn);     \
    }

/* "<source dir>/<relative>" in a static buffer (one at a time). */
const char *rt_test_source_path(const char *relative);

/* "<source dir>/../shared/<relative>", or NULL when ../shared is absent. */
const char *rt_test_shared_path(const char *relative);

/* Parses a scene held in a C string; fails the test with the loader's
 * message if it does not load. */
rt_scene *rt_test_scene_from_string(const char *text);

/* Renders `scene` with `options` into a new image of the size they ask
 * for; fails the test if the render does not succeed. */
rt_image rt_test_render_with(const rt_scene *scene,
                             const rt_render_options *options);

/* Renders `scene` with the given depth and thread count into a new image. */
rt_image rt_test_render(const rt_scene *scene, int max_depth, int threads);

/* Number of pixels that differ between two images of the same size, and the
 * largest channel difference (through *max_diff when not NULL). */
long rt_test_image_diff(const rt_image *a, const rt_image *b, int *max_diff);

/* A growing buffer of bytes and the rt_write_func that appends to it
 * (`user`: the rt_test_bytes, zeroed to start); free `data` when done. */
typedef struct rt_test_bytes {
    unsigned char *data;
    size_t size, capacity;
} rt_test_bytes;
int rt_test_bytes_add(void *user, const void *data, size_t size);

/* The whole file at `path`, malloc'd and NUL-terminated (the NUL not
 * counted), its length through *size when not NULL; NULL when it cannot
 * be opened.  Fails the test when out of memory. */
char *rt_test_read_file(const char *path, size_t *size);

/* Writes `text` to the file at `path`, replacing it; fails the test when it
 * cannot. */
void rt_test_write_file(const char *path, const char *text);

/* Fails the test unless every channel of `c` is within `tol` of (r, g, b);
 * `what` names the colour in the message. */
void rt_test_assert_color(rt_color c, double r, double g, double b,
                          double tol, const char *what);

#endif /* RAYTRACE_TESTUTIL_H */
