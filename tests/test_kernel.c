/*
 * test_kernel.c - the fast kernel (facet blocks tested with AVX2) against
 * the plain scalar loops: the same image, byte for byte, in both
 * precisions and for any thread count, on the project's scenes, on the SPD
 * scenes (small images), and the same colour and the same rays for many
 * single rays - random ones, rays through shared edges and vertices, and
 * rays whose edge functions are exactly zero (the exact-sign fallback).
 * Also: the exact skips of the scene analysis, counted.
 *
 * On a processor without AVX2 both choices run the scalar loops and these
 * tests still pass (they then check nothing about the fast loops).
 */
#include <glob.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "bench_scenes.h"
#include "kernel/kernel.h"
#include "scene/scene_internal.h"
#include "testutil.h"

/* The size to render at; 0: the scene's. */
typedef struct image_size {
    int width, height;
} image_size;

static const image_size full_size = {0, 0};

static rt_image render(const rt_scene *scene, const image_size *size,
                       rt_precision precision,
                       rt_kernel_choice kernel, int threads,
                       rt_render_stats *stats)
{
    rt_render_options options;
    rt_render_options_init(&options);
    options.width = size->width;
    options.height = size->height;
    options.precision = precision;
    options.kernel = kernel;
    options.threads = threads;
    options.stats = stats;
    return rt_test_render_with(scene, &options);
}

/* Scalar on one thread is the reference; the fast kernel on 1 and 2
 * threads must give the same bytes, and cast the same rays. */
static void check_scene(const rt_scene *scene, image_size size,
                        const char *name)
{
    for (int p = 0; p < 2; p++) {
        rt_precision precision = p ? RT_PRECISION_FLOAT : RT_PRECISION_DOUBLE;
        rt_render_stats s_ref = {.size = sizeof s_ref};
        rt_render_stats s_fast = {.size = sizeof s_fast};
        rt_image ref = render(scene, &size, precision, RT_KERNEL_SCALAR, 1,
                              &s_ref);
        rt_image fast1 = render(scene, &size, precision, RT_KERNEL_AUTO, 1,
                                &s_fast);
        rt_image fast2 = render(scene, &size, precision, RT_KERNEL_AUTO, 2,
                                NULL);
        ck_assert_msg(rt_test_image_diff(&ref, &fast1, NULL) == 0,
                      "%s (%s): the fast kernel changed the image", name,
                      p ? "float" : "double");
        ck_assert_msg(rt_test_image_diff(&ref, &fast2, NULL) == 0,
                      "%s (%s): 2 threads changed the image", name,
                      p ? "float" : "double");
        ck_assert_uint_eq(s_ref.shadow_rays, s_fast.shadow_rays);
        ck_assert_uint_eq(s_ref.reflection_rays, s_fast.reflection_rays);
        rt_image_release(&ref);
        rt_image_release(&fast1);
        rt_image_release(&fast2);
    }
}

START_TEST(project_scenes_render_identically_with_both_kernels)
{
    glob_t g;
    char pattern[4096];
    snprintf(pattern, sizeof pattern, "%s/scenes/*.scn", RT_SOURCE_DIR);
    ck_assert_int_eq(glob(pattern, 0, NULL, &g), 0);
    ck_assert_uint_gt(g.gl_pathc, 0);
    for (size_t i = 0; i < g.gl_pathc; i++) {
        rt_scene *scene;
        rt_error error;
        ck_assert_msg(rt_scene_load(g.gl_pathv[i], NULL, &scene, &error) ==
                          RT_OK,
                      "%s", error.message);
        check_scene(scene, (image_size){0, 0}, g.gl_pathv[i]);
        rt_scene_destroy(scene);
    }
    globfree(&g);
}
END_TEST

START_TEST(spd_scenes_render_identically_with_both_kernels)
{
    const char *dir = rt_test_shared_path("spd-scenes");
    ck_assert_ptr_nonnull(dir);
    glob_t g;
    char pattern[4096];
    snprintf(pattern, sizeof pattern, "%s/*.scn", dir);
    ck_assert_msg(glob(pattern, 0, NULL, &g) == 0, "no scene in %s", dir);
    for (size_t i = 0; i < g.gl_pathc; i++) {
        rt_scene *scene;
        rt_error error;
        ck_assert_msg(rt_scene_load(g.gl_pathv[i], NULL, &scene, &error) ==
                          RT_OK,
                      "%s", error.message);
        /* 48 x 48 keeps the scalar renders of 10,000 facets short (and
         * 8 x 8 under valgrind) */
        int side = rt_test_memcheck() ? 8 : 48;
        check_scene(scene, (image_size){side, side}, g.gl_pathv[i]);
        rt_scene_destroy(scene);
    }
    globfree(&g);
}
END_TEST

