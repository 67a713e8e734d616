/*
 * test_float_output.c - linear float output (raytrace/image.h's
 * rt_image_float, rt_render_options.linear): every float of a render,
 * rounded as the renderer rounds (rt_channel_to_byte(255 * value)), is the
 * byte of the 8-bit image rendered beside it and of rt-export's PPM; some
 * exceed 1.0 (unclamped: a scene of three white lights, the teapot's
 * highlights); the PFM file read back by a parser of our own holds those
 * floats bit for bit, rows bottom to top; a region's floats are the whole
 * image's there; debug views refuse a linear image.  The `exr` entry reads
 * the OpenEXR file back through OpenEXR's C API, and exits 77 (a visible
 * skip) in a build without OpenEXR.  Under valgrind the renders are
 * half as wide and high (shrink()).
 */
#define _GNU_SOURCE 1

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if RT_TEST_HAVE_OPENEXR
#include <openexr.h>
#endif

#include "testutil.h"

/* cubes.scn lit by two more white lights: the top face then gets more
 * than 255 in green. */
static rt_scene *load_scene(const char *name, int more_lights)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/scenes/%s", RT_SOURCE_DIR, name);
    size_t size = 0;
    char *text = rt_test_read_file(path, &size);
    ck_assert_msg(text != NULL, "cannot read %s", path);
    if (more_lights) {
        static const char extra[] = "\n-6, -4, 9, 255, 255, 255\n"
                                    "3, -8, 6, 255, 255, 255\n";
        text = realloc(text, size + sizeof extra);
        ck_assert_ptr_nonnull(text);
        memcpy(text + size, extra, sizeof extra);
        size += sizeof extra - 1;
    }
    rt_scene *scene = NULL;
    rt_error error = {0};
    ck_assert_msg(rt_scene_parse(text, size, path, NULL, &scene, &error) ==
                      RT_OK,
                  "%s: %s", path, error.message);
    free(text);
    return scene;
}

/* Under valgrind (.ci/memcheck sets RT_TEST_MEMCHECK) every render is
 * half as wide and as high, a quarter of the rays on the same code paths:
 * shrink() gives a size or a pixel coordinate at that scale. */
static int shrink(int value)
{
    return rt_test_memcheck() ? value / 2 : value;
}

/* A render of `scene` with `samples`, bytes and floats; returns how many
 * floats exceed 1.0, after checking every one against its byte. */
static int render_both(const rt_scene *scene, int samples, rt_region region,
                       rt_image *image, rt_image_float *linear)
{
    rt_render_options options;
    rt_render_options_init(&options);
    options.samples = samples;
    rt_error error = {0};
    int width = 0, height = 0;
    ck_assert_int_eq(rt_render_image_size(scene, &options, &width, &height,
                                          &error), RT_OK);
    options.width = shrink(width);
    options.height = shrink(height);
    options.region = region;
    ck_assert_int_eq(rt_render_image_size(scene, &options, &width, &height,
                                          &error), RT_OK);
    ck_assert_int_eq(rt_image_init(image, width, height, &error), RT_OK);
    ck_assert_int_eq(rt_image_float_init(linear, width, height, &error),
                     RT_OK);
    /* NaN everywhere first: a float the render forgot shows */
    for (size_t i = 0; i < (size_t)width * height * 3; i++)
        linear->pixels[i] = NAN;
    options.linear = linear;
    ck_assert_msg(rt_render(scene, &options, image, &error) == RT_OK, "%s",
                  error.message);
    /* the bytes of a render without floats are the same */
    rt_image plain;
    ck_assert_int_eq(rt_image_init(&plain, width, height, &error), RT_OK);
    options.linear = NULL;
    ck_assert_int_eq(rt_render(scene, &options, &plain, &error), RT_OK);
    ck_assert_mem_eq(plain.pixels, image->pixels, (size_t)width * height * 3);
    rt_image_release(&plain);
    int above = 0;
    for (int y = 0; y < height; y++) {
        for (int x = 0; x < width; x++) {
            const float *f = rt_image_float_pixel(linear, x, y);
            const unsigned char *b = rt_image_pixel(image, x, y);
            for (int c = 0; c < 3; c++) {
                ck_assert_msg(isfinite(f[c]) && f[c] >= 0.0f,
                              "pixel %d,%d channel %d: %g", x, y, c, f[c]);
                ck_assert_msg(rt_channel_to_byte(255.0 * (double)f[c]) ==
                                  b[c],
                              "pixel %d,%d channel %d: float %.9g rounds to "
                              "%d, the byte is %d", x, y, c, f[c],
                              rt_channel_to_byte(255.0 * (double)f[c]), b[c]);
                above += f[c] > 1.0f;
            }
        }
    }
    return above;
}

