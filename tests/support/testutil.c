/*
 * testutil.c - helpers shared by the Check suites (see testutil.h).
 */
#include "testutil.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int rt_test_run_suite(Suite *suite)
{
    SRunner *runner = srunner_create(suite);
    srunner_run_all(runner, CK_NORMAL);
    int failed = srunner_ntests_failed(runner);
    srunner_free(runner);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

int rt_test_main_with_shared(int argc, char **argv, Suite *(*main_fn)(void),
                             Suite *(*shared_fn)(void))
{
    if (argc > 1 && strcmp(argv[1], "shared") == 0) {
        if (rt_test_shared_path("") == NULL) {
            printf("%s: SKIPPED: ../shared is absent, the course's scenes "
                   "are not checked\n", argv[0]);
            return RT_TEST_SKIPPED;
        }
        return rt_test_run_suite(shared_fn());
    }
    return rt_test_run_suite(main_fn());
}

const char *rt_test_source_path(const char *relative)
{
    static char buffer[4096];
    snprintf(buffer, sizeof buffer, "%s/%s", RT_SOURCE_DIR, relative);
    return buffer;
}

const char *rt_test_shared_path(const char *relative)
{
    static char buffer[4096];
    struct stat st;
    if (stat(RT_SHARED_DIR, &st) != 0 || !S_ISDIR(st.st_mode))
        return NULL;
    snprintf(buffer, sizeof buffer, "%s/%s", RT_SHARED_DIR, relative);
    return buffer;
}

rt_scene *rt_test_scene_from_string(const char *text)
{
    rt_scene *scene = NULL;
    rt_error error;
    rt_status status = rt_scene_parse(text, strlen(text), "<test>", &scene,
                                      &error);
    ck_assert_msg(status == RT_OK, "scene did not load: %s", error.message);
    return scene;
}

rt_image rt_test_render_with(const rt_scene *scene,
                             const rt_render_options *options)
{
    int width, height;
    rt_error error;
    ck_assert_msg(rt_render_image_size(scene, options, &width, &height,
                                       &error) == RT_OK,
                  "%s", error.message);
    rt_image image;
    ck_assert_int_eq(rt_image_init(&image, width, height, NULL), RT_OK);
    ck_assert_int_eq(rt_render(scene, options, &image, NULL), RT_OK);
    return image;
}

rt_image rt_test_render(const rt_scene *scene, int max_depth, int threads)
{
    rt_render_options options;
    rt_render_options_init(&options);
    options.max_depth = max_depth;
    options.threads = threads;
    return rt_test_render_with(scene, &options);
}

long rt_test_image_diff(const rt_image *a, const rt_image *b, int *max_diff)
{
    ck_assert_int_eq(a->width, b->width);
    ck_assert_int_eq(a->height, b->height);
    long count = 0;
    int worst = 0;
    for (int y = 0; y < a->height; y++) {
        for (int x = 0; x < a->width; x++) {
            const unsigned char *p = rt_image_pixel(a, x, y);
            const unsigned char *q = rt_image_pixel(b, x, y);
            int differs = 0;
            for (int c = 0; c < 3; c++) {
                int d = abs((int)p[c] - (int)q[c]);
                if (d > worst)
                    worst = d;
                differs |= d != 0;
            }
            count += differs;
        }
    }
    if (max_diff)
        *max_diff = worst;
    return count;
}

int rt_test_bytes_add(void *user, const void *data, size_t size)
{
    rt_test_bytes *b = user;
    if (b->size + size > b->capacity) {
        size_t capacity = 2 * (b->size + size) + 256;
        unsigned char *grown = realloc(b->data, capacity);
        if (grown == NULL)
            return 0;
        b->data = grown;
        b->capacity = capacity;
    }
    memcpy(b->data + b->size, data, size);
    b->size += size;
    return 1;
}

char *rt_test_read_file(const char *path, size_t *size)
{
    FILE *file = fopen(path, "rb");
    if (file == NULL)
        return NULL;
    size_t capacity = 1 << 16, used = 0;
    char *data = malloc(capacity + 1);
    ck_assert_ptr_nonnull(data);
    size_t n;
    while ((n = fread(data + used, 1, capacity - used, file)) > 0) {
        used += n;
        if (used == capacity) {
            capacity *= 2;
            data = realloc(data, capacity + 1);
            ck_assert_ptr_nonnull(data);
        }
    }
    fclose(file);
    data[used] = '\0';
    if (size != NULL)
        *size = used;
    return data;
}

void rt_test_write_file(const char *path, const char *text)
{
    FILE *file = fopen(path, "wb");
    ck_assert_msg(file != NULL, "cannot write %s", path);
    ck_assert_int_eq(fputs(text, file) >= 0, 1);
    ck_assert_int_eq(fclose(file), 0);
}

void rt_test_assert_color(rt_color c, double r, double g, double b,
                          double tol, const char *what)
{
    ck_assert_msg(fabs(c.r - r) <= tol && fabs(c.g - g) <= tol &&
                      fabs(c.b - b) <= tol,
                  "%s: (%.12g, %.12g, %.12g), expected (%.12g, %.12g, %.12g) "
                  "within %g",
                  what, c.r, c.g, c.b, r, g, b, tol);
}