START_TEST(generated_meshes_render_identically_with_both_kernels)
{
    rt_scene *scene;
    rt_error error;
    int side = rt_test_memcheck() ? 16 : 64;
    ck_assert_int_eq(bench_sphere(2000, side, side, &scene, &error), RT_OK);
    check_scene(scene, (image_size){0, 0}, "sphere");
    rt_scene_destroy(scene);
    ck_assert_int_eq(bench_soup(2001, side, side, &scene, &error), RT_OK);
    check_scene(scene, (image_size){0, 0}, "soup");
    rt_scene_destroy(scene);
}
END_TEST

/* --- single rays, through the internal kernels ---------------------- */

/* The generator of the grids and rays (support/rng.h). */
static rt_test_rng rng = {0x9e3779b97f4a7c15u};

static double uniform(double lo, double hi)
{
    return rt_test_rng_range(&rng, lo, hi);
}

/* An n x n grid of squares (two facets each) in the plane z = 0, the
 * vertices at integer coordinates - shared edges everywhere, many of them
 * parallel to the axes - or jittered when `jitter` is set.  Every third
 * facet reflects. */
static rt_scene *grid_scene(int n, int jitter)
{
    int nv = (n + 1) * (n + 1);
    rt_vec3 *v = malloc((size_t)nv * sizeof *v);
    rt_facet_desc *f = malloc((size_t)(2 * n * n) * sizeof *f);
    ck_assert_ptr_nonnull(v);
    ck_assert_ptr_nonnull(f);
    for (int y = 0; y <= n; y++)
        for (int x = 0; x <= n; x++)
            v[y * (n + 1) + x] =
                (rt_vec3){x + (jitter ? uniform(-0.3, 0.3) : 0.0),
                          y + (jitter ? uniform(-0.3, 0.3) : 0.0),
                          jitter ? uniform(-0.5, 0.5) : 0.0};
    int m = 0;
    for (int y = 0; y < n; y++)
        for (int x = 0; x < n; x++) {
            int a = y * (n + 1) + x, b = a + 1, c = a + n + 1, d = c + 1;
            rt_rgb8 color = {(unsigned char)(50 + 7 * x),
                             (unsigned char)(50 + 11 * y), 120};
            f[m] = (rt_facet_desc){{a, b, d}, m % 3 == 0 ? 0.5 : 0.0, color};
            m++;
            f[m] = (rt_facet_desc){{a, d, c}, m % 3 == 0 ? 0.5 : 0.0, color};
            m++;
        }
    rt_scene_desc desc = {
        .observer = {n / 2.0, -n / 2.0, n / 2.0},
        .screen_center = {n / 2.0, -n / 2.0 + 1.0, n / 2.0 - 0.5},
        .screen_right = {n / 2.0 + 1.0, -n / 2.0 + 1.0, n / 2.0 - 0.5},
        .width = 8, .height = 8,
        .vertices = v, .vertex_count = nv, .facets = f, .facet_count = m,
        .background = {10, 20, 30},
        .lights = &(rt_light){{n / 3.0, n / 4.0, n}, {255, 255, 255}},
        .light_count = 1};
    rt_scene *scene;
    rt_error error;
    ck_assert_int_eq(rt_scene_create(&desc, &scene, &error), RT_OK);
    free(v);
    free(f);
    return scene;
}

/* The same colour, bit for bit, and the same rays, from the scalar loops
 * and the fast ones (with and without the eye at the ray's origin). */
