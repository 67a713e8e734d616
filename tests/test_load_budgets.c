/*
 * test_load_budgets.c - what a small hostile NFF or .scn file may cost
 * (docs/robustness-input.md, "Budgets of a load"): spheres and cones cut
 * by how large they look from the eye (the coarsest below a pixel or
 * behind the eye, the image's pixels at most around it), the budget of
 * facets per byte of file, radii too small for their centre, zero-area
 * facets left out of curved surfaces, the limit on lights, NFF's Ks + T
 * near DBL_MAX, and the cancellation flag of a load.  Every input is
 * generated here and small; what is checked is bytes in against facets,
 * warnings and memory out, never time.  Expected counts are worked out by
 * hand from the rules of docs/formats.md ("Tessellation").
 */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "formats/tessellate.h"
#include "testutil.h"
#include "raytrace/raytrace.h"
#include "scene/scene_internal.h"

#define PI 3.14159265358979323846

/* The eye at (0, -10, 0) looking along +y, 45 degrees, 100 x 100. */
#define VIEW                                                                 \
    "v\nfrom 0 -10 0\nat 0 0 0\nup 0 0 1\nangle 45\nhither 1\n"              \
    "resolution 100 100\nl 0 -10 10\nf 1 1 1 1 0 0 0 0\n"

static rt_status parse_as(rt_scene_format format, const char *text,
                          size_t length, double tolerance, rt_cancel *cancel,
                          rt_scene **scene, rt_error *error)
{
    rt_load_options options;
    rt_load_options_init(&options);
    options.format = format;
    options.tessellation = tolerance;
    options.cancel = cancel;
    memset(error, 0, sizeof *error);
    return rt_scene_parse(text, length,
                          format == RT_SCENE_FORMAT_NFF ? "t.nff" : "t.scn",
                          &options, scene, error);
}

static rt_scene *load_nff(const char *text)
{
    rt_scene *scene;
    rt_error error;
    rt_status status = parse_as(RT_SCENE_FORMAT_NFF, text, strlen(text), 0,
                                NULL, &scene, &error);
    ck_assert_msg(status == RT_OK, "%s", error.message);
    return scene;
}

static int facets_of(const char *text)
{
    rt_scene *scene = load_nff(text);
    int n = rt_test_scene_info(scene).facet_count;
    rt_scene_destroy(scene);
    return n;
}

/* ------------------------------------------------------------------ */
/* How finely a primitive is cut                                        */

START_TEST(a_sphere_smaller_than_a_pixel_gets_the_coarsest_cut)
{
    /* 100 pixels over 2 tan(22.5) at depth 10 - r: 120.7 r / (10 - r)
     * pixels of radius.  r = 0.004: 0.048 px, under half a pixel: the
     * octahedron (8 facets).  r = 0.05: 0.61 px, a diameter over a pixel:
     * the largest default tolerance, 0.05, 168 facets (docs/formats.md). */
    ck_assert_int_eq(facets_of(VIEW "s 0 0 0 0.004\n"), 8);
    ck_assert_int_eq(facets_of(VIEW "s 0 0 0 0.05\n"), 168);
    /* A cone below a pixel: three segments (2 facets each, open). */
    ck_assert_int_eq(facets_of(VIEW "c 0 0 0 0.004 0 0 0.01 0.004\n"), 6);
}
END_TEST

START_TEST(a_primitive_behind_the_eye_gets_the_coarsest_cut)
{
    /* The eye plane is y = -10: everything below it is behind. */
    ck_assert_int_eq(facets_of(VIEW "s 0 -20 0 5\n"), 8);
    ck_assert_int_eq(facets_of(VIEW "c 0 -30 0 2 0 -20 0 2\n"), 6);
    ck_assert_int_eq(facets_of(VIEW "c 0 -30 0 2 0 -20 0 0\n"), 3);
    /* A sphere touching the eye plane from behind is behind too; one that
     * reaches past it is not (it is cut for what it covers). */
    ck_assert_int_eq(facets_of(VIEW "s 0 -11 0 1\n"), 8);
    ck_assert_int_gt(facets_of(VIEW "s 0 -11 0 1.5\n"), 8);
}
END_TEST

