/*
 * test_ppm.c - PPM output and input (docs/rendering-model.md, "The image"):
 * P3 and P6 written to a memory sink read back identical, P3 lines of at
 * most 70 characters, strided images, the atomic save (a complete file,
 * nothing left behind on success or failure), comments in headers,
 * truncated or unsupported input refused with a message.
 */
#include "testutil.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A memory sink that fails after `fail_after` calls (< 0: never). */
typedef struct buffer {
    rt_test_bytes bytes;
    int fail_after;
} buffer;

static int buffer_write(void *user, const void *data, size_t size)
{
    buffer *b = user;
    if (b->fail_after == 0)
        return 0;
    if (b->fail_after > 0)
        b->fail_after--;
    ck_assert(rt_test_bytes_add(&b->bytes, data, size));
    return 1;
}

/* A w x h image of the support library's pattern (0, 255 and everything
 * between); its rows are `pad` bytes longer than needed. */
static rt_image make_pattern(int w, int h, size_t pad, unsigned char **memory)
{
    rt_image image = {w, h, (size_t)w * 3 + pad, NULL};
    *memory = malloc(image.stride * (size_t)h);
    ck_assert_ptr_nonnull(*memory);
    memset(*memory, 0xAB, image.stride * (size_t)h);
    image.pixels = *memory;
    rt_test_fill_pattern(&image);
    return image;
}

static void assert_same_pixels(const rt_image *a, const rt_image *b)
{
    ck_assert_int_eq(a->width, b->width);
    ck_assert_int_eq(a->height, b->height);
    int worst;
    long differing = rt_test_image_diff(a, b, &worst);
    ck_assert_msg(differing == 0, "%ld pixels differ (max difference %d)",
                  differing, worst);
}

static void round_trip(rt_image_format format, int w, int h)
{
    unsigned char *memory;
    rt_image image = make_pattern(w, h, 5, &memory);
    buffer out = {{NULL, 0, 0}, -1};
    ck_assert_int_eq(
        rt_image_write_to(buffer_write, &out, &image, format, NULL), RT_OK);
    ck_assert_uint_ge(out.bytes.size, 2);
    ck_assert_int_eq(out.bytes.data[0], 'P');
    ck_assert_int_eq(out.bytes.data[1], format == RT_IMAGE_P3 ? '3' : '6');
    rt_image back;
    rt_error error;
    rt_status status = rt_ppm_parse(out.bytes.data, out.bytes.size, "<sink>",
                                    &back, &error);
    ck_assert_msg(status == RT_OK, "%s", error.message);
    assert_same_pixels(&image, &back);
    rt_image_release(&back);
    free(out.bytes.data);
    free(memory);
}

START_TEST(p3_written_to_a_sink_reads_back_identical)
{
    round_trip(RT_IMAGE_P3, 23, 7);
    round_trip(RT_IMAGE_P3, 1, 1);
}
END_TEST

START_TEST(p6_written_to_a_sink_reads_back_identical)
{
    round_trip(RT_IMAGE_P6, 23, 7);
    round_trip(RT_IMAGE_P6, 1, 1);
}
END_TEST

START_TEST(p6_output_is_header_then_exactly_the_pixels)
{
    unsigned char *memory;
    rt_image image = make_pattern(4, 3, 7, &memory);
    buffer out = {{NULL, 0, 0}, -1};
    ck_assert_int_eq(rt_image_write_to(buffer_write, &out, &image,
                                       RT_IMAGE_P6, NULL),
                     RT_OK);
    const char *header = "P6\n4 3\n255\n";
    size_t header_size = strlen(header);
    ck_assert_uint_eq(out.bytes.size, header_size + 4 * 3 * 3);
    /* the header may be laid out differently, but its size is fixed by the
     * pixel count: check the pixels row by row after it */
    size_t start = out.bytes.size - 4 * 3 * 3;
    for (int y = 0; y < 3; y++)
        ck_assert_int_eq(memcmp(out.bytes.data + start + (size_t)y * 12,
                                rt_image_pixel(&image, 0, y), 12),
                         0);
    free(out.bytes.data);
    free(memory);
}
END_TEST

