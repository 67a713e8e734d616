/*
 * test_viewer_overlay.c - rt-view's click overlay and debug views: a window
 * point maps to the image pixel under it, a pixel's camera ray projects
 * back to its centre, segments behind the observer are clipped, each ray
 * of an explanation is drawn in its colour along its projection, a
 * shadowed pixel shows its blocker, a click on a pixel of several samples
 * draws the one sample under it (regular, stratified, through a lens;
 * Tab steps to the others) with a text panel that leaves the picture
 * visible, and the debug-view keys and --view change what the window
 * shows.  On SDL's dummy video driver (no display).
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

#include "cli_explain.h"
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

/* ---- a pixel of several samples: the one under the click ---- */

/* An app showing `scene` (a source path) rendered with `samples` rays a
 * pixel (`sampling`), at width x height (0: the scene's), finished. */
static view_app *open_sampled_app(const char *scene, int samples,
                                  rt_sampling sampling, int width,
                                  int height)
{
    view_app_options options;
    rt_test_view_app_options(&options);
    options.format = RT_IMAGE_P6;
    options.render.samples = samples;
    options.render.sampling = sampling;
    options.render.threads = 1;
    options.render.width = width;
    options.render.height = height;
    view_app *app = rt_test_view_app_open(&options);
    ck_assert(rt_test_view_app_load(app, rt_test_source_path(scene)));
    rt_test_view_app_image(app);
    view_window_sync(view_app_window(app));
    return app;
}

/* The render options the app above renders with. */
static rt_render_options sampled_options(int samples, rt_sampling sampling,
                                         int width, int height)
{
    rt_render_options options;
    rt_render_options_init(&options);
    options.samples = samples;
    options.sampling = sampling;
    options.threads = 1;
    options.width = width;
    options.height = height;
    return options;
}

/* The library's tree of sample k of pixel (x, y), asked directly. */
static rt_ray_tree *sample_tree(const view_app *app_const, int x, int y,
                                int k, const rt_render_options *options)
{
    view_app *app = (view_app *)app_const;
    rt_ray_tree *tree;
    rt_error error;
    ck_assert_msg(rt_explain_pixel(view_session_scene(view_app_session(app)),
                                   options, x, y, k, &tree, &error) == RT_OK,
                  "%s", error.message);
    return tree;
}

/* The rays of `tree` the overlay can draw (all but shadow rays not cast),
 * and in *cameras its camera rays. */
static int drawable_rays(const rt_ray_tree *tree, int *cameras)
{
    size_t count;
    const rt_ray_node *nodes = rt_ray_tree_nodes(tree, &count);
    int drawable = 0;
    *cameras = 0;
    for (size_t i = 0; i < count; i++) {
        drawable += !(nodes[i].kind == RT_RAY_SHADOW && !nodes[i].cast);
        *cameras += nodes[i].kind == RT_RAY_CAMERA;
    }
    return drawable;
}

/* The direction of the camera ray through image point (px, py) of a w x h
 * image of `camera`, by the rendering model's formula (pinhole), unit. */
static rt_vec3 model_direction(const rt_camera *camera, int w, int h,
                               double px, double py)
{
    double s = (2 * px - w) / w, t = (h - 2 * py) / w;
    rt_vec3 p = {camera->screen_center.x + s * camera->right.x +
                     t * camera->up.x,
                 camera->screen_center.y + s * camera->right.y +
                     t * camera->up.y,
                 camera->screen_center.z + s * camera->right.z +
                     t * camera->up.z};
    rt_vec3 d = {p.x - camera->observer.x, p.y - camera->observer.y,
                 p.z - camera->observer.z};
    return unit(d);
}

/* The formatter's text of `tree` (rt-export's words), in a new string. */
static char *formatted(const rt_ray_tree *tree, const char *name, int x,
                       int y, int samples)
{
    char *data = NULL;
    size_t size = 0;
    FILE *out = open_memstream(&data, &size);
    ck_assert_ptr_nonnull(out);
    cli_explain_print_text(out, tree, name, x, y, samples);
    ck_assert_int_eq(fclose(out), 0);
    return data;
}

