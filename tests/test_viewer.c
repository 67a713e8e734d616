/*
 * test_viewer.c - the viewer's logic without its event loop: a view_session
 * rendering on its own thread, shown by a view_window on SDL's dummy video
 * driver with the software renderer (no display needed), and read back
 * pixel by pixel.  Dummy rather than offscreen: offscreen initialises EGL,
 * whose allocations LeakSanitizer reports as leaks.
 *
 * What is checked: the finished window shows exactly rt-export's image; a
 * frame taken while rendering shows finished rows exactly and the
 * placeholder everywhere else; cancelling stops the render well under a
 * second and leaves no thread; restarting starts from the placeholder; and
 * the small pure helpers (window fitting, save path, rescaling, errors).
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
#include "view_app.h"
#include "view_scene.h"
#include "view_session.h"
#include "view_window.h"

/* Half the side of the square marking a hit (view_window.c's MARK_SIZE). */
#define MARK_HALF 3

/* Longest a test waits for a render before failing. */
#define WAIT_SECONDS 60.0

static rt_scene *load_scene(const char *relative)
{
    rt_scene *scene = NULL;
    rt_error error;
    rt_status status = rt_scene_load(rt_test_source_path(relative), &scene,
                                     &error);
    ck_assert_msg(status == RT_OK, "%s", error.message);
    return scene;
}

/*
 * A scene slow to render: `count` small reflective triangles scattered in
 * front of a large floor (brute force tests every facet for every ray).
 * Same camera as scenes/two-facets.scn.
 */
static rt_scene *heavy_scene(int count, int width, int height)
{
    rt_vec3 *vertices = malloc(sizeof *vertices * (size_t)(3 * count + 3));
    rt_facet_desc *facets = malloc(sizeof *facets * (size_t)(count + 1));
    ck_assert(vertices != NULL && facets != NULL);
    rt_test_rng rng = {12345};
    for (int i = 0; i < count; i++) {
        double p[3];
        for (int c = 0; c < 3; c++)
            p[c] = rt_test_rng_uniform(&rng);
        rt_vec3 centre = {-8 + 16 * p[0], -6 + 12 * p[1], 0.5 + 1.5 * p[2]};
        vertices[3 * i] = (rt_vec3){centre.x - 0.2, centre.y - 0.1, centre.z};
        vertices[3 * i + 1] = (rt_vec3){centre.x + 0.2, centre.y - 0.1,
                                        centre.z + 0.1};
        vertices[3 * i + 2] = (rt_vec3){centre.x, centre.y + 0.2, centre.z};
        facets[i] = (rt_facet_desc){{3 * i, 3 * i + 1, 3 * i + 2},
                                    0.3,
                                    {(unsigned char)(i * 37),
                                     (unsigned char)(i * 91), 200}};
    }
    vertices[3 * count] = (rt_vec3){-30, -30, 0};
    vertices[3 * count + 1] = (rt_vec3){30, -30, 0};
    vertices[3 * count + 2] = (rt_vec3){0, 40, 0};
    facets[count] = (rt_facet_desc){{3 * count, 3 * count + 1, 3 * count + 2},
                                    0.5,
                                    {180, 180, 180}};
    rt_scene_desc desc = {
        .observer = {0, 0, 10},
        .screen_center = {0, 0, 5},
        .screen_right = {4, 0, 5},
        .width = width,
        .height = height,
        .vertices = vertices,
        .vertex_count = 3 * count + 3,
        .facets = facets,
        .facet_count = count + 1,
        .background = {30, 30, 60},
        .light_position = {-3, 2, 20},
        .light_color = {255, 255, 255},
    };
    rt_scene *scene = NULL;
    rt_error error;
    rt_status status = rt_scene_create(&desc, &scene, &error);
    free(vertices);
    free(facets);
    ck_assert_msg(status == RT_OK, "%s", error.message);
    return scene;
}

static view_session *new_session(rt_scene *scene, int threads,
                                 view_notify_func notify, void *user)
{
    view_session_options options;
    view_session_options_init(&options);
    options.render.threads = threads;
    options.notify = notify;
    options.notify_user = user;
    view_session *session = NULL;
    ck_assert_int_eq(view_session_create(scene, &options, &session, NULL),
                     RT_OK);
    return session;
}

static view_state wait_until_finished(view_session *session)
{
    view_progress progress;
    double deadline = rt_test_now() + WAIT_SECONDS;
    for (;;) {
        view_session_get_progress(session, &progress);
        if (progress.state != VIEW_RENDERING)
            return progress.state;
        ck_assert_msg(rt_test_now() < deadline, "render did not finish");
        rt_test_sleep_ms(2);
    }
}

static view_window *open_window(int width, int height)
{
    /* Headless unless told otherwise (tests/viewer.cmake sets it too). */
    setenv("SDL_VIDEODRIVER", "dummy", 0);
    ck_assert_msg(SDL_Init(SDL_INIT_VIDEO) == 0, "SDL_Init: %s",
                  SDL_GetError());
    char error[256];
    view_window *window = view_window_create(
        "test", width, height, VIEW_WINDOW_SOFTWARE | VIEW_WINDOW_HIDDEN,
        error, sizeof error);
    ck_assert_msg(window != NULL, "%s", error);
    return window;
}