static void check_ray(const rt_scene *scene, const rt_kernel *kf,
                      rt_vec3 origin, rt_vec3 target)
{
    rt_vec3 direction = {target.x - origin.x, target.y - origin.y,
                         target.z - origin.z};
    if (direction.x == 0 && direction.y == 0 && direction.z == 0)
        return;
    rt_trace_settings scalar = {5, 0, RT_KERNEL_SCALAR, NULL};
    rt_trace_settings fast = {5, 0, RT_KERNEL_AUTO, NULL};
    rt_counters c1 = {0}, c2 = {0}, c3 = {0};

    rt_color expected = rt__kernel_trace(scene->kernel, origin, direction,
                                           &scalar, &c1);
    rt_color got = rt__kernel_trace(scene->kernel, origin, direction,
                                      &fast, &c2);
    rt_kernel_eye *eye_d = rt__kernel_eye_create(scene->kernel, origin);
    ck_assert_ptr_nonnull(eye_d);
    fast.eye = eye_d;
    rt_color from_eye = rt__kernel_trace(scene->kernel, origin, direction,
                                           &fast, &c3);
    rt__kernel_eye_destroy(scene->kernel, eye_d);
    ck_assert_msg(memcmp(&expected, &got, sizeof got) == 0 &&
                      memcmp(&expected, &from_eye, sizeof got) == 0,
                  "double: (%.17g %.17g %.17g) -> (%.17g %.17g %.17g): "
                  "colours differ",
                  origin.x, origin.y, origin.z, target.x, target.y, target.z);
    ck_assert_uint_eq(c1.shadow_rays, c2.shadow_rays);
    ck_assert_uint_eq(c1.reflection_rays, c3.reflection_rays);

    fast.eye = NULL;
    expected = rt__kernel_trace(kf, origin, direction, &scalar, &c1);
    got = rt__kernel_trace(kf, origin, direction, &fast, &c2);
    rt_kernel_eye *eye_f = rt__kernel_eye_create(kf, origin);
    ck_assert_ptr_nonnull(eye_f);
    fast.eye = eye_f;
    from_eye = rt__kernel_trace(kf, origin, direction, &fast, &c3);
    rt__kernel_eye_destroy(kf, eye_f);
    ck_assert_msg(memcmp(&expected, &got, sizeof got) == 0 &&
                      memcmp(&expected, &from_eye, sizeof got) == 0,
                  "float: (%.9g %.9g %.9g) -> (%.9g %.9g %.9g): "
                  "colours differ",
                  origin.x, origin.y, origin.z, target.x, target.y, target.z);
}

static void check_rays_on_grid(int jitter)
{
    const int n = 12;
    rt_scene *scene = grid_scene(n, jitter);
    rt_kernel_source source;
    rt__scene_kernel_source(scene, &source);
    rt_kernel *kf = rt__kernel_float_ops.create(&source);
    ck_assert_ptr_nonnull(kf);
    for (int i = 0; i < (rt_test_memcheck() ? 200 : 4000); i++) {
        rt_vec3 origin = {uniform(-2, n + 2), uniform(-2, n + 2),
                          uniform(0.5, n)};
        if (i % 4 == 0)         /* from below, too */
            origin.z = -origin.z;
        /* a vertex, a point of a shared edge, or anywhere */
        int x = (int)uniform(0, n), y = (int)uniform(0, n);
        rt_vec3 p = rt_scene_vertex(scene, y * (n + 1) + x);
        rt_vec3 q = rt_scene_vertex(scene, (y + 1) * (n + 1) + x + 1);
        double t = uniform(0, 1);
        rt_vec3 target;
        switch (i % 3) {
        case 0:
            target = p;
            break;
        case 1:         /* on the diagonal shared by a square's facets */
            target = (rt_vec3){p.x + t * (q.x - p.x), p.y + t * (q.y - p.y),
                               p.z + t * (q.z - p.z)};
            break;
        default:
            target = (rt_vec3){uniform(0, n), uniform(0, n), 0.0};
        }
        check_ray(scene, kf, origin, target);
    }
    /* Axis-parallel rays through the grid's vertices and edges: edge
     * functions exactly 0, decided by the exact-sign fallback. */
    if (!jitter) {
        for (int y = 0; y <= n; y++)
            for (int x = 0; x <= n; x++) {
                check_ray(scene, kf, (rt_vec3){x, y, 3.0},
                          (rt_vec3){x, y, 0.0});
                check_ray(scene, kf, (rt_vec3){x + 0.5, y, -3.0},
                          (rt_vec3){x + 0.5, y, 0.0});
                check_ray(scene, kf, (rt_vec3){x, y + 0.25, 2.0},
                          (rt_vec3){x, y + 0.25, 1.0});
            }
    }
    rt__kernel_destroy(kf);
    rt_scene_destroy(scene);
}

START_TEST(rays_through_shared_edges_see_the_same_with_both_kernels)
{
    check_rays_on_grid(0);
}
END_TEST

START_TEST(rays_through_a_jittered_mesh_see_the_same_with_both_kernels)
{
    check_rays_on_grid(1);
}
END_TEST

START_TEST(random_rays_in_a_soup_see_the_same_with_both_kernels)
{
    rt_scene *scene;
    rt_error error;
    ck_assert_int_eq(bench_soup(300, 8, 8, &scene, &error), RT_OK);
    rt_kernel_source source;
    rt__scene_kernel_source(scene, &source);
    rt_kernel *kf = rt__kernel_float_ops.create(&source);
    ck_assert_ptr_nonnull(kf);
    for (int i = 0; i < (rt_test_memcheck() ? 200 : 5000); i++) {
        rt_vec3 origin = {uniform(-3, 3), uniform(-3, 3), uniform(-3, 3)};
        rt_facet_info f = {.size = sizeof f};
        rt_scene_facet(scene, (int)uniform(0, 300), &f);
        /* aim at a vertex of a facet: rays along shared vertices' lines */
        rt_vec3 target = rt_scene_vertex(scene, f.vertex[i % 3]);
        if (i % 2)
            target = (rt_vec3){uniform(-1, 1), uniform(-1, 1),
                               uniform(-1, 1)};
        check_ray(scene, kf, origin, target);
    }
    rt__kernel_destroy(kf);
    rt_scene_destroy(scene);
}
END_TEST

