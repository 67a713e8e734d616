/*
 * test_cli_numbers.c - one grammar for a number, in a scene file and on the
 * command line.  rt_scene_read_number (the library's rule, which the .scn
 * reader applies to its tokens) is checked against the .scn reader itself,
 * text by text; the option parser (apps/common/cli.h) in process, on the
 * values the issue found read differently (a subnormal refused, hex
 * accepted); and the programs' messages for a value out of range, which
 * name the bound and the value.
 */
#include <check.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "testutil.h"

/* ------------------------------------------------------------------ */
/* The library's rule against the scene reader                         */

static const struct {
    const char *text;
    rt_status status;
} numbers[] = {
    {"1", RT_OK},          {"-1.5", RT_OK},       {".5", RT_OK},
    {"2.", RT_OK},         {"+3", RT_OK},         {"1e-9", RT_OK},
    {"1E5", RT_OK},        {"-0", RT_OK},         {"1e-320", RT_OK},
    {"1e-308", RT_OK},     {"1e-400", RT_OK},     {"0.0e+0", RT_OK},
    {"0x10", RT_ERR_SYNTAX}, {"0x1p3", RT_ERR_SYNTAX}, {"1e", RT_ERR_SYNTAX},
    {"e5", RT_ERR_SYNTAX}, {".", RT_ERR_SYNTAX},  {"-", RT_ERR_SYNTAX},
    {"1.2.3", RT_ERR_SYNTAX}, {"--1", RT_ERR_SYNTAX}, {"1e+", RT_ERR_SYNTAX},
    {"1d3", RT_ERR_SYNTAX}, {"nan", RT_ERR_RANGE}, {"-inf", RT_ERR_RANGE},
    {"Infinity", RT_ERR_RANGE}, {"1e999", RT_ERR_RANGE},
    {"-1e309", RT_ERR_RANGE},
};

/* A scene whose observer's x is `number`. */
static rt_status parse_observer(const char *number, double *x)
{
    char text[512];
    snprintf(text, sizeof text,
             "%s, 0, 10\n0, 0, 5, 4, 0, 5, 8, 8\n3\n-1, -1, 0\n1, -1, 0\n"
             "0, 1, 0\n1\n1, 2, 3, 0, 200, 200, 200\n10, 10, 10\n"
             "0, 0, 20, 255, 255, 255\n",
             number);
    rt_scene *scene;
    rt_error error;
    rt_status status =
        rt_scene_parse(text, strlen(text), "number.scn", NULL, &scene, &error);
    if (status == RT_OK) {
        rt_scene_info info = {.size = sizeof info};
        rt_scene_get_info(scene, &info);
        *x = info.camera.observer.x;
        rt_scene_destroy(scene);
    }
    return status;
}

START_TEST(read_number_takes_what_a_scene_file_takes)
{
    for (size_t i = 0; i < sizeof numbers / sizeof *numbers; i++) {
        double value = 42, in_scene = 0;
        rt_error error;
        memset(&error, 0, sizeof error);
        rt_status status = rt_scene_read_number(
            numbers[i].text, strlen(numbers[i].text), &value, &error);
        ck_assert_msg(status == numbers[i].status, "'%s': %s, expected %s",
                      numbers[i].text, rt_status_string(status),
                      rt_status_string(numbers[i].status));
        if (status != RT_OK) {
            /* the error says why, naming the text */
            char found[64];
            snprintf(found, sizeof found, "found `%s`", numbers[i].text);
            ck_assert_int_eq(error.status, status);
            ck_assert_msg(strncmp(error.message, "expected ", 9) == 0 &&
                              strstr(error.message, found),
                          "'%s': %s", numbers[i].text, error.message);
        }
        rt_status scene = parse_observer(numbers[i].text, &in_scene);
        ck_assert_msg((scene == RT_OK) == (status == RT_OK),
                      "'%s': the scene reader says %s, the rule %s",
                      numbers[i].text, rt_status_string(scene),
                      rt_status_string(status));
        if (status == RT_OK)
            ck_assert_msg(value == in_scene, "'%s': %.17g, the scene %.17g",
                          numbers[i].text, value, in_scene);
        else
            ck_assert_double_eq(value, 42); /* untouched */
    }
}
END_TEST

START_TEST(read_number_takes_a_subnormal_as_it_is)
{
    double v;
    ck_assert_int_eq(rt_scene_read_number("1e-320", 6, &v, NULL), RT_OK);
    ck_assert(v > 0 && v < DBL_MIN);
    ck_assert_double_eq(v, strtod("1e-320", NULL));
    ck_assert_int_eq(rt_scene_read_number("1e-400", 6, &v, NULL), RT_OK);
    ck_assert_double_eq(v, 0.0);
}
END_TEST

