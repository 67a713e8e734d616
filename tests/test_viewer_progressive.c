/*
 * test_viewer_progressive.c - a view_session's passes, coarse to fine
 * (apps/rt-view/view_session.h), and its debug views and cameras, on SDL's
 * dummy video driver with the software renderer (no display needed).
 *
 * What is checked: the pass schedule; a coarse pass's camera sees each
 * block through its centre (by the camera formula of
 * docs/rendering-model.md); a frame frozen at each notification shows each
 * row as the pass under way or the one before left it (the passes' images
 * rendered by the library and enlarged here), the passes come in order,
 * and the last is rt_render's image byte for byte, with 1 sample and with
 * 4; a restart mid-pass cancels that render (its report says where) and
 * the next runs every pass; a debug view renders exactly rt_render_view's
 * bytes on two threads, rows reported, and cancels; a camera set on the
 * session renders what rt_render gives with options.camera; the finished
 * picture comes back at once after a view, and not after a change of
 * depth; and the words of the title and of --stats.  Nothing here asserts
 * a time.
 */
#include <errno.h>
#include <math.h>
#include <semaphore.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define SDL_MAIN_HANDLED
#include <SDL.h>

#include "testutil.h"
#include "viewer.h"

/* A session of `scene` with `render` options (notify and its user may be
 * NULL). */
static view_session *session_with(rt_scene *scene,
                                  const rt_render_options *render,
                                  view_notify_func notify, void *user)
{
    view_session_options options;
    view_session_options_init(&options);
    options.render = *render;
    options.notify = notify;
    options.notify_user = user;
    view_session *session = NULL;
    rt_error error;
    ck_assert_msg(view_session_create(scene, &options, &session, &error) ==
                      RT_OK,
                  "%s", error.message);
    return session;
}

static int row_equals(const rt_image *a, const rt_image *b, int y)
{
    return memcmp(rt_image_pixel(a, 0, y), rt_image_pixel(b, 0, y),
                  (size_t)a->width * 3) == 0;
}

/* ---- the schedule and the coarse camera ---- */

static void assert_plan(int width, int height, int region, int samples,
                        int view, const view_pass *expected, int count)
{
    view_pass passes[VIEW_MAX_PASSES];
    int got = view_session_plan(width, height, region, samples, view,
                                passes);
    ck_assert_msg(got == count, "%dx%d region %d samples %d view %d: %d "
                  "passes, expected %d", width, height, region, samples,
                  view, got, count);
    for (int i = 0; i < count; i++) {
        ck_assert_int_eq(passes[i].scale, expected[i].scale);
        ck_assert_int_eq(passes[i].samples, expected[i].samples);
    }
}

START_TEST(the_plan_goes_coarse_to_fine_and_ends_with_the_render_asked)
{
    /* 1/8, 1/4, 1/2 with one sample, then the full resolution. */
    assert_plan(640, 480, 0, 1, 0,
                (view_pass[]){{8, 1}, {4, 1}, {2, 1}, {1, 1}}, 4);
    /* With samples: the full resolution with one, then with them. */
    assert_plan(640, 480, 0, 4, 0,
                (view_pass[]){{8, 1}, {4, 1}, {2, 1}, {1, 1}, {1, 4}}, 5);
    /* A view reads only the first sample: one full pass, as asked. */
    assert_plan(640, 480, 0, 4, RT_VIEW_NORMAL,
                (view_pass[]){{8, 1}, {4, 1}, {2, 1}, {1, 4}}, 4);
    /* A region: no coarse pass. */
    assert_plan(640, 480, 1, 1, 0, (view_pass[]){{1, 1}}, 1);
    assert_plan(640, 480, 1, 9, 0, (view_pass[]){{1, 1}, {1, 9}}, 2);
    /* Under 128 x 128 pixels: none either; at 128 x 128 all three. */
    assert_plan(127, 128, 0, 1, 0, (view_pass[]){{1, 1}}, 1);
    assert_plan(128, 128, 0, 1, 0,
                (view_pass[]){{8, 1}, {4, 1}, {2, 1}, {1, 1}}, 4);
    /* A coarse image under 8 pixels on a side is skipped: 48 / 8 = 6. */
    assert_plan(48, 1500, 0, 1, 0,
                (view_pass[]){{4, 1}, {2, 1}, {1, 1}}, 3);
    assert_plan(20, 2000, 0, 1, 0, (view_pass[]){{2, 1}, {1, 1}}, 2);
}
END_TEST

