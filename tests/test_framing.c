/*
 * test_framing.c - the one framing of a view (src/formats/framing.h): an
 * eye, a point looked at, up and a horizontal field of view become the
 * camera points O, A, B, with answers worked out by hand; the refusals as
 * codes; and the three users frame through it bit for bit: the loader's
 * --look-from/--look-at/--up/--fov, NFF's `v` (its angle spanning the
 * columns' centres) and the OBJ reader's automatic camera.
 */
#include <math.h>
#include <string.h>

#include "formats/framing.h"
#include "scene/scene_internal.h"
#include "testutil.h"

static void assert_vec_eq(rt_vec3 a, rt_vec3 b, double tolerance)
{
    ck_assert_double_eq_tol(a.x, b.x, tolerance);
    ck_assert_double_eq_tol(a.y, b.y, tolerance);
    ck_assert_double_eq_tol(a.z, b.z, tolerance);
}

/* The same bits, component by component. */
static void assert_vec_same(rt_vec3 a, rt_vec3 b)
{
    ck_assert_msg(memcmp(&a, &b, sizeof a) == 0,
                  "(%.17g, %.17g, %.17g) != (%.17g, %.17g, %.17g)", a.x, a.y,
                  a.z, b.x, b.y, b.z);
}

START_TEST(framing_puts_the_screen_edge_at_the_half_width_of_the_angle)
{
    /* Looking down -z from 10 away with up +y and 90 degrees: the right
     * edge of the screen is 10 tan(45) = 10 along +x. */
    rt_view view = {{0, 0, 10}, {0, 0, 0}, {0, 1, 0}, 90.0, 64, 0};
    rt_vec3 o, a, b;
    ck_assert_int_eq(rt__frame_view(&view, &o, &a, &b), RT_FRAME_OK);
    assert_vec_same(o, view.from);
    assert_vec_same(a, view.at);
    assert_vec_eq(b, (rt_vec3){10, 0, 0}, 1e-12);
    /* 60 degrees from (3, 0, 0) towards (3, 4, 0), up +z: right is
     * look x up = +x, at |AO| tan(30) = 4 / sqrt(3). */
    rt_view side = {{3, 0, 0}, {3, 4, 0}, {0, 0, 1}, 60.0, 8, 0};
    ck_assert_int_eq(rt__frame_view(&side, &o, &a, &b), RT_FRAME_OK);
    assert_vec_eq(b, (rt_vec3){3 + 4 / sqrt(3.0), 4, 0}, 1e-12);
    ck_assert_double_eq_tol(rt__frame_tan_half(90.0), 1.0, 1e-15);
}
END_TEST

START_TEST(an_angle_over_the_columns_centres_widens_the_screen_by_a_column)
{
    /* With w = 4 columns the centres of the first and last are 3/4 of the
     * screen's width apart: the half width is |AO| tan(angle / 2) / (3/4). */
    rt_view view = {{0, 0, 10}, {0, 0, 0}, {0, 1, 0}, 90.0, 4, 1};
    rt_vec3 o, a, b;
    ck_assert_int_eq(rt__frame_view(&view, &o, &a, &b), RT_FRAME_OK);
    assert_vec_eq(b, (rt_vec3){40.0 / 3.0, 0, 0}, 1e-12);
    /* one column: no centres to span, the edges instead */
    view.width = 1;
    ck_assert_int_eq(rt__frame_view(&view, &o, &a, &b), RT_FRAME_OK);
    assert_vec_eq(b, (rt_vec3){10, 0, 0}, 1e-12);
}
END_TEST

START_TEST(framing_says_what_keeps_a_view_from_being_framed)
{
    rt_vec3 o = {7, 7, 7}, a = o, b = o;
    rt_view view = {{0, 0, 10}, {0, 0, 0}, {0, 1, 0}, 0.0, 8, 0};
    ck_assert_int_eq(rt__frame_view(&view, &o, &a, &b), RT_FRAME_FOV);
    view.fov = 180.0;
    ck_assert_int_eq(rt__frame_view(&view, &o, &a, &b), RT_FRAME_FOV);
    view.fov = NAN;
    ck_assert_int_eq(rt__frame_view(&view, &o, &a, &b), RT_FRAME_FOV);
    view.fov = 45.0;
    view.at = view.from;
    ck_assert_int_eq(rt__frame_view(&view, &o, &a, &b),
                     RT_FRAME_SAME_POINT);
    /* too far apart for their distance to be a double */
    view.from = (rt_vec3){-1.5e308, 0, 0};
    view.at = (rt_vec3){1.5e308, 0, 0};
    ck_assert_int_eq(rt__frame_view(&view, &o, &a, &b),
                     RT_FRAME_SAME_POINT);
    view.from = (rt_vec3){0, 0, 10};
    view.at = (rt_vec3){0, 0, 0};
    view.up = (rt_vec3){0, 0, -3};
    ck_assert_int_eq(rt__frame_view(&view, &o, &a, &b),
                     RT_FRAME_UP_ALONG_VIEW);
    /* nothing is set on a refusal */
    assert_vec_same(o, (rt_vec3){7, 7, 7});
    assert_vec_same(b, (rt_vec3){7, 7, 7});
}
END_TEST