/* Asserts that the explanation draws sample k of its pixel: one camera
 * ray, the library's for sample k; as many segments as that sample's
 * tree has rays to draw, fewer than the whole pixel's; its text the
 * formatter's for that tree. */
static void assert_draws_sample(const view_app *app, int k,
                                const rt_render_options *options)
{
    const view_explanation *e = view_app_explanation(app);
    ck_assert_ptr_nonnull(e);
    ck_assert_int_eq(e->sample, k);
    rt_ray_tree *tree = sample_tree(app, e->x, e->y, k, options);
    rt_ray_tree *whole = sample_tree(app, e->x, e->y, -1, options);
    int cameras, whole_cameras;
    int drawable = drawable_rays(tree, &cameras);
    int whole_drawable = drawable_rays(whole, &whole_cameras);
    ck_assert_int_eq(cameras, 1);
    ck_assert_int_eq(whole_cameras, options->samples);
    ck_assert_int_eq(e->segment_count, drawable);
    ck_assert_int_lt(e->segment_count, whole_drawable);
    int camera_segments = 0;
    for (int i = 0; i < e->segment_count; i++)
        camera_segments += e->segments[i].kind == VIEW_RAY_CAMERA;
    ck_assert_int_eq(camera_segments, 1);
    const rt_ray_node *ray = rt_ray_tree_nodes(tree, NULL);
    ck_assert_int_eq(e->first.kind, RT_RAY_CAMERA);
    ck_assert_int_eq(e->first.sample, k);
    ck_assert_double_eq_tol(e->first.direction.x, ray[0].direction.x, 1e-12);
    ck_assert_double_eq_tol(e->first.direction.y, ray[0].direction.y, 1e-12);
    ck_assert_double_eq_tol(e->first.direction.z, ray[0].direction.z, 1e-12);
    ck_assert_double_eq_tol(e->first.origin.x, ray[0].origin.x, 1e-12);
    ck_assert_double_eq_tol(e->first.origin.y, ray[0].origin.y, 1e-12);
    ck_assert_double_eq_tol(e->first.origin.z, ray[0].origin.z, 1e-12);
    char *text = formatted(tree, "name", e->x, e->y, options->samples);
    /* the same lines but the first, which names the scene */
    ck_assert_str_eq(strchr(e->sample_text, '\n'), strchr(text, '\n'));
    free(text);
    rt_ray_tree_destroy(tree);
    rt_ray_tree_destroy(whole);
}

START_TEST(a_click_with_four_samples_draws_only_the_sample_under_it)
{
    view_app *app = open_sampled_app("scenes/cubes.scn", 4,
                                     RT_SAMPLING_REGULAR, 0, 0);
    rt_render_options options =
        sampled_options(4, RT_SAMPLING_REGULAR, 0, 0);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(view_session_scene(view_app_session(app)), &info);
    const int x = 268, y = 124;
    /* A regular 2 x 2 grid: sample sy * 2 + sx at the centre of cell
     * (sx, sy), the top-left quarter first (src/render/pixel.c). */
    for (int k = 0; k < 4; k++) {
        int sx = k % 2, sy = k / 2;
        double px = x + (sx ? 0.8 : 0.2), py = y + (sy ? 0.7 : 0.3);
        ck_assert(view_app_explain_at(app, px, py));
        assert_draws_sample(app, k, &options);
        const view_explanation *e = view_app_explanation(app);
        ck_assert_int_eq(e->x, x);
        ck_assert_int_eq(e->y, y);
        /* its ray goes through the centre of its cell, as the model
         * says */
        rt_vec3 expected = model_direction(&info.camera, info.width,
                                           info.height, x + (sx + 0.5) / 2,
                                           y + (sy + 0.5) / 2);
        rt_vec3 actual = unit(e->first.direction);
        ck_assert_double_eq_tol(actual.x, expected.x, 1e-9);
        ck_assert_double_eq_tol(actual.y, expected.y, 1e-9);
        ck_assert_double_eq_tol(actual.z, expected.z, 1e-9);
        /* the pixel's value stays the pixel's: the byte shown */
        const unsigned char *shown =
            rt_image_pixel(view_session_image(view_app_session(app)), x, y);
        ck_assert_int_eq(rt_channel_to_byte(e->value.r), shown[0]);
        ck_assert_int_eq(rt_channel_to_byte(e->value.g), shown[1]);
        ck_assert_int_eq(rt_channel_to_byte(e->value.b), shown[2]);
    }
    /* The pixel's centre, equally near all four: the first. */
    ck_assert(view_app_explain(app, x, y));
    ck_assert_int_eq(view_app_explanation(app)->sample, 0);
    rt_test_view_app_close(app);
}
END_TEST

