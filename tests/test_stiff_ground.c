/*
 * test_stiff_ground.c - a ground far wider than the eye is high, in both
 * precisions, against images computed independently and exactly.
 *
 * tests/reference/stiff_ground.py writes each scene (a square ground of
 * half-size RATIO x 1.7, the eye 1.7 above its centre looking along it,
 * flat or turned by rational rotations) and the image the rendering model
 * gives for it, with rational arithmetic from the coordinates as the
 * render's precision holds them.  The watertight test alone lost the
 * ground from a ratio of about 3e5 in float and 6e14 in double (its bound
 * on t outgrew t); the crossing of the facet's plane (plane_crossing.c)
 * keeps it, and this suite checks every pixel, byte for byte, through
 * every kernel and accelerator: float up to 1e7 and beyond, double up to
 * 1e16 and beyond, both measured limits included (docs/accuracy.md,
 * "Facets far larger than their distance").
 *
 * Needs python3 (standard library only); without it the suite exits 77, a
 * skip CTest shows.
 */
#include <check.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "raytrace/raytrace.h"
#include "testutil.h"

typedef struct ground_case {
    const char *ratio;
    const char *orientation;    /* flat, tilted */
    rt_precision precision;
} ground_case;

static const ground_case CASES[] = {
    {"1e3", "flat", RT_PRECISION_FLOAT},
    {"1e5", "flat", RT_PRECISION_FLOAT},
    {"1e6", "flat", RT_PRECISION_FLOAT},
    {"1e7", "flat", RT_PRECISION_FLOAT},
    {"1e3", "tilted", RT_PRECISION_FLOAT},
    {"1e5", "tilted", RT_PRECISION_FLOAT},
    {"1e6", "tilted", RT_PRECISION_FLOAT},
    {"1e7", "tilted", RT_PRECISION_FLOAT},
    {"1e12", "tilted", RT_PRECISION_FLOAT},
    {"1e16", "tilted", RT_PRECISION_FLOAT},  /* float's coordinates end
                                                at 1e17 */
    {"1e6", "flat", RT_PRECISION_DOUBLE},
    {"1e12", "flat", RT_PRECISION_DOUBLE},
    {"1e14", "flat", RT_PRECISION_DOUBLE},
    {"1e16", "flat", RT_PRECISION_DOUBLE},
    {"1e6", "tilted", RT_PRECISION_DOUBLE},
    {"1e12", "tilted", RT_PRECISION_DOUBLE},
    {"1e14", "tilted", RT_PRECISION_DOUBLE},
    {"1e15", "tilted", RT_PRECISION_DOUBLE},
    {"1e16", "tilted", RT_PRECISION_DOUBLE},
    {"1e24", "tilted", RT_PRECISION_DOUBLE},
    {"1e30", "tilted", RT_PRECISION_DOUBLE},   /* the measured limit */
};
#define CASE_COUNT ((int)(sizeof CASES / sizeof CASES[0]))

static int python_found(void)
{
    return system("python3 -c 'import fractions' >/dev/null 2>&1") == 0;
}

/* Writes the case's scene and expected image into the build folder. */
static void generate(const ground_case *c, char *scene, char *expected,
                     size_t size)
{
    const char *p = c->precision == RT_PRECISION_FLOAT ? "float" : "double";
    snprintf(scene, size, "stiff-%s-%s-%s.scn", c->orientation, c->ratio, p);
    snprintf(expected, size, "stiff-%s-%s-%s.ppm", c->orientation, c->ratio,
             p);
    char command[1024];
    snprintf(command, sizeof command, "python3 '%s' %s %s %s '%s' '%s'",
             rt_test_source_path("tests/reference/stiff_ground.py"),
             c->ratio, c->orientation, p, scene, expected);
    ck_assert_msg(system(command) == 0, "failed: %s", command);
}

/* The half of the image below the horizon is ground (no pixel shows the
 * sky there), the half above is sky: what the watertight test alone
 * failed.  A check of the reference itself, so that it cannot agree with
 * a vanishing ground. */
static void assert_ground_below_the_horizon(const rt_image *expected,
                                            const char *path)
{
    for (int y = 0; y < expected->height; y++)
        for (int x = 0; x < expected->width; x++) {
            const unsigned char *p = rt_image_pixel(expected, x, y);
            int sky = p[0] == 40 && p[1] == 80 && p[2] == 200;
            int ground = p[0] == 200 && p[1] == 150 && p[2] == 100;
            ck_assert_msg(y < expected->height / 2 ? sky : ground,
                          "pixel (%d, %d) of %s", x, y, path);
        }
}

