/*
 * test_viewer.c - the viewer's logic without its event loop: a view_session
 * rendering on its own thread, shown by a view_window on SDL's dummy video
 * driver with the software renderer (no display needed), and read back
 * pixel by pixel.  Dummy rather than offscreen: offscreen initialises EGL,
 * whose allocations LeakSanitizer reports as leaks.
 *
 * What is checked: the finished window shows exactly rt-export's image; a
 * frame taken while rendering shows finished rows exactly and the
 * placeholder everywhere else (on images small enough to have one pass:
 * test_viewer_progressive.c has the coarse passes); cancelling stops the
 * render well under a second and leaves no thread; a session's first
 * render starts from the placeholder, a restart keeps the old pixels until
 * the new render replaces them; and the small pure helpers (window
 * fitting, save path, rescaling, errors, numbered names).  The app around
 * them has test_viewer_app.c, the click overlay and the debug views
 * test_viewer_overlay.c; what they share is in support/viewer.h.
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

static int row_equals(const rt_image *a, const rt_image *b, int y)
{
    return memcmp(rt_image_pixel(a, 0, y), rt_image_pixel(b, 0, y),
                  (size_t)a->width * 3) == 0;
}

/* Renders `scene` through a session and a window of its size; returns what
 * the window shows at the end. */
static rt_image show_until_done(rt_scene *scene, int threads)
{
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    view_window *window = rt_test_view_window_open(info.width, info.height);
    view_session *session = rt_test_view_session(scene, threads, NULL, NULL);
    ck_assert(view_window_attach(window, session, NULL, 0));
    ck_assert_int_eq(view_session_start(session), RT_OK);
    double deadline = rt_test_now() + RT_TEST_VIEW_WAIT_SECONDS;
    view_progress progress;
    do {
        view_session_get_progress(session, &progress);
        if (view_window_sync(window))
            view_window_draw(window);
        ck_assert_msg(rt_test_now() < deadline, "render did not finish");
        rt_test_sleep_ms(5);
    } while (progress.state == VIEW_RENDERING);
    view_window_sync(window);
    ck_assert_int_eq(progress.state, VIEW_DONE);
    ck_assert_int_eq(progress.rows_done, info.height);
    rt_image frame = rt_test_view_window_read(window);
    view_window_attach(window, NULL, NULL, 0);
    view_session_destroy(session);
    rt_test_view_window_close(window);
    return frame;
}

START_TEST(finished_window_equals_rt_export_image_pixel_for_pixel)
{
    const char *scene_path = rt_test_source_path("scenes/cubes.scn");
    char command[4096];
    snprintf(command, sizeof command,
             "'%s' '%s' -o viewer-cubes-export.ppm -q >/dev/null",
             RT_EXPORT_PATH, scene_path);
    ck_assert_msg(system(command) == 0, "failed: %s", command);
    rt_image exported;
    rt_error error;
    ck_assert_msg(rt_ppm_load("viewer-cubes-export.ppm", &exported, &error) ==
                      RT_OK,
                  "%s", error.message);
    remove("viewer-cubes-export.ppm");

    rt_image frame =
        show_until_done(rt_test_load_source_scene("scenes/cubes.scn"), 0);
    ck_assert_int_eq(frame.width, exported.width);
    ck_assert_int_eq(frame.height, exported.height);
    rt_test_assert_same_image(&frame, &exported, "viewer-cubes");
    rt_image_release(&frame);
    rt_image_release(&exported);
}
END_TEST

START_TEST(finished_window_equals_library_render_for_each_scene)
{
    static const char *const scenes[] = {
        "scenes/two-facets.scn", "scenes/one-facet.scn", "scenes/empty.scn"};
    for (size_t i = 0; i < sizeof scenes / sizeof scenes[0]; i++) {
        rt_scene *reference_scene = rt_test_load_source_scene(scenes[i]);
        rt_image expected = rt_test_render(reference_scene, RT_DEFAULT_DEPTH, 1);
        rt_scene_destroy(reference_scene);
        rt_image frame = show_until_done(rt_test_load_source_scene(scenes[i]),
                                         (int)i % 3);
        rt_test_assert_same_image(&frame, &expected, "viewer-scene");
        rt_image_release(&frame);
        rt_image_release(&expected);
    }
}
END_TEST

