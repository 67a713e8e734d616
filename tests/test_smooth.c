/*
 * test_smooth.c - analytic checks of smooth shading and highlights
 * (docs/rendering-model.md, "Smooth shading and highlights") through the
 * public API only, against values worked out here from the geometry:
 *
 *  - the shading normal at a mesh's vertices is the vertex's normal, at its
 *    edges' midpoints normalise(n_i + n_j), and at every hit the
 *    barycentric interpolation of the corners' normals;
 *  - the shading point P' is Hanika's formula, and P itself (bit for bit)
 *    on a facet whose corner normals are its geometric normal wherever no
 *    corner lies above the hit along its normal;
 *  - a Phong highlight peaks at the mirror point (R_l = V) and falls to
 *    half its peak at the angle acos(2^(-1/p)) between R_l and V, for
 *    p = 10, 50, 200.
 *
 * The cameras look straight down at the plane z = 0 from (0, 0, 10) with
 * the screen at z = 9, so pixel (i, j) of a w x h image sees, up to
 * rounding, the point 10 |AB| ((2i + 1 - w)/w, (h - 2j - 1)/w, 0)
 * (the rendering model's pixel centres): the points to check are placed on
 * those.
 */
#include "testutil.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "raytrace/explain.h"

static rt_vec3 v3(double x, double y, double z)
{
    return (rt_vec3){x, y, z};
}

static rt_vec3 sub3(rt_vec3 a, rt_vec3 b)
{
    return v3(a.x - b.x, a.y - b.y, a.z - b.z);
}

static rt_vec3 add3(rt_vec3 a, rt_vec3 b)
{
    return v3(a.x + b.x, a.y + b.y, a.z + b.z);
}

static rt_vec3 scale3(rt_vec3 a, double s)
{
    return v3(a.x * s, a.y * s, a.z * s);
}

