/*
 * test_robust_lights.c - lights in a facet's plane, on a vertex, on a facet, and at grazing angles.
 * (issue 5; the cases are in robust/cases.c, docs/robustness.md).
 */
#include "testutil.h"
#include "robust/robust_check.h"

RB_CASE_TESTS(light_in_the_plane_of_a_floor_gives_it_no_light, "L1")
RB_CASE_TESTS(light_in_a_tilted_floor_plane_gives_it_no_visible_light, "L2")
RB_CASE_TESTS(light_on_a_shared_vertex_lights_the_floor_below, "L3")
RB_CASE_TESTS(light_on_a_wall_lights_the_floor_on_both_sides, "L4")
RB_CASE_TESTS(grazing_light_at_1e_6_rad_gives_no_acne, "L5")
RB_CASE_TESTS(grazing_light_at_1e_12_rad_gives_no_acne, "L6")

static Suite *robust_lights_suite(void)
{
    Suite *s = suite_create("robust_lights");
    TCase *tc = rb_tcase("cases");
    RB_ADD_TESTS(tc, light_in_the_plane_of_a_floor_gives_it_no_light);
    RB_ADD_TESTS(tc, light_in_a_tilted_floor_plane_gives_it_no_visible_light);
    RB_ADD_TESTS(tc, light_on_a_shared_vertex_lights_the_floor_below);
    RB_ADD_TESTS(tc, light_on_a_wall_lights_the_floor_on_both_sides);
    RB_ADD_TESTS(tc, grazing_light_at_1e_6_rad_gives_no_acne);
    RB_ADD_TESTS(tc, grazing_light_at_1e_12_rad_gives_no_acne);
    suite_add_tcase(s, tc);
    return s;
}

RT_CHECK_MAIN(robust_lights_suite)
