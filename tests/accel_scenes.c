/*
 * accel_scenes.c - the soups, hard distributions and byte-for-byte checks
 * the accelerators' comparison tests share (accel_scenes.h).  The
 * reference is brute force in the same process: the fold over every facet
 * in file order, which tests/test_kernel.c and the expected images check
 * on their own.
 */
#include "accel_scenes.h"

#include <glob.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static double uniform(rt_test_rng *rng, double lo, double hi)
{
    return rt_test_rng_range(rng, lo, hi);
}

void accel_soup_add(accel_soup *s, rt_vec3 a, rt_vec3 b, rt_vec3 c, double k)
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

rt_scene *accel_soup_create(const rt_scene_desc *desc, accel_soup *s)
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

rt_scene *accel_soup_scene(accel_soup *s, rt_vec3 eye, rt_vec3 at,
                           rt_vec3 light, int side)
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
    return accel_soup_create(&desc, s);
}

rt_vec3 accel_jitter(rt_test_rng *rng, rt_vec3 p, double r)
{
    return (rt_vec3){p.x + uniform(rng, -r, r), p.y + uniform(rng, -r, r),
                     p.z + uniform(rng, -r, r)};
}

/* --- the distributions ---------------------------------------------- */

rt_scene *accel_one_spot(rt_test_rng *rng, int small)
{
    accel_soup s = {0};
    rt_vec3 c = {0.1, 0.2, 0.3};
    for (int i = 0; i < (small ? 200 : 3000); i++)
        accel_soup_add(&s, accel_jitter(rng, c, 1e-3),
                       accel_jitter(rng, c, 1e-3),
                       accel_jitter(rng, c, 1e-3), i % 4 == 0 ? 0.5 : 0.0);
    /* and one big floor far away, so the box is large */
    accel_soup_add(&s, (rt_vec3){-50, -50, -1}, (rt_vec3){50, -50, -1},
                   (rt_vec3){0, 50, -1}, 0.3);
    return accel_soup_scene(&s, (rt_vec3){0.1, 0.2 - 0.01, 0.31}, c,
                            (rt_vec3){1, 1, 3}, small ? 12 : 48);
}

rt_scene *accel_spanning(rt_test_rng *rng, int small)
{
    accel_soup s = {0};
    for (int i = 0; i < 40; i++)
        accel_soup_add(&s, accel_jitter(rng, (rt_vec3){-10, -10, 0}, 3),
                       accel_jitter(rng, (rt_vec3){10, -10, 0}, 3),
                       accel_jitter(rng, (rt_vec3){0, 10, 0}, 3),
                       i % 3 == 0 ? 0.6 : 0.0);
    for (int i = 0; i < 200; i++) {     /* small ones among them */
        rt_vec3 p = {uniform(rng, -5, 5), uniform(rng, -5, 5),
                     uniform(rng, -2, 2)};
        accel_soup_add(&s, p, accel_jitter(rng, p, 0.3),
                       accel_jitter(rng, p, 0.3), 0.0);
    }
    return accel_soup_scene(&s, (rt_vec3){0, -15, 6}, (rt_vec3){0, 0, 0},
                            (rt_vec3){3, -4, 12}, small ? 12 : 48);
}

rt_scene *accel_slivers_and_walls(rt_test_rng *rng, int small)
{
    accel_soup s = {0};
    /* walls of 1e6, a floor, and slivers 1e-6 thin near the centre */
    accel_soup_add(&s, (rt_vec3){-1e6, 5, -1e6}, (rt_vec3){1e6, 5, -1e6},
                   (rt_vec3){0, 5, 1e6}, 0.5);
    accel_soup_add(&s, (rt_vec3){-1e6, -1e6, -2}, (rt_vec3){1e6, -1e6, -2},
                   (rt_vec3){0, 1e6, -2}, 0.0);
    for (int i = 0; i < (small ? 100 : 1500); i++) {
        rt_vec3 p = {uniform(rng, -2, 2), uniform(rng, -1, 3),
                     uniform(rng, -1.5, 1.5)};
        rt_vec3 q = accel_jitter(rng, p, 1.0);
        rt_vec3 m = {(p.x + q.x) / 2 + uniform(rng, -1e-6, 1e-6),
                     (p.y + q.y) / 2 + uniform(rng, -1e-6, 1e-6),
                     (p.z + q.z) / 2 + uniform(rng, -1e-6, 1e-6)};
        if (i % 3 == 0)         /* an ordinary one now and then */
            m = accel_jitter(rng, p, 0.4);
        accel_soup_add(&s, p, q, m, i % 5 == 0 ? 0.4 : 0.0);
    }
    return accel_soup_scene(&s, (rt_vec3){0.3, -6, 1.5}, (rt_vec3){0, 1, 0},
                            (rt_vec3){-2, -3, 4}, small ? 12 : 56);
}

