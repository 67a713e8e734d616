/*
 * test_shade.c - the colour of a ray without reflections
 * (docs/rendering-model.md, k = 0): C = E (N.S) C_S C_F / 255, each term checked on one-facet scenes
 * against values computed here by hand; the background on a miss; shadows;
 * two-sided facets; scale-independent self-intersection; and the final
 * clamp-and-round of rt_channel_to_byte, alone and through whole renders.
 */
#include "testutil.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Real colours agree within 1e-9 per channel (they are sums of a few
 * products of numbers <= 255). */
#define COLOR_TOL 1e-9

/* A large facet in the plane z = 0 (times `s`), colour C_F = (200, 100, 50),
 * background (10, 20, 30), light of colour C_S = (255, 128, 64) at
 * (lx, ly, lz) (times `s`), plus an optional second facet `extra` given as
 * three vertices and a k (its colour is white). */
static rt_scene *diffuse_scene(double s, double lx, double ly, double lz,
                               const double extra[10], int reverse_winding)
{
    char text[2048];
    int n = snprintf(text, sizeof text,
                     "0 0 %.17g\n0 0 %.17g %.17g 0 %.17g 3 3\n%d\n"
                     "%.17g %.17g 0\n%.17g %.17g 0\n0 %.17g 0\n",
                     5 * s, 4 * s, s, 4 * s, extra ? 6 : 3, -30 * s, -30 * s,
                     30 * s, -30 * s, 30 * s);
    if (extra)
        n += snprintf(text + n, sizeof text - (size_t)n,
                      "%.17g %.17g %.17g\n%.17g %.17g %.17g\n"
                      "%.17g %.17g %.17g\n",
                      extra[0], extra[1], extra[2], extra[3], extra[4],
                      extra[5], extra[6], extra[7], extra[8]);
    n += snprintf(text + n, sizeof text - (size_t)n, "%d\n%s 0 200 100 50\n",
                  extra ? 2 : 1, reverse_winding ? "3 2 1" : "1 2 3");
    if (extra)
        n += snprintf(text + n, sizeof text - (size_t)n,
                      "4 5 6 %.17g 255 255 255\n", extra[9]);
    snprintf(text + n, sizeof text - (size_t)n,
             "10 20 30\n%.17g %.17g %.17g 255 128 64\n", lx * s, ly * s,
             lz * s);
    return rt_test_scene_from_string(text);
}

static rt_ray down_from(double x, double y, double z)
{
    return (rt_ray){{x, y, z}, {0, 0, -1}};
}