START_TEST(the_sample_drawn_is_in_rt_exports_words)
{
    view_app *app = open_sampled_app("scenes/cubes.scn", 4,
                                     RT_SAMPLING_REGULAR, 0, 0);
    const int x = 268, y = 124;
    ck_assert(view_app_explain_at(app, x + 0.8, y + 0.8));
    const view_explanation *e = view_app_explanation(app);
    ck_assert_int_eq(e->sample, 3);
    char *dir = rt_test_temp_dir();
    const char *scene = rt_test_source_path("scenes/cubes.scn");
    const char *args[] = {scene, "--samples", "4", "--explain", "268,124",
                          NULL};
    rt_test_output r = rt_test_run(dir, RT_EXPORT_PATH, args);
    ck_assert_msg(r.code == 0, "%s", r.err);
    /* What is printed is rt-export's text for the pixel, every sample. */
    ck_assert_str_eq(e->text, r.out);
    /* The sample's own text: its "sample 3:" block is rt-export's, line
     * for line (all but the first line, which names the scene, and the
     * last, the value line: here the sample's, there the pixel's). */
    const char *block = strstr(e->sample_text, "\nsample 3:\n");
    ck_assert_ptr_nonnull(block);
    const char *end = strstr(block, "\npixel value ");
    ck_assert_ptr_nonnull(end);
    char *lines = strndup(block, (size_t)(end - block + 1));
    ck_assert_msg(strstr(r.out, lines) != NULL,
                  "sample 3's lines:\n%s\nare not in rt-export's:\n%s", lines,
                  r.out);
    /* and only sample 3's */
    ck_assert_ptr_null(strstr(e->sample_text, "sample 0:"));
    ck_assert_ptr_null(strstr(e->sample_text, "sample 2:"));
    free(lines);
    rt_test_output_free(&r);
    rt_test_remove_dir(dir);
    rt_test_view_app_close(app);
}
END_TEST

