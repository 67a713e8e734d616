/*
 * test_parse.c - the `.scn` loader against docs/scene-format.md: every
 * rule has a case that checks the status, the position (line and column of
 * the first character of the bad token; just after the last token for a
 * missing value; the line after the last line for an unexpected end of file)
 * and a message of the form "<test>:<line>:<column>: expected ..., found
 * <token>"; the table of broken rules is here, with the other refusals and
 * the loads of files.  The inputs that must be accepted (integral values
 * written `200.` or `200.0`, empty scenes, comments anywhere, CRLF, a
 * byte-order mark, mixed separators, a French locale) are in
 * test_parse_accepts.c; both build on support/base_scene.h's base scene.
 */
#include "base_scene.h"
#include "testutil.h"

#include <ctype.h>
#include <errno.h>
#include <locale.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

enum {
    S_SYNTAX = 1 << RT_ERR_SYNTAX,
    S_RANGE = 1 << RT_ERR_RANGE,
    S_CAMERA = 1 << RT_ERR_CAMERA,
    S_LIMIT = 1 << RT_ERR_LIMIT
};

/* One broken rule.  `statuses` is the set of statuses that fit (the format
 * does not say whether `nan` is a syntax or a range error, for instance); the
 * message must contain `token` and, when `expected` is set, "expected". */
typedef struct bad_case {
    const char *rule;
    int replace;
    const char *replacement;
    int keep;
    const char *append;
    int statuses;
    int line, column;
    const char *token;
    int expected;
} bad_case;