static void close_window(view_window *window)
{
    view_window_destroy(window);
    SDL_Quit();
}

static rt_image read_window(view_window *window)
{
    rt_image frame;
    ck_assert_msg(view_window_read(window, &frame), "read back: %s",
                  SDL_GetError());
    return frame;
}

static int row_is_placeholder(const rt_image *frame, int y)
{
    for (int x = 0; x < frame->width; x++) {
        unsigned char expected[3];
        view_placeholder_color(x, y, expected);
        if (memcmp(rt_image_pixel(frame, x, y), expected, 3) != 0)
            return 0;
    }
    return 1;
}

static int row_equals(const rt_image *a, const rt_image *b, int y)
{
    return memcmp(rt_image_pixel(a, 0, y), rt_image_pixel(b, 0, y),
                  (size_t)a->width * 3) == 0;
}

/* Fails the test, after writing both images, when they differ. */
static void assert_same_image(const rt_image *actual, const rt_image *expected,
                              const char *name)
{
    int max_diff;
    long differ = rt_test_image_diff(actual, expected, &max_diff);
    if (differ != 0) {
        char path[256];
        snprintf(path, sizeof path, "viewer-%s-actual.ppm", name);
        rt_ppm_save(path, actual, RT_PPM_P6, NULL);
        snprintf(path, sizeof path, "viewer-%s-expected.ppm", name);
        rt_ppm_save(path, expected, RT_PPM_P6, NULL);
    }
    ck_assert_msg(differ == 0,
                  "%s: %ld pixels differ (by up to %d), images written to "
                  "viewer-%s-*.ppm",
                  name, differ, max_diff, name);
}

/* Renders `scene` through a session and a window of its size; returns what
 * the window shows at the end. */
static rt_image show_until_done(rt_scene *scene, int threads)
{
    rt_scene_info info;
    rt_scene_get_info(scene, &info);
    view_window *window = open_window(info.width, info.height);
    view_session *session = new_session(scene, threads, NULL, NULL);
    ck_assert(view_window_attach(window, session, NULL, 0));
    ck_assert_int_eq(view_session_start(session), RT_OK);
    double deadline = rt_test_now() + WAIT_SECONDS;
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
    rt_image frame = read_window(window);
    view_window_attach(window, NULL, NULL, 0);
    view_session_destroy(session);
    close_window(window);
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

    rt_image frame = show_until_done(load_scene("scenes/cubes.scn"), 0);
    ck_assert_int_eq(frame.width, exported.width);
    ck_assert_int_eq(frame.height, exported.height);
    assert_same_image(&frame, &exported, "cubes");
    rt_image_release(&frame);
    rt_image_release(&exported);
}
END_TEST

