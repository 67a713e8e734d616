/*
 * test_render.c - whole renders: every scene of scenes/ against its expected
 * image in tests/expected/ (made by the independent Python renderer of
 * tests/reference/), exactly, and at N samples a pixel where
 * tests/expected/<scene>-s<N>.ppm exists; the same image whatever the thread count, the
 * kernel or the split into bands; progress callbacks and cancellation;
 * argument checks; and, as the test_render_shared entry, the handout's seed
 * scenes of ../shared when present.
 * A mismatching image is written as <scene>.actual.ppm in the test's
 * working directory (the build tree's tests/).
 */
#include "testutil.h"

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_SCENES 64

/* Scene names (without .scn) found in scenes/ when the suite is built. */
static char scene_names[MAX_SCENES][128];
static int scene_count;

static int compare_names(const void *a, const void *b)
{
    return strcmp(a, b);
}

static void find_scenes(void)
{
    DIR *dir = opendir(rt_test_source_path("scenes"));
    if (!dir)
        return;
    struct dirent *entry;
    while ((entry = readdir(dir)) != NULL && scene_count < MAX_SCENES) {
        size_t n = strlen(entry->d_name);
        if (n > 4 && n < sizeof scene_names[0] + 4 &&
            strcmp(entry->d_name + n - 4, ".scn") == 0) {
            memcpy(scene_names[scene_count], entry->d_name, n - 4);
            scene_names[scene_count][n - 4] = '\0';
            scene_count++;
        }
    }
    closedir(dir);
    qsort(scene_names, (size_t)scene_count, sizeof scene_names[0],
          compare_names);
}

static rt_scene *load_scene(const char *path)
{
    rt_scene *scene = NULL;
    rt_error error;
    rt_status status = rt_scene_load(path, NULL, &scene, &error);
    ck_assert_msg(status == RT_OK, "%s does not load: %s", path,
                  error.message);
    return scene;
}

/* Renders scenes/<name>.scn with `samples` rays per pixel and compares it
 * with tests/expected/<expected_name>.ppm, exactly; on a mismatch says
 * where and writes the actual image beside the test. */
static void check_expected_image(const char *name, int samples,
                                 const char *expected_name)
{
    char relative[256];
    snprintf(relative, sizeof relative, "scenes/%s.scn", name);
    rt_scene *scene = load_scene(rt_test_source_path(relative));
    rt_render_options options;
    rt_render_options_init(&options);
    options.samples = samples;

    snprintf(relative, sizeof relative, "tests/expected/%s.ppm",
             expected_name);
    rt_image expected;
    rt_error error;
    rt_status status = rt_ppm_load(rt_test_source_path(relative), &expected,
                                   &error);
    ck_assert_msg(status == RT_OK, "scene %s has no usable expected image: %s",
                  name, error.message);
    if (rt_test_memcheck()) {
        /* Under valgrind (.ci/memcheck) only the middle quarter of the
         * rows, whose pixels are the whole image's there (a region): the
         * same code paths at a quarter of the time. */
        int y0 = expected.height * 3 / 8, y1 = expected.height * 5 / 8;
        options.region = (rt_region){0, y0, expected.width, y1};
        rt_image band;
        ck_assert(rt_image_init(&band, expected.width, y1 - y0, NULL) ==
                  RT_OK);
        for (int y = y0; y < y1; y++)
            memcpy(rt_image_pixel(&band, 0, y - y0),
                   rt_image_pixel(&expected, 0, y),
                   (size_t)expected.width * 3);
        rt_image_release(&expected);
        expected = band;
    }
    rt_image actual = rt_test_render_with(scene, &options);
    ck_assert_msg(expected.width == actual.width &&
                      expected.height == actual.height,
                  "%s: expected %dx%d, rendered %dx%d", name, expected.width,
                  expected.height, actual.width, actual.height);

    int worst = 0;
    long differing = rt_test_image_diff(&expected, &actual, &worst);
    if (differing != 0) {
        /* where: bounding box and the first few pixels */
        int x0 = actual.width, y0 = actual.height, x1 = -1, y1 = -1;
        char where[512] = "";
        int listed = 0;
        for (int y = 0; y < actual.height; y++)
            for (int x = 0; x < actual.width; x++) {
                const unsigned char *p = rt_image_pixel(&actual, x, y);
                const unsigned char *q = rt_image_pixel(&expected, x, y);
                if (memcmp(p, q, 3) == 0)
                    continue;
                x0 = x < x0 ? x : x0;
                y0 = y < y0 ? y : y0;
                x1 = x > x1 ? x : x1;
                y1 = y > y1 ? y : y1;
                if (listed++ < 6) {
                    size_t used = strlen(where);
                    snprintf(where + used, sizeof where - used,
                             " (%d,%d) %d %d %d vs %d %d %d;", x, y, p[0],
                             p[1], p[2], q[0], q[1], q[2]);
                }
            }
        char out[300];
        snprintf(out, sizeof out, "%s.actual.ppm", expected_name);
        rt_status saved =
            rt_image_save(out, &actual, RT_IMAGE_P6, NULL, &error);
        ck_abort_msg("%s: %ld of %d pixels differ from tests/expected/%s.ppm, "
                     "max channel difference %d, in x %d..%d y %d..%d; "
                     "actual vs expected:%s actual image %s %s",
                     name, differing, actual.width * actual.height,
                     expected_name, worst, x0, x1, y0, y1, where,
                     saved == RT_OK ? "written to" : "NOT written to", out);
    }
    rt_image_release(&expected);
    rt_image_release(&actual);
    rt_scene_destroy(scene);
}

