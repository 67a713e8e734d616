/*
 * test_robust_facets.c - zero-area facets are never hit; slivers of aspect 1e8 to 1e12 are hit where aimed and have accurate normals.
 * (issue 5; the cases are in robust/cases.c, docs/robustness.md).
 */
#include "testutil.h"
#include "robust/robust_check.h"

RB_CASE_TESTS(zero_area_facets_are_never_hit, "D1")
RB_CASE_TESTS(cap_slivers_of_aspect_1e8_are_hit_where_aimed, "D2")
RB_CASE_TESTS(cap_slivers_of_aspect_1e12_are_hit_where_aimed, "D3")
RB_CASE_TESTS(needles_of_aspect_1e12_are_hit_where_aimed, "D4")
RB_CASE_TESTS(sliver_normals_are_within_1e_9_of_exact, "D5")

static Suite *robust_facets_suite(void)
{
    Suite *s = suite_create("robust_facets");
    TCase *tc = rb_tcase("cases");
    RB_ADD_TESTS(tc, zero_area_facets_are_never_hit);
    RB_ADD_TESTS(tc, cap_slivers_of_aspect_1e8_are_hit_where_aimed);
    RB_ADD_TESTS(tc, cap_slivers_of_aspect_1e12_are_hit_where_aimed);
    RB_ADD_TESTS(tc, needles_of_aspect_1e12_are_hit_where_aimed);
    RB_ADD_TESTS(tc, sliver_normals_are_within_1e_9_of_exact);
    suite_add_tcase(s, tc);
    return s;
}

RT_CHECK_MAIN(robust_facets_suite)
