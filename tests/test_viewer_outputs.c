/*
 * test_viewer_outputs.c - rt-view's S never writes over what the scene was
 * read from: with -o naming the scene (by its name, a symbolic or a hard
 * link) the save is refused with a message naming both, in the title and
 * on stderr, and the scene stays as it was; an output that is no input
 * saves as before.  `test_viewer_outputs sources` does the same for an
 * OBJ's material library once the loader lists the files it read
 * (rt_scene_source_at); until then it exits 77, a skip.  The app runs on
 * SDL's dummy video driver, without an event loop (as test_viewer.c).
 */
#include <check.h>
#include <stdio.h>
#include <sys/stat.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define SDL_MAIN_HANDLED
#include <SDL.h>

#include "testutil.h"
#include "viewer.h"

static view_app *open_app(const char *output)
{
    view_app_options options;
    rt_test_view_app_options(&options);
    options.format = RT_IMAGE_P6;
    options.output = output;
    options.render.width = 32;
    options.render.height = 24;
    return rt_test_view_app_open(&options);
}
/* Opens `path` in a new app saving to `output`, and waits for the whole
 * image (so that S goes to -o, not to a partial name). */
static view_app *render(const char *path, const char *output)
{
    view_app *app = open_app(output);
    ck_assert_msg(view_app_open(app, path) && view_app_wait_load(app), "%s",
                  view_app_message(app));
    ck_assert_int_eq(rt_test_view_wait(view_app_session(app)), VIEW_DONE);
    return app;
}

static void assert_same_file_text(const char *path, const char *text)
{
    char *now = rt_test_read_file(path, NULL);
    ck_assert_ptr_nonnull(now);
    ck_assert_msg(strcmp(now, text) == 0, "%s was changed", path);
    free(now);
}