/* The screen point of pixel coordinates (x, y) of a w x h image seen by
 * `c` (docs/rendering-model.md, "The camera"), minus the observer. */
static rt_vec3 screen_direction(const rt_camera *c, double x, double y,
                                int w, int h)
{
    double u = 2.0 * x / w - 1.0, v = (1.0 - 2.0 * y / h) * h / w;
    rt_vec3 p = {c->screen_center.x + u * c->right.x + v * c->up.x,
                 c->screen_center.y + u * c->right.y + v * c->up.y,
                 c->screen_center.z + u * c->right.z + v * c->up.z};
    return (rt_vec3){p.x - c->observer.x, p.y - c->observer.y,
                     p.z - c->observer.z};
}

static rt_vec3 unit(rt_vec3 v)
{
    double n = sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    return (rt_vec3){v.x / n, v.y / n, v.z / n};
}

START_TEST(a_coarse_pixel_is_seen_through_the_centre_of_its_block)
{
    rt_scene *scene = rt_test_load_source_scene("scenes/cubes.scn");
    rt_camera camera = rt_test_scene_info(scene).camera;
    /* Sizes the scales divide and sizes they do not (cut blocks). */
    static const int sizes[][2] = {{400, 400}, {203, 77}, {640, 480},
                                   {99, 301}};
    for (size_t k = 0; k < sizeof sizes / sizeof *sizes; k++)
        for (int scale = 2; scale <= 8; scale *= 2) {
            int w = sizes[k][0], h = sizes[k][1], cw, ch;
            rt_camera coarse;
            view_pass_camera(&camera, w, h, scale, &coarse, &cw, &ch);
            ck_assert_int_eq(cw, (w + scale - 1) / scale);
            ck_assert_int_eq(ch, (h + scale - 1) / scale);
            ck_assert_int_eq(coarse.width, cw);
            ck_assert_int_eq(coarse.height, ch);
            const int probes[][2] = {{0, 0}, {cw - 1, 0}, {0, ch - 1},
                                     {cw - 1, ch - 1}, {cw / 2, ch / 3}};
            for (int p = 0; p < 5; p++) {
                int i = probes[p][0], j = probes[p][1];
                rt_ray ray = rt_camera_ray(&coarse, i, j);
                rt_vec3 expected = unit(screen_direction(
                    &camera, (i + 0.5) * scale, (j + 0.5) * scale, w, h));
                rt_vec3 actual = unit(ray.direction);
                ck_assert_double_eq_tol(actual.x, expected.x, 1e-12);
                ck_assert_double_eq_tol(actual.y, expected.y, 1e-12);
                ck_assert_double_eq_tol(actual.z, expected.z, 1e-12);
                ck_assert_double_eq_tol(ray.origin.x, camera.observer.x,
                                        1e-12);
            }
        }
    rt_scene_destroy(scene);
}
END_TEST

/* ---- passes shown in the window ---- */

/* Freezes the render at each notification until the test lets it go (as
 * test_viewer.c's gate); `open` lets every notification through. */
typedef struct gate {
    sem_t paused;
    sem_t resume;
    atomic_int open;
} gate;

static void gate_init(gate *g)
{
    ck_assert_int_eq(sem_init(&g->paused, 0, 0), 0);
    ck_assert_int_eq(sem_init(&g->resume, 0, 0), 0);
    atomic_init(&g->open, 0);
}

static void gate_destroy(gate *g)
{
    sem_destroy(&g->paused);
    sem_destroy(&g->resume);
}

static void gate_notify(void *user)
{
    gate *g = user;
    if (atomic_load(&g->open))
        return;
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

/* What pass `pass` shows: the library's render of its coarse image (or
 * the full one), each pixel enlarged to its block. */
static rt_image pass_image(const rt_scene *scene,
                           const rt_render_options *render, view_pass pass,
                           int width, int height)
{
    rt_render_options options = *render;
    options.samples = pass.samples;
    if (pass.scale == 1)
        return rt_test_render_with(scene, &options);
    rt_camera coarse;
    int cw, ch;
    rt_camera camera = rt_test_scene_info(scene).camera;
    view_pass_camera(&camera, width, height, pass.scale, &coarse, &cw, &ch);
    options.camera = &coarse;
    options.width = cw;
    options.height = ch;
    rt_image small = rt_test_render_with(scene, &options);
    rt_image large;
    ck_assert_int_eq(rt_image_init(&large, width, height, NULL), RT_OK);
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++)
            memcpy(rt_image_pixel(&large, x, y),
                   rt_image_pixel(&small, x / pass.scale, y / pass.scale), 3);
    rt_image_release(&small);
    return large;
}

