/*
 * test_viewer_overlay.c - rt-view's click overlay and debug views: a window
 * point maps to the image pixel under it, a pixel's camera ray projects
 * back to its centre, segments behind the observer are clipped, each ray
 * of an explanation is drawn in its colour along its projection, a
 * shadowed pixel shows its blocker, and the debug-view keys and --view
 * change what the window shows.  On SDL's dummy video driver (no display).
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

/* Half the side of the square marking a hit (view_window.c's MARK_SIZE). */
#define MARK_HALF 3

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
    rt_scene *scene = rt_test_load_source_scene("scenes/cubes.scn");
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    view_window *window = rt_test_view_window_open(info.width, info.height);
    view_session *session = rt_test_view_session(scene, 1, NULL, NULL);
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
    rt_test_view_window_close(window);
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
    rt_scene *scene = rt_test_load_source_scene("scenes/cubes.scn");
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
    rt_scene *scene = rt_test_load_source_scene("scenes/cubes.scn");
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
    rt_scene *scene = rt_test_load_source_scene("scenes/cubes.scn");
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    view_window *window = rt_test_view_window_open(info.width, info.height);
    view_session *session = rt_test_view_session(scene, 1, NULL, NULL);
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
    rt_image frame = rt_test_view_window_read(window);
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
    frame = rt_test_view_window_read(window);
    ck_assert(rt_test_view_row_is_placeholder(&frame, 20));
    rt_image_release(&frame);
    view_window_attach(window, NULL, NULL, 0);
    view_session_destroy(session);
    rt_test_view_window_close(window);
}
END_TEST

/* ---- clicking a pixel, the debug views (view_app) ---- */

/* An app showing scenes/cubes.scn, finished and on screen. */
static view_app *open_cubes_app(void)
{
    view_app *app = rt_test_view_app(NULL, 0, 1);
    ck_assert(rt_test_view_app_load(app,
                                    rt_test_source_path("scenes/cubes.scn")));
    rt_test_view_app_image(app);
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
    rt_scene_info info = {.size = sizeof info};
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
    rt_test_view_app_close(app);
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
    rt_image frame = rt_test_view_window_read(view_app_window(app));
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
    rt_test_view_app_close(app);
}
END_TEST

START_TEST(debug_view_keys_change_what_the_window_shows)
{
    view_app *app = open_cubes_app();
    view_window *window = view_app_window(app);
    rt_image picture = rt_test_view_window_read(window);
    view_app_key(app, SDLK_n, 0);
    ck_assert_ptr_nonnull(strstr(view_app_title(app), "normal view"));
    /* The view renders on the session's worker, as the picture does: once
     * it is done, the window shows the library's normal view. */
    view_session *session = view_app_session(app);
    ck_assert_int_eq(rt_test_view_wait(session), VIEW_DONE);
    view_window_sync(window);
    rt_image normals = rt_test_view_window_read(window);
    rt_image expected;
    ck_assert_int_eq(rt_image_init(&expected, picture.width, picture.height,
                                   NULL), RT_OK);
    ck_assert_int_eq(rt_render_view(view_session_scene(view_app_session(app)),
                                    NULL, RT_VIEW_NORMAL, 0, &expected, NULL),
                     RT_OK);
    rt_test_assert_same_image(&normals, &expected, "viewer-normal view");
    rt_image_release(&expected);
    view_app_key(app, SDLK_l, 0);
    ck_assert_ptr_nonnull(strstr(view_app_title(app), "shadow view of light 0"));
    /* V cancels the shadow view under way; the picture, finished before,
     * is shown again at once, without rendering. */
    view_app_key(app, SDLK_v, 0);
    ck_assert_ptr_null(strstr(view_app_title(app), "shadow view"));
    view_progress progress;
    view_session_get_progress(session, &progress);
    ck_assert_int_eq(progress.state, VIEW_DONE);
    ck_assert_int_eq(progress.view, 0);
    view_window_sync(window);
    rt_image again = rt_test_view_window_read(window);
    rt_test_assert_same_image(&again, &picture, "viewer-the picture again");
    rt_image_release(&picture);
    rt_image_release(&normals);
    rt_image_release(&again);
    rt_test_view_app_close(app);
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
    ck_assert(rt_test_view_app_load(app,
                                    rt_test_source_path("scenes/cubes.scn")));
    ck_assert_ptr_nonnull(strstr(view_app_title(app), "facet view"));
    /* A light the scene does not have: the picture, and the reason. */
    ck_assert(!view_app_set_view(app, RT_VIEW_SHADOW, 7));
    ck_assert_ptr_null(strstr(view_app_title(app), "view -"));
    ck_assert_ptr_nonnull(strstr(view_app_message(app), "shadow view"));
    rt_test_view_app_close(app);
}
END_TEST

static Suite *viewer_overlay_suite(void)
{
    Suite *suite = suite_create("viewer_overlay");
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
    return suite;
}

RT_CHECK_MAIN(viewer_overlay_suite)
