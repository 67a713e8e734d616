/*
 * test_octree_hostile.c - the octree under what a hostile model does to it
 * (issue 25): a build so long the user cancels it, a fan of slivers (a
 * convex polygon of many corners, triangulated as a fan) that no ray may
 * have to test whole, models seen from so far that the margin no longer
 * covers the watertight test's rounding, and a model far from the
 * coordinates' origin compared to its size.  Every image is compared byte
 * for byte with brute force, as tests/test_octree.c does for ordinary
 * scenes; the costs are checked as counts (facet tests per query, queries
 * left to brute force), never as times.
 *
 * Sizes shrink under valgrind (RT_TEST_MEMCHECK), as in test_octree.c.
 */
#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "bench_scenes.h"
#include "kernel/kernel.h"
#include "scene/scene_internal.h"
#include "testutil.h"

static const double pi = 3.14159265358979323846;

/* Renders `scene` into *image (allocated here at the scene's size, or
 * side x side when side > 0) and returns the status. */
static rt_status render_into(const rt_scene *scene, rt_precision precision,
                             rt_accel accel, rt_cancel *cancel,
                             rt_render_stats *stats, rt_image *image)
{
    rt_render_options options;
    rt_render_options_init(&options);
    options.precision = precision;
    options.accel = accel;
    options.threads = 2;
    options.cancel = cancel;
    options.stats = stats;
    int width, height;
    ck_assert_int_eq(rt_render_image_size(scene, &options, &width, &height,
                                          NULL),
                     RT_OK);
    ck_assert_int_eq(rt_image_init(image, width, height, NULL), RT_OK);
    rt_error error;
    rt_status status = rt_render(scene, &options, image, &error);
    ck_assert_msg(status == RT_OK || status == RT_ERR_CANCELLED, "%s",
                  error.message);
    return status;
}

static rt_image render(const rt_scene *scene, rt_precision precision,
                       rt_accel accel, rt_render_stats *stats)
{
    rt_image image;
    ck_assert_int_eq(render_into(scene, precision, accel, NULL, stats,
                                 &image),
                     RT_OK);
    return image;
}

/* The octree's image is brute force's, in `precision`; its statistics in
 * *stats. */
static void check_identical(const rt_scene *scene, rt_precision precision,
                            const char *name, rt_render_stats *stats)
{
    rt_image ref = render(scene, precision, RT_ACCEL_NONE, NULL);
    rt_image tree = render(scene, precision, RT_ACCEL_OCTREE, stats);
    ck_assert_msg(rt_test_image_diff(&ref, &tree, NULL) == 0,
                  "%s (%s): the octree changed the image", name,
                  precision == RT_PRECISION_FLOAT ? "float" : "double");
    ck_assert_int_eq(stats->accel_used, 1);
    rt_image_release(&ref);
    rt_image_release(&tree);
}

/* --- cancelled builds ------------------------------------------------- */

/* Random facets: enough that the build takes a while (a few tenths of a
 * second at full size). */
static rt_scene *big_soup(void)
{
    rt_scene *scene;
    rt_error error;
    ck_assert_int_eq(bench_soup(rt_test_memcheck() ? 20000 : 300000, 16, 16,
                                &scene, &error),
                     RT_OK);
    return scene;
}

/* RT_OK when the kernel of `precision` keeps an octree: asked with a
 * raised flag, octree_prepare builds nothing, so it says RT_OK only for a
 * tree built before (RT_ERR_CANCELLED otherwise). */
static rt_status kept_tree(const rt_scene *scene, rt_precision precision,
                           rt_octree_info *info)
{
    rt_cancel *raised;
    ck_assert_int_eq(rt_cancel_create(&raised, NULL), RT_OK);
    rt_cancel_request(raised);
    rt_status status = rt__kernel_prepare_octree(
        rt__scene_kernel(scene, precision, NULL), raised, info);
    rt_cancel_destroy(raised);
    return status;
}