/* Renders a 160 x 120 heavy scene with `samples` through a gated session
 * and a window; at each freeze every row of the window is what the pass
 * under way or the one before it left there (the checker before the
 * first), final rows are rt_render's; the passes come in order, each seen;
 * the last frame is rt_render's image. */
static void check_passes(int samples)
{
    const int width = 160, height = 120;
    rt_render_options render;
    rt_render_options_init(&render);
    render.threads = 2;
    render.samples = samples;
    rt_scene *reference = rt_test_view_heavy_scene(300, width, height);
    view_pass plan[VIEW_MAX_PASSES];
    int count = view_session_plan(width, height, 0, samples, 0, plan);
    ck_assert_int_eq(count, samples > 1 ? 5 : 4);
    rt_image expected[VIEW_MAX_PASSES];
    for (int p = 0; p < count; p++)
        expected[p] = pass_image(reference, &render, plan[p], width, height);
    /* The render asked, whatever the plan says. */
    rt_image asked = rt_test_render_with(reference, &render);
    rt_test_assert_same_image(&expected[count - 1], &asked,
                              "viewer-progressive-last-pass");

    gate g;
    gate_init(&g);
    view_window *window = rt_test_view_window_open(width, height);
    view_session *session = session_with(
        rt_test_view_heavy_scene(300, width, height), &render, gate_notify,
        &g);
    ck_assert(view_window_attach(window, session, NULL, 0));
    ck_assert_int_eq(view_session_start(session), RT_OK);
    int seen[VIEW_MAX_PASSES] = {0};
    int last_pass = 0;
    for (;;) {
        wait_paused(&g);
        view_progress progress;
        view_session_get_progress(session, &progress);
        ck_assert_int_eq(progress.pass_count, count);
        ck_assert_int_ge(progress.pass, last_pass);
        last_pass = progress.pass;
        view_window_sync(window);
        rt_image frame = rt_test_view_window_read(window);
        int p = progress.pass;
        for (int y = 0; y < height; y++) {
            if (view_session_row_done(session, y)) {
                ck_assert_msg(p == count - 1, "row %d final in pass %d", y,
                              p);
                ck_assert_msg(row_equals(&frame, &expected[count - 1], y),
                              "final row %d is not rt_render's", y);
                continue;
            }
            int now = row_equals(&frame, &expected[p], y);
            int before = p == 0 ? rt_test_view_row_is_placeholder(&frame, y)
                                : row_equals(&frame, &expected[p - 1], y);
            ck_assert_msg(now || before, "pass %d: row %d is neither its "
                          "own nor the pass before", p, y);
        }
        rt_image_release(&frame);
        if (progress.state == VIEW_RENDERING)
            seen[p] = 1;
        sem_post(&g.resume);
        if (progress.state != VIEW_RENDERING) {
            ck_assert_int_eq(progress.state, VIEW_DONE);
            ck_assert_int_eq(progress.rows_final, height);
            break;
        }
    }
    for (int p = 0; p < count; p++)
        ck_assert_msg(seen[p], "pass %d never seen", p);
    view_window_sync(window);
    rt_image final_frame = rt_test_view_window_read(window);
    rt_test_assert_same_image(&final_frame, &asked,
                              "viewer-progressive-final");
    rt_test_assert_same_image(view_session_image(session), &asked,
                              "viewer-progressive-image");
    rt_image_release(&final_frame);

    /* The report: every pass, in order, a frame shown, rays cast. */
    view_render_report report;
    view_session_last_report(session, &report);
    ck_assert_uint_eq(report.generation, 1);
    ck_assert_int_eq(report.state, VIEW_DONE);
    ck_assert_int_eq(report.passes_done, count);
    for (int p = 1; p < count; p++)
        ck_assert(report.pass_seconds[p] >= report.pass_seconds[p - 1]);
    ck_assert(report.shown_seconds >= 0);
    ck_assert(report.rays > (uint64_t)width * height * samples);

    view_window_attach(window, NULL, NULL, 0);
    view_session_destroy(session);
    rt_test_view_window_close(window);
    gate_destroy(&g);
    for (int p = 0; p < count; p++)
        rt_image_release(&expected[p]);
    rt_image_release(&asked);
    rt_scene_destroy(reference);
}