START_TEST(tab_steps_through_the_samples_of_the_pixel)
{
    view_app *app = open_sampled_app("scenes/cubes.scn", 4,
                                     RT_SAMPLING_REGULAR, 0, 0);
    rt_render_options options =
        sampled_options(4, RT_SAMPLING_REGULAR, 0, 0);
    ck_assert(view_app_explain_at(app, 200.2, 300.2));
    assert_draws_sample(app, 0, &options);
    for (int k = 1; k <= 4; k++) {
        view_app_key(app, SDLK_TAB, 0);
        assert_draws_sample(app, k % 4, &options);
        ck_assert_int_eq(view_app_explanation(app)->x, 200);
        ck_assert_int_eq(view_app_explanation(app)->y, 300);
    }
    /* Shift+Tab: the previous one, from 0 to the last */
    SDL_SetModState(KMOD_LSHIFT);
    view_app_key(app, SDLK_TAB, 0);
    SDL_SetModState(KMOD_NONE);
    assert_draws_sample(app, 3, &options);
    const view_explanation *e = view_app_explanation(app);
    ck_assert_ptr_nonnull(e->panel);
    ck_assert_msg(strstr(e->panel, "sample 3 of 4") != NULL, "%s", e->panel);
    /* Esc clears it; Tab then does nothing */
    view_app_key(app, SDLK_ESCAPE, 0);
    ck_assert_ptr_null(view_app_explanation(app));
    view_app_key(app, SDLK_TAB, 0);
    ck_assert_ptr_null(view_app_explanation(app));
    ck_assert(!view_app_step_sample(app, 1));
    rt_test_view_app_close(app);
    /* With one sample there is nothing to step to. */
    app = open_cubes_app();
    ck_assert(view_app_explain(app, 200, 300));
    ck_assert_int_eq(view_app_explanation(app)->samples, 1);
    ck_assert(!view_app_step_sample(app, 1));
    ck_assert_int_eq(view_app_explanation(app)->sample, 0);
    rt_test_view_app_close(app);
}
END_TEST

START_TEST(a_click_in_a_quarter_of_an_enlarged_pixel_draws_its_sample)
{
    /* A 40 x 30 picture in a 400 x 300 window: each pixel is 10 x 10
     * window points, window point (200 + a, 150 + b) shows pixel (20, 15)
     * at (a + 1/2, b + 1/2) / 10 of it. */
    view_app *app = open_sampled_app("scenes/cubes.scn", 4,
                                     RT_SAMPLING_REGULAR, 40, 30);
    rt_render_options options =
        sampled_options(4, RT_SAMPLING_REGULAR, 40, 30);
    view_window *window = view_app_window(app);
    int bounds[4] = {0, 0, 4000, 4000};
    view_window_place(window, 400, 300, bounds, 1);
    int i, j;
    ck_assert(view_window_pixel_at(window, 205, 155, &i, &j));
    ck_assert_int_eq(i, 20);
    ck_assert_int_eq(j, 15);
    const int points[4][2] = {{202, 151}, {207, 153}, {201, 158}, {209,
                                                                   156}};
    for (int k = 0; k < 4; k++) {
        ck_assert(view_app_click(app, points[k][0], points[k][1]));
        ck_assert_int_eq(view_app_explanation(app)->x, 20);
        ck_assert_int_eq(view_app_explanation(app)->y, 15);
        assert_draws_sample(app, k, &options);
    }
    rt_test_view_app_close(app);
}
END_TEST

/* Where `ray` (a camera ray from the observer) crosses the screen, in
 * image coordinates of a w x h image: the model's formula inverted. */
static void screen_point(const rt_camera *camera, int w, int h,
                         const rt_ray_node *ray, double *px, double *py)
{
    rt_vec3 ao = {camera->screen_center.x - camera->observer.x,
                  camera->screen_center.y - camera->observer.y,
                  camera->screen_center.z - camera->observer.z};
    const rt_vec3 d = ray->direction;
    double along = (ao.x * ao.x + ao.y * ao.y + ao.z * ao.z) /
                   (d.x * ao.x + d.y * ao.y + d.z * ao.z);
    rt_vec3 pa = {camera->observer.x + along * d.x - camera->screen_center.x,
                  camera->observer.y + along * d.y - camera->screen_center.y,
                  camera->observer.z + along * d.z - camera->screen_center.z};
    const rt_vec3 ab = camera->right, ac = camera->up;
    double s = (pa.x * ab.x + pa.y * ab.y + pa.z * ab.z) /
               (ab.x * ab.x + ab.y * ab.y + ab.z * ab.z);
    double t = (pa.x * ac.x + pa.y * ac.y + pa.z * ac.z) /
               (ac.x * ac.x + ac.y * ac.y + ac.z * ac.z);
    *px = (s + 1) * w / 2;
    *py = (h - t * w) / 2;
}