/* With the flag reset, a render through the octree succeeds, gives brute
 * force's image and keeps its octree (described in *info when not NULL). */
static void renders_again(const rt_scene *scene, rt_precision precision,
                          rt_cancel *cancel, rt_octree_info *info)
{
    rt_image image;
    rt_cancel_reset(cancel);
    ck_assert_int_eq(render_into(scene, precision, RT_ACCEL_OCTREE, cancel,
                                 NULL, &image),
                     RT_OK);
    rt_image ref = render(scene, precision, RT_ACCEL_NONE, NULL);
    ck_assert_int_eq(rt_test_image_diff(&ref, &image, NULL), 0);
    ck_assert_int_eq(kept_tree(scene, precision, info), RT_OK);
    rt_image_release(&image);
    rt_image_release(&ref);
}

START_TEST(a_render_cancelled_before_it_starts_builds_no_octree)
{
    rt_scene *scene = big_soup();
    rt_cancel *cancel;
    ck_assert_int_eq(rt_cancel_create(&cancel, NULL), RT_OK);
    for (int p = 0; p < 2; p++) {
        rt_precision precision = p ? RT_PRECISION_FLOAT : RT_PRECISION_DOUBLE;
        rt_cancel_request(cancel);
        rt_image image;
        ck_assert_int_eq(render_into(scene, precision, RT_ACCEL_OCTREE,
                                     cancel, NULL, &image),
                         RT_ERR_CANCELLED);
        rt_image_release(&image);
        ck_assert_int_eq(kept_tree(scene, precision, NULL), RT_ERR_CANCELLED);
        /* The next render builds it, and gives brute force's image. */
        renders_again(scene, precision, cancel, NULL);
    }
    rt_cancel_destroy(cancel);
    rt_scene_destroy(scene);
}
END_TEST

static void *raise_flag(void *cancel)
{
    rt_cancel_request(cancel);
    return NULL;
}

/* The flag raised by another thread while the render runs - before, during
 * or after the build, as the threads happen to be scheduled: whatever the
 * moment, the render ends, and the octree left is none or a whole one (the
 * same as an uncancelled build's), never a part. */
START_TEST(a_render_cancelled_from_another_thread_keeps_no_partial_octree)
{
    rt_scene *scene = big_soup(), *twin = big_soup();
    rt_octree_info whole, left;
    ck_assert_int_eq(rt__kernel_prepare_octree(twin->kernel, NULL, &whole),
                     RT_OK);
    rt_cancel *cancel;
    ck_assert_int_eq(rt_cancel_create(&cancel, NULL), RT_OK);
    pthread_t thread;
    ck_assert_int_eq(pthread_create(&thread, NULL, raise_flag, cancel), 0);
    rt_image image;
    rt_status status = render_into(scene, RT_PRECISION_DOUBLE,
                                   RT_ACCEL_OCTREE, cancel, NULL, &image);
    pthread_join(thread, NULL);
    ck_assert_msg(status == RT_OK || status == RT_ERR_CANCELLED, "%s",
                  rt_status_string(status));
    rt_image_release(&image);
    status = kept_tree(scene, RT_PRECISION_DOUBLE, &left);
    if (status == RT_OK) {      /* kept: then whole */
        ck_assert_uint_eq(left.nodes, whole.nodes);
        ck_assert_uint_eq(left.references, whole.references);
        ck_assert_uint_eq(left.bytes, whole.bytes);
    } else {
        ck_assert_int_eq(status, RT_ERR_CANCELLED);
    }
    renders_again(scene, RT_PRECISION_DOUBLE, cancel, &left);
    ck_assert_uint_eq(left.nodes, whole.nodes);
    ck_assert_uint_eq(left.references, whole.references);
    rt_cancel_destroy(cancel);
    rt_scene_destroy(scene);
    rt_scene_destroy(twin);
}
END_TEST

/* --- generated models -------------------------------------------------- */

