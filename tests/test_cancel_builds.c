/*
 * test_cancel_builds.c - the builds of a load and of a render poll their
 * cancellation flag: the scene builder's pass over the facets, the double
 * kernel it makes, and the float kernel the first float render makes.  A
 * raised flag stops each with RT_ERR_CANCELLED and keeps nothing half
 * built; the next call, with the flag down, builds it all and renders the
 * same bytes.  (The readers' own polls and the octree's are tested in
 * test_load_budgets.c, test_obj_costs.c and test_octree_hostile.c.)
 */
#include <check.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#include "formats/reader.h"
#include "kernel/kernel.h"
#include "scene/scene_internal.h"
#include "testutil.h"

/* A grid of 2 n^2 facets, more than RT_KERNEL_POLL and RT_LOAD_POLL so
 * that both passes reach a poll. */
typedef struct grid {
    rt_vec3 *vertices;
    rt_facet_desc *facets;
    rt_light *light;        /* on the heap: the grid is returned by value */
    rt_scene_desc desc;
} grid;

static grid make_grid(int n)
{
    grid g;
    memset(&g, 0, sizeof g);
    g.vertices = malloc((size_t)(n + 1) * (size_t)(n + 1) * sizeof *g.vertices);
    g.facets = calloc((size_t)2 * (size_t)n * (size_t)n, sizeof *g.facets);
    g.light = malloc(sizeof *g.light);
    ck_assert(g.vertices != NULL && g.facets != NULL && g.light != NULL);
    for (int y = 0; y <= n; y++)
        for (int x = 0; x <= n; x++)
            g.vertices[y * (n + 1) + x] = (rt_vec3){x, y, 0};
    int f = 0;
    for (int y = 0; y < n; y++)
        for (int x = 0; x < n; x++) {
            int a = y * (n + 1) + x, b = a + 1, c = a + n + 1, d = c + 1;
            g.facets[f++] = (rt_facet_desc){{a, b, d}, 0, {200, 100, 50},
                                            0, 0, 0, 0};
            g.facets[f++] = (rt_facet_desc){{a, d, c}, 0, {50, 100, 200},
                                            0, 0, 0, 0};
        }
    g.desc.observer = (rt_vec3){n / 2.0, n / 2.0, n};
    g.desc.screen_center = (rt_vec3){n / 2.0, n / 2.0, 0};
    g.desc.screen_right = (rt_vec3){n, n / 2.0, 0};
    g.desc.width = g.desc.height = 16;
    g.desc.vertices = g.vertices;
    g.desc.vertex_count = (n + 1) * (n + 1);
    g.desc.facets = g.facets;
    g.desc.facet_count = f;
    g.desc.background = (rt_rgb8){10, 20, 30};
    *g.light = (rt_light){{n / 2.0, 0, n}, {255, 255, 255}};
    g.desc.lights = g.light;
    g.desc.light_count = 1;
    return g;
}

static void free_grid(grid *g)
{
    free(g->vertices);
    free(g->facets);
    free(g->light);
}

static int grid_side(void)
{
    /* 2 x 200^2 = 80,000 facets > RT_KERNEL_POLL (65,536) */
    return 200;
}

START_TEST(a_raised_flag_stops_the_builder_and_keeps_no_scene)
{
    grid g = make_grid(grid_side());
    rt_cancel *cancel;
    ck_assert_int_eq(rt_cancel_create(&cancel, NULL), RT_OK);
    rt_cancel_request(cancel);
    rt_scene *scene = (rt_scene *)1;
    rt_error error;
    ck_assert_int_eq(rt__scene_build(&g.desc, "grid", NULL, NULL, cancel,
                                     &scene, &error, NULL),
                     RT_ERR_CANCELLED);
    ck_assert_ptr_null(scene);
    ck_assert_ptr_nonnull(strstr(error.message, "cancelled"));
    rt_cancel_reset(cancel);
    ck_assert_int_eq(rt__scene_build(&g.desc, "grid", NULL, NULL, cancel,
                                     &scene, &error, NULL),
                     RT_OK);
    rt_scene_destroy(scene);
    rt_cancel_destroy(cancel);
    free_grid(&g);
}
END_TEST