START_TEST(p3_lines_are_at_most_70_characters)
{
    /* pass 0: every value has three digits (the worst case); pass 1: the
     * pattern, with values of one to three digits */
    for (int pass = 0; pass < 2; pass++) {
        unsigned char *memory;
        rt_image image = make_pattern(40, 5, 0, &memory);
        if (pass == 0)
            for (int y = 0; y < 5; y++)
                memset(rt_image_pixel(&image, 0, y), 255, 40 * 3);
        buffer out = {{NULL, 0, 0}, -1};
        ck_assert_int_eq(
            rt_image_write_to(buffer_write, &out, &image, RT_IMAGE_P3,
                              NULL), RT_OK);
        size_t line_length = 0, longest = 0, lines = 0;
        for (size_t i = 0; i < out.bytes.size; i++) {
            if (out.bytes.data[i] == '\n') {
                lines++;
                line_length = 0;
            } else if (++line_length > longest) {
                longest = line_length;
            }
        }
        ck_assert_msg(longest <= 70, "a P3 line has %zu characters", longest);
        ck_assert_msg(out.bytes.size > 0 &&
                          out.bytes.data[out.bytes.size - 1] == '\n',
                      "P3 output does not end with a newline");
        /* 600 values of up to 4 characters need more than 5 lines */
        ck_assert_uint_gt(lines, 5);
        free(out.bytes.data);
        free(memory);
    }
}
END_TEST

START_TEST(failing_sink_makes_the_writer_fail)
{
    unsigned char *memory;
    rt_image image = make_pattern(8, 8, 0, &memory);
    for (int format = 0; format < 2; format++) {
        for (int after = 0; after < 3; after++) {
            buffer out = {{NULL, 0, 0}, after};
            rt_status status = rt_image_write_to(
                buffer_write, &out, &image, format ? RT_IMAGE_P6 : RT_IMAGE_P3,
                NULL);
            /* a writer that made fewer calls than `after` + 1 has not met
             * the failure */
            if (out.fail_after == 0)
                ck_assert_msg(status != RT_OK,
                              "sink failed after %d calls, writer said OK",
                              after);
            free(out.bytes.data);
        }
    }
    free(memory);
}
END_TEST

START_TEST(reader_accepts_comments_in_headers)
{
    const char p3[] = "P3\n# made by hand\n2 1 # size\n#maxval next\n255\n"
                      "255 0 0  0 128 255\n";
    rt_image image;
    rt_error error;
    rt_status status = rt_ppm_parse(p3, strlen(p3), "<p3>", &image, &error);
    ck_assert_msg(status == RT_OK, "%s", error.message);
    ck_assert_int_eq(image.width, 2);
    ck_assert_int_eq(image.height, 1);
    const unsigned char *p = rt_image_pixel(&image, 1, 0);
    ck_assert_int_eq(p[0], 0);
    ck_assert_int_eq(p[1], 128);
    ck_assert_int_eq(p[2], 255);
    rt_image_release(&image);

    const char p6[] = "P6\n# comment\n2 # w\n1\n# last\n255\n"
                      "\x01\x02\x03\x0a\x23\xff";
    status = rt_ppm_parse(p6, sizeof p6 - 1, "<p6>", &image, &error);
    ck_assert_msg(status == RT_OK, "%s", error.message);
    p = rt_image_pixel(&image, 1, 0);
    /* 0x0a and 0x23 ('#') are pixel data here, not a newline or comment */
    ck_assert_int_eq(p[0], 0x0a);
    ck_assert_int_eq(p[1], 0x23);
    ck_assert_int_eq(p[2], 0xff);
    rt_image_release(&image);
}
END_TEST

