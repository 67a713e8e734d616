/*
 * test_packets_edges.c - the camera-ray packets of the fast kernel
 * (src/kernel/packet_impl.h) against the plain scalar loops where the
 * geometry is exact: tessellated grids whose shared edges and vertices the
 * rays hit exactly; telephoto views in which a pixel is a few units in the
 * last place, where the tile cull's margin is all that keeps it exact; an
 * eye far from the origin.  The same image, byte for byte, as in
 * test_packets.c (which says how each case is rendered); the scenes and
 * the comparison are support/spec.h's.
 *
 * RT_TEST_MEMCHECK (set under valgrind) shrinks the images; every kind of
 * case still runs.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "spec.h"
#include "testutil.h"

/* The generator of the grids' heights, seeded by each test. */
static rt_test_rng rng;

/* --- shared edges ---------------------------------------------------- */

/* An nx x ny grid of squares of side `side` (two facets each, diagonals
 * alternating or not) in the plane z = 0 from (x0, y0), heights from
 * `height` (NULL: flat). */
static void grid(rt_test_spec *s, int nx, int ny, double side, double x0,
                 double y0, const double *height, int alternate)
{
    int first = s->nv;
    for (int y = 0; y <= ny; y++)
        for (int x = 0; x <= nx; x++)
            rt_test_spec_vertex(s, vec(x0 + x * side, y0 + y * side,
                          height ? height[y * (nx + 1) + x] : 0.0));
    for (int y = 0; y < ny; y++)
        for (int x = 0; x < nx; x++) {
            int a = first + y * (nx + 1) + x, b = a + 1, c = a + nx + 1,
                d = c + 1;
            int r = 60 + 20 * x, g = 60 + 25 * y, bl = 140;
            double k = (x + y) % 3 == 0 ? 0.5 : 0;
            if (alternate && (x + y) % 2) {
                rt_test_spec_facet(s, a, b, c, k, r, g, bl);
                rt_test_spec_facet(s, b, d, c, k, r, g, bl);
            } else {
                rt_test_spec_facet(s, a, b, d, k, r, g, bl);
                rt_test_spec_facet(s, a, d, c, k, r, g, bl);
            }
        }
}

START_TEST(tessellated_grids_render_identically)
{
    rt_test_kernels_reset();
    const int w = rt_test_memcheck() ? 8 : 32, h = rt_test_memcheck() ? 8 : 16;
    /* 1. A flat 8 x 4 grid (64 facets) of side 2^-6 seen straight down from
     * the height that puts the pixel centres' rays on its vertices and the
     * 2 x 2 samples' on its diagonals, exactly. */
    for (int alternate = 0; alternate < 2; alternate++) {
        rt_test_spec *s = rt_test_spec_new();
        const double side = 0x1p-6;
        grid(s, 8, 4, side, -4 * side, -2 * side, NULL, alternate);
        s->width = w;
        s->height = h;
        /* centre ray of pixel i hits x = (2i + 1 - w) H / w: H = w side / 2
         * puts it on a vertex (x a multiple of side when w even) */
        double height = w * side / 2;
        s->eye = vec(0, 0, height);
        s->a = vec(0, 0, height - side);
        s->b = vec(side, 0, height - side);
        rt_test_spec_light(s, vec(3 * side, 1 * side, 2 * side), 255, 255, 255);
        rt_test_spec_light(s, vec(-2 * side, -1 * side, 0), 100, 100, 100);
        char name[96];
        snprintf(name, sizeof name, "a flat grid seen straight down%s",
                 alternate ? ", diagonals alternating" : "");
        rt_test_spec_check(name, s, 1, NULL, RT_TEST_BOTH_PRECISIONS, 0);
        /* the same grid at an angle, and from below */
        rt_test_spec_aim(s, vec(-3 * side, -5 * side, 4 * side), vec(3, 5, -4),
                         vec(0, 0, 1), 0.5);
        snprintf(name, sizeof name, "a flat grid at an angle%s",
                 alternate ? ", diagonals alternating" : "");
        rt_test_spec_check(name, s, 1, NULL, RT_TEST_BOTH_PRECISIONS, 0);
        rt_test_spec_aim(s, vec(1 * side, 0.5 * side, -3 * side),
                         vec(-1, -0.5, 3),
                         vec(0, 1, 0), 1);
        snprintf(name, sizeof name, "a flat grid from below%s",
                 alternate ? ", diagonals alternating" : "");
        rt_test_spec_check(name, s, 1, NULL, RT_TEST_BOTH_PRECISIONS, 0);
        free(s);
    }
    /* 2. A bumpy 7 x 4 height field (56 facets) that shadows itself, with
     * posts, seen from several sides. */
    rng.state = 0x917du;
    double heights[8 * 5];
    for (int i = 0; i < 8 * 5; i++)
        heights[i] = rt_test_rng_range(&rng, 0, 0.6);
    for (int view = 0; view < 4; view++) {
        rt_test_spec *s = rt_test_spec_new();
        grid(s, 7, 4, 0.5, -1.75, -1, heights, view % 2);
        rt_test_spec_triangle(s, vec(-0.5, 0, 0.3), vec(0.5, 0, 0.3),
                              vec(0, 0.1, 1.5),
                              0.25, 240, 200, 60);
        rt_test_spec_light(s, vec(-2, -1, 2.5), 255, 255, 255);
        rt_test_spec_light(s, vec(3, 2, 1.2), 120, 140, 160);
        static const rt_vec3 eyes[] = {
            {-3, -3, 2.5}, {0.25, 0.0, 4}, {3, -0.5, 0.8}, {-1, 3, 1.5}};
        rt_test_spec_aim(s, eyes[view], sub(vec(0, 0, 0.3), eyes[view]),
                         vec(0, 0, 1),
                         0.7);
        s->width = rt_test_memcheck() ? 10 : 37;
        s->height = rt_test_memcheck() ? 8 : 25;
        char name[64];
        snprintf(name, sizeof name, "a bumpy height field, view %d", view);
        rt_test_spec_check(name, s, 1, NULL, RT_TEST_BOTH_PRECISIONS, 0);
        free(s);
    }
    rt_test_kernels_finish("tessellated grids");
}
END_TEST

