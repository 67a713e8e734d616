/*
 * test_viewer_app.c - rt-view's app (view_app) driven without its event
 * loop on SDL's dummy video driver: R reloads the edited file, a failing
 * reload keeps the picture and says why, --watch reloads when the file
 * changes and only then, saves are numbered and never replace an earlier
 * one, a save mid-render is partial, a scene that never loaded exits 1 when
 * the window closes, and rt-view without a display says so at once.
 */
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <pthread.h>
#include <semaphore.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>

#define SDL_MAIN_HANDLED
#include <SDL.h>

#include "testutil.h"
#include "view_scene.h"
#include "viewer.h"

/* Moves the file's modification time `seconds` on, so that --watch sees a
 * change even on a file system with coarse times. */
static void touch_later(const char *path, int seconds)
{
    struct stat info;
    ck_assert_int_eq(stat(path, &info), 0);
    struct timespec times[2] = {info.st_atim, info.st_mtim};
    times[1].tv_sec += seconds;
    ck_assert_int_eq(utimensat(AT_FDCWD, path, times, 0), 0);
}

/* The background colour of the image's top-left pixel (two-facets shows
 * the background there). */
static int shows_background(const rt_image *image, int r, int g, int b)
{
    const unsigned char *pixel = rt_image_pixel(image, 0, 0);
    return pixel[0] == r && pixel[1] == g && pixel[2] == b;
}

/* Writes the scene with the background r, g, b, presses R and checks the
 * new picture, with no error left in the title. */
static void edit_and_reload(view_app *app, const char *path, int r, int g,
                            int b)
{
    char background[64];
    snprintf(background, sizeof background, "%d, %d, %d", r, g, b);
    rt_test_write_two_facet_scene(path, background);
    ck_assert(view_app_reload(app));
    ck_assert(view_app_wait_load(app));
    ck_assert(shows_background(rt_test_view_app_image(app), r, g, b));
    ck_assert_str_eq(view_app_message(app), "");
}

START_TEST(reload_reads_the_edited_file)
{
    rt_test_write_two_facet_scene("viewer-reload.scn", "30, 30, 60");
    view_app *app = rt_test_view_app(NULL, 0, 1);
    ck_assert(rt_test_view_app_load(app, "viewer-reload.scn"));
    ck_assert(shows_background(rt_test_view_app_image(app), 30, 30, 60));
    edit_and_reload(app, "viewer-reload.scn", 200, 10, 10);
    rt_test_view_app_close(app);
    remove("viewer-reload.scn");
}
END_TEST

START_TEST(failing_reload_keeps_the_picture_and_reports_the_error)
{
    rt_test_write_two_facet_scene("viewer-broken.scn", "30, 30, 60");
    view_app *app = rt_test_view_app(NULL, 0, 1);
    ck_assert(rt_test_view_app_load(app, "viewer-broken.scn"));
    const rt_image *before = rt_test_view_app_image(app);
    view_session *session = view_app_session(app);
    rt_test_write_two_facet_scene("viewer-broken.scn", "30, 30");
    ck_assert(view_app_reload(app));
    ck_assert(!view_app_wait_load(app));
    ck_assert_ptr_eq(view_app_session(app), session);
    ck_assert_ptr_eq(rt_test_view_app_image(app), before);
    ck_assert(shows_background(before, 30, 30, 60));
    /* FILE:LINE:COLUMN: the background is line 13. */
    ck_assert_msg(strncmp(view_app_message(app), "viewer-broken.scn:13:",
                          21) == 0,
                  "%s", view_app_message(app));
    /* Fixed, it loads again and the error goes. */
    edit_and_reload(app, "viewer-broken.scn", 10, 200, 10);
    ck_assert_int_eq(view_app_exit_status(app), 0);
    rt_test_view_app_close(app);
    remove("viewer-broken.scn");
}
END_TEST

