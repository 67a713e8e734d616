/*
 * test_robust_special.c - NaN and infinities in inputs, rays of every magnitude, far lights, float's lost shapes, subnormal scenes.
 * (issue 5; the cases are in robust/cases.c, docs/robustness.md).
 */
#include "testutil.h"
#include "robust/robust_check.h"

RB_CASE_TESTS(non_finite_inputs_are_refused_by_the_loader, "V1")
RB_CASE_TESTS(ray_magnitude_does_not_change_the_hit_and_non_rays_hit_nothing, "V2")
RB_CASE_TESTS(light_beyond_floats_range_gives_the_same_image, "V3")
RB_CASE_TESTS(facets_collapsed_in_float_give_no_nan, "V4")
RB_CASE_TESTS(subnormal_scene_gives_no_nan, "V5")

static Suite *robust_special_suite(void)
{
    Suite *s = suite_create("robust_special");
    TCase *tc = rb_tcase("cases");
    RB_ADD_TESTS(tc, non_finite_inputs_are_refused_by_the_loader);
    RB_ADD_TESTS(tc, ray_magnitude_does_not_change_the_hit_and_non_rays_hit_nothing);
    RB_ADD_TESTS(tc, light_beyond_floats_range_gives_the_same_image);
    RB_ADD_TESTS(tc, facets_collapsed_in_float_give_no_nan);
    RB_ADD_TESTS(tc, subnormal_scene_gives_no_nan);
    suite_add_tcase(s, tc);
    return s;
}

RT_CHECK_MAIN(robust_special_suite)