typedef struct mesh {
    rt_vec3 *v;
    rt_facet_desc *f;
    int nv, nf;
} mesh;

static void mesh_alloc(mesh *m, int vertices, int facets)
{
    m->v = malloc((size_t)vertices * sizeof *m->v);
    m->f = calloc((size_t)facets, sizeof *m->f);
    ck_assert_ptr_nonnull(m->v);
    ck_assert_ptr_nonnull(m->f);
    m->nv = m->nf = 0;
}

static void mesh_facet(mesh *m, int a, int b, int c, double k)
{
    rt_rgb8 color = {(unsigned char)(60 + m->nf * 37 % 190),
                     (unsigned char)(80 + m->nf * 91 % 170),
                     (unsigned char)(50 + m->nf * 53 % 200)};
    m->f[m->nf++] = (rt_facet_desc){{a, b, c}, k, color};
}

/* The scene of `m` seen from `eye` towards `at` through a screen halfway
 * there, of half width `half` times that distance; the mesh's arrays are
 * freed. */
static rt_scene *mesh_scene(mesh *m, rt_vec3 eye, rt_vec3 at, double half,
                            rt_vec3 light, int side)
{
    rt_vec3 d = {(at.x - eye.x) / 2, (at.y - eye.y) / 2, (at.z - eye.z) / 2};
    rt_vec3 a = {eye.x + d.x, eye.y + d.y, eye.z + d.z};
    half *= sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    rt_vec3 r = {d.y, -d.x, 0};     /* d x z */
    double rl = sqrt(r.x * r.x + r.y * r.y);
    if (rl == 0)
        r = (rt_vec3){1, 0, 0}, rl = 1;
    rt_vec3 b = {a.x + half * r.x / rl, a.y + half * r.y / rl, a.z};
    rt_scene_desc desc = {
        .observer = eye, .screen_center = a, .screen_right = b,
        .width = side, .height = side,
        .vertices = m->v, .vertex_count = m->nv,
        .facets = m->f, .facet_count = m->nf,
        .background = {20, 30, 40},
        .lights = &(rt_light){light, {255, 240, 220}}, .light_count = 1};
    rt_scene *scene;
    rt_error error;
    ck_assert_msg(rt_scene_create(&desc, &scene, &error) == RT_OK, "%s",
                  error.message);
    free(m->v);
    free(m->f);
    memset(m, 0, sizeof *m);
    return scene;
}

/* --- slivers ----------------------------------------------------------- */

/*
 * A convex polygon of corners + 1 vertices on an arc of `angle` radians of
 * the unit circle in z = 0, triangulated as a fan from its first corner,
 * as a reader fans a convex face: `corners - 1` facets, each of condition
 * about 2 corners / angle (a sliver beyond OCTREE_CONDITION_MAX).  Over
 * it, two ordinary facets hide part of the fan from the eye (the rays
 * that hit them first still cross the fan's cells); below, a floor.
 */
static rt_scene *sliver_fan_scene(int corners, double angle, int side)
{
    mesh m;
    mesh_alloc(&m, corners + 1 + 7, corners + 3);
    for (int i = 0; i <= corners; i++) {
        double t = angle * (i / (double)corners - 0.5);
        m.v[m.nv++] = (rt_vec3){cos(t) - 0.5, sin(t), 0};
    }
    for (int i = 1; i < corners; i++)
        mesh_facet(&m, 0, i, i + 1, 0.0);
    int w = m.nv;                       /* the cover, at z = 0.2 */
    m.v[m.nv++] = (rt_vec3){0.1, -0.3, 0.2};
    m.v[m.nv++] = (rt_vec3){0.6, -0.3, 0.2};
    m.v[m.nv++] = (rt_vec3){0.1, 0.05, 0.2};
    m.v[m.nv++] = (rt_vec3){0.6, 0.05, 0.2};
    mesh_facet(&m, w, w + 1, w + 3, 0.4);
    mesh_facet(&m, w, w + 3, w + 2, 0.0);
    int f = m.nv;                       /* the floor */
    m.v[m.nv++] = (rt_vec3){-20, -20, -0.5};
    m.v[m.nv++] = (rt_vec3){20, -20, -0.5};
    m.v[m.nv++] = (rt_vec3){0, 20, -0.5};
    mesh_facet(&m, f, f + 1, f + 2, 0.3);
    return mesh_scene(&m, (rt_vec3){0.4, -1.2, 1.6}, (rt_vec3){0.4, 0, 0},
                      0.45, (rt_vec3){-1, -2, 5}, side);
}

