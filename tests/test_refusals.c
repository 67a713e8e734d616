/*
 * test_refusals.c - the builder is the one validator of a description and
 * reports what it refuses as data (src/scene/scene_build.h: item, index,
 * field, part, the rule's words), as SQLite's sqlite3_error_offset does;
 * each reader maps the refusal back to the token it kept, so that a value
 * the builder refuses is still named at its line and column.  Checked: the
 * data of every kind of refusal, the order (the first rule a file states
 * is the first refused), the builder's own words for rt_scene_create, and
 * the .scn and NFF readers' mapping, commas and replaced items included.
 */
#include <math.h>
#include <string.h>

#include "scene/scene_build.h"
#include "testutil.h"

/* A valid description: a triangle seen from +z, one light. */
typedef struct world {
    rt_scene_desc d;
    rt_vec3 vertices[3];
    rt_facet_desc facets[2];
    rt_light lights[RT_MAX_LIGHTS + 1];
} world;

static void make_world(world *w)
{
    memset(w, 0, sizeof *w);
    w->vertices[0] = (rt_vec3){-1, -1, 0};
    w->vertices[1] = (rt_vec3){1, -1, 0};
    w->vertices[2] = (rt_vec3){0, 1, 0};
    for (int i = 0; i < 2; i++) {
        w->facets[i].vertex[0] = 0;
        w->facets[i].vertex[1] = 1;
        w->facets[i].vertex[2] = 2;
        w->facets[i].color = (rt_rgb8){200, 0, 0};
    }
    for (int i = 0; i <= RT_MAX_LIGHTS; i++)
        w->lights[i] = (rt_light){{0, 0, 4 + i}, {255, 255, 255}};
    w->d.observer = (rt_vec3){0, 0, 10};
    w->d.screen_center = (rt_vec3){0, 0, 5};
    w->d.screen_right = (rt_vec3){4, 0, 5};
    w->d.width = w->d.height = 8;
    w->d.vertices = w->vertices;
    w->d.vertex_count = 3;
    w->d.facets = w->facets;
    w->d.facet_count = 2;
    w->d.lights = w->lights;
    w->d.light_count = 1;
}

/* Builds w and expects a refusal of `status`; returns it. */
static rt_refusal refused(const world *w, rt_status status, rt_error *error)
{
    rt_refusal r;
    memset(&r, 0x55, sizeof r);
    rt_scene *scene = (rt_scene *)1;
    ck_assert_int_eq(rt__scene_build(&w->d, NULL, NULL, NULL, NULL, &scene,
                                     error, &r),
                     status);
    ck_assert_ptr_null(scene);
    ck_assert_int_eq(r.status, status);
    return r;
}

static void assert_refusal(const rt_refusal *r, rt_item item, int index,
                           rt_field field, int part, const char *expected)
{
    ck_assert_int_eq(r->item, item);
    ck_assert_int_eq(r->index, index);
    ck_assert_int_eq(r->field, field);
    ck_assert_int_eq(r->part, part);
    ck_assert_str_eq(r->expected, expected);
}