/* Freezes the render at each notification until the test lets it go: the
 * thread in the row callback waits, and the others wait for the callback's
 * lock, so no row is marked finished while a frame is checked. */
typedef struct gate {
    sem_t paused;
    sem_t resume;
} gate;

static void gate_notify(void *user)
{
    gate *g = user;
    sem_post(&g->paused);
    sem_wait(&g->resume);
}

static void wait_paused(gate *g)
{
    struct timespec deadline;
    clock_gettime(CLOCK_REALTIME, &deadline);
    deadline.tv_sec += (time_t)RT_TEST_VIEW_WAIT_SECONDS;
    int result;
    do
        result = sem_timedwait(&g->paused, &deadline);
    while (result != 0 && errno == EINTR);
    ck_assert_msg(result == 0, "the render never notified");
}

/* 96 x 72 is under VIEW_COARSE_MIN_PIXELS: one pass, each row shown once,
 * final. */
START_TEST(intermediate_frames_show_only_finished_rows)
{
    rt_scene *reference_scene = rt_test_view_heavy_scene(300, 96, 72);
    rt_image expected = rt_test_render(reference_scene, RT_DEFAULT_DEPTH, 1);
    rt_scene_destroy(reference_scene);

    gate g;
    ck_assert_int_eq(sem_init(&g.paused, 0, 0), 0);
    ck_assert_int_eq(sem_init(&g.resume, 0, 0), 0);
    view_window *window = rt_test_view_window_open(expected.width,
                                                   expected.height);
    view_session *session = rt_test_view_session(rt_test_view_heavy_scene(300, 96, 72), 2,
                                                 gate_notify, &g);
    ck_assert(view_window_attach(window, session, NULL, 0));

    rt_image first = rt_test_view_window_read(window);
    for (int y = 0; y < first.height; y++)
        ck_assert_msg(rt_test_view_row_is_placeholder(&first, y),
                      "row %d is not the placeholder before the render", y);
    rt_image_release(&first);

    ck_assert_int_eq(view_session_start(session), RT_OK);
    int partial_frames = 0;
    for (;;) {
        wait_paused(&g);
        view_window_sync(window);
        rt_image frame = rt_test_view_window_read(window);
        int finished = 0;
        for (int y = 0; y < frame.height; y++) {
            if (view_session_row_done(session, y)) {
                finished++;
                ck_assert_msg(row_equals(&frame, &expected, y),
                              "finished row %d is not the rendered row", y);
            } else {
                ck_assert_msg(rt_test_view_row_is_placeholder(&frame, y),
                              "unfinished row %d shows something", y);
            }
        }
        rt_image_release(&frame);
        partial_frames += finished > 0 && finished < expected.height;
        view_progress progress;
        view_session_get_progress(session, &progress);
        sem_post(&g.resume);
        if (progress.state != VIEW_RENDERING) {
            ck_assert_int_eq(progress.state, VIEW_DONE);
            break;
        }
    }
    ck_assert_int_ge(partial_frames, 2);
    view_window_sync(window);
    rt_image final_frame = rt_test_view_window_read(window);
    rt_test_assert_same_image(&final_frame, &expected, "viewer-gated");

    rt_image_release(&final_frame);
    view_window_attach(window, NULL, NULL, 0);
    view_session_destroy(session);
    rt_test_view_window_close(window);
    sem_destroy(&g.paused);
    sem_destroy(&g.resume);
    rt_image_release(&expected);
}
END_TEST

