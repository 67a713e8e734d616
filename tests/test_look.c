/*
 * test_look.c - another view of a loaded scene (raytrace/scene.h,
 * rt_scene_look; raytrace/render.h, rt_render_options.camera) and the
 * debug views as renders (raytrace/explain.h, rt_render_view on threads,
 * with rows reported, cancellation and statistics).
 *
 * The camera of rt_scene_look is compared bit for bit with the one the
 * loader builds from the same four view options, and the renders through
 * options.camera with the renders of the scene loaded with them, with
 * every accelerator and kernel and both precisions; the .scn lines written
 * from it read back as the same camera.
 */
#include "testutil.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int same_vec(rt_vec3 a, rt_vec3 b)
{
    return memcmp(&a.x, &b.x, sizeof a.x) == 0 &&
           memcmp(&a.y, &b.y, sizeof a.y) == 0 &&
           memcmp(&a.z, &b.z, sizeof a.z) == 0;
}

/* Field by field (memcmp of the struct would read its padding). */
static int same_camera(const rt_camera *a, const rt_camera *b)
{
    return same_vec(a->observer, b->observer) &&
           same_vec(a->screen_center, b->screen_center) &&
           same_vec(a->right, b->right) && same_vec(a->up, b->up) &&
           a->width == b->width && a->height == b->height &&
           memcmp(&a->aperture, &b->aperture, sizeof a->aperture) == 0 &&
           memcmp(&a->focal_distance, &b->focal_distance,
                  sizeof a->focal_distance) == 0;
}

static rt_scene *load(const char *relative, const rt_load_options *options)
{
    rt_scene *scene = NULL;
    rt_error error;
    rt_status status = rt_scene_load(rt_test_source_path(relative), options,
                                     &scene, &error);
    ck_assert_msg(status == RT_OK, "%s: %s", relative, error.message);
    return scene;
}

static rt_camera camera_of(const rt_scene *scene)
{
    rt_scene_info info = rt_test_scene_info(scene);
    return info.camera;
}

/* A look away from the file's: turned about the vertical through the
 * screen centre and raised, and narrower. */
static rt_look moved_look(const rt_scene *scene)
{
    rt_camera c = camera_of(scene);
    rt_look look;
    rt_camera_get_look(&c, &look);
    rt_vec3 d = {look.look_from.x - look.look_at.x,
                 look.look_from.y - look.look_at.y,
                 look.look_from.z - look.look_at.z};
    double a = 0.7, ca = cos(a), sa = sin(a);
    look.look_from = (rt_vec3){look.look_at.x + ca * d.x - sa * d.y,
                               look.look_at.y + sa * d.x + ca * d.y,
                               look.look_at.z + d.z * 1.3 + 0.25};
    look.fov *= 0.8;
    return look;
}

static rt_load_options options_of(const rt_look *look)
{
    rt_load_options o;
    rt_load_options_init(&o);
    o.look_from_given = o.look_at_given = o.up_given = o.fov_given = 1;
    o.look_from = look->look_from;
    o.look_at = look->look_at;
    o.up = look->up;
    o.fov = look->fov;
    return o;
}

static rt_image render(const rt_scene *scene, const rt_camera *camera,
                       rt_accel accel, rt_kernel_choice kernel,
                       rt_precision precision, int threads)
{
    rt_render_options o;
    rt_render_options_init(&o);
    o.camera = camera;
    o.accel = accel;
    o.kernel = kernel;
    o.precision = precision;
    o.threads = threads;
    o.max_depth = 3;
    o.width = 96;
    o.height = 72;
    rt_image image;
    rt_error error;
    ck_assert(rt_image_init(&image, 96, 72, NULL) == RT_OK);
    rt_status status = rt_render(scene, &o, &image, &error);
    ck_assert_msg(status == RT_OK, "rt_render: %s", error.message);
    return image;
}

