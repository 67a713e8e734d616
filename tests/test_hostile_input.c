/*
 * test_hostile_input.c - bad input (the first part of the hostile suites):
 * the loaders fed what the fuzzer found and what an attacker would try -
 * counts that promise more than the file holds, a megabyte of digits, a line
 * of commas, image headers promising more pixels than the file holds - are
 * refused with a message that says why, before allocating what the input
 * does not justify.
 *
 * Tests that need a child process fork one themselves, so that they also
 * hold under CK_FORK=no (valgrind).
 */
#define _GNU_SOURCE 1

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <math.h>
#include <sched.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "testutil.h"

/* ------------------------------------------------------------------ */
/* Findings of the fuzzer and of reading the loaders, kept as tests     */

/* Every file of a corpus directory: a refusal has a status and a message;
 * an accepted scene answers the accessors and traces its corner pixels. */
START_TEST(scene_corpus_replays_without_fault)
{
    const char *dir_path = rt_test_source_path("tests/fuzz/corpus/scene");
    char *dir = strdup(dir_path);
    DIR *d = opendir(dir);
    ck_assert_msg(d != NULL, "%s: %s", dir, strerror(errno));
    int files = 0, loaded = 0;
    struct dirent *entry;
    while ((entry = readdir(d)) != NULL) {
        if (entry->d_name[0] == '.')
            continue;
        char *path = rt_test_join(dir, entry->d_name);
        size_t size;
        char *data = rt_test_read_file(path, &size);
        ck_assert_ptr_nonnull(data);
        rt_scene *scene = (rt_scene *)1;
        rt_error error;
        memset(&error, 0, sizeof error);
        rt_status status =
            rt_scene_parse(data, size, entry->d_name, NULL, &scene, &error);
        int valid = strncmp(entry->d_name, "valid-", 6) == 0;
        int broken = strncmp(entry->d_name, "broken-", 7) == 0;
        ck_assert_msg(!valid || status == RT_OK, "%s: %s", entry->d_name,
                      error.message);
        ck_assert_msg(!broken || status != RT_OK, "%s loaded",
                      entry->d_name);
        if (status == RT_OK) {
            rt_scene_info info = {.size = sizeof info};
            rt_scene_get_info(scene, &info);
            rt_ray ray = rt_camera_ray(&info.camera, info.width - 1,
                                       info.height - 1);
            (void)rt_trace(scene, ray, 5);
            rt_scene_destroy(scene);
            loaded++;
        } else {
            ck_assert_ptr_null(scene);
            ck_assert_msg(error.message[0] != '\0', "%s: no message",
                          entry->d_name);
        }
        free(data);
        free(path);
        files++;
    }
    closedir(d);
    free(dir);
    ck_assert_int_ge(files, 10);
    ck_assert_int_ge(loaded, 3);
}
END_TEST

/* A count far beyond the lines of the file is refused with a message that
 * says how many lines there are, before anything is allocated for it. */
START_TEST(count_beyond_the_file_is_refused_with_the_lines_left)
{
    static const char text[] =
        "0 0 10\n0 0 5 4 0 5 8 8\n2147483647\n0 0 0\n1 0 0\n";
    rt_error error;
    ck_assert_int_eq(rt_test_parse_refused(text, sizeof text - 1, &error),
                     RT_ERR_LIMIT);
    ck_assert_int_eq(error.line, 3);
    ck_assert_int_eq(error.column, 1);
    ck_assert_str_eq(error.message,
                     "hostile.scn:3:1: expected a vertex count of at most 2 "
                     "(the lines left in the file), found `2147483647`");
}
END_TEST

START_TEST(count_beyond_int_is_refused_as_out_of_range)
{
    static const char text[] =
        "0 0 10\n0 0 5 4 0 5 8 8\n0\n99999999999999999999\n";
    rt_error error;
    ck_assert_int_eq(rt_test_parse_refused(text, sizeof text - 1, &error),
                     RT_ERR_RANGE);
    ck_assert_int_eq(error.line, 4);
    ck_assert_ptr_nonnull(strstr(error.message, "a facet count"));
}
END_TEST

