/*
 * test_packets.c - the camera-ray packets of the fast kernel
 * (src/kernel/packet_impl.h: spans of up to 8 pixels of a row share a tile
 * cull and go through the filter several rays at a time; their shadow rays
 * go in packets with a plane cull) against the plain scalar loops: the
 * same image, byte for byte.
 *
 * The packets serve pinhole renders of opaque scenes of at most 64 live
 * facets, brute force, with the AVX2 kernel; their shadow packets scenes of
 * at most 8 lights.  Every case here is such a scene (or one just past a
 * limit), built in memory as .scn text, and rendered with RT_KERNEL_SCALAR
 * on one thread (the reference) and with RT_KERNEL_AUTO on one and two
 * threads, in double and in float, with 1 sample, 4 regular and 4
 * stratified samples a pixel.  A mismatch names the case, the render, the
 * first differing pixel and both colours; every mismatch of a test is
 * printed before the test fails, so one run shows all the cases a bug
 * breaks.
 *
 * Cases here: random scenes (1..64 facets, random cameras - diagonal views,
 * wide angles whose spans straddle the frames and the sign of their axis,
 * eyes inside the scene - and 1..3 lights); facets across, behind, very
 * near and through the eye; lights on, near and inside facets and inside a
 * closed box; extreme scales; 1, 3, 8 and 9 lights; 0, 1, 64 and 65
 * facets; image sizes and regions whose spans start at odd columns.
 * test_packets_edges.c has the exact geometry: tessellated grids, telephoto
 * views, an eye far from the origin.  The scenes and the comparison are
 * support/spec.h's.
 *
 * RT_TEST_MEMCHECK (set under valgrind) shrinks the images and the number
 * of random cases about twenty times; every kind of case still runs.  On a
 * processor without AVX2 both kernels run the scalar loops: the suite then
 * says so and checks nothing about the packets.
 */
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "spec.h"
#include "testutil.h"

/* --- random scenes --------------------------------------------------- */

/* The generator of the random scenes, seeded by each test. */
static rt_test_rng rng;

static double uniform(double lo, double hi)
{
    return rt_test_rng_range(&rng, lo, hi);
}

static int below(int n) { return rt_test_rng_below(&rng, n); }

static rt_vec3 random_point(double r)
{
    return vec(uniform(-r, r), uniform(-r, r), uniform(-r, r));
}

static rt_vec3 random_direction(void)
{
    for (;;) {
        rt_vec3 d = random_point(1);
        double l = length(d);
        if (l > 0.1 && l <= 1)
            return mul(d, 1 / l);
    }
}

static const double reflections[] = {0, 0, 0, 0.25, 0.5, 1};

static void random_facets(rt_test_spec *s, int count)
{
    int start = s->nf;
    if (count >= 6 && uniform(0, 1) < 0.5) {     /* a floor under them */
        double z = uniform(-2, -1);
        rt_test_spec_quad(s, vec(-4, -4, z), vec(4, -4, z), vec(4, 4, z),
                          vec(-4, 4, z),
                          uniform(0, 1) < 0.5 ? 0.0 : 0.4, 160, 160, 150);
    }
    while (s->nf - start < count) {
        double k = reflections[below(6)];
        int r = below(256), g = below(256), b = below(256);
        if (s->nf > start && uniform(0, 1) < 0.35) {
            /* a neighbour: shares an edge with the previous facet */
            const rt_test_spec_facet_t *p = &s->f[s->nf - 1];
            int e = below(3);
            int i = p->v[e], j = p->v[(e + 1) % 3];
            rt_vec3 mid = mul(add(s->v[i], s->v[j]), 0.5);
            int c = rt_test_spec_vertex(s, add(mid, random_point(1.2)));
            rt_test_spec_facet(s, j, i, c, k, r, g, b);
            continue;
        }
        rt_vec3 centre = random_point(1.8);
        double size = uniform(0.15, 1.8);
        rt_test_spec_triangle(s, add(centre, mul(random_direction(), size)),
                              add(centre, mul(random_direction(), size)),
                              add(centre, mul(random_direction(), size)), k,
                              r, g, b);
    }
}

static const rt_vec3 diagonals[] = {
    {1, 1, 1},  {1, 1, 0},  {-1, 1, 1}, {1, 0, -1}, {0, -1, 1},
    {-1, -1, -1}, {1, -1, 0}, {2, 1, 1}, {1, 1, 2}, {-1, 0, -1}};

