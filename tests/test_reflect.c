/*
 * test_reflect.c - mirror reflections (docs/rendering-model.md, k > 0): a
 * mirror shows the facet it faces, k mixes the reflected and the diffuse
 * colours, the depth limit (0: no reflection; the reflection past the
 * limit is black) counted exactly in a corridor of two parallel mirrors, and
 * reflections that miss everything bring the background weighted by k.
 */
#include "testutil.h"

#include <math.h>
#include <stdio.h>

#define COLOR_TOL 1e-9

/* Colours of the mirror scene. */
static const double CS[3] = {200, 220, 240}; /* light */
static const double CF[3] = {100, 150, 250}; /* the facet in the mirror */
static const double CM[3] = {60, 70, 80};    /* the mirror's own colour */
static const double BG[3] = {11, 22, 33};    /* background */

/*
 * A mirror of reflection k in the plane z = 0 (hit at (5, 0, 0) by the ray
 * from O = (0, 0, 5) along (1, 0, -1)), which reflects the ray to a facet
 * of colour CF in the plane x = 10, hit at (10, 0, 5).  The light at
 * (5, 0, 5) lights both points head-on (N.S = 1) and no shadow falls.
 * The 1x1 image's only primary ray is that ray.
 */
static rt_scene *mirror_scene_scaled(double k, double s)
{
    char text[1024];
    snprintf(text, sizeof text,
             "0 0 %.17g\n%.17g 0 %.17g %.17g %.17g %.17g 1 1\n6\n"
             "%.17g %.17g 0\n%.17g %.17g 0\n0 %.17g 0\n"
             "%.17g %.17g %.17g\n%.17g %.17g %.17g\n%.17g 0 %.17g\n"
             "2\n1 2 3 %.17g %g %g %g\n4 5 6 0 %g %g %g\n"
             "%g %g %g\n%.17g 0 %.17g %g %g %g\n",
             5 * s, 1 * s, 4 * s, 1 * s, 1 * s, 4 * s, -20 * s, -20 * s,
             20 * s, -20 * s, 20 * s, 10 * s, -20 * s, 1 * s, 10 * s, 20 * s,
             1 * s, 10 * s, 20 * s, k, CM[0], CM[1], CM[2], CF[0], CF[1],
             CF[2], BG[0], BG[1], BG[2], 5 * s, 5 * s, CS[0], CS[1], CS[2]);
    return rt_test_scene_from_string(text);
}

static rt_scene *mirror_scene(double k)
{
    return mirror_scene_scaled(k, 1.0);
}

static const rt_ray to_mirror = {{0, 0, 5}, {1, 0, -1}};

