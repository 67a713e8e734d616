/*
 * test_vec.c - the internal vector maths of src/base/vecmath.h: the operations
 * every module builds on, including lengths of vectors whose squared
 * components would overflow or underflow a double.
 */
#include "testutil.h"

#include <float.h>
#include <math.h>

#include "base/vecmath.h"

/* Components equal within an absolute tolerance; tol = 0 means exactly. */
static void assert_vec_eq(rt_vec3 a, rt_vec3 b, double tol)
{
    ck_assert_msg(fabs(a.x - b.x) <= tol && fabs(a.y - b.y) <= tol &&
                      fabs(a.z - b.z) <= tol,
                  "(%.17g, %.17g, %.17g) != (%.17g, %.17g, %.17g) within %g",
                  a.x, a.y, a.z, b.x, b.y, b.z, tol);
}

START_TEST(add_sub_scale_and_neg_work_per_component)
{
    rt_vec3 a = v3(1.5, -2.0, 4.0), b = v3(0.25, 8.0, -1.0);
    assert_vec_eq(v3_add(a, b), v3(1.75, 6.0, 3.0), 0.0);
    assert_vec_eq(v3_sub(a, b), v3(1.25, -10.0, 5.0), 0.0);
    assert_vec_eq(v3_scale(a, -2.0), v3(-3.0, 4.0, -8.0), 0.0);
    assert_vec_eq(v3_neg(a), v3(-1.5, 2.0, -4.0), 0.0);
}
END_TEST

START_TEST(dot_is_the_sum_of_products)
{
    ck_assert_double_eq(v3_dot(v3(1, 2, 3), v3(4, -5, 6)), 12.0);
    ck_assert_double_eq(v3_dot(v3(1, 0, 0), v3(0, 1, 0)), 0.0);
}
END_TEST

START_TEST(cross_is_right_handed_and_anticommutative)
{
    assert_vec_eq(v3_cross(v3(1, 0, 0), v3(0, 1, 0)), v3(0, 0, 1), 0.0);
    assert_vec_eq(v3_cross(v3(0, 1, 0), v3(0, 0, 1)), v3(1, 0, 0), 0.0);
    assert_vec_eq(v3_cross(v3(0, 0, 1), v3(1, 0, 0)), v3(0, 1, 0), 0.0);
    rt_vec3 a = v3(1, 2, 3), b = v3(-4, 5, 0.5);
    rt_vec3 ab = v3_cross(a, b), ba = v3_cross(b, a);
    assert_vec_eq(ab, v3_neg(ba), 0.0);
    /* (2*0.5 - 3*5, 3*(-4) - 1*0.5, 1*5 - 2*(-4)) */
    assert_vec_eq(ab, v3(-14.0, -12.5, 13.0), 0.0);
    ck_assert_double_eq_tol(v3_dot(ab, a), 0.0, 1e-12);
    ck_assert_double_eq_tol(v3_dot(ab, b), 0.0, 1e-12);
}
END_TEST

START_TEST(length_of_a_pythagorean_vector_is_exact)
{
    ck_assert_double_eq(v3_length(v3(3, 4, 0)), 5.0);
    ck_assert_double_eq(v3_length(v3(-2, 3, -6)), 7.0);
    ck_assert_double_eq(v3_length(v3(0, 0, -9)), 9.0);
}
END_TEST

START_TEST(length_of_1e300_vector_does_not_overflow)
{
    /* 1e300^2 overflows; the length is sqrt(3) * 1e300, relative
     * tolerance 4 ulps. */
    double len = v3_length(v3(1e300, 1e300, 1e300));
    ck_assert(isfinite(len));
    double expected = sqrt(3.0) * 1e300;
    ck_assert_double_eq_tol(len / expected, 1.0, 4 * DBL_EPSILON);
    ck_assert_double_eq_tol(v3_length(v3(-1e308, 0, 1e308)) /
                                (sqrt(2.0) * 1e308),
                            1.0, 4 * DBL_EPSILON);
}
END_TEST

