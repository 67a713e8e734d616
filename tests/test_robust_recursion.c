/*
 * test_robust_recursion.c - facing mirrors at depth 100,000 in linear time and constant stack; no ray escapes a closed mirror box.
 * (issue 5; the cases are in robust/cases.c, docs/robustness.md).
 */
#include "testutil.h"
#include "robust/robust_check.h"

RB_CASE_TESTS(facing_mirrors_at_depth_100000_finish_black_in_linear_work, "R1")
RB_CASE_TESTS(no_ray_escapes_a_closed_mirror_box, "R2")

static Suite *robust_recursion_suite(void)
{
    Suite *s = suite_create("robust_recursion");
    TCase *tc = rb_tcase("cases");
    RB_ADD_TESTS(tc, facing_mirrors_at_depth_100000_finish_black_in_linear_work);
    RB_ADD_TESTS(tc, no_ray_escapes_a_closed_mirror_box);
    suite_add_tcase(s, tc);
    return s;
}

RT_CHECK_MAIN(robust_recursion_suite)
