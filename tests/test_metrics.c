/*
 * test_metrics.c - rt-bench's error metrics (tools/rt-bench/metrics.h) on tiny
 * images whose answers are worked out by hand in the comments.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "metrics.h"
#include "testutil.h"

/* A width x height image whose channels are `values` in order. */
static rt_image image_of(int width, int height, const unsigned char *values)
{
    rt_image image;
    ck_assert_int_eq(rt_image_init(&image, width, height, NULL), RT_OK);
    for (int y = 0; y < height; y++)
        memcpy(rt_image_pixel(&image, 0, y), values + 3 * width * y,
               (size_t)(3 * width));
    return image;
}

START_TEST(identical_images_have_zero_error_and_infinite_psnr)
{
    const unsigned char v[] = {1, 2, 3, 250, 251, 252};
    rt_image a = image_of(2, 1, v), b = image_of(2, 1, v);
    bench_error e;
    bench_compare(&a, &b, &e);
    ck_assert_double_eq(e.rmse, 0.0);
    ck_assert(isinf(e.psnr) && e.psnr > 0);
    ck_assert_int_eq(e.max_error, 0);
    ck_assert_int_eq(e.pixels, 2);
    ck_assert_int_eq(e.differing, 0);
    ck_assert_int_eq(e.differing_much, 0);
    rt_image_release(&a);
    rt_image_release(&b);
}
END_TEST

/* 2 x 2 pixels, 12 channels.  Differences: pixel 0 (1, 0, 0), pixel 1
 * none, pixel 2 (0, 3, 0), pixel 3 (2, 2, 2): sum of squares
 * 1 + 9 + 4 + 4 + 4 = 22, RMSE sqrt(22 / 12) = 1.354006400...,
 * PSNR 20 log10(255 / 1.3540064) = 45.4984 dB; max 3; three pixels
 * differ, one (pixel 2) by more than 2 levels (pixel 3's 2 is not more). */
START_TEST(small_differences_give_hand_computed_metrics)
{
    const unsigned char ref[] = {10, 20, 30, 40, 50, 60,
                                 70, 80, 90, 100, 110, 120};
    const unsigned char test[] = {11, 20, 30, 40, 50, 60,
                                  70, 77, 90, 102, 112, 118};
    rt_image a = image_of(2, 2, test), b = image_of(2, 2, ref);
    bench_error e;
    bench_compare(&a, &b, &e);
    ck_assert_double_eq_tol(e.rmse, sqrt(22.0 / 12.0), 1e-12);
    ck_assert_double_eq_tol(e.rmse, 1.3540064, 1e-7);
    ck_assert_double_eq_tol(e.psnr, 45.4984, 1e-4);
    ck_assert_int_eq(e.max_error, 3);
    ck_assert_int_eq(e.pixels, 4);
    ck_assert_int_eq(e.differing, 3);
    ck_assert_int_eq(e.differing_much, 1);
    ck_assert_double_eq_tol(bench_percent(e.differing, e.pixels), 75.0,
                            1e-12);
    rt_image_release(&a);
    rt_image_release(&b);
}
END_TEST

/* One full flip, black against white, in one channel of one pixel of
 * four: RMSE sqrt(255^2 / 12) = 73.6122..., PSNR 10 log10(12) = 10.7918
 * dB, max 255.  The average hides it; the counts do not. */
START_TEST(one_full_flip_is_counted_as_a_pixel_changed_much)
{
    unsigned char ref[12] = {0}, test[12] = {0};
    test[4] = 255;
    rt_image a = image_of(4, 1, test), b = image_of(4, 1, ref);
    bench_error e;
    bench_compare(&a, &b, &e);
    ck_assert_double_eq_tol(e.rmse, 255.0 / sqrt(12.0), 1e-12);
    ck_assert_double_eq_tol(e.psnr, 10.0 * log10(12.0), 1e-12);
    ck_assert_int_eq(e.max_error, 255);
    ck_assert_int_eq(e.differing, 1);
    ck_assert_int_eq(e.differing_much, 1);
    rt_image_release(&a);
    rt_image_release(&b);
}
END_TEST

