/*
 * test_shading.c - smooth shading and highlights through the public API
 * (docs/rendering-model.md, "Smooth shading and highlights"): the
 * description's vertex normals and highlight fields, their rules and
 * accessors; the shading normal, the shading point and the highlight of
 * rt_trace against values worked out here from the geometry; the same
 * bytes from every kernel and accelerator; what a scene without them
 * keeps (the same bytes with zero normals); the shading-normal view and
 * the explanation's new fields.
 */
#include "testutil.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define COLOR_TOL 1e-9
#define PI 3.14159265358979323846

/* A square of side 20 in z = 0 (two facets, corners 0..3), colour
 * C_F = (200, 100, 50), background (10, 20, 30), light C_S = (255, 128, 64)
 * at `light`; the camera above looks down.  `normals` (NULL: none) gives
 * the 4 corners' normals; `s`, `p` the highlight; `d` < 0: 1 - k. */
static rt_scene *square(const rt_vec3 *normals, double s, double p,
                        double d, rt_vec3 light)
{
    static const rt_vec3 corners[4] = {
        {-10, -10, 0}, {10, -10, 0}, {10, 10, 0}, {-10, 10, 0}};
    rt_facet_desc f[2];
    memset(f, 0, sizeof f);
    for (int i = 0; i < 2; i++) {
        f[i].color = (rt_rgb8){200, 100, 50};
        f[i].highlight = s;
        f[i].highlight_exponent = p;
        f[i].diffuse = d;
        f[i].diffuse_given = d >= 0;
    }
    f[0].vertex[0] = 0, f[0].vertex[1] = 1, f[0].vertex[2] = 2;
    f[1].vertex[0] = 0, f[1].vertex[1] = 2, f[1].vertex[2] = 3;
    rt_light l = {light, {255, 128, 64}};
    rt_scene_desc desc = {0};
    desc.observer = (rt_vec3){0, 0, 8};
    desc.screen_center = (rt_vec3){0, 0, 7};
    desc.screen_right = (rt_vec3){1, 0, 7};
    desc.width = 40;
    desc.height = 40;
    desc.vertices = corners;
    desc.vertex_count = 4;
    desc.facets = f;
    desc.facet_count = 2;
    desc.background = (rt_rgb8){10, 20, 30};
    desc.lights = &l;
    desc.light_count = 1;
    desc.normals = normals;
    rt_scene *scene = NULL;
    rt_error error;
    rt_status status = rt_scene_create(&desc, &scene, &error);
    ck_assert_msg(status == RT_OK, "rt_scene_create: %s", error.message);
    return scene;
}

static rt_vec3 unit(rt_vec3 v)
{
    double n = sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    return (rt_vec3){v.x / n, v.y / n, v.z / n};
}