static void assert_refused(const char *data, size_t size, const char *what)
{
    rt_image image = {1, 1, 3, (unsigned char *)&image};
    rt_error error;
    memset(&error, 0, sizeof error);
    rt_status status = rt_ppm_parse(data, size, "<bad>", &image, &error);
    ck_assert_msg(status != RT_OK, "%s: accepted", what);
    ck_assert_msg(image.pixels == NULL, "%s: pixels not NULL after failure",
                  what);
    ck_assert_msg(error.message[0] != '\0', "%s: empty message", what);
    ck_assert_msg(strncmp(error.message, "<bad>", 5) == 0,
                  "%s: message does not name the input: \"%s\"", what,
                  error.message);
}

START_TEST(truncated_input_is_refused_with_a_message)
{
    const char p6[] = "P6\n2 2\n255\n\x01\x02\x03\x04\x05\x06\x07\x08\x09";
    assert_refused(p6, sizeof p6 - 1, "P6 missing 3 bytes");
    assert_refused(p6, 7, "P6 cut in the header");
    const char p3[] = "P3\n2 1\n255\n1 2 3 4 5\n";
    assert_refused(p3, sizeof p3 - 1, "P3 missing a value");
    assert_refused("", 0, "empty input");
    assert_refused("P6", 2, "magic number only");
}
END_TEST

START_TEST(unsupported_or_malformed_input_is_refused)
{
    const char maxval[] = "P3\n1 1\n65535\n1 2 3\n";
    assert_refused(maxval, sizeof maxval - 1, "maxval 65535");
    const char p5[] = "P5\n1 1\n255\n\x01";
    assert_refused(p5, sizeof p5 - 1, "P5 (grey)");
    const char big[] = "P3\n1 1\n255\n1 256 3\n";
    assert_refused(big, sizeof big - 1, "value above maxval");
    const char zero[] = "P3\n0 1\n255\n";
    assert_refused(zero, sizeof zero - 1, "zero width");
    const char huge[] = "P6\n100000 100000\n255\n\x01\x02\x03";
    assert_refused(huge, sizeof huge - 1, "size past the limit");
}
END_TEST