/* Coincident and overlapping coplanar facets in shuffled order: the tie
 * rule (the first in the file stays) must decide the same whatever leaves
 * the facets come from. */
rt_scene *accel_coincident(rt_test_rng *rng, int small)
{
    accel_soup s = {0};
    int n = small ? 60 : 600;
    for (int i = 0; i < n; i++) {
        double x = uniform(rng, -3, 3), y = uniform(rng, -3, 3);
        double size = uniform(rng, 0.2, 2.5);
        double z = (i % 3) * 0.5;   /* three planes */
        rt_vec3 a = {x, y, z}, b = {x + size, y, z},
                c = {x + uniform(rng, -1, 1) * size, y + size, z};
        accel_soup_add(&s, a, b, c, i % 7 == 0 ? 0.5 : 0.0);
        if (i % 2 == 0)         /* the same facet again, other vertex order */
            accel_soup_add(&s, c, a, b, 0.0);
    }
    return accel_soup_scene(&s, (rt_vec3){0.5, -7, 6}, (rt_vec3){0, 0, 0},
                            (rt_vec3){1, -2, 9}, small ? 12 : 64);
}

/* A soup seen from very far (beyond the margin's reach), or from inside. */
rt_scene *accel_far_camera(rt_test_rng *rng, int small, int inside)
{
    accel_soup s = {0};
    for (int i = 0; i < 400; i++) {
        rt_vec3 p = {uniform(rng, -1, 1), uniform(rng, -1, 1),
                     uniform(rng, -1, 1)};
        accel_soup_add(&s, p, accel_jitter(rng, p, 0.2),
                       accel_jitter(rng, p, 0.2), i % 4 ? 0.0 : 0.7);
    }
    if (inside)
        return accel_soup_scene(&s, (rt_vec3){0.01, 0.02, 0.03},
                                (rt_vec3){1, 0.5, 0.2}, (rt_vec3){0, 0, 0},
                                small ? 12 : 40);
    return accel_soup_scene(&s, (rt_vec3){1e5, -2e5, 3e4}, (rt_vec3){0, 0, 0},
                            (rt_vec3){5, 5, 5}, small ? 12 : 40);
}

/* Transparent facets (refraction, total internal reflection), several
 * lights and a thin lens: every query of the ray tree goes through the
 * structure too. */
rt_scene *accel_transparency_lights_lens(rt_test_rng *rng, int small)
{
    accel_soup s = {0};
    for (int i = 0; i < (small ? 150 : 1200); i++) {
        rt_vec3 p = {uniform(rng, -1, 1), uniform(rng, -1, 1),
                     uniform(rng, -1, 1)};
        accel_soup_add(&s, p, accel_jitter(rng, p, 0.3),
                       accel_jitter(rng, p, 0.3), i % 5 ? 0.0 : 0.3);
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
        .width = small ? 12 : 48, .height = small ? 12 : 48,
        .vertices = s.v, .vertex_count = s.nv,
        .facets = s.f, .facet_count = s.nf,
        .background = {30, 40, 50},
        .lights = lights, .light_count = 3,
        .aperture = 0.05, .focal_distance = 4};
    return accel_soup_create(&desc, &s);
}

/* Coordinates at the limit a scene may hold (1e152): double only (a float
 * render of it is refused). */
