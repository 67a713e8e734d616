/*
 * test_readers.c - what every scene reader refuses, and how it says so:
 * old Mac line endings, UTF-16 and UTF-32 text, binary data, endless or
 * huge inputs, coordinates beyond the arithmetic, and scenes a float render
 * cannot resolve.  Each kind once produced a misleading message (or
 * none); each test checks the message names the real cause, in every
 * format the loader reads.
 */
#include <check.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#include "testutil.h"

static const rt_scene_format formats[] = {
    RT_SCENE_FORMAT_SCN, RT_SCENE_FORMAT_NFF, RT_SCENE_FORMAT_OBJ};
#define FORMAT_COUNT (int)(sizeof formats / sizeof formats[0])

/* Parses `length` bytes in format `_i` and expects a refusal whose message
 * holds `words`. */
static void expect_refusal(int format, const char *text, size_t length,
                           rt_status status, const char *words)
{
    rt_load_options options;
    rt_load_options_init(&options);
    options.format = formats[format];
    rt_scene *scene = (rt_scene *)&options;     /* must become NULL */
    rt_error error;
    memset(&error, 0, sizeof error);
    rt_status got =
        rt_scene_parse(text, length, "input", &options, &scene, &error);
    ck_assert_msg(got == status, "%s: status %s, expected %s: %s",
                  rt_scene_format_name(formats[format]),
                  rt_status_string(got), rt_status_string(status),
                  error.message);
    ck_assert_ptr_null(scene);
    ck_assert_msg(strstr(error.message, words) != NULL,
                  "%s: the message does not say \"%s\": %s",
                  rt_scene_format_name(formats[format]), words,
                  error.message);
}

START_TEST(old_mac_line_endings_are_named)
{
    static const char text[] = "# a scene\r1 2 3\r4 5 6\r";
    expect_refusal(_i, text, sizeof text - 1, RT_ERR_FORMAT,
                   "old Mac line endings (CR only");
}
END_TEST

START_TEST(utf16_and_utf32_are_named_by_their_byte_order_mark)
{
    static const struct {
        const char *bytes;
        size_t length;
        const char *name;
    } marks[] = {
        {"\xFF\xFE" "1\0 \0" "2\0", 8, "UTF-16 (little-endian)"},
        {"\xFE\xFF" "\0" "1\0 \0" "2", 8, "UTF-16 (big-endian)"},
        {"\xFF\xFE\0\0" "1\0\0\0", 8, "UTF-32 (little-endian)"},
        {"\0\0\xFE\xFF" "\0\0\0" "1", 8, "UTF-32 (big-endian)"},
    };
    for (size_t i = 0; i < sizeof marks / sizeof marks[0]; i++)
        expect_refusal(_i, marks[i].bytes, marks[i].length, RT_ERR_FORMAT,
                       marks[i].name);
}
END_TEST

START_TEST(utf16_without_a_mark_is_recognised)
{
    static const char text[] = "0\0 \0" "0\0 \0" "1\0" "0\0\n\0";
    expect_refusal(_i, text, sizeof text - 1, RT_ERR_FORMAT,
                   "looks UTF-16 encoded");
}
END_TEST

START_TEST(binary_data_is_refused_at_its_first_nul_byte)
{
    static const char text[] = "0 0 10\n\x7f" "ELF\x02\x01\x01\0\0";
    rt_error error;
    rt_scene *scene;
    ck_assert_int_eq(
        rt_scene_parse(text, sizeof text - 1, "x.scn", NULL, &scene, &error),
        RT_ERR_FORMAT);
    ck_assert_str_eq(error.message, "x.scn:2:8: expected text, found a NUL "
                                    "byte: the file is binary, not a scene");
    expect_refusal(_i, text, sizeof text - 1, RT_ERR_FORMAT,
                   "the file is binary, not a scene");
}
END_TEST

/* Endless devices: reading stops at the first chunk that holds a NUL byte
 * (test timeout: a reader that reads on would run out of memory or time). */
START_TEST(endless_devices_are_refused_after_one_chunk)
{
    static const char *const devices[] = {"/dev/zero", "/dev/urandom"};
    for (size_t i = 0; i < sizeof devices / sizeof devices[0]; i++) {
        if (access(devices[i], R_OK) != 0) {
            fprintf(stderr, "test_readers: %s absent; skipped\n", devices[i]);
            continue;
        }
        rt_load_options options;
        rt_load_options_init(&options);
        options.format = formats[_i];
        rt_scene *scene;
        rt_error error;
        ck_assert_int_eq(rt_scene_load(devices[i], &options, &scene, &error),
                         RT_ERR_FORMAT);
        ck_assert_msg(strstr(error.message, "found a NUL byte") != NULL,
                      "%s: %s", devices[i], error.message);
    }
}
END_TEST

/* More than RT_MAX_SCENE_BYTES is refused before a byte is read: a sparse
 * file mapped in memory costs nothing, and no line or column number can
 * ever pass 2^30. */
START_TEST(input_beyond_the_size_limit_is_refused_before_reading)
{
    char path[] = "/tmp/rt-test-readers-XXXXXX";
    int fd = mkstemp(path);
    ck_assert_int_ge(fd, 0);
    unlink(path);
    size_t length = RT_MAX_SCENE_BYTES + 1;
    ck_assert_int_eq(ftruncate(fd, (off_t)length), 0);
    void *text = mmap(NULL, length, PROT_READ, MAP_PRIVATE, fd, 0);
    ck_assert(text != MAP_FAILED);
    expect_refusal(_i, text, length, RT_ERR_LIMIT,
                   "expected a scene of at most 1073741824 bytes");
    munmap(text, length);
    close(fd);
}
END_TEST