START_TEST(the_builder_names_the_facet_and_field_it_refuses)
{
    world w;
    rt_error error;
    make_world(&w);
    w.facets[1].reflection = 1.5;
    rt_refusal r = refused(&w, RT_ERR_RANGE, &error);
    assert_refusal(&r, RT_ITEM_FACET, 1, RT_FIELD_K, 0, RT_RULE_K);
    ck_assert_str_eq(r.found, "");
    ck_assert_str_eq(error.message, "facet 1: expected a reflection "
                                    "coefficient k in [0, 1], found 1.5");
    ck_assert_int_eq(error.line, 0);
    make_world(&w);
    w.facets[0].reflection = 0.5;
    w.facets[0].transparency = 0.6;
    r = refused(&w, RT_ERR_RANGE, &error);
    assert_refusal(&r, RT_ITEM_FACET, 0, RT_FIELD_T, 0, RT_RULE_T);
    w.facets[0].transparency = -0.1;
    r = refused(&w, RT_ERR_RANGE, &error);
    assert_refusal(&r, RT_ITEM_FACET, 0, RT_FIELD_T, 0, RT_RULE_T_SIGN);
    make_world(&w);
    w.facets[1].refractive_index = -1.5;
    r = refused(&w, RT_ERR_RANGE, &error);
    assert_refusal(&r, RT_ITEM_FACET, 1, RT_FIELD_N, 0, RT_RULE_N);
    make_world(&w);
    w.facets[1].diffuse_given = 1;
    w.facets[1].diffuse = -2;
    r = refused(&w, RT_ERR_RANGE, &error);
    assert_refusal(&r, RT_ITEM_FACET, 1, RT_FIELD_D, 0, RT_RULE_D);
    make_world(&w);
    w.facets[1].vertex[2] = 3;
    r = refused(&w, RT_ERR_RANGE, &error);
    ck_assert_int_eq(r.item, RT_ITEM_FACET);
    ck_assert_int_eq(r.field, RT_FIELD_CORNER);
    ck_assert_int_eq(r.part, 2);
}
END_TEST

START_TEST(the_builder_names_the_point_and_coordinate_out_of_range)
{
    world w;
    rt_error error;
    make_world(&w);
    w.d.screen_center.y = -2e152;
    rt_refusal r = refused(&w, RT_ERR_RANGE, &error);
    assert_refusal(&r, RT_ITEM_CAMERA, 0, RT_FIELD_SCREEN_CENTER, 1,
                   RT_RULE_COORDINATE);
    ck_assert_ptr_nonnull(strstr(error.message, "found -2e+152"));
    make_world(&w);
    w.vertices[2].z = 3e152;
    r = refused(&w, RT_ERR_RANGE, &error);
    assert_refusal(&r, RT_ITEM_VERTEX, 2, RT_FIELD_POSITION, 2,
                   RT_RULE_COORDINATE);
    make_world(&w);
    w.vertices[1].x = NAN;
    r = refused(&w, RT_ERR_RANGE, &error);
    assert_refusal(&r, RT_ITEM_VERTEX, 1, RT_FIELD_POSITION, 0,
                   "finite coordinates");
    ck_assert_str_eq(error.message,
                     "expected finite coordinates for every vertex");
}
END_TEST

START_TEST(the_builder_names_the_lens_the_camera_and_the_lights)
{
    world w;
    rt_error error;
    make_world(&w);
    w.d.aperture = -1;
    rt_refusal r = refused(&w, RT_ERR_RANGE, &error);
    assert_refusal(&r, RT_ITEM_LENS, 0, RT_FIELD_APERTURE, 0,
                   RT_RULE_APERTURE);
    make_world(&w);
    w.d.focal_distance = -3;
    r = refused(&w, RT_ERR_RANGE, &error);
    assert_refusal(&r, RT_ITEM_LENS, 0, RT_FIELD_FOCAL_DISTANCE, 0,
                   RT_RULE_FOCAL);
    make_world(&w);
    w.d.observer = w.d.screen_center;
    r = refused(&w, RT_ERR_CAMERA, &error);
    assert_refusal(&r, RT_ITEM_CAMERA, 0, RT_FIELD_SCREEN_CENTER, 0,
                   RT_RULE_CAMERA);
    ck_assert_str_eq(r.found, "that the observer O is the screen centre A");
    ck_assert_str_eq(error.message,
                     "expected a camera that sees something, found that the "
                     "observer O is the screen centre A");
    make_world(&w);
    w.d.screen_right = (rt_vec3){0, 0, 7};
    r = refused(&w, RT_ERR_CAMERA, &error);
    assert_refusal(&r, RT_ITEM_CAMERA, 0, RT_FIELD_SCREEN_RIGHT, 0,
                   RT_RULE_CAMERA);
    make_world(&w);
    w.d.light_count = RT_MAX_LIGHTS + 1;
    r = refused(&w, RT_ERR_LIMIT, &error);
    assert_refusal(&r, RT_ITEM_LIGHT, RT_MAX_LIGHTS, RT_FIELD_NONE, 0,
                   RT_RULE_LIGHTS);
    ck_assert_str_eq(r.found, "light 65");
}
END_TEST

