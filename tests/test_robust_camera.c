/*
 * test_robust_camera.c - the camera on a facet, rays in a facet's plane, grazing camera rays.
 * (issue 5; the cases are in robust/cases.c, docs/robustness.md).
 */
#include "testutil.h"
#include "robust/robust_check.h"

RB_CASE_TESTS(camera_on_the_floor_never_sees_the_floor, "C1")
RB_CASE_TESTS(rays_in_a_facets_plane_never_hit_it, "C2")
RB_CASE_TESTS(grazing_rays_at_shared_edges_all_hit, "C3")

static Suite *robust_camera_suite(void)
{
    Suite *s = suite_create("robust_camera");
    TCase *tc = rb_tcase("cases");
    RB_ADD_TESTS(tc, camera_on_the_floor_never_sees_the_floor);
    RB_ADD_TESTS(tc, rays_in_a_facets_plane_never_hit_it);
    RB_ADD_TESTS(tc, grazing_rays_at_shared_edges_all_hit);
    suite_add_tcase(s, tc);
    return s;
}

RT_CHECK_MAIN(robust_camera_suite)