START_TEST(watch_reloads_when_the_file_changes_and_only_then)
{
    rt_test_write_two_facet_scene("viewer-watch.scn", "30, 30, 60");
    view_app *app = rt_test_view_app(NULL, 1, 1);
    ck_assert(rt_test_view_app_load(app, "viewer-watch.scn"));
    ck_assert(shows_background(rt_test_view_app_image(app), 30, 30, 60));
    ck_assert(!view_app_check_watch(app));
    rt_test_write_two_facet_scene("viewer-watch.scn", "60, 30, 30");
    touch_later("viewer-watch.scn", 2);
    ck_assert(view_app_check_watch(app));
    ck_assert(view_app_wait_load(app));
    ck_assert(shows_background(rt_test_view_app_image(app), 60, 30, 30));
    ck_assert(!view_app_check_watch(app));
    /* Removed (an editor between delete and rename): nothing happens, and
     * the new file is read when it appears. */
    remove("viewer-watch.scn");
    ck_assert(!view_app_check_watch(app));
    ck_assert_str_eq(view_app_message(app), "");
    rt_test_write_two_facet_scene("viewer-watch.scn", "30, 60, 30");
    ck_assert(view_app_check_watch(app));
    ck_assert(view_app_wait_load(app));
    ck_assert(shows_background(rt_test_view_app_image(app), 30, 60, 30));
    rt_test_view_app_close(app);
    remove("viewer-watch.scn");
}
END_TEST

START_TEST(saves_are_numbered_and_never_replace_an_earlier_one)
{
    remove("viewer-save-1.ppm");
    remove("viewer-save-2.ppm");
    remove("viewer-save-3.ppm");
    rt_test_write_two_facet_scene("viewer-save.scn", "30, 30, 60");
    /* A file of that name from before is not a candidate. */
    rt_test_write_two_facet_scene("viewer-save-1.ppm", "not an image");
    view_app *app = rt_test_view_app(NULL, 0, 1);
    ck_assert(rt_test_view_app_load(app, "viewer-save.scn"));
    rt_test_view_app_image(app);
    char path[256];
    ck_assert(view_app_save(app, path, sizeof path));
    ck_assert_str_eq(path, "viewer-save-2.ppm");
    size_t first_size;
    char *first = rt_test_read_file(path, &first_size);
    ck_assert_ptr_nonnull(first);

    edit_and_reload(app, "viewer-save.scn", 200, 10, 10);
    ck_assert(view_app_save(app, path, sizeof path));
    ck_assert_str_eq(path, "viewer-save-3.ppm");
    size_t again_size;
    char *again = rt_test_read_file("viewer-save-2.ppm", &again_size);
    ck_assert_ptr_nonnull(again);
    ck_assert(first_size == again_size &&
              memcmp(first, again, first_size) == 0);
    free(again);
    again = rt_test_read_file("viewer-save-1.ppm", &again_size);
    ck_assert_ptr_nonnull(again);
    ck_assert(strstr(again, "not an image") != NULL);

    rt_image saved;
    rt_error error;
    ck_assert_int_eq(rt_ppm_load("viewer-save-3.ppm", &saved, &error),
                     RT_OK);
    ck_assert(shows_background(&saved, 200, 10, 10));
    rt_image_release(&saved);
    free(first);
    free(again);
    rt_test_view_app_close(app);
    remove("viewer-save.scn");
    remove("viewer-save-1.ppm");
    remove("viewer-save-2.ppm");
    remove("viewer-save-3.ppm");
}
END_TEST

