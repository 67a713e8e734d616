/*
 * test_extension.c - the rendering model beyond the handout: several
 * lights, transparency and refraction, the thin lens.  Each check is a
 * property the model implies, computed by hand or by comparing renders of
 * the same scene built two ways; none compares with a captured image.
 */
#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

/* ------------------------------------------------------------------ */
/* A small world: a floor, a cube on it, seen from above at an angle    */

#define MAX_V 64
#define MAX_F 64

typedef struct world {
    rt_vec3 v[MAX_V];
    rt_facet_desc f[MAX_F];
    int nv, nf;
    rt_light lights[4];     /* d.lights */
    rt_scene_desc d;
} world;

static int vertex(world *w, double x, double y, double z)
{
    ck_assert_int_lt(w->nv, MAX_V);
    w->v[w->nv] = (rt_vec3){x, y, z};
    return w->nv++;
}

static rt_facet_desc *facet(world *w, int a, int b, int c, rt_rgb8 color)
{
    ck_assert_int_lt(w->nf, MAX_F);
    w->f[w->nf] = (rt_facet_desc){{a, b, c}, 0.0, color};
    return &w->f[w->nf++];
}

/* A quad a b c d (counter-clockwise seen from where its normal points). */
static void quad(world *w, int a, int b, int c, int d, rt_rgb8 color)
{
    facet(w, a, b, c, color);
    facet(w, a, c, d, color);
}

/* An axis-aligned box [x0,x1]x[y0,y1]x[z0,z1], its facets wound
 * counter-clockwise seen from outside; returns its first facet. */
static int box(world *w, double x0, double x1, double y0, double y1,
               double z0, double z1, rt_rgb8 color)
{
    int first = w->nf;
    int p[8];
    for (int i = 0; i < 8; i++)
        p[i] = vertex(w, i & 1 ? x1 : x0, i & 2 ? y1 : y0, i & 4 ? z1 : z0);
    quad(w, p[0], p[2], p[3], p[1], color);     /* z0, normal -z */
    quad(w, p[4], p[5], p[7], p[6], color);     /* z1, normal +z */
    quad(w, p[0], p[1], p[5], p[4], color);     /* y0, normal -y */
    quad(w, p[2], p[6], p[7], p[3], color);     /* y1, normal +y */
    quad(w, p[0], p[4], p[6], p[2], color);     /* x0, normal -x */
    quad(w, p[1], p[3], p[7], p[5], color);     /* x1, normal +x */
    return first;
}

/* The floor and a cube, every facet opaque and matte, a black
 * background, one white light; the camera of the project's cube scene. */
static void cube_world(world *w, int width, int height)
{
    memset(w, 0, sizeof *w);
    int a = vertex(w, -12, -12, 0), b = vertex(w, 12, -12, 0),
        c = vertex(w, 12, 12, 0), d = vertex(w, -12, 12, 0);
    quad(w, a, b, c, d, (rt_rgb8){200, 200, 200});
    box(w, -1, 1, -1, 1, 1, 3, (rt_rgb8){220, 120, 40});
    w->d = (rt_scene_desc){
        .observer = {9, -7, 7},
        .screen_center = {5.4, -4.2, 4.36},
        .screen_right = {7.53, -3.32, 5.02},
        .width = width,
        .height = height,
        .background = {0, 0, 0},
        .lights = w->lights,
        .light_count = 1,
    };
    w->lights[0] = (rt_light){{2, -2, 9}, {255, 255, 255}};
}

static rt_scene *build(world *w)
{
    w->d.vertices = w->v;
    w->d.vertex_count = w->nv;
    w->d.facets = w->f;
    w->d.facet_count = w->nf;
    rt_scene *scene;
    rt_error error;
    rt_status status = rt_scene_create(&w->d, &scene, &error);
    ck_assert_msg(status == RT_OK, "scene: %s", error.message);
    return scene;
}

static rt_image render_with(const rt_scene *scene, int depth, int samples,
                            double aperture, double focal_distance)
{
    rt_render_options options;
    rt_render_options_init(&options);
    options.max_depth = depth;
    options.samples = samples;
    options.aperture = aperture;
    options.focal_distance = focal_distance;
    return rt_test_render_with(scene, &options);
}

/* ------------------------------------------------------------------ */
/* Several lights                                                       */

/* With k = t = 0 and a black background the formula is linear in the
 * lights: the image of both is the sum of the images of each (up to the
 * rounding of each image to 8 bits). */