/* --- telephoto: pixels a few ulps wide -------------------------------- */

/*
 * A fan of 6 facets round a vertex V, a wall behind it and an occluder
 * casting a shadow on the wall, seen through a screen so narrow that a
 * pixel of a 16384-pixel image spans about one unit in the last place of
 * the rays' shear: the rays of a span, normalised and divided in the
 * kernel's precision, then stray out of the box of the span's corners (by
 * a few ulps), past the edges of facets that cross near it.  The tile cull
 * must keep every facet such a ray may hit: only its margin (`slack`)
 * covers that.  targets[]: V, a point on each of the six edges from V
 * (each shared by two facets), a corner of the shadow.
 */
#define TARGETS 8

static rt_test_spec *fan_scene(rt_vec3 targets[TARGETS])
{
    rt_test_spec *s = rt_test_spec_new();
    const rt_vec3 v = {0.3, 0.7, -0.2};
    int centre = rt_test_spec_vertex(s, v);
    int ring[6];
    for (int i = 0; i < 6; i++) {
        double angle = 2 * 3.14159265358979323846 * (i + 0.37) / 6;
        ring[i] = rt_test_spec_vertex(s,
                                      add(v, vec(cos(angle), 0.3 * sin(angle),
                                       sin(angle))));
    }
    for (int i = 0; i < 6; i++)
        rt_test_spec_facet(s, centre, ring[i], ring[(i + 1) % 6],
                           i % 2 ? 0.25 : 0,
                           40 * i + 30, 200 - 30 * i, 90 + 25 * i);
    /* a wall behind the fan, and an occluder between it and a light */
    rt_test_spec_quad(s, vec(-5, 5, -5), vec(5, 5, -5), vec(5, 5, 5),
                      vec(-5, 5, 5), 0,
                      180, 180, 180);
    const rt_vec3 corner = {3, 0.5, 1}, bright = {3.2, -2, 1.6};
    rt_test_spec_triangle(s, corner, vec(3.6, 0.5, 1.1), vec(3.3, 0.6, 0.4), 0,
                          250, 250,
                          40);
    rt_test_spec_light(s, bright, 255, 255, 255);
    rt_test_spec_light(s, vec(-2, -3, -1), 80, 80, 120);
    targets[0] = v;
    for (int i = 0; i < 6; i++)
        targets[1 + i] = add(mul(v, 0.75), mul(s->v[ring[i]], 0.25));
    targets[7] = add(bright, mul(sub(corner, bright),
                                 (5 - bright.y) / (corner.y - bright.y)));
    return s;
}