START_TEST(stratified_samples_are_chosen_by_where_their_rays_go)
{
    /* 160 x 120: sixteen samples of the whole 400 x 400 picture outran
     * the wait under valgrind; the rays' cells are those at any size. */
    view_app *app = open_sampled_app("scenes/cubes.scn", 16,
                                     RT_SAMPLING_STRATIFIED, 160, 120);
    rt_render_options options =
        sampled_options(16, RT_SAMPLING_STRATIFIED, 160, 120);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(view_session_scene(view_app_session(app)), &info);
    info.width = 160;
    info.height = 120;
    const int x = 60, y = 84;
    int off_centre = 0;
    for (int k = 0; k < 16; k++) {
        rt_ray_tree *tree = sample_tree(app, x, y, k, &options);
        double px, py;
        screen_point(&info.camera, info.width, info.height,
                     rt_ray_tree_nodes(tree, NULL), &px, &py);
        rt_ray_tree_destroy(tree);
        /* in its cell of the 4 x 4 grid, jittered off its centre */
        ck_assert_int_eq((int)floor((px - x) * 4), k % 4);
        ck_assert_int_eq((int)floor((py - y) * 4), k / 4);
        off_centre += fabs((px - x) * 4 - (k % 4 + 0.5)) > 1e-3;
        ck_assert(view_app_explain_at(app, px, py));
        assert_draws_sample(app, k, &options);
    }
    ck_assert_int_gt(off_centre, 8);
    rt_test_view_app_close(app);
}
END_TEST

START_TEST(samples_through_a_lens_are_chosen_by_their_place_in_the_pixel)
{
    /* focus.scn's lens (a = 0.4): camera rays leave the lens, not the
     * observer, yet a regular sample's place in its pixel is its cell's
     * centre. */
    view_app *app = open_sampled_app("scenes/focus.scn", 4,
                                     RT_SAMPLING_REGULAR, 0, 0);
    rt_render_options options =
        sampled_options(4, RT_SAMPLING_REGULAR, 0, 0);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(view_session_scene(view_app_session(app)), &info);
    ck_assert_double_gt(info.camera.aperture, 0);
    const int x = 60, y = 100;
    for (int k = 0; k < 4; k++) {
        double px = x + (k % 2 ? 0.7 : 0.3), py = y + (k / 2 ? 0.9 : 0.1);
        ck_assert(view_app_explain_at(app, px, py));
        assert_draws_sample(app, k, &options);
        const view_explanation *e = view_app_explanation(app);
        ck_assert_double_eq_tol(e->points[k][0], x + (k % 2 + 0.5) / 2,
                                1e-9);
        ck_assert_double_eq_tol(e->points[k][1], y + (k / 2 + 0.5) / 2,
                                1e-9);
        /* off the observer: a lens ray */
        ck_assert(fabs(e->first.origin.x - info.camera.observer.x) +
                      fabs(e->first.origin.z - info.camera.observer.z) >
                  1e-6);
    }
    rt_test_view_app_close(app);
}
END_TEST

/* The line of `text` starting at `line`, as a new string. */
static char *line_copy(const char *line)
{
    return strndup(line, strcspn(line, "\n"));
}