START_TEST(two_lights_add_up_channel_by_channel)
{
    static const rt_light lights[2] = {{{2, -2, 9}, {200, 90, 30}},
                                       {{-6, -3, 7}, {40, 120, 210}}};
    world w;
    rt_image alone[2];
    for (int l = 0; l < 2; l++) {
        cube_world(&w, 120, 90);
        w.lights[0] = lights[l];
        rt_scene *scene = build(&w);
        alone[l] = render_with(scene, 5, 1, -1, 0);
        rt_scene_destroy(scene);
    }
    cube_world(&w, 120, 90);
    w.lights[0] = lights[0];
    w.lights[1] = lights[1];
    w.d.light_count = 2;
    rt_scene *scene = build(&w);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    ck_assert_int_eq(info.light_count, 2);
    rt_image both = render_with(scene, 5, 1, -1, 0);
    long lit_by_both = 0;
    for (int y = 0; y < both.height; y++)
        for (int x = 0; x < both.width; x++)
            for (int c = 0; c < 3; c++) {
                int sum = rt_image_pixel(&alone[0], x, y)[c] +
                          rt_image_pixel(&alone[1], x, y)[c];
                int value = rt_image_pixel(&both, x, y)[c];
                if (sum > 255)
                    sum = 255;
                ck_assert_msg(abs(value - sum) <= 1,
                              "pixel (%d, %d) channel %d: %d, alone %d + %d",
                              x, y, c, value,
                              rt_image_pixel(&alone[0], x, y)[c],
                              rt_image_pixel(&alone[1], x, y)[c]);
                lit_by_both += rt_image_pixel(&alone[0], x, y)[c] > 0 &&
                               rt_image_pixel(&alone[1], x, y)[c] > 0;
            }
    ck_assert_int_gt(lit_by_both, 1000);    /* the test is not vacuous */
    rt_image_release(&both);
    rt_image_release(&alone[0]);
    rt_image_release(&alone[1]);
    rt_scene_destroy(scene);
}
END_TEST

/* ------------------------------------------------------------------ */
/* Transparency                                                         */

/* A sheet with t = 1 and n = 1 between the camera and the cube, away from
 * the light's paths: it lets every ray through unchanged and has no term
 * of its own, so the picture is the one without it. */
START_TEST(clear_sheet_of_index_one_is_invisible)
{
    world w;
    cube_world(&w, 160, 120);
    /* a vertical sheet across the view, between the camera and the cube,
     * below the light's height so that it shadows nothing the camera
     * sees: the light is above it and the shadow rays go up */
    int a = vertex(&w, 6, -7, 0.5), b = vertex(&w, 6, 3, 0.5),
        c = vertex(&w, 3, 3, 6.5), d = vertex(&w, 3, -7, 6.5);
    for (int i = 0; i < 2; i++) {
        rt_facet_desc *f = i == 0 ? facet(&w, a, b, c, (rt_rgb8){9, 9, 9})
                                  : facet(&w, a, c, d, (rt_rgb8){9, 9, 9});
        f->transparency = 1.0;
        f->refractive_index = 1.0;
    }
    w.lights[0].position = (rt_vec3){-3, 2, 12};
    rt_scene *sheet = build(&w);
    cube_world(&w, 160, 120);
    w.lights[0].position = (rt_vec3){-3, 2, 12};
    rt_scene *without = build(&w);
    rt_image expected = render_with(without, 5, 1, -1, 0);
    rt_image actual = render_with(sheet, 5, 1, -1, 0);
    int worst = 0;
    long differ = rt_test_image_diff(&actual, &expected, &worst);
    ck_assert_msg(differ == 0, "%ld pixels differ (by up to %d)", differ,
                  worst);
    rt_image_release(&actual);
    rt_image_release(&expected);
    rt_scene_destroy(sheet);
    rt_scene_destroy(without);
}
END_TEST

/* The world behind the glass: a wall at x = -20 whose left half (y < 0)
 * is red and right half green, lit from the front by a light between it
 * and the glass (transparent facets cast shadows too); the colour a ray
 * carries tells which half it reached. */
static void wall_world(world *w)
{
    memset(w, 0, sizeof *w);
    int p[6];
    for (int i = 0; i < 6; i++)
        p[i] = vertex(w, -20, (i % 3 - 1) * 500.0, i < 3 ? -50 : 50);
    quad(w, p[0], p[1], p[4], p[3], (rt_rgb8){255, 0, 0});
    quad(w, p[1], p[2], p[5], p[4], (rt_rgb8){0, 255, 0});
    w->d = (rt_scene_desc){.observer = {10, 0, 0},
                           .screen_center = {9, 0, 0},
                           .screen_right = {9, -1, 0},
                           .width = 8,
                           .height = 8,
                           .background = {0, 0, 255},
                           .lights = w->lights,
                           .light_count = 1};
    w->lights[0] = (rt_light){{-12, 0, 0}, {255, 255, 255}};
}