START_TEST(a_fan_of_slivers_renders_identically_and_no_ray_tests_it_whole)
{
    int corners = rt_test_memcheck() ? 3000 : 40000;
    double angle = 0.5;     /* conditions from about 12,000 */
    rt_scene *scene = sliver_fan_scene(corners, angle,
                                       rt_test_memcheck() ? 12 : 64);
    rt_octree_info info;
    ck_assert_int_eq(rt__kernel_prepare_octree(scene->kernel, NULL, &info),
                     RT_OK);
    ck_assert_uint_eq(info.slivers, (uint64_t)corners - 1);
    ck_assert_uint_eq(info.always, 0);
    for (int p = 0; p < 2; p++) {
        rt_precision precision = p ? RT_PRECISION_FLOAT : RT_PRECISION_DOUBLE;
        rt_render_stats stats = {.size = sizeof stats};
        check_identical(scene, precision, "sliver fan", &stats);
        ck_assert_uint_eq(stats.accel_always, 0);
        ck_assert_uint_gt(stats.accel_queries, 0);
        /* Before, every query tested every sliver (1 test per query per
         * sliver); now a ray tests those of the cells it crosses. */
        double per_query =
            (double)stats.accel_facet_tests / (double)stats.accel_queries;
        ck_assert_msg(per_query < (corners - 1) / 10.0,
                      "%s: %.0f facet tests per query for %d slivers",
                      p ? "float" : "double", per_query, corners - 1);
    }
    rt_scene_destroy(scene);
}
END_TEST

/* The degenerate distributions of test_octree.c with slivers among them
 * (listed in leaves now, not tested by every ray): a thin sliver fan
 * spanning a soup, and slivers through one point. */
START_TEST(slivers_among_ordinary_facets_render_identically)
{
    rt_scene *soup;
    rt_error error;
    ck_assert_int_eq(bench_soup(rt_test_memcheck() ? 300 : 3000, 8, 8, &soup,
                                &error),
                     RT_OK);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(soup, &info);
    int corners = rt_test_memcheck() ? 400 : 4000;
    mesh m;
    mesh_alloc(&m, info.vertex_count + corners + 1,
               info.facet_count + corners);
    for (int i = 0; i < info.vertex_count; i++)
        m.v[m.nv++] = rt_scene_vertex(soup, i);
    for (int i = 0; i < info.facet_count; i++) {
        rt_facet_info f = {.size = sizeof f};
        rt_scene_facet(soup, i, &f);
        mesh_facet(&m, f.vertex[0], f.vertex[1], f.vertex[2], f.reflection);
    }
    rt_scene_destroy(soup);
    /* a fan through the soup, tilted, every sliver through its corner */
    int base = m.nv;
    for (int i = 0; i <= corners; i++) {
        double t = 0.05 * (i / (double)corners - 0.5);
        m.v[m.nv++] = (rt_vec3){1.8 * cos(t) - 0.9, 1.8 * sin(t),
                                0.3 * cos(t) - 0.2};
    }
    for (int i = 1; i < corners; i++)
        mesh_facet(&m, base, base + i, base + i + 1, i % 5 ? 0.0 : 0.6);
    rt_scene *scene = mesh_scene(&m, (rt_vec3){1.0, -4.0, 1.5},
                                 (rt_vec3){0, 0, 0}, 0.45,
                                 (rt_vec3){-2.5, -3, 4},
                                     rt_test_memcheck() ? 12 : 48);
    rt_octree_info tree;
    ck_assert_int_eq(rt__kernel_prepare_octree(scene->kernel, NULL, &tree),
                     RT_OK);
    ck_assert_uint_ge(tree.slivers, (uint64_t)corners - 1);
    for (int p = 0; p < 2; p++) {
        rt_render_stats stats = {.size = sizeof stats};
        check_identical(scene, p ? RT_PRECISION_FLOAT : RT_PRECISION_DOUBLE,
                        "slivers in a soup", &stats);
    }
    rt_scene_destroy(scene);
}
END_TEST