START_TEST(project_scenes_render_exactly_their_expected_images)
{
    check_expected_image(scene_names[_i], 1, scene_names[_i]);
}
END_TEST

/* tests/expected/<name>-s<N>.ppm: scenes/<name>.scn at N samples a pixel
 * (depth of field needs several). */
static char sampled_names[MAX_SCENES][128];
static int sampled_samples[MAX_SCENES];
static int sampled_count;

static void find_sampled_images(void)
{
    DIR *dir = opendir(rt_test_source_path("tests/expected"));
    if (!dir)
        return;
    struct dirent *entry;
    while ((entry = readdir(dir)) != NULL && sampled_count < MAX_SCENES) {
        char name[128];
        int samples, end = 0;
        const char *dash = strrchr(entry->d_name, '-');
        if (dash == NULL || dash - entry->d_name >= (long)sizeof name ||
            sscanf(dash, "-s%d.ppm%n", &samples, &end) != 1 ||
            dash[end] != '\0' || samples < 1)
            continue;
        memcpy(name, entry->d_name, (size_t)(dash - entry->d_name));
        name[dash - entry->d_name] = '\0';
        snprintf(sampled_names[sampled_count], sizeof sampled_names[0], "%s",
                 name);
        sampled_samples[sampled_count++] = samples;
    }
    closedir(dir);
}

START_TEST(sampled_images_render_exactly)
{
    char expected[160];
    snprintf(expected, sizeof expected, "%s-s%d", sampled_names[_i],
             sampled_samples[_i]);
    check_expected_image(sampled_names[_i], sampled_samples[_i], expected);
}
END_TEST

START_TEST(project_scenes_are_present)
{
    ck_abort_msg("no scene found in %s", rt_test_source_path("scenes"));
}
END_TEST

/* A scene with shadows and reflections for the consistency tests: the
 * project's mirror scene, its 400 x 400 image cut down to 120 x 90 so that
 * the many renders below stay quick (and the image is not square). */
static rt_scene *busy_scene(void)
{
    const char *path = rt_test_source_path("scenes/mirror.scn");
    FILE *file = fopen(path, "rb");
    ck_assert_msg(file != NULL, "cannot open %s", path);
    static char text[1 << 16];
    size_t length = fread(text, 1, sizeof text - 1, file);
    fclose(file);
    text[length] = '\0';
    char *size = strstr(text, "400, 400");
    ck_assert_msg(size != NULL, "%s: no \"400, 400\" image size to reduce",
                  path);
    memcpy(size, "120,  90", 8);
    return rt_test_scene_from_string(text);
}