/* A camera of kind `kind` on the scene near the origin. */
static void random_camera(rt_test_spec *s, int kind)
{
    static const double fields[] = {0.3, 0.8, 1.5, 4, 40};
    double half_width = fields[below(5)];
    rt_vec3 up = random_direction();
    switch (kind) {
    case 0: {   /* from outside, at a point of the scene */
        rt_vec3 eye = mul(random_direction(), uniform(4, 8));
        rt_test_spec_aim(s, eye, sub(random_point(1), eye), up, half_width);
        break;
    }
    case 1: {   /* along a diagonal, exactly: spans straddle the frames */
        rt_vec3 d = diagonals[below(10)];
        rt_vec3 eye = sub(vec(below(3) - 1, below(3) - 1, below(3) - 1),
                          mul(d, 4));
        rt_test_spec_aim(s, eye, d, uniform(0, 1) < 0.5 ? vec(0, 0, 1) : up,
                         half_width);
        break;
    }
    case 2: {   /* a wide angle: spans cross the axis planes, some straddle
                   the sign of their axis */
        rt_vec3 eye = mul(random_direction(), uniform(3, 6));
        rt_test_spec_aim(s, eye, sub(random_point(1), eye), up,
                         uniform(5, 500));
        break;
    }
    default: {  /* inside the scene: facets all round and behind */
        rt_vec3 eye = random_point(1.5);
        rt_test_spec_aim(s, eye, random_direction(), up, half_width);
        break;
    }
    }
}

static void random_lights(rt_test_spec *s, int count)
{
    for (int i = 0; i < count; i++)
        rt_test_spec_light(s, random_point(4), 80 + below(176), 80 + below(176),
                           80 + below(176));
}

START_TEST(random_scenes_render_identically)
{
    rt_test_kernels_reset();
    int cases = rt_test_memcheck() ? 4 : 48;
    for (int i = 0; i < cases; i++) {
        rng.state = 0x5eed0000u + (uint64_t)i * 7919u;
        rt_test_spec *s = rt_test_spec_new();
        random_facets(s, 1 + below(64));
        random_camera(s, i % 4);
        random_lights(s, 1 + below(3));
        s->width = rt_test_memcheck() ? 6 + below(5) : 17 + below(24);
        s->height = rt_test_memcheck() ? 5 + below(4) : 9 + below(16);
        char name[128];
        snprintf(name, sizeof name, "random scene %d (%d facets, %d lights, "
                 "camera kind %d)", i, s->nf, s->nl, i % 4);
        rt_test_spec_check(name, s, 1, NULL, RT_TEST_BOTH_PRECISIONS, 0);
        free(s);
    }
    rt_test_kernels_finish("random scenes");
}
END_TEST

/* A camera on the origin looking along exact diagonals with a wide screen,
 * in a ring of facets: the screen crosses the axis planes and the planes
 * where the dominant axis changes. */
START_TEST(diagonal_views_render_identically)
{
    rt_test_kernels_reset();
    static const rt_vec3 views[] = {{1, 1, 1}, {1, 1, 0}, {-1, 1, -1},
                                    {0, 1, 1}, {1, 0, 0}};
    static const double widths[] = {1, 3, 1e3};
    for (int v = 0; v < 5; v++)
        for (int w = 0; w < 3; w++) {
            rng.state = 0xd1a90000u + (uint64_t)(v * 3 + w);
            rt_test_spec *s = rt_test_spec_new();
            /* facets all round the eye: a shell of 40 random ones */
            for (int i = 0; i < 40; i++) {
                rt_vec3 c = mul(random_direction(), uniform(2, 4));
                double size = uniform(0.3, 1.5);
                rt_test_spec_triangle(s, add(c, mul(random_direction(), size)),
                                      add(c, mul(random_direction(), size)),
                                      add(c, mul(random_direction(), size)),
                                      reflections[below(6)], below(256),
                                      below(256), below(256));
            }
            random_lights(s, 2);
            rt_test_spec_light(s, vec(0.5, 0.25, 0.125), 200, 200, 200);
            rt_test_spec_aim(s, vec(0, 0, 0), views[v], vec(0, 0, 1),
                             widths[w]);
            s->width = rt_test_memcheck() ? 9 : 33;
            s->height = rt_test_memcheck() ? 7 : 25;
            char name[128];
            snprintf(name, sizeof name,
                     "diagonal view (%g, %g, %g), half-width %g", views[v].x,
                     views[v].y, views[v].z, widths[w]);
            rt_test_spec_check(name, s, 1, NULL, RT_TEST_BOTH_PRECISIONS, 0);
            free(s);
        }
    rt_test_kernels_finish("diagonal views");
}
END_TEST

