/*
 * test_camera.c - the camera of docs/rendering-model.md: B projected onto the
 * screen plane when AB is not perpendicular to AO, the right-handed frame
 * (AB, AC, AO) with |AC| = |AB|, and the primary rays of rt_camera_ray
 * against the pixel-centre formula computed here by hand, for square and
 * non-square images.
 */
#include "testutil.h"

#include <math.h>
#include <stdio.h>

/* Local vector arithmetic, independent of the library's. */
static rt_vec3 add(rt_vec3 a, rt_vec3 b)
{
    return (rt_vec3){a.x + b.x, a.y + b.y, a.z + b.z};
}
static rt_vec3 sub(rt_vec3 a, rt_vec3 b)
{
    return (rt_vec3){a.x - b.x, a.y - b.y, a.z - b.z};
}
static rt_vec3 scale(rt_vec3 a, double s)
{
    return (rt_vec3){a.x * s, a.y * s, a.z * s};
}
static double dot(rt_vec3 a, rt_vec3 b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
static rt_vec3 cross(rt_vec3 a, rt_vec3 b)
{
    return (rt_vec3){a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z,
                     a.x * b.y - a.y * b.x};
}
static double length(rt_vec3 a)
{
    return sqrt(dot(a, a));
}

/* |a - b| <= tol, with a readable message. */
static void assert_near(rt_vec3 a, rt_vec3 b, double tol, const char *what)
{
    double d = length(sub(a, b));
    ck_assert_msg(d <= tol,
                  "%s: (%.17g, %.17g, %.17g) != (%.17g, %.17g, %.17g), "
                  "distance %g > %g",
                  what, a.x, a.y, a.z, b.x, b.y, b.z, d, tol);
}

static rt_scene *camera_scene(rt_vec3 o, rt_vec3 a, rt_vec3 b, int w, int h)
{
    char text[512];
    snprintf(text, sizeof text,
             "%.17g %.17g %.17g\n%.17g %.17g %.17g %.17g %.17g %.17g %d %d\n"
             "0\n0\n0 0 0\n0 0 0 255 255 255\n",
             o.x, o.y, o.z, a.x, a.y, a.z, b.x, b.y, b.z, w, h);
    return rt_test_scene_from_string(text);
}

START_TEST(camera_keeps_perpendicular_b_and_builds_up_vector)
{
    rt_scene *scene = camera_scene((rt_vec3){0, 0, 5}, (rt_vec3){0, 0, 4},
                                   (rt_vec3){1, 0, 4}, 3, 3);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    rt_camera cam = info.camera;
    ck_assert_int_eq(cam.b_was_projected, 0);
    ck_assert_int_eq(cam.width, 3);
    ck_assert_int_eq(cam.height, 3);
    assert_near(cam.observer, (rt_vec3){0, 0, 5}, 0.0, "observer");
    assert_near(cam.screen_center, (rt_vec3){0, 0, 4}, 0.0, "A");
    assert_near(cam.right, (rt_vec3){1, 0, 0}, 0.0, "AB");
    /* AC = AO x AB = (0,0,1) x (1,0,0) = (0,1,0), tolerance 1e-15 */
    assert_near(cam.up, (rt_vec3){0, 1, 0}, 1e-15, "AC");
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(camera_projects_b_when_ab_is_not_perpendicular_to_ao)
{
    /* the handout's cubes scene */
    rt_vec3 o = {8, -8, -3}, a = {3, -3, -1}, b = {3, -9, 0};
    rt_scene *scene = camera_scene(o, a, b, 400, 400);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    rt_camera cam = info.camera;
    ck_assert_int_ne(cam.b_was_projected, 0);

    /* by hand: AO = (5,-5,-2), |AO|^2 = 54, AB = (0,-6,1), AB.AO = 28,
     * AB' = AB - (28/54) AO */
    rt_vec3 ao = sub(o, a);
    rt_vec3 expected_right = sub(sub(b, a), scale(ao, 28.0 / 54.0));
    assert_near(cam.right, expected_right, 1e-13, "projected AB");
    double ab = length(cam.right);
    /* the frame, tolerances relative to |AB| |AO| ~ 30 */
    ck_assert_double_eq_tol(dot(cam.right, ao), 0.0, 1e-12);
    ck_assert_double_eq_tol(length(cam.up), ab, 1e-13);
    ck_assert_double_eq_tol(dot(cam.up, ao), 0.0, 1e-12);
    ck_assert_double_eq_tol(dot(cam.up, cam.right), 0.0, 1e-12);
    ck_assert(dot(cross(cam.right, cam.up), ao) > 0); /* right-handed */
    rt_vec3 expected_up = cross(ao, expected_right);
    expected_up = scale(expected_up, ab / length(expected_up));
    assert_near(cam.up, expected_up, 1e-13, "AC");
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(camera_frame_is_right_handed_for_a_tilted_screen)
{
    /* AO = (-3,-4,0), AB = (2,-1.5,0) perpendicular, |AB| = 2.5;
     * AO x AB = (0,0,12.5) so AC = (0,0,2.5) */
    rt_scene *scene = camera_scene((rt_vec3){1, 2, 3}, (rt_vec3){4, 6, 3},
                                   (rt_vec3){6, 4.5, 3}, 5, 3);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    ck_assert_int_eq(info.camera.b_was_projected, 0);
    assert_near(info.camera.right, (rt_vec3){2, -1.5, 0}, 1e-15, "AB");
    assert_near(info.camera.up, (rt_vec3){0, 0, 2.5}, 1e-15, "AC");
    rt_scene_destroy(scene);
}
END_TEST

/* The screen point of docs/rendering-model.md ("The camera"), computed
 * here. */
static rt_vec3 pixel_point(const rt_camera *cam, int i, int j)
{
    double w = cam->width, h = cam->height;
    double s = 2.0 * (i + 0.5) / w - 1.0;
    double t = (1.0 - 2.0 * (j + 0.5) / h) * (h / w);
    return add(add(cam->screen_center, scale(cam->right, s)),
               scale(cam->up, t));
}

/* The ray starts at O and goes through P (the direction may have any
 * positive length): its point on the screen plane is P. */
static void check_pixel_ray(const rt_camera *cam, int i, int j)
{
    char what[64];
    snprintf(what, sizeof what, "pixel (%d, %d)", i, j);
    rt_ray ray = rt_camera_ray(cam, i, j);
    assert_near(ray.origin, cam->observer, 0.0, what);
    rt_vec3 p = pixel_point(cam, i, j);
    rt_vec3 ao = sub(cam->observer, cam->screen_center);
    double denom = dot(ray.direction, ao);
    ck_assert_msg(denom < 0, "%s: the ray points away from the screen", what);
    double t = dot(sub(cam->screen_center, cam->observer), ao) / denom;
    ck_assert_msg(t > 0, "%s: screen behind the observer", what);
    rt_vec3 q = add(ray.origin, scale(ray.direction, t));
    double size = length(ao) + length(cam->right) + length(cam->observer);
    assert_near(q, p, 1e-13 * size, what);
}

static void check_corners_and_centre(rt_vec3 o, rt_vec3 a, rt_vec3 b, int w,
                                     int h)
{
    rt_scene *scene = camera_scene(o, a, b, w, h);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    const rt_camera *cam = &info.camera;
    check_pixel_ray(cam, 0, 0);
    check_pixel_ray(cam, w - 1, 0);
    check_pixel_ray(cam, 0, h - 1);
    check_pixel_ray(cam, w - 1, h - 1);
    check_pixel_ray(cam, w / 2, h / 2);
    if (w % 2 == 1 && h % 2 == 1) {
        /* the centre pixel looks exactly at A */
        rt_ray ray = rt_camera_ray(cam, w / 2, h / 2);
        rt_vec3 d = ray.direction, ao = sub(a, o);
        double cosine = dot(d, ao) / (length(d) * length(ao));
        ck_assert_double_eq_tol(cosine, 1.0, 1e-15);
    }
    rt_scene_destroy(scene);
}

START_TEST(camera_rays_of_corners_and_centre_follow_the_formula_square)
{
    check_corners_and_centre((rt_vec3){0, 0, 5}, (rt_vec3){0, 0, 4},
                             (rt_vec3){1, 0, 4}, 3, 3);
    check_corners_and_centre((rt_vec3){8, -8, -3}, (rt_vec3){3, -3, -1},
                             (rt_vec3){3, -9, 0}, 401, 401);
    check_corners_and_centre((rt_vec3){8, 0, 0}, (rt_vec3){3, 0, 0},
                             (rt_vec3){3, 4, 0}, 200, 200);
}
END_TEST

START_TEST(camera_rays_of_corners_and_centre_follow_the_formula_wide_and_tall)
{
    check_corners_and_centre((rt_vec3){1, 2, 3}, (rt_vec3){4, 6, 3},
                             (rt_vec3){6, 4.5, 3}, 5, 3);
    check_corners_and_centre((rt_vec3){1, 2, 3}, (rt_vec3){4, 6, 3},
                             (rt_vec3){6, 4.5, 3}, 3, 7);
    check_corners_and_centre((rt_vec3){8, -8, -3}, (rt_vec3){3, -3, -1},
                             (rt_vec3){3, -9, 0}, 640, 480);
}
END_TEST

START_TEST(camera_top_left_pixel_is_up_and_left)
{
    /* O above the screen plane z = 4, AB = +x, AC = +y: pixel (0, 0) is
     * at x = -2/3, y = +2/3 for a 3x3 image */
    rt_scene *scene = camera_scene((rt_vec3){0, 0, 5}, (rt_vec3){0, 0, 4},
                                   (rt_vec3){1, 0, 4}, 3, 3);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    rt_ray ray = rt_camera_ray(&info.camera, 0, 0);
    double t = -1.0 / ray.direction.z; /* reach z = 4 */
    ck_assert_double_eq_tol(ray.origin.x + t * ray.direction.x, -2.0 / 3.0,
                            1e-15);
    ck_assert_double_eq_tol(ray.origin.y + t * ray.direction.y, 2.0 / 3.0,
                            1e-15);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(camera_pixels_are_square_when_width_and_height_differ)
{
    /* 5 x 3 image, |AB| = 2.5: the screen is 5 wide and 3 tall, pixel
     * centres 1 apart in both directions (tolerance 1e-13) */
    rt_scene *scene = camera_scene((rt_vec3){1, 2, 3}, (rt_vec3){4, 6, 3},
                                   (rt_vec3){6, 4.5, 3}, 5, 3);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    const rt_camera *cam = &info.camera;
    rt_vec3 ao = sub(cam->observer, cam->screen_center);
    rt_vec3 points[2][2];
    for (int j = 0; j < 2; j++)
        for (int i = 0; i < 2; i++) {
            rt_ray ray = rt_camera_ray(cam, i, j);
            double t = dot(sub(cam->screen_center, cam->observer), ao) /
                       dot(ray.direction, ao);
            points[j][i] = add(ray.origin, scale(ray.direction, t));
        }
    ck_assert_double_eq_tol(length(sub(points[0][1], points[0][0])), 1.0,
                            1e-13);
    ck_assert_double_eq_tol(length(sub(points[1][0], points[0][0])), 1.0,
                            1e-13);
    /* top row is 1 pixel below the top edge: height 3 -> t = (1 - 1/3) */
    assert_near(points[0][0],
                add(add(cam->screen_center, scale(cam->right, -0.8)),
                    scale(cam->up, 0.4)),
                1e-13, "pixel (0, 0)");
    rt_scene_destroy(scene);
}
END_TEST

Suite *camera_suite(void);

Suite *camera_suite(void)
{
    Suite *suite = suite_create("camera");
    TCase *tc = tcase_create("camera");
    tcase_add_test(tc, camera_keeps_perpendicular_b_and_builds_up_vector);
    tcase_add_test(tc, camera_projects_b_when_ab_is_not_perpendicular_to_ao);
    tcase_add_test(tc, camera_frame_is_right_handed_for_a_tilted_screen);
    tcase_add_test(tc,
                   camera_rays_of_corners_and_centre_follow_the_formula_square);
    tcase_add_test(
        tc, camera_rays_of_corners_and_centre_follow_the_formula_wide_and_tall);
    tcase_add_test(tc, camera_top_left_pixel_is_up_and_left);
    tcase_add_test(tc, camera_pixels_are_square_when_width_and_height_differ);
    suite_add_tcase(suite, tc);
    return suite;
}

RT_CHECK_MAIN(camera_suite)