/* Which half of the wall a ray from `origin` along `direction` reaches:
 * -1 red (y < 0), +1 green, 0 neither. */
static int half_reached(const rt_scene *scene, rt_vec3 origin,
                        rt_vec3 direction)
{
    rt_color c = rt_trace(scene, (rt_ray){origin, direction}, 8);
    if (c.r > 1 && c.g < 1e-9 && c.b < 1e-9)
        return -1;
    if (c.g > 1 && c.r < 1e-9 && c.b < 1e-9)
        return 1;
    return 0;
}

/* The y at which rays of direction (-cos(angle), sin(angle), 0) from
 * x = 0 switch from the red half to the green one, found by bisection. */
static double edge_seen_at(const rt_scene *scene, double angle)
{
    rt_vec3 direction = {-cos(angle), sin(angle), 0};
    /* the starts whose rays would meet the wall 30 either side of the
     * edge without glass (the glass moves them by less than 2) */
    double lo = -20 * tan(angle) - 30, hi = -20 * tan(angle) + 30;
    ck_assert_int_eq(half_reached(scene, (rt_vec3){0, lo, 0.3}, direction),
                     -1);
    ck_assert_int_eq(half_reached(scene, (rt_vec3){0, hi, 0.3}, direction), 1);
    for (int i = 0; i < 60; i++) {
        double mid = 0.5 * (lo + hi);
        int h = half_reached(scene, (rt_vec3){0, mid, 0.3}, direction);
        ck_assert_int_ne(h, 0);
        if (h < 0)
            lo = mid;
        else
            hi = mid;
    }
    return 0.5 * (lo + hi);
}

/* A slab with parallel faces (x in [-6, -4], n = 1.5, t = 1) shifts the
 * wall behind it sideways by the analytic amount
 * thickness sin(i - r) / cos r, sin r = sin i / n, and the same for every
 * ray of one direction (no deformation). */
START_TEST(slab_shifts_what_is_behind_it_without_deforming_it)
{
    world w;
    wall_world(&w);
    rt_scene *bare = build(&w);
    wall_world(&w);
    int first = box(&w, -6, -4, -400, 400, -40, 40, (rt_rgb8){0, 0, 0});
    for (int i = first; i < w.nf; i++) {
        w.f[i].transparency = 1.0;
        w.f[i].refractive_index = 1.5;
    }
    rt_scene *slab = build(&w);
    static const double degrees[] = {0, 10, 30, 50, 70};
    for (size_t i = 0; i < sizeof degrees / sizeof degrees[0]; i++) {
        double angle = degrees[i] * 3.14159265358979323846 / 180;
        double refracted = asin(sin(angle) / 1.5);
        double shift = 2.0 * sin(angle - refracted) / cos(refracted);
        double without = edge_seen_at(bare, angle);
        double with = edge_seen_at(slab, angle);
        /* the ray is pushed towards the normal inside the glass: the
         * edge is met by rays that started further along +y */
        double measured = (with - without) * cos(angle);
        ck_assert_msg(fabs(measured - shift) < 1e-9,
                      "at %g degrees: shift %.12g, expected %.12g",
                      degrees[i], measured, shift);
    }
    rt_scene_destroy(bare);
    rt_scene_destroy(slab);
}
END_TEST

/* Inside glass of index n, a ray meeting the surface beyond the critical
 * angle asin(1/n) is reflected back in; below it, it leaves. */
