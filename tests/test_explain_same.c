/*
 * test_explain_same.c - one explanation formatter (apps/common/cli_explain.h)
 * for rt-export and rt-view: the text rt-view shows and prints for a
 * clicked pixel is the text `rt-export --explain` prints for the same
 * pixel, the same scene (named as given) and the same render options, byte
 * for byte; a shadowed pixel, a total internal reflection, several samples,
 * a region, a mirror several bounces deep and float arithmetic.
 */
#include <check.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SDL_MAIN_HANDLED
#include <SDL.h>

#include "testutil.h"
#include "view_app.h"
#include "view_explain.h"

/* rt-export's --explain X,Y of `scene` with `extra` (NULL-terminated, at
 * most 6), rt_test_output in `dir`. */
static char *export_text(const char *dir, const char *scene, int x, int y,
                         const char *const *extra)
{
    char pixel[64];
    snprintf(pixel, sizeof pixel, "%d,%d", x, y);
    const char *args[10] = {scene, "--explain", pixel};
    int n = 3;
    for (int i = 0; extra[i] != NULL && n < 9; i++)
        args[n++] = extra[i];
    args[n] = NULL;
    rt_test_output r = rt_test_run(dir, RT_EXPORT_PATH, args);
    ck_assert_msg(r.code == 0, "%s", r.err);
    char *out = strdup(r.out);
    rt_test_output_free(&r);
    return out;
}

/* view_explain_pixel's text for the same pixel. */
static char *view_text(const char *path, const rt_render_options *options,
                       int x, int y)
{
    rt_scene *scene;
    rt_error error;
    ck_assert_msg(rt_scene_load(path, NULL, &scene, &error) == RT_OK, "%s",
                  error.message);
    view_explanation e;
    ck_assert_msg(view_explain_pixel(scene, options, path, x, y, &e,
                                     &error) == RT_OK, "%s", error.message);
    char *text = strdup(e.text);
    view_explanation_release(&e);
    rt_scene_destroy(scene);
    return text;
}

START_TEST(rt_view_explains_a_pixel_in_rt_exports_words)
{
    char *dir = rt_test_temp_dir();
    char tir[4200], cubes[4200], glass[4200], mirror[4200];
    /* pixel 4,4 is totally reflected (see the file) */
    snprintf(tir, sizeof tir, "%s",
             rt_test_source_path("tests/data/explain/tir.scn"));
    snprintf(cubes, sizeof cubes, "%s",
             rt_test_source_path("scenes/cubes.scn"));
    snprintf(glass, sizeof glass, "%s",
             rt_test_source_path("scenes/glass.scn"));
    snprintf(mirror, sizeof mirror, "%s",
             rt_test_source_path("scenes/mirror.scn"));
    static const char *const none[] = {NULL};
    static const char *const four[] = {"--samples", "4", NULL};
    static const char *const region[] = {"--region", "100,50,300,250", NULL};
    static const char *const deep[] = {"--depth", "8", NULL};
    static const char *const single[] = {"--precision", "float", NULL};
    struct {
        const char *path;
        int x, y;
        const char *const *extra;
        int samples, depth;
        rt_region region;
        rt_precision precision;
    } cases[] = {
        {cubes, 268, 124, none, 1, 5, {0, 0, 0, 0}, RT_PRECISION_DOUBLE},
        {tir, 4, 4, none, 1, 5, {0, 0, 0, 0}, RT_PRECISION_DOUBLE},
        {glass, 200, 150, four, 4, 5, {0, 0, 0, 0}, RT_PRECISION_DOUBLE},
        {cubes, 20, 30, region, 1, 5, {100, 50, 300, 250},
         RT_PRECISION_DOUBLE},
        {mirror, 150, 150, deep, 1, 8, {0, 0, 0, 0}, RT_PRECISION_DOUBLE},
        {cubes, 269, 172, single, 1, 5, {0, 0, 0, 0}, RT_PRECISION_FLOAT},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        rt_render_options options;
        rt_render_options_init(&options);
        options.samples = cases[i].samples;
        options.max_depth = cases[i].depth;
        options.region = cases[i].region;
        options.precision = cases[i].precision;
        char *expected = export_text(dir, cases[i].path, cases[i].x,
                                     cases[i].y, cases[i].extra);
        char *shown = view_text(cases[i].path, &options, cases[i].x,
                                cases[i].y);
        ck_assert_msg(strcmp(shown, expected) == 0,
                      "case %zu: rt-view:\n%s\nrt-export:\n%s", i, shown,
                      expected);
        /* the cases are what they say: a shadow, a total reflection */
        if (i == 0)
            ck_assert_ptr_nonnull(strstr(shown, "shadowed by facet"));
        if (i == 1)
            ck_assert_ptr_nonnull(strstr(shown, "totally reflected ray"));
        free(expected);
        free(shown);
    }
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(a_click_names_the_scene_as_it_was_given)
{
    setenv("SDL_VIDEODRIVER", "dummy", 0);
    ck_assert_msg(SDL_Init(SDL_INIT_VIDEO) == 0, "SDL_Init: %s",
                  SDL_GetError());
    view_app_options options;
    view_app_options_init(&options);
    options.window_flags = VIEW_WINDOW_SOFTWARE;
    char error[256];
    view_app *app = view_app_create(&options, error, sizeof error);
    ck_assert_msg(app != NULL, "%s", error);
    char cubes[4200];
    snprintf(cubes, sizeof cubes, "%s",
             rt_test_source_path("scenes/cubes.scn"));
    ck_assert(view_app_open(app, cubes) && view_app_wait_load(app));
    ck_assert(view_app_explain(app, 268, 124));
    const view_explanation *e = view_app_explanation(app);
    ck_assert_ptr_nonnull(e);
    char *dir = rt_test_temp_dir();
    static const char *const none[] = {NULL};
    char *expected = export_text(dir, cubes, 268, 124, none);
    ck_assert_str_eq(e->text, expected);
    free(expected);
    rt_test_remove_dir(dir);
    view_app_destroy(app);
    SDL_Quit();
}
END_TEST

static Suite *same_suite(void)
{
    Suite *s = suite_create("explain_same");
    TCase *c = tcase_create("same");
    tcase_set_timeout(c, 120);
    tcase_add_test(c, rt_view_explains_a_pixel_in_rt_exports_words);
    tcase_add_test(c, a_click_names_the_scene_as_it_was_given);
    suite_add_tcase(s, c);
    return s;
}

RT_CHECK_MAIN(same_suite)
