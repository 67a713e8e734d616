/*
 * test_save_formats.c - what rt_image_save writes: PNG decoded back with
 * libpng to every byte of the image (when the library and the suite have
 * libpng), PNG without gamma or colour-space chunks, and the format chosen
 * from the path's extension whatever its case.
 */
#define _GNU_SOURCE 1

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#if RT_TEST_HAVE_LIBPNG
#include <png.h>
#endif

#include "testutil.h"

/* ------------------------------------------------------------------ */
/* Formats                                                              */

#if RT_TEST_HAVE_LIBPNG
/* Decodes PNG bytes as 8-bit RGB with libpng's simplified API; the pixels
 * are malloc'd, rows packed. */
static unsigned char *decode_png(const rt_test_bytes *png, int *width,
                                 int *height)
{
    png_image decoded;
    memset(&decoded, 0, sizeof decoded);
    decoded.version = PNG_IMAGE_VERSION;
    ck_assert_msg(png_image_begin_read_from_memory(&decoded, png->data,
                                                   png->size),
                  "libpng refused the header: %s", decoded.message);
    decoded.format = PNG_FORMAT_RGB;
    unsigned char *pixels = malloc(PNG_IMAGE_SIZE(decoded));
    ck_assert_ptr_nonnull(pixels);
    int ok = png_image_finish_read(&decoded, NULL, pixels, 0, NULL);
    if (!ok)
        free(pixels);
    ck_assert_msg(ok, "libpng could not decode it: %s", decoded.message);
    *width = (int)decoded.width;
    *height = (int)decoded.height;
    return pixels;
}
#endif

START_TEST(png_decodes_back_to_every_byte_of_the_image)
{
    char *dir = rt_test_temp_dir();
    rt_test_path path = rt_test_path_at(dir, "image.png");
    if (!rt_image_format_supported(RT_IMAGE_PNG)) {
        rt_image image = rt_test_pattern(4, 4);
        rt_error error = {0};
        ck_assert_int_eq(
            rt_image_save(path.s, &image, RT_IMAGE_PNG, NULL, &error),
            RT_ERR_FORMAT);
        ck_assert_msg(strstr(error.message, "libpng") != NULL,
                      "the refusal does not mention libpng: %s",
                      error.message);
        rt_test_bytes b = {NULL, 0, 0};
        ck_assert_int_eq(rt_image_write_to(rt_test_bytes_add, &b, &image,
                                           RT_IMAGE_PNG, NULL),
                         RT_ERR_FORMAT);
        ck_assert_uint_eq(b.size, 0);
        rt_test_assert_dir_holds(dir, "");
        rt_image_release(&image);
        rt_test_remove_dir(dir);
        fprintf(stderr, "test_save: this build has no PNG: checked the "
                        "refusal, round trip skipped\n");
        return;
    }
#if RT_TEST_HAVE_LIBPNG
    /* a view of 97 x 61 pixels with rows of 100: the padding must not
     * leak into the file */
    rt_image wide = rt_test_pattern(100, 61);
    rt_image view = wide;
    view.width = 97;
    rt_test_bytes png = rt_test_encode(&view, RT_IMAGE_PNG);
    int width = 0, height = 0;
    unsigned char *pixels = decode_png(&png, &width, &height);
    ck_assert_int_eq(width, view.width);
    ck_assert_int_eq(height, view.height);
    int bad_x = -1, bad_y = -1;
    for (int y = 0; y < height && bad_x < 0; y++)
        for (int x = 0; x < width && bad_x < 0; x++)
            if (memcmp(pixels + ((size_t)y * (size_t)width + (size_t)x) * 3,
                       rt_image_pixel(&view, x, y), 3) != 0)
                bad_x = x, bad_y = y;
    ck_assert_msg(bad_x < 0, "pixel (%d, %d) decodes to another colour",
                  bad_x, bad_y);
    /* the file holds the very bytes the sink got */
    rt_test_save_ok(path.s, &view, RT_IMAGE_PNG);
    ck_assert(rt_test_file_holds(path.s, png.data, png.size));
    rt_test_assert_dir_holds(dir, "image.png");
    free(pixels);
    free(png.data);
    rt_image_release(&wide);
    rt_test_remove_dir(dir);
#else
    rt_test_remove_dir(dir);
    ck_abort_msg("the library writes PNG but this test was built without "
                 "libpng to decode it (tests/save.cmake)");
#endif
}
END_TEST

