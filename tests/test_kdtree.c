/*
 * test_kdtree.c - the kd-tree against brute force: the same image, byte
 * for byte, in both precisions, on one thread and several, with 1 and 4
 * samples, on every scene the octree's comparison (tests/test_octree.c)
 * renders - the project's scenes, the handout's and the SPD scenes of
 * ../shared (their own ctest entry, skipped visibly when ../shared is
 * absent), generated meshes and soups, and the distributions a space
 * subdivision handles worst (accel_scenes.c).  Then single rays, colour
 * for colour, through the internal kernels: random, grazing, along the
 * planes of integer coordinates.  And what the kd-tree promises besides:
 * the option and its figures, one build per scene and precision, bounded
 * references and depth, a cancelled build that keeps nothing.
 */
#include <math.h>
#include <stdint.h>

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

/* The generator of the soups and rays (support/rng.h). */
static rt_test_rng rng = {0x6a09e667f3bcc909u};

static double uniform(double lo, double hi)
{
    return rt_test_rng_range(&rng, lo, hi);
}

static rt_image render(const rt_scene *scene, rt_precision precision,
                       rt_accel accel, int threads, rt_render_stats *stats)
{
    rt_render_options options;
    rt_render_options_init(&options);
    options.precision = precision;
    options.accel = accel;
    options.threads = threads;
    options.stats = stats;
    return rt_test_render_with(scene, &options);
}

/* Renders the scene (destroyed after) through the kd-tree and by brute
 * force (accel_check_scene()). */
static void check_and_destroy(rt_scene *scene, const char *name)
{
    accel_check_scene(scene, 0, 0, RT_ACCEL_KDTREE, name);
    rt_scene_destroy(scene);
}

START_TEST(project_scenes_render_identically_through_the_kdtree)
{
    ck_assert_uint_gt(accel_check_directory(rt_test_source_path("scenes"),
                                            reduced() ? 16 : 160,
                                            RT_ACCEL_KDTREE),
                      0);
}
END_TEST

START_TEST(generated_meshes_render_identically_through_the_kdtree)
{
    rt_scene *scene;
    rt_error error;
    int side = reduced() ? 12 : 64;
    int sizes[] = {100, 2000, 20000};
    for (int i = 0; i < (reduced() ? 2 : 3); i++) {
        ck_assert_int_eq(bench_sphere(sizes[i], side, side, &scene, &error),
                         RT_OK);
        check_and_destroy(scene, "sphere");
        ck_assert_int_eq(bench_soup(sizes[i] + 1, side, side, &scene,
                                    &error),
                         RT_OK);
        check_and_destroy(scene, "soup");
    }
}
END_TEST

START_TEST(facets_all_in_one_spot_render_identically_through_the_kdtree)
{
    check_and_destroy(accel_one_spot(&rng, reduced()), "one spot");
}
END_TEST

START_TEST(a_few_facets_spanning_everything_render_identically_through_the_kdtree)
{
    check_and_destroy(accel_spanning(&rng, reduced()), "spanning");
}
END_TEST

START_TEST(slivers_beside_huge_walls_render_identically_through_the_kdtree)
{
    check_and_destroy(accel_slivers_and_walls(&rng, reduced()),
                      "slivers and walls");
}
END_TEST

START_TEST(coincident_facets_keep_the_tie_of_the_file_order_in_the_kdtree)
{
    check_and_destroy(accel_coincident(&rng, reduced()), "coincident");
}
END_TEST

START_TEST(far_and_inside_cameras_render_identically_through_the_kdtree)
{
    check_and_destroy(accel_far_camera(&rng, reduced(), 0), "far camera");
    check_and_destroy(accel_far_camera(&rng, reduced(), 1), "inside");
}
END_TEST

START_TEST(transparency_lights_and_lens_render_identically_through_the_kdtree)
{
    check_and_destroy(accel_transparency_lights_lens(&rng, reduced()),
                      "transparency, lights, lens");
}
END_TEST

/* Coordinates at the limit a scene may hold (1e152): the facets' float
 * bounds overflow to infinities, planes cannot be placed, and the image
 * stays brute force's (double only: float refuses such a scene). */
START_TEST(coordinates_at_the_limit_of_a_scene_render_identically_through_the_kdtree)
{
    rt_scene *scene = accel_at_the_limit(&rng, reduced());
    rt_render_stats stats = {.size = sizeof stats};
    rt_image ref = render(scene, RT_PRECISION_DOUBLE, RT_ACCEL_NONE, 1, NULL);
    rt_image tree = render(scene, RT_PRECISION_DOUBLE, RT_ACCEL_KDTREE, 2,
                           &stats);
    ck_assert_int_eq(rt_test_image_diff(&ref, &tree, NULL), 0);
    ck_assert_int_eq(stats.accel_used, 1);
    ck_assert_int_eq(stats.accel_kdtree, 1);
    rt_image_release(&ref);
    rt_image_release(&tree);
    rt_scene_destroy(scene);
}
END_TEST