START_TEST(light_straight_above_gives_full_diffuse_light_times_facet_colour)
{
    rt_scene *scene = diffuse_scene(1, 0, 0, 10, NULL, 0);
    rt_color c = rt_trace(scene, down_from(0, 0, 5), RT_DEFAULT_DEPTH);
    /* N.S = 1, E = 1: C_S C_F / 255 */
    rt_test_assert_color(c, 255.0 * 200 / 255, 128.0 * 100 / 255,
                         64.0 * 50 / 255, COLOR_TOL, "light above");
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(diffuse_term_scales_with_cosine_of_light_angle)
{
    /* hit (1, 2, 0), light (4, 2, 4): S = (3, 0, 4)/5, N.S = 0.8 */
    rt_scene *scene = diffuse_scene(1, 4, 2, 4, NULL, 0);
    rt_color c = rt_trace(scene, down_from(1, 2, 5), RT_DEFAULT_DEPTH);
    rt_test_assert_color(c, 0.8 * 200, 0.8 * 128.0 * 100 / 255,
                         0.8 * 64.0 * 50 / 255, COLOR_TOL, "N.S = 0.8");
    rt_scene_destroy(scene);
    /* hit (0, 0, 0), light (10, 0, 10): N.S = 1/sqrt(2) */
    scene = diffuse_scene(1, 10, 0, 10, NULL, 0);
    c = rt_trace(scene, down_from(0, 0, 5), RT_DEFAULT_DEPTH);
    double f = 1 / sqrt(2.0);
    rt_test_assert_color(c, f * 200, f * 128.0 * 100 / 255,
                         f * 64.0 * 50 / 255, COLOR_TOL, "N.S = cos 45");
    /* the viewing direction plays no part (Lambert) */
    rt_ray oblique = {{3, -2, 5}, {-3, 2, -5}};
    c = rt_trace(scene, oblique, RT_DEFAULT_DEPTH);
    rt_test_assert_color(c, f * 200, f * 128.0 * 100 / 255,
                         f * 64.0 * 50 / 255, COLOR_TOL, "oblique view");
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(grazing_light_still_lights_without_self_shadowing)
{
    /* hit (0,0,0), light (100, 0, 1): N.S = 1/sqrt(10001) */
    rt_scene *scene = diffuse_scene(1, 100, 0, 1, NULL, 0);
    rt_color c = rt_trace(scene, down_from(0, 0, 5), RT_DEFAULT_DEPTH);
    double f = 1 / sqrt(10001.0);
    rt_test_assert_color(c, f * 200, f * 128.0 * 100 / 255,
                         f * 64.0 * 50 / 255, COLOR_TOL, "grazing light");
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(light_behind_the_facet_gives_black)
{
    rt_scene *scene = diffuse_scene(1, 0, 0, -10, NULL, 0);
    rt_color c = rt_trace(scene, down_from(0, 0, 5), RT_DEFAULT_DEPTH);
    rt_test_assert_color(c, 0, 0, 0, 0.0, "light behind");
    rt_image image = rt_test_render(scene, RT_DEFAULT_DEPTH, 1);
    for (int y = 0; y < 3; y++)
        for (int x = 0; x < 3; x++) {
            const unsigned char *p = rt_image_pixel(&image, x, y);
            ck_assert_msg(p[0] == 0 && p[1] == 0 && p[2] == 0,
                          "pixel (%d,%d) = %d %d %d, expected black", x, y,
                          p[0], p[1], p[2]);
        }
    rt_image_release(&image);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(facet_seen_from_its_back_is_lit_when_light_is_on_viewer_side)
{
    const double full[3] = {200, 128.0 * 100 / 255, 64.0 * 50 / 255};
    for (int reverse = 0; reverse < 2; reverse++) {
        /* viewer below, light below */
        rt_scene *scene = diffuse_scene(1, 0, 0, -10, NULL, reverse);
        rt_ray up = {{0, 0, -5}, {0, 0, 1}};
        rt_test_assert_color(
            rt_trace(scene, up, RT_DEFAULT_DEPTH), full[0], full[1], full[2],
            COLOR_TOL, reverse ? "back side, reversed winding" : "back side");
        /* viewer below, light above: dark */
        rt_scene_destroy(scene);
        scene = diffuse_scene(1, 0, 0, 10, NULL, reverse);
        rt_test_assert_color(rt_trace(scene, up, RT_DEFAULT_DEPTH), 0, 0, 0,
                             0.0, "back side, light on the other side");
        /* viewer above, light above */
        rt_test_assert_color(
            rt_trace(scene, down_from(0, 0, 5), RT_DEFAULT_DEPTH), full[0],
            full[1], full[2], COLOR_TOL,
            reverse ? "front, reversed winding" : "front");
        rt_scene_destroy(scene);
    }
}
END_TEST

START_TEST(facet_between_hit_point_and_light_casts_a_shadow)
{
    /* a small white facet at z = 7 over the origin, light at z = 10; the
     * primary ray starts at z = 5, below it */
    const double blocker[10] = {-1, -1, 7, 1, -1, 7, 0, 1, 7, 0};
    rt_scene *scene = diffuse_scene(1, 0, 0, 10, blocker, 0);
    rt_test_assert_color(rt_trace(scene, down_from(0, 0, 5), RT_DEFAULT_DEPTH),
                         0, 0, 0, 0.0, "in the shadow");
    /* beside the shadow: lit */
    rt_test_assert_color(
        rt_trace(scene, down_from(10, 0, 5), RT_DEFAULT_DEPTH),
        200 * 10 / sqrt(200.0), 128.0 * 100 / 255 * 10 / sqrt(200.0),
        64.0 * 50 / 255 * 10 / sqrt(200.0), COLOR_TOL, "beside the shadow");
    rt_scene_destroy(scene);
    /* a mirror casts a shadow too */
    const double mirror[10] = {-1, -1, 7, 1, -1, 7, 0, 1, 7, 1};
    scene = diffuse_scene(1, 0, 0, 10, mirror, 0);
    rt_test_assert_color(rt_trace(scene, down_from(0, 0, 5), RT_DEFAULT_DEPTH),
                         0, 0, 0, 0.0, "in the shadow of a mirror");
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(facet_beyond_the_light_casts_no_shadow)
{
    const double beyond[10] = {-1, -1, 12, 1, -1, 12, 0, 1, 12, 0};
    rt_scene *scene = diffuse_scene(1, 0, 0, 10, beyond, 0);
    rt_test_assert_color(rt_trace(scene, down_from(0, 0, 5), RT_DEFAULT_DEPTH),
                         200, 128.0 * 100 / 255, 64.0 * 50 / 255, COLOR_TOL,
                         "blocker beyond the light");
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(ray_that_hits_nothing_returns_the_background)
{
    rt_scene *scene = diffuse_scene(1, 0, 0, 10, NULL, 0);
    rt_ray up = {{0, 0, 5}, {0, 0, 1}};
    rt_test_assert_color(rt_trace(scene, up, RT_DEFAULT_DEPTH), 10, 20, 30,
                         0.0, "miss");
    rt_ray beside = {{100, 0, 5}, {0, 0, -1}};
    rt_test_assert_color(rt_trace(scene, beside, 0), 10, 20, 30, 0.0,
                         "miss beside");
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(shading_does_not_depend_on_the_scale_of_coordinates)
{
    /* the same scene at 1e-6, 1, 1e6 and 1e9: a secondary ray that hit its
     * own facet would darken the point; N.S = 0.8 everywhere */
    const double scales[] = {1e-6, 1.0, 1e6, 1e9};
    for (size_t i = 0; i < sizeof scales / sizeof scales[0]; i++) {
        double s = scales[i];
        rt_scene *scene = diffuse_scene(s, 4, 2, 4, NULL, 0);
        rt_color c = rt_trace(scene, down_from(1 * s, 2 * s, 5 * s),
                              RT_DEFAULT_DEPTH);
        char what[64];
        snprintf(what, sizeof what, "scale %g", s);
        /* relative tolerance 1e-9 on values ~100 */
        rt_test_assert_color(c, 0.8 * 200, 0.8 * 128.0 * 100 / 255,
                             0.8 * 64.0 * 50 / 255, 1e-7, what);
        rt_scene_destroy(scene);
    }
}
END_TEST

START_TEST(shading_far_from_the_origin_has_no_self_shadowing)
{
    /* a facet of size ~60 in the plane z = 1e6, centred on (1e6, 1e6): the
     * hit point carries rounding errors ~1e-10, which a fixed epsilon of
     * 1e-5 would not cover at 1e9 and would swamp at 1e-6; N.S = 0.8 */
    const double offsets[] = {1e6, 1e9};
    for (size_t i = 0; i < 2; i++) {
        double d = offsets[i];
        char text[1024];
        snprintf(text, sizeof text,
                 "%.17g %.17g %.17g\n%.17g %.17g %.17g %.17g %.17g %.17g 3 3\n"
                 "3\n%.17g %.17g %.17g\n%.17g %.17g %.17g\n%.17g %.17g %.17g\n"
                 "1\n1 2 3 0 200 100 50\n10 20 30\n"
                 "%.17g %.17g %.17g 255 128 64\n",
                 d, d, d + 5, d, d, d + 4, d + 1, d, d + 4, d - 30, d - 30, d,
                 d + 30, d - 30, d, d, d + 30, d, d + 3.125 * 4, d + 0.3,
                 d + 4 * 4);
        rt_scene *scene = rt_test_scene_from_string(text);
        /* the ray hits (d + 0.5, d + 0.3, d); the light is at
         * (d + 12.5, d + 0.3, d + 16): S = (12, 0, 16) / 20 */
        rt_ray ray = {{d + 0.5, d + 0.3, d + 5}, {0, 0, -1}};
        rt_color c = rt_trace(scene, ray, RT_DEFAULT_DEPTH);
        char what[64];
        snprintf(what, sizeof what, "offset %g", d);
        /* tolerance 1e-3: the coordinates themselves are rounded to
         * 1e-7 (at 1e9) of distances ~10 */
        rt_test_assert_color(c, 0.8 * 200, 0.8 * 128.0 * 100 / 255,
                             0.8 * 64.0 * 50 / 255, 1e-3, what);
        rt_scene_destroy(scene);
    }
}
END_TEST

START_TEST(channel_to_byte_clamps_and_rounds_halves_away_from_zero)
{
    static const struct {
        double value;
        int byte;
    } cases[] = {
        {-1e300, 0}, {-5, 0},     {-0.5, 0},     {-0.0, 0},    {0, 0},
        {0.49, 0},   {0.5, 1},    {1.5, 2},      {2.5, 3},     {110.5, 111},
        {127.4999, 127}, {127.5, 128}, {254.5, 255}, {254.49, 254},
        {255, 255},  {255.4, 255}, {255.5, 255}, {300, 255},   {1e300, 255},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
        ck_assert_msg(rt_channel_to_byte(cases[i].value) == cases[i].byte,
                      "rt_channel_to_byte(%.17g) = %d, expected %d",
                      cases[i].value, rt_channel_to_byte(cases[i].value),
                      cases[i].byte);
    ck_assert_int_eq(rt_channel_to_byte(NAN), 0);
    ck_assert_int_eq(rt_channel_to_byte(-NAN), 0);
    ck_assert_int_eq(rt_channel_to_byte(INFINITY), 255);
    ck_assert_int_eq(rt_channel_to_byte(-INFINITY), 0);
}
END_TEST

/* Expected pixels of a render of one facet in the plane z = 0 seen from
 * O = (0, 0, 5) through the screen z = 4, AB = (1, 0, 0), computed here
 * from docs/rendering-model.md (k = 0, nothing casts a shadow). */
static void check_rendered_pixels(int w, int h, rt_vec3 light,
                                  const double cs[3], const double cf[3])
{
    char text[1024];
    snprintf(text, sizeof text,
             "0 0 5\n0 0 4 1 0 0 %d %d\n3\n-30 -30 0\n30 -30 0\n0 30 0\n1\n"
             "1 2 3 0 %g %g %g\n1 2 3\n%.17g %.17g %.17g %g %g %g\n",
             w, h, cf[0], cf[1], cf[2], light.x, light.y, light.z, cs[0],
             cs[1], cs[2]);
    rt_scene *scene = rt_test_scene_from_string(text);
    rt_image image = rt_test_render(scene, RT_DEFAULT_DEPTH, 1);
    int near_half = 0;
    for (int j = 0; j < h; j++)
        for (int i = 0; i < w; i++) {
            double s = 2.0 * (i + 0.5) / w - 1.0;
            double t = (1.0 - 2.0 * (j + 0.5) / h) * ((double)h / w);
            /* P = (s, t, 4); the ray O + u (P - O) meets z = 0 at u = 5 */
            double hx = 5 * s, hy = 5 * t;
            double sx = light.x - hx, sy = light.y - hy, sz = light.z;
            double n_dot_s = sz / sqrt(sx * sx + sy * sy + sz * sz);
            if (n_dot_s < 0)
                n_dot_s = 0;
            const unsigned char *p = rt_image_pixel(&image, i, j);
            for (int c = 0; c < 3; c++) {
                double value = n_dot_s * cs[c] * cf[c] / 255;
                int expected = (int)floor(value + 0.5);
                int got = p[c];
                /* exact, except within 1e-9 of a half, where either
                 * neighbour is accepted */
                int ok = got == expected ||
                         (fabs(value - floor(value) - 0.5) < 1e-9 &&
                          abs(got - expected) <= 1);
                ck_assert_msg(ok,
                              "%dx%d pixel (%d,%d) channel %d = %d, expected "
                              "%d (real %.12g)",
                              w, h, i, j, c, got, expected, value);
                near_half += fabs(value - floor(value) - 0.5) < 1e-9;
            }
        }
    if (near_half)
        printf("note: %d channels within 1e-9 of a half\n", near_half);
    rt_image_release(&image);
    rt_scene_destroy(scene);
}

START_TEST(rendered_pixels_match_the_formula_square_image)
{
    const double cs[3] = {255, 200, 100}, cf[3] = {180, 90, 240};
    check_rendered_pixels(3, 3, (rt_vec3){2, -1, 3}, cs, cf);
    check_rendered_pixels(9, 9, (rt_vec3){-4, 7, 1.5}, cs, cf);
}
END_TEST

START_TEST(rendered_pixels_match_the_formula_wide_and_tall_images)
{
    const double cs[3] = {250, 255, 30}, cf[3] = {255, 17, 99};
    check_rendered_pixels(8, 3, (rt_vec3){2, -1, 3}, cs, cf);
    check_rendered_pixels(3, 7, (rt_vec3){0.5, 0.5, 2}, cs, cf);
}
END_TEST

START_TEST(rendered_pixel_is_trace_of_camera_ray_rounded_once)
{
    /* the render writes exactly rt_channel_to_byte(rt_trace(primary ray)) */
    const double blocker[10] = {-1, -1, 2, 1, -1, 2, 0, 1, 2, 0.5};
    rt_scene *scene = diffuse_scene(1, 3, 1, 6, blocker, 0);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    rt_image image = rt_test_render(scene, RT_DEFAULT_DEPTH, 1);
    for (int j = 0; j < info.height; j++)
        for (int i = 0; i < info.width; i++) {
            rt_color c = rt_trace(scene, rt_camera_ray(&info.camera, i, j),
                                  RT_DEFAULT_DEPTH);
            const unsigned char *p = rt_image_pixel(&image, i, j);
            ck_assert_msg(p[0] == rt_channel_to_byte(c.r) &&
                              p[1] == rt_channel_to_byte(c.g) &&
                              p[2] == rt_channel_to_byte(c.b),
                          "pixel (%d,%d) = %d %d %d, trace gives %.9g %.9g "
                          "%.9g",
                          i, j, p[0], p[1], p[2], c.r, c.g, c.b);
        }
    rt_image_release(&image);
    rt_scene_destroy(scene);
}
END_TEST

Suite *shade_suite(void);

Suite *shade_suite(void)
{
    Suite *suite = suite_create("shade");
    TCase *tc = tcase_create("diffuse");
    tcase_add_test(tc,
                   light_straight_above_gives_full_diffuse_light_times_facet_colour);
    tcase_add_test(tc, diffuse_term_scales_with_cosine_of_light_angle);
    tcase_add_test(tc, grazing_light_still_lights_without_self_shadowing);
    tcase_add_test(tc, light_behind_the_facet_gives_black);
    tcase_add_test(tc,
                   facet_seen_from_its_back_is_lit_when_light_is_on_viewer_side);
    tcase_add_test(tc, facet_between_hit_point_and_light_casts_a_shadow);
    tcase_add_test(tc, facet_beyond_the_light_casts_no_shadow);
    tcase_add_test(tc, ray_that_hits_nothing_returns_the_background);
    tcase_add_test(tc, shading_does_not_depend_on_the_scale_of_coordinates);
    tcase_add_test(tc, shading_far_from_the_origin_has_no_self_shadowing);
    suite_add_tcase(suite, tc);

    TCase *pixels = tcase_create("pixels");
    tcase_add_test(pixels, channel_to_byte_clamps_and_rounds_halves_away_from_zero);
    tcase_add_test(pixels, rendered_pixels_match_the_formula_square_image);
    tcase_add_test(pixels, rendered_pixels_match_the_formula_wide_and_tall_images);
    tcase_add_test(pixels, rendered_pixel_is_trace_of_camera_ray_rounded_once);
    suite_add_tcase(suite, pixels);
    return suite;
}

RT_CHECK_MAIN(shade_suite)