START_TEST(telephoto_views_render_identically)
{
    rt_test_kernels_reset();
    /* the screen's half-width over |AO|: a pixel is 2 field / 16384 of
     * shear, a few ulps of the rays' shear (about 0.1 here) in double
     * (2^-52) and in float's kernel (2^-23) */
    static const struct {
        double field;
        unsigned precisions;
    } fields[] = {{3e-13, RT_TEST_DOUBLE_ONLY}, {2e-13, RT_TEST_DOUBLE_ONLY},
                  {1.5e-13, RT_TEST_DOUBLE_ONLY}, {1e-13, RT_TEST_DOUBLE_ONLY},
                  {7e-14, RT_TEST_DOUBLE_ONLY}, {5e-14, RT_TEST_DOUBLE_ONLY},
                  {1e-4, RT_TEST_FLOAT_ONLY},   {7e-5, RT_TEST_FLOAT_ONLY},
                  {5e-5, RT_TEST_FLOAT_ONLY},   {3.5e-5, RT_TEST_FLOAT_ONLY},
                  {2.5e-5, RT_TEST_FLOAT_ONLY}, {1.8e-5, RT_TEST_FLOAT_ONLY}};
    for (size_t i = 0; i < sizeof fields / sizeof fields[0]; i++)
        for (int t = 0; t < TARGETS; t++) {
            if (rt_test_memcheck() && (t + (int)i) % 4 != 0)
                continue;
            rt_vec3 targets[TARGETS];
            rt_test_spec *s = fan_scene(targets);
            rt_vec3 eye = vec(0.1, -3.3, 0.35);
            rt_test_spec_aim(s, eye, sub(targets[t], eye), vec(0, 0, 1),
                             fields[i].field);
            s->width = 16384;
            s->height = 16384;
            rt_render_options options;
            rt_render_options_init(&options);
            int rw = rt_test_memcheck() ? 16 : 64,
                rh = rt_test_memcheck() ? 4 : 16;
            options.region = (rt_region){8192 - rw / 2 + 1, 8192 - rh / 2,
                                         8192 + rw / 2 + 1, 8192 + rh / 2};
            char name[128];
            snprintf(name, sizeof name, "telephoto %g at %s %d",
                     fields[i].field,
                     t == 0 ? "the fan's vertex"
                     : t < 7 ? "a shared edge" : "a shadow's corner", t);
            rt_test_spec_check(name, s, 1, &options, fields[i].precisions, 0);
            free(s);
        }
    rt_test_kernels_finish("telephoto views");
}
END_TEST

/* --- an eye far from the origin ---------------------------------------- */

/*
 * Found by a review: an eye a million units from the origin and a screen a
 * millionth of a unit wide.  The camera's rounding of the directions (of
 * the order of eps |O| over |AO|) put one stratified sample's shear outside
 * the box of the span's four corner rays, and the tile cull built from
 * that box left out the facet the sample hits: pixel (32, 0) came out as
 * background.  The cull now takes its box from the rays' own shears.
 */
static const char far_eye_scene[] =
    "700000, -500000, 300000\n"
    "700000.94072086841, -499999.7177837395, 300000.18814417365, "
    "700000.9407208655, -499999.7177837299, 300000.18814417365, 64, 4\n"
    "3\n"
    "1000700000, 299499999.94183695, -799700000.49500477\n"
    "1000700000, 299499999.94183695, 1200299999.5049953\n"
    "1000700000, -700500000.05816293, 200299999.50499529\n"
    "1\n"
    "1, 2, 3, 0, 200, 100, 50\n"
    "20, 40, 90\n"
    "229639.56580820138, -641108.13025753957, 205927.91316164029, 255, "
    "255, 255\n";

START_TEST(an_eye_far_from_the_origin_renders_identically)
{
    rt_test_kernels_reset();
    rt_scene *scene = NULL;
    rt_error error;
    ck_assert_msg(rt_scene_parse(far_eye_scene, strlen(far_eye_scene),
                                 "far-eye.scn", NULL, &scene, &error) == RT_OK,
                  "%s", error.message);
    static const int samples[] = {16, 9, 4, 1};
    for (int p = 0; p < 2; p++)
        for (size_t i = 0; i < sizeof samples / sizeof samples[0]; i++) {
            rt_render_options options;
            rt_render_options_init(&options);
            options.precision = p ? RT_PRECISION_FLOAT : RT_PRECISION_DOUBLE;
            options.samples = samples[i];
            options.sampling = RT_SAMPLING_STRATIFIED;
            char what[128];
            snprintf(what, sizeof what, "far eye (%s, %d stratified)",
                     p ? "float" : "double", samples[i]);
            if (rt_scene_check_precision(scene, options.precision,
                                         &error) != RT_OK) {
                rt_test_kernels_skip(what, error.message);
                continue;
            }
            rt_test_kernels_count_case();
            options.kernel = RT_KERNEL_SCALAR;
            rt_image ref = rt_test_kernels_render(scene, &options, what);
            options.kernel = RT_KERNEL_AUTO;
            rt_image fast = rt_test_kernels_render(scene, &options, what);
            rt_test_kernels_compare(&ref, &fast, &options, what);
            rt_image_release(&ref);
            rt_image_release(&fast);
        }
    rt_scene_destroy(scene);
    rt_test_kernels_finish("an eye far from the origin");
}
END_TEST

static Suite *packets_edges_suite(void)
{
    Suite *s = suite_create("packets_edges");
    TCase *c = tcase_create("images");
    tcase_set_timeout(c, 600);
    tcase_add_test(c, tessellated_grids_render_identically);
    tcase_add_test(c, telephoto_views_render_identically);
    tcase_add_test(c, an_eye_far_from_the_origin_renders_identically);
    suite_add_tcase(s, c);
    return s;
}

RT_CHECK_MAIN(packets_edges_suite)