START_TEST(finished_window_equals_library_render_for_each_scene)
{
    static const char *const scenes[] = {
        "scenes/two-facets.scn", "scenes/one-facet.scn", "scenes/empty.scn"};
    for (size_t i = 0; i < sizeof scenes / sizeof scenes[0]; i++) {
        rt_scene *reference_scene = load_scene(scenes[i]);
        rt_image expected = rt_test_render(reference_scene, RT_DEFAULT_DEPTH, 1);
        rt_scene_destroy(reference_scene);
        rt_image frame = show_until_done(load_scene(scenes[i]), (int)i % 3);
        assert_same_image(&frame, &expected, "scene");
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
    deadline.tv_sec += (time_t)WAIT_SECONDS;
    int result;
    do
        result = sem_timedwait(&g->paused, &deadline);
    while (result != 0 && errno == EINTR);
    ck_assert_msg(result == 0, "the render never notified");
}

START_TEST(intermediate_frames_show_only_finished_rows)
{
    rt_scene *reference_scene = heavy_scene(300, 96, 72);
    rt_image expected = rt_test_render(reference_scene, RT_DEFAULT_DEPTH, 1);
    rt_scene_destroy(reference_scene);

    gate g;
    ck_assert_int_eq(sem_init(&g.paused, 0, 0), 0);
    ck_assert_int_eq(sem_init(&g.resume, 0, 0), 0);
    view_window *window = open_window(expected.width, expected.height);
    view_session *session = new_session(heavy_scene(300, 96, 72), 2,
                                        gate_notify, &g);
    ck_assert(view_window_attach(window, session, NULL, 0));

    rt_image first = read_window(window);
    for (int y = 0; y < first.height; y++)
        ck_assert_msg(row_is_placeholder(&first, y),
                      "row %d is not the placeholder before the render", y);
    rt_image_release(&first);

    ck_assert_int_eq(view_session_start(session), RT_OK);
    int partial_frames = 0;
    for (;;) {
        wait_paused(&g);
        view_window_sync(window);
        rt_image frame = read_window(window);
        int finished = 0;
        for (int y = 0; y < frame.height; y++) {
            if (view_session_row_done(session, y)) {
                finished++;
                ck_assert_msg(row_equals(&frame, &expected, y),
                              "finished row %d is not the rendered row", y);
            } else {
                ck_assert_msg(row_is_placeholder(&frame, y),
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
    rt_image final_frame = read_window(window);
    assert_same_image(&final_frame, &expected, "gated");

    rt_image_release(&final_frame);
    view_window_attach(window, NULL, NULL, 0);
    view_session_destroy(session);
    close_window(window);
    sem_destroy(&g.paused);
    sem_destroy(&g.resume);
    rt_image_release(&expected);
}
END_TEST

START_TEST(cancel_stops_the_render_promptly_and_leaves_no_thread)
{
    int threads_before = rt_test_baseline_thread_count();
    view_session *session = new_session(heavy_scene(2000, 48, 1500), 0,
                                        NULL, NULL);
    ck_assert_int_eq(view_session_start(session), RT_OK);

    view_progress progress;
    double deadline = rt_test_now() + WAIT_SECONDS;
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
    ck_assert_int_eq(rt_test_settled_thread_count(threads_before, 0.2), threads_before);

    view_session_get_progress(session, &progress);
    ck_assert_int_eq(progress.state, VIEW_CANCELLED);
    ck_assert_int_eq(progress.status, RT_ERR_CANCELLED);
    ck_assert_int_lt(progress.rows_done, progress.rows_total);
    char text[96];
    view_progress_describe(&progress, text, sizeof text);
    ck_assert_msg(strncmp(text, "cancelled at ", 13) == 0, "%s", text);

    /* Rows it reports finished stay; nothing else is marked. */
    int marked = 0;
    for (int y = 0; y < progress.rows_total; y++)
        marked += view_session_row_done(session, y);
    ck_assert_int_eq(marked, progress.rows_done);

    view_session_destroy(session);
    ck_assert_int_eq(rt_test_settled_thread_count(threads_before, 0.2), threads_before);
}
END_TEST

START_TEST(destroying_a_rendering_session_joins_its_thread)
{
    int threads_before = rt_test_baseline_thread_count();
    for (int i = 0; i < 5; i++) {
        view_session *session = new_session(heavy_scene(1500, 64, 400),
                                            i % 3, NULL, NULL);
        ck_assert_int_eq(view_session_start(session), RT_OK);
        rt_test_sleep_ms(i * 7);
        double started = rt_test_now();
        view_session_destroy(session);
        double took = rt_test_now() - started;
        ck_assert_msg(took < 0.5, "destroying took %.3f s", took);
        ck_assert_int_eq(rt_test_settled_thread_count(threads_before, 0.2), threads_before);
    }
}
END_TEST

START_TEST(restart_goes_back_to_the_placeholder_and_renders_again)
{
    rt_scene *reference_scene = heavy_scene(400, 80, 60);
    rt_image expected = rt_test_render(reference_scene, 2, 1);
    rt_scene_destroy(reference_scene);

    view_window *window = open_window(80, 60);
    view_session *session = new_session(heavy_scene(400, 80, 60), 0, NULL,
                                        NULL);
    ck_assert(view_window_attach(window, session, NULL, 0));
    ck_assert_int_eq(view_session_start(session), RT_OK);
    wait_until_finished(session);
    view_window_sync(window);

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

    /* The frame after a restart shows only the new render's rows. */
    view_window_sync(window);
    rt_image frame = read_window(window);
    for (int y = 0; y < frame.height; y++) {
        if (view_session_row_done(session, y))
            ck_assert(row_equals(&frame, &expected, y));
        else
            ck_assert_msg(row_is_placeholder(&frame, y),
                          "row %d kept the old render", y);
    }
    rt_image_release(&frame);

    ck_assert_int_eq(view_session_start(session), RT_OK);
    ck_assert_int_eq(wait_until_finished(session), VIEW_DONE);
    view_window_sync(window);
    frame = read_window(window);
    assert_same_image(&frame, &expected, "restart");
    rt_image_release(&frame);

    view_window_attach(window, NULL, NULL, 0);
    view_session_destroy(session);
    close_window(window);
    rt_image_release(&expected);
}
END_TEST

START_TEST(taking_rows_returns_each_finished_row_once_in_order)
{
    view_session *session = new_session(heavy_scene(50, 32, 300), 0, NULL,
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
    char path[64];
    ck_assert(view_scene_image_path("scenes/cubes.scn", ".ppm", path,
                                    sizeof path));
    ck_assert_str_eq(path, "scenes/cubes.ppm");
    ck_assert(view_scene_image_path("scenes/cubes.scn", ".png", path,
                                    sizeof path));
    ck_assert_str_eq(path, "scenes/cubes.png");
    ck_assert(view_scene_image_path("/a.b/scene", ".ppm", path, sizeof path));
    ck_assert_str_eq(path, "/a.b/scene.ppm");
    ck_assert(view_scene_image_path("x.txt", ".ppm", path, sizeof path));
    ck_assert_str_eq(path, "x.txt.ppm");
    ck_assert(view_scene_image_path("dir/.scn", ".ppm", path, sizeof path));
    ck_assert_str_eq(path, "dir/.scn.ppm");
    ck_assert(!view_scene_image_path("a-rather-long-name.scn", ".ppm", path,
                                     8));
}
END_TEST

START_TEST(size_renders_the_library_image_of_that_size_without_a_copy)
{
    /* --scale 2 of two-facets (64 x 48) asks for 128 x 96. */
    ck_assert_int_eq(view_scale_side(64, 2.0), 128);
    ck_assert_int_eq(view_scale_side(48, 0.01), 1);
    ck_assert_int_eq(view_scale_side(400, 64.0), RT_MAX_IMAGE_SIDE + 1);

    rt_scene *scene = load_scene("scenes/two-facets.scn");
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
    ck_assert_int_eq(wait_until_finished(session), VIEW_DONE);
    assert_same_image(image, &expected, "size");
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
    ck_assert_int_eq(view_session_create(load_scene("scenes/cubes.scn"),
                                         &options, &session, &error),
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

/* two-facets.scn with the background `background` ("30, 30, 60"). */
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

/* An rt-view on the dummy driver, saving binary PPM; `samples` rays a
 * pixel on one thread. */
static view_app *open_app_with(const char *output, int watch, int samples)
{
    setenv("SDL_VIDEODRIVER", "dummy", 0);
    ck_assert_msg(SDL_Init(SDL_INIT_VIDEO) == 0, "SDL_Init: %s",
                  SDL_GetError());
    view_app_options options;
    view_app_options_init(&options);
    options.format = RT_IMAGE_P6;
    options.output = output;
    options.watch = watch;
    options.window_flags = VIEW_WINDOW_SOFTWARE;
    if (samples > 1) {
        options.render.samples = samples;
        options.render.threads = 1;
    }
    char error[256];
    view_app *app = view_app_create(&options, error, sizeof error);
    ck_assert_msg(app != NULL, "%s", error);
    return app;
}

/* view_app_open, then what the event loop does when the load ends: 1 when
 * the scene loaded. */
static int open_and_wait(view_app *app, const char *path)
{
    return view_app_open(app, path) && view_app_wait_load(app);
}

static view_app *open_app(const char *output, int watch)
{
    return open_app_with(output, watch, 1);
}

static void close_app(view_app *app)
{
    view_app_destroy(app);
    SDL_Quit();
}

/* The finished image of the app's session. */
static const rt_image *finished_image(view_app *app)
{
    view_session *session = view_app_session(app);
    ck_assert_ptr_nonnull(session);
    ck_assert_int_eq(wait_until_finished(session), VIEW_DONE);
    return view_session_image(session);
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
    ck_assert(shows_background(finished_image(app), r, g, b));
    ck_assert_str_eq(view_app_message(app), "");
}

START_TEST(reload_reads_the_edited_file)
{
    rt_test_write_two_facet_scene("viewer-reload.scn", "30, 30, 60");
    view_app *app = open_app(NULL, 0);
    ck_assert(open_and_wait(app, "viewer-reload.scn"));
    ck_assert(shows_background(finished_image(app), 30, 30, 60));
    edit_and_reload(app, "viewer-reload.scn", 200, 10, 10);
    close_app(app);
    remove("viewer-reload.scn");
}
END_TEST

START_TEST(failing_reload_keeps_the_picture_and_reports_the_error)
{
    rt_test_write_two_facet_scene("viewer-broken.scn", "30, 30, 60");
    view_app *app = open_app(NULL, 0);
    ck_assert(open_and_wait(app, "viewer-broken.scn"));
    const rt_image *before = finished_image(app);
    view_session *session = view_app_session(app);
    rt_test_write_two_facet_scene("viewer-broken.scn", "30, 30");
    ck_assert(view_app_reload(app));
    ck_assert(!view_app_wait_load(app));
    ck_assert_ptr_eq(view_app_session(app), session);
    ck_assert_ptr_eq(finished_image(app), before);
    ck_assert(shows_background(before, 30, 30, 60));
    /* FILE:LINE:COLUMN: the background is line 13. */
    ck_assert_msg(strncmp(view_app_message(app), "viewer-broken.scn:13:",
                          21) == 0,
                  "%s", view_app_message(app));
    /* Fixed, it loads again and the error goes. */
    edit_and_reload(app, "viewer-broken.scn", 10, 200, 10);
    ck_assert_int_eq(view_app_exit_status(app), 0);
    close_app(app);
    remove("viewer-broken.scn");
}
END_TEST

START_TEST(watch_reloads_when_the_file_changes_and_only_then)
{
    rt_test_write_two_facet_scene("viewer-watch.scn", "30, 30, 60");
    view_app *app = open_app(NULL, 1);
    ck_assert(open_and_wait(app, "viewer-watch.scn"));
    ck_assert(shows_background(finished_image(app), 30, 30, 60));
    ck_assert(!view_app_check_watch(app));
    rt_test_write_two_facet_scene("viewer-watch.scn", "60, 30, 30");
    touch_later("viewer-watch.scn", 2);
    ck_assert(view_app_check_watch(app));
    ck_assert(view_app_wait_load(app));
    ck_assert(shows_background(finished_image(app), 60, 30, 30));
    ck_assert(!view_app_check_watch(app));
    /* Removed (an editor between delete and rename): nothing happens, and
     * the new file is read when it appears. */
    remove("viewer-watch.scn");
    ck_assert(!view_app_check_watch(app));
    ck_assert_str_eq(view_app_message(app), "");
    rt_test_write_two_facet_scene("viewer-watch.scn", "30, 60, 30");
    ck_assert(view_app_check_watch(app));
    ck_assert(view_app_wait_load(app));
    ck_assert(shows_background(finished_image(app), 30, 60, 30));
    close_app(app);
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
    view_app *app = open_app(NULL, 0);
    ck_assert(open_and_wait(app, "viewer-save.scn"));
    finished_image(app);
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
    close_app(app);
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
    view_app *app = open_app("viewer-out.ppm", 0);
    ck_assert(open_and_wait(app, "viewer-mid.scn"));
    finished_image(app);
    char path[256];
    ck_assert(view_app_save(app, path, sizeof path));
    ck_assert_str_eq(path, "viewer-out.ppm");
    /* A second complete save goes beside -o's path. */
    ck_assert(view_app_save(app, path, sizeof path));
    ck_assert_str_eq(path, "viewer-out-1.ppm");
    close_app(app);
    size_t first_size;
    char *first = rt_test_read_file("viewer-out.ppm", &first_size);
    ck_assert_ptr_nonnull(first);

    /* 1024 rays a pixel on one thread, stopped at once: surely unfinished
     * when S is pressed. */
    app = open_app_with("viewer-out.ppm", 0, 1024);
    ck_assert(open_and_wait(app, "viewer-mid.scn"));
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
    close_app(app);
    remove("viewer-mid.scn");
    remove("viewer-out.ppm");
    remove("viewer-out-1.ppm");
    remove("viewer-out-partial-1.ppm");
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

START_TEST(a_scene_that_never_loaded_exits_1_when_the_window_closes)
{
    view_app *app = open_app(NULL, 0);
    ck_assert(!open_and_wait(app, "viewer-no-such-scene.scn"));
    SDL_Event quit;
    SDL_zero(quit);
    quit.type = SDL_QUIT;
    ck_assert_int_eq(SDL_PushEvent(&quit), 1);
    view_app_run(app);
    ck_assert_int_eq(view_app_exit_status(app), 1);
    close_app(app);

    /* No scene asked for, or one that loaded: 0. */
    app = open_app(NULL, 0);
    ck_assert_int_eq(SDL_PushEvent(&quit), 1);
    view_app_run(app);
    ck_assert_int_eq(view_app_exit_status(app), 0);
    ck_assert(open_and_wait(app, rt_test_source_path("scenes/empty.scn")));
    ck_assert_int_eq(view_app_exit_status(app), 0);
    close_app(app);
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

/* ---- the click overlay: window -> pixel, projection, drawing ---- */

START_TEST(window_point_maps_to_the_image_pixel_under_it)
{
    /* A 100x50 image in a 200x200 output: scale 2, letterboxed to rows
     * 50..149. */
    int i = -1, j = -1;
    ck_assert(view_output_to_pixel(100, 50, 200, 200, 0.5, 50.5, &i, &j));
    ck_assert_int_eq(i, 0);
    ck_assert_int_eq(j, 0);
    ck_assert(view_output_to_pixel(100, 50, 200, 200, 199.5, 149.5, &i, &j));
    ck_assert_int_eq(i, 99);
    ck_assert_int_eq(j, 49);
    ck_assert(view_output_to_pixel(100, 50, 200, 200, 21.5, 61.5, &i, &j));
    ck_assert_int_eq(i, 10);
    ck_assert_int_eq(j, 5);
    /* The bands above and below the picture are no pixel. */
    ck_assert(!view_output_to_pixel(100, 50, 200, 200, 100.5, 49.5, &i, &j));
    ck_assert(!view_output_to_pixel(100, 50, 200, 200, 100.5, 150.5, &i,
                                    &j));
    /* A window showing the image at its own size maps one to one. */
    rt_scene *scene = load_scene("scenes/cubes.scn");
    rt_scene_info info;
    rt_scene_get_info(scene, &info);
    view_window *window = open_window(info.width, info.height);
    view_session *session = new_session(scene, 1, NULL, NULL);
    ck_assert(!view_window_pixel_at(window, 3, 4, &i, &j));
    ck_assert(view_window_attach(window, session, NULL, 0));
    ck_assert(view_window_pixel_at(window, 3, 4, &i, &j));
    ck_assert_int_eq(i, 3);
    ck_assert_int_eq(j, 4);
    ck_assert(view_window_pixel_at(window, info.width - 1, info.height - 1,
                                   &i, &j));
    ck_assert_int_eq(i, info.width - 1);
    ck_assert_int_eq(j, info.height - 1);
    view_window_attach(window, NULL, NULL, 0);
    view_session_destroy(session);
    close_window(window);
}
END_TEST

/* Projection of `scene` at `width` x `height` (0: the scene's) with
 * `region`. */
static view_projection projection_of(const rt_scene *scene, int width,
                                     int height, rt_region region)
{
    rt_render_options options;
    rt_render_options_init(&options);
    options.width = width;
    options.height = height;
    options.region = region;
    view_projection projection;
    view_projection_init(&projection, scene, &options);
    return projection;
}

static rt_vec3 along(rt_ray ray, double t)
{
    rt_vec3 p = {ray.origin.x + t * ray.direction.x,
                 ray.origin.y + t * ray.direction.y,
                 ray.origin.z + t * ray.direction.z};
    return p;
}

START_TEST(camera_ray_of_a_pixel_projects_back_to_its_centre)
{
    rt_scene *scene = load_scene("scenes/cubes.scn");
    const int sizes[][2] = {{0, 0}, {200, 100}, {64, 256}};
    for (size_t s = 0; s < sizeof sizes / sizeof *sizes; s++) {
        rt_region none = {0, 0, 0, 0};
        view_projection projection =
            projection_of(scene, sizes[s][0], sizes[s][1], none);
        rt_camera camera = projection.camera;
        camera.width = projection.width;
        camera.height = projection.height;
        const int pixels[][2] = {{0, 0}, {17, 3}, {camera.width - 1, 0},
                                 {camera.width / 2, camera.height - 1}};
        for (size_t p = 0; p < sizeof pixels / sizeof *pixels; p++) {
            rt_ray ray = rt_camera_ray(&camera, pixels[p][0], pixels[p][1]);
            /* At t = 1 (the screen) and farther along the same ray. */
            for (double t = 1; t <= 9; t += 4) {
                double x, y;
                ck_assert(view_project_point(&projection, along(ray, t), &x,
                                             &y));
                ck_assert_double_eq_tol(x, pixels[p][0] + 0.5, 1e-9);
                ck_assert_double_eq_tol(y, pixels[p][1] + 0.5, 1e-9);
            }
        }
    }
    /* With a region, coordinates are the region's. */
    rt_region region = {10, 20, 50, 60};
    view_projection projection = projection_of(scene, 0, 0, region);
    rt_ray ray = rt_camera_ray(&projection.camera, 12, 25);
    double x, y;
    ck_assert(view_project_point(&projection, along(ray, 1), &x, &y));
    ck_assert_double_eq_tol(x, 2.5, 1e-9);
    ck_assert_double_eq_tol(y, 5.5, 1e-9);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(segments_behind_the_observer_are_clipped)
{
    rt_scene *scene = load_scene("scenes/cubes.scn");
    rt_region none = {0, 0, 0, 0};
    view_projection projection = projection_of(scene, 0, 0, none);
    rt_ray ray = rt_camera_ray(&projection.camera, 40, 30);
    double x, y, line[4];
    /* Behind the observer: no projection. */
    ck_assert(!view_project_point(&projection, along(ray, -1), &x, &y));
    ck_assert(!view_project_segment(&projection, along(ray, -2),
                                    along(ray, -1), line));
    /* From behind to in front: the part in front, ending where the point in
     * front projects. */
    ck_assert(view_project_segment(&projection, along(ray, -1),
                                   along(ray, 2), line));
    ck_assert_double_eq_tol(line[2], 40.5, 1e-9);
    ck_assert_double_eq_tol(line[3], 30.5, 1e-9);
    ck_assert(isfinite(line[0]) && isfinite(line[1]));
    rt_scene_destroy(scene);
}
END_TEST

static int pixel_is(const rt_image *image, int x, int y,
                    const unsigned char rgb[3])
{
    const unsigned char *p = rt_image_pixel(image, x, y);
    return p[0] == rgb[0] && p[1] == rgb[1] && p[2] == rgb[2];
}

START_TEST(overlay_draws_each_ray_in_its_colour_along_its_projection)
{
    rt_scene *scene = load_scene("scenes/cubes.scn");
    rt_scene_info info;
    rt_scene_get_info(scene, &info);
    view_window *window = open_window(info.width, info.height);
    view_session *session = new_session(scene, 1, NULL, NULL);
    ck_assert(view_window_attach(window, session, NULL, 0));
    rt_region none = {0, 0, 0, 0};
    view_projection projection =
        projection_of(view_session_scene(session), 0, 0, none);
    const rt_camera *camera = &projection.camera;
    /* Screen points at pixel centres: a horizontal shadow ray on row 20
     * from column 10 to 90, and a vertical reflected ray at column 150
     * from row 30 to 120 (far beyond the screen), marked. */
    view_segment segments[2] = {
        {VIEW_RAY_SHADOW, along(rt_camera_ray(camera, 10, 20), 1),
         along(rt_camera_ray(camera, 90, 20), 1), 0},
        {VIEW_RAY_REFLECTED, along(rt_camera_ray(camera, 150, 30), 1),
         along(rt_camera_ray(camera, 150, 120), 5), 1},
    };
    ck_assert(view_window_set_overlay(window, &projection, segments, 2));
    rt_image frame = read_window(window);
    unsigned char yellow[3], cyan[3];
    view_ray_color(VIEW_RAY_SHADOW, yellow);
    view_ray_color(VIEW_RAY_REFLECTED, cyan);
    for (int x = 10; x <= 90; x++)
        ck_assert_msg(pixel_is(&frame, x, 20, yellow), "(%d, 20)", x);
    ck_assert(!pixel_is(&frame, 50, 22, yellow));
    for (int y = 30; y <= 120; y++)
        ck_assert_msg(pixel_is(&frame, 150, y, cyan), "(150, %d)", y);
    /* The mark: a square around the hit. */
    ck_assert(pixel_is(&frame, 147, 120, cyan));
    ck_assert(pixel_is(&frame, 153, 123, cyan));
    rt_image_release(&frame);

    /* Cleared: the placeholder again. */
    ck_assert(view_window_set_overlay(window, NULL, NULL, 0));
    frame = read_window(window);
    ck_assert(row_is_placeholder(&frame, 20));
    rt_image_release(&frame);
    view_window_attach(window, NULL, NULL, 0);
    view_session_destroy(session);
    close_window(window);
}
END_TEST

/* ---- clicking a pixel, the debug views (view_app) ---- */

/* An app showing scenes/cubes.scn, finished and on screen. */
static view_app *open_cubes_app(void)
{
    view_app *app = open_app(NULL, 0);
    ck_assert(open_and_wait(app, rt_test_source_path("scenes/cubes.scn")));
    finished_image(app);
    view_window_sync(view_app_window(app));
    return app;
}

static rt_vec3 unit(rt_vec3 v)
{
    double length = sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    rt_vec3 u = {v.x / length, v.y / length, v.z / length};
    return u;
}

START_TEST(clicking_a_pixel_explains_it_starting_with_its_camera_ray)
{
    view_app *app = open_cubes_app();
    view_window *window = view_app_window(app);
    int x, y;
    ck_assert(view_window_pixel_at(window, 123, 77, &x, &y));
    ck_assert(view_app_click(app, 123, 77));
    const view_explanation *e = view_app_explanation(app);
    ck_assert_ptr_nonnull(e);
    ck_assert_int_eq(e->x, x);
    ck_assert_int_eq(e->y, y);
    ck_assert_int_eq(e->first.kind, RT_RAY_CAMERA);
    rt_scene_info info;
    rt_scene_get_info(view_session_scene(view_app_session(app)), &info);
    rt_ray ray = rt_camera_ray(&info.camera, x, y);
    rt_vec3 expected = unit(ray.direction), actual = unit(e->first.direction);
    ck_assert_double_eq_tol(e->first.origin.x, ray.origin.x, 1e-9);
    ck_assert_double_eq_tol(e->first.origin.y, ray.origin.y, 1e-9);
    ck_assert_double_eq_tol(e->first.origin.z, ray.origin.z, 1e-9);
    ck_assert_double_eq_tol(actual.x, expected.x, 1e-6);
    ck_assert_double_eq_tol(actual.y, expected.y, 1e-6);
    ck_assert_double_eq_tol(actual.z, expected.z, 1e-6);
    /* The value explained is the byte shown. */
    const unsigned char *shown =
        rt_image_pixel(view_session_image(view_app_session(app)), x, y);
    ck_assert_int_eq(rt_channel_to_byte(e->value.r), shown[0]);
    ck_assert_int_eq(rt_channel_to_byte(e->value.g), shown[1]);
    ck_assert_int_eq(rt_channel_to_byte(e->value.b), shown[2]);
    ck_assert_ptr_nonnull(strstr(e->text, "camera"));
    /* Outside the picture: nothing; Esc clears the explanation. */
    ck_assert(!view_app_click(app, -5, -5));
    view_app_key(app, SDLK_ESCAPE, 0);
    ck_assert_ptr_null(view_app_explanation(app));
    close_app(app);
}
END_TEST

/* Does the 3x3 neighbourhood of (x, y) in `frame` hold colour rgb? */
static int near_color(const rt_image *frame, double x, double y,
                      const unsigned char rgb[3])
{
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++) {
            int px = (int)floor(x) + dx, py = (int)floor(y) + dy;
            if (px >= 0 && py >= 0 && px < frame->width &&
                py < frame->height && pixel_is(frame, px, py, rgb))
                return 1;
        }
    return 0;
}

START_TEST(a_shadowed_pixel_shows_its_blocker_in_red_over_the_image)
{
    view_app *app = open_cubes_app();
    const rt_image *image = view_session_image(view_app_session(app));
    /* The first pixel, on a coarse grid, in some facet's shadow. */
    const rt_scene *scene = view_session_scene(view_app_session(app));
    int found = 0, x, y;
    for (y = 4; y < image->height && !found; y += 8)
        for (x = 4; x < image->width && !found; x += 8) {
            view_explanation probe;
            ck_assert_int_eq(view_explain_pixel(scene, NULL, "cubes.scn", x,
                                                y, &probe, NULL), RT_OK);
            for (int k = 0; k < probe.segment_count; k++)
                found |= probe.segments[k].kind == VIEW_RAY_BLOCKED;
            view_explanation_release(&probe);
        }
    ck_assert_msg(found, "no shadowed pixel in cubes.scn");
    ck_assert(view_app_explain(app, x - 8, y - 8));
    const view_explanation *e = view_app_explanation(app);
    const view_segment *blocked = NULL;
    for (int k = 0; k < e->segment_count; k++)
        if (e->segments[k].kind == VIEW_RAY_BLOCKED)
            blocked = &e->segments[k];
    ck_assert_ptr_nonnull(blocked);
    ck_assert_ptr_nonnull(strstr(e->text, "shadowed by facet"));
    ck_assert_ptr_nonnull(strstr(e->text, "(line "));

    rt_render_options options;
    rt_render_options_init(&options);
    view_projection projection;
    view_projection_init(&projection,
                         view_session_scene(view_app_session(app)), &options);
    double line[4];
    ck_assert(view_project_segment(&projection, blocked->from, blocked->to,
                                   line));
    rt_image frame = read_window(view_app_window(app));
    ck_assert_int_eq(frame.width, image->width);
    unsigned char red[3];
    view_ray_color(VIEW_RAY_BLOCKED, red);
    /* Along the projected segment (where it is in the picture), and its
     * blocker marked. */
    int checked = 0;
    for (int step = 1; step < 10; step++) {
        double f = step / 10.0;
        double px = line[0] + f * (line[2] - line[0]);
        double py = line[1] + f * (line[3] - line[1]);
        if (px < 1 || py < 1 || px > frame.width - 2 ||
            py > frame.height - 2)
            continue;
        ck_assert_msg(near_color(&frame, px, py, red),
                      "no red at (%g, %g), %g of the blocked shadow ray", px,
                      py, f);
        checked++;
    }
    ck_assert_int_gt(checked, 0);
    ck_assert(near_color(&frame, line[2] + MARK_HALF, line[3], red) ||
              near_color(&frame, line[2], line[3] + MARK_HALF, red));
    rt_image_release(&frame);
    close_app(app);
}
END_TEST

START_TEST(debug_view_keys_change_what_the_window_shows)
{
    view_app *app = open_cubes_app();
    view_window *window = view_app_window(app);
    rt_image picture = read_window(window);
    view_app_key(app, SDLK_n, 0);
    ck_assert_ptr_nonnull(strstr(view_app_title(app), "normal view"));
    rt_image normals = read_window(window);
    /* The window shows the library's normal view. */
    rt_image expected;
    ck_assert_int_eq(rt_image_init(&expected, picture.width, picture.height,
                                   NULL), RT_OK);
    ck_assert_int_eq(rt_render_view(view_session_scene(view_app_session(app)),
                                    NULL, RT_VIEW_NORMAL, 0, &expected, NULL),
                     RT_OK);
    assert_same_image(&normals, &expected, "normal view");
    rt_image_release(&expected);
    view_app_key(app, SDLK_l, 0);
    ck_assert_ptr_nonnull(strstr(view_app_title(app), "shadow view of light 0"));
    view_app_key(app, SDLK_v, 0);
    ck_assert_ptr_null(strstr(view_app_title(app), "shadow view"));
    rt_image again = read_window(window);
    assert_same_image(&again, &picture, "the picture again");
    rt_image_release(&picture);
    rt_image_release(&normals);
    rt_image_release(&again);
    close_app(app);
}
END_TEST

START_TEST(view_option_starts_in_that_debug_view)
{
    setenv("SDL_VIDEODRIVER", "dummy", 0);
    ck_assert(SDL_Init(SDL_INIT_VIDEO) == 0);
    view_app_options options;
    view_app_options_init(&options);
    options.window_flags = VIEW_WINDOW_SOFTWARE;
    options.view = RT_VIEW_FACET;
    char error[256];
    view_app *app = view_app_create(&options, error, sizeof error);
    ck_assert_msg(app != NULL, "%s", error);
    ck_assert(open_and_wait(app, rt_test_source_path("scenes/cubes.scn")));
    ck_assert_ptr_nonnull(strstr(view_app_title(app), "facet view"));
    /* A light the scene does not have: the picture, and the reason. */
    ck_assert(!view_app_set_view(app, RT_VIEW_SHADOW, 7));
    ck_assert_ptr_null(strstr(view_app_title(app), "view -"));
    ck_assert_ptr_nonnull(strstr(view_app_message(app), "shadow view"));
    close_app(app);
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
                   restart_goes_back_to_the_placeholder_and_renders_again);
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

    TCase *overlay = tcase_create("overlay");
    tcase_set_timeout(overlay, 120);
    tcase_add_test(overlay, window_point_maps_to_the_image_pixel_under_it);
    tcase_add_test(overlay, camera_ray_of_a_pixel_projects_back_to_its_centre);
    tcase_add_test(overlay, segments_behind_the_observer_are_clipped);
    tcase_add_test(overlay,
                   overlay_draws_each_ray_in_its_colour_along_its_projection);
    tcase_add_test(overlay,
                   clicking_a_pixel_explains_it_starting_with_its_camera_ray);
    tcase_add_test(overlay,
                   a_shadowed_pixel_shows_its_blocker_in_red_over_the_image);
    tcase_add_test(overlay, debug_view_keys_change_what_the_window_shows);
    tcase_add_test(overlay, view_option_starts_in_that_debug_view);
    suite_add_tcase(suite, overlay);

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

RT_CHECK_MAIN(viewer_suite)