/* --- the eye --------------------------------------------------------- */

START_TEST(facets_at_the_eye_render_identically)
{
    rt_test_kernels_reset();
    const rt_vec3 e = {0.25, -0.5, 0.125};     /* the eye, dyadic */
    const rt_vec3 d = {0.5, 1, 0.25};          /* the view */
    for (int variant = 0; variant < 8; variant++) {
        rt_test_spec *s = rt_test_spec_new();
        /* a backdrop: a wall ahead and a floor */
        rt_test_spec_quad(s, vec(-6, 8, -3), vec(6, 8, -3), vec(6, 8, 5),
                          vec(-6, 8, 5), 0,
                          200, 190, 170);
        rt_test_spec_quad(s, vec(-6, -6, -1), vec(6, -6, -1), vec(6, 8, -1),
                          vec(-6, 8, -1),
                          0.5, 120, 140, 160);
        const char *what = "";
        switch (variant) {
        case 0:     /* a large facet across the eye plane, beside the eye */
            what = "a facet across the eye plane";
            rt_test_spec_triangle(s, add(e, vec(-2, -3, -0.5)),
                                  add(e, vec(0.5, 4, -0.25)),
                                  add(e, vec(-0.5, 2, 1.5)), 0.25, 250, 60, 60);
            break;
        case 1:     /* facets wholly behind the eye, and one across */
            what = "facets behind the eye";
            rt_test_spec_triangle(s, add(e, vec(-1, -2, -1)),
                                  add(e, vec(1, -2, -1)),
                                  add(e, vec(0, -2, 1)), 0, 250, 60, 60);
            rt_test_spec_triangle(s, add(e, vec(-3, -0.5, -2)),
                                  add(e, vec(3, -0.5, -2)),
                                  add(e, vec(0, 1.5, 2)), 0.5, 60, 250, 60);
            break;
        case 2:     /* tiny facets just in front of the eye */
            what = "facets very near the eye";
            rt_test_spec_triangle(s, add(e, vec(-1e-6, 2e-6, -1e-6)),
                                  add(e, vec(1e-6, 2e-6, -1e-6)),
                                  add(e, vec(0, 2e-6, 1e-6)), 0.25, 250, 60,
                                  60);
            rt_test_spec_triangle(s, add(e, vec(1e-9, 1e-8, 1e-9)),
                                  add(e, vec(3e-9, 1.1e-8, -2e-9)),
                                  add(e, vec(-2e-9, 0.9e-8, 0)), 0, 60, 250,
                                  60);
            break;
        case 3:     /* the eye inside a facet (its plane holds the eye) */
            what = "a facet through the eye";
            rt_test_spec_triangle(s, add(e, vec(-1, -1, -1)),
                                  add(e, vec(2, 0, -0.5)),
                                  add(e, vec(-1, 1, 1.5)), 0.25, 250, 60, 60);
            break;
        case 4:     /* a vertex at the eye, an edge pointing at it */
            what = "a vertex at the eye and an edge pointing at it";
            rt_test_spec_triangle(s, e, add(e, vec(1, 3, 0.5)),
                                  add(e, vec(-0.5, 3, 1)), 0,
                                  250, 60, 60);
            rt_test_spec_triangle(s, add(e, mul(d, 2)), add(e, mul(d, 4)),
                                  add(e, vec(1, 2, -1)), 0.5, 60, 250, 60);
            break;
        case 5:     /* facets seen edge-on: their planes hold the eye */
            what = "facets seen edge-on";
            rt_test_spec_triangle(s, add(e, vec(-1, 2, 0)),
                                  add(e, vec(1, 2, 0)),
                                  add(e, vec(0, 4, 0)), 0, 250, 60, 60);
            rt_test_spec_triangle(s, add(e, vec(0, 2, -1)),
                                  add(e, vec(0, 3, 1)),
                                  add(e, vec(0, 5, 0)), 0.5, 60, 250, 60);
            break;
        case 6:     /* a facet a hair off the eye, almost edge-on */
            what = "a facet a hair from the eye";
            rt_test_spec_triangle(s, add(e, vec(-1, 1, 1e-13)),
                                  add(e, vec(1, 1, 1e-13)),
                                  add(e, vec(0, 4, -1e-12)), 0.25, 250, 60, 60);
            rt_test_spec_triangle(s, add(e, vec(-2, -2, -2)),
                                  add(e, vec(2, -1, 2)),
                                  add(e, vec(0, 1e-12, 0)), 0, 60, 250, 60);
            break;
        default:    /* the eye inside a closed box */
            what = "the eye inside a closed box";
            rt_test_spec_box(s, add(e, vec(-1, -1, -1)),
                             add(e, vec(1.5, 2, 1)), 0.5, 200,
                             200, 60);
            break;
        }
        rt_test_spec_light(s, vec(2, 1, 4), 255, 255, 255);
        rt_test_spec_light(s, add(e, vec(0.5, 0.5, 0.5)), 120, 120, 255);
        for (int camera = 0; camera < 2; camera++) {
            rt_test_spec_aim(s, e, d, vec(0, 0, 1), camera ? 6 : 0.7);
            s->width = rt_test_memcheck() ? 9 : 35;
            s->height = rt_test_memcheck() ? 7 : 27;
            char name[160];
            snprintf(name, sizeof name, "%s (%s)", what,
                     camera ? "wide" : "normal");
            rt_test_spec_check(name, s, 1, NULL, RT_TEST_BOTH_PRECISIONS, 0);
        }
        free(s);
    }
    rt_test_kernels_finish("facets at the eye");
}
END_TEST