/* Vertices or camera points beyond RT_MAX_COORDINATE: the intersection
 * test's products would overflow and the scene would render as the
 * background.  The loader refuses them, at their column. */
START_TEST(coordinates_beyond_the_arithmetic_are_refused_where_they_are)
{
    static const char scene_text[] =
        "0 0 10\n0 0 5 1 0 5 8 8\n3\n0 0 0\n2e152 0 0\n0 1 0\n1\n"
        "1 2 3 0 255 0 0\n0 0 0\n0 0 10 255 255 255\n";
    rt_scene *scene;
    rt_error error;
    ck_assert_int_eq(rt_scene_parse(scene_text, sizeof scene_text - 1,
                                    "far.scn", NULL, &scene, &error),
                     RT_ERR_RANGE);
    ck_assert_str_eq(error.message,
                     "far.scn:5:1: expected a coordinate of magnitude at "
                     "most 1e152 (the renderer's arithmetic overflows "
                     "beyond), found `2e152`");
    /* the builder refuses it too, for every reader */
    rt_vec3 v[3] = {{0, 0, 0}, {2e152, 0, 0}, {0, 1, 0}};
    rt_facet_desc f = {{0, 1, 2}, 0, {255, 0, 0}};
    rt_light light = {{0, 0, 10}, {255, 255, 255}};
    rt_scene_desc d = {.observer = {0, 0, 10}, .screen_center = {0, 0, 5},
                       .screen_right = {1, 0, 5}, .width = 8, .height = 8,
                       .vertices = v, .vertex_count = 3, .facets = &f,
                       .facet_count = 1, .lights = &light, .light_count = 1};
    ck_assert_int_eq(rt_scene_create(&d, &scene, &error), RT_ERR_RANGE);
    ck_assert_ptr_nonnull(strstr(error.message, "at most 1e+152"));
    /* at the limit, and a light far beyond it, the scene loads */
    v[1].x = 1e152;
    light.position = (rt_vec3){0, 0, 1e200};
    ck_assert_int_eq(rt_scene_create(&d, &scene, &error), RT_OK);
    rt_scene_destroy(scene);
}
END_TEST

/* A small scene far from the origin: double renders it, float refuses
 * with the rule's reason; the same scene near the origin renders in
 * both. */
START_TEST(float_refuses_a_scene_it_cannot_resolve)
{
    static const double offsets[] = {0, 1e6};
    for (int k = 0; k < 2; k++) {
        double o = offsets[k];
        rt_vec3 v[3] = {{o - 1, o - 1, o}, {o + 1, o - 1, o}, {o, o + 1, o}};
        rt_facet_desc f = {{0, 1, 2}, 0, {255, 0, 0}};
        rt_scene_desc d = {.observer = {o, o, o + 10},
                           .screen_center = {o, o, o + 5},
                           .screen_right = {o + 1, o, o + 5}, .width = 8,
                           .height = 8, .vertices = v, .vertex_count = 3,
                           .facets = &f, .facet_count = 1,
                           .lights = &(rt_light){{o, o, o + 10},
                                                 {255, 255, 255}},
                           .light_count = 1};
        rt_scene *scene;
        rt_error error;
        ck_assert_int_eq(rt_scene_create(&d, &scene, &error), RT_OK);
        ck_assert_int_eq(rt_scene_check_precision(scene, RT_PRECISION_DOUBLE,
                                                  &error),
                         RT_OK);
        rt_status status =
            rt_scene_check_precision(scene, RT_PRECISION_FLOAT, &error);
        rt_image image;
        ck_assert_int_eq(rt_image_init(&image, 8, 8, NULL), RT_OK);
        rt_render_options options;
        rt_render_options_init(&options);
        options.precision = RT_PRECISION_FLOAT;
        rt_status rendered = rt_render(scene, &options, &image, NULL);
        if (k == 0) {
            ck_assert_int_eq(status, RT_OK);
            ck_assert_int_eq(rendered, RT_OK);
        } else {
            ck_assert_int_eq(status, RT_ERR_RANGE);
            ck_assert_int_eq(rendered, RT_ERR_RANGE);
            ck_assert_msg(strstr(error.message, "cannot resolve this scene")
                              && strstr(error.message, "render in double"),
                          "%s", error.message);
        }
        rt_image_release(&image);
        rt_scene_destroy(scene);
    }
}
END_TEST

static Suite *readers_suite(void)
{
    Suite *s = suite_create("readers");
    TCase *c = tcase_create("refusals");
    tcase_set_timeout(c, 60);
    tcase_add_loop_test(c, old_mac_line_endings_are_named, 0, FORMAT_COUNT);
    tcase_add_loop_test(c, utf16_and_utf32_are_named_by_their_byte_order_mark,
                        0, FORMAT_COUNT);
    tcase_add_loop_test(c, utf16_without_a_mark_is_recognised, 0,
                        FORMAT_COUNT);
    tcase_add_loop_test(c, binary_data_is_refused_at_its_first_nul_byte, 0,
                        FORMAT_COUNT);
    tcase_add_loop_test(c, endless_devices_are_refused_after_one_chunk, 0,
                        FORMAT_COUNT);
    tcase_add_loop_test(c, input_beyond_the_size_limit_is_refused_before_reading,
                        0, FORMAT_COUNT);
    tcase_add_test(c,
                   coordinates_beyond_the_arithmetic_are_refused_where_they_are);
    tcase_add_test(c, float_refuses_a_scene_it_cannot_resolve);
    suite_add_tcase(s, c);
    return s;
}

RT_CHECK_MAIN(readers_suite)