/* The short name of RT_TEST_BASE_ALL in the table. */
#define ALL RT_TEST_BASE_ALL
static const bad_case bad_cases[] = {
    /* non-numbers */
    {"word in observer", 1, "0 abc 5", ALL, NULL, S_SYNTAX, 1, 3, "abc", 1},
    {"word in vertex", 5, "1 -1 x1", ALL, NULL, S_SYNTAX, 5, 6, "x1", 1},
    {"word for w", 2, "0 0 4 1 0 0 two 2", ALL, NULL, S_SYNTAX, 2, 13, "two",
     1},
    {"number glued to a word", 9, "10 20x 30", ALL, NULL, S_SYNTAX, 9, 4,
     "20x", 1},
    /* nan / inf / overflow */
    {"nan coordinate", 1, "0 nan 5", ALL, NULL, S_SYNTAX | S_RANGE, 1, 3,
     "nan", 1},
    {"inf coordinate", 4, "-1 inf 0", ALL, NULL, S_SYNTAX | S_RANGE, 4, 4,
     "inf", 1},
    {"-inf light", 10, "0 0 -inf 255 255 255", ALL, NULL, S_SYNTAX | S_RANGE,
     10, 5, "-inf", 1},
    {"1e999 overflows to inf", 6, "0 1e999 0", ALL, NULL, S_SYNTAX | S_RANGE,
     6, 3, "1e999", 1},
    {"NAN upper case in screen", 2, "0 0 NAN 1 0 0 2 2", ALL, NULL,
     S_SYNTAX | S_RANGE, 2, 5, "NAN", 1},
    /* non-integral counts, indices, sizes, colours */
    {"w 200.5", 2, "0 0 4 1 0 0 200.5 2", ALL, NULL, S_SYNTAX | S_RANGE, 2, 13,
     "200.5", 1},
    {"h 2.5", 2, "0 0 4 1 0 0 2 2.5", ALL, NULL, S_SYNTAX | S_RANGE, 2, 15,
     "2.5", 1},
    {"vertex count 3.5", 3, "3.5", ALL, NULL, S_SYNTAX | S_RANGE, 3, 1, "3.5",
     1},
    {"facet count 1.5", 7, "1.5", ALL, NULL, S_SYNTAX | S_RANGE, 7, 1, "1.5",
     1},
    {"index 1.5", 8, "1.5 2 3 0 255 0 0", ALL, NULL, S_SYNTAX | S_RANGE, 8, 1,
     "1.5", 1},
    {"facet colour 254.5", 8, "1 2 3 0 254.5 0 0", ALL, NULL,
     S_SYNTAX | S_RANGE, 8, 9, "254.5", 1},
    {"background 20.5", 9, "10 20.5 30", ALL, NULL, S_SYNTAX | S_RANGE, 9, 4,
     "20.5", 1},
    {"light colour 0.5", 10, "0 0 10 255 255 0.5", ALL, NULL,
     S_SYNTAX | S_RANGE, 10, 16, "0.5", 1},
    /* ranges */
    {"facet colour 256", 8, "1 2 3 0 256 0 0", ALL, NULL, S_RANGE, 8, 9, "256",
     1},
    {"background 256", 9, "10 20 256", ALL, NULL, S_RANGE, 9, 7, "256", 1},
    {"light colour 256", 10, "0 0 10 255 256 255", ALL, NULL, S_RANGE, 10, 12,
     "256", 1},
    {"negative colour", 9, "-1 20 30", ALL, NULL, S_RANGE, 9, 1, "-1", 1},
    {"k 1.5", 8, "1 2 3 1.5 255 0 0", ALL, NULL, S_RANGE, 8, 7, "1.5", 1},
    {"k -0.1", 8, "1 2 3 -0.1 255 0 0", ALL, NULL, S_RANGE, 8, 7, "-0.1", 1},
    {"index 0", 8, "0 2 3 0 255 0 0", ALL, NULL, S_RANGE, 8, 1, "0", 1},
    {"index n+1", 8, "1 2 4 0 255 0 0", ALL, NULL, S_RANGE, 8, 5, "4", 1},
    {"negative index", 8, "1 -2 3 0 255 0 0", ALL, NULL, S_RANGE, 8, 3, "-2",
     1},
    {"w 0", 2, "0 0 4 1 0 0 0 2", ALL, NULL, S_RANGE | S_LIMIT, 2, 13, "0", 1},
    {"h 0", 2, "0 0 4 1 0 0 2 0", ALL, NULL, S_RANGE | S_LIMIT, 2, 15, "0", 1},
    {"w 16385", 2, "0 0 4 1 0 0 16385 2", ALL, NULL, S_RANGE | S_LIMIT, 2, 13,
     "16385", 1},
    {"h 16385", 2, "0 0 4 1 0 0 2 16385", ALL, NULL, S_RANGE | S_LIMIT, 2, 15,
     "16385", 1},
    {"negative vertex count", 3, "-1", ALL, NULL, S_SYNTAX | S_RANGE, 3, 1,
     "-1", 1},
    /* too few values: the column just after the last token */
    {"observer with 2 values", 1, "0 0", ALL, NULL, S_SYNTAX, 1, 4, "", 1},
    {"screen with 7 values", 2, "0 0 4 1 0 0 2", ALL, NULL, S_SYNTAX, 2, 14,
     "", 1},
    {"vertex with 2 values", 5, "1 -1", ALL, NULL, S_SYNTAX, 5, 5, "", 1},
    {"facet with 6 values", 8, "1 2 3 0 255 0", ALL, NULL, S_SYNTAX, 8, 14, "",
     1},
    {"background with 2 values", 9, "10,20", ALL, NULL, S_SYNTAX, 9, 6, "", 1},
    {"light with 5 values", 10, "0 0 10 255 255", ALL, NULL, S_SYNTAX, 10, 15,
     "", 1},
    {"too few values before a comment", 1, "0 0 # z?", ALL, NULL, S_SYNTAX, 1,
     4, "", 1},
    /* too many values: the first extra token */
    {"observer with 4 values", 1, "0 0 5 7", ALL, NULL,
     S_SYNTAX, 1, 7, "7", 1},
    {"vertex with 4 values", 5, "1 -1 0 0", ALL, NULL, S_SYNTAX, 5, 8, "0", 1},
    /* the extended records of 0.4 (vertex normals, d, s, p) */
    {"vertex with 5 values", 5, "1 -1 0 0 1", ALL, NULL,
     S_SYNTAX, 5, 8, "0", 1},
    {"vertex with a zero normal", 5, "1 -1 0 0 0 0", ALL, NULL,
     S_RANGE, 5, 8, "0", 1},
    {"vertex with a word in its normal", 5, "1 -1 0 0 x 1", ALL, NULL,
     S_SYNTAX, 5, 10, "x", 1},
    {"vertex with 7 values", 5, "1 -1 0 0 0 1 8", ALL, NULL,
     S_SYNTAX, 5, 14, "8", 1},
    {"vertex with an infinite normal", 5, "1 -1 0 0 inf 1", ALL, NULL,
     S_SYNTAX | S_RANGE, 5, 10, "inf", 1},
    {"facet with 13 values", 8, "1 2 3 0 255 0 0 0 1 1 0.5 2 9", ALL, NULL,
     S_SYNTAX, 8, 29, "9", 1},
    {"facet with d < 0", 8, "1 2 3 0 255 0 0 0 1 -0.5", ALL, NULL,
     S_RANGE, 8, 21, "-0.5", 1},
    {"facet with s < 0", 8, "1 2 3 0 255 0 0 0 1 1 -1 2", ALL, NULL,
     S_RANGE, 8, 23, "-1", 1},
    {"facet with p < 1", 8, "1 2 3 0 255 0 0 0 1 1 0.5 0.5", ALL, NULL,
     S_RANGE, 8, 27, "0.5", 1},
    {"facet with p = 0", 8, "1 2 3 0 255 0 0 0 1 1 0.5 0", ALL, NULL,
     S_RANGE, 8, 27, "0", 1},
    {"facet with a word for s", 8, "1 2 3 0 255 0 0 0 1 1 s 2", ALL, NULL,
     S_SYNTAX, 8, 23, "s", 1},
    {"facet with s and no p", 8, "1 2 3 0 255 0 0 0 1 1 0.5", ALL, NULL,
     S_SYNTAX, 8, 26, "", 1},
    {"facet with k + t > 1", 8, "1 2 3 0.5 255 0 0 0.6", ALL, NULL, S_RANGE, 8,
     19, "0.6", 1},
    {"facet with t < 0", 8, "1 2 3 0 255 0 0 -0.1", ALL, NULL, S_RANGE, 8, 17,
     "-0.1", 1},
    {"facet with n = 0", 8, "1 2 3 0 255 0 0 0.5 0", ALL, NULL, S_RANGE, 8, 21,
     "0", 1},
    {"screen with an aperture and no focal distance", 2,
     "0 0 4 1 0 0 8 8 0.1", ALL, NULL, S_SYNTAX, 2, 20, "", 1},
    {"screen with a negative aperture", 2, "0 0 4 1 0 0 8 8 -1 3", ALL, NULL,
     S_RANGE, 2, 17, "-1", 1},
    {"screen with a zero focal distance", 2, "0 0 4 1 0 0 8 8 0.1 0", ALL,
     NULL, S_RANGE, 2, 21, "0", 1},
    {"background with 4 values", 9, "10 20 30 40", ALL, NULL, S_SYNTAX, 9, 10,
     "40", 1},
    {"count with 2 values", 3, "3 4", ALL, NULL, S_SYNTAX, 3, 3, "4", 1},
    {"light with 7 values", 10, "0 0 10 255 255 255 1", ALL, NULL, S_SYNTAX,
     10, 20, "1", 1},
    /* missing records: unexpected end of file, on the line after the last */
    {"empty file", 0, NULL, 0, NULL, S_SYNTAX, 1, 1, "observer", 1},
    {"missing screen", 0, NULL, 1, NULL, S_SYNTAX, 2, 1, "screen", 1},
    {"missing vertex count", 0, NULL, 2, NULL, S_SYNTAX, 3, 1, "vert", 1},
    {"missing facet count", 0, NULL, 6, NULL, S_SYNTAX, 7, 1, "facet", 1},
    {"missing background", 0, NULL, 8, NULL, S_SYNTAX, 9, 1, "background", 1},
    {"missing light", 0, NULL, 9, NULL, S_SYNTAX, 10, 1, "light", 1},
    {"missing light after comments", 0, NULL, 9, "# no light\n\n", S_SYNTAX,
     12, 1, "light", 1},
    /* anything after the light */
    {"short light after the light", 0, NULL, ALL, "1 2 3\n", S_SYNTAX, 11, 6,
     "3", 1},
    {"light with a colour beyond 255", 0, NULL, ALL, "1 2 3 0 0 256\n",
     S_RANGE, 11, 11, "256", 1},
    {"word after the light", 0, NULL, ALL, "# ok\n  junk\n", S_SYNTAX, 12, 3,
     "junk", 1},
    /* counts promising more lines than the file holds */
    {"vertex count 100", 3, "100", ALL, NULL, S_SYNTAX | S_RANGE | S_LIMIT, 3,
     1, "100", 1},
    {"facet count 50", 7, "50", ALL, NULL, S_SYNTAX | S_RANGE | S_LIMIT, 7, 1,
     "50", 1},
    {"vertex count 2000000000", 3, "2000000000", ALL, NULL,
     S_SYNTAX | S_RANGE | S_LIMIT, 3, 1, "2000000000", 1},
    {"facet count 2000000000", 7, "2000000000", ALL, NULL,
     S_SYNTAX | S_RANGE | S_LIMIT, 7, 1, "2000000000", 1},
    {"vertex count past int", 3, "99999999999", ALL, NULL,
     S_SYNTAX | S_RANGE | S_LIMIT, 3, 1, "99999999999", 1},
    /* at the boundary: lines 4..10 are 7 record lines */
    {"vertex count 8 with 7 lines left", 3, "8", ALL, NULL,
     S_SYNTAX | S_RANGE | S_LIMIT, 3, 1, "8", 1},
    {"vertex count 7 eats the facet count", 3, "7", ALL, NULL, S_SYNTAX, 7, 2,
     "", 1},
    {"facet count 4 with 3 lines left", 7, "4", ALL, NULL,
     S_SYNTAX | S_RANGE | S_LIMIT, 7, 1, "4", 1},
    {"facet count 3 eats the background", 7, "3", ALL, NULL, S_SYNTAX, 9, 9,
     "", 1},
    /* degenerate cameras: reported on the screen record */
    {"O = A", 1, "0 0 4", ALL, NULL, S_CAMERA, 2, 0, "", 0},
    {"B = A", 2, "0 0 4 0 0 4 2 2", ALL, NULL, S_CAMERA, 2, 0, "", 0},
    {"B on line OA beyond A", 2, "0 0 4 0 0 3 2 2", ALL, NULL, S_CAMERA, 2, 0,
     "", 0},
    {"B on line OA behind O", 2, "0 0 4 0 0 9 2 2", ALL, NULL, S_CAMERA, 2, 0,
     "", 0},
};