/* The lights are an array of 1..RT_MAX_LIGHTS: none is a value out of
 * range, named as data; a negative count or no array is the caller's
 * mistake (RT_ERR_ARGUMENT, as for the vertices and facets). */
START_TEST(the_builder_refuses_a_scene_without_a_light)
{
    world w;
    rt_error error;
    make_world(&w);
    w.d.light_count = 0;
    rt_refusal r = refused(&w, RT_ERR_RANGE, &error);
    assert_refusal(&r, RT_ITEM_LIGHT, 0, RT_FIELD_NONE, 0, RT_RULE_A_LIGHT);
    ck_assert_str_eq(r.found, "none");
    ck_assert_str_eq(error.message, "expected at least one light, found none");
    rt_scene *scene = (rt_scene *)1;
    ck_assert_int_eq(rt_scene_create(&w.d, &scene, &error), RT_ERR_RANGE);
    ck_assert_ptr_null(scene);
    w.d.light_count = -1;
    r = refused(&w, RT_ERR_ARGUMENT, &error);
    ck_assert_str_eq(error.message, "expected an array of lights");
    make_world(&w);
    w.d.lights = NULL;
    r = refused(&w, RT_ERR_ARGUMENT, &error);
    ck_assert_str_eq(error.message, "expected an array of lights");
}
END_TEST

START_TEST(the_first_rule_a_file_states_is_the_first_refused)
{
    /* the camera's points, the lens, the camera, the vertices, the
     * facets, the lights: the order of a .scn file */
    world w;
    rt_error error;
    make_world(&w);
    w.facets[0].reflection = 2;
    w.vertices[0].x = 2e152;
    w.d.light_count = RT_MAX_LIGHTS + 1;
    rt_refusal r = refused(&w, RT_ERR_RANGE, &error);
    ck_assert_int_eq(r.item, RT_ITEM_VERTEX);
    w.d.observer = w.d.screen_center;
    r = refused(&w, RT_ERR_CAMERA, &error);
    ck_assert_int_eq(r.item, RT_ITEM_CAMERA);
    w.d.aperture = -1;
    r = refused(&w, RT_ERR_RANGE, &error);
    ck_assert_int_eq(r.item, RT_ITEM_LENS);
    w.d.screen_right.x = 5e152;
    r = refused(&w, RT_ERR_RANGE, &error);
    assert_refusal(&r, RT_ITEM_CAMERA, 0, RT_FIELD_SCREEN_RIGHT, 0,
                   RT_RULE_COORDINATE);
    make_world(&w);
    w.facets[1].transparency = 3;
    w.d.light_count = RT_MAX_LIGHTS + 1;
    r = refused(&w, RT_ERR_RANGE, &error);
    ck_assert_int_eq(r.item, RT_ITEM_FACET);
}
END_TEST

START_TEST(a_build_that_refuses_nothing_leaves_no_refusal)
{
    world w;
    make_world(&w);
    rt_refusal r;
    memset(&r, 0x55, sizeof r);
    rt_scene *scene;
    rt_error error;
    ck_assert_int_eq(rt__scene_build(&w.d, "ok.scn", NULL, NULL, NULL,
                                     &scene, &error, &r),
                     RT_OK);
    ck_assert_int_eq(r.status, RT_OK);
    rt_scene_destroy(scene);
    /* a name puts "name: " before the builder's words */
    w.facets[0].reflection = -1;
    ck_assert_int_eq(rt__scene_build(&w.d, "named.scn", NULL, NULL, NULL,
                                     &scene, &error, NULL),
                     RT_ERR_RANGE);
    ck_assert_str_eq(error.message, "named.scn: facet 0: expected a "
                                    "reflection coefficient k in [0, 1], "
                                    "found -1");
}
END_TEST

