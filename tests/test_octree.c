/*
 * test_octree.c - the octree against brute force: the same image, byte for
 * byte, in both precisions, on one thread and several, with 1 and 4
 * samples, on every scene the tests render - the project's scenes, the
 * handout's and the SPD scenes of ../shared (their own ctest entry, skipped
 * visibly when ../shared is absent), generated meshes and soups, and the
 * distributions an octree handles worst: everything in one spot, a few
 * facets spanning everything, slivers beside huge walls, coincident facets
 * whose tie the file order decides.  Then single rays, colour for colour,
 * through the internal kernels: random, grazing, along cell faces.  And the
 * choice itself: the option, its default, its bounds.
 *
 * The reference is brute force in the same process (the fold over every
 * facet in file order, which tests/test_kernel.c and the expected images
 * check on their own); the scenes and the checks are accel_scenes.c's,
 * which tests/test_kdtree.c runs through the kd-tree.
 */
#include <stdint.h>
#include <string.h>

#include "accel_scenes.h"
#include "bench_scenes.h"
#include "kernel/kernel.h"
#include "scene/scene_internal.h"
#include "testutil.h"

/* Under valgrind or AddressSanitizer (a Debug build, 50 times slower) the
 * comparisons run on fewer rays and smaller images: the same code paths,
 * the full counts being the normal pass's. */
static int reduced(void)
{
    return rt_test_memcheck() || RT_TEST_UNDER_ASAN;
}

/* The size to render at; 0: the scene's. */
typedef struct image_size {
    int width, height;
} image_size;

static const image_size full_size = {0, 0};

static rt_image render(const rt_scene *scene, const image_size *size,
                       rt_precision precision,
                       rt_accel accel, int threads, int samples,
                       rt_render_stats *stats)
{
    rt_render_options options;
    rt_render_options_init(&options);
    options.width = size->width;
    options.height = size->height;
    options.precision = precision;
    options.accel = accel;
    options.threads = threads;
    options.samples = samples;
    options.stats = stats;
    return rt_test_render_with(scene, &options);
}

static void check_scene(const rt_scene *scene, image_size size,
                        const char *name)
{
    accel_check_scene(scene, size.width, size.height, RT_ACCEL_OCTREE, name);
}

static size_t check_directory(const char *dir, int side)
{
    return accel_check_directory(dir, side, RT_ACCEL_OCTREE);
}

START_TEST(project_scenes_render_identically_through_the_octree)
{
    ck_assert_uint_gt(check_directory(rt_test_source_path("scenes"),
                                      reduced() ? 16 : 160),
                      0);
}
END_TEST

START_TEST(generated_meshes_render_identically_through_the_octree)
{
    rt_scene *scene;
    rt_error error;
    int side = reduced() ? 12 : 64;
    int sizes[] = {100, 2000, 20000};
    for (int i = 0; i < (reduced() ? 2 : 3); i++) {
        ck_assert_int_eq(bench_sphere(sizes[i], side, side, &scene, &error),
                         RT_OK);
        check_scene(scene, (image_size){0, 0}, "sphere");
        rt_scene_destroy(scene);
        ck_assert_int_eq(bench_soup(sizes[i] + 1, side, side, &scene,
                                    &error),
                         RT_OK);
        check_scene(scene, (image_size){0, 0}, "soup");
        rt_scene_destroy(scene);
    }
}
END_TEST

/* --- degenerate distributions ---------------------------------------- */

/* The generator of the soups and rays (support/rng.h). */
static rt_test_rng rng = {0x2545f4914f6cdd1du};

static double uniform(double lo, double hi)
{
    return rt_test_rng_range(&rng, lo, hi);
}

/* Renders the scene (destroyed after) through the octree and brute force. */
static void check_and_destroy(rt_scene *scene, const char *name)
{
    check_scene(scene, full_size, name);
    rt_scene_destroy(scene);
}

START_TEST(facets_all_in_one_spot_render_identically)
{
    check_and_destroy(accel_one_spot(&rng, reduced()), "one spot");
}
END_TEST

START_TEST(a_few_facets_spanning_everything_render_identically)
{
    check_and_destroy(accel_spanning(&rng, reduced()), "spanning");
}
END_TEST

