/*
 * cases_special.c - the robustness cases (docs/robustness.md) of NaN,
 * infinities, huge, tiny and subnormal values in scenes and rays (V:
 * special values).  Their table is in cases.c.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "robust/cases.h"

/* ================================================================== */
/* Special values                                                      */

static const char *const bad_scenes[] = {
    "0 0 5\n0 0 4 1 0 4 8 8\n3\nnan 0 0\n1 0 0\n0 1 0\n1\n1 2 3 0 255 0 0\n0 0 0\n0 0 9 255 255 255\n",
    "0 0 5\n0 0 4 1 0 4 8 8\n3\ninf 0 0\n1 0 0\n0 1 0\n1\n1 2 3 0 255 0 0\n0 0 0\n0 0 9 255 255 255\n",
    "0 0 5\n0 0 4 1 0 4 8 8\n3\n0 -INF 0\n1 0 0\n0 1 0\n1\n1 2 3 0 255 0 0\n0 0 0\n0 0 9 255 255 255\n",
    "0 0 5\n0 0 4 1 0 4 8 8\n3\n0 0 1e400\n1 0 0\n0 1 0\n1\n1 2 3 0 255 0 0\n0 0 0\n0 0 9 255 255 255\n",
    "0 0 5\n0 0 4 1 0 4 8 8\n3\n0 0 0\n1 0 0\n0 1 0\n1\n1 2 3 0 255 0 0\n0 0 0\n0 0 NaN 255 255 255\n",
    "NAN 0 5\n0 0 4 1 0 4 8 8\n3\n0 0 0\n1 0 0\n0 1 0\n1\n1 2 3 0 255 0 0\n0 0 0\n0 0 9 255 255 255\n",
    "0 0 5\n0 0 4 infinity 0 4 8 8\n3\n0 0 0\n1 0 0\n0 1 0\n1\n1 2 3 0 255 0 0\n0 0 0\n0 0 9 255 255 255\n",
    "0 0 5\n0 0 4 1 0 4 8 8\n3\n0 0 0\n1 0 0\n0 1 0\n1\n1 2 3 nan 255 0 0\n0 0 0\n0 0 9 255 255 255\n",
    "0 0 5\n0 0 4 1 0 4 8 8\n3\n0 0 0\n-1e309 0 0\n0 1 0\n1\n1 2 3 0 255 0 0\n0 0 0\n0 0 9 255 255 255\n",
};

/* What a loader built on strtod alone accepts: every token a number. */
static int naive_accepts(const char *text)
{
    const char *p = text;
    while (*p) {
        while (*p == ' ' || *p == '\n')
            p++;
        if (!*p)
            break;
        char *end;
        (void)strtod(p, &end);
        if (end == p)
            return 0;
        p = end;
    }
    return 1;
}

void rb_case_v1(rb_method method, rt_precision precision, rb_result *r)
{
    (void)precision;
    if (method == RB_NAIVE_MT_FMA || method == RB_NAIVE_PLANE) {
        rb_not_applicable(r, "the loader does not depend on the intersection test");
        return;
    }
    int n = (int)(sizeof bad_scenes / sizeof bad_scenes[0]);
    for (int i = 0; i < n; i++) {
        r->total++;
        if (method != RB_OURS) {
            r->failures += naive_accepts(bad_scenes[i]);
            continue;
        }
        rt_scene *scene = NULL;
        rt_error error;
        if (rt_scene_parse(bad_scenes[i], strlen(bad_scenes[i]), "<v1>", NULL,
                           &scene, &error) == RT_OK ||
            scene != NULL)
            r->failures++;
        rt_scene_destroy(scene);
    }
    /* The same values through rt_scene_create. */
    const double specials[3] = {NAN, INFINITY, -INFINITY};
    for (int s = 0; s < 3; s++) {
        for (int where = 0; where < 3; where++) {
            if (method != RB_OURS)
                break;
            rb_mesh m = {0};
            rb_mesh_triangle(&m, rb_v(0, 0, 0), rb_v(1, 0, 0), rb_v(0, 1, 0), 0, GREY);
            rb_view view = rb_ray_view(1, rb_v(0, 0, 3), SKY);
            if (where == 0)
                m.vertices[1].y = specials[s];
            else if (where == 1)
                view.observer.z = specials[s];
            else
                view.light.x = specials[s];
            rt_light light = {view.light, WHITE};
            rt_scene_desc desc = {view.observer, view.screen_center,
                                  view.screen_right, 8, 8, m.vertices,
                                  m.vertex_count, m.facets, m.facet_count,
                                  SKY, &light, 1};
            rt_scene *scene = NULL;
            r->total++;
            if (rt_scene_create(&desc, &scene, NULL) == RT_OK || scene != NULL)
                r->failures++;
            rt_scene_destroy(scene);
            rb_mesh_free(&m);
        }
    }
}