START_TEST(save_writes_a_complete_file_and_leaves_no_temporary)
{
    char *dir = rt_test_temp_dir();
    rt_test_path out = rt_test_path_at(dir, "out.ppm");
    const char *path = out.s;
    unsigned char *memory;
    rt_image image = make_pattern(31, 17, 2, &memory);
    for (int format = 0; format < 2; format++) {
        rt_error error;
        rt_status status = rt_image_save(
            path, &image, format ? RT_IMAGE_P6 : RT_IMAGE_P3, NULL, &error);
        ck_assert_msg(status == RT_OK, "%s", error.message);
        rt_test_assert_dir_holds(dir, "out.ppm");
        rt_image back;
        status = rt_ppm_load(path, &back, &error);
        ck_assert_msg(status == RT_OK, "%s", error.message);
        assert_same_pixels(&image, &back);
        rt_image_release(&back);
    }
    free(memory);
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(save_replaces_an_existing_file)
{
    char *dir = rt_test_temp_dir();
    rt_test_path out = rt_test_path_at(dir, "out.ppm");
    const char *path = out.s;
    FILE *file = fopen(path, "w");
    ck_assert_ptr_nonnull(file);
    fputs("old contents, much longer than the new image would be if the save "
          "wrote over it in place without truncating; padding padding "
          "padding padding padding padding padding padding padding padding",
          file);
    fclose(file);
    unsigned char *memory;
    rt_image image = make_pattern(2, 2, 0, &memory);
    rt_error error;
    ck_assert_int_eq(rt_image_save(path, &image, RT_IMAGE_P6, NULL, &error),
                     RT_OK);
    rt_image back;
    rt_status status = rt_ppm_load(path, &back, &error);
    ck_assert_msg(status == RT_OK, "%s", error.message);
    assert_same_pixels(&image, &back);
    rt_image_release(&back);
    rt_test_assert_dir_holds(dir, "out.ppm");
    free(memory);
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(save_to_a_missing_directory_fails_and_leaves_nothing)
{
    char *dir = rt_test_temp_dir();
    rt_test_path out = rt_test_path_at(dir, "no-such-dir/out.ppm");
    const char *path = out.s;
    unsigned char *memory;
    rt_image image = make_pattern(2, 2, 0, &memory);
    rt_error error;
    memset(&error, 0, sizeof error);
    ck_assert_int_eq(rt_image_save(path, &image, RT_IMAGE_P3, NULL, &error),
                     RT_ERR_IO);
    ck_assert_int_eq(error.status, RT_ERR_IO);
    ck_assert_msg(strstr(error.message, path) != NULL,
                  "message does not name the path: \"%s\"", error.message);
    rt_test_assert_dir_holds(dir, "");
    free(memory);
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(load_of_a_missing_file_is_an_io_error)
{
    rt_image image;
    rt_error error;
    const char *path = "/nonexistent-rt-dir/image.ppm";
    ck_assert_int_eq(rt_ppm_load(path, &image, &error), RT_ERR_IO);
    ck_assert_ptr_null(image.pixels);
    ck_assert_msg(strstr(error.message, path) != NULL, "\"%s\"",
                  error.message);
}
END_TEST

START_TEST(image_create_and_destroy_follow_the_contract)
{
    rt_image image;
    ck_assert_int_eq(rt_image_init(&image, 3, 2, NULL), RT_OK);
    ck_assert_int_eq(image.width, 3);
    ck_assert_int_eq(image.height, 2);
    ck_assert_uint_eq(image.stride, 9);
    for (int y = 0; y < 2; y++)
        for (int x = 0; x < 9; x++)
            ck_assert_int_eq(image.pixels[(size_t)y * image.stride + x], 0);
    rt_image_release(&image);
    ck_assert_ptr_null(image.pixels);
    rt_image_release(&image); /* a zeroed image is a no-op */
    ck_assert_int_ne(rt_image_init(&image, 0, 2, NULL), RT_OK);
    ck_assert_ptr_null(image.pixels);
    ck_assert_int_ne(rt_image_init(&image, 2, RT_MAX_IMAGE_SIDE + 1, NULL),
                     RT_OK);
    ck_assert_ptr_null(image.pixels);
}
END_TEST

Suite *ppm_suite(void);

Suite *ppm_suite(void)
{
    Suite *suite = suite_create("ppm");
    TCase *write = tcase_create("write");
    tcase_add_test(write, p3_written_to_a_sink_reads_back_identical);
    tcase_add_test(write, p6_written_to_a_sink_reads_back_identical);
    tcase_add_test(write, p6_output_is_header_then_exactly_the_pixels);
    tcase_add_test(write, p3_lines_are_at_most_70_characters);
    tcase_add_test(write, failing_sink_makes_the_writer_fail);
    suite_add_tcase(suite, write);

    TCase *read = tcase_create("read");
    tcase_add_test(read, reader_accepts_comments_in_headers);
    tcase_add_test(read, truncated_input_is_refused_with_a_message);
    tcase_add_test(read, unsupported_or_malformed_input_is_refused);
    tcase_add_test(read, load_of_a_missing_file_is_an_io_error);
    tcase_add_test(read, image_create_and_destroy_follow_the_contract);
    suite_add_tcase(suite, read);

    TCase *save = tcase_create("save");
    tcase_add_test(save, save_writes_a_complete_file_and_leaves_no_temporary);
    tcase_add_test(save, save_replaces_an_existing_file);
    tcase_add_test(save, save_to_a_missing_directory_fails_and_leaves_nothing);
    suite_add_tcase(suite, save);
    return suite;
}

RT_CHECK_MAIN(ppm_suite)