START_TEST(total_internal_reflection_begins_at_the_critical_angle)
{
    world w;
    memset(&w, 0, sizeof w);
    /* the surface z = 0, its winding normal +z: glass below, air above */
    int a = vertex(&w, -100, -100, 0), b = vertex(&w, 100, -100, 0),
        c = vertex(&w, 100, 100, 0), d = vertex(&w, -100, 100, 0);
    quad(&w, a, b, c, d, (rt_rgb8){0, 0, 0});
    w.f[0].transparency = w.f[1].transparency = 1.0;
    w.f[0].refractive_index = w.f[1].refractive_index = 1.5;
    /* a red floor inside the glass, lit from inside */
    int e = vertex(&w, -100, -100, -5), f = vertex(&w, 100, -100, -5),
        g = vertex(&w, 100, 100, -5), h = vertex(&w, -100, 100, -5);
    quad(&w, e, f, g, h, (rt_rgb8){255, 0, 0});
    w.d = (rt_scene_desc){.observer = {0, 0, 10},
                          .screen_center = {0, 0, 9},
                          .screen_right = {1, 0, 9},
                          .width = 4,
                          .height = 4,
                          .background = {0, 255, 0},
                          .lights = &(rt_light){{0, 0, -1}, {255, 255, 255}},
                          .light_count = 1};
    rt_scene *scene = build(&w);
    double critical = asin(1 / 1.5);
    static const double margins[] = {1e-3, 1e-6};
    for (size_t i = 0; i < sizeof margins / sizeof margins[0]; i++) {
        for (int side = -1; side <= 1; side += 2) {
            double angle = critical + side * margins[i];
            rt_ray ray = {{0, 0, -1}, {sin(angle), 0, cos(angle)}};
            rt_color color = rt_trace(scene, ray, 5);
            if (side < 0)   /* leaves: the green sky */
                ck_assert_msg(color.g > 250 && color.r == 0,
                              "%g below the critical angle: (%g, %g, %g)",
                              margins[i], color.r, color.g, color.b);
            else            /* reflected onto the red floor */
                ck_assert_msg(color.r > 1 && color.g == 0,
                              "%g beyond the critical angle: (%g, %g, %g)",
                              margins[i], color.r, color.g, color.b);
        }
    }
    rt_scene_destroy(scene);
}
END_TEST

/* ------------------------------------------------------------------ */
/* The thin lens                                                        */

/* A scene built with a = 0 and the same scene without a lens render the
 * same bytes, with one sample and with several; so does a lens scene
 * rendered with the option a = 0. */
START_TEST(zero_aperture_is_the_pinhole_byte_for_byte)
{
    static const int samples[] = {1, 4};
    for (size_t i = 0; i < sizeof samples / sizeof samples[0]; i++) {
        world w;
        cube_world(&w, 100, 80);
        rt_scene *pinhole = build(&w);
        cube_world(&w, 100, 80);
        w.d.aperture = 0.3;
        w.d.focal_distance = 11;
        rt_scene *lens = build(&w);
        rt_image expected = render_with(pinhole, 5, samples[i], -1, 0);
        rt_image closed = render_with(lens, 5, samples[i], 0, 0);
        rt_image open = render_with(lens, 5, samples[i], -1, 0);
        ck_assert_int_eq(rt_test_image_diff(&closed, &expected, NULL), 0);
        if (samples[i] > 1)     /* the lens does something when open */
            ck_assert_int_gt(rt_test_image_diff(&open, &expected, NULL), 0);
        rt_image_release(&expected);
        rt_image_release(&closed);
        rt_image_release(&open);
        rt_scene_destroy(pinhole);
        rt_scene_destroy(lens);
    }
}
END_TEST

/* The number of pixels of row `y` strictly between the two colours of an
 * edge: the width of its blur. */
static int blur_width(const rt_image *image, int y, int x0, int x1)
{
    int dark = 255, bright = 0;
    for (int x = x0; x < x1; x++) {
        int v = rt_image_pixel(image, x, y)[0];
        dark = v < dark ? v : dark;
        bright = v > bright ? v : bright;
    }
    int width = 0;
    for (int x = x0; x < x1; x++) {
        int v = rt_image_pixel(image, x, y)[0];
        width += v > dark + 2 && v < bright - 2;
    }
    return width;
}

/* Two walls facing the camera, each with a vertical black/white edge:
 * one at the focal distance, one twice as far.  As the aperture grows
 * the edge in focus stays within a pixel; the other spreads. */