/* --- the exact skips, counted --------------------------------------- */

START_TEST(a_scene_without_reflective_facets_casts_no_reflection_ray)
{
    rt_scene *scene;
    rt_error error;
    ck_assert_int_eq(bench_sphere(500, 32, 32, &scene, &error), RT_OK);
    rt_render_stats stats = {.size = sizeof stats};
    rt_image image = render(scene, &full_size, RT_PRECISION_DOUBLE,
                            RT_KERNEL_AUTO, 1,
                            &stats);
    ck_assert_uint_eq(stats.reflection_rays, 0);
    ck_assert_uint_gt(stats.reflection_rays_skipped, 0);
    ck_assert_uint_gt(stats.ray_facet_tests_skipped, 0);
    rt_image_release(&image);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(the_cubes_scene_casts_fewer_shadow_rays_than_it_has_hits)
{
    rt_scene *scene;
    rt_error error;
    ck_assert_int_eq(rt_scene_load(rt_test_source_path("scenes/cubes.scn"),
                                   NULL, &scene, &error),
                     RT_OK);
    rt_render_stats stats = {.size = sizeof stats};
    rt_image image = render(scene, &full_size, RT_PRECISION_DOUBLE,
                            RT_KERNEL_AUTO, 0,
                            &stats);
    /* every hit either casts its shadow ray or skips it */
    uint64_t hits = stats.shadow_rays + stats.shadow_rays_skipped;
    ck_assert_uint_gt(stats.shadow_rays_skipped, 0);
    ck_assert_uint_lt(stats.shadow_rays, hits);
    ck_assert_uint_eq(stats.camera_rays, 400u * 400u);
    rt_image_release(&image);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(an_unknown_kernel_choice_is_an_argument_error)
{
    rt_scene *scene = rt_test_scene_from_string(
        "0 0 5\n0 0 4 1 0 4 2 2\n0\n0\n0 0 0\n0 0 10 255 255 255\n");
    rt_image image;
    ck_assert_int_eq(rt_image_init(&image, 2, 2, NULL), RT_OK);
    rt_render_options options;
    rt_render_options_init(&options);
    ck_assert_int_eq(options.kernel, RT_KERNEL_AUTO);
    options.kernel = (rt_kernel_choice)7;
    ck_assert_int_eq(rt_render(scene, &options, &image, NULL),
                     RT_ERR_ARGUMENT);
    rt_image_release(&image);
    rt_scene_destroy(scene);
}
END_TEST

static Suite *kernel_suite(void)
{
    Suite *s = suite_create("kernel");
    TCase *images = tcase_create("images");
    tcase_set_timeout(images, 300);
    tcase_add_test(images, project_scenes_render_identically_with_both_kernels);
    tcase_add_test(images,
                   generated_meshes_render_identically_with_both_kernels);
    suite_add_tcase(s, images);
    TCase *rays = tcase_create("rays");
    tcase_set_timeout(rays, 120);
    tcase_add_test(rays, rays_through_shared_edges_see_the_same_with_both_kernels);
    tcase_add_test(rays,
                   rays_through_a_jittered_mesh_see_the_same_with_both_kernels);
    tcase_add_test(rays, random_rays_in_a_soup_see_the_same_with_both_kernels);
    suite_add_tcase(s, rays);
    TCase *skips = tcase_create("skips");
    tcase_set_timeout(skips, 60);
    tcase_add_test(skips,
                   a_scene_without_reflective_facets_casts_no_reflection_ray);
    tcase_add_test(skips,
                   the_cubes_scene_casts_fewer_shadow_rays_than_it_has_hits);
    tcase_add_test(skips, an_unknown_kernel_choice_is_an_argument_error);
    suite_add_tcase(s, skips);
    return s;
}

/* The course's SPD scenes: their own ctest entry, skipped when absent. */
static Suite *kernel_shared_suite(void)
{
    Suite *s = suite_create("kernel-shared");
    TCase *images = tcase_create("shared");
    tcase_set_timeout(images, 300);
    tcase_add_test(images, spd_scenes_render_identically_with_both_kernels);
    suite_add_tcase(s, images);
    return s;
}

RT_CHECK_MAIN_WITH_SHARED(kernel_suite, kernel_shared_suite)