/* --- lights on and in facets ----------------------------------------- */

/* A floor z = 0, a wall x = 2, posts that cast shadows on them. */
static rt_test_spec *shadow_scene(void)
{
    rt_test_spec *s = rt_test_spec_new();
    rt_test_spec_quad(s, vec(-4, -4, 0), vec(4, -4, 0), vec(4, 4, 0),
                      vec(-4, 4, 0), 0.25,
                      200, 200, 200);
    rt_test_spec_quad(s, vec(2, -4, 0), vec(2, 4, 0), vec(2, 4, 3),
                      vec(2, -4, 3), 0, 180,
                      200, 220);
    rt_test_spec_box(s, vec(-1, -1, 0.5), vec(0, 0, 1.5), 0, 220, 80, 80);
    rt_test_spec_triangle(s, vec(0.5, 1, 0.25), vec(1.5, 1.5, 0.25),
                          vec(1, 1, 2), 0.5,
                          80, 220, 80);
    rt_test_spec_aim(s, vec(-6, -5, 4), vec(5.5, 5, -3.5), vec(0, 0, 1), 0.8);
    return s;
}

START_TEST(lights_on_and_in_facets_render_identically)
{
    rt_test_kernels_reset();
    static const struct {
        rt_vec3 p;
        const char *what;
    } lights[] = {
        {{-2, 1, 0}, "a light on the floor's plane"},
        {{-2, 1, 1e-14}, "a light 1e-14 above the floor's plane"},
        {{-2, 1, -1e-14}, "a light 1e-14 below the floor's plane"},
        {{-2, 1, 1e-9}, "a light 1e-9 above the floor's plane"},
        {{2, 0.5, 1.5}, "a light inside the wall (a facet through it)"},
        {{2, -4, 3}, "a light at a corner of the wall"},
        {{2, 0, 0}, "a light on the edge shared by wall and floor"},
        {{-0.5, -0.5, 1}, "a light inside the closed box"},
        {{-0.5, -0.5, 1.5}, "a light on the box's top face"},
        {{1, 1.25, 1.125}, "a light on the slanted facet's plane"},
    };
    for (size_t i = 0; i < sizeof lights / sizeof lights[0]; i++) {
        rt_test_spec *s = shadow_scene();
        rt_test_spec_light(s, lights[i].p, 255, 240, 220);
        rt_test_spec_light(s, vec(-3, 2, 5), 90, 90, 140);
        s->width = rt_test_memcheck() ? 10 : 40;
        s->height = rt_test_memcheck() ? 8 : 30;
        rt_test_spec_check(lights[i].what, s, 1, NULL, RT_TEST_BOTH_PRECISIONS,
                           0);
        free(s);
    }
    /* the eye in the box with the light */
    rt_test_spec *s = rt_test_spec_new();
    rt_test_spec_box(s, vec(-1, -1, -1), vec(1, 1, 1), 0.25, 200, 200, 200);
    rt_test_spec_box(s, vec(-0.25, 0.25, -0.5), vec(0.25, 0.5, 0), 0, 220, 80,
                     80);
    rt_test_spec_light(s, vec(0.5, 0.5, 0.75), 255, 255, 255);
    rt_test_spec_light(s, vec(-0.75, 0.5, -0.9), 100, 100, 255);
    rt_test_spec_aim(s, vec(0, -0.75, 0.25), vec(0.25, 1, -0.5), vec(0, 0, 1),
                     1.5);
    s->width = rt_test_memcheck() ? 10 : 40;
    s->height = rt_test_memcheck() ? 8 : 30;
    rt_test_spec_check("the eye and the lights inside a closed box", s, 1,
                       NULL, RT_TEST_BOTH_PRECISIONS,
                       0);
    free(s);
    rt_test_kernels_finish("lights on and in facets");
}
END_TEST