START_TEST(perfect_mirror_shows_the_facet_it_faces)
{
    rt_scene *scene = mirror_scene(1.0);
    rt_color c = rt_trace(scene, to_mirror, RT_DEFAULT_DEPTH);
    /* C = 1 * C_R = C_S C_F / 255 */
    rt_test_assert_color(c, CS[0] * CF[0] / 255, CS[1] * CF[1] / 255,
                         CS[2] * CF[2] / 255, COLOR_TOL, "k = 1");
    /* what the facet looks like when seen directly from the mirror point */
    rt_ray direct = {{5, 0, 0}, {1, 0, 1}};
    rt_test_assert_color(rt_trace(scene, direct, RT_DEFAULT_DEPTH), c.r, c.g,
                         c.b, COLOR_TOL, "facet seen directly");
    /* and through a render: the one pixel */
    rt_image image = rt_test_render(scene, RT_DEFAULT_DEPTH, 1);
    const unsigned char *p = rt_image_pixel(&image, 0, 0);
    ck_assert_int_eq(p[0], 78);  /* 200*100/255 = 78.43 */
    ck_assert_int_eq(p[1], 129); /* 220*150/255 = 129.41 */
    ck_assert_int_eq(p[2], 235); /* 240*250/255 = 235.29 */
    rt_image_release(&image);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(half_mirror_mixes_reflection_and_own_colour)
{
    const double ks[] = {0.5, 0.25, 0.9};
    for (size_t i = 0; i < sizeof ks / sizeof ks[0]; i++) {
        double k = ks[i];
        rt_scene *scene = mirror_scene(k);
        double e[3];
        for (int ch = 0; ch < 3; ch++)
            e[ch] = k * CS[ch] * CF[ch] / 255 + (1 - k) * CS[ch] * CM[ch] / 255;
        char what[32];
        snprintf(what, sizeof what, "k = %g", k);
        rt_test_assert_color(rt_trace(scene, to_mirror, RT_DEFAULT_DEPTH),
                             e[0], e[1], e[2], COLOR_TOL, what);
        rt_scene_destroy(scene);
    }
}
END_TEST

START_TEST(depth_zero_follows_no_reflection)
{
    rt_scene *scene = mirror_scene(1.0);
    rt_test_assert_color(rt_trace(scene, to_mirror, 0), 0, 0, 0, 0.0,
                         "k = 1, depth 0");
    rt_test_assert_color(rt_trace(scene, to_mirror, 1), CS[0] * CF[0] / 255,
                         CS[1] * CF[1] / 255, CS[2] * CF[2] / 255, COLOR_TOL,
                         "k = 1, depth 1");
    rt_image image = rt_test_render(scene, 0, 1);
    const unsigned char *p = rt_image_pixel(&image, 0, 0);
    ck_assert_msg(p[0] == 0 && p[1] == 0 && p[2] == 0,
                  "depth 0 pixel = %d %d %d, expected black", p[0], p[1],
                  p[2]);
    rt_image_release(&image);
    rt_scene_destroy(scene);
    scene = mirror_scene(0.5);
    rt_test_assert_color(rt_trace(scene, to_mirror, 0),
                         0.5 * CS[0] * CM[0] / 255, 0.5 * CS[1] * CM[1] / 255,
                         0.5 * CS[2] * CM[2] / 255, COLOR_TOL,
                         "k = 0.5, depth 0");
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(reflection_that_misses_brings_background_weighted_by_k)
{
    /* along (-1, 0, -1) the ray hits the mirror at (-5, 0, 0) and goes off
     * to the left, where nothing is; the light at (5, 0, 5) gives
     * N.S = 5 / sqrt(125) there */
    rt_ray ray = {{0, 0, 5}, {-1, 0, -1}};
    double ns = 5 / sqrt(125.0);
    const double ks[] = {1.0, 0.5};
    for (size_t i = 0; i < 2; i++) {
        double k = ks[i];
        rt_scene *scene = mirror_scene(k);
        double e[3];
        for (int ch = 0; ch < 3; ch++)
            e[ch] = k * BG[ch] + (1 - k) * ns * CS[ch] * CM[ch] / 255;
        rt_test_assert_color(rt_trace(scene, ray, RT_DEFAULT_DEPTH), e[0],
                             e[1], e[2], COLOR_TOL,
                             k == 1 ? "k = 1" : "k = 0.5");
        rt_scene_destroy(scene);
    }
}
END_TEST

START_TEST(mirror_works_at_every_scale_of_coordinates)
{
    /* the reflected ray must neither hit the mirror it leaves nor miss
     * because of the offset that prevents it: same colour from 1e-6 to 1e9
     * (tolerance 1e-6) */
    const double scales[] = {1e-6, 1e-3, 1e3, 1e6, 1e9};
    for (size_t i = 0; i < sizeof scales / sizeof scales[0]; i++) {
        rt_scene *scene = mirror_scene_scaled(0.5, scales[i]);
        rt_ray ray = {{0, 0, 5 * scales[i]}, {1, 0, -1}};
        double e[3];
        for (int ch = 0; ch < 3; ch++)
            e[ch] = 0.5 * CS[ch] * CF[ch] / 255 + 0.5 * CS[ch] * CM[ch] / 255;
        char what[32];
        snprintf(what, sizeof what, "scale %g", scales[i]);
        rt_test_assert_color(rt_trace(scene, ray, RT_DEFAULT_DEPTH), e[0],
                             e[1], e[2], 1e-6, what);
        rt_scene_destroy(scene);
    }
}
END_TEST

/*
 * Two parallel mirrors (k = 1) z = 0 and z = 10, for x in [-50, x_end]: the
 * ray from (0, 0, 5) along (1, 0, -1) hits them at x = 5, 15, 25, ...
 */
static rt_scene *corridor(double x_end, double k)
{
    char text[1024];
    snprintf(text, sizeof text,
             "0 0 5\n1 0 4 1 1 4 1 1\n8\n"
             "-50 -50 0\n%.17g -50 0\n%.17g 50 0\n-50 50 0\n"
             "-50 -50 10\n%.17g -50 10\n%.17g 50 10\n-50 50 10\n"
             "4\n1 2 3 %.17g 255 255 255\n1 3 4 %.17g 255 255 255\n"
             "5 6 7 %.17g 255 255 255\n5 7 8 %.17g 255 255 255\n"
             "%g %g %g\n0 0 5 255 255 255\n",
             x_end, x_end, x_end, x_end, k, k, k, k, BG[0], BG[1], BG[2]);
    return rt_test_scene_from_string(text);
}

START_TEST(depth_limit_counts_reflections_exactly)
{
    /* x_end = 40: four hits (5, 15, 25, 35), the fourth reflection escapes
     * to the background; with depth 3 it is past the limit: black */
    rt_scene *scene = corridor(40, 1.0);
    rt_ray ray = {{0, 0, 5}, {1, 0, -1}};
    for (int depth = 0; depth <= 3; depth++) {
        char what[32];
        snprintf(what, sizeof what, "depth %d", depth);
        rt_test_assert_color(rt_trace(scene, ray, depth), 0, 0, 0, 0.0, what);
    }
    for (int depth = 4; depth <= 8; depth++) {
        char what[32];
        snprintf(what, sizeof what, "depth %d", depth);
        rt_test_assert_color(rt_trace(scene, ray, depth), BG[0], BG[1], BG[2],
                             COLOR_TOL, what);
    }
    rt_image image = rt_test_render(scene, 4, 1);
    const unsigned char *p = rt_image_pixel(&image, 0, 0);
    ck_assert_msg(p[0] == 11 && p[1] == 22 && p[2] == 33,
                  "depth 4 pixel = %d %d %d", p[0], p[1], p[2]);
    rt_image_release(&image);
    image = rt_test_render(scene, 3, 1);
    p = rt_image_pixel(&image, 0, 0);
    ck_assert_msg(p[0] == 0 && p[1] == 0 && p[2] == 0,
                  "depth 3 pixel = %d %d %d", p[0], p[1], p[2]);
    rt_image_release(&image);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(parallel_mirrors_terminate_at_any_depth)
{
    /* the corridor runs to x = 1e7: the ray never escapes */
    rt_scene *scene = corridor(1e7, 1.0);
    rt_ray ray = {{0, 0, 5}, {1, 0, -1}};
    const int depths[] = {0, 1, 5, 100, 10000};
    for (size_t i = 0; i < sizeof depths / sizeof depths[0]; i++) {
        char what[32];
        snprintf(what, sizeof what, "depth %d", depths[i]);
        rt_test_assert_color(rt_trace(scene, ray, depths[i]), 0, 0, 0, 0.0,
                             what);
    }
    rt_scene_destroy(scene);
    /* half mirrors: the value stays finite and within [0, 255] */
    scene = corridor(1e7, 0.5);
    rt_color c = rt_trace(scene, ray, 1000);
    ck_assert(isfinite(c.r) && c.r >= 0 && c.r <= 255 + 1e-9);
    ck_assert(isfinite(c.g) && c.g >= 0 && c.g <= 255 + 1e-9);
    rt_image image = rt_test_render(scene, RT_DEFAULT_DEPTH, 1);
    rt_image_release(&image);
    rt_scene_destroy(scene);
}
END_TEST

Suite *reflect_suite(void);

Suite *reflect_suite(void)
{
    Suite *suite = suite_create("reflect");
    TCase *tc = tcase_create("reflect");
    tcase_set_timeout(tc, 20);
    tcase_add_test(tc, perfect_mirror_shows_the_facet_it_faces);
    tcase_add_test(tc, half_mirror_mixes_reflection_and_own_colour);
    tcase_add_test(tc, depth_zero_follows_no_reflection);
    tcase_add_test(tc, reflection_that_misses_brings_background_weighted_by_k);
    tcase_add_test(tc, mirror_works_at_every_scale_of_coordinates);
    tcase_add_test(tc, depth_limit_counts_reflections_exactly);
    tcase_add_test(tc, parallel_mirrors_terminate_at_any_depth);
    suite_add_tcase(suite, tc);
    return suite;
}

RT_CHECK_MAIN(reflect_suite)