START_TEST(a_raised_flag_stops_the_kernels_construction)
{
    grid g = make_grid(grid_side());
    rt_scene *scene;
    ck_assert_int_eq(rt_scene_create(&g.desc, &scene, NULL), RT_OK);
    rt_cancel *cancel;
    ck_assert_int_eq(rt_cancel_create(&cancel, NULL), RT_OK);
    rt_cancel_request(cancel);
    rt_kernel_source source;
    rt__scene_kernel_source(scene, &source);
    source.cancel = cancel;
    ck_assert_ptr_null(rt__kernel_double_ops.create(&source));
    ck_assert_ptr_null(rt__kernel_float_ops.create(&source));
    /* the scene's lazy float kernel: nothing kept, built next time */
    ck_assert_ptr_null(rt__scene_kernel(scene, RT_PRECISION_FLOAT, cancel));
    ck_assert_ptr_nonnull(rt__scene_kernel(scene, RT_PRECISION_FLOAT, NULL));
    rt_cancel_destroy(cancel);
    rt_scene_destroy(scene);
    free_grid(&g);
}
END_TEST

/* A float render with a raised flag is cancelled before its kernel is
 * kept; with the flag down it renders what a render never cancelled
 * renders. */
START_TEST(a_cancelled_float_render_keeps_no_kernel_and_renders_after)
{
    grid g = make_grid(grid_side());
    rt_scene *fresh, *scene;
    ck_assert_int_eq(rt_scene_create(&g.desc, &fresh, NULL), RT_OK);
    ck_assert_int_eq(rt_scene_create(&g.desc, &scene, NULL), RT_OK);
    rt_cancel *cancel;
    ck_assert_int_eq(rt_cancel_create(&cancel, NULL), RT_OK);
    rt_render_options options;
    rt_render_options_init(&options);
    options.precision = RT_PRECISION_FLOAT;
    options.threads = 1;
    options.cancel = cancel;
    rt_image image, expected;
    ck_assert_int_eq(rt_image_init(&image, 16, 16, NULL), RT_OK);
    ck_assert_int_eq(rt_image_init(&expected, 16, 16, NULL), RT_OK);
    rt_cancel_request(cancel);
    ck_assert_int_eq(rt_render(scene, &options, &image, NULL),
                     RT_ERR_CANCELLED);
    ck_assert_ptr_null(atomic_load(&scene->kernel_f));
    rt_cancel_reset(cancel);
    ck_assert_int_eq(rt_render(scene, &options, &image, NULL), RT_OK);
    options.cancel = NULL;
    ck_assert_int_eq(rt_render(fresh, &options, &expected, NULL), RT_OK);
    int max_diff;
    ck_assert_int_eq(rt_test_image_diff(&image, &expected, &max_diff), 0);
    rt_image_release(&image);
    rt_image_release(&expected);
    rt_cancel_destroy(cancel);
    rt_scene_destroy(scene);
    rt_scene_destroy(fresh);
    free_grid(&g);
}
END_TEST

static Suite *cancel_builds_suite(void)
{
    Suite *s = suite_create("cancel_builds");
    TCase *c = tcase_create("builds");
    tcase_set_timeout(c, 120);
    tcase_add_test(c, a_raised_flag_stops_the_builder_and_keeps_no_scene);
    tcase_add_test(c, a_raised_flag_stops_the_kernels_construction);
    tcase_add_test(c,
                   a_cancelled_float_render_keeps_no_kernel_and_renders_after);
    suite_add_tcase(s, c);
    return s;
}

RT_CHECK_MAIN(cancel_builds_suite)
