/*
 * test_robust_determinism.c - coincident facets obey the tie rule; images are the same for every thread count and loop.
 * (issue 5; the cases are in robust/cases.c, docs/robustness.md).
 */
#include "testutil.h"
#include "robust/robust_check.h"

RB_CASE_TESTS(duplicate_facets_first_in_the_file_wins, "Q1")
RB_CASE_TESTS(duplicate_facets_with_rotated_vertices_first_wins, "Q2")
RB_CASE_TESTS(thread_counts_give_identical_images, "X1")
RB_CASE_TESTS(scalar_and_avx2_loops_give_identical_images, "X2")

static Suite *robust_determinism_suite(void)
{
    Suite *s = suite_create("robust_determinism");
    TCase *tc = rb_tcase("cases");
    RB_ADD_TESTS(tc, duplicate_facets_first_in_the_file_wins);
    RB_ADD_TESTS(tc, duplicate_facets_with_rotated_vertices_first_wins);
    RB_ADD_TESTS(tc, thread_counts_give_identical_images);
    RB_ADD_TESTS(tc, scalar_and_avx2_loops_give_identical_images);
    suite_add_tcase(s, tc);
    return s;
}

RT_CHECK_MAIN(robust_determinism_suite)