/* --- single rays ------------------------------------------------------ */

static const rt_trace_settings through_kdtree = {5, 0, RT_KERNEL_AUTO, NULL,
                                                 0, NULL, 1};

/* Both kernels of `scene` with their kd-trees built; the float one in *kf. */
static void prepare_both(rt_scene *scene, const rt_kernel **kf)
{
    *kf = rt__scene_kernel(scene, RT_PRECISION_FLOAT, NULL);
    ck_assert_ptr_nonnull(*kf);
    ck_assert_int_eq(
        rt__kernel_prepare_kdtree(scene->kernel, NULL, NULL, 1, NULL), RT_OK);
    ck_assert_int_eq(rt__kernel_prepare_kdtree(*kf, NULL, NULL, 1, NULL),
                     RT_OK);
}

START_TEST(rays_grazing_and_along_integer_planes_see_the_same_through_the_kdtree)
{
    const int n = 16;
    rt_scene *scene = accel_grid(n);
    const rt_kernel *kf;
    prepare_both(scene, &kf);
    for (int i = 0; i < (reduced() ? 300 : 6000); i++) {
        rt_vec3 o, t;
        accel_grid_ray(&rng, n, i, &o, &t);
        accel_check_ray(scene->kernel, kf, o, t, &through_kdtree);
    }
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(random_rays_in_a_soup_see_the_same_through_the_kdtree)
{
    rt_scene *scene;
    rt_error error;
    ck_assert_int_eq(bench_soup(3000, 8, 8, &scene, &error), RT_OK);
    const rt_kernel *kf;
    prepare_both(scene, &kf);
    for (int i = 0; i < (reduced() ? 200 : 6000); i++) {
        rt_vec3 o = {uniform(-3, 3), uniform(-3, 3), uniform(-3, 3)};
        rt_facet_info f = {.size = sizeof f};
        rt_scene_facet(scene, (int)uniform(0, 3000), &f);
        rt_vec3 t = rt_scene_vertex(scene, f.vertex[i % 3]);
        if (i % 2)
            t = (rt_vec3){uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
        accel_check_ray(scene->kernel, kf, o, t, &through_kdtree);
    }
    rt_scene_destroy(scene);
}
END_TEST

/* --- what it promises besides ------------------------------------------ */

/* RT_ACCEL_KDTREE is a valid choice and its figures say it was used: a
 * tree of several leaves, each query testing fewer facets than brute
 * force, nothing left to brute force on an ordinary mesh, and traversal
 * steps that a binary tree's walks can take. */
START_TEST(the_kdtree_is_chosen_by_its_option_and_reports_its_figures)
{
    rt_scene *scene;
    rt_error error;
    ck_assert_int_eq(bench_sphere(5000, 16, 16, &scene, &error), RT_OK);
    rt_render_stats stats = {.size = sizeof stats};
    rt_image image = render(scene, RT_PRECISION_DOUBLE, RT_ACCEL_KDTREE, 1,
                            &stats);
    ck_assert_int_eq(stats.accel_used, 1);
    ck_assert_int_eq(stats.accel_kdtree, 1);
    ck_assert_uint_gt(stats.accel_leaves, 1);
    ck_assert_uint_eq(stats.accel_nodes, 2 * stats.accel_leaves - 1);
    ck_assert_int_gt(stats.accel_depth, 0);
    ck_assert_uint_ge(stats.accel_references, stats.accel_facets);
    ck_assert_uint_gt(stats.accel_bytes, 8 * stats.accel_nodes);
    ck_assert_uint_eq(stats.accel_always, 0);
    ck_assert_uint_gt(stats.accel_queries, 0);
    ck_assert_uint_eq(stats.accel_fallbacks, 0);
    ck_assert_uint_lt(stats.accel_facet_tests,
                      stats.accel_queries * stats.accel_facets / 20);
    /* the nodes a walk takes up form a subtree holding the root, whose
     * leaves include the L leaves it visited: at least 2L - 1 nodes for
     * L >= 1, and at most every node once */
    ck_assert_uint_ge(stats.accel_steps + stats.accel_queries,
                      2 * stats.accel_leaves_visited);
    ck_assert_uint_gt(stats.accel_steps, stats.accel_leaves_visited);
    ck_assert_uint_le(stats.accel_steps,
                      stats.accel_queries * stats.accel_nodes);
    rt_image_release(&image);
    /* the octree's figures are not the kd-tree's: the flag follows */
    image = render(scene, RT_PRECISION_DOUBLE, RT_ACCEL_OCTREE, 1, &stats);
    ck_assert_int_eq(stats.accel_used, 1);
    ck_assert_int_eq(stats.accel_kdtree, 0);
    rt_image_release(&image);
    rt_scene_destroy(scene);
}
END_TEST

/* Built once per scene and precision: a second render finds it built and
 * reports the same construction. */
START_TEST(the_kdtree_is_built_once_and_reused_by_every_render)
{
    rt_scene *scene;
    rt_error error;
    ck_assert_int_eq(bench_sphere(3000, 16, 16, &scene, &error), RT_OK);
    for (int p = 0; p < 2; p++) {
        rt_precision precision = p ? RT_PRECISION_FLOAT : RT_PRECISION_DOUBLE;
        rt_render_stats first = {.size = sizeof first};
        rt_render_stats second = {.size = sizeof second};
        rt_image a = render(scene, precision, RT_ACCEL_KDTREE, 2, &first);
        rt_image b = render(scene, precision, RT_ACCEL_KDTREE, 1, &second);
        ck_assert_double_eq(first.accel_build_seconds,
                            second.accel_build_seconds);
        ck_assert_uint_eq(first.accel_bytes, second.accel_bytes);
        ck_assert_int_eq(rt_test_image_diff(&a, &b, NULL), 0);
        rt_image_release(&a);
        rt_image_release(&b);
    }
    rt_scene_destroy(scene);
}
END_TEST

/* Facets crossing one another everywhere (5000 through one point, a
 * fan of long ones over a soup): references and nodes stay within the
 * limit, depth within the cap, and the image is brute force's. */
START_TEST(a_degenerate_scene_keeps_the_kdtree_bounded)
{
    accel_soup s = {0};
    rt_vec3 c = {1, 1, 1};
    int n = reduced() ? 1000 : 5000;
    for (int i = 0; i < n; i++)
        accel_soup_add(&s, c, accel_jitter(&rng, c, 10),
                       accel_jitter(&rng, c, 10), 0.0);
    rt_scene *scene = accel_soup_scene(&s, (rt_vec3){1, -30, 1}, c,
                                       (rt_vec3){5, -5, 20}, 6);
    rt_render_stats stats = {.size = sizeof stats};
    rt_image tree = render(scene, RT_PRECISION_DOUBLE, RT_ACCEL_KDTREE, 1,
                           &stats);
    rt_image ref = render(scene, RT_PRECISION_DOUBLE, RT_ACCEL_NONE, 1, NULL);
    ck_assert_int_eq(rt_test_image_diff(&ref, &tree, NULL), 0);
    int cap = (int)(8 + 1.3 * log2((double)n));
    ck_assert_int_le(stats.accel_depth, cap);
    uint64_t limit = (uint64_t)RT_KDTREE_REFERENCE_LIMIT * (uint64_t)n +
                     RT_KDTREE_REFERENCE_EXTRA;
    ck_assert_uint_le(stats.accel_references, limit);
    ck_assert_uint_le(stats.accel_nodes, limit);
    rt_image_release(&ref);
    rt_image_release(&tree);
    rt_scene_destroy(scene);
}
END_TEST

/* A raised flag stops the build, on one thread and on three, with
 * RT_ERR_CANCELLED and keeps nothing; with the flag down the next call
 * builds it, and the render that follows is brute force's. */
START_TEST(a_cancelled_kdtree_build_keeps_nothing_and_is_built_again)
{
    for (int threads = 1; threads <= 3; threads += 2) {
        rt_scene *scene;
        rt_error error;
        ck_assert_int_eq(bench_soup(6000, 8, 8, &scene, &error), RT_OK);
        rt_cancel *flag;
        ck_assert_int_eq(rt_cancel_create(&flag, NULL), RT_OK);
        rt_cancel_request(flag);
        rt_octree_info info = {0};
        ck_assert_int_eq(rt__kernel_prepare_kdtree(scene->kernel, flag, NULL,
                                                   threads, &info),
                         RT_ERR_CANCELLED);
        ck_assert_uint_eq(info.nodes, 0);
        rt_cancel_reset(flag);
        ck_assert_int_eq(rt__kernel_prepare_kdtree(scene->kernel, flag, NULL,
                                                   threads, &info),
                         RT_OK);
        ck_assert_uint_gt(info.nodes, 1);
        rt_image tree = render(scene, RT_PRECISION_DOUBLE, RT_ACCEL_KDTREE, 2,
                               NULL);
        rt_image ref = render(scene, RT_PRECISION_DOUBLE, RT_ACCEL_NONE, 1,
                              NULL);
        ck_assert_int_eq(rt_test_image_diff(&ref, &tree, NULL), 0);
        rt_image_release(&ref);
        rt_image_release(&tree);
        rt_cancel_destroy(flag);
        rt_scene_destroy(scene);
    }
}
END_TEST

START_TEST(the_kdtree_is_the_same_tree_on_any_number_of_threads)
{
    /* enough facets for many tasks (the build's parts) */
    int facets = reduced() ? 6000 : 24000;
    rt_octree_info first = {0};
    for (int threads = 1; threads <= 5; threads++) {
        rt_scene *scene;
        rt_error error;
        ck_assert_int_eq(bench_soup(facets, 8, 8, &scene, &error), RT_OK);
        rt_octree_info info = {0};
        ck_assert_int_eq(rt__kernel_prepare_kdtree(scene->kernel, NULL, NULL,
                                                   threads, &info),
                         RT_OK);
        ck_assert_uint_gt(info.nodes, 100);
        if (threads == 1)
            first = info;
        ck_assert_uint_eq(info.nodes, first.nodes);
        ck_assert_uint_eq(info.references, first.references);
        ck_assert_int_eq(info.depth, first.depth);
        ck_assert_uint_eq(info.digest, first.digest);
        rt_scene_destroy(scene);
    }
}
END_TEST

static Suite *kdtree_suite(void)
{
    Suite *s = suite_create("kdtree");
    TCase *images = tcase_create("images");
    tcase_set_timeout(images, 600);
    tcase_add_test(images, project_scenes_render_identically_through_the_kdtree);
    tcase_add_test(images,
                   generated_meshes_render_identically_through_the_kdtree);
    tcase_add_test(images,
                   facets_all_in_one_spot_render_identically_through_the_kdtree);
    tcase_add_test(
        images,
        a_few_facets_spanning_everything_render_identically_through_the_kdtree);
    tcase_add_test(
        images, slivers_beside_huge_walls_render_identically_through_the_kdtree);
    tcase_add_test(
        images, coincident_facets_keep_the_tie_of_the_file_order_in_the_kdtree);
    tcase_add_test(
        images, far_and_inside_cameras_render_identically_through_the_kdtree);
    tcase_add_test(
        images,
        transparency_lights_and_lens_render_identically_through_the_kdtree);
    tcase_add_test(
        images,
        coordinates_at_the_limit_of_a_scene_render_identically_through_the_kdtree);
    suite_add_tcase(s, images);
    TCase *rays = tcase_create("rays");
    tcase_set_timeout(rays, 300);
    tcase_add_test(
        rays,
        rays_grazing_and_along_integer_planes_see_the_same_through_the_kdtree);
    tcase_add_test(rays, random_rays_in_a_soup_see_the_same_through_the_kdtree);
    suite_add_tcase(s, rays);
    TCase *promises = tcase_create("promises");
    tcase_set_timeout(promises, 120);
    tcase_add_test(promises,
                   the_kdtree_is_chosen_by_its_option_and_reports_its_figures);
    tcase_add_test(promises, the_kdtree_is_built_once_and_reused_by_every_render);
    tcase_add_test(promises, a_degenerate_scene_keeps_the_kdtree_bounded);
    tcase_add_test(promises,
                   the_kdtree_is_the_same_tree_on_any_number_of_threads);
    tcase_add_test(promises,
                   a_cancelled_kdtree_build_keeps_nothing_and_is_built_again);
    suite_add_tcase(s, promises);
    return s;
}

/* --- ../shared: its own ctest entry, skipped (77) when absent ----------- */

START_TEST(shared_scenes_render_identically_through_the_kdtree)
{
    char seed[4096], spd[4096];
    snprintf(seed, sizeof seed, "%s", rt_test_shared_path("seed-scenes"));
    snprintf(spd, sizeof spd, "%s", rt_test_shared_path("spd-scenes"));
    size_t scenes = accel_check_directory(seed, reduced() ? 16 : 160,
                                          RT_ACCEL_KDTREE) +
                    accel_check_directory(spd, reduced() ? 8 : 48,
                                          RT_ACCEL_KDTREE);
    ck_assert_uint_gt(scenes, 0);
}
END_TEST

static Suite *shared_suite(void)
{
    Suite *s = suite_create("kdtree-shared");
    TCase *images = tcase_create("shared");
    tcase_set_timeout(images, 600);
    tcase_add_test(images, shared_scenes_render_identically_through_the_kdtree);
    suite_add_tcase(s, images);
    return s;
}

RT_CHECK_MAIN_WITH_SHARED(kdtree_suite, shared_suite)