START_TEST(passes_come_coarse_to_fine_and_the_last_is_rt_render_bytes)
{
    check_passes(1);
}
END_TEST

START_TEST(with_4_samples_the_last_pass_is_rt_render_bytes_too)
{
    check_passes(4);
}
END_TEST

/* ---- restarts and cancellation ---- */

/* Options slow enough to catch a render between passes: brute force. */
static rt_render_options slow_options(int threads)
{
    rt_render_options render;
    rt_render_options_init(&render);
    render.threads = threads;
    render.accel = RT_ACCEL_NONE;
    return render;
}

/* Waits while `session` renders pass 0, then returns its progress (still
 * rendering, in a later pass). */
static view_progress wait_for_pass(view_session *session, int pass)
{
    view_progress progress;
    double deadline = rt_test_now() + RT_TEST_VIEW_WAIT_SECONDS;
    do {
        rt_test_sleep_ms(1);
        view_session_get_progress(session, &progress);
        ck_assert(rt_test_now() < deadline);
    } while (progress.state == VIEW_RENDERING && progress.pass < pass);
    ck_assert_msg(progress.state == VIEW_RENDERING,
                  "the render finished before pass %d could be caught", pass);
    return progress;
}

START_TEST(a_restart_mid_pass_cancels_it_and_the_next_runs_every_pass)
{
    int threads_before = rt_test_baseline_thread_count();
    rt_render_options render;
    rt_render_options_init(&render);
    render.threads = 2;
    rt_scene *reference = rt_test_view_heavy_scene(300, 160, 120);
    rt_image expected = rt_test_render_with(reference, &render);
    rt_scene_destroy(reference);
    /* The first render held at each notification until it is in its
     * second pass (1/4) or later; there its cancel flag is raised (as the
     * restart's cancel does first, before it joins: raised while the render
     * is held, it cannot finish a pass meanwhile), the render let go and
     * the session started again. */
    gate g;
    gate_init(&g);
    view_session *session = session_with(
        rt_test_view_heavy_scene(300, 160, 120), &render, gate_notify, &g);
    int *rows = malloc(sizeof *rows * 120);
    ck_assert_ptr_nonnull(rows);
    ck_assert_int_eq(view_session_start(session), RT_OK);
    view_progress caught;
    for (;;) {
        wait_paused(&g);
        view_session_get_progress(session, &caught);
        ck_assert_int_eq(caught.state, VIEW_RENDERING);
        view_session_take_finished_rows(session, rows, 120, NULL);
        if (caught.pass >= 1) {
            view_session_request_cancel(session);
            atomic_store(&g.open, 1);
        }
        sem_post(&g.resume);
        if (caught.pass >= 1)
            break;
    }
    free(rows);

    ck_assert_int_eq(view_session_start(session), RT_OK);
    view_render_report first;
    view_session_last_report(session, &first);
    ck_assert_uint_eq(first.generation, 1);
    ck_assert_int_eq(first.state, VIEW_CANCELLED);
    ck_assert_int_eq(first.status, RT_ERR_CANCELLED);
    ck_assert_int_eq(first.passes_done, caught.pass);
    /* (The cancel may come with the pass's last row: all its rows.) */
    ck_assert_int_le(first.rows_reached, first.rows_total);
    char line[512];
    view_render_report_describe(&first, line, sizeof line);
    ck_assert_msg(strncmp(line, "render 1 (picture): cancelled in ", 33) ==
                      0,
                  "%s", line);

    /* The new render: generation 2, from the coarsest pass. */
    view_progress progress;
    view_session_get_progress(session, &progress);
    ck_assert_uint_eq(progress.generation, 2);
    ck_assert_int_eq(rt_test_view_wait(session), VIEW_DONE);
    view_render_report second;
    view_session_last_report(session, &second);
    ck_assert_uint_eq(second.generation, 2);
    ck_assert_int_eq(second.state, VIEW_DONE);
    ck_assert_int_eq(second.passes_done, second.pass_count);
    ck_assert_int_eq(second.pass_count, 4);
    ck_assert(second.pass_seconds[0] > 0);
    rt_test_assert_same_image(view_session_image(session), &expected,
                              "viewer-progressive-restart");
    view_session_destroy(session);
    ck_assert_int_eq(rt_test_settled_thread_count(threads_before, 0.2),
                     threads_before);
    gate_destroy(&g);
    rt_image_release(&expected);
}
END_TEST

