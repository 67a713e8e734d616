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
 * check on their own).
 */
#include <glob.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

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

/* Brute force on one thread against the octree on 1 and 3 threads, with 1
 * and 4 samples per pixel, in double and float. */
static void check_scene(const rt_scene *scene, image_size size,
                        const char *name)
{
    for (int p = 0; p < 2; p++) {
        rt_precision precision = p ? RT_PRECISION_FLOAT : RT_PRECISION_DOUBLE;
        /* a scene float cannot resolve is refused alike with or without
         * the octree (rt_scene_check_precision) */
        if (rt_scene_check_precision(scene, precision, NULL) != RT_OK)
            continue;
        for (int samples = 1; samples <= 4; samples += 3) {
            rt_render_stats s_ref = {.size = sizeof s_ref};
            rt_render_stats s_oct = {.size = sizeof s_oct};
            rt_image ref = render(scene, &size, precision, RT_ACCEL_NONE, 1,
                                  samples,
                                  &s_ref);
            rt_image one = render(scene, &size, precision, RT_ACCEL_OCTREE, 1,
                                  samples, &s_oct);
            rt_image three = render(scene, &size, precision, RT_ACCEL_OCTREE,
                                    3,
                                    samples, NULL);
            ck_assert_msg(rt_test_image_diff(&ref, &one, NULL) == 0,
                          "%s (%s, %d samples): the octree changed the image",
                          name, p ? "float" : "double", samples);
            ck_assert_msg(rt_test_image_diff(&ref, &three, NULL) == 0,
                          "%s (%s, %d samples): the octree on 3 threads "
                          "changed the image",
                          name, p ? "float" : "double", samples);
            ck_assert_uint_eq(s_ref.shadow_rays, s_oct.shadow_rays);
            ck_assert_uint_eq(s_ref.reflection_rays, s_oct.reflection_rays);
            ck_assert_int_eq(s_ref.accel_used, 0);
            ck_assert_int_eq(s_oct.accel_used, 1);
            rt_image_release(&ref);
            rt_image_release(&one);
            rt_image_release(&three);
        }
    }
}

/* Every .scn of a directory, at most side x side pixels; the number of
 * scenes. */