/* The error is symmetric, and padding beyond 3 * width is not compared. */
START_TEST(padding_is_ignored_and_order_does_not_matter)
{
    unsigned char pa[2 * 8] = {5, 5, 5, 0, 0, 0, 99, 99,
                               9, 9, 9, 1, 1, 1, 42, 42};
    unsigned char pb[2 * 8] = {5, 5, 6, 0, 0, 0, 7, 7,
                               9, 9, 9, 1, 1, 1, 13, 13};
    rt_image a = {2, 2, 8, pa}, b = {2, 2, 8, pb};
    bench_error e1, e2;
    bench_compare(&a, &b, &e1);
    bench_compare(&b, &a, &e2);
    ck_assert_double_eq_tol(e1.rmse, sqrt(1.0 / 12.0), 1e-15);
    ck_assert_double_eq(e1.rmse, e2.rmse);
    ck_assert_int_eq(e1.max_error, 1);
    ck_assert_int_eq(e1.differing, 1);
    ck_assert_int_eq(e1.differing_much, 0);
    ck_assert(bench_image_hash(&a) != bench_image_hash(&b));
    pb[2] = 5;
    ck_assert(bench_image_hash(&a) == bench_image_hash(&b));
}
END_TEST

/* Median of an odd and an even count; min and max. */
START_TEST(summary_gives_median_and_spread)
{
    double odd[] = {0.5, 0.1, 0.3, 0.9, 0.2};
    double even[] = {4.0, 1.0, 3.0, 2.0};
    double median, minimum, maximum;
    bench_summarize(odd, 5, &median, &minimum, &maximum);
    ck_assert_double_eq(median, 0.3);
    ck_assert_double_eq(minimum, 0.1);
    ck_assert_double_eq(maximum, 0.9);
    bench_summarize(even, 4, &median, &minimum, &maximum);
    ck_assert_double_eq(median, 2.5);
    ck_assert_double_eq(minimum, 1.0);
    ck_assert_double_eq(maximum, 4.0);
}
END_TEST

/* Points (time, error): A (1, 10), B (2, 5), C (3, 6) is beaten by B on
 * both, D (4, 1), E (4, 1) equal to D (both kept), F (0.5, 20) the fastest,
 * G (2, 7) beaten by B (same time, more error). */
START_TEST(pareto_front_keeps_only_points_nothing_beats)
{
    const double x[] = {1, 2, 3, 4, 4, 0.5, 2};
    const double y[] = {10, 5, 6, 1, 1, 20, 7};
    int front[7];
    ck_assert_int_eq(bench_pareto_front(x, y, 7, front), 5);
    const int expected[] = {1, 1, 0, 1, 1, 1, 0};
    for (int i = 0; i < 7; i++)
        ck_assert_int_eq(front[i], expected[i]);
}
END_TEST

/* cubes.scn (docs/accuracy.md): peak 255, k_max 0.5 (the floor), pair
 * 0.5 x 0.3 = 0.15.  B(0) = 255 x 0.5 = 127.5; B(1) = 255 x 0.15 = 38.25;
 * B(5) = 255 x 0.15^3 = 0.860625; B(13) = 255 x 0.15^7 = 4.35691e-4. */
START_TEST(truncation_bound_of_the_cube_scene)
{
    bench_depth_bound b = {255.0, 0.5, 0.15};
    ck_assert_double_eq_tol(bench_truncation_bound(&b, 0), 127.5, 1e-12);
    ck_assert_double_eq_tol(bench_truncation_bound(&b, 1), 38.25, 1e-12);
    ck_assert_double_eq_tol(bench_truncation_bound(&b, 2), 19.125, 1e-12);
    ck_assert_double_eq_tol(bench_truncation_bound(&b, 5), 0.860625, 1e-12);
    ck_assert_double_eq_tol(bench_truncation_bound(&b, 13), 4.3569140625e-4,
                            1e-15);
}
END_TEST