/* Every pixel of every render of the case equals the reference's. */
START_TEST(stiff_ground_renders_the_exact_image_in_every_kernel)
{
    const ground_case *c = &CASES[_i];
    char scene_path[256], expected_path[256];
    generate(c, scene_path, expected_path, sizeof scene_path);
    rt_scene *scene;
    rt_error error;
    ck_assert_msg(rt_scene_load(scene_path, NULL, &scene, &error) == RT_OK,
                  "%s", error.message);
    ck_assert_int_eq(rt_scene_check_precision(scene, c->precision, &error),
                     RT_OK);
    rt_image expected;
    ck_assert_msg(rt_ppm_load(expected_path, &expected, &error) == RT_OK,
                  "%s", error.message);
    assert_ground_below_the_horizon(&expected, expected_path);
    static const rt_kernel_choice kernels[] = {RT_KERNEL_AUTO,
                                               RT_KERNEL_SCALAR};
    static const rt_accel accels[] = {RT_ACCEL_NONE, RT_ACCEL_OCTREE};
    for (int k = 0; k < 2; k++)
        for (int a = 0; a < 2; a++) {
            rt_render_options options;
            rt_render_options_init(&options);
            options.precision = c->precision;
            options.kernel = kernels[k];
            options.accel = accels[a];
            options.threads = 1;
            rt_image image;
            ck_assert_int_eq(rt_image_init(&image, expected.width,
                                           expected.height, NULL), RT_OK);
            ck_assert_msg(rt_render(scene, &options, &image, &error) == RT_OK,
                          "%s", error.message);
            int max_diff;
            long differ = rt_test_image_diff(&image, &expected, &max_diff);
            ck_assert_msg(differ == 0,
                          "%s ground, ratio %s, %s, kernel %s, accel %s: %ld "
                          "of %d pixels differ from the exact image (%s), "
                          "by up to %d",
                          c->orientation, c->ratio,
                          c->precision == RT_PRECISION_FLOAT ? "float"
                                                             : "double",
                          k ? "scalar" : "auto", a ? "octree" : "none",
                          differ, expected.width * expected.height,
                          expected_path, max_diff);
            rt_image_release(&image);
        }
    rt_image_release(&expected);
    rt_scene_destroy(scene);
}
END_TEST

/* Beyond RT_FLOAT_MAX_COORDINATE a float render refuses the scene (its
 * edge functions would overflow: measured, a ground of half-size 1e20
 * renders as sky), and says what to do; double takes it. */
START_TEST(float_refuses_coordinates_beyond_its_products_range)
{
    const ground_case c = {"1e18", "tilted", RT_PRECISION_FLOAT};
    char scene_path[256], expected_path[256];
    generate(&c, scene_path, expected_path, sizeof scene_path);
    rt_scene *scene;
    rt_error error;
    ck_assert_msg(rt_scene_load(scene_path, NULL, &scene, &error) == RT_OK,
                  "%s", error.message);
    ck_assert_int_eq(rt_scene_check_precision(scene, RT_PRECISION_FLOAT,
                                              &error), RT_ERR_RANGE);
    ck_assert_msg(strstr(error.message, "render in double") != NULL, "%s",
                  error.message);
    ck_assert_int_eq(rt_scene_check_precision(scene, RT_PRECISION_DOUBLE,
                                              &error), RT_OK);
    rt_scene_destroy(scene);
}
END_TEST

/* Beyond the measured limit (a ratio of 1e30) the loader says which
 * facets the eye cannot be placed against - here both halves of the
 * ground at 1e32 - and says nothing at 1e30 or for a ground seen from
 * 1.7 above at ordinary ratios. */
START_TEST(the_loader_warns_beyond_the_crossing_s_limit)
{
    static const struct {
        const char *ratio;
        int warnings;
    } cases[] = {{"1e3", 0}, {"1e16", 0}, {"1e30", 0}, {"1e32", 2}};
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        const ground_case c = {cases[k].ratio, "tilted", RT_PRECISION_DOUBLE};
        char scene_path[256], expected_path[256];
        generate(&c, scene_path, expected_path, sizeof scene_path);
        rt_scene *scene;
        rt_error error;
        ck_assert_msg(rt_scene_load(scene_path, NULL, &scene, &error) == RT_OK,
                      "%s", error.message);
        ck_assert_msg(rt_test_count_warnings(scene, "plane through the eye") ==
                          cases[k].warnings,
                      "ratio %s: expected %d warnings", cases[k].ratio,
                      cases[k].warnings);
        rt_scene_destroy(scene);
    }
}
END_TEST

/* An eye exactly in a facet's plane: the facet is named (camera rays
 * never meet it), the others not. */
START_TEST(the_loader_names_a_facet_in_a_plane_through_the_eye)
{
    rt_scene *scene = rt_test_scene_from_string(
        "0,0,0\n0,1,0, 1,1,0, 16,16\n"
        "6\n-1,2,0\n1,2,0\n0,3,0\n-1,2,-1\n1,2,-1\n0,3,-1\n"
        "2\n1,2,3, 0, 255,0,0\n4,5,6, 0, 0,255,0\n"
        "0,0,0\n0,0,5, 255,255,255\n");
    ck_assert_int_eq(rt_test_count_warnings(scene, "plane through the eye"), 1);
    ck_assert_int_eq(rt_test_count_warnings(scene, "facet 1 lies in a plane"),
                     1);
    rt_scene_destroy(scene);
}
END_TEST

static Suite *stiff_ground_suite(void)
{
    Suite *s = suite_create("stiff_ground");
    TCase *c = tcase_create("ratios");
    tcase_set_timeout(c, 300);
    tcase_add_loop_test(c, stiff_ground_renders_the_exact_image_in_every_kernel,
                        0, CASE_COUNT);
    tcase_add_test(c, float_refuses_coordinates_beyond_its_products_range);
    tcase_add_test(c, the_loader_warns_beyond_the_crossing_s_limit);
    tcase_add_test(c, the_loader_names_a_facet_in_a_plane_through_the_eye);
    suite_add_tcase(s, c);
    return s;
}

int main(void)
{
    if (!python_found()) {
        fprintf(stderr, "test_stiff_ground: python3 is not installed; the "
                        "exact images cannot be computed\n");
        return RT_TEST_SKIPPED;
    }
    return rt_test_run_suite(stiff_ground_suite());
}