START_TEST(slivers_beside_huge_walls_render_identically)
{
    check_and_destroy(accel_slivers_and_walls(&rng, reduced()),
                      "slivers and walls");
}
END_TEST

/* Coincident and overlapping coplanar facets in shuffled order: the tie
 * rule (the first in the file stays) must decide the same whatever leaves
 * the facets come from. */
START_TEST(coincident_facets_keep_the_tie_of_the_file_order)
{
    check_and_destroy(accel_coincident(&rng, reduced()), "coincident");
}
END_TEST

/* A mesh seen from very far (beyond the margin's reach) and one seen from
 * inside. */
START_TEST(far_and_inside_cameras_render_identically)
{
    check_and_destroy(accel_far_camera(&rng, reduced(), 0), "far camera");
    check_and_destroy(accel_far_camera(&rng, reduced(), 1), "inside");
}
END_TEST

/* Transparent facets (refraction, total internal reflection), several
 * lights and a thin lens: every query of the ray tree goes through the
 * octree too. */
START_TEST(transparency_lights_and_lens_render_identically)
{
    check_and_destroy(accel_transparency_lights_lens(&rng, reduced()),
                      "transparency, lights, lens");
}
END_TEST

/* Coordinates at the limit a scene may hold (1e152): cell boxes, margins
 * and intervals stay finite, and the image stays brute force's (double
 * only: a float render of such a scene is refused). */
START_TEST(coordinates_at_the_limit_of_a_scene_render_identically)
{
    rt_scene *scene = accel_at_the_limit(&rng, reduced());
    for (int samples = 1; samples <= 4; samples += 3) {
        rt_render_stats stats = {.size = sizeof stats};
        rt_image ref = render(scene, &full_size, RT_PRECISION_DOUBLE,
                              RT_ACCEL_NONE, 1,
                              samples, NULL);
        rt_image tree = render(scene, &full_size, RT_PRECISION_DOUBLE,
                               RT_ACCEL_OCTREE, 2,
                               samples, &stats);
        ck_assert_int_eq(rt_test_image_diff(&ref, &tree, NULL), 0);
        ck_assert_int_eq(stats.accel_used, 1);
        rt_image_release(&ref);
        rt_image_release(&tree);
    }
    rt_scene_destroy(scene);
}
END_TEST

/* --- single rays ------------------------------------------------------ */

/* The same colour, bit for bit, through the octree and brute force, in
 * both precisions. */
static const rt_trace_settings through_octree = {5, 0, RT_KERNEL_AUTO, NULL,
                                                 1, NULL, 0};

static void check_ray(const rt_kernel *kd, const rt_kernel *kf,
                      rt_vec3 origin, rt_vec3 target)
{
    accel_check_ray(kd, kf, origin, target, &through_octree);
}