static double dot3(rt_vec3 a, rt_vec3 b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

static rt_vec3 unit3(rt_vec3 a)
{
    return scale3(a, 1.0 / sqrt(dot3(a, a)));
}

static double dist3(rt_vec3 a, rt_vec3 b)
{
    rt_vec3 d = sub3(a, b);
    return sqrt(dot3(d, d));
}

/* ------------------------------------------------------------------ grid */

/* A 5 x 5 grid of vertices in z = 0, spacing 2, x and y in
 * {-4.5, -2.5, -0.5, 1.5, 3.5}: half-integers, which the 20 x 20 camera
 * below hits at pixel centres (pixel (i, j) sees (i - 9.5, 9.5 - j)), as
 * it does the edges' midpoints (odd integers from the vertices: still
 * half-integers).  Each square is cut along its diagonal from (gx, gy) to
 * (gx + 1, gy + 1). */
#define GRID 5
#define GRID_FACETS (2 * (GRID - 1) * (GRID - 1))

static rt_vec3 grid_vertices[GRID * GRID];
static rt_vec3 grid_normals[GRID * GRID];
static rt_facet_desc grid_facets[GRID_FACETS];

static int grid_index(int gx, int gy)
{
    return gy * GRID + gx;
}

/* tilted: each vertex its own normal (all with a positive z, so none is
 * turned); else every normal (0, 0, 2) (unit once normalised: N_g). */
static rt_scene *grid_scene(int tilted)
{
    for (int gy = 0; gy < GRID; gy++)
        for (int gx = 0; gx < GRID; gx++) {
            int i = grid_index(gx, gy);
            grid_vertices[i] = v3(-4.5 + 2 * gx, -4.5 + 2 * gy, 0);
            grid_normals[i] =
                tilted ? v3(0.35 * sin(1.7 * gx + 0.3 * gy),
                            0.3 * cos(0.9 * gx - 1.3 * gy), 1.0 + 0.1 * gx)
                       : v3(0, 0, 2);
        }
    memset(grid_facets, 0, sizeof grid_facets);
    int f = 0;
    for (int gy = 0; gy + 1 < GRID; gy++)
        for (int gx = 0; gx + 1 < GRID; gx++) {
            int a = grid_index(gx, gy), b = grid_index(gx + 1, gy);
            int c = grid_index(gx + 1, gy + 1), d = grid_index(gx, gy + 1);
            int tri[2][3] = {{a, b, c}, {a, c, d}};
            for (int t = 0; t < 2; t++, f++) {
                for (int k = 0; k < 3; k++)
                    grid_facets[f].vertex[k] = tri[t][k];
                grid_facets[f].color = (rt_rgb8){180, 180, 180};
            }
        }
    rt_light light = {{1, 2, 30}, {255, 255, 255}};
    rt_scene_desc desc = {0};
    desc.observer = v3(0, 0, 10);
    desc.screen_center = v3(0, 0, 9);
    desc.screen_right = v3(1, 0, 9);
    desc.width = 20;
    desc.height = 20;
    desc.vertices = grid_vertices;
    desc.vertex_count = GRID * GRID;
    desc.facets = grid_facets;
    desc.facet_count = GRID_FACETS;
    desc.background = (rt_rgb8){0, 0, 0};
    desc.lights = &light;
    desc.light_count = 1;
    desc.normals = grid_normals;
    rt_scene *scene = NULL;
    rt_error error;
    rt_status status = rt_scene_create(&desc, &scene, &error);
    ck_assert_msg(status == RT_OK, "rt_scene_create: %s", error.message);
    return scene;
}

/* The camera ray's node of pixel (i, j) (the tree's first node), copied;
 * the tree is freed. */
static rt_ray_node camera_node(const rt_scene *scene, int i, int j)
{
    rt_ray_tree *tree = NULL;
    rt_error error;
    rt_status status = rt_explain_pixel(scene, NULL, i, j, -1, &tree, &error);
    ck_assert_msg(status == RT_OK, "rt_explain_pixel(%d, %d): %s", i, j,
                  error.message);
    size_t count = 0;
    const rt_ray_node *nodes = rt_ray_tree_nodes(tree, &count);
    ck_assert_uint_gt(count, 0);
    ck_assert_int_eq(nodes[0].kind, RT_RAY_CAMERA);
    rt_ray_node node = nodes[0];
    rt_ray_tree_destroy(tree);
    return node;
}

/* The barycentric weights of p (in z = 0) in grid facet f. */
static void grid_weights(int f, rt_vec3 p, double w[3])
{
    rt_vec3 a = grid_vertices[grid_facets[f].vertex[0]];
    rt_vec3 b = grid_vertices[grid_facets[f].vertex[1]];
    rt_vec3 c = grid_vertices[grid_facets[f].vertex[2]];
    double det = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    w[1] = ((p.x - a.x) * (c.y - a.y) - (c.x - a.x) * (p.y - a.y)) / det;
    w[2] = ((b.x - a.x) * (p.y - a.y) - (p.x - a.x) * (b.y - a.y)) / det;
    w[0] = 1.0 - w[1] - w[2];
}

/* The pixel (i, j) of the grid camera that sees point p. */
static void pixel_of(rt_vec3 p, int *i, int *j)
{
    *i = (int)lround(p.x + 9.5);
    *j = (int)lround(9.5 - p.y);
}

/* The shading normal is a unit vector within `tol` of `want`. */
static void assert_normal(rt_vec3 got, rt_vec3 want, double tol,
                          const char *what, int i, int j)
{
    ck_assert_msg(fabs(dot3(got, got) - 1.0) < 1e-12,
                  "%s, pixel (%d, %d): N_s is not unit (|N_s|^2 = %.17g)",
                  what, i, j, dot3(got, got));
    ck_assert_msg(dist3(got, want) < tol,
                  "%s, pixel (%d, %d): N_s (%.15g, %.15g, %.15g), expected "
                  "(%.15g, %.15g, %.15g)",
                  what, i, j, got.x, got.y, got.z, want.x, want.y, want.z);
}

/* Tolerance of the normal checks: the hit point is the pixel centre's
 * point up to a few ulps of 10 (~1e-14), the normals vary by less than 1
 * per unit length, normalisation adds a few ulps: 1e-12 has room. */
#define NORMAL_TOL 1e-12

START_TEST(the_shading_normal_is_the_vertex_normal_at_each_vertex)
{
    rt_scene *scene = grid_scene(1);
    int checked = 0;
    /* the inner vertices: on facets all round, so the hit is on one of
     * them whichever way a border is decided, and each gives n_v */
    for (int gy = 1; gy + 1 < GRID; gy++)
        for (int gx = 1; gx + 1 < GRID; gx++) {
            int v = grid_index(gx, gy), i, j;
            pixel_of(grid_vertices[v], &i, &j);
            rt_ray_node node = camera_node(scene, i, j);
            ck_assert_msg(node.hit && node.smooth,
                          "pixel (%d, %d) misses the smooth grid", i, j);
            ck_assert(dist3(node.point, grid_vertices[v]) < 1e-13);
            assert_normal(node.shading_normal, unit3(grid_normals[v]),
                          NORMAL_TOL, "at a vertex", i, j);
            checked++;
        }
    ck_assert_int_eq(checked, (GRID - 2) * (GRID - 2));
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(the_shading_normal_at_an_edge_midpoint_is_the_mean_normal)
{
    rt_scene *scene = grid_scene(1);
    int checked = 0;
    for (int f = 0; f < GRID_FACETS; f++)
        for (int e = 0; e < 3; e++) {
            int a = grid_facets[f].vertex[e];
            int b = grid_facets[f].vertex[(e + 1) % 3];
            rt_vec3 m = scale3(add3(grid_vertices[a], grid_vertices[b]), 0.5);
            /* midpoints on the grid's outer border have one facet only:
             * skipped (a border hit is the intersection test's call) */
            if (m.x == -4.5 || m.x == 3.5 || m.y == -4.5 || m.y == 3.5)
                continue;
            int i, j;
            pixel_of(m, &i, &j);
            rt_ray_node node = camera_node(scene, i, j);
            ck_assert_msg(node.hit && node.smooth,
                          "pixel (%d, %d) misses the smooth grid", i, j);
            ck_assert(dist3(node.point, m) < 1e-13);
            rt_vec3 want = unit3(add3(unit3(grid_normals[a]),
                                      unit3(grid_normals[b])));
            assert_normal(node.shading_normal, want, NORMAL_TOL,
                          "at an edge's midpoint", i, j);
            checked++;
        }
    /* every facet's 3 edges, less the 16 border edges' single visits */
    ck_assert_int_eq(checked, GRID_FACETS * 3 - 4 * (GRID - 1));
    rt_scene_destroy(scene);
}
END_TEST

/* Hanika's shading point, as docs/rendering-model.md writes it:
 * P' = P - sum_i b_i min(0, (P - v_i).n_i) n_i. */
static rt_vec3 hanika_point(int f, rt_vec3 p, const double w[3])
{
    rt_vec3 shift = v3(0, 0, 0);
    for (int k = 0; k < 3; k++) {
        int v = grid_facets[f].vertex[k];
        rt_vec3 n = unit3(grid_normals[v]);
        double along = dot3(sub3(p, grid_vertices[v]), n);
        if (along < 0)
            shift = add3(shift, scale3(n, w[k] * along));
    }
    return sub3(p, shift);
}

START_TEST(every_hit_interpolates_the_normals_and_moves_to_hanikas_point)
{
    rt_scene *scene = grid_scene(1);
    int hits = 0, moved = 0;
    for (int j = 0; j < 20; j++)
        for (int i = 0; i < 20; i++) {
            rt_ray_node node = camera_node(scene, i, j);
            if (!node.hit)
                continue;
            hits++;
            ck_assert(node.smooth);
            ck_assert(node.facet >= 0 && node.facet < GRID_FACETS);
            double w[3];
            grid_weights(node.facet, node.point, w);
            for (int k = 0; k < 3; k++)
                ck_assert(w[k] > -1e-12);
            rt_vec3 sum = v3(0, 0, 0);
            for (int k = 0; k < 3; k++)
                sum = add3(sum, scale3(unit3(grid_normals[grid_facets
                                                              [node.facet]
                                                                  .vertex[k]]),
                                       w[k]));
            assert_normal(node.shading_normal, unit3(sum), NORMAL_TOL,
                          "interpolated", i, j);
            /* the geometric normal faces the camera: +z */
            ck_assert(node.normal.z == 1.0);
            rt_vec3 want = hanika_point(node.facet, node.point, w);
            ck_assert_msg(dist3(node.shading_point, want) < 1e-12,
                          "pixel (%d, %d): P' (%.15g, %.15g, %.15g), "
                          "expected (%.15g, %.15g, %.15g)",
                          i, j, node.shading_point.x, node.shading_point.y,
                          node.shading_point.z, want.x, want.y, want.z);
            if (dist3(want, node.point) > 1e-6)
                moved++;
        }
    /* the grid [-4.5, 3.5]^2 is in view: its 7 x 7 pixel centres strictly
     * inside at least are hits; and the tilted normals do move P' */
    ck_assert_int_ge(hits, 49);
    ck_assert_int_gt(moved, 0);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(the_shading_point_of_a_flat_normal_facet_is_the_hit_point)
{
    rt_scene *scene = grid_scene(0);
    int exact = 0, hits = 0;
    for (int j = 0; j < 20; j++)
        for (int i = 0; i < 20; i++) {
            rt_ray_node node = camera_node(scene, i, j);
            if (!node.hit)
                continue;
            hits++;
            ck_assert(node.smooth);
            /* normals (0, 0, 1) everywhere: N_s = N_g exactly */
            ck_assert(node.shading_normal.x == 0.0 &&
                      node.shading_normal.y == 0.0 &&
                      node.shading_normal.z == 1.0);
            /* (P - v_i).n_i = P.z for every corner: when P.z >= 0 no
             * corner moves P and P' = P bit for bit; when the rounding of
             * P left it below the plane, P' is moved by P.z at most. */
            if (node.point.z >= 0.0) {
                ck_assert_msg(
                    memcmp(&node.shading_point, &node.point,
                           sizeof node.point) == 0,
                    "pixel (%d, %d): P' (%.17g, %.17g, %.17g) is not P "
                    "(%.17g, %.17g, %.17g)",
                    i, j, node.shading_point.x, node.shading_point.y,
                    node.shading_point.z, node.point.x, node.point.y,
                    node.point.z);
                exact++;
            } else {
                ck_assert(dist3(node.shading_point, node.point) <=
                          2 * fabs(node.point.z) + 1e-300);
            }
        }
    ck_assert_int_ge(hits, 49);
    ck_assert_int_gt(exact, 0);
    rt_scene_destroy(scene);
}
END_TEST

/* ------------------------------------------------------------- highlight */

/*
 * A mirror-like scan: the plane z = 0 (two facets, [-50, 50]^2) with
 * uniform vertex normals (0, 0, 1), d = 0 and s = 1, so a shadow ray's
 * whole term is the highlight 255 (R.V)^p; light (6, 0, 10), white; the
 * camera at O = (0, 0, 10) looks down through a screen one pixel high and
 * SCAN pixels wide, |AB| = 0.6: pixel i sees x = 6 (2i + 1 - SCAN)/SCAN,
 * y = 0, spacing 12/SCAN = 0.006.
 *
 * The mirror point, where R_l = V: the light mirrored in the plane is
 * (6, 0, -10); the segment from O to it meets z = 0 halfway: M = (3, 0, 0).
 */
#define SCAN 2001
#define LIGHT_X 6.0
#define LIGHT_Z 10.0

static rt_scene *highlight_scene(double p)
{
    static const rt_vec3 corners[4] = {
        {-50, -50, 0}, {50, -50, 0}, {50, 50, 0}, {-50, 50, 0}};
    static const rt_vec3 normals[4] = {
        {0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    rt_facet_desc f[2];
    memset(f, 0, sizeof f);
    for (int i = 0; i < 2; i++) {
        f[i].color = (rt_rgb8){200, 200, 200};
        f[i].diffuse = 0.0;
        f[i].diffuse_given = 1;
        f[i].highlight = 1.0;
        f[i].highlight_exponent = p;
    }
    f[0].vertex[0] = 0, f[0].vertex[1] = 1, f[0].vertex[2] = 2;
    f[1].vertex[0] = 0, f[1].vertex[1] = 2, f[1].vertex[2] = 3;
    rt_light light = {{LIGHT_X, 0, LIGHT_Z}, {255, 255, 255}};
    rt_scene_desc desc = {0};
    desc.observer = v3(0, 0, 10);
    desc.screen_center = v3(0, 0, 9);
    desc.screen_right = v3(0.6, 0, 9);
    desc.width = SCAN;
    desc.height = 1;
    desc.vertices = corners;
    desc.vertex_count = 4;
    desc.facets = f;
    desc.facet_count = 2;
    desc.background = (rt_rgb8){0, 0, 0};
    desc.lights = &light;
    desc.light_count = 1;
    desc.normals = normals;
    rt_scene *scene = NULL;
    rt_error error;
    rt_status status = rt_scene_create(&desc, &scene, &error);
    ck_assert_msg(status == RT_OK, "rt_scene_create: %s", error.message);
    return scene;
}

/* What the scan of one pixel gives: the hit's x, the highlight's share of
 * its peak (highlight_own / (s C_S)), and the angle between R_l and V
 * worked out here from the hit point, O and the light. */
typedef struct scan_sample {
    double x;
    double share;
    double angle;
} scan_sample;

static scan_sample scan_pixel(const rt_scene *scene, int i, double p)
{
    rt_ray_tree *tree = NULL;
    rt_error error;
    ck_assert_int_eq(rt_explain_pixel(scene, NULL, i, 0, -1, &tree, &error),
                     RT_OK);
    size_t count = 0;
    const rt_ray_node *nodes = rt_ray_tree_nodes(tree, &count);
    ck_assert(count >= 2 && nodes[0].hit);
    rt_vec3 hit = nodes[0].point;
    const rt_ray_node *shadow = NULL;
    for (size_t k = 1; k < count; k++)
        if (nodes[k].kind == RT_RAY_SHADOW && nodes[k].parent == 0)
            shadow = &nodes[k];
    ck_assert_msg(shadow != NULL && shadow->cast && shadow->e == 1.0,
                  "pixel %d: the light is not seen", i);

    rt_vec3 s = unit3(sub3(v3(LIGHT_X, 0, LIGHT_Z), hit));
    rt_vec3 n = v3(0, 0, 1);
    rt_vec3 r = sub3(scale3(n, 2 * dot3(n, s)), s);
    rt_vec3 view = unit3(sub3(v3(0, 0, 10), hit));
    double cosine = dot3(r, view);
    scan_sample out;
    out.x = hit.x;
    out.share = shadow->highlight_own.r / 255.0;
    out.angle = acos(fmin(1.0, cosine));
    /* the term is Phong's, to rounding, everywhere on the scan */
    double want = cosine > 0 ? pow(cosine, p) : 0.0;
    ck_assert_msg(fabs(out.share - want) < 1e-9,
                  "pixel %d, p = %g: highlight share %.12g, (R.V)^p = %.12g",
                  i, p, out.share, want);
    ck_assert(fabs(shadow->r_dot_v - cosine) < 1e-12);
    /* d = 0: the highlight is the whole term */
    ck_assert(fabs(shadow->own.r - shadow->highlight_own.r) < 1e-12);
    rt_ray_tree_destroy(tree);
    return out;
}

static void check_highlight(double p)
{
    rt_scene *scene = highlight_scene(p);
    scan_sample *scan = malloc(SCAN * sizeof *scan);
    ck_assert_ptr_nonnull(scan);
    int peak = 0;
    for (int i = 0; i < SCAN; i++) {
        scan[i] = scan_pixel(scene, i, p);
        if (scan[i].share > scan[peak].share)
            peak = i;
    }
    /* (b) the peak is at the mirror point M = (3, 0, 0), within a pixel
     * (the scan's spacing 0.006) */
    double spacing = 12.0 / SCAN;
    double mirror_x = LIGHT_X * 10.0 / (10.0 + LIGHT_Z);
    ck_assert_msg(fabs(scan[peak].x - mirror_x) <= spacing,
                  "p = %g: the highlight peaks at x = %.9g, the mirror "
                  "point is at x = %.9g",
                  p, scan[peak].x, mirror_x);
    ck_assert(scan[peak].share > 0.99);

    /* (c) half-width: on each side of the peak, the first pixel whose
     * share falls below 1/2 and the one before it bracket the angle where
     * (R.V)^p = 1/2, acos(2^(-1/p)).  The bracket is exact (no tolerance:
     * the share falls monotonically away from M); its width, the angle
     * between two neighbouring pixels (about 0.0011 rad here), is at most
     * 1.5% of the half-width for these p, so an exponent off by 5% (p = 10
     * read as 9.5) falls outside it. */
    double half = acos(pow(2.0, -1.0 / p));
    for (int side = -1; side <= 1; side += 2) {
        int i = peak;
        while (i + side >= 0 && i + side < SCAN && scan[i + side].share >= 0.5)
            i += side;
        ck_assert_msg(i + side >= 0 && i + side < SCAN,
                      "p = %g: the highlight is wider than the scan", p);
        double inside = scan[i].angle, outside = scan[i + side].angle;
        ck_assert_msg(inside <= half && half <= outside,
                      "p = %g, side %d: half the peak between %.9g and %.9g "
                      "rad from the mirror direction, acos(2^(-1/p)) = %.9g",
                      p, side, inside, outside, half);
        ck_assert_msg(outside - inside < 0.015 * half,
                      "p = %g: the scan is too coarse (%.3g rad a pixel)", p,
                      outside - inside);
    }
    free(scan);
    rt_scene_destroy(scene);
}

START_TEST(the_highlight_peaks_at_the_mirror_point_and_halves_at_its_width)
{
    static const double exponents[] = {10, 50, 200};
    check_highlight(exponents[_i]);
}
END_TEST

static Suite *smooth_suite(void)
{
    Suite *suite = suite_create("smooth");
    TCase *tc = tcase_create("analytic");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, the_shading_normal_is_the_vertex_normal_at_each_vertex);
    tcase_add_test(tc,
                   the_shading_normal_at_an_edge_midpoint_is_the_mean_normal);
    tcase_add_test(
        tc, every_hit_interpolates_the_normals_and_moves_to_hanikas_point);
    tcase_add_test(tc,
                   the_shading_point_of_a_flat_normal_facet_is_the_hit_point);
    tcase_add_loop_test(
        tc, the_highlight_peaks_at_the_mirror_point_and_halves_at_its_width,
        0, 3);
    suite_add_tcase(suite, tc);
    return suite;
}

RT_CHECK_MAIN(smooth_suite)