/* --- scales ---------------------------------------------------------- */

START_TEST(extreme_scales_render_identically)
{
    rt_test_kernels_reset();
    static const struct {
        double scale;
        unsigned precisions;
    } scales[] = {
        {1e-100, RT_TEST_DOUBLE_ONLY}, {1e100, RT_TEST_DOUBLE_ONLY},
        {1e-20, RT_TEST_FLOAT_ONLY},   {1e20, RT_TEST_FLOAT_ONLY},
        {1e-150, RT_TEST_DOUBLE_ONLY}, {1e150, RT_TEST_DOUBLE_ONLY},
        {1e-15, RT_TEST_FLOAT_ONLY},   {1e15, RT_TEST_FLOAT_ONLY},
        {1e160, RT_TEST_DOUBLE_ONLY},  {1e-160, RT_TEST_DOUBLE_ONLY},
        {1e-22, RT_TEST_FLOAT_ONLY},   /* products subnormal */
    };
    for (int scene = 0; scene < 2; scene++) {
        rt_test_spec *s;
        if (scene == 0) {
            s = shadow_scene();
            rt_test_spec_light(s, vec(-2, 1, 3), 255, 240, 220);
            rt_test_spec_light(s, vec(1, -3, 2), 90, 90, 140);
        } else {
            rng.state = 0x5ca1e000u;
            s = rt_test_spec_new();
            random_facets(s, 60);
            random_camera(s, 1);
            random_lights(s, 3);
        }
        s->width = rt_test_memcheck() ? 10 : 40;
        s->height = rt_test_memcheck() ? 8 : 30;
        for (size_t i = 0; i < sizeof scales / sizeof scales[0]; i++) {
            char name[128];
            snprintf(name, sizeof name, "%s scaled by %g",
                     scene ? "a random scene" : "the shadow scene",
                     scales[i].scale);
            rt_test_spec_check(name, s, scales[i].scale, NULL,
                               scales[i].precisions, 1);
        }
        free(s);
    }
    rt_test_kernels_finish("extreme scales");
}
END_TEST

/* --- limits ---------------------------------------------------------- */

START_TEST(light_counts_render_identically)
{
    rt_test_kernels_reset();
    static const int counts[] = {1, 3, 8, 9};
    for (size_t i = 0; i < sizeof counts / sizeof counts[0]; i++)
        for (int scene = 0; scene < 2; scene++) {
            rt_test_spec *s;
            if (scene == 0) {
                s = shadow_scene();
            } else {
                rng.state = 0x119470u;
                s = rt_test_spec_new();
                random_facets(s, 50);
                random_camera(s, 0);
            }
            rng.state = 0x1167u + i;
            for (int l = 0; l < counts[i]; l++)
                rt_test_spec_light(s, add(vec(0, 0, 2.5), random_point(3)),
                                   30 + below(60),
                                   30 + below(60), 30 + below(60));
            s->width = rt_test_memcheck() ? 10 : 36;
            s->height = rt_test_memcheck() ? 8 : 27;
            char name[128];
            snprintf(name, sizeof name, "%s with %d lights",
                     scene ? "a random scene" : "the shadow scene", counts[i]);
            rt_test_spec_check(name, s, 1, NULL, RT_TEST_BOTH_PRECISIONS, 0);
            free(s);
        }
    rt_test_kernels_finish("light counts");
}
END_TEST

