/*
 * test_render_size.c - rendering at any image size and rendering a region.
 *
 * A render at W x H must be the render of the same scene file edited to say
 * W x H on its screen line, byte for byte; a region must hold exactly the
 * pixels the whole image has there.  Both are checked on the project's
 * scenes (lights, glass, the thin lens with stratified samples included),
 * in both precisions, through brute force and the octree, on one and two
 * threads.  Neither side of a comparison is a captured image.
 */
#include <check.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

/* Is the line starting at `line` a record (not blank, not a comment)? */
static int is_record(const char *line)
{
    line += strspn(line, " \t\r");
    return *line != '\0' && *line != '\n' && *line != '#';
}

/*
 * The .scn text `text` with the image size on its screen line (the second
 * record: A, B, width, height and optionally the lens) replaced by
 * width x height, the way a person would edit the file.  Caller frees.
 */
static char *edit_size(const char *text, int width, int height)
{
    const char *line = text;
    for (int records = 0;; ) {
        ck_assert_msg(*line != '\0', "no screen line");
        if (is_record(line) && ++records == 2)
            break;
        line = strchr(line, '\n');
        ck_assert_ptr_nonnull(line);
        line++;
    }
    /* fields 0..5 are A and B; 6 and 7 are the width and the height */
    const char *width_at = line;
    for (int commas = 0; commas < 6; width_at++)
        if (*width_at == ',')
            commas++;
    const char *after_height = strchr(strchr(width_at, ',') + 1, ',');
    const char *end_of_line = strchr(width_at, '\n');
    if (after_height == NULL || (end_of_line && after_height > end_of_line))
        after_height = end_of_line ? end_of_line : width_at + strlen(width_at);
    size_t size = strlen(text) + 64;
    char *edited = malloc(size);
    ck_assert_ptr_nonnull(edited);
    snprintf(edited, size, "%.*s %d, %d%s", (int)(width_at - text), text,
             width, height, after_height);
    return edited;
}

static rt_scene *load(const char *path)
{
    rt_scene *scene;
    rt_error error;
    ck_assert_msg(rt_scene_load(path, NULL, &scene, &error) == RT_OK, "%s",
                  error.message);
    return scene;
}

/* The render settings every comparison runs through. */
typedef struct setting {
    rt_precision precision;
    rt_accel accel;
    int threads;
} setting;

static const setting settings[] = {
    {RT_PRECISION_DOUBLE, RT_ACCEL_NONE, 1},
    {RT_PRECISION_DOUBLE, RT_ACCEL_OCTREE, 2},
    {RT_PRECISION_FLOAT, RT_ACCEL_NONE, 2},
};

static void options_for(const setting *s, const char *scene_name,
                        rt_render_options *options)
{
    rt_render_options_init(options);
    options->precision = s->precision;
    options->accel = s->accel;
    options->threads = s->threads;
    /* the lens scene is meant for several samples a pixel */
    if (strstr(scene_name, "focus") != NULL) {
        options->samples = 4;
        options->sampling = RT_SAMPLING_STRATIFIED;
    }
}

static const char *const scene_names[] = {"cubes.scn", "mirror.scn",
                                          "glass.scn", "focus.scn"};

START_TEST(a_size_renders_as_the_scene_edited_to_that_size)
{
    const char *name = scene_names[_i];
    char path[4096];
    snprintf(path, sizeof path, "scenes/%s", name);
    char *text = rt_test_read_file(rt_test_source_path(path), NULL);
    ck_assert_msg(text != NULL, "cannot open %s", path);
    rt_scene *scene = load(rt_test_source_path(path));
    /* wider, taller, tiny, odd and one-pixel sizes */
    static const int sizes[][2] = {{97, 61}, {40, 90}, {1, 1}, {3, 1},
                                   {1, 5}, {160, 160}};
    int size_count = rt_test_memcheck() ? 3 : 6;
    for (int k = 0; k < size_count; k++) {
        int w = sizes[k][0], h = sizes[k][1];
        char *edited_text = edit_size(text, w, h);
        rt_scene *edited = rt_test_scene_from_string(edited_text);
        rt_scene_info info = {.size = sizeof info};
        rt_scene_get_info(edited, &info);
        ck_assert_int_eq(info.width, w);
        ck_assert_int_eq(info.height, h);
        for (size_t s = 0; s < sizeof settings / sizeof settings[0]; s++) {
            rt_render_options options;
            options_for(&settings[s], name, &options);
            rt_image expected = rt_test_render_with(edited, &options);
            options.width = w;
            options.height = h;
            rt_image sized = rt_test_render_with(scene, &options);
            ck_assert_int_eq(sized.width, w);
            ck_assert_int_eq(sized.height, h);
            ck_assert_msg(rt_test_image_diff(&expected, &sized, NULL) == 0,
                          "%s at %d x %d (setting %zu): differs from the "
                          "scene edited to that size", name, w, h, s);
            rt_image_release(&expected);
            rt_image_release(&sized);
        }
        rt_scene_destroy(edited);
        free(edited_text);
    }
    rt_scene_destroy(scene);
    free(text);
}
END_TEST