START_TEST(image_side_beyond_the_limit_is_refused)
{
    static const char text[] = "0 0 10\n0 0 5 4 0 5 16385 1\n";
    rt_error error;
    ck_assert_int_eq(rt_test_parse_refused(text, sizeof text - 1, &error),
                     RT_ERR_RANGE);
    ck_assert_str_eq(error.message,
                     "hostile.scn:2:13: expected an image width (a whole "
                     "number in 1..16384), found `16385`");
}
END_TEST

/* The input is read by length: no NUL after it, none needed, and a NUL
 * inside is a bad byte like any other. */
START_TEST(scene_without_terminating_nul_is_read_by_length)
{
    size_t length = strlen(rt_test_small_scene);
    char *exact = malloc(length);
    ck_assert_ptr_nonnull(exact);
    memcpy(exact, rt_test_small_scene, length);
    rt_scene *scene;
    rt_error error;
    ck_assert_int_eq(rt_scene_parse(exact, length, NULL, NULL, &scene, &error),
                     RT_OK);
    rt_scene_destroy(scene);
    /* every prefix is refused, with a message, until the last record
     * "0 0 4 255 255 255" has its sixth value; then every prefix loads */
    size_t complete = (size_t)(strstr(rt_test_small_scene,
                                      "0 0 4 255 255 255") -
                               rt_test_small_scene) + strlen("0 0 4 255 255 ");
    for (size_t n = 0; n < length; n++) {
        rt_status status =
            rt_scene_parse(exact, n, NULL, NULL, &scene, &error);
        if (n > complete) {
            ck_assert_msg(status == RT_OK, "prefix %zu: %s", n,
                          error.message);
            rt_scene_destroy(scene);
            continue;
        }
        ck_assert_msg(status != RT_OK, "a prefix of %zu bytes loaded", n);
        ck_assert_ptr_null(scene);
        ck_assert_msg(error.message[0] != '\0', "prefix %zu: no message", n);
    }
    free(exact);
    /* a NUL byte: no scene file holds one; the message says the file is
     * binary, at the byte's position */
    static const char nul_inside[] = "0 0 1\0" "0\n";
    ck_assert_int_eq(rt_test_parse_refused(nul_inside, sizeof nul_inside - 1,
                                           &error),
                     RT_ERR_FORMAT);
    ck_assert_str_eq(error.message,
                     "hostile.scn:1:6: expected text, found a NUL byte: the "
                     "file is binary, not a scene");
}
END_TEST

/* A number token longer than any number needs is refused by its length,
 * without copying it. */
START_TEST(megabyte_number_is_refused_as_too_long)
{
    size_t length = 1 << 20;
    char *text = malloc(length);
    ck_assert_ptr_nonnull(text);
    memset(text, '7', length);
    memcpy(text, "0 0 ", 4);
    rt_error error;
    ck_assert_int_eq(rt_test_parse_refused(text, length, &error), RT_ERR_LIMIT);
    ck_assert_str_eq(error.message,
                     "hostile.scn:1:5: expected a number of at most 256 "
                     "characters, found `7777777777777777777777777777777777777777"
                     "...`");
    free(text);
}
END_TEST