/* The facets of a sphere cut by the default tolerance for a radius of rho
 * pixels (docs/formats.md), capped at `most` facets. */
static int expected_sphere_facets(double rho, double most)
{
    double tol = 0.25 / rho;
    double across = 1 - cos(5 / (sqrt(2.0) * rho));
    if (across < tol)
        tol = across;
    tol = tol < 5e-5 ? 5e-5 : tol > 0.05 ? 0.05 : tol;
    int bands = rt__tess_sphere_bands(tol);
    while (4.0 * bands * (bands - 1) > most)
        bands--;
    return 4 * bands * (bands - 1);
}

START_TEST(a_sphere_around_the_eye_has_at_most_the_image_s_pixels_in_facets)
{
    /* Centred on the eye, radius 3, 64 x 64 at 45 degrees: seen from its
     * farthest point (3 away) its radius is the focal length, 32 /
     * tan(22.5) = 77.3 pixels, which asks for 4 800 facets; the image has
     * 4 096 pixels, so 32 bands (3 968 facets). */
    const char *around = "v from 0 0 0 at 0 1 0 up 0 0 1 angle 45 hither 1 "
                         "resolution 64 64\nl 0 0 0\ns 0 0 0 3\n";
    double focal = 32 / tan(PI / 8);
    int expected = expected_sphere_facets(focal, 64 * 64);
    ck_assert_int_eq(expected, 3968);
    ck_assert_int_eq(facets_of(around), expected);
    /* 16 x 16: at most 256 facets (8 bands, 224). */
    ck_assert_int_eq(
        facets_of("v from 0 0 0 at 0 1 0 up 0 0 1 angle 45 hither 1 "
                  "resolution 16 16\nl 0 0 0\ns 0 0 0 3\n"),
        224);
    /* Off-centre around the eye: the farthest point is 3 + 2 away. */
    ck_assert_int_eq(
        facets_of("v from 0 0 0 at 0 1 0 up 0 0 1 angle 45 hither 1 "
                  "resolution 64 64\nl 0 0 0\ns 0 2 0 3\n"),
        expected_sphere_facets(focal * 3 / 5, 64 * 64));
}
END_TEST

START_TEST(the_issue_s_hostile_views_cost_what_the_file_weighs)
{
    /* 40 spheres behind the eye and 40 sub-pixel ones, at 16384 x 16384
     * (each once got the finest cut, 198 024 facets, and a warning per
     * zero-area facet): now 8 facets each, a few hundred bytes of file. */
    rt_test_text t = {0};
    rt_test_text_add(&t, "v from 0 0 0 at 0 0 1 up 0 1 0 angle 45 hither 1 "
                      "resolution 16384 16384\nl 0 0 0\n");
    for (int i = 0; i < 40; i++)
        rt_test_text_add(&t, "s 0 0 -%d 1\ns %d 0 1e9 1\n", 10 + i, i);
    rt_scene *scene = load_nff(t.data);
    rt_scene_info info = rt_test_scene_info(scene);
    ck_assert_int_eq(info.facet_count, 80 * 8);
    ck_assert_int_eq(info.live_facet_count, info.facet_count);
    ck_assert_int_le(info.warning_count, 4);
    /* The scene's own records: under 200 bytes a byte of file. */
    ck_assert_uint_lt(rt__scene_bytes(scene), 200 * t.length);
    rt_scene_destroy(scene);
    free(t.data);
}
END_TEST

/* ------------------------------------------------------------------ */
/* The budget of facets and the refusals                                */

START_TEST(the_facet_budget_grows_with_the_file_and_stops_at_the_limit)
{
    ck_assert_double_eq(rt__tess_budget(0), 1 << 20);
    ck_assert_double_eq(rt__tess_budget(1000), (1 << 20) + 32 * 1000);
    ck_assert_double_eq(rt__tess_budget((size_t)1 << 30), 1 << 24);
}
END_TEST