/* ---- debug views ---- */

/* cubes.scn's options at 160 x 120: four passes (19,200 pixels), quick
 * under valgrind. */
static rt_render_options cubes_options(void)
{
    rt_render_options render;
    rt_render_options_init(&render);
    render.threads = 2;
    render.width = 160;
    render.height = 120;
    return render;
}

/* Renders `view` of `light` through a 2-thread session of cubes.scn
 * (taking the rows as a window does) and compares with rt_render_view. */
static void check_view(int view, int light)
{
    rt_render_options render = cubes_options();
    rt_scene *scene = rt_test_load_source_scene("scenes/cubes.scn");
    rt_image expected;
    ck_assert_int_eq(rt_image_init(&expected, render.width, render.height,
                                   NULL),
                     RT_OK);
    rt_error error;
    ck_assert_msg(rt_render_view(scene, &render, (rt_debug_view)view, light,
                                 &expected, &error) == RT_OK,
                  "%s", error.message);
    view_session *session = session_with(scene, &render, NULL, NULL);
    ck_assert_int_eq(view_session_set_view(session, view, light), RT_OK);
    ck_assert_int_eq(view_session_start(session), RT_OK);
    int height = render.height;
    int *rows = malloc(sizeof *rows * (size_t)height);
    char *seen = calloc((size_t)height, 1);
    ck_assert(rows != NULL && seen != NULL);
    view_progress progress;
    double deadline = rt_test_now() + RT_TEST_VIEW_WAIT_SECONDS;
    do {
        view_session_get_progress(session, &progress);
        int n = view_session_take_finished_rows(session, rows, height,
                                                NULL);
        for (int k = 0; k < n; k++)
            seen[rows[k]] = 1;
        ck_assert(rt_test_now() < deadline);
    } while (progress.state == VIEW_RENDERING);
    ck_assert_int_eq(progress.state, VIEW_DONE);
    ck_assert_int_eq(progress.view, view);
    ck_assert_int_eq(progress.rows_final, height);
    int n = view_session_take_finished_rows(session, rows, height, NULL);
    for (int k = 0; k < n; k++)
        seen[rows[k]] = 1;
    for (int y = 0; y < height; y++)
        ck_assert_msg(seen[y], "row %d was never reported", y);
    char name[64];
    snprintf(name, sizeof name, "viewer-progressive-view-%d", view);
    rt_test_assert_same_image(view_session_image(session), &expected, name);
    view_render_report report;
    view_session_last_report(session, &report);
    ck_assert_int_eq(report.passes_done, 4);
    ck_assert_int_eq(report.view, view);
    ck_assert(report.rays >= (uint64_t)render.width * height);
    free(rows);
    free(seen);
    view_session_destroy(session);
    rt_image_release(&expected);
}

START_TEST(a_view_session_renders_rt_render_view_bytes_on_two_threads)
{
    check_view(RT_VIEW_NORMAL, 0);
    check_view(RT_VIEW_SHADOW, 0);
    check_view(RT_VIEW_FACET, 0);
    /* The depth view reports its rows at the end, all at once. */
    check_view(RT_VIEW_DEPTH, 0);
}
END_TEST