START_TEST(read_number_reads_only_the_length_given_and_refuses_null)
{
    double v = 0;
    ck_assert_int_eq(rt_scene_read_number("12,34", 2, &v, NULL), RT_OK);
    ck_assert_double_eq(v, 12);
    ck_assert_int_eq(rt_scene_read_number("12,34", 5, &v, NULL),
                     RT_ERR_SYNTAX);
    ck_assert_int_eq(rt_scene_read_number("", 0, &v, NULL), RT_ERR_SYNTAX);
    rt_error error;
    ck_assert_int_eq(rt_scene_read_number(NULL, 1, &v, &error),
                     RT_ERR_ARGUMENT);
    ck_assert_int_eq(error.status, RT_ERR_ARGUMENT);
    ck_assert_int_eq(rt_scene_read_number("1", 1, NULL, NULL),
                     RT_ERR_ARGUMENT);
    char longest[258];
    memset(longest, '1', sizeof longest);
    ck_assert_int_eq(rt_scene_read_number(longest, 256, &v, NULL), RT_OK);
    ck_assert_int_eq(rt_scene_read_number(longest, 257, &v, &error),
                     RT_ERR_LIMIT);
    ck_assert_msg(strstr(error.message, "at most 256 characters"), "%s",
                  error.message);
}
END_TEST

/* ------------------------------------------------------------------ */
/* The parser, in process                                              */

static const cli_program test_program = {
    "rt-test", "SCENE", "A program that takes every group.", NULL,
    CLI_GROUP_RENDER | CLI_GROUP_LOAD | CLI_GROUP_OUTPUT |
        CLI_GROUP_EXPLAIN,
    NULL, 1, 1, "expected a scene file"};

static int parse(cli_settings *s, const char *option, const char *value)
{
    static char *argv[4];
    argv[0] = "rt-test";
    argv[1] = (char *)option;
    argv[2] = (char *)value;
    argv[3] = "s.scn";
    return cli_parse(&test_program, 4, argv, s);
}

START_TEST(options_take_what_the_scene_format_takes)
{
    cli_settings s;
    ck_assert_int_eq(parse(&s, "--aperture", "1e-320"), CLI_CONTINUE);
    ck_assert_double_eq(s.render.aperture, strtod("1e-320", NULL));
    ck_assert(s.render.aperture > 0);
    ck_assert_int_eq(parse(&s, "--focus", "1e-308"), CLI_CONTINUE);
    ck_assert_double_eq(s.render.focal_distance, 1e-308);
    ck_assert_int_eq(parse(&s, "--depth", "2.0"), CLI_CONTINUE);
    ck_assert_int_eq(s.render.max_depth, 2);
    ck_assert_int_eq(parse(&s, "--samples", "4e0"), CLI_CONTINUE);
    ck_assert_int_eq(s.render.samples, 4);
    ck_assert_int_eq(parse(&s, "--size", "1e2x50."), CLI_CONTINUE);
    ck_assert_int_eq(s.render.width, 100);
    ck_assert_int_eq(s.render.height, 50);
    ck_assert_int_eq(parse(&s, "--look-from", "1e152,-1e152,.5"),
                     CLI_CONTINUE);
    ck_assert_double_eq(s.load.look_from.x, 1e152);
    ck_assert_int_eq(parse(&s, "--up", "1e200,0,1"), CLI_CONTINUE);
    ck_assert_int_eq(parse(&s, "--light", "1e200,0,1,200.,0,255"),
                     CLI_CONTINUE);
    ck_assert_int_eq(s.lights[0].color.r, 200);
    ck_assert_int_eq(parse(&s, "--region", "0,0,16384,1"), CLI_CONTINUE);
    ck_assert_int_eq(s.render.region.x1, 16384);
}
END_TEST