rt_scene *accel_at_the_limit(rt_test_rng *rng, int small)
{
    accel_soup s = {0};
    double big = 8e151;
    for (int i = 0; i < 400; i++) {
        rt_vec3 p = {uniform(rng, -big, big), uniform(rng, -big, big),
                     uniform(rng, -1, 1)};
        rt_vec3 q = {p.x + uniform(rng, -1e151, 1e151),
                     p.y + uniform(rng, -1e151, 1e151), uniform(rng, -1, 1)};
        rt_vec3 r = {p.x + uniform(rng, -1e151, 1e151),
                     p.y + uniform(rng, -1e151, 1e151), uniform(rng, -1, 1)};
        accel_soup_add(&s, p, q, r, i % 4 ? 0.0 : 0.5);
    }
    rt_scene_desc desc = {
        .observer = {0, -1e151, 5e150}, .screen_center = {0, 0, 4e150},
        .screen_right = {1e151, 0, 4e150},
        .width = small ? 8 : 32, .height = small ? 8 : 32,
        .vertices = s.v, .vertex_count = s.nv,
        .facets = s.f, .facet_count = s.nf,
        .background = {20, 30, 40},
        .lights = &(rt_light){{1e150, -2e150, 5e151}, {255, 255, 255}},
        .light_count = 1};
    return accel_soup_create(&desc, &s);
}

rt_scene *accel_grid(int n)
{
    accel_soup s = {0};
    for (int y = 0; y < n; y++)
        for (int x = 0; x < n; x++) {
            rt_vec3 a = {x, y, 0}, b = {x + 1, y, 0}, c = {x, y + 1, 0},
                    d = {x + 1, y + 1, 0};
            accel_soup_add(&s, a, b, d, (x + y) % 3 == 0 ? 0.5 : 0.0);
            accel_soup_add(&s, a, d, c, 0.0);
        }
    accel_soup_add(&s, (rt_vec3){0, 0, 2}, (rt_vec3){n, 0, 2},
                   (rt_vec3){0, n, 2}, 0.8);
    return accel_soup_scene(&s, (rt_vec3){n / 2.0, -n / 2.0, 1},
                            (rt_vec3){n / 2.0, n / 2.0, 0},
                            (rt_vec3){n / 3.0, n / 4.0, 1.5}, 8);
}

void accel_grid_ray(rt_test_rng *rng, int n, int i, rt_vec3 *origin,
                    rt_vec3 *target)
{
    rt_vec3 o, t;
    switch (i % 4) {
    case 0:     /* random, from above or below */
        o = (rt_vec3){uniform(rng, -2, n + 2), uniform(rng, -2, n + 2),
                      uniform(rng, -3, 3)};
        t = (rt_vec3){uniform(rng, 0, n), uniform(rng, 0, n), 0};
        break;
    case 1:     /* grazing the grid's plane */
        o = (rt_vec3){uniform(rng, -2, 0), uniform(rng, 0, n),
                      uniform(rng, 1e-9, 1e-3)};
        t = (rt_vec3){n + 1, uniform(rng, 0, n), -uniform(rng, 0, 1e-3)};
        break;
    case 2:     /* in the plane of a cell face (integer x) */
        o = (rt_vec3){(int)uniform(rng, 0, n), -1, uniform(rng, 0.1, 1.9)};
        t = (rt_vec3){o.x, n + 1, uniform(rng, -1, 1)};
        break;
    default:    /* through a vertex, from anywhere */
        o = (rt_vec3){uniform(rng, -n, 2 * n), uniform(rng, -n, 2 * n),
                      uniform(rng, -5, 5)};
        t = (rt_vec3){(int)uniform(rng, 0, n), (int)uniform(rng, 0, n), 0};
    }
    *origin = o;
    *target = t;
}

/* --- the checks ------------------------------------------------------ */

static rt_image render(const rt_scene *scene, int width, int height,
                       rt_precision precision, rt_accel accel, int threads,
                       int samples, rt_render_stats *stats)
{
    rt_render_options options;
    rt_render_options_init(&options);
    options.width = width;
    options.height = height;
    options.precision = precision;
    options.accel = accel;
    options.threads = threads;
    options.samples = samples;
    options.stats = stats;
    return rt_test_render_with(scene, &options);
}