static double dot3(rt_vec3 a, rt_vec3 b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

START_TEST(normals_are_normalised_counted_and_read_back)
{
    rt_vec3 n[4] = {{0, 0, 3}, {0, 0, 0.5}, {1e-3, 0, 1e-3}, {0, 0, 0}};
    rt_scene *scene = square(n, 0.5, 20, -1, (rt_vec3){0, 0, 10});
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    /* facet 0 has three normals, facet 1 lacks corner 3's */
    ck_assert_int_eq(info.smooth_facet_count, 1);
    ck_assert_int_eq(info.highlight_facet_count, 2);
    rt_vec3 got = rt_scene_vertex_normal(scene, 2);
    ck_assert(fabs(got.x - sqrt(0.5)) < 1e-15 && got.y == 0.0 &&
              fabs(got.z - sqrt(0.5)) < 1e-15);
    got = rt_scene_vertex_normal(scene, 3);
    ck_assert(got.x == 0.0 && got.y == 0.0 && got.z == 0.0);
    rt_facet_info f = {.size = sizeof f};
    rt_scene_facet(scene, 0, &f);
    ck_assert_int_eq(f.smooth, 1);
    ck_assert(f.vertex_normal[0].z == 1.0 && f.vertex_normal[1].z == 1.0);
    ck_assert(f.highlight == 0.5 && f.highlight_exponent == 20);
    rt_scene_facet(scene, 1, &f);
    ck_assert_int_eq(f.smooth, 0);
    ck_assert(f.vertex_normal[0].z == 0.0);
    rt_scene_destroy(scene);

    /* no normals, p = 0 stands for 1 */
    scene = square(NULL, 0, 0, -1, (rt_vec3){0, 0, 10});
    rt_scene_get_info(scene, &info);
    ck_assert_int_eq(info.smooth_facet_count, 0);
    ck_assert_int_eq(info.highlight_facet_count, 0);
    rt_scene_facet(scene, 0, &f);
    ck_assert(f.highlight == 0.0 && f.highlight_exponent == 1.0);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(bad_normals_and_highlights_are_refused)
{
    static const rt_vec3 v[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    rt_vec3 n[3] = {{0, 0, 1}, {0, NAN, 1}, {0, 0, 1}};
    rt_facet_desc f = {{0, 1, 2}, 0, {1, 2, 3}, 0, 0, 0, 0, 0, 0};
    rt_light l = {{0, 0, 5}, {255, 255, 255}};
    rt_scene_desc d = {0};
    d.observer = (rt_vec3){0, 0, 5};
    d.screen_center = (rt_vec3){0, 0, 4};
    d.screen_right = (rt_vec3){1, 0, 4};
    d.width = d.height = 4;
    d.vertices = v;
    d.vertex_count = 3;
    d.facets = &f;
    d.facet_count = 1;
    d.lights = &l;
    d.light_count = 1;
    d.normals = n;
    rt_scene *scene;
    rt_error e;
    ck_assert_int_eq(rt_scene_create(&d, &scene, &e), RT_ERR_RANGE);
    ck_assert_msg(strstr(e.message, "vertex 1") &&
                      strstr(e.message, "a finite vertex normal"),
                  "%s", e.message);
    n[1].y = 0;
    f.highlight = -0.5;
    ck_assert_int_eq(rt_scene_create(&d, &scene, &e), RT_ERR_RANGE);
    ck_assert_msg(strstr(e.message, "a highlight weight s >= 0"), "%s",
                  e.message);
    f.highlight = 0.5;
    f.highlight_exponent = 0.5;
    ck_assert_int_eq(rt_scene_create(&d, &scene, &e), RT_ERR_RANGE);
    ck_assert_msg(strstr(e.message, "a highlight exponent p >= 1"), "%s",
                  e.message);
    f.highlight_exponent = INFINITY;
    ck_assert_int_eq(rt_scene_create(&d, &scene, &e), RT_ERR_RANGE);
    f.highlight_exponent = 1;
    ck_assert_int_eq(rt_scene_create(&d, &scene, &e), RT_OK);
    rt_scene_destroy(scene);
}
END_TEST

/* One normal n for every corner: the shading normal is n wherever the
 * ray meets the square, so the diffuse term is (n.S) C_S C_F / 255. */
START_TEST(a_uniform_vertex_normal_is_the_shading_normal_of_every_hit)
{
    rt_vec3 n = unit((rt_vec3){0.3, -0.2, 1});
    rt_vec3 ns[4] = {n, n, n, n};
    rt_vec3 light = {4, 6, 10};
    rt_scene *scene = square(ns, 0, 1, -1, light);
    const double points[3][2] = {{0, 0}, {3.5, -2.25}, {-7, 6}};
    for (int i = 0; i < 3; i++) {
        rt_vec3 p = {points[i][0], points[i][1], 0};
        rt_color c =
            rt_trace(scene, (rt_ray){{p.x, p.y, 5}, {0, 0, -1}}, 5);
        double cosine =
            dot3(n, unit((rt_vec3){light.x - p.x, light.y - p.y, light.z}));
        rt_test_assert_color(c, cosine * 255 * 200 / 255,
                             cosine * 128 * 100 / 255,
                             cosine * 64 * 50 / 255, COLOR_TOL,
                             "uniform vertex normal");
    }
    rt_scene_destroy(scene);
}
END_TEST

/* The highlight: E s max(0, R.V)^p C_S with R = 2 (N.S) N - S, V = -I,
 * in the light's colour; with d = 0 it is the whole colour. */
START_TEST(the_highlight_is_phong_in_the_lights_colour)
{
    rt_vec3 light = {3, -2, 9};
    const double s = 0.7, p = 12;
    for (int flat = 0; flat < 2; flat++) {
        rt_vec3 up[4] = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
        rt_scene *scene = square(flat ? NULL : up, s, p, 0, light);
        const double points[3][2] = {{1.2, -0.8}, {1, 0}, {0, 0}};
        for (int i = 0; i < 3; i++) {
            rt_vec3 o = {points[i][0] + 0.5, points[i][1] - 0.25, 6};
            rt_vec3 hit = {points[i][0], points[i][1], 0};
            rt_vec3 d = {hit.x - o.x, hit.y - o.y, hit.z - o.z};
            rt_color c = rt_trace(scene, (rt_ray){o, d}, 0);
            rt_vec3 S = unit((rt_vec3){light.x - hit.x, light.y - hit.y,
                                       light.z - hit.z});
            rt_vec3 R = {-S.x, -S.y, S.z};  /* 2 (N.S) N - S, N = +z */
            rt_vec3 V = unit((rt_vec3){-d.x, -d.y, -d.z});
            double rv = dot3(R, V);
            double h = rv > 0 ? s * pow(rv, p) : 0;
            rt_test_assert_color(c, h * 255, h * 128, h * 64, 1e-7,
                                 flat ? "flat highlight"
                                      : "smooth highlight");
        }
        rt_scene_destroy(scene);
    }
}
END_TEST

/* Renders `scene` with `options` (or the defaults) into *image. */
static void render(const rt_scene *scene, const rt_render_options *options,
                   rt_image *image)
{
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    rt_error e;
    ck_assert_int_eq(rt_image_init(image, info.width, info.height, &e),
                     RT_OK);
    ck_assert_msg(rt_render(scene, options, image, &e) == RT_OK, "%s",
                  e.message);
}

/* A low-poly sphere (exact normals at its vertices, a highlight) above a
 * mirror floor, two lights: `smooth` 0 gives it no normals at all, -1
 * all-zero normals (which stand for none). */
static rt_scene *ball(int smooth)
{
    enum { NU = 9, NV = 6 };
    rt_vec3 v[(NV + 1) * NU + 4], n[(NV + 1) * NU + 4];
    rt_facet_desc f[2 * NV * NU + 2];
    int nv = 0, nf = 0;
    for (int j = 0; j <= NV; j++)
        for (int i = 0; i < NU; i++) {
            double th = PI * j / NV, ph = 2 * PI * i / NU;
            n[nv] = smooth > 0 ? (rt_vec3){sin(th) * cos(ph), cos(th),
                                           sin(th) * sin(ph)}
                               : (rt_vec3){0, 0, 0};
            v[nv++] = (rt_vec3){sin(th) * cos(ph), cos(th) + 1.1,
                                sin(th) * sin(ph)};
        }
    memset(f, 0, sizeof f);
    for (int j = 0; j < NV; j++)
        for (int i = 0; i < NU; i++) {
            int a = j * NU + i, b = j * NU + (i + 1) % NU;
            int quad[2][3] = {{a, a + NU, b}, {b, a + NU, b + NU}};
            for (int t = 0; t < 2; t++, nf++) {
                memcpy(f[nf].vertex, quad[t], sizeof quad[t]);
                f[nf].color = (rt_rgb8){60, 160, 220};
                f[nf].highlight = 0.6;
                f[nf].highlight_exponent = 25;
            }
        }
    const rt_vec3 floor[4] = {{-4, 0, -4}, {4, 0, -4}, {4, 0, 4}, {-4, 0, 4}};
    for (int i = 0; i < 4; i++)
        n[nv] = (rt_vec3){0, 0, 0}, v[nv++] = floor[i];
    for (int t = 0; t < 2; t++, nf++) {
        int g = nv - 4;
        int tri[2][3] = {{g, g + 1, g + 2}, {g, g + 2, g + 3}};
        memcpy(f[nf].vertex, tri[t], sizeof tri[t]);
        f[nf].color = (rt_rgb8){200, 200, 200};
        f[nf].reflection = 0.4;
    }
    rt_light lights[2] = {{{5, 2, 1}, {255, 255, 255}},
                          {{-2, 5, 4}, {80, 80, 160}}};
    rt_scene_desc d = {0};
    d.observer = (rt_vec3){0, 1.8, 5};
    d.screen_center = (rt_vec3){0, 1.6, 4};
    d.screen_right = (rt_vec3){0.5, 1.6, 4};
    d.width = 64;
    d.height = 48;
    d.vertices = v;
    d.vertex_count = nv;
    d.facets = f;
    d.facet_count = nf;
    d.background = (rt_rgb8){20, 20, 40};
    d.lights = lights;
    d.light_count = 2;
    d.normals = smooth != 0 ? n : NULL;
    rt_scene *scene;
    rt_error e;
    ck_assert_msg(rt_scene_create(&d, &scene, &e) == RT_OK, "%s", e.message);
    return scene;
}

START_TEST(every_kernel_and_accelerator_gives_the_same_bytes)
{
    rt_scene *scene = ball(1);
    for (int precision = 0; precision < 2; precision++) {
        rt_render_options o;
        rt_render_options_init(&o);
        o.precision = precision ? RT_PRECISION_FLOAT : RT_PRECISION_DOUBLE;
        rt_image first;
        render(scene, &o, &first);
        const rt_kernel_choice kernels[] = {RT_KERNEL_AUTO, RT_KERNEL_SCALAR};
        const rt_accel accels[] = {RT_ACCEL_NONE, RT_ACCEL_OCTREE,
                                   RT_ACCEL_KDTREE};
        for (int k = 0; k < 2; k++)
            for (int a = 0; a < 3; a++)
                for (int threads = 1; threads <= 3; threads += 2) {
                    o.kernel = kernels[k];
                    o.accel = accels[a];
                    o.threads = threads;
                    rt_image other;
                    render(scene, &o, &other);
                    ck_assert_msg(rt_test_image_diff(&first, &other, NULL) ==
                                      0,
                                  "precision %d kernel %d accel %d threads "
                                  "%d differ",
                                  precision, k, a, threads);
                    rt_image_release(&other);
                }
        rt_image_release(&first);
    }
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(zero_normals_render_as_no_normals_and_smooth_ones_do_not)
{
    rt_scene *none = ball(0), *zero = ball(-1), *smooth = ball(1);
    rt_image a, b, c;
    render(none, NULL, &a);
    render(zero, NULL, &b);
    render(smooth, NULL, &c);
    ck_assert_int_eq(rt_test_image_diff(&a, &b, NULL), 0);
    ck_assert_int_gt(rt_test_image_diff(&a, &c, NULL), 100);
    rt_image_release(&a);
    rt_image_release(&b);
    rt_image_release(&c);
    rt_scene_destroy(none);
    rt_scene_destroy(zero);
    rt_scene_destroy(smooth);
}
END_TEST

static void view(const rt_scene *scene, rt_debug_view v, rt_image *image)
{
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    rt_error e;
    ck_assert_int_eq(rt_image_init(image, info.width, info.height, &e),
                     RT_OK);
    ck_assert_msg(rt_render_view(scene, NULL, v, 0, image, &e) == RT_OK,
                  "%s", e.message);
}

START_TEST(the_shading_normal_view_differs_from_the_normal_view_on_smooth_facets)
{
    rt_scene *flat = ball(0), *smooth = ball(1);
    rt_image a, b, c, d;
    view(flat, RT_VIEW_NORMAL, &a);
    view(flat, RT_VIEW_SHADING_NORMAL, &b);
    view(smooth, RT_VIEW_NORMAL, &c);
    view(smooth, RT_VIEW_SHADING_NORMAL, &d);
    ck_assert_int_eq(rt_test_image_diff(&a, &b, NULL), 0);
    ck_assert_int_eq(rt_test_image_diff(&a, &c, NULL), 0);
    ck_assert_int_gt(rt_test_image_diff(&c, &d, NULL), 100);
    rt_image_release(&a);
    rt_image_release(&b);
    rt_image_release(&c);
    rt_image_release(&d);
    rt_scene_destroy(flat);
    rt_scene_destroy(smooth);
}
END_TEST

/* The explanation of a pixel on the smooth ball: N_s unit and on N_g's
 * side, P' from the formula with the hit's barycentric weights, the
 * shadow rays leaving P' (by less than the offset), and each shadow ray's
 * term the diffuse one plus its highlight. */
START_TEST(the_explanation_gives_the_shading_normal_point_and_highlight)
{
    rt_scene *scene = ball(1);
    rt_ray_tree *tree;
    rt_error e;
    ck_assert_msg(rt_explain_pixel(scene, NULL, 36, 18, -1, &tree, &e) ==
                      RT_OK,
                  "%s", e.message);
    size_t count;
    const rt_ray_node *n = rt_ray_tree_nodes(tree, &count);
    ck_assert(count >= 3 && n[0].hit);
    ck_assert_int_eq(n[0].smooth, 1);
    ck_assert(fabs(dot3(n[0].shading_normal, n[0].shading_normal) - 1) <
              1e-12);
    ck_assert(dot3(n[0].shading_normal, n[0].normal) > 0);
    ck_assert(n[0].highlight == 0.6 && n[0].highlight_exponent == 25);

    /* P' by hand: the facet's corners and normals, the hit's weights
     * from areas (exact enough for 1e-9) */
    rt_facet_info f = {.size = sizeof f};
    rt_scene_facet(scene, n[0].facet, &f);
    rt_vec3 v[3];
    for (int j = 0; j < 3; j++)
        v[j] = rt_scene_vertex(scene, f.vertex[j]);
    rt_vec3 P = n[0].point, N = f.normal;
    double area[3];
    for (int j = 0; j < 3; j++) {
        rt_vec3 a = v[(j + 1) % 3], b = v[(j + 2) % 3];
        rt_vec3 pa = {a.x - P.x, a.y - P.y, a.z - P.z},
                pb = {b.x - P.x, b.y - P.y, b.z - P.z};
        rt_vec3 x = {pa.y * pb.z - pa.z * pb.y, pa.z * pb.x - pa.x * pb.z,
                     pa.x * pb.y - pa.y * pb.x};
        area[j] = dot3(x, N);
    }
    double total = area[0] + area[1] + area[2];
    rt_vec3 expected = P;
    for (int j = 0; j < 3; j++) {
        rt_vec3 ni = f.vertex_normal[j];
        double along = (P.x - v[j].x) * ni.x + (P.y - v[j].y) * ni.y +
                       (P.z - v[j].z) * ni.z;
        if (along < 0) {
            double w = area[j] / total * along;
            expected.x -= w * ni.x;
            expected.y -= w * ni.y;
            expected.z -= w * ni.z;
        }
    }
    rt_vec3 got = n[0].shading_point;
    ck_assert_msg(fabs(got.x - expected.x) < 1e-9 &&
                      fabs(got.y - expected.y) < 1e-9 &&
                      fabs(got.z - expected.z) < 1e-9,
                  "P' (%g %g %g), expected (%g %g %g)", got.x, got.y, got.z,
                  expected.x, expected.y, expected.z);
    /* on a convex ball P' lies outside the facet */
    ck_assert(dot3((rt_vec3){got.x - P.x, got.y - P.y, got.z - P.z},
                   n[0].normal) > 0);
    int shadows = 0;
    for (size_t i = 1; i < count; i++) {
        if (n[i].kind != RT_RAY_SHADOW || n[i].parent != 0 || !n[i].cast)
            continue;
        shadows++;
        rt_vec3 o = n[i].origin;
        ck_assert(fabs(o.x - got.x) < 1e-9 && fabs(o.y - got.y) < 1e-9 &&
                  fabs(o.z - got.z) < 1e-9);
        if (n[i].e > 0) {
            ck_assert(n[i].r_dot_v >= -1 && n[i].r_dot_v <= 1);
            double h = n[i].r_dot_v > 0 ? 0.6 * pow(n[i].r_dot_v, 25) : 0;
            rt_light l;
            rt_scene_light(scene, n[i].light, &l);
            ck_assert(fabs(n[i].highlight_own.r - h * l.color.r) < 1e-9);
            ck_assert(n[i].own.r >= n[i].highlight_own.r);
        }
    }
    ck_assert_int_gt(shadows, 0);
    rt_ray_tree_destroy(tree);
    rt_scene_destroy(scene);
}
END_TEST

static Suite *shading_suite(void)
{
    Suite *suite = suite_create("shading");
    TCase *tc = tcase_create("model");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, normals_are_normalised_counted_and_read_back);
    tcase_add_test(tc, bad_normals_and_highlights_are_refused);
    tcase_add_test(tc,
                   a_uniform_vertex_normal_is_the_shading_normal_of_every_hit);
    tcase_add_test(tc, the_highlight_is_phong_in_the_lights_colour);
    tcase_add_test(tc, every_kernel_and_accelerator_gives_the_same_bytes);
    tcase_add_test(tc,
                   zero_normals_render_as_no_normals_and_smooth_ones_do_not);
    tcase_add_test(
        tc,
        the_shading_normal_view_differs_from_the_normal_view_on_smooth_facets);
    tcase_add_test(tc,
                   the_explanation_gives_the_shading_normal_point_and_highlight);
    suite_add_tcase(suite, tc);
    return suite;
}

RT_CHECK_MAIN(shading_suite)