START_TEST(a_view_session_cancels_and_refuses_what_the_scene_lacks)
{
    int threads_before = rt_test_baseline_thread_count();
    rt_render_options render = slow_options(2);
    view_session *session = session_with(
        rt_test_view_heavy_scene(1000, 256, 192), &render, NULL, NULL);
    ck_assert_int_eq(view_session_set_view(session, -1, 0), RT_ERR_ARGUMENT);
    ck_assert_int_eq(view_session_set_view(session, RT_VIEW_SHADING_NORMAL + 1,
                                           0),
                     RT_ERR_ARGUMENT);
    ck_assert_int_eq(view_session_set_view(session, RT_VIEW_SHADOW, 1),
                     RT_ERR_ARGUMENT);      /* one light: 0 */
    ck_assert_int_eq(view_session_set_view(session, RT_VIEW_NS, -1),
                     RT_ERR_ARGUMENT);
    ck_assert_int_eq(view_session_set_view(session, RT_VIEW_NORMAL, 0),
                     RT_OK);
    ck_assert_int_eq(view_session_start(session), RT_OK);
    wait_for_pass(session, 2);
    ck_assert_int_gt(rt_test_thread_count(), threads_before);
    double started = rt_test_now();
    view_session_cancel(session);
    if (getenv("RT_TEST_VERBOSE"))
        fprintf(stderr, "view cancel: %.4f s\n", rt_test_now() - started);
    ck_assert_int_eq(rt_test_settled_thread_count(threads_before, 0.2),
                     threads_before);
    view_progress progress;
    view_session_get_progress(session, &progress);
    ck_assert_int_eq(progress.state, VIEW_CANCELLED);
    ck_assert_int_eq(progress.view, RT_VIEW_NORMAL);
    ck_assert_int_lt(progress.rows_final, progress.rows_total);
    char text[96];
    view_progress_describe(&progress, text, sizeof text);
    ck_assert_msg(strstr(text, "cancelled at ") == text &&
                      strstr(text, " of ") != NULL,
                  "%s", text);
    view_session_destroy(session);
}
END_TEST

/* ---- cameras and the picture kept ---- */

START_TEST(a_camera_set_on_the_session_renders_what_options_camera_gives)
{
    rt_scene *scene = rt_test_load_source_scene("scenes/cubes.scn");
    rt_look look = {{12, -3, 9}, {0, 0, 1}, {0, 0, 1}, 50};
    rt_camera camera;
    rt_error error;
    ck_assert_msg(rt_scene_look(scene, &look, &camera, NULL, &error) == RT_OK,
                  "%s", error.message);
    rt_render_options render = cubes_options();
    rt_render_options moved = render;
    moved.camera = &camera;
    rt_image expected = rt_test_render_with(scene, &moved);
    rt_image scene_view = rt_test_render_with(scene, &render);
    rt_image normals;
    ck_assert_int_eq(rt_image_init(&normals, render.width, render.height,
                                   NULL),
                     RT_OK);
    ck_assert_int_eq(rt_render_view(scene, &moved, RT_VIEW_NORMAL, 0,
                                    &normals, NULL),
                     RT_OK);
    ck_assert_int_ne(rt_test_image_diff(&expected, &scene_view, NULL), 0);

    view_session *session = session_with(scene, &render, NULL, NULL);
    ck_assert_int_eq(view_session_set_camera(session, &camera), RT_OK);
    ck_assert_int_eq(view_session_start(session), RT_OK);
    ck_assert_int_eq(rt_test_view_wait(session), VIEW_DONE);
    rt_test_assert_same_image(view_session_image(session), &expected,
                              "viewer-progressive-camera");
    /* A view with it. */
    ck_assert_int_eq(view_session_set_view(session, RT_VIEW_NORMAL, 0),
                     RT_OK);
    ck_assert_int_eq(view_session_start(session), RT_OK);
    ck_assert_int_eq(rt_test_view_wait(session), VIEW_DONE);
    rt_test_assert_same_image(view_session_image(session), &normals,
                              "viewer-progressive-camera-normals");
    /* NULL: the scene's camera again. */
    ck_assert_int_eq(view_session_set_view(session, 0, 0), RT_OK);
    ck_assert_int_eq(view_session_set_camera(session, NULL), RT_OK);
    ck_assert_int_eq(view_session_start(session), RT_OK);
    ck_assert_int_eq(rt_test_view_wait(session), VIEW_DONE);
    rt_test_assert_same_image(view_session_image(session), &scene_view,
                              "viewer-progressive-scene-camera");
    view_session_destroy(session);
    rt_image_release(&expected);
    rt_image_release(&scene_view);
    rt_image_release(&normals);
}
END_TEST