START_TEST(cancel_stops_the_render_promptly_and_leaves_no_thread)
{
    int threads_before = rt_test_baseline_thread_count();
    view_session *session = rt_test_view_session(rt_test_view_heavy_scene(2000, 48, 1500), 0,
                                                 NULL, NULL);
    ck_assert_int_eq(view_session_start(session), RT_OK);

    view_progress progress;
    double deadline = rt_test_now() + RT_TEST_VIEW_WAIT_SECONDS;
    do {
        rt_test_sleep_ms(1);
        view_session_get_progress(session, &progress);
        ck_assert(rt_test_now() < deadline);
    } while (progress.rows_done < 3 && progress.state == VIEW_RENDERING);
    ck_assert_msg(progress.state == VIEW_RENDERING,
                  "the heavy scene finished before it could be cancelled");
    ck_assert_int_gt(rt_test_thread_count(), threads_before);

    double started = rt_test_now();
    view_session_cancel(session);
    double took = rt_test_now() - started;
    if (getenv("RT_TEST_VERBOSE"))
        fprintf(stderr, "cancel: %.4f s after %d rows\n", took,
                progress.rows_done);
    ck_assert_msg(took < 0.5, "cancelling took %.3f s", took);
    ck_assert_int_eq(rt_test_settled_thread_count(threads_before, 0.2),
                     threads_before);

    view_session_get_progress(session, &progress);
    ck_assert_int_eq(progress.state, VIEW_CANCELLED);
    ck_assert_int_eq(progress.status, RT_ERR_CANCELLED);
    ck_assert_int_lt(progress.rows_final, progress.rows_total);
    char text[96];
    view_progress_describe(&progress, text, sizeof text);
    ck_assert_msg(strncmp(text, "cancelled at ", 13) == 0, "%s", text);

    /* Rows it reports final stay; nothing else is marked. */
    int marked = 0;
    for (int y = 0; y < progress.rows_total; y++)
        marked += view_session_row_done(session, y);
    ck_assert_int_eq(marked, progress.rows_final);

    view_session_destroy(session);
    ck_assert_int_eq(rt_test_settled_thread_count(threads_before, 0.2),
                     threads_before);
}
END_TEST

START_TEST(destroying_a_rendering_session_joins_its_thread)
{
    int threads_before = rt_test_baseline_thread_count();
    for (int i = 0; i < 5; i++) {
        view_session *session = rt_test_view_session(rt_test_view_heavy_scene(1500, 64, 400),
                                                     i % 3, NULL, NULL);
        ck_assert_int_eq(view_session_start(session), RT_OK);
        rt_test_sleep_ms(i * 7);
        double started = rt_test_now();
        view_session_destroy(session);
        double took = rt_test_now() - started;
        ck_assert_msg(took < 0.5, "destroying took %.3f s", took);
        ck_assert_int_eq(rt_test_settled_thread_count(threads_before, 0.2),
                         threads_before);
    }
}
END_TEST

