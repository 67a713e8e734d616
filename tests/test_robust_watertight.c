/*
 * test_robust_watertight.c - no ray falls through a closed mesh: rays aimed exactly at shared edges and vertices, at every scale.
 * (issue 5; the cases are in robust/cases.c, docs/robustness.md).
 */
#include "testutil.h"
#include "robust/robust_check.h"

RB_CASE_TESTS(rays_at_shared_edges_of_a_sphere_of_radius_1e_3_all_hit, "W1")
RB_CASE_TESTS(rays_at_shared_edges_of_a_sphere_of_radius_1_all_hit, "W2")
RB_CASE_TESTS(rays_at_shared_edges_of_a_sphere_of_radius_1e3_all_hit, "W3")
RB_CASE_TESTS(rays_through_the_apex_of_a_fan_of_64_facets_all_hit, "W4")
RB_CASE_TESTS(rays_at_shared_edges_of_a_tilted_grid_near_1e6_all_hit, "W5")

static Suite *robust_watertight_suite(void)
{
    Suite *s = suite_create("robust_watertight");
    TCase *tc = rb_tcase("cases");
    RB_ADD_TESTS(tc, rays_at_shared_edges_of_a_sphere_of_radius_1e_3_all_hit);
    RB_ADD_TESTS(tc, rays_at_shared_edges_of_a_sphere_of_radius_1_all_hit);
    RB_ADD_TESTS(tc, rays_at_shared_edges_of_a_sphere_of_radius_1e3_all_hit);
    RB_ADD_TESTS(tc, rays_through_the_apex_of_a_fan_of_64_facets_all_hit);
    RB_ADD_TESTS(tc, rays_at_shared_edges_of_a_tilted_grid_near_1e6_all_hit);
    suite_add_tcase(s, tc);
    return s;
}

RT_CHECK_MAIN(robust_watertight_suite)