START_TEST(the_finished_picture_comes_back_at_once_after_a_view)
{
    rt_render_options render = cubes_options();
    rt_scene *scene = rt_test_load_source_scene("scenes/cubes.scn");
    rt_image picture = rt_test_render_with(scene, &render);
    render.max_depth = 1;
    rt_image shallow = rt_test_render_with(scene, &render);
    render.max_depth = RT_DEFAULT_DEPTH;
    view_window *window = rt_test_view_window_open(picture.width,
                                                   picture.height);
    view_session *session = session_with(scene, &render, NULL, NULL);
    ck_assert(view_window_attach(window, session, NULL, 0));
    ck_assert_int_eq(view_session_start(session), RT_OK);
    ck_assert_int_eq(rt_test_view_wait(session), VIEW_DONE);
    ck_assert_int_eq(view_session_set_view(session, RT_VIEW_FACET, 0), RT_OK);
    ck_assert_int_eq(view_session_start(session), RT_OK);
    ck_assert_int_eq(rt_test_view_wait(session), VIEW_DONE);
    view_window_sync(window);
    ck_assert_int_ne(rt_test_image_diff(view_session_image(session), &picture,
                                        NULL),
                     0);

    /* Back to the picture: done when start returns, nothing rendered. */
    ck_assert_int_eq(view_session_set_view(session, 0, 0), RT_OK);
    ck_assert_int_eq(view_session_start(session), RT_OK);
    view_progress progress;
    view_session_get_progress(session, &progress);
    ck_assert_int_eq(progress.state, VIEW_DONE);
    ck_assert_uint_eq(progress.generation, 3);
    ck_assert_int_eq(progress.rows_final, picture.height);
    view_render_report report;
    view_session_last_report(session, &report);
    ck_assert_int_eq(report.kept, 1);
    ck_assert_uint_eq(report.generation, 3);
    ck_assert(report.rays == 0);
    rt_test_assert_same_image(view_session_image(session), &picture,
                              "viewer-progressive-kept");
    ck_assert(view_window_sync(window));
    rt_image frame = rt_test_view_window_read(window);
    rt_test_assert_same_image(&frame, &picture, "viewer-progressive-kept-frame");
    rt_image_release(&frame);

    /* Another depth: rendered again. */
    ck_assert_int_eq(view_session_set_depth(session, 1), RT_OK);
    ck_assert_int_eq(view_session_start(session), RT_OK);
    ck_assert_int_eq(rt_test_view_wait(session), VIEW_DONE);
    view_session_last_report(session, &report);
    ck_assert_int_eq(report.kept, 0);
    ck_assert_int_eq(report.passes_done, 4);
    rt_test_assert_same_image(view_session_image(session), &shallow,
                              "viewer-progressive-depth-1");
    view_window_attach(window, NULL, NULL, 0);
    view_session_destroy(session);
    rt_test_view_window_close(window);
    rt_image_release(&picture);
    rt_image_release(&shallow);
}
END_TEST

START_TEST(a_region_has_no_coarse_pass_and_renders_its_bytes)
{
    for (int samples = 1; samples <= 4; samples += 3) {
        rt_render_options render = cubes_options();
        render.width = 400;
        render.height = 300;
        render.samples = samples;
        render.region = (rt_region){30, 40, 230, 190};   /* 200 x 150 */
        rt_scene *scene = rt_test_load_source_scene("scenes/cubes.scn");
        rt_image expected = rt_test_render_with(scene, &render);
        view_session *session = session_with(scene, &render, NULL, NULL);
        ck_assert_int_eq(view_session_image(session)->width, 200);
        ck_assert_int_eq(view_session_image(session)->height, 150);
        ck_assert_int_eq(view_session_start(session), RT_OK);
        ck_assert_int_eq(rt_test_view_wait(session), VIEW_DONE);
        rt_test_assert_same_image(view_session_image(session), &expected,
                                  "viewer-progressive-region");
        view_render_report report;
        view_session_last_report(session, &report);
        ck_assert_int_eq(report.pass_count, samples > 1 ? 2 : 1);
        ck_assert_int_eq(report.passes[0].scale, 1);
        ck_assert_int_eq(report.passes[report.pass_count - 1].samples,
                         samples);
        view_session_destroy(session);
        rt_image_release(&expected);
    }
}
END_TEST

/* ---- words ---- */

