/*
 * test_exact.c - the exact cross product's scaling (src/base/exact.c): the
 * triangle is brought to a largest coordinate in [0.5, 1) by a power of
 * two read from the bits of a double and multiplied in, which must give
 * the doubles frexp and ldexp give, bit for bit, at every scale - normal
 * results, subnormal ones, zeros, the largest doubles.  The check: a
 * triangle and the same triangle scaled beforehand with frexp and ldexp
 * (which the function then leaves as it is) have the same cross product
 * and the same answer to "has an area", for random triangles of coordinates
 * spread over the whole range of doubles.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "base/exact.h"
#include "testutil.h"

static uint64_t bits_of(double v)
{
    uint64_t b;
    memcpy(&b, &v, sizeof b);
    return b;
}

/* The triangle scaled as exact.c scales it, by frexp and ldexp. */
static void scale_by_ldexp(rt_vec3 *p)
{
    double largest = 0;
    for (int i = 0; i < 3; i++)
        largest = fmax(largest, fmax(fabs(p[i].x),
                                     fmax(fabs(p[i].y), fabs(p[i].z))));
    int e = 0;
    if (largest > 0.0)
        frexp(largest, &e);
    for (int i = 0; i < 3; i++)
        p[i] = (rt_vec3){ldexp(p[i].x, -e), ldexp(p[i].y, -e),
                         ldexp(p[i].z, -e)};
}

/* A coordinate: a sign, 53 random bits, and a power of two near `scale`
 * (from the subnormals to the largest doubles), or a zero. */
static double coordinate(rt_test_rng *rng, int scale)
{
    if (rt_test_rng_below(rng, 16) == 0)
        return rt_test_rng_below(rng, 2) ? 0.0 : -0.0;
    double m = rt_test_rng_range(rng, 0.5, 1.0);
    double v = ldexp(m, scale - rt_test_rng_below(rng, 1100));
    return rt_test_rng_below(rng, 2) ? -v : v;
}

START_TEST(scaling_by_the_bits_gives_ldexps_doubles)
{
    rt_test_rng rng = {1997};
    int n = rt_test_memcheck() ? 1000 : 50000;
    for (int i = 0; i < n; i++) {
        int scale = rt_test_rng_below(&rng, 2100) - 1050;
        if (scale > 1024)
            scale = 1024;
        rt_vec3 p[3];
        for (int k = 0; k < 3; k++)
            p[k] = (rt_vec3){coordinate(&rng, scale), coordinate(&rng, scale),
                             coordinate(&rng, scale)};
        rt_vec3 on_line = {2 * p[1].x - p[0].x, 2 * p[1].y - p[0].y,
                           2 * p[1].z - p[0].z};
        if (i % 4 == 0 && isfinite(on_line.x) && isfinite(on_line.y) &&
            isfinite(on_line.z))
            p[2] = on_line;     /* collinear (to within rounding) */
        rt_vec3 q[3] = {p[0], p[1], p[2]};
        scale_by_ldexp(q);
        rt_vec3 got = rt__exact_cross(p[0], p[1], p[2]);
        rt_vec3 want = rt__exact_cross(q[0], q[1], q[2]);
        if (bits_of(got.x) != bits_of(want.x) ||
            bits_of(got.y) != bits_of(want.y) ||
            bits_of(got.z) != bits_of(want.z))
            ck_abort_msg("triangle %d (scale 2^%d): cross (%a, %a, %a), "
                         "after ldexp's scaling (%a, %a, %a)", i, scale,
                         got.x, got.y, got.z, want.x, want.y, want.z);
        if (rt__triangle_has_area(p[0], p[1], p[2]) !=
            rt__triangle_has_area(q[0], q[1], q[2]))
            ck_abort_msg("triangle %d (scale 2^%d): the area decided "
                         "otherwise after ldexp's scaling", i, scale);
    }
}
END_TEST

START_TEST(the_scaling_leaves_no_area_to_collinear_corners_at_any_scale)
{
    /* the same collinear triangle at every power of two: no area; moved
     * off its line by one unit in the last place: an area */
    for (int e = -1070; e <= 1020; e += 7) {
        rt_vec3 a = {ldexp(1, e), ldexp(3, e), ldexp(-2, e)};
        rt_vec3 b = {ldexp(2, e), ldexp(5, e), ldexp(-1, e)};
        rt_vec3 c = {ldexp(3, e), ldexp(7, e), 0.0};
        ck_assert_msg(!rt__triangle_has_area(a, b, c), "2^%d", e);
        rt_vec3 cross = rt__exact_cross(a, b, c);
        ck_assert(cross.x == 0 && cross.y == 0 && cross.z == 0);
        c.y = nextafter(c.y, INFINITY);
        ck_assert_msg(rt__triangle_has_area(a, b, c), "2^%d, moved", e);
    }
}
END_TEST

static Suite *exact_suite(void)
{
    Suite *s = suite_create("exact");
    TCase *tc = tcase_create("scaling");
    tcase_set_timeout(tc, 60);  /* a second under the sanitizers */
    tcase_add_test(tc, scaling_by_the_bits_gives_ldexps_doubles);
    tcase_add_test(tc,
                   the_scaling_leaves_no_area_to_collinear_corners_at_any_scale);
    suite_add_tcase(s, tc);
    return s;
}

RT_CHECK_MAIN(exact_suite)