START_TEST(restart_keeps_the_old_pixels_until_the_new_render_replaces_them)
{
    rt_scene *reference_scene = rt_test_view_heavy_scene(400, 80, 60);
    rt_image expected = rt_test_render(reference_scene, 2, 1);
    rt_image before = rt_test_render(reference_scene, RT_DEFAULT_DEPTH, 1);
    rt_scene_destroy(reference_scene);

    view_window *window = rt_test_view_window_open(80, 60);
    view_session *session = rt_test_view_session(rt_test_view_heavy_scene(400, 80, 60), 0,
                                                 NULL,
                                                 NULL);
    ck_assert(view_window_attach(window, session, NULL, 0));
    /* A session's first render starts from the checker. */
    rt_image frame = rt_test_view_window_read(window);
    for (int y = 0; y < frame.height; y++)
        ck_assert(rt_test_view_row_is_placeholder(&frame, y));
    rt_image_release(&frame);
    ck_assert_int_eq(view_session_start(session), RT_OK);
    ck_assert_int_eq(rt_test_view_wait(session), VIEW_DONE);
    view_window_sync(window);
    frame = rt_test_view_window_read(window);
    rt_test_assert_same_image(&frame, &before, "viewer-before-restart");
    rt_image_release(&frame);

    /* A depth change takes effect at the next start. */
    ck_assert_int_eq(view_session_set_depth(session, -1), RT_ERR_ARGUMENT);
    ck_assert_int_eq(view_session_set_depth(session, VIEW_MAX_DEPTH + 1),
                     RT_ERR_ARGUMENT);
    ck_assert_int_eq(view_session_set_depth(session, 2), RT_OK);
    view_session_cancel(session);
    ck_assert_int_eq(view_session_start(session), RT_OK);
    view_session_cancel(session);
    view_progress progress;
    view_session_get_progress(session, &progress);
    ck_assert_int_eq(progress.generation, 2);
    ck_assert_int_eq(progress.max_depth, 2);

    /* The frame after a restart shows the new render's rows and the old
     * render everywhere else: no checker (80 x 60 has one pass, so every
     * row the new render reached is final). */
    view_window_sync(window);
    frame = rt_test_view_window_read(window);
    for (int y = 0; y < frame.height; y++) {
        if (view_session_row_done(session, y))
            ck_assert(row_equals(&frame, &expected, y));
        else
            ck_assert_msg(row_equals(&frame, &before, y),
                          "row %d is neither the new render nor the old", y);
    }
    rt_image_release(&frame);

    ck_assert_int_eq(view_session_start(session), RT_OK);
    ck_assert_int_eq(rt_test_view_wait(session), VIEW_DONE);
    view_window_sync(window);
    frame = rt_test_view_window_read(window);
    rt_test_assert_same_image(&frame, &expected, "viewer-restart");
    rt_image_release(&frame);

    view_window_attach(window, NULL, NULL, 0);
    view_session_destroy(session);
    rt_test_view_window_close(window);
    rt_image_release(&expected);
    rt_image_release(&before);
}
END_TEST

START_TEST(taking_rows_returns_each_finished_row_once_in_order)
{
    view_session *session = rt_test_view_session(rt_test_view_heavy_scene(50, 32, 300), 0,
                                                 NULL,
                                                 NULL);
    const rt_image *image = view_session_image(session);
    int *rows = malloc(sizeof *rows * (size_t)image->height);
    char *seen = calloc((size_t)image->height, 1);
    ck_assert(rows != NULL && seen != NULL);
    unsigned generation = 0;
    ck_assert_int_eq(view_session_take_finished_rows(session, rows,
                                                     image->height,
                                                     &generation),
                     0);
    ck_assert_int_eq(generation, 0);

    ck_assert_int_eq(view_session_start(session), RT_OK);
    int total = 0;
    view_progress progress;
    do {
        view_session_get_progress(session, &progress);
        int count = view_session_take_finished_rows(session, rows, 7,
                                                    &generation);
        ck_assert_int_eq(generation, 1);
        for (int i = 0; i < count; i++) {
            ck_assert(rows[i] >= 0 && rows[i] < image->height);
            ck_assert_msg(!seen[rows[i]], "row %d taken twice", rows[i]);
            if (i > 0)
                ck_assert_int_lt(rows[i - 1], rows[i]);
            seen[rows[i]] = 1;
        }
        total += count;
    } while (progress.state == VIEW_RENDERING || total < image->height);
    ck_assert_int_eq(total, image->height);
    ck_assert_int_eq(view_session_take_finished_rows(session, rows,
                                                     image->height, NULL),
                     0);
    free(rows);
    free(seen);
    view_session_destroy(session);
}
END_TEST

START_TEST(progress_describes_each_state)
{
    view_progress p = {VIEW_RENDERING, 42, 100, 5, 1.25, RT_OK, 1};
    char text[96];
    view_progress_describe(&p, text, sizeof text);
    ck_assert_str_eq(text, "42% - 1.2 s");
    p.state = VIEW_DONE;
    p.rows_done = 100;
    p.seconds = 2.414;
    view_progress_describe(&p, text, sizeof text);
    ck_assert_str_eq(text, "done in 2.41 s");
    p.state = VIEW_FAILED;
    p.status = RT_ERR_NOMEM;
    view_progress_describe(&p, text, sizeof text);
    ck_assert_str_eq(text, "failed: out of memory");
}
END_TEST