/* The camera a framed view gives a w x h image. */
static rt_camera framed_camera(const rt_view *view, int width, int height)
{
    rt_vec3 o, a, b;
    ck_assert_int_eq(rt__frame_view(view, &o, &a, &b), RT_FRAME_OK);
    rt_camera camera;
    ck_assert_ptr_null(
        rt__camera_make(o, a, b, width, height, &camera, NULL));
    return camera;
}

static void assert_same_camera(const rt_camera *a, const rt_camera *b)
{
    assert_vec_same(a->observer, b->observer);
    assert_vec_same(a->screen_center, b->screen_center);
    assert_vec_same(a->right, b->right);
    assert_vec_same(a->up, b->up);
}

static rt_camera loaded_camera(const char *text, const char *name,
                               const rt_load_options *options)
{
    rt_scene *scene;
    rt_error error;
    ck_assert_msg(rt_scene_parse(text, strlen(text), name, options, &scene,
                                 &error) == RT_OK,
                  "%s", error.message);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    rt_scene_destroy(scene);
    return info.camera;
}

START_TEST(the_look_options_frame_the_view_through_the_framing)
{
    static const char scene[] = "0 0 10\n0 0 5 4 0 5 16 12\n0\n0\n0 0 0\n"
                                "0 0 10 255 255 255\n";
    rt_load_options options;
    rt_load_options_init(&options);
    options.look_from_given = options.look_at_given = 1;
    options.up_given = options.fov_given = 1;
    options.look_from = (rt_vec3){1.25, -2.5, 7};
    options.look_at = (rt_vec3){0.5, 0.25, -1};
    options.up = (rt_vec3){0, 0.6, 0.8};
    options.fov = 37.5;
    rt_camera loaded = loaded_camera(scene, "view.scn", &options);
    rt_view view = {options.look_from, options.look_at, options.up,
                    options.fov, 16, 0};
    rt_camera framed = framed_camera(&view, 16, 12);
    assert_same_camera(&loaded, &framed);
}
END_TEST

START_TEST(nff_frames_its_viewpoint_through_the_framing)
{
    static const char scene[] =
        "v\nfrom 1.5 -7 2.25\nat 0.125 0.5 -0.75\nup 0.1 0.2 1\n"
        "angle 41.5\nhither 1\nresolution 40 30\nl 0 0 10\n"
        "f 1 1 1 1 0 0 0 1\np 3\n0 0 0\n1 0 0\n0 1 0\n";
    rt_load_options options;
    rt_load_options_init(&options);
    rt_camera loaded = loaded_camera(scene, "view.nff", &options);
    rt_view view = {{1.5, -7, 2.25}, {0.125, 0.5, -0.75}, {0.1, 0.2, 1},
                    41.5, 40, 1};
    rt_camera framed = framed_camera(&view, 40, 30);
    assert_same_camera(&loaded, &framed);
}
END_TEST

START_TEST(the_automatic_camera_of_an_obj_spans_forty_degrees)
{
    static const char model[] = "v 0 0 0\nv 2 0 0\nv 0 3 1\nf 1 2 3\n";
    rt_load_options options;
    rt_load_options_init(&options);
    options.width = 64;
    options.height = 48;
    rt_camera c = loaded_camera(model, "model.obj", &options);
    /* B = A + |AO| tan(20 degrees) unit(look x +y): |AB| / |AO| is the
     * framing's half width, and AB is level (no y). */
    rt_vec3 ao = {c.observer.x - c.screen_center.x,
                  c.observer.y - c.screen_center.y,
                  c.observer.z - c.screen_center.z};
    double distance = sqrt(ao.x * ao.x + ao.y * ao.y + ao.z * ao.z);
    double half = sqrt(c.right.x * c.right.x + c.right.y * c.right.y +
                       c.right.z * c.right.z);
    ck_assert_double_eq_tol(half / distance, rt__frame_tan_half(40.0),
                            1e-14);
    ck_assert_double_eq_tol(c.right.y, 0.0, 1e-12 * half);
}
END_TEST

static Suite *framing_suite(void)
{
    Suite *s = suite_create("framing");
    TCase *tc = tcase_create("framing");
    tcase_add_test(tc,
                   framing_puts_the_screen_edge_at_the_half_width_of_the_angle);
    tcase_add_test(
        tc, an_angle_over_the_columns_centres_widens_the_screen_by_a_column);
    tcase_add_test(tc, framing_says_what_keeps_a_view_from_being_framed);
    tcase_add_test(tc, the_look_options_frame_the_view_through_the_framing);
    tcase_add_test(tc, nff_frames_its_viewpoint_through_the_framing);
    tcase_add_test(tc, the_automatic_camera_of_an_obj_spans_forty_degrees);
    suite_add_tcase(s, tc);
    return s;
}

RT_CHECK_MAIN(framing_suite)