/* --- far origins ------------------------------------------------------- */

/* A sphere of radius 1 at the origin, as rings x segments quads. */
static void sphere_mesh(mesh *m, int rings, int segments)
{
    mesh_alloc(m, (rings + 1) * segments, 2 * rings * segments);
    for (int i = 0; i <= rings; i++) {
        double theta = pi * i / rings;
        for (int j = 0; j < segments; j++) {
            double phi = 2 * pi * (j + 0.5 * (i % 2)) / segments;
            m->v[m->nv++] = (rt_vec3){sin(theta) * cos(phi),
                                      sin(theta) * sin(phi), cos(theta)};
        }
    }
    for (int i = 0; i < rings; i++)
        for (int j = 0; j < segments; j++) {
            int a = i * segments + j, b = i * segments + (j + 1) % segments;
            int c = a + segments, d = b + segments;
            if (i > 0)
                mesh_facet(m, a, c, b, j % 7 == 0 ? 0.5 : 0.0);
            if (i < rings - 1)
                mesh_facet(m, b, c, d, 0.0);
        }
}

/* The sphere seen from `distance` (in radii) along a direction off every
 * axis, filling the image. */
static rt_scene *far_sphere(double distance, int side)
{
    mesh m;
    sphere_mesh(&m, rt_test_memcheck() ? 10 : 40, rt_test_memcheck() ? 20 : 80);
    rt_vec3 eye = {0.6 * distance, -0.7 * distance, 0.38 * distance};
    return mesh_scene(&m, eye, (rt_vec3){0, 0, 0}, 1.3 / distance,
                      (rt_vec3){3, -5, 4}, side);
}

/*
 * Beyond the margin's reach (2^16 root sizes in double, 2^6 in float) the
 * camera rays walk the octree with grown cells instead of falling back to
 * brute force, up to 1/16 of the root's side of growth; beyond that they
 * are brute force again (in double: float refuses to render a scene whose
 * coordinates exceed 4096 times its size, well within that limit).  Every
 * image is brute force's.
 */
START_TEST(a_model_seen_from_far_walks_grown_cells_and_renders_identically)
{
    int side = rt_test_memcheck() ? 8 : 32;
    struct {
        rt_precision precision;
        double distance;
        int walked;         /* camera rays through the octree */
    } cases[] = {
        {RT_PRECISION_FLOAT, 40, 1},        /* within reach */
        {RT_PRECISION_FLOAT, 2000, 1},      /* 1,000 root sizes */
        {RT_PRECISION_DOUBLE, 1e7, 1},      /* 5e6 root sizes */
        {RT_PRECISION_DOUBLE, 1e15, 0},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        rt_scene *scene = far_sphere(cases[i].distance, side);
        rt_scene_info info = {.size = sizeof info};
        rt_scene_get_info(scene, &info);
        rt_render_stats stats = {.size = sizeof stats};
        check_identical(scene, cases[i].precision, "far sphere", &stats);
        uint64_t camera = (uint64_t)side * (uint64_t)side;
        if (cases[i].walked) {
            ck_assert_msg(stats.accel_fallbacks < camera / 16,
                          "distance %g: %llu of %llu queries brute force",
                          cases[i].distance,
                          (unsigned long long)stats.accel_fallbacks,
                          (unsigned long long)stats.accel_queries);
            ck_assert_uint_lt(stats.accel_facet_tests,
                              stats.accel_queries *
                                  (uint64_t)info.facet_count / 8);
        } else {
            ck_assert_uint_ge(stats.accel_fallbacks, camera);
        }
        rt_scene_destroy(scene);
    }
}
END_TEST