/* Rays of every magnitude, and rays that are not rays, at a sphere. */
void rb_case_v2(rb_method method, rt_precision precision, rb_result *r)
{
    rb_mesh m = {0};
    rb_mesh_icosphere(&m, rb_v(0, 0, 0), 1, 2, 0, GREY);
    rb_view view = rb_ray_view(1, rb_v(0.2, 0.1, 0), SKY);
    rt_scene *scene = rb_scene(&m, &view);
    rb_engine *e = rb_engine_create(scene, method, precision);
    static const double doubles[] = {1e-300, 1e-150, 1e-20, 1, 1e20, 1e150, 1e300};
    static const double floats[] = {1e-30, 1e-15, 1e-5, 1, 1e5, 1e15, 1e30};
    const double *magnitudes = rb_is_double(precision) ? doubles : floats;
    rt_test_rng rng = {8};
    for (int i = 0; i < rb_scaled(2000); i++) {
        rt_vec3 origin = rb_random_in_ball(&rng, 0.5), d = rb_random_unit(&rng);
        rb_hit first;
        int found = rb_engine_hit(e, (rt_ray){origin, d}, &first);
        for (int k = 0; k < 7; k++) {
            rb_hit h;
            r->total++;
            if (!found || !rb_engine_hit(e, (rt_ray){origin, rb_scale(d, magnitudes[k])}, &h)) {
                r->failures++;
                continue;
            }
            if (rb_hit_is_nan(&h))
                r->nans++;
            else if (h.facet != first.facet ||
                     !(fabs(h.t * magnitudes[k] - first.t) <= 1e-5 * first.t))
                r->failures++;
        }
        /* Not rays: a NaN or infinite origin or direction, a zero
         * direction: no hit, and a finite colour. */
        rt_ray bad[5] = {{rb_v(NAN, 0, 0), d}, {origin, rb_v(0, NAN, 0)},
                         {origin, rb_v(0, 0, INFINITY)}, {origin, rb_v(0, 0, 0)},
                         {rb_v(INFINITY, 0, 0), d}};
        for (int k = 0; k < 5; k++) {
            rb_hit h;
            r->total++;
            if (rb_engine_hit(e, bad[k], &h))
                r->failures++;
            r->nans += rb_color_has_nan(rb_engine_trace(e, bad[k], 3));
        }
    }
    if (!rb_is_double(precision))
        snprintf(r->note, sizeof r->note, "magnitudes 1e-30 to 1e30");
    rb_engine_free(e);
    rt_scene_destroy(scene);
    rb_mesh_free(&m);
}

/* The light far away (1e200: beyond float's range): the same image as with
 * the light at 1e30 in the same direction, and no NaN. */
void rb_case_v3(rb_method method, rt_precision precision, rb_result *r)
{
    rb_mesh m = {0};
    rb_view view;
    rb_invariance_scene(&m, &view);
    rt_vec3 dir = rb_v(0.4, 0.3, 0.866);
    long nans[2];
    rt_image images[2];
    for (int k = 0; k < 2; k++) {
        view.light = rb_scale(dir, k ? 1e200 : 1e30);
        images[k] = rb_render_view(&m, &view, 1, rb_v(0, 0, 0), method,
                                   precision, &nans[k]);
    }
    r->total = 64 * 64;
    if (method == RB_OURS && !rb_is_double(precision) && nans[1] < 0 &&
        nans[0] >= 0) {
        /* Decided: a float render whose light float cannot hold is
         * refused (rt_render returns an error), never drawn wrong. */
        snprintf(r->note, sizeof r->note, "refused by rt_render");
        r->nans = nans[0];
    } else {
        r->nans = (nans[0] > 0 ? nans[0] : 0) + (nans[1] > 0 ? nans[1] : 0);
        r->failures = rb_count_differing(&images[0], &images[1]);
    }
    rt_image_release(&images[0]);
    rt_image_release(&images[1]);
    rb_mesh_free(&m);
}