START_TEST(a_save_mid_render_is_partial_and_replaces_no_complete_one)
{
    remove("viewer-out.ppm");
    remove("viewer-out-1.ppm");
    remove("viewer-out-partial-1.ppm");
    rt_test_write_two_facet_scene("viewer-mid.scn", "30, 30, 60");
    view_app *app = rt_test_view_app("viewer-out.ppm", 0, 1);
    ck_assert(rt_test_view_app_load(app, "viewer-mid.scn"));
    rt_test_view_app_image(app);
    char path[256];
    ck_assert(view_app_save(app, path, sizeof path));
    ck_assert_str_eq(path, "viewer-out.ppm");
    /* A second complete save goes beside -o's path. */
    ck_assert(view_app_save(app, path, sizeof path));
    ck_assert_str_eq(path, "viewer-out-1.ppm");
    rt_test_view_app_close(app);
    size_t first_size;
    char *first = rt_test_read_file("viewer-out.ppm", &first_size);
    ck_assert_ptr_nonnull(first);

    /* 1024 rays a pixel on one thread, stopped at once: surely unfinished
     * when S is pressed. */
    app = rt_test_view_app("viewer-out.ppm", 0, 1024);
    ck_assert(rt_test_view_app_load(app, "viewer-mid.scn"));
    view_session *session = view_app_session(app);
    view_session_cancel(session);
    view_progress progress;
    view_session_get_progress(session, &progress);
    ck_assert_int_lt(progress.rows_done, progress.rows_total);
    ck_assert(view_app_save(app, path, sizeof path));
    ck_assert_str_eq(path, "viewer-out-partial-1.ppm");
    size_t again_size;
    char *again = rt_test_read_file("viewer-out.ppm", &again_size);
    ck_assert_ptr_nonnull(again);
    ck_assert(first_size == again_size &&
              memcmp(first, again, first_size) == 0);
    free(first);
    free(again);
    rt_test_view_app_close(app);
    remove("viewer-mid.scn");
    remove("viewer-out.ppm");
    remove("viewer-out-1.ppm");
    remove("viewer-out-partial-1.ppm");
}
END_TEST

START_TEST(a_scene_that_never_loaded_exits_1_when_the_window_closes)
{
    view_app *app = rt_test_view_app(NULL, 0, 1);
    ck_assert(!rt_test_view_app_load(app, "viewer-no-such-scene.scn"));
    SDL_Event quit;
    SDL_zero(quit);
    quit.type = SDL_QUIT;
    ck_assert_int_eq(SDL_PushEvent(&quit), 1);
    view_app_run(app);
    ck_assert_int_eq(view_app_exit_status(app), 1);
    rt_test_view_app_close(app);

    /* No scene asked for, or one that loaded: 0. */
    app = rt_test_view_app(NULL, 0, 1);
    ck_assert_int_eq(SDL_PushEvent(&quit), 1);
    view_app_run(app);
    ck_assert_int_eq(view_app_exit_status(app), 0);
    ck_assert(rt_test_view_app_load(app,
                                    rt_test_source_path("scenes/empty.scn")));
    ck_assert_int_eq(view_app_exit_status(app), 0);
    rt_test_view_app_close(app);
}
END_TEST

START_TEST(without_a_display_rt_view_says_so_and_exits_1_at_once)
{
    char command[4096];
    snprintf(command, sizeof command,
             "env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER "
             "timeout -s KILL 10 '%s' '%s' 2>viewer-nodisplay.txt",
             RT_VIEW_PATH, rt_test_source_path("scenes/cubes.scn"));
    double start = rt_test_now();
    int status = system(command);
    double seconds = rt_test_now() - start;
    ck_assert_msg(WIFEXITED(status) && WEXITSTATUS(status) == 1,
                  "status %d after %.2f s", status, seconds);
    ck_assert_msg(seconds < 2.0, "took %.2f s", seconds);
    size_t size;
    char *message = rt_test_read_file("viewer-nodisplay.txt", &size);
    ck_assert_ptr_nonnull(message);
    message[size] = '\0';
    ck_assert_msg(strstr(message, "rt-view: cannot open a window: ") ==
                          message &&
                      strstr(message, "rt-export renders without a display"),
                  "%s", message);
    free(message);
    remove("viewer-nodisplay.txt");
}
END_TEST

static Suite *viewer_app_suite(void)
{
    Suite *suite = suite_create("viewer_app");
    TCase *app = tcase_create("app");
    tcase_set_timeout(app, 120);
    tcase_add_test(app, reload_reads_the_edited_file);
    tcase_add_test(app, failing_reload_keeps_the_picture_and_reports_the_error);
    tcase_add_test(app, watch_reloads_when_the_file_changes_and_only_then);
    tcase_add_test(app, saves_are_numbered_and_never_replace_an_earlier_one);
    tcase_add_test(app,
                   a_save_mid_render_is_partial_and_replaces_no_complete_one);
    tcase_add_test(app,
                   a_scene_that_never_loaded_exits_1_when_the_window_closes);
    tcase_add_test(app, without_a_display_rt_view_says_so_and_exits_1_at_once);
    suite_add_tcase(suite, app);
    return suite;
}

RT_CHECK_MAIN(viewer_app_suite)