START_TEST(facet_counts_render_identically)
{
    rt_test_kernels_reset();
    static const int counts[] = {0, 1, 2, 63, 64, 65};
    for (size_t i = 0; i < sizeof counts / sizeof counts[0]; i++) {
        rng.state = 0xfac37u + i;
        rt_test_spec *s = rt_test_spec_new();
        random_facets(s, counts[i]);
        ck_assert_int_eq(s->nf, counts[i]);
        if (counts[i] == 0)
            rt_test_spec_vertex(s, vec(1, 2, 3));
        random_camera(s, 0);
        random_lights(s, 2);
        s->width = rt_test_memcheck() ? 10 : 36;
        s->height = rt_test_memcheck() ? 8 : 27;
        char name[64];
        snprintf(name, sizeof name, "%d facets", counts[i]);
        rt_test_spec_check(name, s, 1, NULL, RT_TEST_BOTH_PRECISIONS, 0);
        if (counts[i] == 65) {
            /* 65 in the file, 64 live: a zero-area facet is left out, so
             * the packets serve it */
            s->f[10].v[2] = s->f[10].v[0];
            char *t = rt_test_spec_text(s, 1);
            rt_scene *scene = rt_test_scene_from_string(t);
            free(t);
            rt_scene_info info = {.size = sizeof info};
            rt_scene_get_info(scene, &info);
            ck_assert_int_eq(info.facet_count, 65);
            ck_assert_int_eq(info.live_facet_count, 64);
            rt_scene_destroy(scene);
            rt_test_spec_check("65 facets, one of zero area", s, 1, NULL,
                               RT_TEST_BOTH_PRECISIONS, 0);
        }
        free(s);
    }
    rt_test_kernels_finish("facet counts");
}
END_TEST

/* Another image size than the scene's and regions: spans start at odd
 * columns and end short. */
START_TEST(sizes_and_regions_render_identically)
{
    rt_test_kernels_reset();
    static const struct {
        int width, height;
        rt_region region;
    } cases[] = {
        {37, 23, {0, 0, 0, 0}},     {37, 23, {3, 1, 36, 20}},
        {37, 23, {5, 7, 6, 9}},     {37, 23, {1, 0, 37, 23}},
        {0, 0, {7, 2, 31, 11}},     {61, 9, {13, 0, 56, 9}},
        {11, 40, {9, 3, 11, 38}},   {120, 90, {51, 40, 66, 47}},
    };
    for (int scene = 0; scene < 2; scene++) {
        rt_test_spec *s;
        if (scene == 0) {
            s = shadow_scene();
            rt_test_spec_light(s, vec(-2, 1, 3), 255, 240, 220);
        } else {
            rng.state = 0x5123u;
            s = rt_test_spec_new();
            random_facets(s, 64);
            random_camera(s, 1);
            random_lights(s, 2);
        }
        s->width = 32;
        s->height = 24;
        for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
            if (rt_test_memcheck() && i % 3 != 0)
                continue;
            rt_render_options options;
            rt_render_options_init(&options);
            options.width = cases[i].width;
            options.height = cases[i].height;
            options.region = cases[i].region;
            char name[160];
            snprintf(name, sizeof name,
                     "%s at %d x %d, region (%d, %d)..(%d, %d)",
                     scene ? "a random scene" : "the shadow scene",
                     cases[i].width, cases[i].height, cases[i].region.x0,
                     cases[i].region.y0, cases[i].region.x1,
                     cases[i].region.y1);
            rt_test_spec_check(name, s, 1, &options, RT_TEST_BOTH_PRECISIONS,
                               0);
        }
        free(s);
    }
    rt_test_kernels_finish("sizes and regions");
}
END_TEST

static Suite *packets_suite(void)
{
    Suite *s = suite_create("packets");
#if defined(__x86_64__) || defined(__i386__)
    int avx2 = __builtin_cpu_supports("avx2");
#else
    int avx2 = 0;
#endif
    if (!avx2)
        printf("test_packets: this processor has no AVX2: both kernels run "
               "the scalar loops, the packets are not checked\n");
    TCase *c = tcase_create("images");
    tcase_set_timeout(c, 600);
    tcase_add_test(c, random_scenes_render_identically);
    tcase_add_test(c, diagonal_views_render_identically);
    tcase_add_test(c, facets_at_the_eye_render_identically);
    tcase_add_test(c, lights_on_and_in_facets_render_identically);
    tcase_add_test(c, extreme_scales_render_identically);
    tcase_add_test(c, light_counts_render_identically);
    tcase_add_test(c, facet_counts_render_identically);
    tcase_add_test(c, sizes_and_regions_render_identically);
    suite_add_tcase(s, c);
    return s;
}

RT_CHECK_MAIN(packets_suite)