/* An n x n grid of unit squares (integer vertices, so cell faces fall on
 * edges) under a mirror, moved `offset` away: beyond 2^16 sizes from the
 * coordinates' origin the cells' rounding exceeds a margin relative to the
 * size; the margin covers it (OCTREE_ROUNDING). */
static rt_scene *offset_grid(int n, double offset, int side)
{
    mesh m;
    mesh_alloc(&m, (n + 1) * (n + 1) + 3, 2 * n * n + 1);
    for (int y = 0; y <= n; y++)
        for (int x = 0; x <= n; x++)
            m.v[m.nv++] = (rt_vec3){offset + x, offset + y, 0};
    for (int y = 0; y < n; y++)
        for (int x = 0; x < n; x++) {
            int a = y * (n + 1) + x, b = a + 1, c = a + n + 1, d = c + 1;
            mesh_facet(&m, a, b, d, (x + y) % 3 == 0 ? 0.5 : 0.0);
            mesh_facet(&m, a, d, c, 0.0);
        }
    int top = m.nv;
    m.v[m.nv++] = (rt_vec3){offset, offset, 2};
    m.v[m.nv++] = (rt_vec3){offset + n, offset, 2};
    m.v[m.nv++] = (rt_vec3){offset, offset + n, 2};
    mesh_facet(&m, top, top + 1, top + 2, 0.8);
    return mesh_scene(&m, (rt_vec3){offset + n / 2.0, offset - n / 2.0, 1},
                      (rt_vec3){offset + n / 2.0, offset + n / 2.0, 0}, 0.6,
                      (rt_vec3){offset + n / 3.0, offset + n / 4.0, 1.5},
                      side);
}

START_TEST(a_model_far_from_the_coordinates_origin_renders_identically)
{
    double offsets[] = {0x1p20, 0x1p30, 0x1p36};
    for (int i = 0; i < 3; i++) {
        rt_scene *scene = offset_grid(16, offsets[i],
                                      rt_test_memcheck() ? 12 : 64);
        rt_render_stats stats = {.size = sizeof stats};
        check_identical(scene, RT_PRECISION_DOUBLE, "offset grid", &stats);
        ck_assert_uint_eq(stats.accel_fallbacks, 0);
        rt_scene_destroy(scene);
    }
}
END_TEST

static Suite *octree_hostile_suite(void)
{
    Suite *s = suite_create("octree_hostile");
    TCase *cancel = tcase_create("cancel");
    tcase_set_timeout(cancel, 300);
    tcase_add_test(cancel, a_render_cancelled_before_it_starts_builds_no_octree);
    tcase_add_test(cancel,
                   a_render_cancelled_from_another_thread_keeps_no_partial_octree);
    suite_add_tcase(s, cancel);
    TCase *slivers = tcase_create("slivers");
    tcase_set_timeout(slivers, 300);
    tcase_add_test(slivers,
                   a_fan_of_slivers_renders_identically_and_no_ray_tests_it_whole);
    tcase_add_test(slivers, slivers_among_ordinary_facets_render_identically);
    suite_add_tcase(s, slivers);
    TCase *far = tcase_create("far");
    tcase_set_timeout(far, 300);
    tcase_add_test(far,
                   a_model_seen_from_far_walks_grown_cells_and_renders_identically);
    tcase_add_test(far,
                   a_model_far_from_the_coordinates_origin_renders_identically);
    suite_add_tcase(s, far);
    return s;
}

RT_CHECK_MAIN(octree_hostile_suite)