START_TEST(focal_plane_stays_sharp_as_the_aperture_grows)
{
    world w;
    memset(&w, 0, sizeof w);
    static const double depth[2] = {10, 20};   /* along -z from z = 0 */
    for (int k = 0; k < 2; k++) {
        double z = -depth[k], top = k == 0 ? 3 : -0.5,
               bottom = k == 0 ? 0.5 : -3 * 2;
        double half = 4 * (k + 1);
        int p[6];
        for (int i = 0; i < 6; i++)
            p[i] = vertex(&w, (i % 3 - 1) * half, i < 3 ? bottom : top, z);
        quad(&w, p[0], p[1], p[4], p[3], (rt_rgb8){255, 255, 255});
        quad(&w, p[1], p[2], p[5], p[4], (rt_rgb8){0, 0, 0});
    }
    w.d = (rt_scene_desc){.observer = {0.013, 0, 0},
                          .screen_center = {0.013, 0, -1},
                          .screen_right = {1.013, 0, -1},
                          .width = 64,
                          .height = 64,
                          .background = {0, 0, 0},
                          /* far behind the camera: every point of a
                             wall gets the same light, so only edges make
                             intermediate values */
                          .lights = &(rt_light){{0, 0, 1e6}, {255, 255, 255}},
                          .light_count = 1,
                          .focal_distance = 10};
    rt_scene *scene = build(&w);
    int previous_far = -1;
    /* blur of the far edge: 2 a (1/f - 1/2f) = a / 10 screen units, a
     * pixel being 2/64: about 1.6 and 6.4 pixels */
    static const double apertures[] = {0, 0.5, 2};
    for (size_t i = 0; i < sizeof apertures / sizeof apertures[0]; i++) {
        rt_image image = render_with(scene, 0, 16, apertures[i], 0);
        int near = blur_width(&image, 26, 8, 56);   /* the wall at f */
        int far = blur_width(&image, 37, 8, 56);    /* the wall at 2f */
        ck_assert_msg(near <= 1, "aperture %g: the edge in focus spans %d "
                      "pixels", apertures[i], near);
        if (apertures[i] > 0)
            ck_assert_msg(far > previous_far && far >= 2,
                          "aperture %g: the far edge spans %d pixels "
                          "(before: %d)", apertures[i], far, previous_far);
        previous_far = far;
        rt_image_release(&image);
    }
    rt_scene_destroy(scene);
}
END_TEST

/* ------------------------------------------------------------------ */
/* The builder's rules                                                  */

START_TEST(builder_refuses_what_the_model_forbids)
{
    static const struct {
        double k, t, n, d;
        int d_given;
        double aperture, focal;
        const char *word;
    } cases[] = {
        {0.6, 0.5, 1, 0, 0, 0, 0, "transparency"},
        {0, -0.1, 1, 0, 0, 0, 0, "transparency"},
        {0, 0.5, -1, 0, 0, 0, 0, "refractive index"},
        {0, 0, 1, -0.5, 1, 0, 0, "diffuse"},
        {0, 0, 1, 0, 0, -1, 0, "aperture"},
        {0, 0, 1, 0, 0, 0, -2, "focal distance"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        world w;
        cube_world(&w, 8, 8);
        w.f[3].reflection = cases[i].k;
        w.f[3].transparency = cases[i].t;
        w.f[3].refractive_index = cases[i].n;
        w.f[3].diffuse = cases[i].d;
        w.f[3].diffuse_given = cases[i].d_given;
        w.d.aperture = cases[i].aperture;
        w.d.focal_distance = cases[i].focal;
        w.d.vertices = w.v;
        w.d.vertex_count = w.nv;
        w.d.facets = w.f;
        w.d.facet_count = w.nf;
        rt_scene *scene;
        rt_error error;
        ck_assert_int_eq(rt_scene_create(&w.d, &scene, &error), RT_ERR_RANGE);
        ck_assert_ptr_null(scene);
        ck_assert_msg(strstr(error.message, cases[i].word) != NULL,
                      "case %zu: %s", i, error.message);
    }
}
END_TEST

static Suite *extension_suite(void)
{
    Suite *s = suite_create("extension");
    TCase *c = tcase_create("lights");
    tcase_add_test(c, two_lights_add_up_channel_by_channel);
    suite_add_tcase(s, c);
    c = tcase_create("transparency");
    tcase_set_timeout(c, 60);
    tcase_add_test(c, clear_sheet_of_index_one_is_invisible);
    tcase_add_test(c, slab_shifts_what_is_behind_it_without_deforming_it);
    tcase_add_test(c, total_internal_reflection_begins_at_the_critical_angle);
    suite_add_tcase(s, c);
    c = tcase_create("lens");
    tcase_set_timeout(c, 60);
    tcase_add_test(c, zero_aperture_is_the_pinhole_byte_for_byte);
    tcase_add_test(c, focal_plane_stays_sharp_as_the_aperture_grows);
    suite_add_tcase(s, c);
    c = tcase_create("builder");
    tcase_add_test(c, builder_refuses_what_the_model_forbids);
    suite_add_tcase(s, c);
    return s;
}

RT_CHECK_MAIN(extension_suite)