START_TEST(save_refuses_an_output_that_is_the_scene)
{
    char *dir = rt_test_temp_dir();
    char *text = rt_test_read_file(rt_test_source_path("scenes/cubes.scn"),
                                   NULL);
    ck_assert_ptr_nonnull(text);
    char scene[4200], soft[4200], hard[4200];
    snprintf(scene, sizeof scene, "%s", rt_test_in_dir(dir, "v.scn"));
    snprintf(soft, sizeof soft, "%s", rt_test_in_dir(dir, "link.scn"));
    snprintf(hard, sizeof hard, "%s", rt_test_in_dir(dir, "hard.scn"));
    rt_test_write_file(scene, text);
    ck_assert_int_eq(symlink("v.scn", soft), 0);
    ck_assert_int_eq(link(scene, hard), 0);
    const char *outputs[] = {scene, soft, hard};
    for (size_t i = 0; i < 3; i++) {
        view_app *app = render(scene, outputs[i]);
        char path[4200];
        ck_assert(!view_app_save(app, path, sizeof path));
        char expected[16000];
        snprintf(expected, sizeof expected, "%s: refusing to write the image "
                 "over %s, the scene it comes from (the same file)",
                 outputs[i], scene);
        ck_assert_str_eq(view_app_message(app), expected);
        ck_assert_ptr_nonnull(strstr(view_app_title(app), "refusing"));
        rt_test_view_app_close(app);
        assert_same_file_text(scene, text);
    }
    /* an output that is no input: saved as before */
    view_app *app = render(scene, rt_test_in_dir(dir, "out.ppm"));
    char path[4200];
    ck_assert(view_app_save(app, path, sizeof path));
    ck_assert_str_eq(path, rt_test_in_dir(dir, "out.ppm"));
    ck_assert_str_eq(view_app_message(app), "");
    rt_test_view_app_close(app);
    rt_image saved;
    ck_assert_int_eq(rt_ppm_load(rt_test_in_dir(dir, "out.ppm"), &saved, NULL),
                     RT_OK);
    ck_assert_int_eq(saved.width, 32);
    rt_image_release(&saved);
    free(text);
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(save_refuses_the_material_library_its_obj_read)
{
    char *dir = rt_test_temp_dir();
    char *obj = rt_test_read_file(rt_test_source_path(
                                      "tests/data/obj/cube.obj"), NULL);
    char *mtl = rt_test_read_file(rt_test_source_path(
                                      "tests/data/obj/cube.mtl"), NULL);
    ck_assert(obj != NULL && mtl != NULL);
    char scene[4200], library[4200];
    snprintf(scene, sizeof scene, "%s", rt_test_in_dir(dir, "cube.obj"));
    snprintf(library, sizeof library, "%s", rt_test_in_dir(dir, "cube.mtl"));
    rt_test_write_file(scene, obj);
    rt_test_write_file(library, mtl);
    view_app *app = render(scene, library);
    char path[4200];
    ck_assert(!view_app_save(app, path, sizeof path));
    ck_assert_msg(strstr(view_app_message(app), "cube.mtl, a file the scene "
                                                "read (the same file)"),
                  "%s", view_app_message(app));
    rt_test_view_app_close(app);
    assert_same_file_text(library, mtl);
    assert_same_file_text(scene, obj);
    free(obj);
    free(mtl);
    rt_test_remove_dir(dir);
}
END_TEST

/* Copies source file `from` into `dir` as `name`; the copy's path. */
static const char *copy_in(const char *dir, const char *from,
                           const char *name)
{
    char *text = rt_test_read_file(rt_test_source_path(from), NULL);
    ck_assert_ptr_nonnull(text);
    const char *path = rt_test_in_dir(dir, name);
    rt_test_write_file(path, text);
    free(text);
    return path;
}

static int exists(const char *path)
{
    struct stat info;
    return stat(path, &info) == 0;
}

/* An app saving in its default format (PNG when this build writes it),
 * rendering `samples` rays a pixel on one thread, at 32 x 24. */
static view_app *open_default_app(int samples)
{
    view_app_options options;
    rt_test_view_app_options(&options);
    options.render.width = 32;
    options.render.height = 24;
    options.render.samples = samples;
    options.render.threads = 1;
    return rt_test_view_app_open(&options);
}

START_TEST(saves_are_named_after_the_scenes_stem_whatever_its_extension)
{
    char *dir = rt_test_temp_dir();
    copy_in(dir, "tests/data/obj/cube.mtl", "cube.mtl");
    struct {
        const char *from, *name, *stem;
    } scenes[] = {
        {"scenes/nff-sphere.nff", "balls-s2.nff", "balls-s2"},
        {"tests/data/obj/cube.obj", "cube.obj", "cube"},
        {"scenes/cubes.scn", "my.scene.scn", "my.scene"},
    };
    view_app_options defaults;
    view_app_options_init(&defaults);
    const char *extension =
        defaults.format == RT_IMAGE_PNG ? ".png" : ".ppm";
    for (size_t i = 0; i < sizeof scenes / sizeof *scenes; i++) {
        char scene[4200], expected[8600], wrong[8600];
        snprintf(scene, sizeof scene, "%s",
                 copy_in(dir, scenes[i].from, scenes[i].name));
        view_app *app = open_default_app(1);
        ck_assert_msg(view_app_open(app, scene) && view_app_wait_load(app),
                      "%s", view_app_message(app));
        ck_assert_int_eq(rt_test_view_wait(view_app_session(app)),
                         VIEW_DONE);
        char path[4200];
        for (int n = 1; n <= 2; n++) {
            ck_assert_msg(view_app_save(app, path, sizeof path), "%s",
                          view_app_message(app));
            snprintf(expected, sizeof expected, "%s/%s-%d%s", dir,
                     scenes[i].stem, n, extension);
            ck_assert_str_eq(path, expected);
            ck_assert(exists(expected));
            snprintf(wrong, sizeof wrong, "%s-%d%s", scene, n, extension);
            ck_assert_msg(!exists(wrong), "%s", wrong);
        }
        rt_test_view_app_close(app);

        /* 1024 rays a pixel on one thread, stopped at once: surely
         * unfinished when S is pressed. */
        app = open_default_app(1024);
        ck_assert(view_app_open(app, scene) && view_app_wait_load(app));
        view_session *session = view_app_session(app);
        view_session_cancel(session);
        view_progress progress;
        view_session_get_progress(session, &progress);
        ck_assert_int_lt(progress.rows_done, progress.rows_total);
        ck_assert(view_app_save(app, path, sizeof path));
        snprintf(expected, sizeof expected, "%s/%s-partial-1%s", dir,
                 scenes[i].stem, extension);
        ck_assert_str_eq(path, expected);
        snprintf(wrong, sizeof wrong, "%s-partial-1%s", scene, extension);
        ck_assert_msg(!exists(wrong), "%s", wrong);
        rt_test_view_app_close(app);
    }
    rt_test_remove_dir(dir);
}
END_TEST

static Suite *outputs_suite(void)
{
    Suite *s = suite_create("viewer_outputs");
    TCase *c = tcase_create("save");
    tcase_set_timeout(c, 120);
    tcase_add_test(c, save_refuses_an_output_that_is_the_scene);
    tcase_add_test(c,
                   saves_are_named_after_the_scenes_stem_whatever_its_extension);
    suite_add_tcase(s, c);
    return s;
}

static Suite *sources_suite(void)
{
    Suite *s = suite_create("viewer_outputs_sources");
    TCase *c = tcase_create("libraries");
    tcase_set_timeout(c, 120);
    tcase_add_test(c, save_refuses_the_material_library_its_obj_read);
    suite_add_tcase(s, c);
    return s;
}

int main(int argc, char **argv)
{
    return rt_test_main_with_sources(argc, argv, outputs_suite, sources_suite);
}
