/*
 * test_api.c - the promises of the public headers about the API itself.
 *
 * Every fallible call fills an optional rt_error with a message that says
 * what was wrong, and accepts a NULL one; option structs grow by the rule of
 * raytrace/render.h (a caller's `size` decides which fields are read; 0 or
 * more than the library knows is refused).
 */
#include <check.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "testutil.h"

/* Fails the test unless `error` reports `status` with `text` in its
 * message. */
static void assert_reported(const rt_error *error, rt_status status,
                            const char *text)
{
    ck_assert_int_eq(error->status, status);
    ck_assert_msg(strstr(error->message, text) != NULL,
                  "expected \"%s\" in the message \"%s\"", text,
                  error->message);
}

START_TEST(options_init_sets_size_to_sizeof)
{
    rt_render_options render;
    rt_render_options_init(&render);
    ck_assert_uint_eq(render.size, sizeof render);
    rt_load_options load;
    rt_load_options_init(&load);
    ck_assert_uint_eq(load.size, sizeof load);
}
END_TEST

START_TEST(old_caller_without_size_fields_renders_at_scene_size)
{
    rt_scene *scene = rt_test_scene_from_string(rt_test_centred_facet_scene);
    rt_render_options options;
    rt_render_options_init(&options);
    /* A caller built before width, height and region existed: its struct
     * ends before them, whatever lies there in ours is not read. */
    options.size = offsetof(rt_render_options, width);
    options.width = 7;
    options.height = 5;
    options.region = (rt_region){1, 1, 2, 2};
    int width, height;
    ck_assert_int_eq(rt_render_image_size(scene, &options, &width, &height,
                                          NULL),
                     RT_OK);
    ck_assert_int_eq(width, 40);
    ck_assert_int_eq(height, 30);
    rt_image image, expected;
    ck_assert_int_eq(rt_image_init(&image, 40, 30, NULL), RT_OK);
    rt_error error;
    ck_assert_int_eq(rt_render(scene, &options, &image, &error), RT_OK);
    rt_render_options defaults;
    rt_render_options_init(&defaults);
    expected = rt_test_render_with(scene, &defaults);
    ck_assert_int_eq(rt_test_image_diff(&image, &expected, NULL), 0);
    rt_image_release(&expected);
    rt_image_release(&image);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(options_of_size_zero_or_too_large_are_refused)
{
    rt_scene *scene = rt_test_scene_from_string(rt_test_centred_facet_scene);
    rt_image image;
    ck_assert_int_eq(rt_image_init(&image, 40, 30, NULL), RT_OK);
    rt_render_options options;
    memset(&options, 0, sizeof options);        /* never initialised */
    rt_error error;
    ck_assert_int_eq(rt_render(scene, &options, &image, &error),
                     RT_ERR_ARGUMENT);
    assert_reported(&error, RT_ERR_ARGUMENT, "render options of 0 bytes");
    ck_assert_int_eq(rt_render(scene, &options, &image, NULL),
                     RT_ERR_ARGUMENT);
    rt_render_options_init(&options);
    options.size = sizeof options + 8;          /* a newer header's */
    ck_assert_int_eq(rt_render_rows(scene, &options, 0, 1, &image, &error),
                     RT_ERR_ARGUMENT);
    assert_reported(&error, RT_ERR_ARGUMENT, "rt_render_options_init");

    rt_load_options load;
    memset(&load, 0, sizeof load);
    rt_scene *loaded = (rt_scene *)&load;       /* must become NULL */
    ck_assert_int_eq(rt_scene_parse(rt_test_centred_facet_scene,
                                    strlen(rt_test_centred_facet_scene),
                                    "a.scn", &load, &loaded, &error),
                     RT_ERR_ARGUMENT);
    ck_assert_ptr_null(loaded);
    assert_reported(&error, RT_ERR_ARGUMENT, "load options of 0 bytes");
    rt_image_release(&image);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(old_load_options_read_only_their_fields)
{
    rt_load_options load;
    rt_load_options_init(&load);
    load.size = offsetof(rt_load_options, look_from_given);
    load.fov_given = 1;                 /* beyond the caller's size */
    load.fov = -1.0;                    /* refused if it were read */
    rt_scene *scene;
    rt_error error;
    ck_assert_int_eq(rt_scene_parse(rt_test_centred_facet_scene,
                                    strlen(rt_test_centred_facet_scene),
                                    "a.scn", &load, &scene, &error),
                     RT_OK);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(render_into_image_of_wrong_size_names_both_sizes)
{
    rt_scene *scene = rt_test_scene_from_string(rt_test_centred_facet_scene);
    rt_image image;
    ck_assert_int_eq(rt_image_init(&image, 400, 300, NULL), RT_OK);
    rt_render_options options;
    rt_render_options_init(&options);
    options.width = 200;
    options.height = 100;
    rt_error error;
    ck_assert_int_eq(rt_render(scene, &options, &image, &error),
                     RT_ERR_ARGUMENT);
    assert_reported(&error, RT_ERR_ARGUMENT,
                    "the image is 400 x 300 but the render writes 200 x 100");
    ck_assert_int_eq(rt_render(scene, &options, &image, NULL),
                     RT_ERR_ARGUMENT);
    rt_image_release(&image);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(bad_render_options_say_what_is_wrong)
{
    rt_scene *scene = rt_test_scene_from_string(rt_test_centred_facet_scene);
    rt_image image;
    ck_assert_int_eq(rt_image_init(&image, 40, 30, NULL), RT_OK);
    rt_render_options options;
    rt_error error;

    rt_render_options_init(&options);
    options.max_depth = -1;
    ck_assert_int_eq(rt_render(scene, &options, &image, &error),
                     RT_ERR_ARGUMENT);
    assert_reported(&error, RT_ERR_ARGUMENT, "a depth of -1");

    rt_render_options_init(&options);
    options.samples = 3;
    ck_assert_int_eq(rt_render(scene, &options, &image, &error),
                     RT_ERR_ARGUMENT);
    assert_reported(&error, RT_ERR_ARGUMENT, "3 samples per pixel");

    rt_render_options_init(&options);
    ck_assert_int_eq(rt_render_rows(scene, &options, 5, 40, &image, &error),
                     RT_ERR_ARGUMENT);
    assert_reported(&error, RT_ERR_ARGUMENT, "rows 5..40");

    rt_render_options_init(&options);
    options.region = (rt_region){0, 0, 50, 10};
    ck_assert_int_eq(rt_render(scene, &options, &image, &error),
                     RT_ERR_ARGUMENT);
    assert_reported(&error, RT_ERR_ARGUMENT, "not inside");
    rt_image_release(&image);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(cancelled_render_says_so)
{
    rt_scene *scene = rt_test_scene_from_string(rt_test_centred_facet_scene);
    rt_image image;
    ck_assert_int_eq(rt_image_init(&image, 40, 30, NULL), RT_OK);
    rt_cancel *cancel;
    ck_assert_int_eq(rt_cancel_create(&cancel, NULL), RT_OK);
    ck_assert_ptr_nonnull(cancel);
    rt_cancel_request(cancel);
    rt_render_options options;
    rt_render_options_init(&options);
    options.cancel = cancel;
    rt_error error;
    ck_assert_int_eq(rt_render(scene, &options, &image, &error),
                     RT_ERR_CANCELLED);
    assert_reported(&error, RT_ERR_CANCELLED, "cancelled");
    rt_cancel_destroy(cancel);
    rt_image_release(&image);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(image_init_refuses_bad_sides_with_the_sizes)
{
    rt_image image;
    rt_error error;
    ck_assert_int_eq(rt_image_init(&image, 0, 10, &error), RT_ERR_ARGUMENT);
    assert_reported(&error, RT_ERR_ARGUMENT, "0 x 10");
    ck_assert_ptr_null(image.pixels);
    rt_image_release(&image);                   /* a zeroed image: no-op */
    ck_assert_int_eq(rt_image_init(&image, 10, RT_MAX_IMAGE_SIDE + 1, NULL),
                     RT_ERR_ARGUMENT);
}
END_TEST

static int refuse(void *user, const void *data, size_t size)
{
    (void)user;
    (void)data;
    (void)size;
    return 0;
}

START_TEST(ppm_writing_fills_the_error)
{
    rt_image image;
    ck_assert_int_eq(rt_image_init(&image, 2, 2, NULL), RT_OK);
    rt_error error;
    ck_assert_int_eq(rt_image_write_to(refuse, NULL, &image, RT_IMAGE_P6,
                                       &error),
                     RT_ERR_IO);
    ck_assert_int_eq(error.status, RT_ERR_IO);
    ck_assert_str_ne(error.message, "");
    ck_assert_int_eq(rt_image_write_to(refuse, NULL, &image,
                                       (rt_image_format)5, &error),
                     RT_ERR_FORMAT);
    assert_reported(&error, RT_ERR_FORMAT, "format 5");
    ck_assert_int_eq(rt_image_write_file(NULL, &image, RT_IMAGE_P3, &error),
                     RT_ERR_ARGUMENT);
    assert_reported(&error, RT_ERR_ARGUMENT, "stream");
    ck_assert_int_eq(rt_image_write_file(NULL, &image, RT_IMAGE_P3, NULL),
                     RT_ERR_ARGUMENT);
    rt_image_release(&image);
}
END_TEST

START_TEST(format_from_path_names_the_path)
{
    rt_error error;
    rt_image_format image_format;
    ck_assert_int_eq(rt_image_format_from_path("out.gif", &image_format,
                                               &error),
                     RT_ERR_FORMAT);
    assert_reported(&error, RT_ERR_FORMAT, "out.gif");
    rt_scene_format scene_format;
    ck_assert_int_eq(rt_scene_format_from_path("a.txt", &scene_format,
                                               &error),
                     RT_ERR_FORMAT);
    assert_reported(&error, RT_ERR_FORMAT, "a.txt");
    ck_assert_int_eq(rt_scene_format_from_path("a.NFF", &scene_format, NULL),
                     RT_OK);
    ck_assert_int_eq(scene_format, RT_SCENE_FORMAT_NFF);
}
END_TEST

static Suite *api_suite(void)
{
    Suite *suite = suite_create("api");
    TCase *tc = tcase_create("contract");
    tcase_add_test(tc, options_init_sets_size_to_sizeof);
    tcase_add_test(tc, old_caller_without_size_fields_renders_at_scene_size);
    tcase_add_test(tc, options_of_size_zero_or_too_large_are_refused);
    tcase_add_test(tc, old_load_options_read_only_their_fields);
    tcase_add_test(tc, render_into_image_of_wrong_size_names_both_sizes);
    tcase_add_test(tc, bad_render_options_say_what_is_wrong);
    tcase_add_test(tc, cancelled_render_says_so);
    tcase_add_test(tc, image_init_refuses_bad_sides_with_the_sizes);
    tcase_add_test(tc, ppm_writing_fills_the_error);
    tcase_add_test(tc, format_from_path_names_the_path);
    suite_add_tcase(suite, tc);
    return suite;
}

RT_CHECK_MAIN(api_suite)