START_TEST(window_fits_the_screen_keeping_the_aspect_ratio)
{
    int w, h;
    view_fit_size(400, 300, 1264, 976, &w, &h);
    ck_assert_int_eq(w, 400);
    ck_assert_int_eq(h, 300);
    view_fit_size(4000, 1000, 1264, 976, &w, &h);
    ck_assert_int_eq(w, 1264);
    ck_assert_int_eq(h, 316);
    view_fit_size(1000, 4000, 1264, 976, &w, &h);
    ck_assert_int_eq(w, 244);
    ck_assert_int_eq(h, 976);
    view_fit_size(16384, 1, 800, 600, &w, &h);
    ck_assert_int_eq(w, 800);
    ck_assert_int_eq(h, 1);
}
END_TEST

START_TEST(image_is_saved_next_to_the_scene)
{
    /* rt-export's default output name (the stem, whatever the extension),
     * in the scene's folder. */
    char path[64];
    ck_assert(view_scene_image_path("scenes/cubes.scn", RT_IMAGE_P6, path,
                                    sizeof path));
    ck_assert_str_eq(path, "scenes/cubes.ppm");
    ck_assert(view_scene_image_path("scenes/cubes.scn", RT_IMAGE_PNG, path,
                                    sizeof path));
    ck_assert_str_eq(path, "scenes/cubes.png");
    ck_assert(view_scene_image_path("/a.b/scene", RT_IMAGE_P6, path,
                                    sizeof path));
    ck_assert_str_eq(path, "/a.b/scene.ppm");
    ck_assert(view_scene_image_path("x.txt", RT_IMAGE_P6, path, sizeof path));
    ck_assert_str_eq(path, "x.ppm");
    ck_assert(view_scene_image_path("dir/.scn", RT_IMAGE_P6, path,
                                    sizeof path));
    ck_assert_str_eq(path, "dir/.scn.ppm");
    ck_assert(!view_scene_image_path("a-rather-long-name.scn", RT_IMAGE_P6,
                                     path, 8));
}
END_TEST

START_TEST(size_renders_the_library_image_of_that_size_without_a_copy)
{
    /* --scale 2 of two-facets (64 x 48) asks for 128 x 96. */
    ck_assert_int_eq(view_scale_side(64, 2.0), 128);
    ck_assert_int_eq(view_scale_side(48, 0.01), 1);
    ck_assert_int_eq(view_scale_side(400, 64.0), RT_MAX_IMAGE_SIDE + 1);

    rt_scene *scene = rt_test_load_source_scene("scenes/two-facets.scn");
    rt_render_options render;
    rt_render_options_init(&render);
    render.width = 128;
    render.height = 96;
    render.threads = 1;
    rt_image expected = rt_test_render_with(scene, &render);
    view_session_options options;
    view_session_options_init(&options);
    options.render = render;
    view_session *session = NULL;
    ck_assert_int_eq(view_session_create(scene, &options, &session, NULL),
                     RT_OK);
    const rt_image *image = view_session_image(session);
    ck_assert_int_eq(image->width, 128);
    ck_assert_int_eq(image->height, 96);
    ck_assert_int_eq(view_session_start(session), RT_OK);
    ck_assert_int_eq(rt_test_view_wait(session), VIEW_DONE);
    rt_test_assert_same_image(image, &expected, "viewer-size");
    view_session_destroy(session);
    rt_image_release(&expected);
}
END_TEST

START_TEST(size_beyond_the_image_limit_is_refused_with_a_reason)
{
    view_session_options options;
    view_session_options_init(&options);
    options.render.width = RT_MAX_IMAGE_SIDE + 1;
    options.render.height = 10;
    view_session *session = (view_session *)1;
    rt_error error;
    rt_scene *scene = rt_test_load_source_scene("scenes/cubes.scn");
    ck_assert_int_eq(view_session_create(scene, &options, &session, &error),
                     RT_ERR_ARGUMENT);
    ck_assert_ptr_null(session);
    ck_assert_msg(error.message[0] != '\0', "no reason given");
}
END_TEST