/* ------------------------------------------------------------ readers */

/* Parses `text` as `name` with `options` (may be NULL): the status, the
 * message in *error. */
static rt_status parse(const char *text, const char *name,
                       const rt_load_options *options, rt_error *error)
{
    rt_scene *scene = NULL;
    memset(error, 0, sizeof *error);
    rt_status status =
        rt_scene_parse(text, strlen(text), name, options, &scene, error);
    rt_scene_destroy(scene);
    return status;
}

static void assert_refused_at(const char *text, const char *name,
                              rt_status status, const char *message)
{
    rt_error error;
    ck_assert_int_eq(parse(text, name, NULL, &error), status);
    ck_assert_str_eq(error.message, message);
}

START_TEST(the_scn_reader_names_the_token_of_each_value_the_builder_refuses)
{
    assert_refused_at("0 0 10\n0 0 5 4 0 5 8 8\n3\n0 0 0\n1 0 0\n"
                      "0 1  -3e152\n0\n0 0 0\n0 0 4 255 255 255\n",
                      "far.scn", RT_ERR_RANGE,
                      "far.scn:6:6: expected " RT_RULE_COORDINATE
                      ", found `-3e152`");
    /* commas are no values: the third value of `4, 0,5e152` */
    assert_refused_at("0 0 10\n4, 0,5e152, 4 0 5 8 8\n0\n0\n0 0 0\n"
                      "0 0 4 255 255 255\n",
                      "comma.scn", RT_ERR_RANGE,
                      "comma.scn:2:6: expected " RT_RULE_COORDINATE
                      ", found `5e152`");
    assert_refused_at("0 0 10\n0 0 5 4 0 5 8 8 0.5 -2\n0\n0\n0 0 0\n"
                      "0 0 4 255 255 255\n",
                      "lens.scn", RT_ERR_RANGE,
                      "lens.scn:2:21: expected a focal distance f > 0, "
                      "found `-2`");
    assert_refused_at("0 0 10\n0 0 5 4 0 5 8 8\n3\n0 0 0\n1 0 0\n0 1 0\n2\n"
                      "1 2 3 0 1 1 1\n1 2 3 0 1 1 1 0.5 -1.5\n0 0 0\n"
                      "0 0 4 255 255 255\n",
                      "glass.scn", RT_ERR_RANGE,
                      "glass.scn:9:19: expected a refractive index n > 0, "
                      "found `-1.5`");
    assert_refused_at("0 0 10\n0 0 5 0 0 5 8 8\n0\n0\n0 0 0\n"
                      "0 0 4 255 255 255\n",
                      "b.scn", RT_ERR_CAMERA,
                      "b.scn:2:7: expected a camera that sees something, "
                      "found that the screen point B is the screen centre "
                      "A");
}
END_TEST

START_TEST(a_value_the_builder_refuses_comes_after_the_files_own_errors)
{
    /* The file is read whole before the builder judges its values: a
     * word in the background is named before the k of the facet above. */
    assert_refused_at("0 0 10\n0 0 5 4 0 5 8 8\n3\n0 0 0\n1 0 0\n0 1 0\n1\n"
                      "1 2 3 7 1 1 1\n0 zero 0\n0 0 4 255 255 255\n",
                      "order.scn", RT_ERR_SYNTAX,
                      "order.scn:9:3: expected a number, found `zero`");
}
END_TEST

