/*
 * test_robust_invariance.c - a scene and its copy translated or scaled give the same picture but for edge pixels.
 * (issue 5; the cases are in robust/cases.c, docs/robustness.md).
 */
#include "testutil.h"
#include "robust/robust_check.h"

RB_CASE_TESTS(translation_by_1e6_changes_only_edge_pixels, "T1")
RB_CASE_TESTS(scaling_by_1e_6_changes_only_edge_pixels, "T2")
RB_CASE_TESTS(scaling_by_1e6_changes_only_edge_pixels, "T3")
RB_CASE_TESTS(scaling_by_1e_150_changes_only_edge_pixels, "T4")
RB_CASE_TESTS(scaling_by_1e150_changes_only_edge_pixels, "T5")

static Suite *robust_invariance_suite(void)
{
    Suite *s = suite_create("robust_invariance");
    TCase *tc = rb_tcase("cases");
    RB_ADD_TESTS(tc, translation_by_1e6_changes_only_edge_pixels);
    RB_ADD_TESTS(tc, scaling_by_1e_6_changes_only_edge_pixels);
    RB_ADD_TESTS(tc, scaling_by_1e6_changes_only_edge_pixels);
    RB_ADD_TESTS(tc, scaling_by_1e_150_changes_only_edge_pixels);
    RB_ADD_TESTS(tc, scaling_by_1e150_changes_only_edge_pixels);
    suite_add_tcase(s, tc);
    return s;
}

RT_CHECK_MAIN(robust_invariance_suite)