static unsigned long be32(const unsigned char *p)
{
    return (unsigned long)p[0] << 24 | (unsigned long)p[1] << 16 |
           (unsigned long)p[2] << 8 | (unsigned long)p[3];
}

START_TEST(png_has_no_gamma_or_colour_space_chunk)
{
    if (!rt_image_format_supported(RT_IMAGE_PNG)) {
        fprintf(stderr, "test_save: this build has no PNG: chunk test "
                        "skipped\n");
        return;
    }
    rt_image image = rt_test_pattern(33, 17);
    rt_test_bytes png = rt_test_encode(&image, RT_IMAGE_PNG);
    static const unsigned char signature[8] = {0x89, 'P', 'N', 'G',
                                               '\r', '\n', 0x1a, '\n'};
    ck_assert_uint_gt(png.size, 8 + 25);
    ck_assert(memcmp(png.data, signature, 8) == 0);
    char types[1024] = "";
    size_t at_byte = 8;
    while (at_byte + 12 <= png.size) {
        unsigned long length = be32(png.data + at_byte);
        ck_assert_uint_le(length, png.size - at_byte - 12);
        char type[5];
        memcpy(type, png.data + at_byte + 4, 4);
        type[4] = '\0';
        ck_assert_uint_lt(strlen(types) + 6, sizeof types);
        strcat(types, types[0] ? " " : "");
        strcat(types, type);
        static const char *const forbidden[] = {"gAMA", "sRGB", "iCCP",
                                                "cHRM"};
        for (int i = 0; i < 4; i++)
            ck_assert_msg(strcmp(type, forbidden[i]) != 0,
                          "the PNG has a %s chunk (chunks: %s)", type,
                          types);
        at_byte += 12 + length;
    }
    ck_assert_uint_eq(at_byte, png.size);
    ck_assert_msg(strncmp(types, "IHDR ", 5) == 0 &&
                      strcmp(types + strlen(types) - 4, "IEND") == 0,
                  "chunks: %s", types);
    const unsigned char *header = png.data + 16;
    ck_assert_uint_eq(be32(header), 33);
    ck_assert_uint_eq(be32(header + 4), 17);
    ck_assert_uint_eq(header[8], 8);   /* bits per channel */
    ck_assert_uint_eq(header[9], 2);   /* RGB */
    ck_assert_uint_eq(header[12], 0);  /* not interlaced */
    free(png.data);
    rt_image_release(&image);
}
END_TEST

START_TEST(the_format_comes_from_the_extension_whatever_its_case)
{
    static const struct {
        const char *path;
        rt_status status;
        rt_image_format format;
    } cases[] = {
        {"out.png", RT_OK, RT_IMAGE_PNG},
        {"OUT.PNG", RT_OK, RT_IMAGE_PNG},
        {"dir/x.Png", RT_OK, RT_IMAGE_PNG},
        {"out.ppm", RT_OK, RT_IMAGE_P6},
        {"out.PPM", RT_OK, RT_IMAGE_P6},
        {"out.pnm", RT_OK, RT_IMAGE_P6},
        {"a.png.ppm", RT_OK, RT_IMAGE_P6},
        {"out.jpg", RT_ERR_FORMAT, 0},
        {"out", RT_ERR_FORMAT, 0},
        {"out.", RT_ERR_FORMAT, 0},
        {"out.pngx", RT_ERR_FORMAT, 0},
        {"dir.png/out", RT_ERR_FORMAT, 0},
        {".png", RT_ERR_FORMAT, 0},
        {"-", RT_ERR_FORMAT, 0},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        rt_image_format format = (rt_image_format)12345;
        rt_status status = rt_image_format_from_path(cases[i].path, &format,
                                                     NULL);
        ck_assert_msg(status == cases[i].status, "%s: %s", cases[i].path,
                      rt_status_string(status));
        rt_image_format expected = status == RT_OK ? cases[i].format
                                                   : (rt_image_format)12345;
        ck_assert_msg(format == expected, "%s: format %d, expected %d",
                      cases[i].path, (int)format, (int)expected);
    }
}
END_TEST

/* ------------------------------------------------------------------ */

static Suite *save_formats_suite(void)
{
    Suite *s = suite_create("save_formats");
    TCase *tc = tcase_create("formats");
    tcase_add_test(tc, png_decodes_back_to_every_byte_of_the_image);
    tcase_add_test(tc, png_has_no_gamma_or_colour_space_chunk);
    tcase_add_test(tc, the_format_comes_from_the_extension_whatever_its_case);
    suite_add_tcase(s, tc);
    return s;
}

RT_CHECK_MAIN(save_formats_suite)
