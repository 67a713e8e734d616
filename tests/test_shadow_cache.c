/*
 * test_shadow_cache.c - the last-blocker cache of the shadow rays
 * (src/kernel/shade_impl.h, shadow_blocked()): per thread and light, the
 * facet that blocked the last shadow ray is tested first, and when it
 * blocks, no query is made.  Counted exactly on a scene whose blocker is
 * the last facet, so that brute force in index order tests every other
 * facet before it: one test instead of all of them, the same colour bit
 * for bit, by brute force, the octree and the kd-tree, in both
 * precisions; and a render whose every row begins in the shadow makes one
 * walk per row, whatever the thread count (the cache is emptied at each
 * row, so the counts do not depend on which thread took which row).
 */
#include <stdint.h>
#include <string.h>

#include "kernel/kernel.h"
#include "scene/scene_internal.h"
#include "testutil.h"

/* scenes/two-facets.scn with the small triangle matte, four facets far to
 * the side (never hit, never in the way) between the floor and it, so that
 * it is facet 5 of 6, the last one brute force tests.  Its shadow on the
 * floor covers x 2.2 .. 5, y -1 .. 1 (the triangle scaled 2x about the
 * light). */
static const char shadow_scene[] =
    "0, 0, 10\n"
    "0, 0, 5,   4, 0, 5,   64, 48\n"
    "15\n"
    "-9.37, -5.73, 0\n"
    " 9.71, -5.38, 0\n"
    " 0.31, 13.1,  0\n"
    "-1.13, -1.27, 2\n"
    " 1.58, -0.93, 2\n"
    "-0.17,  1.74, 2\n"
    "100, 0, 0\n"
    "101, 0, 0\n"
    "100, 1, 0\n"
    "100, 0, 3\n"
    "101, 0, 3\n"
    "100, 1, 3\n"
    "100, 0, 6\n"
    "101, 0, 6\n"
    "100, 1, 6\n"
    "6\n"
    "1, 2, 3, 0,   180, 180, 180\n"
    "7, 8, 9, 0,   10, 10, 10\n"
    "10, 11, 12, 0,   10, 10, 10\n"
    "13, 14, 15, 0,   10, 10, 10\n"
    "7, 11, 15, 0,   10, 10, 10\n"
    "4, 5, 6, 0,   40, 120, 255\n"
    "30, 30, 60\n"
    "-3.875, 0.125, 4, 255, 255, 255\n";

#define FACETS 6

static const rt_vec3 eye = {0, 0, 10};

/* Two floor points in the shadow, the second near the first. */
static const rt_vec3 shadowed[2] = {{4.06, -0.43, 0}, {4.2, -0.3, 0}};

/* The ray from the eye to floor point `p`. */
static rt_vec3 towards(rt_vec3 p)
{
    return (rt_vec3){p.x - eye.x, p.y - eye.y, p.z - eye.z};
}

static rt_scene *load(void)
{
    rt_scene *scene = rt_test_scene_from_string(shadow_scene);
    ck_assert_int_eq(scene->live_count, FACETS);
    return scene;
}

/* The kernel of `scene` in double (float: 1), its structure `accel`
 * built; a float kernel is the caller's, in *own (else NULL). */
static const rt_kernel *kernel_with(const rt_scene *scene, int float_kernel,
                                    rt_accel accel, rt_kernel **own)
{
    const rt_kernel *k = scene->kernel;
    *own = NULL;
    if (float_kernel) {
        rt_kernel_source source;
        rt__scene_kernel_source(scene, &source);
        *own = rt__kernel_float_ops.create(&source);
        ck_assert_ptr_nonnull(*own);
        k = *own;
    }
    if (accel == RT_ACCEL_OCTREE)
        ck_assert_int_eq(rt__kernel_prepare_octree(k, NULL, NULL), RT_OK);
    if (accel == RT_ACCEL_KDTREE)
        ck_assert_int_eq(rt__kernel_prepare_kdtree(k, NULL, NULL, 1, NULL),
                         RT_OK);
    return k;
}

/* By brute force (the scalar loops, in index order): a first shadow ray
 * tests the FACETS - 1 facets it does not leave, the blocker last; the
 * next one, with the blocker cached, one.  A camera ray tests all. */
