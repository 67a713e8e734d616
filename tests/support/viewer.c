/*
 * viewer.c - what the suites of rt-view's logic share (see viewer.h).
 */
#include "viewer.h"

#include <check.h>
#include <stdlib.h>
#include <string.h>

#define SDL_MAIN_HANDLED
#include <SDL.h>

#include "clock.h"
#include "rng.h"

int rt_test_view_row_is_placeholder(const rt_image *frame, int y)
{
    for (int x = 0; x < frame->width; x++) {
        unsigned char expected[3];
        view_placeholder_color(x, y, expected);
        if (memcmp(rt_image_pixel(frame, x, y), expected, 3) != 0)
            return 0;
    }
    return 1;
}

void rt_test_view_sdl_init(void)
{
    setenv("SDL_VIDEODRIVER", "dummy", 0);
    ck_assert_msg(SDL_Init(SDL_INIT_VIDEO) == 0, "SDL_Init: %s",
                  SDL_GetError());
}

view_session *rt_test_view_session(rt_scene *scene, int threads,
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

view_state rt_test_view_wait(view_session *session)
{
    view_progress progress;
    double deadline = rt_test_now() + RT_TEST_VIEW_WAIT_SECONDS;
    for (;;) {
        view_session_get_progress(session, &progress);
        if (progress.state != VIEW_RENDERING)
            return progress.state;
        ck_assert_msg(rt_test_now() < deadline, "render did not finish");
        rt_test_sleep_ms(2);
    }
}

view_window *rt_test_view_window_open(int width, int height)
{
    rt_test_view_sdl_init();
    char error[256];
    view_window *window = view_window_create(
        "test", width, height, VIEW_WINDOW_SOFTWARE | VIEW_WINDOW_HIDDEN,
        error, sizeof error);
    ck_assert_msg(window != NULL, "%s", error);
    return window;
}

void rt_test_view_window_close(view_window *window)
{
    view_window_destroy(window);
    SDL_Quit();
}

rt_image rt_test_view_window_read(view_window *window)
{
    rt_image frame;
    ck_assert_msg(view_window_read(window, &frame), "read back: %s",
                  SDL_GetError());
    return frame;
}

void rt_test_view_app_options(view_app_options *options)
{
    view_app_options_init(options);
    options->window_flags = VIEW_WINDOW_SOFTWARE;
}

view_app *rt_test_view_app_open(const view_app_options *options)
{
    rt_test_view_sdl_init();
    char error[256];
    view_app *app = view_app_create(options, error, sizeof error);
    ck_assert_msg(app != NULL, "%s", error);
    return app;
}

void rt_test_view_app_close(view_app *app)
{
    view_app_destroy(app);
    SDL_Quit();
}

view_app *rt_test_view_app(const char *output, int watch, int samples)
{
    view_app_options options;
    rt_test_view_app_options(&options);
    options.format = RT_IMAGE_P6;
    options.output = output;
    options.watch = watch;
    if (samples > 1) {
        options.render.samples = samples;
        options.render.threads = 1;
    }
    return rt_test_view_app_open(&options);
}

int rt_test_view_app_load(view_app *app, const char *path)
{
    return view_app_open(app, path) && view_app_wait_load(app);
}

const rt_image *rt_test_view_app_image(view_app *app)
{
    view_session *session = view_app_session(app);
    ck_assert_ptr_nonnull(session);
    ck_assert_int_eq(rt_test_view_wait(session), VIEW_DONE);
    return view_session_image(session);
}

/*
 * A scene slow to render (see viewer.h).
 */
rt_scene *rt_test_view_heavy_scene(int count, int width, int height)
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
        .lights = &(rt_light){{-3, 2, 20}, {255, 255, 255}},
        .light_count = 1,
    };
    rt_scene *scene = NULL;
    rt_error error;
    rt_status status = rt_scene_create(&desc, &scene, &error);
    free(vertices);
    free(facets);
    ck_assert_msg(status == RT_OK, "%s", error.message);
    return scene;
}