START_TEST(line_of_commas_is_refused_at_the_first_stray_comma)
{
    size_t length = 1000000;
    char *text = malloc(length);
    ck_assert_ptr_nonnull(text);
    memset(text, ',', length);
    rt_error error;
    ck_assert_int_eq(rt_test_parse_refused(text, length, &error),
                     RT_ERR_SYNTAX);
    ck_assert_str_eq(error.message,
                     "hostile.scn:1:1: expected a number, found `,`");
    /* values then a million commas: the thirteenth value (one more than
     * the longest record, a facet with highlights, holds) is the error,
     * found before the commas are read */
    memcpy(text, "1,2,3,4,5,6,7,8,9,10,11,12,13", 29);
    ck_assert_int_eq(rt_test_parse_refused(text, length, &error),
                     RT_ERR_SYNTAX);
    ck_assert_str_eq(error.message,
                     "hostile.scn:1:28: expected the end of the line, found "
                     "`13`");
    /* a complete observer, then a million commas on the next line */
    memset(text, ',', length);
    memcpy(text, "0,0,0\n1,", 8);
    ck_assert_int_eq(rt_test_parse_refused(text, length, &error),
                     RT_ERR_SYNTAX);
    ck_assert_str_eq(error.message,
                     "hostile.scn:2:3: expected a number, found `,`");
    free(text);
}
END_TEST

/*
 * A P3 header promising 16384 x 16384 pixels in a 20-byte file must be
 * refused before the 805 MB image is allocated: a P3 file needs at least
 * two bytes per value, so the header can be checked against what is left,
 * as the P6 reader already does.  Found by fuzz_ppm
 * (tests/fuzz/corpus/ppm/p3-huge-header.ppm); checked here under an
 * address-space limit, which does not work under AddressSanitizer or
 * valgrind (both reserve far more address space than they use).
 */
typedef struct bounded_parse {
    const char *data;
    size_t length;
    int is_image;
    size_t limit;           /* bytes of address space the parse may add */
} bounded_parse;

static int parse_with_memory_limit(void *arg, char *message, size_t size)
{
    const bounded_parse *b = arg;
    if (!rt_test_limit_address_space(b->limit, message, size))
        return 2;
    rt_error error;
    rt_status status;
    if (b->is_image) {
        rt_image image;
        status = rt_ppm_parse(b->data, b->length, "hostile.ppm", &image,
                              &error);
        rt_image_release(&image);
    } else {
        rt_scene *scene;
        status = rt_scene_parse(b->data, b->length, "hostile.scn", NULL,
                                &scene, &error);
        rt_scene_destroy(scene);
    }
    snprintf(message, size, "%s: %s", rt_status_string(status),
             status == RT_OK ? "loaded" : error.message);
    return status == RT_ERR_NOMEM ? 1 : 0;
}

static int memory_limit_unavailable(void)
{
    if (RT_TEST_UNDER_ASAN || rt_test_under_valgrind()) {
        fprintf(stderr,
                "test_hostile_input: address-space limits skipped under "
                "a sanitizer or valgrind\n");
        return 1;
    }
    return 0;
}

START_TEST(ppm_header_promising_more_pixels_than_the_file_holds_is_refused_before_allocating)
{
    static const char text[] = "P3\n16384 16384\n255\n1";
    rt_image image;
    rt_error error;
    ck_assert_int_eq(rt_ppm_parse(text, sizeof text - 1, "hostile.ppm",
                                  &image, &error),
                     RT_ERR_SYNTAX);
    ck_assert_ptr_null(image.pixels);
    if (memory_limit_unavailable())
        return;
    bounded_parse b = {text, sizeof text - 1, 1, 64u << 20};
    char message[1024];
    int code = rt_test_in_child(parse_with_memory_limit, &b, message,
                                sizeof message);
    ck_assert_msg(code == 0,
                  "a 20-byte P3 file made the reader allocate more than "
                  "64 MB: %s", message);
}
END_TEST