START_TEST(options_refuse_what_the_scene_format_refuses)
{
    static const char *const bad[][2] = {
        {"--aperture", "0x1p3"},   {"--look-from", "0x10,0,0"},
        {"--depth", "0x10"},       {"--aperture", "nan"},
        {"--focus", "inf"},        {"--aperture", "1e999"},
        {"--aperture", " 1"},      {"--depth", "2.5"},
        {"--look-from", "1,2"},    {"--look-from", "1,,2,3"},
        {"--look-from", "1e153,0,0"}, {"--look-at", "0,-2e152,0"},
        {"--light", "0,0,0,1,2,255.5"}, {"--light", "0,0,0,1,2,256"},
        {"--size", "0x10"},        {"--size", "16385x1"},
        {"--region", "-1,0,5,5"},  {"--region", "0,0,2147483647,1"},
        {"--explain", "16384,0"},  {"--focus", "1e-400"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        cli_settings s;
        ck_assert_msg(parse(&s, bad[i][0], bad[i][1]) == CLI_EXIT_USAGE,
                      "%s %s was accepted", bad[i][0], bad[i][1]);
    }
}
END_TEST

/* ------------------------------------------------------------------ */
/* The programs' messages                                              */

START_TEST(range_messages_give_the_bound_and_the_value)
{
    char *dir = rt_test_temp_dir();
    static const struct {
        const char *option, *value, *message;
    } cases[] = {
        {"--region", "0,0,2147483647,1",
         "--region: expected X1 in 0..16384, found 2147483647"},
        {"--region", "-3,0,5,5",
         "--region: expected X0 in 0..16384, found -3"},
        {"--depth", "1e7",
         "--depth: expected an integer in 0..1000000, found 10000000 "
         "('1e7')"},
        {"--samples", "2048",
         "--samples: expected a square (1, 4, 9, 16, ...) in 1..1024, "
         "found 2048"},
        {"--focus", "1e-400",
         "--focus: expected a number > 0, found 0 ('1e-400')"},
        {"--focus", "-1e-308",
         "--focus: expected a number > 0, found -1e-308"},
        {"--tessellate", "1", "--tessellate: expected a number in (0, 1), "
                              "found 1"},
        {"--look-from", "1e200,0,0",
         "--look-from: expected a coordinate of magnitude at most 1e+152 "
         "(the renderer's arithmetic overflows beyond), found 1e+200 "
         "('1e200')"},
        {"--light", "0,0,9,1,2,256",
         "--light: expected a colour component in 0..255, found 256"},
        {"--size", "0x10", "--size: expected a width in 1..16384, found 0"},
        {"--explain", "3,20000",
         "--explain: expected Y in 0..16383, found 20000"},
        /* not of the value's form: quoted as typed */
        {"--aperture", "0x1p3",
         "--aperture: expected a number >= 0, found '0x1p3'"},
        {"--look-from", "0x10,0,0",
         "--look-from: expected X,Y,Z (three numbers), found '0x10,0,0'"},
        {"--depth", "2.5",
         "--depth: expected an integer in 0..1000000, found '2.5'"},
        /* control bytes of a value are escaped */
        {"--depth", "\x1b[2J",
         "--depth: expected an integer in 0..1000000, found '\\x1b[2J'"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        const char *args[] = {cases[i].option, cases[i].value, "s.scn",
                              NULL};
        rt_test_output r = rt_test_run(dir, RT_EXPORT_PATH, args);
        char expected[512];
        snprintf(expected, sizeof expected,
                 "rt-export: %s\nTry 'rt-export --help'.\n",
                 cases[i].message);
        ck_assert_msg(r.code == 2, "%s %s: exit %d", cases[i].option,
                      cases[i].value, r.code);
        ck_assert_str_eq(r.err, expected);
        rt_test_output_free(&r);
    }
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(values_the_scene_format_takes_render)
{
    char *dir = rt_test_temp_dir();
    char scene[4096];
    snprintf(scene, sizeof scene, "%s",
             rt_test_source_path("scenes/cubes.scn"));
    static const char *const options[][2] = {
        {"--aperture", "1e-320"}, {"--focus", "1e-308"},
        {"--depth", "2.0"},       {"--size", "16e0x12"},
    };
    for (size_t i = 0; i < sizeof options / sizeof *options; i++) {
        const char *args[] = {scene, options[i][0], options[i][1],
                              "--size=16x12", "-q", "-o", "out.ppm", NULL};
        if (strcmp(options[i][0], "--size") == 0)
            args[3] = "-q";
        rt_test_output r = rt_test_run(dir, RT_EXPORT_PATH, args);
        ck_assert_msg(r.code == 0, "%s %s: exit %d: %s", options[i][0],
                      options[i][1], r.code, r.err);
        ck_assert_str_eq(r.out, "out.ppm\n");
        rt_test_output_free(&r);
        rt_image image;
        ck_assert_int_eq(rt_ppm_load(rt_test_in_dir(dir, "out.ppm"), &image,
                                     NULL),
                         RT_OK);
        ck_assert_int_eq(image.width, 16);
        ck_assert_int_eq(image.height, 12);
        rt_image_release(&image);
    }
    rt_test_remove_dir(dir);
}
END_TEST

static Suite *numbers_suite(void)
{
    Suite *s = suite_create("cli_numbers");
    TCase *c = tcase_create("grammar");
    tcase_add_test(c, read_number_takes_what_a_scene_file_takes);
    tcase_add_test(c, read_number_takes_a_subnormal_as_it_is);
    tcase_add_test(c, read_number_reads_only_the_length_given_and_refuses_null);
    tcase_add_test(c, options_take_what_the_scene_format_takes);
    tcase_add_test(c, options_refuse_what_the_scene_format_refuses);
    suite_add_tcase(s, c);
    c = tcase_create("programs");
    tcase_set_timeout(c, 60);
    tcase_add_test(c, range_messages_give_the_bound_and_the_value);
    tcase_add_test(c, values_the_scene_format_takes_render);
    suite_add_tcase(s, c);
    return s;
}

RT_CHECK_MAIN(numbers_suite)