/* A mirror (k = 1) facing a floor (k = 0.5): pair 0.5, and the bound is
 * capped at 255 where peak x k_max would be 255 already: B(0) = 255,
 * B(1) = B(2) = 127.5, B(35) = 255 / 2^18 = 9.72748e-4.  A peak that no
 * finite colour bounds (a facet with k + t = 1 and a local term) gives the
 * format's 255 levels while the weight is positive, and 0, not NaN, once
 * it is 0 (no facet passes anything on). */
START_TEST(truncation_bound_caps_and_zero_weights)
{
    bench_depth_bound mirror = {255.0, 1.0, 0.5};
    ck_assert_double_eq(bench_truncation_bound(&mirror, 0), 255.0);
    ck_assert_double_eq(bench_truncation_bound(&mirror, 1), 127.5);
    ck_assert_double_eq(bench_truncation_bound(&mirror, 2), 127.5);
    ck_assert_double_eq_tol(bench_truncation_bound(&mirror, 35),
                            255.0 / 262144.0, 1e-15);
    bench_depth_bound unbounded = {INFINITY, 0.6, 0.36};
    ck_assert_double_eq(bench_truncation_bound(&unbounded, 7), 255.0);
    bench_depth_bound matte = {INFINITY, 0.0, 0.0};
    ck_assert_double_eq(bench_truncation_bound(&matte, 0), 0.0);
    bench_depth_bound one_mirror = {200.0, 0.8, 0.0};  /* sees matte only */
    ck_assert_double_eq_tol(bench_truncation_bound(&one_mirror, 0), 160.0,
                            1e-12);
    ck_assert_double_eq(bench_truncation_bound(&one_mirror, 1), 0.0);
    ck_assert_double_eq(bench_truncation_bound(&one_mirror, 2), 0.0);
}
END_TEST

/* C = (k + t) C_rays + local with C_rays <= P and local <= 100: P = 100 /
 * (1 - k - t) is the least peak with C <= P.  k + t = 0.5 -> 200; 0 (a
 * matte facet, .scn's d = 1) -> the local term itself; 0.75 -> 400; k + t
 * = 1 with a local term (a format that gives d on its own) -> no finite
 * peak; no local term (d = 0: a perfect mirror or clear glass) -> 0, the
 * facet adds nothing of its own. */
START_TEST(peak_needed_by_a_facet)
{
    ck_assert_double_eq_tol(bench_peak_needed(100.0, 0.5), 200.0, 1e-12);
    ck_assert_double_eq(bench_peak_needed(100.0, 0.0), 100.0);
    ck_assert_double_eq_tol(bench_peak_needed(100.0, 0.75), 400.0, 1e-12);
    ck_assert(isinf(bench_peak_needed(100.0, 1.0)));
    ck_assert_double_eq(bench_peak_needed(0.0, 1.0), 0.0);
    ck_assert_double_eq(bench_peak_needed(0.0, 0.3), 0.0);
}
END_TEST

static Suite *metrics_suite(void)
{
    Suite *suite = suite_create("metrics");
    TCase *tc = tcase_create("metrics");
    tcase_add_test(tc, identical_images_have_zero_error_and_infinite_psnr);
    tcase_add_test(tc, small_differences_give_hand_computed_metrics);
    tcase_add_test(tc, one_full_flip_is_counted_as_a_pixel_changed_much);
    tcase_add_test(tc, padding_is_ignored_and_order_does_not_matter);
    tcase_add_test(tc, summary_gives_median_and_spread);
    tcase_add_test(tc, pareto_front_keeps_only_points_nothing_beats);
    tcase_add_test(tc, truncation_bound_of_the_cube_scene);
    tcase_add_test(tc, truncation_bound_caps_and_zero_weights);
    tcase_add_test(tc, peak_needed_by_a_facet);
    suite_add_tcase(suite, tc);
    return suite;
}

RT_CHECK_MAIN(metrics_suite)
