/*
 * test_robust_shadows.c - secondary rays neither leak through a close occluder nor hit their own surface, at every scale.
 * (issue 5; the cases are in robust/cases.c, docs/robustness.md).
 */
#include "testutil.h"
#include "robust/robust_check.h"

RB_CASE_TESTS(contact_shadow_is_dark_and_floor_clean_at_scale_1e_6, "S1")
RB_CASE_TESTS(contact_shadow_is_dark_and_floor_clean_at_scale_1e_3, "S2")
RB_CASE_TESTS(contact_shadow_is_dark_and_floor_clean_at_scale_1, "S3")
RB_CASE_TESTS(contact_shadow_is_dark_and_floor_clean_at_scale_1e3, "S4")
RB_CASE_TESTS(contact_shadow_is_dark_and_floor_clean_at_scale_1e6, "S5")
RB_CASE_TESTS(contact_shadow_is_dark_and_floor_clean_near_1e12, "S6")

static Suite *robust_shadows_suite(void)
{
    Suite *s = suite_create("robust_shadows");
    TCase *tc = rb_tcase("cases");
    RB_ADD_TESTS(tc, contact_shadow_is_dark_and_floor_clean_at_scale_1e_6);
    RB_ADD_TESTS(tc, contact_shadow_is_dark_and_floor_clean_at_scale_1e_3);
    RB_ADD_TESTS(tc, contact_shadow_is_dark_and_floor_clean_at_scale_1);
    RB_ADD_TESTS(tc, contact_shadow_is_dark_and_floor_clean_at_scale_1e3);
    RB_ADD_TESTS(tc, contact_shadow_is_dark_and_floor_clean_at_scale_1e6);
    RB_ADD_TESTS(tc, contact_shadow_is_dark_and_floor_clean_near_1e12);
    suite_add_tcase(s, tc);
    return s;
}

RT_CHECK_MAIN(robust_shadows_suite)
