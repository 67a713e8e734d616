/*
 * test_intersect.c - rt_scene_nearest_hit and rt_scene_occluded on small
 * scenes whose answers are known by hand: t, point and normal of a hit,
 * misses beside and behind, t_max, ties between coincident facets, rays
 * through the shared edge or vertex of a mesh (none may pass between the
 * facets), zero-area facets.
 */
#include "testutil.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define CAMERA "0 0 5\n0 0 4 1 0 0 2 2\n"
#define LIGHT "0 0 0\n0 0 10 255 255 255\n"

/* One facet in the plane z = 0 around the origin. */
static const char *const one_facet_scene =
    CAMERA "3\n-1 -1 0\n1 -1 0\n0 1 0\n1\n1 2 3 0 255 0 0\n" LIGHT;

static rt_ray ray_of(double ox, double oy, double oz, double dx, double dy,
                     double dz)
{
    return (rt_ray){{ox, oy, oz}, {dx, dy, dz}};
}

START_TEST(hit_from_above_gives_t_point_and_normal_facing_the_origin)
{
    rt_scene *scene = rt_test_scene_from_string(one_facet_scene);
    rt_hit hit;
    ck_assert(rt_scene_nearest_hit(scene, ray_of(0, 0, 5, 0, 0, -1), INFINITY,
                                   &hit));
    ck_assert_int_eq(hit.facet, 0);
    ck_assert_double_eq_tol(hit.t, 5.0, 1e-14);
    ck_assert_double_eq_tol(hit.point.x, 0.0, 1e-14);
    ck_assert_double_eq_tol(hit.point.y, 0.0, 1e-14);
    ck_assert_double_eq_tol(hit.point.z, 0.0, 1e-14);
    ck_assert_double_eq_tol(hit.normal.x, 0.0, 1e-15);
    ck_assert_double_eq_tol(hit.normal.y, 0.0, 1e-15);
    ck_assert_double_eq_tol(hit.normal.z, 1.0, 1e-15);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(hit_from_below_turns_normal_and_scales_t_with_direction)
{
    rt_scene *scene = rt_test_scene_from_string(one_facet_scene);
    rt_hit hit;
    /* direction of length 2 and oblique: reaches z = 0 at t = 2.5, point
     * (0.25, -0.5, 0) */
    ck_assert(rt_scene_nearest_hit(scene, ray_of(0, 0, -5, 0.1, -0.2, 2),
                                   INFINITY, &hit));
    ck_assert_double_eq_tol(hit.t, 2.5, 1e-14);
    ck_assert_double_eq_tol(hit.point.x, 0.25, 1e-14);
    ck_assert_double_eq_tol(hit.point.y, -0.5, 1e-14);
    ck_assert_double_eq_tol(hit.point.z, 0.0, 1e-14);
    ck_assert_double_eq_tol(hit.normal.z, -1.0, 1e-15);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(ray_beside_the_facet_misses)
{
    rt_scene *scene = rt_test_scene_from_string(one_facet_scene);
    rt_hit hit;
    ck_assert(!rt_scene_nearest_hit(scene, ray_of(5, 0, 5, 0, 0, -1),
                                    INFINITY, &hit));
    /* just outside the slanted edge x = (1 - y)/2 at y = 0 */
    ck_assert(!rt_scene_nearest_hit(scene, ray_of(0.5001, 0, 5, 0, 0, -1),
                                    INFINITY, &hit));
    ck_assert(rt_scene_nearest_hit(scene, ray_of(0.4999, 0, 5, 0, 0, -1),
                                   INFINITY, &hit));
    /* parallel to the plane, in it or above it */
    ck_assert(!rt_scene_nearest_hit(scene, ray_of(-5, 0, 1, 1, 0, 0),
                                    INFINITY, &hit));
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(hits_behind_the_origin_are_ignored)
{
    rt_scene *scene = rt_test_scene_from_string(one_facet_scene);
    rt_hit hit;
    ck_assert(!rt_scene_nearest_hit(scene, ray_of(0, 0, 5, 0, 0, 1), INFINITY,
                                    &hit));
    ck_assert(!rt_scene_nearest_hit(scene, ray_of(0, 0, -5, 0, 0, -1),
                                    INFINITY, &hit));
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(hits_at_or_beyond_t_max_are_ignored)
{
    rt_scene *scene = rt_test_scene_from_string(one_facet_scene);
    rt_hit hit;
    rt_ray ray = ray_of(0, 0, 5, 0, 0, -1); /* hit at t = 5 */
    ck_assert(!rt_scene_nearest_hit(scene, ray, 4.9, &hit));
    ck_assert(rt_scene_nearest_hit(scene, ray, 5.1, &hit));
    ck_assert_double_eq_tol(hit.t, 5.0, 1e-14);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(nearest_of_two_facets_wins_whatever_their_order)
{
    /* facet 1 (z = 0) and facet 2 (z = 1) on the same vertical ray */
    const char *text = CAMERA "6\n-1 -1 0\n1 -1 0\n0 1 0\n"
                              "-1 -1 1\n1 -1 1\n0 1 1\n"
                              "2\n1 2 3 0 255 0 0\n4 5 6 0 0 255 0\n" LIGHT;
    rt_scene *scene = rt_test_scene_from_string(text);
    rt_hit hit;
    ck_assert(rt_scene_nearest_hit(scene, ray_of(0, 0, 5, 0, 0, -1), INFINITY,
                                   &hit));
    ck_assert_int_eq(hit.facet, 1);
    ck_assert_double_eq_tol(hit.t, 4.0, 1e-14);
    ck_assert(rt_scene_nearest_hit(scene, ray_of(0, 0, -5, 0, 0, 1), INFINITY,
                                   &hit));
    ck_assert_int_eq(hit.facet, 0);
    ck_assert_double_eq_tol(hit.t, 5.0, 1e-14);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(tie_between_coincident_facets_goes_to_the_lower_index)
{
    /* facet 0 lies further away; facets 1, 2 and 3 are the same record */
    const char *text = CAMERA "6\n-1 -1 0\n1 -1 0\n0 1 0\n"
                              "-1 -1 -1\n1 -1 -1\n0 1 -1\n"
                              "4\n4 5 6 0 0 0 255\n1 2 3 0 255 0 0\n"
                              "1 2 3 0 0 255 0\n1 2 3 0 0 255 0\n" LIGHT;
    rt_scene *scene = rt_test_scene_from_string(text);
    rt_hit hit;
    double points[][2] = {{0, 0}, {0.3, -0.7}, {-0.2, 0.5}, {0.1, 0.1}};
    for (size_t p = 0; p < sizeof points / sizeof points[0]; p++) {
        ck_assert(rt_scene_nearest_hit(
            scene, ray_of(points[p][0] * 0.5, points[p][1] * 0.5, 5,
                          points[p][0] * 0.5, points[p][1] * 0.5, -5),
            INFINITY, &hit));
        ck_assert_msg(hit.facet == 1, "ray %zu hit facet %d, expected 1", p,
                      hit.facet);
    }
    rt_scene_destroy(scene);
}
END_TEST

/* A quad v1 v2 v3 v4 made of the triangles (1,2,3) and (1,3,4), whose
 * shared edge is the diagonal v1-v3, in a tilted plane with awkward
 * coordinates so that rounding matters. */
static rt_scene *tilted_square(rt_vec3 v[4], int flip_second)
{
    rt_vec3 origin = {0.1, 0.2, 0.3};
    rt_vec3 e1 = {1.7, 0.3, -0.45}, e2 = {-0.2, 1.3, 0.77};
    v[0] = origin;
    v[1] = (rt_vec3){origin.x + e1.x, origin.y + e1.y, origin.z + e1.z};
    v[2] = (rt_vec3){v[1].x + e2.x, v[1].y + e2.y, v[1].z + e2.z};
    v[3] = (rt_vec3){origin.x + e2.x, origin.y + e2.y, origin.z + e2.z};
    char text[1024];
    snprintf(text, sizeof text,
             CAMERA "4\n%.17g %.17g %.17g\n%.17g %.17g %.17g\n"
                    "%.17g %.17g %.17g\n%.17g %.17g %.17g\n2\n"
                    "1 2 3 0 255 0 0\n%s 0 0 255 0\n" LIGHT,
             v[0].x, v[0].y, v[0].z, v[1].x, v[1].y, v[1].z, v[2].x, v[2].y,
             v[2].z, v[3].x, v[3].y, v[3].z, flip_second ? "4 3 1" : "1 3 4");
    return rt_test_scene_from_string(text);
}

static void rays_through_the_diagonal_never_miss(int flip_second)
{
    rt_vec3 v[4];
    rt_scene *scene = tilted_square(v, flip_second);
    rt_test_rng rng = {12345};
    int misses = 0, first_miss = -1;
    const int rays = 20000;
    for (int n = 0; n < rays; n++) {
        double s = 0.02 + 0.96 * rt_test_rng_uniform(&rng);
        rt_vec3 p = {v[0].x + s * (v[2].x - v[0].x),
                     v[0].y + s * (v[2].y - v[0].y),
                     v[0].z + s * (v[2].z - v[0].z)};
        /* origins on both sides of the plane, in all directions */
        rt_vec3 o = {p.x + 10 * (rt_test_rng_uniform(&rng) - 0.5),
                     p.y + 10 * (rt_test_rng_uniform(&rng) - 0.5),
                     p.z + 10 * (rt_test_rng_uniform(&rng) - 0.5)};
        rt_ray ray = {o, {p.x - o.x, p.y - o.y, p.z - o.z}};
        rt_hit hit;
        if (!rt_scene_nearest_hit(scene, ray, INFINITY, &hit)) {
            if (first_miss < 0)
                first_miss = n;
            misses++;
        }
    }
    ck_assert_msg(misses == 0, "%d of %d rays through the shared edge missed "
                               "both triangles (first: ray %d)",
                  misses, rays, first_miss);
    rt_scene_destroy(scene);
}

START_TEST(rays_through_a_shared_edge_hit_one_of_the_two_triangles)
{
    rays_through_the_diagonal_never_miss(0);
}
END_TEST

START_TEST(rays_through_a_shared_edge_hit_whatever_the_winding)
{
    rays_through_the_diagonal_never_miss(1);
}
END_TEST

START_TEST(rays_through_a_vertex_shared_by_a_fan_never_miss)
{
    /* six triangles around the centre (0.1, 0.2, 0.3) in the plane
     * z = 0.3 + 0.1 (x - 0.1) - 0.05 (y - 0.2); rays aimed exactly at the
     * centre */
    const char *text =
        CAMERA "7\n0.1 0.2 0.3\n"
               "1.1 0.2 0.4\n0.6 1.1 0.305\n-0.4 1.1 0.205\n"
               "-0.9 0.2 0.2\n-0.4 -0.7 0.295\n0.6 -0.7 0.395\n"
               "6\n1 2 3 0 255 0 0\n1 3 4 0 255 0 0\n1 4 5 0 255 0 0\n"
               "1 5 6 0 255 0 0\n1 6 7 0 255 0 0\n1 7 2 0 255 0 0\n" LIGHT;
    rt_scene *scene = rt_test_scene_from_string(text);
    rt_test_rng rng = {777};
    int misses = 0;
    for (int n = 0; n < 5000; n++) {
        rt_vec3 o = {0.1 + 8 * (rt_test_rng_uniform(&rng) - 0.5),
                     0.2 + 8 * (rt_test_rng_uniform(&rng) - 0.5),
                     0.3 + 8 * (rt_test_rng_uniform(&rng) - 0.5)};
        rt_ray ray = {o, {0.1 - o.x, 0.2 - o.y, 0.3 - o.z}};
        rt_hit hit;
        misses += !rt_scene_nearest_hit(scene, ray, INFINITY, &hit);
    }
    ck_assert_msg(misses == 0, "%d of 5000 rays through the shared vertex "
                               "missed", misses);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(zero_area_facets_are_never_hit)
{
    /* facet 1: three collinear points; facet 2: two equal vertices */
    const char *text = CAMERA "4\n-1 0 0\n0 0 0\n1 0 0\n0 1 0\n"
                              "2\n1 2 3 0 255 0 0\n1 1 4 0 255 0 0\n" LIGHT;
    rt_scene *scene = rt_test_scene_from_string(text);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    ck_assert_int_eq(info.live_facet_count, 0);
    ck_assert_int_eq(info.warning_count, 2);
    rt_hit hit;
    double xs[] = {-1, -0.5, 0, 0.5, 1};
    for (size_t i = 0; i < sizeof xs / sizeof xs[0]; i++) {
        ck_assert(!rt_scene_nearest_hit(scene, ray_of(xs[i], 0, 5, 0, 0, -1),
                                        INFINITY, &hit));
        /* a ray lying along the segment itself */
        ck_assert(!rt_scene_nearest_hit(scene, ray_of(-5, 0, 0, 1, 0, 0),
                                        INFINITY, &hit));
        ck_assert(!rt_scene_occluded(scene, (rt_vec3){xs[i], 0, 5},
                                     (rt_vec3){xs[i], 0, -5}, -1));
    }
    /* along the degenerate facet 2, from (-1,0,0) to (0,1,0) */
    ck_assert(!rt_scene_nearest_hit(scene, ray_of(-0.5, 0.5, 5, 0, 0, -1),
                                    INFINITY, &hit));
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(occluded_when_a_facet_lies_strictly_between)
{
    rt_scene *scene = rt_test_scene_from_string(one_facet_scene);
    ck_assert(rt_scene_occluded(scene, (rt_vec3){0, 0, 5},
                                (rt_vec3){0, 0, -5}, -1));
    ck_assert(rt_scene_occluded(scene, (rt_vec3){0.2, -0.3, -1},
                                (rt_vec3){-0.1, 0.1, 2}, -1));
    /* both ends on the same side, beside, or the facet skipped */
    ck_assert(!rt_scene_occluded(scene, (rt_vec3){0, 0, 5},
                                 (rt_vec3){0, 0, 1}, -1));
    ck_assert(!rt_scene_occluded(scene, (rt_vec3){5, 0, 5},
                                 (rt_vec3){5, 0, -5}, -1));
    ck_assert(!rt_scene_occluded(scene, (rt_vec3){0, 0, 5},
                                 (rt_vec3){0, 0, -5}, 0));
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(occlusion_ignores_facets_past_the_end_point)
{
    /* the end point is above the facet: the facet is beyond it */
    rt_scene *scene = rt_test_scene_from_string(one_facet_scene);
    ck_assert(!rt_scene_occluded(scene, (rt_vec3){0, 0, 5},
                                 (rt_vec3){0, 0, 0.001}, -1));
    ck_assert(!rt_scene_occluded(scene, (rt_vec3){0, 0, -0.001},
                                 (rt_vec3){0, 0, -5}, -1));
    rt_scene_destroy(scene);
}
END_TEST

Suite *intersect_suite(void);

Suite *intersect_suite(void)
{
    Suite *suite = suite_create("intersect");
    TCase *tc = tcase_create("nearest_hit");
    tcase_add_test(tc, hit_from_above_gives_t_point_and_normal_facing_the_origin);
    tcase_add_test(tc, hit_from_below_turns_normal_and_scales_t_with_direction);
    tcase_add_test(tc, ray_beside_the_facet_misses);
    tcase_add_test(tc, hits_behind_the_origin_are_ignored);
    tcase_add_test(tc, hits_at_or_beyond_t_max_are_ignored);
    tcase_add_test(tc, nearest_of_two_facets_wins_whatever_their_order);
    tcase_add_test(tc, tie_between_coincident_facets_goes_to_the_lower_index);
    tcase_add_test(tc, zero_area_facets_are_never_hit);
    suite_add_tcase(suite, tc);

    TCase *edges = tcase_create("watertight");
    tcase_set_timeout(edges, 30);
    tcase_add_test(edges, rays_through_a_shared_edge_hit_one_of_the_two_triangles);
    tcase_add_test(edges, rays_through_a_shared_edge_hit_whatever_the_winding);
    tcase_add_test(edges, rays_through_a_vertex_shared_by_a_fan_never_miss);
    suite_add_tcase(suite, edges);

    TCase *occlusion = tcase_create("occluded");
    tcase_add_test(occlusion, occluded_when_a_facet_lies_strictly_between);
    tcase_add_test(occlusion, occlusion_ignores_facets_past_the_end_point);
    suite_add_tcase(suite, occlusion);
    return suite;
}

RT_CHECK_MAIN(intersect_suite)