START_TEST(scene_counts_promising_more_than_the_file_holds_are_refused_before_allocating)
{
    static const char *const texts[] = {
        "0 0 10\n0 0 5 4 0 5 8 8\n2147483647\n",
        "0 0 10\n0 0 5 4 0 5 8 8\n0\n2147483647\n1 1 1 0 0 0 0\n",
    };
    if (memory_limit_unavailable())
        return;
    for (size_t i = 0; i < sizeof texts / sizeof *texts; i++) {
        bounded_parse b = {texts[i], strlen(texts[i]), 0, 16u << 20};
        char message[1024];
        int code = rt_test_in_child(parse_with_memory_limit, &b, message,
                                    sizeof message);
        ck_assert_msg(code == 0, "case %zu ran out of 16 MB: %s", i,
                      message);
        ck_assert_msg(strstr(message, "loaded") == NULL, "case %zu: %s", i,
                      message);
    }
}
END_TEST

/*
 * A refusal names the bad byte in printable form, as the scene loader does
 * (`?` for what cannot be shown): a NUL would cut the message short, and a
 * control byte from a hostile file would reach the user's terminal.
 */
START_TEST(ppm_refusal_shows_bad_bytes_as_printable_text)
{
    static const char *const inputs[] = {"P6\n1\0 1\n255\n",
                                         "P6\n1\x1b[2J 1\n255\n",
                                         "P6\n1 1\n255\xff"};
    static const size_t lengths[] = {12, 15, 11};
    for (int i = 0; i < 3; i++) {
        rt_image image;
        rt_error error;
        rt_status status = rt_ppm_parse(inputs[i], lengths[i], "in.ppm",
                                        &image, &error);
        ck_assert_int_eq(status, RT_ERR_SYNTAX);
        size_t length = strlen(error.message);
        for (size_t k = 0; k < length; k++)
            ck_assert_msg(error.message[k] >= 0x20 && error.message[k] < 0x7f,
                          "input %d: byte %zu of the message is 0x%02x", i,
                          k, (unsigned char)error.message[k]);
        int quotes = 0;
        for (size_t k = 0; k < length; k++)
            quotes += error.message[k] == '`';
        ck_assert_msg(quotes % 2 == 0, "input %d: the message is cut short: "
                      "%s", i, error.message);
    }
}
END_TEST

/* A zero width is refused where it stands, saying what was found. */
START_TEST(ppm_zero_width_is_refused_at_the_width)
{
    static const char text[] = "P6\n0 1\n255\n";
    rt_image image;
    rt_error error;
    ck_assert_int_eq(rt_ppm_parse(text, sizeof text - 1, "in.ppm", &image,
                                  &error),
                     RT_ERR_RANGE);
    ck_assert_msg(error.line == 2 && error.column == 1,
                  "the error is at %d:%d, not at the width (2:1): %s",
                  error.line, error.column, error.message);
    ck_assert_msg(strstr(error.message, "width") &&
                      strstr(error.message, "found 0"),
                  "the message does not say the width was 0: %s",
                  error.message);
}
END_TEST

static Suite *hostile_input_suite(void)
{
    Suite *s = suite_create("hostile_input");
    TCase *tc = tcase_create("fuzz findings and limits");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, scene_corpus_replays_without_fault);
    tcase_add_test(tc, count_beyond_the_file_is_refused_with_the_lines_left);
    tcase_add_test(tc, count_beyond_int_is_refused_as_out_of_range);
    tcase_add_test(tc, image_side_beyond_the_limit_is_refused);
    tcase_add_test(tc, scene_without_terminating_nul_is_read_by_length);
    tcase_add_test(tc, megabyte_number_is_refused_as_too_long);
    tcase_add_test(tc, line_of_commas_is_refused_at_the_first_stray_comma);
    tcase_add_test(tc, ppm_header_promising_more_pixels_than_the_file_holds_is_refused_before_allocating);
    tcase_add_test(tc, scene_counts_promising_more_than_the_file_holds_are_refused_before_allocating);
    tcase_add_test(tc, ppm_refusal_shows_bad_bytes_as_printable_text);
    tcase_add_test(tc, ppm_zero_width_is_refused_at_the_width);
    suite_add_tcase(s, tc);
    return s;
}

RT_CHECK_MAIN(hostile_input_suite)