static const char *status_set_string(int set, char *buffer, size_t size)
{
    buffer[0] = '\0';
    for (int s = 0; s < 16; s++) {
        if (set & (1 << s)) {
            strncat(buffer, rt_status_string((rt_status)s),
                    size - strlen(buffer) - 1);
            strncat(buffer, " | ", size - strlen(buffer) - 1);
        }
    }
    return buffer;
}

/* Appends one problem to a report (the test fails once, listing all). */
static void problem(char *report, size_t size, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

static void problem(char *report, size_t size, const char *fmt, ...)
{
    size_t used = strlen(report);
    va_list args;
    va_start(args, fmt);
    vsnprintf(report + used, size - used, fmt, args);
    va_end(args);
}

static int contains_ci(const char *haystack, const char *needle)
{
    size_t n = strlen(needle);
    for (; *haystack; haystack++) {
        size_t i = 0;
        while (i < n && tolower((unsigned char)haystack[i]) ==
                            tolower((unsigned char)needle[i]))
            i++;
        if (i == n)
            return 1;
    }
    return n == 0;
}

/* Checks a failed load against a case; `name` is the name the loader got. */
static void check_error(const bad_case *c, rt_status status, rt_scene *scene,
                        const rt_error *error, const char *name)
{
    char report[4096] = "";
    char set[256];
    if (scene != NULL)
        problem(report, sizeof report, "scene not NULL after failure; ");
    if (!(c->statuses & (1 << status)))
        problem(report, sizeof report, "status %s, expected one of {%s}; ",
                rt_status_string(status),
                status_set_string(c->statuses, set, sizeof set));
    if (status != RT_OK && error->status != status)
        problem(report, sizeof report, "error.status %d != returned %d; ",
                (int)error->status, (int)status);
    char prefix[600];
    snprintf(prefix, sizeof prefix, "%s:%d:%d: ", name, error->line,
             error->column);
    if (strncmp(error->message, prefix, strlen(prefix)) != 0)
        problem(report, sizeof report, "message does not start with \"%s\"; ",
                prefix);
    if (c->token[0] && !contains_ci(error->message, c->token))
        problem(report, sizeof report, "message does not name \"%s\"; ",
                c->token);
    if (c->expected && !strstr(error->message, "expected"))
        problem(report, sizeof report, "message lacks \"expected\"; ");
    if (error->line != c->line)
        problem(report, sizeof report, "line %d, expected %d; ", error->line,
                c->line);
    if (c->column > 0 && error->column != c->column)
        problem(report, sizeof report, "column %d, expected %d; ",
                error->column, c->column);
    if (c->column == 0 && error->column < 1)
        problem(report, sizeof report, "column %d, expected >= 1; ",
                error->column);
    ck_assert_msg(report[0] == '\0', "case \"%s\": %smessage: \"%s\"",
                  c->rule, report, error->message);
}

START_TEST(parse_reports_status_position_and_token_of_each_broken_rule)
{
    const bad_case *c = &bad_cases[_i];
    char text[2048];
    rt_test_base_scene(text, sizeof text, c->replace, c->replacement, c->keep,
                       c->append, "\n");
    rt_scene *scene = (rt_scene *)&text; /* must be reset to NULL */
    rt_error error;
    memset(&error, 0, sizeof error);
    rt_status status =
        rt_scene_parse(text, strlen(text), "<test>", NULL, &scene, &error);
    check_error(c, status, scene, &error, "<test>");
    rt_scene_destroy(status == RT_OK ? scene : NULL);
}
END_TEST

START_TEST(parse_reports_the_same_errors_with_crlf_line_endings)
{
    const bad_case *c = &bad_cases[_i];
    char text[2048];
    rt_test_base_scene(text, sizeof text, c->replace, c->replacement, c->keep,
                       c->append, "\r\n");
    /* the appended text uses LF only: convert it too */
    char crlf[4096];
    size_t n = 0;
    for (const char *p = text; *p; p++) {
        if (*p == '\n' && (p == text || p[-1] != '\r'))
            crlf[n++] = '\r';
        crlf[n++] = *p;
    }
    crlf[n] = '\0';
    rt_scene *scene = NULL;
    rt_error error;
    memset(&error, 0, sizeof error);
    rt_status status = rt_scene_parse(crlf, n, "<test>", NULL, &scene, &error);
    check_error(c, status, scene, &error, "<test>");
    rt_scene_destroy(status == RT_OK ? scene : NULL);
}
END_TEST

START_TEST(parse_columns_do_not_count_the_byte_order_mark)
{
    char text[2048] = "\xEF\xBB\xBF";
    rt_test_base_scene(text + 3, sizeof text - 3, 1, "0 abc 5", ALL, NULL,
                       "\n");
    rt_scene *scene = NULL;
    rt_error error;
    rt_status status =
        rt_scene_parse(text, strlen(text), "<test>", NULL, &scene, &error);
    bad_case c = {"BOM then word", 0, NULL, 0, NULL, S_SYNTAX, 1, 3, "abc", 1};
    check_error(&c, status, scene, &error, "<test>");
}
END_TEST

START_TEST(parse_without_name_uses_memory_in_messages)
{
    char text[2048];
    rt_test_base_scene(text, sizeof text, 9, "10 20 256", ALL, NULL, "\n");
    rt_scene *scene = NULL;
    rt_error error;
    ck_assert_int_eq(
        rt_scene_parse(text, strlen(text), NULL, NULL, &scene, &error),
        RT_ERR_RANGE);
    ck_assert_msg(strncmp(error.message, "<memory>:9:7: ", 14) == 0,
                  "message: \"%s\"", error.message);
}
END_TEST

START_TEST(parse_accepts_a_null_error_pointer)
{
    char text[2048];
    rt_test_base_scene(text, sizeof text, 9, "10 20 256", ALL, NULL, "\n");
    rt_scene *scene = NULL;
    ck_assert_int_eq(
        rt_scene_parse(text, strlen(text), "<test>", NULL, &scene, NULL),
        RT_ERR_RANGE);
    ck_assert_ptr_null(scene);
}
END_TEST

START_TEST(parse_reads_only_length_bytes)
{
    /* The light line is cut by `length`: the rest of the buffer must not
     * be read, so this is an error (too few values on line 10). */
    char text[2048];
    rt_test_base_scene(text, sizeof text, 0, NULL, ALL, NULL, "\n");
    size_t length = strlen(text) - strlen(" 255 255\n");
    rt_scene *scene = NULL;
    rt_error error;
    rt_status status =
        rt_scene_parse(text, length, "<test>", NULL, &scene, &error);
    ck_assert_msg(status == RT_ERR_SYNTAX, "status %s: %s",
                  rt_status_string(status), error.message);
    ck_assert_int_eq(error.line, 10);
    ck_assert_int_eq(error.column, 11);
}
END_TEST

/* The info of the base scene, whatever the layout of the file. */
START_TEST(parse_refuses_huge_count_without_allocating)
{
    /* With the address space limited to 256 MiB, a loader that allocated
     * 2e9 vertices before checking the file would report RT_ERR_NOMEM. */
#if RT_TEST_UNDER_ASAN
    /* AddressSanitizer reserves terabytes of address space, and reports a
     * 48 GB allocation by itself */
    printf("NOTE parse_refuses_huge_count_without_allocating: built with "
           "AddressSanitizer, address space not limited\n");
#else
    struct rlimit limit = {256UL << 20, 256UL << 20};
    if (setrlimit(RLIMIT_AS, &limit) != 0)
        printf("NOTE parse_refuses_huge_count_without_allocating: "
               "setrlimit failed (%s); checking the status only\n",
               strerror(errno));
#endif
    char text[2048];
    rt_test_base_scene(text, sizeof text, 3, "2000000000", ALL, NULL, "\n");
    rt_scene *scene = NULL;
    rt_error error;
    rt_status status =
        rt_scene_parse(text, strlen(text), "<test>", NULL, &scene, &error);
    ck_assert_msg(status != RT_OK && status != RT_ERR_NOMEM,
                  "status %s: %s", rt_status_string(status), error.message);
    ck_assert_int_eq(error.line, 3);
}
END_TEST

START_TEST(load_reads_a_file_and_names_it_in_errors)
{
    char *dir = rt_test_temp_dir();
    rt_test_path good = rt_test_path_at(dir, "good.scn");
    rt_test_path bad = rt_test_path_at(dir, "bad.scn");
    char text[2048];
    rt_test_base_scene(text, sizeof text, 0, NULL, ALL, NULL, "\n");
    rt_test_write_file(good.s, text);
    rt_test_base_scene(text, sizeof text, 8, "1 2 3 0 255 0 0 0 1 1 0.5 2 9", ALL,
                       NULL, "\n");
    rt_test_write_file(bad.s, text);

    rt_scene *scene = NULL;
    rt_error error;
    rt_status status = rt_scene_load(good.s, NULL, &scene, &error);
    ck_assert_msg(status == RT_OK, "%s", error.message);
    rt_test_assert_base_scene(scene);
    rt_scene_destroy(scene);

    scene = NULL;
    status = rt_scene_load(bad.s, NULL, &scene, &error);
    bad_case c = {"file with 13 facet values", 0, NULL, 0, NULL, S_SYNTAX, 8,
                  29, "9", 1};
    check_error(&c, status, scene, &error, bad.s);
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(load_of_missing_file_is_io_error_naming_the_path)
{
    const char *path = "/nonexistent-rt-dir/no-such-scene.scn";
    rt_scene *scene = (rt_scene *)&path;
    rt_error error;
    memset(&error, 0, sizeof error);
    rt_status status = rt_scene_load(path, NULL, &scene, &error);
    ck_assert_int_eq(status, RT_ERR_IO);
    ck_assert_int_eq(error.status, RT_ERR_IO);
    ck_assert_ptr_null(scene);
    ck_assert_msg(strstr(error.message, path) != NULL, "message: \"%s\"",
                  error.message);
    ck_assert_int_eq(error.line, 0);
    ck_assert_int_eq(error.column, 0);
}
END_TEST

START_TEST(free_of_null_scene_does_nothing)
{
    rt_scene_destroy(NULL);
}
END_TEST

Suite *parse_suite(void);

Suite *parse_suite(void)
{
    Suite *suite = suite_create("parse");
    int n = (int)(sizeof bad_cases / sizeof bad_cases[0]);

    TCase *errors = tcase_create("errors");
    tcase_add_loop_test(errors,
                        parse_reports_status_position_and_token_of_each_broken_rule,
                        0, n);
    tcase_add_loop_test(errors, parse_reports_the_same_errors_with_crlf_line_endings,
                        0, n);
    tcase_add_test(errors, parse_columns_do_not_count_the_byte_order_mark);
    tcase_add_test(errors, parse_without_name_uses_memory_in_messages);
    tcase_add_test(errors, parse_accepts_a_null_error_pointer);
    tcase_add_test(errors, parse_reads_only_length_bytes);
    tcase_add_test(errors, parse_refuses_huge_count_without_allocating);
    suite_add_tcase(suite, errors);

    TCase *files = tcase_create("files");
    tcase_add_test(files, load_reads_a_file_and_names_it_in_errors);
    tcase_add_test(files, load_of_missing_file_is_io_error_naming_the_path);
    tcase_add_test(files, free_of_null_scene_does_nothing);
    suite_add_tcase(suite, files);
    return suite;
}

RT_CHECK_MAIN(parse_suite)
