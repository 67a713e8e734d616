/*
 * test_hostile_time.c - bad input, in time: the time of a parse grows
 * linearly with the input, whatever its shape (one huge number, a line of
 * commas, blank lines, many vertices, many facets, zero-area facets).
 *
 * Tests that need a child process fork one themselves, so that they also
 * hold under CK_FORK=no (valgrind).
 */
#define _GNU_SOURCE 1

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <math.h>
#include <sched.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "testutil.h"

/* ------------------------------------------------------------------ */
/* Resource bounds: time proportional to the input                      */

/* A hostile input of about `size` bytes, of one of several shapes. */
typedef enum shape {
    SHAPE_DIGITS,           /* one huge number */
    SHAPE_COMMAS,           /* a valid start, then a line of commas */
    SHAPE_BLANK_LINES,      /* a valid start, then blank and comment lines */
    SHAPE_VERTICES,         /* a vertex count and that many vertices, then
                               a truncated file */
    SHAPE_FACETS,           /* a complete scene of many facets */
    SHAPE_DEGENERATE        /* a complete scene of zero-area facets */
} shape;

static const char *const shape_names[] = {
    "digits", "commas", "blank lines", "vertices", "facets",
    "zero-area facets"};

static char *make_input(shape s, size_t size, size_t *length)
{
    char *text = malloc(size + 256);
    ck_assert_ptr_nonnull(text);
    size_t n = 0;
    const char *head = "0 0 10\n0 0 5 4 0 5 8 8\n";
    switch (s) {
    case SHAPE_DIGITS:
        memset(text, '9', size);
        n = size;
        break;
    case SHAPE_COMMAS:
        n = (size_t)sprintf(text, "%s3\n1", head);
        memset(text + n, ',', size - n);
        n = size;
        break;
    case SHAPE_BLANK_LINES:
        n = (size_t)sprintf(text, "%s", head);
        while (n + 8 < size) {
            memcpy(text + n, "  \r\n# \n\n", 8);
            n += 8;
        }
        break;
    case SHAPE_VERTICES:
    case SHAPE_FACETS:
    case SHAPE_DEGENERATE: {
        /* vertices on a parabola, so consecutive triples are not
         * collinear (or all on a line for zero-area facets) */
        int count = (int)(size / 48);
        n = (size_t)sprintf(text, "%s%d\n", head, count);
        for (int i = 0; i < count; i++) {
            double x = (double)(i % 1000) * 0.001;
            double y = s == SHAPE_DEGENERATE ? 0.0 : x * x;
            n += (size_t)sprintf(text + n, "%.3f %.6f %d\n", x, y, -(i % 7));
        }
        if (s == SHAPE_VERTICES)
            break;
        n += (size_t)sprintf(text + n, "%d\n", count - 2);
        for (int i = 1; i + 2 <= count; i++)
            n += (size_t)sprintf(text + n, "%d %d %d 0 1 2 3\n", i, i + 1,
                                 i + 2);
        n += (size_t)sprintf(text + n, "0 0 0\n0 0 4 255 255 255\n");
        break;
    }
    }
    *length = n;
    return text;
}

/* The time of one parse, in seconds. */
/* CPU time of the calling thread: what the parse itself costs, whatever
 * else the machine is running (a parallel ctest, say). */
static double thread_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

static double parse_time(const char *text, size_t length, shape s)
{
    rt_scene *scene;
    rt_error error;
    double start = thread_seconds();
    rt_status status =
        rt_scene_parse(text, length, "big.scn", NULL, &scene, &error);
    double elapsed = thread_seconds() - start;
    int should_load = s == SHAPE_FACETS || s == SHAPE_DEGENERATE;
    ck_assert_msg((status == RT_OK) == should_load, "%s: %s", shape_names[s],
                  error.message);
    rt_scene_destroy(scene);
    return elapsed;
}

/*
 * Parsing 8 times more input (1 MB, then 8 MB) takes about 8 times longer.
 * The bound, 4 x 8 = 32, leaves room for caches (8 MB no longer fits) and
 * for a loaded machine, and still catches a quadratic step (64).  Times
 * are the thread's CPU time, not the wall clock, so other processes do not
 * count.  Runs of
 * both sizes alternate, and the best of each counts, so that a change of
 * load during the test touches both.  A large parse under 20 ms is taken as
 * linear whatever the ratio: too short to tell.
 */
START_TEST(parse_time_grows_linearly_with_the_input)
{
    shape s = (shape)_i;
    size_t small = 1u << 20, large = 8 * small;
    if (rt_test_under_valgrind())
        small /= 4, large /= 4;
    size_t small_length, large_length;
    char *a = make_input(s, small, &small_length);
    char *b = make_input(s, large, &large_length);
    double ta = HUGE_VAL, tb = HUGE_VAL;
    for (int run = 0; run < 3; run++) {
        ta = fmin(ta, parse_time(a, small_length, s));
        tb = fmin(tb, parse_time(b, large_length, s));
    }
    double ratio = tb / (ta > 1e-6 ? ta : 1e-6);
    double size_ratio = (double)large_length / (double)small_length;
    fprintf(stderr, "test_hostile_time: %s: %zu bytes %.2f ms, %zu bytes "
                    "%.2f ms (x%.1f for x%.1f)\n",
            shape_names[s], small_length, ta * 1e3, large_length, tb * 1e3,
            ratio, size_ratio);
    ck_assert_msg(ratio < 4 * size_ratio || tb < 0.02,
                  "%s: %.0f times the input took %.0f times as long",
                  shape_names[s], size_ratio, ratio);
    free(a);
    free(b);
}
END_TEST

static Suite *hostile_time_suite(void)
{
    Suite *s = suite_create("hostile_time");
    TCase *tc = tcase_create("time proportional to the input");
    tcase_set_timeout(tc, 300);
    tcase_add_loop_test(tc, parse_time_grows_linearly_with_the_input,
                        SHAPE_DIGITS, SHAPE_DEGENERATE + 1);
    suite_add_tcase(s, tc);
    return s;
}

RT_CHECK_MAIN(hostile_time_suite)