START_TEST(length_of_1e_minus_300_vector_does_not_underflow)
{
    /* 1e-300^2 underflows to zero; the length is 5e-300 (3-4-0 scaled),
     * relative tolerance 4 ulps. */
    double len = v3_length(v3(3e-300, 4e-300, 0));
    ck_assert_double_eq_tol(len / 5e-300, 1.0, 4 * DBL_EPSILON);
}
END_TEST

START_TEST(length_of_zero_vector_is_zero)
{
    ck_assert_double_eq(v3_length(v3(0, 0, 0)), 0.0);
    ck_assert_double_eq(v3_length(v3(-0.0, 0, -0.0)), 0.0);
}
END_TEST

START_TEST(normalize_gives_unit_vector_in_same_direction)
{
    rt_vec3 n = v3_normalize(v3(0, 3, 4));
    assert_vec_eq(n, v3(0, 0.6, 0.8), 2 * DBL_EPSILON);
    n = v3_normalize(v3(1e300, -1e300, 1e300));
    ck_assert(v3_is_finite(n));
    double c = 1.0 / sqrt(3.0);
    assert_vec_eq(n, v3(c, -c, c), 4 * DBL_EPSILON);
    n = v3_normalize(v3(1e-310, 0, 0)); /* subnormal */
    assert_vec_eq(n, v3(1, 0, 0), 0.0);
    ck_assert_double_eq_tol(v3_length(v3_normalize(v3(-7, 0.1, 123.4))), 1.0,
                            4 * DBL_EPSILON);
}
END_TEST

START_TEST(normalize_keeps_zero_vector_zero_without_nan)
{
    rt_vec3 n = v3_normalize(v3(0, 0, 0));
    ck_assert(!isnan(n.x) && !isnan(n.y) && !isnan(n.z));
    assert_vec_eq(n, v3(0, 0, 0), 0.0);
}
END_TEST

START_TEST(max_abs_get_and_is_finite_report_components)
{
    ck_assert_double_eq(v3_max_abs(v3(1, -7, 3)), 7.0);
    assert_vec_eq(v3_abs(v3(-1, 2, -3)), v3(1, 2, 3), 0.0);
    ck_assert_double_eq(v3_get(v3(4, 5, 6), 0), 4.0);
    ck_assert_double_eq(v3_get(v3(4, 5, 6), 1), 5.0);
    ck_assert_double_eq(v3_get(v3(4, 5, 6), 2), 6.0);
    ck_assert(v3_is_finite(v3(1, 2, 3)));
    ck_assert(!v3_is_finite(v3(1, NAN, 3)));
    ck_assert(!v3_is_finite(v3(1, 2, INFINITY)));
    ck_assert(!v3_is_finite(v3(-INFINITY, 2, 3)));
}
END_TEST

Suite *vec_suite(void);

Suite *vec_suite(void)
{
    Suite *suite = suite_create("vec");
    TCase *tc = tcase_create("vecmath");
    tcase_add_test(tc, add_sub_scale_and_neg_work_per_component);
    tcase_add_test(tc, dot_is_the_sum_of_products);
    tcase_add_test(tc, cross_is_right_handed_and_anticommutative);
    tcase_add_test(tc, length_of_a_pythagorean_vector_is_exact);
    tcase_add_test(tc, length_of_1e300_vector_does_not_overflow);
    tcase_add_test(tc, length_of_1e_minus_300_vector_does_not_underflow);
    tcase_add_test(tc, length_of_zero_vector_is_zero);
    tcase_add_test(tc, normalize_gives_unit_vector_in_same_direction);
    tcase_add_test(tc, normalize_keeps_zero_vector_zero_without_nan);
    tcase_add_test(tc, max_abs_get_and_is_finite_report_components);
    suite_add_tcase(suite, tc);
    return suite;
}

RT_CHECK_MAIN(vec_suite)