/* Facets a few units wide near 1e8, where float's step is 8: in float they
 * collapse to lines and points.  Defined result: no NaN, every reported hit
 * finite; double renders them. */
void rb_case_v4(rb_method method, rt_precision precision, rb_result *r)
{
    rb_mesh m = {0};
    rt_test_rng rng = {404};
    rt_vec3 base = rb_v(1e8, -1e8, 3e7);
    for (int i = 0; i < rb_scaled(200); i++) {
        rt_vec3 a = rb_add(base, rb_random_in_ball(&rng, 40));
        rb_mesh_triangle(&m, a, rb_add(a, rb_random_in_ball(&rng, 3)),
                         rb_add(a, rb_random_in_ball(&rng, 3)), i % 3 ? 0 : 0.5,
                         i % 2 ? RED : GREEN);
    }
    rb_view view = {rb_add(base, rb_v(0, -120, 30)), rb_add(base, rb_v(0, -119, 29.75)),
                    rb_add(base, rb_v(0.6, -119, 29.75)), 64, 64,
                    rb_add(base, rb_v(20, -60, 90)), WHITE, SKY};
    rt_scene *scene = rb_scene(&m, &view);
    rb_engine *e = rb_engine_create(scene, method, precision);
    for (int i = 0; i < rb_scaled(30000); i++) {
        const rt_facet_desc *f = &m.facets[i % m.facet_count];
        rt_vec3 target = rb_lerp(m.vertices[f->vertex[0]],
                                 rb_lerp(m.vertices[f->vertex[1]],
                                         m.vertices[f->vertex[2]],
                                             rt_test_rng_uniform(&rng)),
                                 rt_test_rng_uniform(&rng));
        rt_vec3 origin = rb_add(target, rb_random_in_ball(&rng, 60));
        rt_ray ray = {origin, rb_sub(target, origin)};
        rb_hit h;
        r->total++;
        if (rb_engine_hit(e, ray, &h) && (rb_hit_is_nan(&h) || !isfinite(h.t)))
            r->nans++;
        r->nans += rb_color_has_nan(rb_engine_trace(e, ray, 3));
    }
    rt_image image;
    rt_image_init(&image, 64, 64, NULL);
    long render_nans = rb_engine_render(e, 5, 2, &image);
    if (render_nans < 0 && method == RB_OURS && !rb_is_double(precision))
        /* Decided: float cannot resolve facets 3 wide at 1e8 (its rule,
         * RT_FLOAT_SPREAD_MAX): rt_render refuses, never draws wrong. */
        snprintf(r->note, sizeof r->note, "the render refused by float's "
                                          "rule; the ray queries ran");
    else
        r->nans += render_nans;
    rt_image_release(&image);
    rb_engine_free(e);
    rt_scene_destroy(scene);
    rb_mesh_free(&m);
}

/* The whole scene at subnormal coordinates (scale 1e-310): refused as a
 * degenerate camera, or rendered without NaN - never NaN. */
void rb_case_v5(rb_method method, rt_precision precision, rb_result *r)
{
    rb_mesh m = {0};
    rb_view view;
    rb_invariance_scene(&m, &view);
    long nans;
    double scale = rb_is_double(precision) ? 1e-310 : 1e-40;
    rt_image image = rb_render_view(&m, &view, scale, rb_v(0, 0, 0), method,
                                    precision, &nans);
    r->total = 64 * 64;
    if (image.pixels == NULL) {
        snprintf(r->note, sizeof r->note, "refused by rt_scene_create");
    } else {
        r->nans = nans;
        long background = 0;
        for (int j = 0; j < 64; j++)
            for (int i = 0; i < 64; i++)
                background += rt_image_pixel(&image, i, j)[2] == SKY.b &&
                              rt_image_pixel(&image, i, j)[0] == SKY.r;
        snprintf(r->note, sizeof r->note, "scale %g: rendered, %ld background pixels",
                 scale, background);
    }
    rt_image_release(&image);
    rb_mesh_free(&m);
}