START_TEST(one_thread_and_two_threads_give_identical_images)
{
    rt_scene *scene = busy_scene();
    rt_render_options options;
    rt_render_options_init(&options);
    options.threads = 1;
    rt_image one = rt_test_render_with(scene, &options);
    options.threads = 2;
    rt_image two = rt_test_render_with(scene, &options);
    options.threads = 7;
    rt_image seven = rt_test_render_with(scene, &options);
    ck_assert_int_eq(memcmp(one.pixels, two.pixels,
                            one.stride * (size_t)one.height),
                     0);
    ck_assert_int_eq(memcmp(one.pixels, seven.pixels,
                            one.stride * (size_t)one.height),
                     0);
    rt_image_release(&one);
    rt_image_release(&two);
    rt_image_release(&seven);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(scalar_and_automatic_kernels_give_identical_images)
{
    rt_scene *scene = busy_scene();
    rt_render_options options;
    rt_render_options_init(&options);
    options.kernel = RT_KERNEL_SCALAR;
    rt_image scalar = rt_test_render_with(scene, &options);
    options.kernel = RT_KERNEL_AUTO;
    rt_image automatic = rt_test_render_with(scene, &options);
    int worst;
    long differing = rt_test_image_diff(&scalar, &automatic, &worst);
    ck_assert_msg(differing == 0, "%ld pixels differ (max %d)", differing,
                  worst);
    rt_image_release(&scalar);
    rt_image_release(&automatic);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(two_bands_rendered_apart_equal_the_whole_render)
{
    rt_scene *scene = busy_scene();
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    rt_image whole = rt_test_render_with(scene, NULL);
    rt_image bands;
    ck_assert_int_eq(rt_image_init(&bands, info.width, info.height, NULL),
                     RT_OK);
    int split = info.height / 3;
    ck_assert_int_eq(rt_render_rows(scene, NULL, split, info.height, &bands,
                                    NULL),
                     RT_OK);
    /* rows before the band are untouched (still black from create) */
    for (int y = 0; y < split; y++)
        for (int x = 0; x < info.width * 3; x++)
            ck_assert_int_eq(bands.pixels[(size_t)y * bands.stride + x], 0);
    ck_assert_int_eq(rt_render_rows(scene, NULL, 0, split, &bands, NULL),
                     RT_OK);
    ck_assert_int_eq(memcmp(whole.pixels, bands.pixels,
                            whole.stride * (size_t)whole.height),
                     0);
    rt_image_release(&whole);
    rt_image_release(&bands);
    rt_scene_destroy(scene);
}
END_TEST

typedef struct row_log {
    int calls;
    int cancel_at; /* return 0 on this call (1-based); 0: never */
    int seen[4096];
} row_log;

static int log_row(void *user, int row)
{
    row_log *log = user;
    log->calls++;
    if (row >= 0 && row < 4096)
        log->seen[row]++;
    return log->cancel_at == 0 || log->calls < log->cancel_at;
}

START_TEST(on_row_is_called_once_per_row)
{
    rt_scene *scene = busy_scene();
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    for (int threads = 1; threads <= 2; threads++) {
        static row_log log;
        memset(&log, 0, sizeof log);
        rt_render_options options;
        rt_render_options_init(&options);
        options.threads = threads;
        options.on_row = log_row;
        options.user = &log;
        rt_image image = rt_test_render_with(scene, &options);
        ck_assert_int_eq(log.calls, info.height);
        for (int y = 0; y < info.height; y++)
            ck_assert_msg(log.seen[y] == 1, "row %d reported %d times", y,
                          log.seen[y]);
        rt_image_release(&image);
    }
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(cancel_from_on_row_returns_cancelled)
{
    rt_scene *scene = busy_scene();
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    for (int threads = 1; threads <= 2; threads++) {
        static row_log log;
        memset(&log, 0, sizeof log);
        log.cancel_at = 1;
        rt_render_options options;
        rt_render_options_init(&options);
        options.threads = threads;
        options.on_row = log_row;
        options.user = &log;
        rt_image image;
        ck_assert_int_eq(rt_image_init(&image, info.width, info.height, NULL),
                         RT_OK);
        ck_assert_int_eq(rt_render(scene, &options, &image, NULL),
                         RT_ERR_CANCELLED);
        ck_assert_msg(log.calls < info.height,
                      "%d threads: %d rows reported after the cancel",
                      threads, log.calls);
        ck_assert_int_eq(rt_render_rows(scene, &options, 0, info.height,
                                        &image, NULL),
                         RT_ERR_CANCELLED);
        rt_image_release(&image);
    }
    rt_scene_destroy(scene);
}
END_TEST

/* Raises the token when the first row is done, and asks to go on: only
 * the token can stop the render. */
static int raise_token(void *user, int row)
{
    (void)row;
    rt_cancel_request(user);
    return 1;
}

START_TEST(cancel_token_stops_a_render_within_a_pixel_and_can_be_reset)
{
    rt_scene *scene = busy_scene();
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    rt_cancel *token;
    ck_assert_int_eq(rt_cancel_create(&token, NULL), RT_OK);
    ck_assert_ptr_nonnull(token);
    ck_assert_int_eq(rt_cancel_requested(token), 0);
    rt_image image;
    ck_assert_int_eq(rt_image_init(&image, info.width, info.height, NULL),
                     RT_OK);
    rt_render_options options;
    rt_render_options_init(&options);
    options.cancel = token;

    /* Raised before the render: not one pixel is written. */
    rt_cancel_request(token);
    ck_assert_int_ne(rt_cancel_requested(token), 0);
    memset(image.pixels, 7, image.stride * (size_t)image.height);
    for (int threads = 1; threads <= 2; threads++) {
        options.threads = threads;
        ck_assert_int_eq(rt_render(scene, &options, &image, NULL),
                         RT_ERR_CANCELLED);
    }
    for (size_t i = 0; i < image.stride * (size_t)image.height; i++)
        ck_assert_msg(image.pixels[i] == 7, "byte %zu written", i);

    /* Raised from the first finished row while on_row says go on: the
     * render stops anyway, long before the last row. */
    rt_cancel_reset(token);
    ck_assert_int_eq(rt_cancel_requested(token), 0);
    options.threads = 1;
    options.on_row = raise_token;
    options.user = token;
    ck_assert_int_eq(rt_render(scene, &options, &image, NULL),
                     RT_ERR_CANCELLED);
    int untouched_rows = 0;
    for (int y = 0; y < image.height; y++)
        untouched_rows += rt_image_pixel(&image, 0, y)[0] == 7 &&
                          rt_image_pixel(&image, image.width - 1, y)[2] == 7;
    ck_assert_msg(untouched_rows >= image.height - 2,
                  "only %d of %d rows untouched after the cancel",
                  untouched_rows, image.height);

    /* Reset: the same options render the whole image. */
    rt_cancel_reset(token);
    options.on_row = NULL;
    ck_assert_int_eq(rt_render(scene, &options, &image, NULL), RT_OK);
    rt_image_release(&image);
    rt_cancel_destroy(token);
    rt_cancel_destroy(NULL);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(render_refuses_wrong_image_size_and_negative_depth)
{
    rt_scene *scene = busy_scene();
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    rt_image image;
    ck_assert_int_eq(rt_image_init(&image, info.width + 1, info.height, NULL),
                     RT_OK);
    ck_assert_int_eq(rt_render(scene, NULL, &image, NULL), RT_ERR_ARGUMENT);
    rt_image_release(&image);
    ck_assert_int_eq(rt_image_init(&image, info.width, info.height, NULL),
                     RT_OK);
    rt_render_options options;
    rt_render_options_init(&options);
    options.max_depth = -1;
    ck_assert_int_eq(rt_render(scene, &options, &image, NULL),
                     RT_ERR_ARGUMENT);
    rt_image_release(&image);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(options_init_sets_the_documented_defaults)
{
    rt_render_options options;
    memset(&options, 0x5A, sizeof options);
    rt_render_options_init(&options);
    ck_assert_int_eq(options.max_depth, RT_DEFAULT_DEPTH);
    ck_assert_int_eq(RT_DEFAULT_DEPTH, 5);
    ck_assert_int_eq(options.threads, 0);
    ck_assert(options.on_row == NULL);
    ck_assert_ptr_null(options.stats);
    ck_assert_int_eq(options.samples, 1);
}
END_TEST

START_TEST(stats_count_one_camera_ray_per_pixel)
{
    rt_scene *scene = busy_scene();
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    rt_render_stats stats = {.size = sizeof stats};
    rt_render_options options;
    rt_render_options_init(&options);
    options.stats = &stats;
    rt_image image = rt_test_render_with(scene, &options);
    uint64_t pixels = (uint64_t)info.width * (uint64_t)info.height;
    ck_assert_uint_eq(stats.pixels, pixels);
    ck_assert_uint_eq(stats.camera_rays, pixels);
    ck_assert_uint_gt(stats.shadow_rays, 0);
    ck_assert_uint_gt(stats.reflection_rays, 0);
    rt_image_release(&image);
    rt_scene_destroy(scene);
}
END_TEST

/* Not every pixel is the background. */
static void check_not_all_background(const char *name)
{
    const char *path = rt_test_shared_path(name);
    ck_assert_ptr_nonnull(path);
    rt_scene *scene = load_scene(path);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    rt_image image = rt_test_render_with(scene, NULL);
    long other = 0;
    for (int y = 0; y < image.height; y++)
        for (int x = 0; x < image.width; x++) {
            const unsigned char *p = rt_image_pixel(&image, x, y);
            other += p[0] != info.background.r || p[1] != info.background.g ||
                     p[2] != info.background.b;
        }
    ck_assert_msg(other > image.width * image.height / 100,
                  "%s: only %ld pixels are not the background", name, other);
    rt_image_release(&image);
    rt_scene_destroy(scene);
}

START_TEST(seed_scenes_render_something)
{
    check_not_all_background("seed-scenes/cubes.scn");
    check_not_all_background("seed-scenes/mirror.scn");
    check_not_all_background("seed-scenes/test1.scn");
    check_not_all_background("seed-scenes/test2.scn");
}
END_TEST

START_TEST(seed_cubes_scene_needs_the_projection_of_b)
{
    const char *path = rt_test_shared_path("seed-scenes/cubes.scn");
    ck_assert_ptr_nonnull(path);
    rt_scene *scene = load_scene(path);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    ck_assert_int_ne(info.camera.b_was_projected, 0);
    ck_assert_int_eq(info.facet_count, 14);
    ck_assert_int_eq(info.width, 400);
    rt_scene_destroy(scene);
    scene = load_scene(rt_test_shared_path("seed-scenes/test1.scn"));
    rt_scene_get_info(scene, &info);
    ck_assert_int_eq(info.camera.b_was_projected, 0);
    rt_scene_destroy(scene);
}
END_TEST

static Suite *render_suite(void)
{
    Suite *suite = suite_create("render");
    find_scenes();
    find_sampled_images();
    TCase *regression = tcase_create("regression");
    tcase_set_timeout(regression, 120);
    if (scene_count > 0)
        tcase_add_loop_test(regression,
                            project_scenes_render_exactly_their_expected_images,
                            0, scene_count);
    if (sampled_count > 0)
        tcase_add_loop_test(regression, sampled_images_render_exactly, 0,
                            sampled_count);
    else
        tcase_add_test(regression, project_scenes_are_present);
    suite_add_tcase(suite, regression);

    TCase *consistency = tcase_create("consistency");
    tcase_set_timeout(consistency, 60);
    tcase_add_test(consistency, one_thread_and_two_threads_give_identical_images);
    tcase_add_test(consistency, scalar_and_automatic_kernels_give_identical_images);
    tcase_add_test(consistency, two_bands_rendered_apart_equal_the_whole_render);
    tcase_add_test(consistency, on_row_is_called_once_per_row);
    tcase_add_test(consistency, cancel_from_on_row_returns_cancelled);
    tcase_add_test(consistency,
                   cancel_token_stops_a_render_within_a_pixel_and_can_be_reset);
    tcase_add_test(consistency, render_refuses_wrong_image_size_and_negative_depth);
    tcase_add_test(consistency, options_init_sets_the_documented_defaults);
    tcase_add_test(consistency, stats_count_one_camera_ray_per_pixel);
    suite_add_tcase(suite, consistency);

    return suite;
}

/* The handout's seed scenes: their own ctest entry, skipped when absent. */
static Suite *render_shared_suite(void)
{
    Suite *suite = suite_create("render-shared");
    TCase *seed = tcase_create("seed");
    tcase_set_timeout(seed, 60);
    tcase_add_test(seed, seed_scenes_render_something);
    tcase_add_test(seed, seed_cubes_scene_needs_the_projection_of_b);
    suite_add_tcase(suite, seed);
    return suite;
}

RT_CHECK_MAIN_WITH_SHARED(render_suite, render_shared_suite)