START_TEST(progress_and_reports_name_the_pass)
{
    view_progress p;
    memset(&p, 0, sizeof p);
    p.state = VIEW_RENDERING;
    p.rows_done = 42;
    p.rows_total = 100;
    p.seconds = 0.125;
    p.pass = 1;
    p.pass_count = 5;
    view_pass passes[] = {{8, 1}, {4, 1}, {2, 1}, {1, 1}, {1, 16}};
    memcpy(p.passes, passes, sizeof passes);
    char text[160];
    view_progress_describe(&p, text, sizeof text);
    ck_assert_str_eq(text, "1/4: 42% - 0.1 s");
    p.pass = 4;
    view_progress_describe(&p, text, sizeof text);
    ck_assert_str_eq(text, "16 samples: 42% - 0.1 s");
    p.pass = 3;
    p.state = VIEW_CANCELLED;
    view_progress_describe(&p, text, sizeof text);
    ck_assert_str_eq(text, "cancelled at 42% of full after 0.1 s");

    view_render_report r;
    memset(&r, 0, sizeof r);
    r.generation = 3;
    r.state = VIEW_DONE;
    r.pass_count = 4;
    memcpy(r.passes, passes, sizeof r.passes);
    r.passes_done = 4;
    r.pass_seconds[0] = 0.006;
    r.pass_seconds[1] = 0.018;
    r.pass_seconds[2] = 0.061;
    r.pass_seconds[3] = 0.84;
    r.shown_seconds = 0.009;
    r.rays = 1230000;
    r.rows_total = 480;
    view_render_report_describe(&r, text, sizeof text);
    ck_assert_str_eq(text, "render 3 (picture): 1/8 in 6.0 ms, 1/4 in 18 ms, "
                           "1/2 in 61 ms, full in 840 ms; first shown at "
                           "9.0 ms; 1.23 M rays");
    r.generation = 4;
    r.view = RT_VIEW_SHADOW;
    r.light = 1;
    r.state = VIEW_CANCELLED;
    r.passes_done = 1;
    r.rows_reached = 41;
    r.seconds = 1.5;
    r.shown_seconds = -1;
    view_render_report_describe(&r, text, sizeof text);
    ck_assert_str_eq(text, "render 4 (shadow view of light 1): cancelled in "
                           "1/4 (41 of 480 rows) after 1.50 s; 1/8 in 6.0 "
                           "ms; 1.23 M rays");
    r.rays = 99999;
    r.passes_done = 0;
    r.rows_reached = 0;
    r.state = VIEW_FAILED;
    snprintf(r.error, sizeof r.error, "the camera is degenerate");
    view_render_report_describe(&r, text, sizeof text);
    ck_assert_str_eq(text, "render 4 (shadow view of light 1): failed in "
                           "1/8 (0 of 480 rows) after 1.50 s: the camera is "
                           "degenerate; 99999 rays");
    r.kept = 1;
    r.view = 0;
    view_render_report_describe(&r, text, sizeof text);
    ck_assert_str_eq(text, "render 4 (picture): the picture finished before, "
                           "shown again at once");
}
END_TEST

static Suite *viewer_progressive_suite(void)
{
    Suite *suite = suite_create("viewer_progressive");
    TCase *plan = tcase_create("plan");
    tcase_add_test(plan,
                   the_plan_goes_coarse_to_fine_and_ends_with_the_render_asked);
    tcase_add_test(plan, a_coarse_pixel_is_seen_through_the_centre_of_its_block);
    tcase_add_test(plan, progress_and_reports_name_the_pass);
    suite_add_tcase(suite, plan);

    TCase *passes = tcase_create("passes");
    tcase_set_timeout(passes, 240);
    tcase_add_test(passes,
                   passes_come_coarse_to_fine_and_the_last_is_rt_render_bytes);
    tcase_add_test(passes, with_4_samples_the_last_pass_is_rt_render_bytes_too);
    tcase_add_test(passes,
                   a_restart_mid_pass_cancels_it_and_the_next_runs_every_pass);
    tcase_add_test(passes,
                   a_view_session_renders_rt_render_view_bytes_on_two_threads);
    tcase_add_test(passes,
                   a_view_session_cancels_and_refuses_what_the_scene_lacks);
    tcase_add_test(passes,
                   a_camera_set_on_the_session_renders_what_options_camera_gives);
    tcase_add_test(passes, the_finished_picture_comes_back_at_once_after_a_view);
    tcase_add_test(passes, a_region_has_no_coarse_pass_and_renders_its_bytes);
    suite_add_tcase(suite, passes);
    return suite;
}

RT_CHECK_MAIN(viewer_progressive_suite)