static const rt_region WHOLE = {0, 0, 0, 0};

START_TEST(every_float_rounds_to_its_byte_in_shipped_scenes)
{
    static const char *const names[] = {"cubes.scn", "teapot.scn",
                                        "glass.scn", "smooth-glass.scn",
                                        "focus.scn"};
    int above_teapot = 0;
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        rt_scene *scene = load_scene(names[i], 0);
        rt_image image;
        rt_image_float linear;
        int above = render_both(scene, 1, WHOLE, &image, &linear);
        if (strcmp(names[i], "teapot.scn") == 0)
            above_teapot = above;
        rt_image_release(&image);
        rt_image_float_release(&linear);
        rt_scene_destroy(scene);
    }
    ck_assert_msg(above_teapot > 0, "no highlight of the teapot above 1.0");
}
END_TEST

START_TEST(three_lights_exceed_white_and_samples_are_averaged_first)
{
    rt_scene *scene = load_scene("cubes.scn", 1);
    rt_image image;
    rt_image_float linear;
    int above = render_both(scene, 4, WHOLE, &image, &linear);
    ck_assert_msg(above > 1000, "only %d floats above 1.0", above);
    int saturated = 0;
    for (size_t i = 0; i < (size_t)image.width * image.height * 3; i++)
        saturated += image.pixels[i] == 255 &&
                     linear.pixels[i] > 300.0f / 255.0f;
    ck_assert_msg(saturated > 0, "no byte clamped from more than 300");
    rt_image_release(&image);
    rt_image_float_release(&linear);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(a_region_holds_the_whole_image_floats_there)
{
    rt_scene *scene = load_scene("teapot.scn", 0);
    rt_image whole, part;
    rt_image_float whole_f, part_f;
    render_both(scene, 1, WHOLE, &whole, &whole_f);
    rt_region region = {shrink(37), shrink(21), shrink(150), shrink(99)};
    render_both(scene, 1, region, &part, &part_f);
    for (int y = 0; y < part_f.height; y++)
        ck_assert_mem_eq(rt_image_float_pixel(&part_f, 0, y),
                         rt_image_float_pixel(&whole_f, region.x0,
                                              region.y0 + y),
                         sizeof(float) * 3 * (size_t)part_f.width);
    rt_image_release(&whole);
    rt_image_release(&part);
    rt_image_float_release(&whole_f);
    rt_image_float_release(&part_f);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(a_debug_view_or_a_wrong_size_refuses_the_linear_image)
{
    rt_scene *scene = load_scene("cubes.scn", 0);
    rt_image image;
    rt_image_float linear, small;
    rt_error error = {0};
    ck_assert_int_eq(rt_image_init(&image, 400, 400, &error), RT_OK);
    ck_assert_int_eq(rt_image_float_init(&linear, 400, 400, &error), RT_OK);
    ck_assert_int_eq(rt_image_float_init(&small, 40, 400, &error), RT_OK);
    rt_render_options options;
    rt_render_options_init(&options);
    options.linear = &linear;
    ck_assert_int_eq(rt_render_view(scene, &options, RT_VIEW_NORMAL, 0,
                                    &image, &error), RT_ERR_ARGUMENT);
    ck_assert_msg(strstr(error.message, "linear") != NULL, "%s",
                  error.message);
    options.linear = &small;
    ck_assert_int_eq(rt_render(scene, &options, &image, &error),
                     RT_ERR_ARGUMENT);
    ck_assert_msg(strstr(error.message, "40 x 400") != NULL, "%s",
                  error.message);
    /* and an 8-bit image is no PFM */
    rt_test_bytes bytes = {0};
    ck_assert_int_eq(rt_image_write_to(rt_test_bytes_add, &bytes, &image,
                                       RT_IMAGE_PFM, &error),
                     RT_ERR_FORMAT);
    free(bytes.data);
    rt_image_release(&image);
    rt_image_float_release(&linear);
    rt_image_float_release(&small);
    rt_scene_destroy(scene);
}
END_TEST

/* ---- PFM read back ---------------------------------------------------- */

/* Our own PFM reader: "PF\n", "W H\n", a negative scale (little endian),
 * then rows bottom to top; the floats go into *image top to bottom. */
static void read_pfm(const char *data, size_t size, rt_image_float *image)
{
    int width = 0, height = 0, used = 0;
    double scale = 0.0;
    ck_assert_msg(sscanf(data, "PF\n%d %d\n%lf%n", &width, &height, &scale,
                         &used) == 3,
                  "not a PFM header");
    ck_assert_msg(scale < 0.0, "scale %g: not little-endian", scale);
    ck_assert_int_eq(data[used], '\n');
    used++;
    ck_assert_msg(size == (size_t)used + (size_t)width * height * 12,
                  "%zu bytes for %d x %d", size, width, height);
    rt_error error = {0};
    ck_assert_int_eq(rt_image_float_init(image, width, height, &error),
                     RT_OK);
    const unsigned char *p = (const unsigned char *)data + used;
    for (int y = height - 1; y >= 0; y--) {
        float *row = rt_image_float_pixel(image, 0, y);
        for (int i = 0; i < width * 3; i++, p += 4) {
            uint32_t bits = (uint32_t)p[0] | (uint32_t)p[1] << 8 |
                            (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
            memcpy(&row[i], &bits, sizeof bits);
        }
    }
}

START_TEST(a_saved_pfm_reads_back_bit_for_bit)
{
    rt_scene *scene = load_scene("cubes.scn", 1);
    rt_image image;
    rt_image_float linear, back;
    rt_region region = {shrink(10), shrink(20), shrink(310), shrink(220)};
    int width = region.x1 - region.x0, height = region.y1 - region.y0;
    render_both(scene, 1, region, &image, &linear);
    char *dir = rt_test_temp_dir();
    rt_test_path path = rt_test_path_at(dir, "out.pfm");
    rt_error error = {0};
    ck_assert_msg(rt_image_float_save(path.s, &linear, RT_IMAGE_PFM, NULL,
                                      &error) == RT_OK, "%s", error.message);
    size_t size = 0;
    char *data = rt_test_read_file(path.s, &size);
    ck_assert_ptr_nonnull(data);
    read_pfm(data, size, &back);
    ck_assert_int_eq(back.width, width);
    ck_assert_int_eq(back.height, height);
    ck_assert_mem_eq(back.pixels, linear.pixels,
                     sizeof(float) * 3 * (size_t)width * (size_t)height);
    /* only the image is left in the folder: the temporary file is gone */
    char *names = rt_test_dir_names(dir);
    ck_assert_str_eq(names, "out.pfm");
    free(names);
    free(data);
    rt_image_release(&image);
    rt_image_float_release(&linear);
    rt_image_float_release(&back);
    rt_scene_destroy(scene);
    rt_test_remove_dir(dir);
}
END_TEST

/* rt-export -o x.pfm and -o x.ppm of one scene: the PFM's floats round to
 * the PPM's bytes. */
START_TEST(rt_export_pfm_rounds_to_its_ppm)
{
#ifndef RT_EXPORT_PATH
    return;
#else
    char *dir = rt_test_temp_dir();
    char scene[4096];
    snprintf(scene, sizeof scene, "%s/scenes/teapot.scn", RT_SOURCE_DIR);
    const char *const pfm_args[] = {"-q", scene, "-o", "t.pfm",
                                    "--samples", "4", NULL};
    const char *const ppm_args[] = {"-q", scene, "-o", "t.ppm",
                                    "--samples", "4", NULL};
    rt_test_output out = rt_test_run(dir, RT_EXPORT_PATH, pfm_args);
    ck_assert_msg(out.code == 0, "%s", out.err);
    rt_test_output_free(&out);
    out = rt_test_run(dir, RT_EXPORT_PATH, ppm_args);
    ck_assert_msg(out.code == 0, "%s", out.err);
    rt_test_output_free(&out);
    size_t size = 0;
    char *data = rt_test_read_file(rt_test_in_dir(dir, "t.pfm"), &size);
    ck_assert_ptr_nonnull(data);
    rt_image_float back;
    read_pfm(data, size, &back);
    rt_image ppm;
    rt_error error = {0};
    ck_assert_msg(rt_ppm_load(rt_test_in_dir(dir, "t.ppm"), &ppm, &error) ==
                      RT_OK, "%s", error.message);
    ck_assert_int_eq(ppm.width, back.width);
    ck_assert_int_eq(ppm.height, back.height);
    int above = 0;
    for (int y = 0; y < ppm.height; y++)
        for (int x = 0; x < ppm.width; x++)
            for (int c = 0; c < 3; c++) {
                float f = rt_image_float_pixel(&back, x, y)[c];
                ck_assert_int_eq(rt_channel_to_byte(255.0 * (double)f),
                                 rt_image_pixel(&ppm, x, y)[c]);
                above += f > 1.0f;
            }
    ck_assert_int_gt(above, 0);
    /* a debug view is refused with a float output, and nothing written */
    const char *const view_args[] = {"-q", scene, "-o", "v.pfm", "--view",
                                     "normal", NULL};
    out = rt_test_run(dir, RT_EXPORT_PATH, view_args);
    ck_assert_int_ne(out.code, 0);
    ck_assert_msg(strstr(out.err, "--view") != NULL, "%s", out.err);
    rt_test_output_free(&out);
    ck_assert_ptr_null(rt_test_read_file(rt_test_in_dir(dir, "v.pfm"), NULL));
    free(data);
    rt_image_release(&ppm);
    rt_image_float_release(&back);
    rt_test_remove_dir(dir);
#endif
}
END_TEST

static Suite *float_output_suite(void)
{
    Suite *s = suite_create("float_output");
    TCase *tc = tcase_create("pfm");
    tcase_set_timeout(tc, 300);
    tcase_add_test(tc, every_float_rounds_to_its_byte_in_shipped_scenes);
    tcase_add_test(tc,
                   three_lights_exceed_white_and_samples_are_averaged_first);
    tcase_add_test(tc, a_region_holds_the_whole_image_floats_there);
    tcase_add_test(tc, a_debug_view_or_a_wrong_size_refuses_the_linear_image);
    tcase_add_test(tc, a_saved_pfm_reads_back_bit_for_bit);
    tcase_add_test(tc, rt_export_pfm_rounds_to_its_ppm);
    suite_add_tcase(s, tc);
    return s;
}

/* ---- EXR read back ---------------------------------------------------- */

#if RT_TEST_HAVE_OPENEXR
/* Reads channel R, G or B of every scanline of the EXR at `path` into
 * *image (allocated here). */
static void read_exr(const char *path, rt_image_float *image)
{
    exr_context_t context = NULL;
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    ck_assert_int_eq(exr_start_read(&context, path, &init), EXR_ERR_SUCCESS);
    exr_attr_box2i_t box;
    ck_assert_int_eq(exr_get_data_window(context, 0, &box), EXR_ERR_SUCCESS);
    int width = box.max.x - box.min.x + 1, height = box.max.y - box.min.y + 1;
    rt_error error = {0};
    ck_assert_int_eq(rt_image_float_init(image, width, height, &error),
                     RT_OK);
    int32_t lines = 0;
    ck_assert_int_eq(exr_get_scanlines_per_chunk(context, 0, &lines),
                     EXR_ERR_SUCCESS);
    exr_decode_pipeline_t decoder;
    int started = 0;
    for (int y = 0; y < height; y += lines) {
        exr_chunk_info_t chunk;
        ck_assert_int_eq(exr_read_scanline_chunk_info(context, 0,
                                                      box.min.y + y, &chunk),
                         EXR_ERR_SUCCESS);
        int first = !started;
        ck_assert_int_eq(started ? exr_decoding_update(context, 0, &chunk,
                                                       &decoder)
                                 : exr_decoding_initialize(context, 0, &chunk,
                                                           &decoder),
                         EXR_ERR_SUCCESS);
        started = 1;
        for (int c = 0; c < decoder.channel_count; c++) {
            char name = decoder.channels[c].channel_name[0];
            int k = name == 'R' ? 0 : name == 'G' ? 1 : 2;
            ck_assert_int_eq(decoder.channels[c].data_type, EXR_PIXEL_FLOAT);
            decoder.channels[c].decode_to_ptr =
                (uint8_t *)(rt_image_float_pixel(image, 0, y) + k);
            decoder.channels[c].user_pixel_stride = 3 * sizeof(float);
            decoder.channels[c].user_line_stride =
                (int32_t)(image->stride * sizeof(float));
            decoder.channels[c].user_data_type = EXR_PIXEL_FLOAT;
            decoder.channels[c].user_bytes_per_element = sizeof(float);
        }
        if (first)
            ck_assert_int_eq(exr_decoding_choose_default_routines(
                                 context, 0, &decoder),
                             EXR_ERR_SUCCESS);
        ck_assert_int_eq(exr_decoding_run(context, 0, &decoder),
                         EXR_ERR_SUCCESS);
    }
    if (started)
        exr_decoding_destroy(context, &decoder);
    exr_finish(&context);
}
#endif

START_TEST(a_saved_exr_reads_back_bit_for_bit)
{
#if RT_TEST_HAVE_OPENEXR
    static const char *const names[] = {"cubes.scn", "teapot.scn",
                                        "glass.scn"};
    for (size_t i = 0; i < 4; i++) {
        rt_scene *scene = load_scene(i < 3 ? names[i] : "cubes.scn", i == 3);
        rt_image image;
        rt_image_float linear, back;
        render_both(scene, i == 3 ? 4 : 1, WHOLE, &image, &linear);
        char *dir = rt_test_temp_dir();
        rt_test_path path = rt_test_path_at(dir, "out.exr");
        rt_error error = {0};
        ck_assert_msg(rt_image_float_save(path.s, &linear, RT_IMAGE_EXR, NULL,
                                          &error) == RT_OK,
                      "%s", error.message);
        read_exr(path.s, &back);
        ck_assert_int_eq(back.width, linear.width);
        ck_assert_int_eq(back.height, linear.height);
        ck_assert_mem_eq(back.pixels, linear.pixels,
                         sizeof(float) * 3 * (size_t)linear.width *
                             (size_t)linear.height);
        rt_image_release(&image);
        rt_image_float_release(&linear);
        rt_image_float_release(&back);
        rt_scene_destroy(scene);
        rt_test_remove_dir(dir);
    }
#endif
}
END_TEST

static Suite *exr_suite(void)
{
    Suite *s = suite_create("float_output_exr");
    TCase *tc = tcase_create("exr");
    tcase_set_timeout(tc, 300);
    tcase_add_test(tc, a_saved_exr_reads_back_bit_for_bit);
    suite_add_tcase(s, tc);
    return s;
}

static const char *exr_missing(void)
{
    if (!rt_image_format_supported(RT_IMAGE_EXR))
        return "this build of libraytrace has no OpenEXR (RAYTRACE_EXR)";
    if (!RT_TEST_HAVE_OPENEXR)
        return "the suite was built without OpenEXR's reader";
    return NULL;
}

int main(int argc, char **argv)
{
    return rt_test_main_with_entry(argc, argv, float_output_suite, "exr",
                                   exr_suite, exr_missing);
}