/* Does `part` hold the pixels of `whole` in region r? */
static void assert_crop(const rt_image *whole, const rt_image *part,
                        rt_region r, const char *what)
{
    ck_assert_int_eq(part->width, r.x1 - r.x0);
    ck_assert_int_eq(part->height, r.y1 - r.y0);
    for (int y = r.y0; y < r.y1; y++)
        ck_assert_msg(memcmp(rt_image_pixel(whole, r.x0, y),
                             rt_image_pixel(part, 0, y - r.y0),
                             3 * (size_t)part->width) == 0,
                      "%s: region %d,%d,%d,%d differs from the whole image "
                      "in row %d", what, r.x0, r.y0, r.x1, r.y1, y);
}

START_TEST(a_region_holds_the_pixels_of_the_whole_image)
{
    const char *name = scene_names[_i];
    char path[4096];
    snprintf(path, sizeof path, "scenes/%s", name);
    rt_scene *scene = load(rt_test_source_path(path));
    /* a size that is not the scene's, so the region is of a sized image */
    int w = rt_test_memcheck() ? 24 : 120, h = rt_test_memcheck() ? 18 : 90;
    rt_region regions[] = {
        {0, 0, w, h},                   /* all of it */
        {0, 0, 1, 1},                   /* the corners */
        {w - 1, h - 1, w, h},
        {w / 3, h / 4, w / 3 + 7, h / 4 + 5},
        {0, h / 2, w, h / 2 + 1},       /* one whole row */
        {w / 2, 0, w / 2 + 1, h},       /* one whole column */
        {5, 3, w, h},                   /* to the far edges */
    };
    for (size_t s = 0; s < sizeof settings / sizeof settings[0]; s++) {
        rt_render_options options;
        options_for(&settings[s], name, &options);
        options.width = w;
        options.height = h;
        rt_image whole = rt_test_render_with(scene, &options);
        for (size_t k = 0; k < sizeof regions / sizeof regions[0]; k++) {
            options.region = regions[k];
            rt_image part = rt_test_render_with(scene, &options);
            assert_crop(&whole, &part, regions[k], name);
            rt_image_release(&part);
        }
        rt_image_release(&whole);
    }
    rt_scene_destroy(scene);
}
END_TEST

/* Rows reported by on_row are rows of the output image. */
typedef struct row_log {
    int count;
    int low, high;
} row_log;

static int log_row(void *user, int row)
{
    row_log *log = user;
    log->count++;
    if (row < log->low)
        log->low = row;
    if (row > log->high)
        log->high = row;
    return 1;
}