static size_t check_directory(const char *dir, int side)
{
    glob_t g;
    char pattern[4096];
    snprintf(pattern, sizeof pattern, "%s/*.scn", dir);
    if (glob(pattern, 0, NULL, &g) != 0)
        return 0;
    for (size_t i = 0; i < g.gl_pathc; i++) {
        rt_scene *scene;
        rt_error error;
        ck_assert_msg(rt_scene_load(g.gl_pathv[i], NULL, &scene, &error) ==
                          RT_OK,
                      "%s", error.message);
        rt_scene_info info = {.size = sizeof info};
        rt_scene_get_info(scene, &info);
        int w = side && info.width > side ? side : info.width;
        int h = side && info.height > side ? side : info.height;
        check_scene(scene, (image_size){w, h}, g.gl_pathv[i]);
        rt_scene_destroy(scene);
    }
    size_t count = g.gl_pathc;
    globfree(&g);
    return count;
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

typedef struct soup {
    rt_vec3 *v;
    rt_facet_desc *f;
    int nv, nf, cap;
} soup;

static void soup_add(soup *s, rt_vec3 a, rt_vec3 b, rt_vec3 c, double k)
{
    if (s->nf == s->cap) {
        s->cap = s->cap ? 2 * s->cap : 64;
        s->v = realloc(s->v, (size_t)s->cap * 3 * sizeof *s->v);
        s->f = realloc(s->f, (size_t)s->cap * sizeof *s->f);
        ck_assert_ptr_nonnull(s->v);
        ck_assert_ptr_nonnull(s->f);
    }
    s->v[s->nv] = a;
    s->v[s->nv + 1] = b;
    s->v[s->nv + 2] = c;
    rt_rgb8 color = {(unsigned char)(40 + s->nf * 37 % 200),
                     (unsigned char)(60 + s->nf * 91 % 190),
                     (unsigned char)(30 + s->nf * 53 % 220)};
    s->f[s->nf] = (rt_facet_desc){{s->nv, s->nv + 1, s->nv + 2}, k, color};
    s->nv += 3;
    s->nf++;
}

/* The scene of `desc` (which holds the soup's arrays); the soup is then
 * emptied. */
static rt_scene *soup_create(const rt_scene_desc *desc, soup *s)
{
    rt_scene *scene;
    rt_error error;
    ck_assert_msg(rt_scene_create(desc, &scene, &error) == RT_OK, "%s",
                  error.message);
    free(s->v);
    free(s->f);
    memset(s, 0, sizeof *s);
    return scene;
}

/* The soup seen from `eye` towards `at`, the light at `light`. */
static rt_scene *soup_scene(soup *s, rt_vec3 eye, rt_vec3 at, rt_vec3 light,
                            int side)
{
    rt_vec3 d = {at.x - eye.x, at.y - eye.y, at.z - eye.z};
    double len = sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    rt_vec3 a = {eye.x + d.x / len, eye.y + d.y / len, eye.z + d.z / len};
    /* right: d x up (z), or x when looking along z */
    rt_vec3 r = {d.y, -d.x, 0};
    double rl = sqrt(r.x * r.x + r.y * r.y);
    if (rl == 0)
        r = (rt_vec3){1, 0, 0}, rl = 1;
    rt_vec3 b = {a.x + 0.6 * r.x / rl, a.y + 0.6 * r.y / rl, a.z};
    rt_scene_desc desc = {
        .observer = eye, .screen_center = a, .screen_right = b,
        .width = side, .height = side,
        .vertices = s->v, .vertex_count = s->nv,
        .facets = s->f, .facet_count = s->nf,
        .background = {20, 30, 40},
        .lights = &(rt_light){light, {255, 240, 220}}, .light_count = 1};
    return soup_create(&desc, s);
}

static rt_vec3 jitter(rt_vec3 p, double r)
{
    return (rt_vec3){p.x + uniform(-r, r), p.y + uniform(-r, r),
                     p.z + uniform(-r, r)};
}

START_TEST(facets_all_in_one_spot_render_identically)
{
    soup s = {0};
    rt_vec3 c = {0.1, 0.2, 0.3};
    for (int i = 0; i < (reduced() ? 200 : 3000); i++)
        soup_add(&s, jitter(c, 1e-3), jitter(c, 1e-3), jitter(c, 1e-3),
                 i % 4 == 0 ? 0.5 : 0.0);
    /* and one big floor far away, so the box is large */
    soup_add(&s, (rt_vec3){-50, -50, -1}, (rt_vec3){50, -50, -1},
             (rt_vec3){0, 50, -1}, 0.3);
    rt_scene *scene = soup_scene(&s, (rt_vec3){0.1, 0.2 - 0.01, 0.31},
                                 c, (rt_vec3){1, 1, 3},
                                     reduced() ? 12 : 48);
    check_scene(scene, (image_size){0, 0}, "one spot");
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(a_few_facets_spanning_everything_render_identically)
{
    soup s = {0};
    for (int i = 0; i < 40; i++)
        soup_add(&s, jitter((rt_vec3){-10, -10, 0}, 3),
                 jitter((rt_vec3){10, -10, 0}, 3),
                 jitter((rt_vec3){0, 10, 0}, 3), i % 3 == 0 ? 0.6 : 0.0);
    for (int i = 0; i < 200; i++) {     /* small ones among them */
        rt_vec3 p = {uniform(-5, 5), uniform(-5, 5), uniform(-2, 2)};
        soup_add(&s, p, jitter(p, 0.3), jitter(p, 0.3), 0.0);
    }
    rt_scene *scene = soup_scene(&s, (rt_vec3){0, -15, 6}, (rt_vec3){0, 0, 0},
                                 (rt_vec3){3, -4, 12},
                                     reduced() ? 12 : 48);
    check_scene(scene, (image_size){0, 0}, "spanning");
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(slivers_beside_huge_walls_render_identically)
{
    soup s = {0};
    /* walls of 1e6, a floor, and slivers 1e-6 thin near the centre */
    soup_add(&s, (rt_vec3){-1e6, 5, -1e6}, (rt_vec3){1e6, 5, -1e6},
             (rt_vec3){0, 5, 1e6}, 0.5);
    soup_add(&s, (rt_vec3){-1e6, -1e6, -2}, (rt_vec3){1e6, -1e6, -2},
             (rt_vec3){0, 1e6, -2}, 0.0);
    for (int i = 0; i < (reduced() ? 100 : 1500); i++) {
        rt_vec3 p = {uniform(-2, 2), uniform(-1, 3), uniform(-1.5, 1.5)};
        rt_vec3 q = jitter(p, 1.0);
        rt_vec3 m = {(p.x + q.x) / 2 + uniform(-1e-6, 1e-6),
                     (p.y + q.y) / 2 + uniform(-1e-6, 1e-6),
                     (p.z + q.z) / 2 + uniform(-1e-6, 1e-6)};
        if (i % 3 == 0)         /* an ordinary one now and then */
            m = jitter(p, 0.4);
        soup_add(&s, p, q, m, i % 5 == 0 ? 0.4 : 0.0);
    }
    rt_scene *scene = soup_scene(&s, (rt_vec3){0.3, -6, 1.5},
                                 (rt_vec3){0, 1, 0}, (rt_vec3){-2, -3, 4},
                                 reduced() ? 12 : 56);
    check_scene(scene, (image_size){0, 0}, "slivers and walls");
    rt_scene_destroy(scene);
}
END_TEST

/* Coincident and overlapping coplanar facets in shuffled order: the tie
 * rule (the first in the file stays) must decide the same whatever leaves
 * the facets come from. */
START_TEST(coincident_facets_keep_the_tie_of_the_file_order)
{
    soup s = {0};
    int n = reduced() ? 60 : 600;
    for (int i = 0; i < n; i++) {
        double x = uniform(-3, 3), y = uniform(-3, 3);
        double size = uniform(0.2, 2.5);
        double z = (i % 3) * 0.5;   /* three planes */
        rt_vec3 a = {x, y, z}, b = {x + size, y, z},
                c = {x + uniform(-1, 1) * size, y + size, z};
        soup_add(&s, a, b, c, i % 7 == 0 ? 0.5 : 0.0);
        if (i % 2 == 0)         /* the same facet again, other vertex order */
            soup_add(&s, c, a, b, 0.0);
    }
    rt_scene *scene = soup_scene(&s, (rt_vec3){0.5, -7, 6},
                                 (rt_vec3){0, 0, 0}, (rt_vec3){1, -2, 9},
                                 reduced() ? 12 : 64);
    check_scene(scene, (image_size){0, 0}, "coincident");
    rt_scene_destroy(scene);
}
END_TEST

/* A mesh seen from very far (most rays fall back to brute force) and one
 * seen from inside. */
START_TEST(far_and_inside_cameras_render_identically)
{
    soup s = {0};
    for (int i = 0; i < 400; i++) {
        rt_vec3 p = {uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
        soup_add(&s, p, jitter(p, 0.2), jitter(p, 0.2), i % 4 ? 0.0 : 0.7);
    }
    soup t = {0};
    for (int i = 0; i < s.nf; i++)
        soup_add(&t, s.v[3 * i], s.v[3 * i + 1], s.v[3 * i + 2],
                 s.f[i].reflection);
    rt_scene *far = soup_scene(&s, (rt_vec3){1e5, -2e5, 3e4},
                               (rt_vec3){0, 0, 0}, (rt_vec3){5, 5, 5},
                               reduced() ? 12 : 40);
    check_scene(far, (image_size){0, 0}, "far camera");
    rt_scene_destroy(far);
    rt_scene *inside = soup_scene(&t, (rt_vec3){0.01, 0.02, 0.03},
                                  (rt_vec3){1, 0.5, 0.2}, (rt_vec3){0, 0, 0},
                                  reduced() ? 12 : 40);
    check_scene(inside, (image_size){0, 0}, "inside");
    rt_scene_destroy(inside);
}
END_TEST

/* Transparent facets (refraction, total internal reflection), several
 * lights and a thin lens: every query of the ray tree goes through the
 * octree too. */
START_TEST(transparency_lights_and_lens_render_identically)
{
    soup s = {0};
    for (int i = 0; i < (reduced() ? 150 : 1200); i++) {
        rt_vec3 p = {uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
        soup_add(&s, p, jitter(p, 0.3), jitter(p, 0.3), i % 5 ? 0.0 : 0.3);
        if (i % 3 == 0) {
            s.f[s.nf - 1].transparency = 0.6;
            s.f[s.nf - 1].refractive_index = i % 2 ? 1.5 : 0.7;
        }
    }
    rt_light lights[3] = {{{1, -2, 5}, {255, 255, 255}},
                          {{-3, 2, 4}, {120, 200, 90}},
                          {{2, -4, -3}, {200, 80, 150}}};
    rt_scene_desc desc = {
        .observer = {0.2, -4, 0.5}, .screen_center = {0.2, -3, 0.45},
        .screen_right = {0.8, -3, 0.45},
        .width = reduced() ? 12 : 48,
            .height = reduced() ? 12 : 48,
        .vertices = s.v, .vertex_count = s.nv,
        .facets = s.f, .facet_count = s.nf,
        .background = {30, 40, 50},
        .lights = lights, .light_count = 3,
        .aperture = 0.05, .focal_distance = 4};
    rt_scene *scene = soup_create(&desc, &s);
    check_scene(scene, (image_size){0, 0}, "transparency, lights, lens");
    rt_scene_destroy(scene);
}
END_TEST

/* Coordinates at the limit a scene may hold (1e152): cell boxes, margins
 * and intervals stay finite, and the image stays brute force's (double
 * only: a float render of such a scene is refused). */
START_TEST(coordinates_at_the_limit_of_a_scene_render_identically)
{
    soup s = {0};
    double big = 8e151;
    for (int i = 0; i < 400; i++) {
        rt_vec3 p = {uniform(-big, big), uniform(-big, big), uniform(-1, 1)};
        rt_vec3 q = {p.x + uniform(-1e151, 1e151),
                     p.y + uniform(-1e151, 1e151), uniform(-1, 1)};
        rt_vec3 r = {p.x + uniform(-1e151, 1e151),
                     p.y + uniform(-1e151, 1e151), uniform(-1, 1)};
        soup_add(&s, p, q, r, i % 4 ? 0.0 : 0.5);
    }
    rt_scene_desc desc = {
        .observer = {0, -1e151, 5e150}, .screen_center = {0, 0, 4e150},
        .screen_right = {1e151, 0, 4e150},
        .width = reduced() ? 8 : 32,
            .height = reduced() ? 8 : 32,
        .vertices = s.v, .vertex_count = s.nv,
        .facets = s.f, .facet_count = s.nf,
        .background = {20, 30, 40},
        .lights = &(rt_light){{1e150, -2e150, 5e151}, {255, 255, 255}},
        .light_count = 1};
    rt_scene *scene = soup_create(&desc, &s);
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
static void check_ray(const rt_kernel *kd, const rt_kernel *kf,
                      rt_vec3 origin, rt_vec3 target)
{
    rt_vec3 d = {target.x - origin.x, target.y - origin.y,
                 target.z - origin.z};
    if (d.x == 0 && d.y == 0 && d.z == 0)
        return;
    for (int kernel = 0; kernel < 2; kernel++) {
        rt_trace_settings brute = {5, 0, (rt_kernel_choice)kernel, NULL, 0};
        rt_trace_settings tree = {5, 0, (rt_kernel_choice)kernel, NULL, 1};
        rt_counters c = {0};
        rt_color a = rt__kernel_trace(kd, origin, d, &brute, &c);
        rt_color b = rt__kernel_trace(kd, origin, d, &tree, &c);
        ck_assert_msg(memcmp(&a, &b, sizeof a) == 0,
                      "double: (%.17g %.17g %.17g) -> (%.17g %.17g %.17g)",
                      origin.x, origin.y, origin.z, target.x, target.y,
                      target.z);
        a = rt__kernel_trace(kf, origin, d, &brute, &c);
        b = rt__kernel_trace(kf, origin, d, &tree, &c);
        ck_assert_msg(memcmp(&a, &b, sizeof a) == 0,
                      "float: (%.9g %.9g %.9g) -> (%.9g %.9g %.9g)",
                      origin.x, origin.y, origin.z, target.x, target.y,
                      target.z);
    }
}

/* An n x n grid of unit squares in z = 0 (every vertex an integer: cell
 * faces of the octree fall on its edges) with a reflective box over it. */
static rt_scene *grid_scene(int n)
{
    soup s = {0};
    for (int y = 0; y < n; y++)
        for (int x = 0; x < n; x++) {
            rt_vec3 a = {x, y, 0}, b = {x + 1, y, 0}, c = {x, y + 1, 0},
                    d = {x + 1, y + 1, 0};
            soup_add(&s, a, b, d, (x + y) % 3 == 0 ? 0.5 : 0.0);
            soup_add(&s, a, d, c, 0.0);
        }
    soup_add(&s, (rt_vec3){0, 0, 2}, (rt_vec3){n, 0, 2}, (rt_vec3){0, n, 2},
             0.8);
    return soup_scene(&s, (rt_vec3){n / 2.0, -n / 2.0, 1},
                      (rt_vec3){n / 2.0, n / 2.0, 0},
                      (rt_vec3){n / 3.0, n / 4.0, 1.5}, 8);
}

START_TEST(rays_grazing_and_along_cell_faces_see_the_same_through_the_octree)
{
    const int n = 16;
    rt_scene *scene = grid_scene(n);
    const rt_kernel *kf = rt__scene_kernel(scene, RT_PRECISION_FLOAT, NULL);
    ck_assert_ptr_nonnull(kf);
    ck_assert_int_eq(rt__kernel_prepare_octree(scene->kernel, NULL, NULL), RT_OK);
    ck_assert_int_eq(rt__kernel_prepare_octree(kf, NULL, NULL), RT_OK);
    int count = reduced() ? 300 : 6000;
    for (int i = 0; i < count; i++) {
        rt_vec3 o, t;
        switch (i % 4) {
        case 0:     /* random, from above or below */
            o = (rt_vec3){uniform(-2, n + 2), uniform(-2, n + 2),
                          uniform(-3, 3)};
            t = (rt_vec3){uniform(0, n), uniform(0, n), 0};
            break;
        case 1:     /* grazing the grid's plane */
            o = (rt_vec3){uniform(-2, 0), uniform(0, n), uniform(1e-9, 1e-3)};
            t = (rt_vec3){n + 1, uniform(0, n), -uniform(0, 1e-3)};
            break;
        case 2:     /* in the plane of a cell face (integer x) */
            o = (rt_vec3){(int)uniform(0, n), -1, uniform(0.1, 1.9)};
            t = (rt_vec3){o.x, n + 1, uniform(-1, 1)};
            break;
        default:    /* through a vertex, from anywhere */
            o = (rt_vec3){uniform(-n, 2 * n), uniform(-n, 2 * n),
                          uniform(-5, 5)};
            t = (rt_vec3){(int)uniform(0, n), (int)uniform(0, n), 0};
        }
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

START_TEST(auto_uses_the_octree_from_the_threshold_on)
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
    ck_assert_uint_gt(stats.accel_leaves, 1);
    ck_assert_uint_gt(stats.accel_queries, 0);
    ck_assert_uint_lt(stats.accel_facet_tests,
                      stats.accel_queries * stats.accel_facets);
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
    soup s = {0};
    rt_vec3 c = {1, 1, 1};
    for (int i = 0; i < 5000; i++)      /* 5000 facets through one point */
        soup_add(&s, c, jitter(c, 10), jitter(c, 10), 0.0);
    rt_scene *scene = soup_scene(&s, (rt_vec3){1, -30, 1}, c,
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
    tcase_add_test(choice, auto_uses_the_octree_from_the_threshold_on);
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