START_TEST(the_panel_holds_the_samples_lines_that_fit)
{
    view_app *app = open_sampled_app("scenes/cubes.scn", 4,
                                     RT_SAMPLING_REGULAR, 0, 0);
    ck_assert(view_app_explain_at(app, 268.8, 124.2));
    const view_explanation *e = view_app_explanation(app);
    ck_assert_int_eq(e->sample, 1);
    /* Roomy: rt-view's two lines, then every line of the sample's tree
     * from its camera ray's hit to its terms, word for word. */
    char *panel = view_explanation_panel(e, 200, 100);
    ck_assert_ptr_nonnull(panel);
    ck_assert_msg(strncmp(panel, "pixel 268,124: bytes ", 21) == 0, "%s",
                  panel);
    ck_assert_ptr_nonnull(strstr(panel, "\nsample 1 of 4 (Tab"));
    const char *hit = strstr(e->sample_text, "    hits facet");
    const char *value = strstr(e->sample_text, "\npixel value");
    ck_assert(hit && value);
    char *lines = strndup(hit, (size_t)(value - hit + 1));
    ck_assert_msg(strstr(panel, lines) != NULL, "%s", panel);
    ck_assert_ptr_null(strstr(panel, "more lines"));
    ck_assert_ptr_null(strstr(panel, "camera ray"));
    free(lines);
    free(panel);
    /* Tight: within the rows, every line but rt-view's a line of the
     * sample's text, and the rest said to be on standard output. */
    for (int rows = 3; rows <= 12; rows++) {
        panel = view_explanation_panel(e, 48, rows);
        ck_assert_ptr_nonnull(panel);
        ck_assert_msg(view_text_rows(panel, 48) <= rows, "%d rows:\n%s",
                      rows, panel);
        ck_assert_ptr_nonnull(strstr(panel, "more lines on standard "
                                            "output\n"));
        int line_number = 0;
        for (const char *p = panel; *p; line_number++) {
            char *line = line_copy(p);
            if (line_number >= 2 && strncmp(line, "... ", 4) != 0) {
                char *within = malloc(strlen(line) + 3);
                sprintf(within, "\n%s\n", line);
                ck_assert_msg(strstr(e->sample_text, within) != NULL,
                              "not the formatter's: %s", line);
                free(within);
            }
            p += strlen(line);
            p += *p == '\n';
            free(line);
        }
        free(panel);
    }
    rt_test_view_app_close(app);
}
END_TEST

START_TEST(the_panel_leaves_most_of_the_picture_visible)
{
    view_app *app = open_sampled_app("scenes/cubes.scn", 4,
                                     RT_SAMPLING_REGULAR, 0, 0);
    view_window *window = view_app_window(app);
    if (!view_window_has_text(window)) {
        rt_test_view_app_close(app);
        return;     /* no panel in this build: the text is on stdout */
    }
    ck_assert(view_app_click(app, 268, 124));
    rt_image with = rt_test_view_window_read(window);
    view_window_set_text(window, NULL);
    rt_image without = rt_test_view_window_read(window);
    /* The panel darkens its rows from x = 4 (its text from x = 8; the
     * click's rays are far to the right). */
    int rows = 0;
    for (int y = 0; y < with.height; y++)
        rows += memcmp(rt_image_pixel(&with, 5, y),
                       rt_image_pixel(&without, 5, y), 3) != 0;
    ck_assert_int_gt(rows, 0);
    ck_assert_msg(rows <= with.height * 2 / 5, "the panel takes %d of %d rows",
                  rows, with.height);
    rt_image_release(&with);
    rt_image_release(&without);
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
    tcase_add_test(overlay,
                   a_click_with_four_samples_draws_only_the_sample_under_it);
    tcase_add_test(overlay, the_sample_drawn_is_in_rt_exports_words);
    tcase_add_test(overlay, tab_steps_through_the_samples_of_the_pixel);
    tcase_add_test(overlay,
                   a_click_in_a_quarter_of_an_enlarged_pixel_draws_its_sample);
    tcase_add_test(overlay,
                   stratified_samples_are_chosen_by_where_their_rays_go);
    tcase_add_test(
        overlay,
        samples_through_a_lens_are_chosen_by_their_place_in_the_pixel);
    tcase_add_test(overlay, the_panel_holds_the_samples_lines_that_fit);
    tcase_add_test(overlay, the_panel_leaves_most_of_the_picture_visible);
    tcase_add_test(overlay, debug_view_keys_change_what_the_window_shows);
    tcase_add_test(overlay, view_option_starts_in_that_debug_view);
    suite_add_tcase(suite, overlay);
    return suite;
}

RT_CHECK_MAIN(viewer_overlay_suite)