START_TEST(bad_scene_reports_file_line_and_column)
{
    FILE *file = fopen("viewer-bad.scn", "w");
    ck_assert(file != NULL);
    fputs("0 0 10\n0 0 5 4 0 5 64 48\n2\n1 2 3\n1 2\n", file);
    fclose(file);
    rt_scene *scene = (rt_scene *)1;
    rt_error error;
    ck_assert_int_ne(view_scene_load("viewer-bad.scn", NULL, &scene, &error),
                     RT_OK);
    ck_assert_ptr_null(scene);
    ck_assert_msg(strncmp(error.message, "viewer-bad.scn:5:", 17) == 0, "%s",
                  error.message);
    ck_assert_int_ne(view_scene_load("viewer-missing.scn", NULL, &scene,
                                     &error),
                     RT_OK);
    ck_assert_ptr_null(scene);
    remove("viewer-bad.scn");
}
END_TEST

START_TEST(numbered_names_are_claimed_exclusively)
{
    char a[64], b[64];
    rt_error error;
    remove("viewer-claim-1.png");
    remove("viewer-claim-2.png");
    ck_assert(view_save_claim_numbered("viewer-claim.png", NULL, a, sizeof a,
                                       &error));
    ck_assert(view_save_claim_numbered("viewer-claim.png", NULL, b, sizeof b,
                                       &error));
    ck_assert_str_eq(a, "viewer-claim-1.png");
    ck_assert_str_eq(b, "viewer-claim-2.png");
    ck_assert(view_save_claim_numbered("dir.d/plain", "partial", a, sizeof a,
                                       &error) == 0);
    ck_assert_msg(strstr(error.message, "dir.d/plain-partial-1") != NULL,
                  "%s", error.message);
    ck_assert(!view_save_claim_numbered("viewer-claim.png", NULL, a, 8,
                                        &error));
    remove("viewer-claim-1.png");
    remove("viewer-claim-2.png");
}
END_TEST

static Suite *viewer_suite(void)
{
    Suite *suite = suite_create("viewer");
    TCase *window = tcase_create("window");
    tcase_set_timeout(window, 120);
    tcase_add_test(window,
                   finished_window_equals_rt_export_image_pixel_for_pixel);
    tcase_add_test(window, finished_window_equals_library_render_for_each_scene);
    tcase_add_test(window, intermediate_frames_show_only_finished_rows);
    tcase_add_test(window,
                   restart_keeps_the_old_pixels_until_the_new_render_replaces_them);
    suite_add_tcase(suite, window);

    TCase *session = tcase_create("session");
    tcase_set_timeout(session, 120);
    tcase_add_test(session, cancel_stops_the_render_promptly_and_leaves_no_thread);
    tcase_add_test(session, destroying_a_rendering_session_joins_its_thread);
    tcase_add_test(session, taking_rows_returns_each_finished_row_once_in_order);
    tcase_add_test(session, progress_describes_each_state);
    suite_add_tcase(suite, session);

    TCase *helpers = tcase_create("helpers");
    tcase_add_test(helpers, window_fits_the_screen_keeping_the_aspect_ratio);
    tcase_add_test(helpers, image_is_saved_next_to_the_scene);
    tcase_add_test(helpers,
                   size_renders_the_library_image_of_that_size_without_a_copy);
    tcase_add_test(helpers,
                   size_beyond_the_image_limit_is_refused_with_a_reason);
    tcase_add_test(helpers, bad_scene_reports_file_line_and_column);
    tcase_add_test(helpers, numbered_names_are_claimed_exclusively);
    suite_add_tcase(suite, helpers);
    return suite;
}

RT_CHECK_MAIN(viewer_suite)