START_TEST(a_shadow_ray_tests_the_last_blocker_first_and_stops_there)
{
    rt_scene *scene = load();
    for (int p = 0; p < 2; p++) {
        rt_kernel *own;
        const rt_kernel *k = kernel_with(scene, p, RT_ACCEL_NONE, &own);
        rt_trace_settings settings = {.max_depth = 5,
                                      .kernel = RT_KERNEL_SCALAR};
        rt_counters c = {0};
        rt_color first = rt__kernel_trace(k, eye, towards(shadowed[0]),
                                          &settings, &c);
        ck_assert_uint_eq(c.shadow_rays, 1);
        ck_assert_uint_eq(c.ray_facet_tests, FACETS + FACETS - 1);
        ck_assert_int_eq(c.last_blocker[0], FACETS);    /* 1 + index 5 */
        rt_counters before = c;
        rt_color second = rt__kernel_trace(k, eye, towards(shadowed[1]),
                                           &settings, &c);
        ck_assert_uint_eq(c.shadow_rays, 2);
        ck_assert_uint_eq(c.ray_facet_tests - before.ray_facet_tests,
                          FACETS + 1);
        /* the renderer that skips nothing would test them all */
        ck_assert_uint_eq(c.early_exit_saved - before.early_exit_saved,
                          FACETS - 2);
        /* emptied, the cache costs the whole search again, and the colour
         * is the same */
        rt__counters_forget_blockers(&c);
        before = c;
        rt_color again = rt__kernel_trace(k, eye, towards(shadowed[1]),
                                          &settings, &c);
        ck_assert_uint_eq(c.ray_facet_tests - before.ray_facet_tests,
                          FACETS + FACETS - 1);
        ck_assert_mem_eq(&second, &again, sizeof again);
        /* shadowed: the floor's colour is black (k = 0, one light) */
        ck_assert(first.r == 0 && first.g == 0 && first.b == 0);
        rt__kernel_destroy(own);
    }
    rt_scene_destroy(scene);
}
END_TEST

/* Through the octree and the kd-tree: the cached blocker answers the
 * second shadow ray without a query (the camera ray's is the only one),
 * with the colour of a search. */
START_TEST(the_cache_answers_without_a_query_through_either_structure)
{
    rt_scene *scene = load();
    for (int a = 0; a < 2; a++) {
        for (int p = 0; p < 2; p++) {
            rt_kernel *own;
            const rt_kernel *k = kernel_with(
                scene, p, a ? RT_ACCEL_KDTREE : RT_ACCEL_OCTREE, &own);
            rt_trace_settings settings = {.max_depth = 5,
                                          .octree = !a, .kdtree = a};
            rt_counters c = {0};
            rt__kernel_trace(k, eye, towards(shadowed[0]), &settings, &c);
            ck_assert_uint_eq(c.accel_queries, 2);  /* camera, shadow */
            ck_assert_int_eq(c.last_blocker[0], FACETS);
            rt_counters before = c;
            rt_color cached = rt__kernel_trace(k, eye, towards(shadowed[1]),
                                               &settings, &c);
            ck_assert_uint_eq(c.accel_queries - before.accel_queries, 1);
            ck_assert_uint_eq(c.shadow_rays - before.shadow_rays, 1);
            rt_counters fresh = {0};
            rt_color searched = rt__kernel_trace(k, eye,
                                                 towards(shadowed[1]),
                                                 &settings, &fresh);
            ck_assert_uint_eq(fresh.accel_queries, 2);
            ck_assert_mem_eq(&cached, &searched, sizeof searched);
            rt__kernel_destroy(own);
        }
    }
    rt_scene_destroy(scene);
}
END_TEST

/* A region of 3 x 8 pixels inside the shadow: every row's first shadow ray
 * walks the kd-tree and the others are answered by the cache, so there
 * are as many queries as camera rays plus rows - for 1, 2 or 3 threads,
 * which take the rows in any order - and the image is brute force's. */
START_TEST(each_row_starts_with_an_empty_cache_whatever_the_threads)
{
    rt_scene *scene = load();
    rt_render_options options;
    rt_render_options_init(&options);
    options.region = (rt_region){47, 20, 50, 28};
    options.accel = RT_ACCEL_NONE;
    options.threads = 1;
    rt_image brute = rt_test_render_with(scene, &options);
    options.accel = RT_ACCEL_KDTREE;
    for (int threads = 1; threads <= 3; threads++) {
        rt_render_stats stats = {.size = sizeof stats};
        options.threads = threads;
        options.stats = &stats;
        rt_image image = rt_test_render_with(scene, &options);
        ck_assert_uint_eq(stats.camera_rays, 3 * 8);
        ck_assert_uint_eq(stats.shadow_rays, 3 * 8);
        ck_assert_uint_eq(stats.accel_queries, 3 * 8 + 8);
        ck_assert_mem_eq(image.pixels, brute.pixels,
                         (size_t)brute.height * brute.stride);
        rt_image_release(&image);
    }
    rt_image_release(&brute);
    rt_scene_destroy(scene);
}
END_TEST

static Suite *shadow_cache_suite(void)
{
    Suite *s = suite_create("shadow_cache");
    TCase *c = tcase_create("cache");
    tcase_add_test(c,
                   a_shadow_ray_tests_the_last_blocker_first_and_stops_there);
    tcase_add_test(c,
                   the_cache_answers_without_a_query_through_either_structure);
    tcase_add_test(c, each_row_starts_with_an_empty_cache_whatever_the_threads);
    suite_add_tcase(s, c);
    return s;
}

RT_CHECK_MAIN(shadow_cache_suite)