START_TEST(the_files_own_refusals_come_before_what_the_options_replace)
{
    /* O = A in the file: refused there, though the options give a whole
     * view (the file is judged as it is written) */
    static const char degenerate[] = "0 0 5\n0 0 5 4 0 5 8 8\n0\n0\n0 0 0\n"
                                     "0 0 4 255 255 255\n";
    rt_load_options options;
    rt_load_options_init(&options);
    options.look_from_given = options.look_at_given = 1;
    options.up_given = options.fov_given = 1;
    options.look_from = (rt_vec3){0, 0, 10};
    options.look_at = (rt_vec3){0, 0, 0};
    options.up = (rt_vec3){0, 1, 0};
    options.fov = 40;
    rt_error error;
    ck_assert_int_eq(parse(degenerate, "view.scn", &options, &error),
                     RT_ERR_CAMERA);
    ck_assert_str_eq(error.message,
                     "view.scn:2:1: expected a camera that sees something, "
                     "found that the observer O is the screen centre A");
    /* a view the options make degenerate is theirs: no line of the file */
    static const char fine[] = "0 0 10\n0 0 5 4 0 5 8 8\n0\n0\n0 0 0\n"
                               "0 0 4 255 255 255\n";
    options.up = (rt_vec3){0, 0, 1};
    ck_assert_int_eq(parse(fine, "view.scn", &options, &error),
                     RT_ERR_CAMERA);
    ck_assert_str_eq(error.message, "view.scn: expected a view, found that "
                                    "the up direction is along the view");
    /* the options' lights are not the file's either */
    rt_light many[RT_MAX_LIGHTS + 1];
    for (int i = 0; i <= RT_MAX_LIGHTS; i++)
        many[i] = (rt_light){{0, 0, 4}, {255, 255, 255}};
    rt_load_options lights;
    rt_load_options_init(&lights);
    lights.lights = many;
    lights.light_count = RT_MAX_LIGHTS + 1;
    ck_assert_int_eq(parse(fine, "lights.scn", &lights, &error),
                     RT_ERR_LIMIT);
    ck_assert_str_eq(error.message,
                     "lights.scn: expected " RT_RULE_LIGHTS ", found 65");
    lights.light_count = 2;
    ck_assert_int_eq(parse(fine, "lights.scn", &lights, &error), RT_OK);
}
END_TEST

START_TEST(the_nff_reader_names_the_light_past_the_limit_at_its_l)
{
    char text[4096] = "v\nfrom 0 0 10\nat 0 0 0\nup 0 1 0\nangle 40\n"
                      "hither 1\nresolution 8 8\n";
    for (int i = 0; i <= RT_MAX_LIGHTS; i++)
        strcat(text, i == RT_MAX_LIGHTS ? "  l 1 2 3\n" : "l 0 0 5\n");
    rt_error error;
    ck_assert_int_eq(parse(text, "l.nff", NULL, &error), RT_ERR_LIMIT);
    ck_assert_str_eq(error.message, "l.nff:72:3: expected " RT_RULE_LIGHTS
                                    ", found light 65");
}
END_TEST

static Suite *refusals_suite(void)
{
    Suite *s = suite_create("refusals");
    TCase *tc = tcase_create("builder");
    tcase_add_test(tc, the_builder_names_the_facet_and_field_it_refuses);
    tcase_add_test(tc,
                   the_builder_names_the_point_and_coordinate_out_of_range);
    tcase_add_test(tc, the_builder_names_the_lens_the_camera_and_the_lights);
    tcase_add_test(tc, the_builder_refuses_a_scene_without_a_light);
    tcase_add_test(tc, the_first_rule_a_file_states_is_the_first_refused);
    tcase_add_test(tc, a_build_that_refuses_nothing_leaves_no_refusal);
    suite_add_tcase(s, tc);
    tc = tcase_create("readers");
    tcase_add_test(
        tc, the_scn_reader_names_the_token_of_each_value_the_builder_refuses);
    tcase_add_test(tc,
                   a_value_the_builder_refuses_comes_after_the_files_own_errors);
    tcase_add_test(
        tc, the_files_own_refusals_come_before_what_the_options_replace);
    tcase_add_test(tc, the_nff_reader_names_the_light_past_the_limit_at_its_l);
    suite_add_tcase(s, tc);
    return s;
}

RT_CHECK_MAIN(refusals_suite)