void accel_check_scene(const rt_scene *scene, int width, int height,
                       rt_accel accel, const char *name)
{
    for (int p = 0; p < 2; p++) {
        rt_precision precision = p ? RT_PRECISION_FLOAT : RT_PRECISION_DOUBLE;
        /* a scene float cannot resolve is refused alike with or without
         * the structure (rt_scene_check_precision) */
        if (rt_scene_check_precision(scene, precision, NULL) != RT_OK)
            continue;
        for (int samples = 1; samples <= 4; samples += 3) {
            rt_render_stats s_ref = {.size = sizeof s_ref};
            rt_render_stats s_acc = {.size = sizeof s_acc};
            rt_image ref = render(scene, width, height, precision,
                                  RT_ACCEL_NONE, 1, samples, &s_ref);
            rt_image one = render(scene, width, height, precision, accel, 1,
                                  samples, &s_acc);
            rt_image three = render(scene, width, height, precision, accel,
                                    3, samples, NULL);
            ck_assert_msg(rt_test_image_diff(&ref, &one, NULL) == 0,
                          "%s (%s, %d samples): the structure changed the "
                          "image", name, p ? "float" : "double", samples);
            ck_assert_msg(rt_test_image_diff(&ref, &three, NULL) == 0,
                          "%s (%s, %d samples): the structure on 3 threads "
                          "changed the image",
                          name, p ? "float" : "double", samples);
            ck_assert_uint_eq(s_ref.shadow_rays, s_acc.shadow_rays);
            ck_assert_uint_eq(s_ref.reflection_rays, s_acc.reflection_rays);
            ck_assert_int_eq(s_ref.accel_used, 0);
            ck_assert_int_eq(s_acc.accel_used, 1);
            ck_assert_int_eq(s_acc.accel_kdtree, accel == RT_ACCEL_KDTREE);
            rt_image_release(&ref);
            rt_image_release(&one);
            rt_image_release(&three);
        }
    }
}

size_t accel_check_directory(const char *dir, int side, rt_accel accel)
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
        accel_check_scene(scene, w, h, accel, g.gl_pathv[i]);
        rt_scene_destroy(scene);
    }
    size_t count = g.gl_pathc;
    globfree(&g);
    return count;
}

void accel_check_ray(const rt_kernel *kd, const rt_kernel *kf,
                     rt_vec3 origin, rt_vec3 target,
                     const rt_trace_settings *tree)
{
    rt_vec3 d = {target.x - origin.x, target.y - origin.y,
                 target.z - origin.z};
    if (d.x == 0 && d.y == 0 && d.z == 0)
        return;
    /* the brute-force AVX2 loops read the kernels' blocks */
    ck_assert_int_eq(rt__kernel_prepare_blocks(kd), RT_OK);
    ck_assert_int_eq(rt__kernel_prepare_blocks(kf), RT_OK);
    for (int kernel = 0; kernel < 2; kernel++) {
        rt_trace_settings brute = {5, 0, (rt_kernel_choice)kernel, NULL, 0,
                                   NULL, 0};
        rt_trace_settings through = *tree;
        through.kernel = (rt_kernel_choice)kernel;
        rt_counters c = {0};
        rt_color a = rt__kernel_trace(kd, origin, d, &brute, &c);
        rt_color b = rt__kernel_trace(kd, origin, d, &through, &c);
        ck_assert_msg(memcmp(&a, &b, sizeof a) == 0,
                      "double: (%.17g %.17g %.17g) -> (%.17g %.17g %.17g)",
                      origin.x, origin.y, origin.z, target.x, target.y,
                      target.z);
        a = rt__kernel_trace(kf, origin, d, &brute, &c);
        b = rt__kernel_trace(kf, origin, d, &through, &c);
        ck_assert_msg(memcmp(&a, &b, sizeof a) == 0,
                      "float: (%.9g %.9g %.9g) -> (%.9g %.9g %.9g)",
                      origin.x, origin.y, origin.z, target.x, target.y,
                      target.z);
    }
}