static const char *const looked_at[] = {
    "scenes/cubes.scn", "scenes/mirror.scn", "scenes/glass.scn",
    "scenes/focus.scn", "scenes/nff-sphere.nff", "scenes/teapot.scn"};

START_TEST(the_look_is_the_loaders_camera_and_renders_its_bytes)
{
    const char *path = looked_at[_i];
    rt_scene *scene = load(path, NULL);
    rt_look look = moved_look(scene);
    rt_camera camera;
    rt_vec3 b;
    rt_error error;
    ck_assert_msg(rt_scene_look(scene, &look, &camera, &b, &error) == RT_OK,
                  "%s", error.message);
    rt_load_options lo = options_of(&look);
    rt_scene *reloaded = load(path, &lo);
    rt_camera expected = camera_of(reloaded);
    ck_assert_msg(same_camera(&camera, &expected),
                  "%s: the look's camera is not the loader's", path);
    ck_assert(!same_camera(&camera, &(rt_camera){0}));

    static const rt_accel accels[] = {RT_ACCEL_NONE, RT_ACCEL_OCTREE,
                                      RT_ACCEL_KDTREE};
    for (int a = 0; a < 3; a++)
        for (int k = 0; k < 2; k++)
            for (int p = 0; p < 2; p++) {
                rt_kernel_choice kernel =
                    k ? RT_KERNEL_SCALAR : RT_KERNEL_AUTO;
                rt_precision precision =
                    p ? RT_PRECISION_FLOAT : RT_PRECISION_DOUBLE;
                rt_image moved = render(scene, &camera, accels[a], kernel,
                                        precision, 2);
                rt_image loaded = render(reloaded, NULL, accels[a], kernel,
                                         precision, 2);
                ck_assert_msg(rt_test_image_diff(&moved, &loaded, NULL) == 0,
                              "%s: accel %d kernel %d precision %d: the "
                              "moved camera's render differs from the "
                              "loaded one's", path, a, k, p);
                rt_image_release(&moved);
                rt_image_release(&loaded);
            }
    /* The scene's own camera, passed in, is the scene's render. */
    rt_camera own = camera_of(scene);
    rt_image given = render(scene, &own, RT_ACCEL_AUTO, RT_KERNEL_AUTO,
                            RT_PRECISION_DOUBLE, 1);
    rt_image plain = render(scene, NULL, RT_ACCEL_AUTO, RT_KERNEL_AUTO,
                            RT_PRECISION_DOUBLE, 1);
    ck_assert(rt_test_image_diff(&given, &plain, NULL) == 0);
    rt_image_release(&given);
    rt_image_release(&plain);
    rt_scene_destroy(reloaded);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(the_scn_lines_of_a_look_read_back_as_its_camera)
{
    rt_scene *scene = load("scenes/focus.scn", NULL);
    rt_look look = moved_look(scene);
    rt_camera camera;
    rt_vec3 b;
    ck_assert(rt_scene_look(scene, &look, &camera, &b, NULL) == RT_OK);
    /* focus.scn sets a lens: its aperture and focus stay the file's. */
    rt_camera own = camera_of(scene);
    ck_assert(camera.aperture > 0 && camera.aperture == own.aperture);
    ck_assert(camera.focal_distance == own.focal_distance);
    rt_test_text text = {0};
    rt_test_text_add(&text,
                     "%.17g, %.17g, %.17g\n%.17g, %.17g, %.17g, %.17g, "
                     "%.17g, %.17g, %d, %d, %.17g, %.17g\n",
                     camera.observer.x, camera.observer.y,
                     camera.observer.z, camera.screen_center.x,
                     camera.screen_center.y, camera.screen_center.z, b.x,
                     b.y, b.z, camera.width, camera.height, camera.aperture,
                     camera.focal_distance);
    rt_test_text_add(&text, "3\n0, 0, 0\n1, 0, 0\n0, 1, 0\n1\n"
                            "1, 2, 3, 0, 200, 200, 200\n5, 5, 5\n"
                            "0, 0, 9, 255, 255, 255\n");
    rt_scene *read = rt_test_scene_from_string(text.data);
    rt_camera back = camera_of(read);
    ck_assert_msg(same_camera(&camera, &back),
                  "the .scn lines do not give the look's camera");
    free(text.data);
    rt_scene_destroy(read);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(bad_looks_and_cameras_are_refused)
{
    rt_scene *scene = load("scenes/cubes.scn", NULL);
    rt_camera c = camera_of(scene), before = c;
    rt_look look;
    rt_camera_get_look(&c, &look);
    rt_error error;
    rt_look bad = look;
    bad.fov = 180;
    ck_assert(rt_scene_look(scene, &bad, &c, NULL, &error) ==
              RT_ERR_ARGUMENT);
    ck_assert(strstr(error.message, "field of view") != NULL);
    bad = look;
    bad.look_at = bad.look_from;
    ck_assert(rt_scene_look(scene, &bad, &c, NULL, &error) ==
              RT_ERR_ARGUMENT);
    bad = look;
    bad.up = (rt_vec3){bad.look_at.x - bad.look_from.x,
                       bad.look_at.y - bad.look_from.y,
                       bad.look_at.z - bad.look_from.z};
    ck_assert(rt_scene_look(scene, &bad, &c, NULL, &error) ==
              RT_ERR_ARGUMENT);
    bad = look;
    bad.look_from.x = NAN;
    ck_assert(rt_scene_look(scene, &bad, &c, NULL, &error) ==
              RT_ERR_ARGUMENT);
    ck_assert(same_camera(&c, &before));

    rt_camera broken = before;
    broken.right = (rt_vec3){0, 0, 0};
    rt_render_options o;
    rt_render_options_init(&o);
    o.camera = &broken;
    rt_image image;
    ck_assert(rt_image_init(&image, before.width, before.height, NULL) ==
              RT_OK);
    ck_assert(rt_render(scene, &o, &image, &error) == RT_ERR_ARGUMENT);
    ck_assert(strstr(error.message, "camera") != NULL);
    broken = before;
    broken.observer.y = INFINITY;
    ck_assert(rt_render(scene, &o, &image, &error) == RT_ERR_ARGUMENT);
    /* Its width and height are the default image size. */
    rt_camera small = before;
    small.width = 20;
    small.height = 10;
    o.camera = &small;
    int w, h;
    ck_assert(rt_render_image_size(scene, &o, &w, &h, NULL) == RT_OK);
    ck_assert_int_eq(w, 20);
    ck_assert_int_eq(h, 10);
    rt_image_release(&image);
    rt_scene_destroy(scene);
}
END_TEST

/* ---- the debug views as renders --------------------------------------- */

typedef struct rows_seen {
    int count;
    int cancel_after;       /* 0: never */
} rows_seen;

static int count_row(void *user, int row)
{
    (void)row;
    rows_seen *seen = user;
    seen->count++;
    return seen->cancel_after == 0 || seen->count < seen->cancel_after;
}

static rt_status view(const rt_scene *scene, const rt_camera *camera,
                      rt_debug_view v, int threads, rows_seen *seen,
                      rt_render_stats *stats, rt_image *image)
{
    rt_render_options o;
    rt_render_options_init(&o);
    o.camera = camera;
    o.threads = threads;
    o.width = 80;
    o.height = 60;
    o.on_row = seen ? count_row : NULL;
    o.user = seen;
    o.stats = stats;
    ck_assert(rt_image_init(image, 80, 60, NULL) == RT_OK);
    return rt_render_view(scene, &o, v, 0, image, NULL);
}

START_TEST(a_view_is_the_same_on_any_threads_and_reports_its_rows)
{
    rt_scene *scene = load("scenes/mirror.scn", NULL);
    rt_look look = moved_look(scene);
    rt_camera camera;
    ck_assert(rt_scene_look(scene, &look, &camera, NULL, NULL) == RT_OK);
    for (int v = RT_VIEW_NORMAL; v <= RT_VIEW_SHADING_NORMAL; v++) {
        rt_image one, two;
        rows_seen seen = {0, 0};
        rt_render_stats stats = {.size = sizeof stats};
        ck_assert(view(scene, &camera, (rt_debug_view)v, 1, NULL, NULL,
                       &one) == RT_OK);
        ck_assert(view(scene, &camera, (rt_debug_view)v, 2, &seen, &stats,
                       &two) == RT_OK);
        ck_assert_msg(rt_test_image_diff(&one, &two, NULL) == 0,
                      "view %d differs on 2 threads", v);
        ck_assert_int_eq(seen.count, 60);
        ck_assert_msg(stats.camera_rays == 80 * 60,
                      "view %d: %llu camera rays", v,
                      (unsigned long long)stats.camera_rays);
        ck_assert(stats.shadow_rays > 0);
        if (v != RT_VIEW_BOUNCES)
            ck_assert_msg(stats.reflection_rays == 0,
                          "view %d traced reflections", v);
        else
            ck_assert(stats.reflection_rays > 0);
        /* The moved camera's view is the reloaded scene's. */
        rt_load_options lo = options_of(&look);
        rt_scene *reloaded = load("scenes/mirror.scn", &lo);
        rt_image loaded;
        ck_assert(view(reloaded, NULL, (rt_debug_view)v, 1, NULL, NULL,
                       &loaded) == RT_OK);
        ck_assert(rt_test_image_diff(&one, &loaded, NULL) == 0);
        rt_image_release(&loaded);
        rt_scene_destroy(reloaded);
        rt_image_release(&one);
        rt_image_release(&two);
    }
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(a_view_is_cancelled_by_its_row_callback)
{
    rt_scene *scene = load("scenes/cubes.scn", NULL);
    rt_image image;
    rows_seen seen = {0, 5};
    ck_assert(view(scene, NULL, RT_VIEW_NORMAL, 1, &seen, NULL, &image) ==
              RT_ERR_CANCELLED);
    ck_assert_int_eq(seen.count, 5);
    rt_image_release(&image);
    /* The depth view reports its rows once its greys are known. */
    seen = (rows_seen){0, 3};
    ck_assert(view(scene, NULL, RT_VIEW_DEPTH, 2, &seen, NULL, &image) ==
              RT_ERR_CANCELLED);
    ck_assert_int_eq(seen.count, 3);
    rt_image_release(&image);
    seen = (rows_seen){0, 0};
    ck_assert(view(scene, NULL, RT_VIEW_DEPTH, 2, &seen, NULL, &image) ==
              RT_OK);
    ck_assert_int_eq(seen.count, 60);
    rt_image_release(&image);
    rt_scene_destroy(scene);
}
END_TEST

static Suite *look_suite(void)
{
    Suite *suite = suite_create("look");
    TCase *tc = tcase_create("look");
    tcase_set_timeout(tc, 120);
    tcase_add_loop_test(tc,
                        the_look_is_the_loaders_camera_and_renders_its_bytes,
                        0,
                        /* under valgrind (.ci/memcheck): two scenes; under
                         * AddressSanitizer (a Debug build) the four small
                         * ones: the NFF sphere's 53,360 facets by brute
                         * force outran the timeout there */
                        rt_test_memcheck()   ? 2
                        : RT_TEST_UNDER_ASAN ? 4
                                             : (int)(sizeof looked_at /
                                                     sizeof looked_at[0]));
    tcase_add_test(tc, the_scn_lines_of_a_look_read_back_as_its_camera);
    tcase_add_test(tc, bad_looks_and_cameras_are_refused);
    tcase_add_test(tc, a_view_is_the_same_on_any_threads_and_reports_its_rows);
    tcase_add_test(tc, a_view_is_cancelled_by_its_row_callback);
    suite_add_tcase(suite, tc);
    return suite;
}

RT_CHECK_MAIN(look_suite)