START_TEST(a_file_past_its_facet_budget_is_refused_naming_the_primitive)
{
    /* --tessellate 3e-6 asks some 1.6 million facets of one sphere, more
     * than the 1 048 576 + 32 x 92 a file of 92 bytes may have: refused at
     * the sphere, before anything is cut. */
    const char *text = VIEW "s 0 0 0 1\n";
    rt_scene *scene = (rt_scene *)1;
    rt_error error;
    rt_status status = parse_as(RT_SCENE_FORMAT_NFF, text, strlen(text),
                                3e-6, NULL, &scene, &error);
    ck_assert_int_eq(status, RT_ERR_LIMIT);
    ck_assert_ptr_null(scene);
    ck_assert_int_eq(error.line, 10);
    ck_assert_int_eq(error.column, 1);
    char expected[160];
    snprintf(expected, sizeof expected,
             "t.nff:10:1: expected at most %d facets in all for a file of "
             "%zu bytes", (1 << 20) + 32 * (int)strlen(text), strlen(text));
    ck_assert_msg(strncmp(error.message, expected, strlen(expected)) == 0,
                  "%s", error.message);
    ck_assert_ptr_nonnull(strstr(error.message, "this sphere brings them"));
    ck_assert_ptr_nonnull(strstr(error.message, "--tessellate"));
    ck_assert_ptr_nonnull(strstr(error.message, "now 3e-06 for this sphere"));
    /* A larger tolerance fits (1e-3: 9 800 facets). */
    status = parse_as(RT_SCENE_FORMAT_NFF, text, strlen(text), 1e-3, NULL,
                      &scene, &error);
    ck_assert_msg(status == RT_OK, "%s", error.message);
    ck_assert_int_eq(rt_test_scene_info(scene).facet_count, 9800);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(a_radius_below_the_spacing_of_its_centre_is_refused)
{
    /* Doubles near 1e6 are 2^-33 = 1.16e-10 apart. */
    static const struct {
        const char *text;
        int column;
    } cases[] = {
        {VIEW "s 1e6 0 0 1e-20\n", 11},
        {VIEW "s 1e6 0 0 -1e-11\n", 11},
        {VIEW "c 1e6 0 0 1e-11 1e6 0 1 1\n", 11},
        {VIEW "c 0 0 0 1 1e6 0 1 1e-11\n", 19},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        rt_scene *scene = (rt_scene *)1;
        rt_error error;
        rt_status status = parse_as(RT_SCENE_FORMAT_NFF, cases[i].text,
                                    strlen(cases[i].text), 0, NULL, &scene,
                                    &error);
        ck_assert_msg(status == RT_ERR_RANGE, "case %zu: %s", i,
                      error.message);
        ck_assert_ptr_null(scene);
        ck_assert_int_eq(error.line, 10);
        ck_assert_int_eq(error.column, cases[i].column);
        ck_assert_msg(strstr(error.message, "expected a radius of at least "
                                            "1.16415e-10, the spacing of "
                                            "doubles at its centre") != NULL,
                      "case %zu: %s", i, error.message);
    }
    /* At the origin doubles are dense: a radius of 1e-30 is a sphere (and
     * below a pixel: the coarsest). */
    ck_assert_int_eq(facets_of(VIEW "s 0 0 0 1e-30\n"), 8);
}
END_TEST

START_TEST(zero_area_facets_are_left_out_of_a_sphere_with_one_warning)
{
    /* Radius 5e-10 at 1e6, where doubles are 1.16e-10 apart, seen from
     * 2e-9 away at 256 pixels: its cut is fine, its vertices round onto a
     * coarse grid, and some facets lose their area. */
    const char *text = "v from 1e6 0 -2e-9 at 1e6 0 0 up 0 1 0 angle 45 "
                       "hither 1 resolution 256 256\nl 1e6 0 -1\n"
                       "s 1e6 0 0 5e-10\n";
    rt_scene *scene = load_nff(text);
    rt_scene_info info = rt_test_scene_info(scene);
    ck_assert_int_gt(info.facet_count, 0);
    ck_assert_int_eq(info.live_facet_count, info.facet_count);
    ck_assert_int_eq(rt_test_count_warnings(scene,
                                            "facets of zero area left out"),
                     1);
    int dropped = 0;
    for (int i = 0; i < info.warning_count; i++) {
        const char *m = rt_scene_warning(scene, i)->message;
        const char *at = strstr(m, "warning: ");
        if (at != NULL && strstr(m, "left out") != NULL)
            dropped = atoi(at + strlen("warning: "));
    }
    ck_assert_int_gt(dropped, 0);
    /* Kept and dropped make the whole cut: a radius of 128 / tan(22.5)
     * x 5e-10 / 1.5e-9 = 103 pixels at its nearest depth. */
    double rho = 128 / tan(PI / 8) * 5e-10 / 1.5e-9;
    ck_assert_int_eq(info.facet_count + dropped,
                     expected_sphere_facets(rho, 1e300));
    /* Besides those, only the facets the rounding puts in the plane
     * x = 1e6, which holds the eye, are named (edge-on: never seen). */
    ck_assert_int_le(info.warning_count -
                         rt_test_count_warnings(scene, "plane through the eye"),
                     3);
    rt_scene_destroy(scene);
}
END_TEST

/* ------------------------------------------------------------------ */
/* Lights                                                               */

/* Loads a file of `count` lights in `format` (NFF: the lights from line
 * 2; .scn: from line 10); checks the count of a scene that loads. */
static rt_status with_lights(rt_scene_format format, int count,
                             rt_error *error)
{
    int nff = format == RT_SCENE_FORMAT_NFF;
    rt_test_text t = {0};
    rt_test_text_add(&t, "%s",
                     nff ? "v from 0 -10 0 at 0 0 0 up 0 0 1 angle 45 hither 1 "
                        "resolution 8 8\n"
                      : "0 0 10\n0 0 5 4 0 5 8 8\n3\n0 0 0\n1 0 0\n0 1 0\n"
                        "1\n1 2 3 0 255 255 255\n0 0 0\n");
    for (int i = 0; i < count; i++)
        rt_test_text_add(&t, nff ? "l %d 0 0\n" : "%d 0 4 255 255 255\n", i);
    if (nff)
        rt_test_text_add(&t, "s 0 0 0 1\n");
    rt_scene *scene = NULL;
    rt_status status = parse_as(format, t.data, t.length, 0, NULL, &scene,
                                error);
    if (status == RT_OK)
        ck_assert_int_eq(rt_test_scene_info(scene).light_count, count);
    rt_scene_destroy(scene);
    free(t.data);
    return status;
}

START_TEST(lights_past_the_limit_are_refused_at_the_first_one_past)
{
    rt_error error;
    ck_assert_int_eq(RT_MAX_LIGHTS, 64);
    ck_assert_int_eq(with_lights(RT_SCENE_FORMAT_NFF, 64, &error), RT_OK);
    ck_assert_int_eq(with_lights(RT_SCENE_FORMAT_NFF, 65, &error), RT_ERR_LIMIT);
    /* the 65th `l` is on line 66 */
    ck_assert_int_eq(error.line, 66);
    ck_assert_int_eq(error.column, 1);
    ck_assert_str_eq(error.message,
                     "t.nff:66:1: expected at most 64 lights (each one costs "
                     "every hit a shadow ray), found light 65");
    ck_assert_int_eq(with_lights(RT_SCENE_FORMAT_SCN, 64, &error), RT_OK);
    ck_assert_int_eq(with_lights(RT_SCENE_FORMAT_SCN, 65, &error), RT_ERR_LIMIT);
    /* the first light is on line 10, the 65th on line 74 */
    ck_assert_int_eq(error.line, 74);
    ck_assert_str_eq(error.message,
                     "t.scn:74:1: expected at most 64 lights (each one costs "
                     "every hit a shadow ray), found light 65");
}
END_TEST

START_TEST(the_builder_refuses_more_lights_than_the_limit)
{
    static const rt_vec3 vertices[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    static const rt_facet_desc facet = {{0, 1, 2}, 0, {255, 255, 255},
                                        0, 0, 0, 0};
    rt_light lights[RT_MAX_LIGHTS + 1];
    lights[0] = (rt_light){{0, 0, 4}, {255, 255, 255}};
    for (int i = 0; i < RT_MAX_LIGHTS; i++)
        lights[1 + i] = (rt_light){{i, 0, 4}, {10, 10, 10}};
    rt_scene_desc d;
    memset(&d, 0, sizeof d);
    d.observer = (rt_vec3){0, 0, 10};
    d.screen_center = (rt_vec3){0, 0, 5};
    d.screen_right = (rt_vec3){4, 0, 5};
    d.width = d.height = 8;
    d.vertices = vertices;
    d.vertex_count = 3;
    d.facets = &facet;
    d.facet_count = 1;
    d.lights = lights;
    d.light_count = RT_MAX_LIGHTS;
    rt_scene *scene;
    rt_error error;
    ck_assert_int_eq(rt_scene_create(&d, &scene, &error), RT_OK);
    rt_scene_destroy(scene);
    d.light_count = RT_MAX_LIGHTS + 1;
    ck_assert_int_eq(rt_scene_create(&d, &scene, &error), RT_ERR_LIMIT);
    ck_assert_ptr_null(scene);
    ck_assert_str_eq(error.message, "expected at most 64 lights (each one "
                                    "costs every hit a shadow ray), found 65");
}
END_TEST

/* ------------------------------------------------------------------ */
/* NFF's Ks + T                                                         */

START_TEST(ks_and_t_near_the_largest_double_keep_half_mirror_half_glass)
{
    /* Ks + T overflows to infinity; both scaled by the finite sum of their
     * halves: k = t = 1/2 exactly. */
    rt_scene *scene = load_nff("v from 0 -10 0 at 0 0 0 up 0 0 1 angle 45 "
                               "hither 1 resolution 8 8\n"
                               "f 1 1 1 1 1e308 0 1e308 1.5\ns 0 0 0 1\n");
    rt_facet_info f = {.size = sizeof f};
    rt_scene_facet(scene, 0, &f);
    ck_assert_double_eq(f.reflection, 0.5);
    ck_assert_double_eq(f.transparency, 0.5);
    ck_assert_double_eq(f.refractive_index, 1.5);
    ck_assert_int_eq(rt_test_scene_info(scene).transparent_facet_count,
                     rt_test_scene_info(scene).live_facet_count);
    ck_assert_int_eq(rt_test_count_warnings(scene,
                                            "Ks + T = 1e+308 + 1e+308 is "
                                           "more than 1"),
                     1);
    rt_scene_destroy(scene);
    /* 1.5e308 and 1e308: k = 0.6, t = 0.4 (to the last bit of the
     * division of the halves). */
    scene = load_nff("v from 0 -10 0 at 0 0 0 up 0 0 1 angle 45 hither 1 "
                     "resolution 8 8\nf 1 1 1 1 1.5e308 0 1e308 1.5\n"
                     "s 0 0 0 1\n");
    rt_scene_facet(scene, 0, &f);
    ck_assert_double_eq_tol(f.reflection, 0.6, 1e-15);
    ck_assert_double_eq_tol(f.transparency, 0.4, 1e-15);
    ck_assert(f.reflection + f.transparency <= 1.0);
    rt_scene_destroy(scene);
}
END_TEST

/* ------------------------------------------------------------------ */
/* Cancellation                                                         */

START_TEST(a_raised_flag_cancels_a_load_in_every_reader)
{
    rt_cancel *cancel;
    ck_assert_int_eq(rt_cancel_create(&cancel, NULL), RT_OK);
    rt_cancel_request(cancel);
    static const char nff[] = VIEW "s 0 0 0 1\n";
    static const char scn[] = "0 0 10\n0 0 5 4 0 5 8 8\n0\n0\n0 0 0\n"
                              "0 0 4 255 255 255\n";
    rt_scene *scene = (rt_scene *)1;
    rt_error error;
    ck_assert_int_eq(parse_as(RT_SCENE_FORMAT_NFF, nff, strlen(nff), 0,
                              cancel, &scene, &error),
                     RT_ERR_CANCELLED);
    ck_assert_ptr_null(scene);
    ck_assert_str_eq(error.message, "t.nff: the load was cancelled");
    ck_assert_int_eq(parse_as(RT_SCENE_FORMAT_SCN, scn, strlen(scn), 0,
                              cancel, &scene, &error),
                     RT_ERR_CANCELLED);
    ck_assert_ptr_null(scene);
    ck_assert_str_eq(error.message, "t.scn: the load was cancelled");
    /* The same flag lowered: both load. */
    rt_cancel_reset(cancel);
    ck_assert_int_eq(parse_as(RT_SCENE_FORMAT_NFF, nff, strlen(nff), 0,
                              cancel, &scene, &error),
                     RT_OK);
    rt_scene_destroy(scene);
    ck_assert_int_eq(parse_as(RT_SCENE_FORMAT_SCN, scn, strlen(scn), 0,
                              cancel, &scene, &error),
                     RT_OK);
    rt_scene_destroy(scene);
    rt_cancel_destroy(cancel);
}
END_TEST

START_TEST(a_raised_flag_stops_a_surface_while_it_is_cut)
{
    rt_cancel *cancel;
    ck_assert_int_eq(rt_cancel_create(&cancel, NULL), RT_OK);
    rt_facet_desc facet;
    memset(&facet, 0, sizeof facet);
    rt_tess_mesh mesh;
    memset(&mesh, 0, sizeof mesh);
    mesh.cancel = cancel;
    /* 100 bands: 400 facets a band, 39 600 in all; the flag is read
     * every 4 096 facets or so. */
    ck_assert_int_eq(rt__tess_sphere(&mesh, (rt_vec3){0, 0, 0}, 1, 0, 100,
                                     &facet, 1),
                     0);
    ck_assert_int_eq(mesh.facet_count, 39600);
    rt_cancel_request(cancel);
    ck_assert_int_eq(rt__tess_sphere(&mesh, (rt_vec3){0, 0, 0}, 1, 0, 100,
                                     &facet, 1),
                     RT_TESS_CANCELLED);
    ck_assert_int_lt(mesh.facet_count, 2 * 39600);
    ck_assert_int_eq(rt__tess_cone(&mesh, (rt_vec3){0, 0, 0}, 1,
                                   (rt_vec3){0, 0, 1}, 1, 0, 10000, &facet,
                                   1),
                     RT_TESS_CANCELLED);
    rt__tess_mesh_free(&mesh);
    rt_cancel_destroy(cancel);
}
END_TEST

static Suite *load_budgets_suite(void)
{
    Suite *s = suite_create("load_budgets");
    TCase *c = tcase_create("cuts");
    tcase_add_test(c, a_sphere_smaller_than_a_pixel_gets_the_coarsest_cut);
    tcase_add_test(c, a_primitive_behind_the_eye_gets_the_coarsest_cut);
    tcase_add_test(c,
                   a_sphere_around_the_eye_has_at_most_the_image_s_pixels_in_facets);
    tcase_add_test(c, the_issue_s_hostile_views_cost_what_the_file_weighs);
    suite_add_tcase(s, c);
    c = tcase_create("refusals");
    tcase_add_test(c, the_facet_budget_grows_with_the_file_and_stops_at_the_limit);
    tcase_add_test(c, a_file_past_its_facet_budget_is_refused_naming_the_primitive);
    tcase_add_test(c, a_radius_below_the_spacing_of_its_centre_is_refused);
    tcase_add_test(c, zero_area_facets_are_left_out_of_a_sphere_with_one_warning);
    suite_add_tcase(s, c);
    c = tcase_create("lights and materials");
    tcase_add_test(c, lights_past_the_limit_are_refused_at_the_first_one_past);
    tcase_add_test(c, the_builder_refuses_more_lights_than_the_limit);
    tcase_add_test(c, ks_and_t_near_the_largest_double_keep_half_mirror_half_glass);
    suite_add_tcase(s, c);
    c = tcase_create("cancellation");
    tcase_add_test(c, a_raised_flag_cancels_a_load_in_every_reader);
    tcase_add_test(c, a_raised_flag_stops_a_surface_while_it_is_cut);
    suite_add_tcase(s, c);
    return s;
}

RT_CHECK_MAIN(load_budgets_suite)