START_TEST(rays_grazing_and_along_cell_faces_see_the_same_through_the_octree)
{
    const int n = 16;
    rt_scene *scene = accel_grid(n);
    const rt_kernel *kf = rt__scene_kernel(scene, RT_PRECISION_FLOAT, NULL);
    ck_assert_ptr_nonnull(kf);
    ck_assert_int_eq(rt__kernel_prepare_octree(scene->kernel, NULL, NULL), RT_OK);
    ck_assert_int_eq(rt__kernel_prepare_octree(kf, NULL, NULL), RT_OK);
    int count = reduced() ? 300 : 6000;
    for (int i = 0; i < count; i++) {
        rt_vec3 o, t;
        accel_grid_ray(&rng, n, i, &o, &t);
        check_ray(scene->kernel, kf, o, t);
    }
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(random_rays_in_a_soup_see_the_same_through_the_octree)
{
    rt_scene *scene;
    rt_error error;
    ck_assert_int_eq(bench_soup(3000, 8, 8, &scene, &error), RT_OK);
    const rt_kernel *kf = rt__scene_kernel(scene, RT_PRECISION_FLOAT, NULL);
    ck_assert_ptr_nonnull(kf);
    ck_assert_int_eq(rt__kernel_prepare_octree(scene->kernel, NULL, NULL), RT_OK);
    ck_assert_int_eq(rt__kernel_prepare_octree(kf, NULL, NULL), RT_OK);
    for (int i = 0; i < (reduced() ? 200 : 6000); i++) {
        rt_vec3 o = {uniform(-3, 3), uniform(-3, 3), uniform(-3, 3)};
        rt_facet_info f = {.size = sizeof f};
        rt_scene_facet(scene, (int)uniform(0, 3000), &f);
        rt_vec3 t = rt_scene_vertex(scene, f.vertex[i % 3]);
        if (i % 2)
            t = (rt_vec3){uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
        check_ray(scene->kernel, kf, o, t);
    }
    rt_scene_destroy(scene);
}
END_TEST

/* --- the choice -------------------------------------------------------- */

START_TEST(the_default_is_auto_and_an_unknown_choice_is_an_argument_error)
{
    rt_scene *scene = rt_test_scene_from_string(
        "0 0 5\n0 0 4 1 0 4 2 2\n0\n0\n0 0 0\n0 0 10 255 255 255\n");
    rt_image image;
    ck_assert_int_eq(rt_image_init(&image, 2, 2, NULL), RT_OK);
    rt_render_options options;
    rt_render_options_init(&options);
    ck_assert_int_eq(options.accel, RT_ACCEL_AUTO);
    options.accel = (rt_accel)9;
    ck_assert_int_eq(rt_render(scene, &options, &image, NULL),
                     RT_ERR_ARGUMENT);
    rt_image_release(&image);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(auto_uses_the_kdtree_from_the_threshold_on)
{
    rt_scene *small, *big;
    rt_error error;
    ck_assert_int_eq(bench_soup(RT_ACCEL_AUTO_FACETS / 2, 8, 8, &small,
                                &error),
                     RT_OK);
    ck_assert_int_eq(bench_soup(RT_ACCEL_AUTO_FACETS * 4, 8, 8, &big, &error),
                     RT_OK);
    rt_render_stats stats = {.size = sizeof stats};
    rt_image a = render(small, &full_size, RT_PRECISION_DOUBLE, RT_ACCEL_AUTO,
                        1, 1,
                        &stats);
    ck_assert_int_eq(stats.accel_used, 0);
    rt_image b = render(big, &full_size, RT_PRECISION_DOUBLE, RT_ACCEL_AUTO,
                        1, 1,
                        &stats);
    ck_assert_int_eq(stats.accel_used, 1);
    ck_assert_int_eq(stats.accel_kdtree, 1);
    ck_assert_uint_gt(stats.accel_leaves, 1);
    ck_assert_uint_gt(stats.accel_queries, 0);
    ck_assert_uint_lt(stats.accel_facet_tests,
                      stats.accel_queries * stats.accel_facets);
    /* every leaf visited is a step, and so is the root (inner: the tree
     * has several leaves) of each query that reached a leaf; no walk
     * takes up a node twice */
    ck_assert_uint_gt(stats.accel_steps, stats.accel_leaves_visited);
    ck_assert_uint_le(stats.accel_steps,
                      stats.accel_queries * stats.accel_nodes);
    rt_image_release(&a);
    rt_image_release(&b);
    rt_scene_destroy(small);
    rt_scene_destroy(big);
}
END_TEST

/* The octree is built once per scene and precision: a second render (or
 * band) finds it built, and reports the same construction. */
START_TEST(the_octree_is_built_once_and_reused_by_every_render)
{
    rt_scene *scene;
    rt_error error;
    ck_assert_int_eq(bench_sphere(3000, 16, 16, &scene, &error), RT_OK);
    rt_render_stats first = {.size = sizeof first};
    rt_render_stats second = {.size = sizeof second};
    rt_image a = render(scene, &full_size, RT_PRECISION_FLOAT,
                        RT_ACCEL_OCTREE, 2, 1,
                        &first);
    rt_image b = render(scene, &full_size, RT_PRECISION_FLOAT,
                        RT_ACCEL_OCTREE, 1, 1,
                        &second);
    ck_assert_double_eq(first.accel_build_seconds,
                        second.accel_build_seconds);
    ck_assert_uint_eq(first.accel_bytes, second.accel_bytes);
    ck_assert_ptr_eq(rt__scene_kernel(scene, RT_PRECISION_FLOAT, NULL),
                     rt__scene_kernel(scene, RT_PRECISION_FLOAT, NULL));
    ck_assert_int_eq(rt_test_image_diff(&a, &b, NULL), 0);
    rt_image_release(&a);
    rt_image_release(&b);
    rt_scene_destroy(scene);
}
END_TEST

/* Degenerate distributions stay bounded: references at most a fixed
 * multiple of the facets, depth at most the limit. */
START_TEST(a_degenerate_scene_keeps_the_octree_bounded)
{
    accel_soup s = {0};
    rt_vec3 c = {1, 1, 1};
    for (int i = 0; i < 5000; i++)      /* 5000 facets through one point */
        accel_soup_add(&s, c, accel_jitter(&rng, c, 10),
                       accel_jitter(&rng, c, 10), 0.0);
    rt_scene *scene = accel_soup_scene(&s, (rt_vec3){1, -30, 1}, c,
                                       (rt_vec3){5, -5, 20}, 4);
    rt_render_stats stats = {.size = sizeof stats};
    rt_image image = render(scene, &full_size, RT_PRECISION_DOUBLE,
                            RT_ACCEL_OCTREE, 1, 1,
                            &stats);
    ck_assert_int_le(stats.accel_depth, 16);
    ck_assert_uint_le(stats.accel_references,
                      RT_OCTREE_REFERENCE_BUDGET * 5000u +
                          RT_OCTREE_REFERENCE_EXTRA);
    rt_image_release(&image);
    rt_scene_destroy(scene);
}
END_TEST

static Suite *octree_suite(void)
{
    Suite *s = suite_create("octree");
    TCase *images = tcase_create("images");
    tcase_set_timeout(images, 600);
    tcase_add_test(images, project_scenes_render_identically_through_the_octree);
    tcase_add_test(images,
                   generated_meshes_render_identically_through_the_octree);
    tcase_add_test(images, facets_all_in_one_spot_render_identically);
    tcase_add_test(images, a_few_facets_spanning_everything_render_identically);
    tcase_add_test(images, slivers_beside_huge_walls_render_identically);
    tcase_add_test(images, coincident_facets_keep_the_tie_of_the_file_order);
    tcase_add_test(images, far_and_inside_cameras_render_identically);
    tcase_add_test(images, transparency_lights_and_lens_render_identically);
    tcase_add_test(images,
                   coordinates_at_the_limit_of_a_scene_render_identically);
    suite_add_tcase(s, images);
    TCase *rays = tcase_create("rays");
    tcase_set_timeout(rays, 300);
    tcase_add_test(
        rays, rays_grazing_and_along_cell_faces_see_the_same_through_the_octree);
    tcase_add_test(rays, random_rays_in_a_soup_see_the_same_through_the_octree);
    suite_add_tcase(s, rays);
    TCase *choice = tcase_create("choice");
    tcase_set_timeout(choice, 120);
    tcase_add_test(choice,
                   the_default_is_auto_and_an_unknown_choice_is_an_argument_error);
    tcase_add_test(choice, auto_uses_the_kdtree_from_the_threshold_on);
    tcase_add_test(choice, the_octree_is_built_once_and_reused_by_every_render);
    tcase_add_test(choice, a_degenerate_scene_keeps_the_octree_bounded);
    suite_add_tcase(s, choice);
    return s;
}

/* --- ../shared: its own ctest entry, skipped (77) when absent ----------- */

START_TEST(shared_scenes_render_identically_through_the_octree)
{
    char seed[4096], spd[4096];
    snprintf(seed, sizeof seed, "%s", rt_test_shared_path("seed-scenes"));
    snprintf(spd, sizeof spd, "%s", rt_test_shared_path("spd-scenes"));
    size_t scenes = check_directory(seed, reduced() ? 16 : 160) +
                    check_directory(spd, reduced() ? 8 : 48);
    ck_assert_uint_gt(scenes, 0);
}
END_TEST

static Suite *shared_suite(void)
{
    Suite *s = suite_create("octree-shared");
    TCase *images = tcase_create("shared");
    tcase_set_timeout(images, 600);
    tcase_add_test(images, shared_scenes_render_identically_through_the_octree);
    suite_add_tcase(s, images);
    return s;
}

RT_CHECK_MAIN_WITH_SHARED(octree_suite, shared_suite)