START_TEST(bands_of_a_region_and_its_progress_are_in_its_own_rows)
{
    rt_scene *scene = load(rt_test_source_path("scenes/cubes.scn"));
    rt_render_options options;
    rt_render_options_init(&options);
    options.width = 64;
    options.height = 48;
    rt_image whole = rt_test_render_with(scene, &options);
    options.region = (rt_region){10, 20, 50, 45};
    row_log log = {0, 1 << 30, -1};
    options.on_row = log_row;
    options.user = &log;
    rt_image part;
    ck_assert_int_eq(rt_image_init(&part, 40, 25, NULL), RT_OK);
    /* two bands, rendered apart, make up the region */
    ck_assert_int_eq(rt_render_rows(scene, &options, 0, 11, &part, NULL),
                     RT_OK);
    ck_assert_int_eq(rt_render_rows(scene, &options, 11, 25, &part, NULL),
                     RT_OK);
    ck_assert_int_eq(log.count, 25);
    ck_assert_int_eq(log.low, 0);
    ck_assert_int_eq(log.high, 24);
    assert_crop(&whole, &part, options.region, "two bands");
    /* a band outside the region's rows is refused */
    ck_assert_int_eq(rt_render_rows(scene, &options, 0, 26, &part, NULL),
                     RT_ERR_ARGUMENT);
    rt_image_release(&part);
    rt_image_release(&whole);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(the_default_size_is_the_scenes)
{
    rt_scene *scene = load(rt_test_source_path("scenes/cubes.scn"));
    int w = -1, h = -1;
    ck_assert_int_eq(rt_render_image_size(scene, NULL, &w, &h, NULL), RT_OK);
    ck_assert_int_eq(w, 400);
    ck_assert_int_eq(h, 400);
    rt_render_options options;
    rt_render_options_init(&options);
    options.width = 300;    /* the height stays the scene's */
    ck_assert_int_eq(rt_render_image_size(scene, &options, &w, &h, NULL),
                     RT_OK);
    ck_assert_int_eq(w, 300);
    ck_assert_int_eq(h, 400);
    options.region = (rt_region){100, 50, 250, 60};
    ck_assert_int_eq(rt_render_image_size(scene, &options, &w, &h, NULL),
                     RT_OK);
    ck_assert_int_eq(w, 150);
    ck_assert_int_eq(h, 10);
    rt_scene_destroy(scene);
}
END_TEST

/* A bad size or region: RT_ERR_ARGUMENT, a message naming what was asked,
 * and nothing rendered. */
static void assert_refused(const rt_scene *scene,
                           const rt_render_options *options,
                           const char *needle)
{
    int w = -1, h = -1;
    rt_error error;
    ck_assert_int_eq(rt_render_image_size(scene, options, &w, &h, &error),
                     RT_ERR_ARGUMENT);
    ck_assert_int_eq(w, 0);
    ck_assert_int_eq(h, 0);
    ck_assert_msg(strstr(error.message, needle) != NULL,
                  "message '%s' lacks '%s'", error.message, needle);
    rt_image image;
    ck_assert_int_eq(rt_image_init(&image, 4, 4, NULL), RT_OK);
    memset(image.pixels, 7, image.stride * 4);
    ck_assert_int_eq(rt_render(scene, options, &image, NULL), RT_ERR_ARGUMENT);
    for (size_t i = 0; i < image.stride * 4; i++)
        ck_assert_int_eq(image.pixels[i], 7);
    rt_image_release(&image);
}

START_TEST(bad_sizes_and_regions_are_refused_with_a_reason)
{
    rt_scene *scene = load(rt_test_source_path("scenes/cubes.scn"));
    rt_render_options options;
    rt_render_options_init(&options);
    options.width = -3;
    assert_refused(scene, &options, "-3 x 400");
    options.width = RT_MAX_IMAGE_SIDE + 1;
    assert_refused(scene, &options, "each side must be in 1..");
    options.width = 0;
    options.height = -1;
    assert_refused(scene, &options, "400 x -1");
    options.height = 0;
    options.region = (rt_region){0, 0, 401, 10};
    assert_refused(scene, &options, "not inside of the 400 x 400 image");
    options.region = (rt_region){-1, 0, 10, 10};
    assert_refused(scene, &options, "not inside");
    options.region = (rt_region){10, 10, 10, 20};
    assert_refused(scene, &options, "an empty part");
    options.region = (rt_region){10, 30, 20, 20};
    assert_refused(scene, &options, "an empty part");
    /* an image of the scene's size no longer fits a smaller render */
    rt_render_options_init(&options);
    options.width = 200;
    rt_image image;
    ck_assert_int_eq(rt_image_init(&image, 400, 400, NULL), RT_OK);
    ck_assert_int_eq(rt_render(scene, &options, &image, NULL),
                     RT_ERR_ARGUMENT);
    rt_image_release(&image);
    rt_scene_destroy(scene);
}
END_TEST

static Suite *render_size_suite(void)
{
    Suite *suite = suite_create("render size");
    TCase *tc = tcase_create("size and region");
    tcase_set_timeout(tc, 600);
    int scenes = sizeof scene_names / sizeof scene_names[0];
    tcase_add_loop_test(tc, a_size_renders_as_the_scene_edited_to_that_size,
                        0, scenes);
    tcase_add_loop_test(tc, a_region_holds_the_pixels_of_the_whole_image, 0,
                        scenes);
    tcase_add_test(tc, bands_of_a_region_and_its_progress_are_in_its_own_rows);
    tcase_add_test(tc, the_default_size_is_the_scenes);
    tcase_add_test(tc, bad_sizes_and_regions_are_refused_with_a_reason);
    suite_add_tcase(suite, tc);
    return suite;
}

RT_CHECK_MAIN(render_size_suite)
