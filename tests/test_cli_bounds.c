/*
 * test_cli_bounds.c - the ends of a real option's interval: the option
 * table says which ends are in it (cli_values.h, CLI_BOUND_...; a
 * program's own option, CLI_NUMBER_CLOSED), the parser accepts exactly
 * those, and the message writes the interval as it is ("[0.01, 64]",
 * "(0, 180)").  rt-view's --scale, whose help says 0.01..64, takes 64 and
 * refuses what lies past it.
 */
#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "cli_values.h"
#include "testutil.h"

START_TEST(a_closed_maximum_is_in_the_interval)
{
    double v = 0;
    cli_problem problem;
    ck_assert_int_eq(cli_read_real("64", 0.01, 64, CLI_BOUND_CLOSED_MAX, &v,
                                   &problem), CLI_READ_OK);
    ck_assert_double_eq(v, 64);
    ck_assert_int_eq(cli_read_real("64.0000001", 0.01, 64,
                                   CLI_BOUND_CLOSED_MAX, &v, &problem),
                     CLI_READ_RANGE);
    ck_assert_str_eq(problem.expected, "a number in [0.01, 64]");
    ck_assert_int_eq(cli_read_real("0.01", 0.01, 64, CLI_BOUND_CLOSED_MAX,
                                   &v, &problem), CLI_READ_OK);
    ck_assert_double_eq(v, 0.01);
}
END_TEST

START_TEST(an_open_maximum_stays_out_and_an_infinite_one_is_no_limit)
{
    double v = 0;
    cli_problem problem;
    /* --fov: (0, 180), neither end a field of view */
    ck_assert_int_eq(cli_read_real("180", 0, 180, CLI_BOUND_OPEN_MIN, &v,
                                   &problem), CLI_READ_RANGE);
    ck_assert_str_eq(problem.expected, "a number in (0, 180)");
    ck_assert_int_eq(cli_read_real("0", 0, 180, CLI_BOUND_OPEN_MIN, &v,
                                   &problem), CLI_READ_RANGE);
    ck_assert_int_eq(cli_read_real("179.5", 0, 180, CLI_BOUND_OPEN_MIN, &v,
                                   &problem), CLI_READ_OK);
    ck_assert_double_eq(v, 179.5);
    /* both ends in */
    ck_assert_int_eq(cli_read_real("0", 0, 1,
                                   CLI_BOUND_CLOSED_MAX, &v, &problem),
                     CLI_READ_OK);
    ck_assert_str_eq(problem.expected, "a number in [0, 1]");
    /* --aperture: >= 0, no upper limit whatever the flags say */
    ck_assert_int_eq(cli_read_real("1e300", 0, HUGE_VAL, 0, &v, &problem),
                     CLI_READ_OK);
    ck_assert_str_eq(problem.expected, "a number >= 0");
    ck_assert_int_eq(cli_read_real("1e300", 0, HUGE_VAL, CLI_BOUND_CLOSED_MAX,
                                   &v, &problem), CLI_READ_OK);
}
END_TEST

/* A program with one option of each kind of real. */
static double closed_value, open_value;

static const cli_option own[] = {
    {"closed", 0, "F", CLI_NUMBER_CLOSED, 1, 8, &closed_value,
     "a factor in 1..8"},
    {"open", 0, "F", CLI_NUMBER, 1, 8, &open_value, "a factor below 8"},
    CLI_OPTIONS_END,
};

static const cli_program program = {
    "bounds", "[SCENE]", "Tests the ends of intervals.", NULL, 0, own, 0, 1,
    NULL};

static int parse(const char *option, const char *value)
{
    char *argv[] = {"bounds", (char *)option, (char *)value, NULL};
    cli_settings settings;
    closed_value = open_value = 0;
    return cli_parse(&program, 3, argv, &settings);
}

START_TEST(a_programs_own_option_may_include_its_maximum)
{
    ck_assert_int_eq(parse("--closed", "8"), CLI_CONTINUE);
    ck_assert_double_eq(closed_value, 8);
    ck_assert_int_eq(parse("--closed", "8.5"), CLI_EXIT_USAGE);
    ck_assert_int_eq(parse("--open", "8"), CLI_EXIT_USAGE);
    ck_assert_int_eq(parse("--open", "7.75"), CLI_CONTINUE);
    ck_assert_double_eq(open_value, 7.75);
}
END_TEST

#ifdef RT_VIEW_PATH
/* rt-view with `args`, no display named (it then never opens a window). */
static rt_test_output view(const char *dir, const char *const *args)
{
    unsetenv("DISPLAY");
    unsetenv("WAYLAND_DISPLAY");
    unsetenv("SDL_VIDEODRIVER");
    return rt_test_run(dir, RT_VIEW_PATH, args);
}

START_TEST(rt_view_takes_scale_64_as_its_help_says)
{
    char *dir = rt_test_temp_dir();
    /* 64 passes the table: the next check, --scale with --width, speaks */
    const char *with_width[] = {"--scale", "64", "--width", "10", NULL};
    rt_test_output r = view(dir, with_width);
    ck_assert_int_eq(r.code, 2);
    ck_assert_str_eq(r.err, "rt-view: --scale: not with --size, --width or "
                            "--height\nTry 'rt-view --help'.\n");
    rt_test_output_free(&r);
    /* alone, it goes as far as the display */
    const char *alone[] = {"--scale", "64", NULL};
    r = view(dir, alone);
    ck_assert_int_eq(r.code, 1);
    ck_assert_msg(strstr(r.err, "rt-view: cannot open a window: ") == r.err,
                  "%s", r.err);
    rt_test_output_free(&r);
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(rt_view_refuses_a_scale_past_either_end)
{
    char *dir = rt_test_temp_dir();
    static const struct {
        const char *value, *message;
    } cases[] = {
        {"64.5", "rt-view: --scale: expected a number in [0.01, 64], found "
                 "64.5\n"},
        {"0.009", "rt-view: --scale: expected a number in [0.01, 64], found "
                  "0.009\n"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        const char *args[] = {"--scale", cases[i].value, NULL};
        rt_test_output r = view(dir, args);
        ck_assert_int_eq(r.code, 2);
        ck_assert_msg(strncmp(r.err, cases[i].message,
                              strlen(cases[i].message)) == 0, "%s", r.err);
        rt_test_output_free(&r);
    }
    rt_test_remove_dir(dir);
}
END_TEST
#endif

static Suite *bounds_suite(void)
{
    Suite *s = suite_create("cli_bounds");
    TCase *c = tcase_create("bounds");
    tcase_set_timeout(c, 60);
    tcase_add_test(c, a_closed_maximum_is_in_the_interval);
    tcase_add_test(c,
                   an_open_maximum_stays_out_and_an_infinite_one_is_no_limit);
    tcase_add_test(c, a_programs_own_option_may_include_its_maximum);
#ifdef RT_VIEW_PATH
    tcase_add_test(c, rt_view_takes_scale_64_as_its_help_says);
    tcase_add_test(c, rt_view_refuses_a_scale_past_either_end);
#endif
    suite_add_tcase(s, c);
    return s;
}

RT_CHECK_MAIN(bounds_suite)
