/*
 * cases_watertight.c - the robustness cases (docs/robustness.md) of rays
 * aimed at the edges and vertices facets share (W: watertightness) and
 * facets without area or nearly so (D: degenerate and sliver facets).
 * Their table is in cases.c.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "robust/cases.h"

/* ================================================================== */
/* Watertightness                                                      */

static void sphere_edges(rb_method method, rt_precision precision,
                         rb_result *r, double scale)
{
    rb_mesh m = {0};
    rt_vec3 centre = rb_scale(rb_v(0.1, -0.2, 0.3), scale);
    rb_mesh_icosphere(&m, centre, scale, 2, 0, GREY);
    rb_view view = rb_ray_view(scale, centre, SKY);
    rt_scene *scene = rb_scene(&m, &view);
    rb_engine *e = rb_engine_create(scene, method, precision);
    rt_test_rng rng = {5};
    rb_shared sh = rb_shared_of(&m);
    for (int i = 0; i < rb_scaled(100000); i++) {
        rt_vec3 target = rb_shared_point(&m, &sh, &rng, 0.3);
        rt_vec3 origin = rb_add(centre, rb_random_in_ball(&rng, 0.5 * scale));
        rb_hit h;
        r->total++;
        if (!rb_engine_hit(e, (rt_ray){origin, rb_sub(target, origin)}, &h))
            r->failures++;
        else
            r->nans += rb_hit_is_nan(&h);
    }
    rb_shared_free(&sh);
    rb_engine_free(e);
    rt_scene_destroy(scene);
    rb_mesh_free(&m);
}

void rb_case_w1(rb_method m, rt_precision p, rb_result *r) { sphere_edges(m, p, r, 1e-3); }
void rb_case_w2(rb_method m, rt_precision p, rb_result *r) { sphere_edges(m, p, r, 1); }
void rb_case_w3(rb_method m, rt_precision p, rb_result *r) { sphere_edges(m, p, r, 1e3); }

/* A cone of 64 thin facets around one apex; rays through the apex and the
 * spokes from everywhere. */
void rb_case_w4(rb_method method, rt_precision precision, rb_result *r)
{
    rb_mesh m = {0};
    int apex = rb_mesh_vertex(&m, rb_rotate(rb_v(0, 0, 0)));
    int rim0 = m.vertex_count;
    for (int i = 0; i < 64; i++) {
        double a = 2 * RB_PI * i / 64;
        rb_mesh_vertex(&m, rb_rotate(rb_v(cos(a), sin(a), 0.4)));
    }
    for (int i = 0; i < 64; i++)
        rb_mesh_facet(&m, apex, rim0 + i, rim0 + (i + 1) % 64, 0, GREY);
    rb_view view = rb_ray_view(1, rb_v(0, 0, 3), SKY);
    rt_scene *scene = rb_scene(&m, &view);
    rb_engine *e = rb_engine_create(scene, method, precision);
    rt_test_rng rng = {44};
    for (int i = 0; i < rb_scaled(50000); i++) {
        rt_vec3 target = m.vertices[apex];
        if (i % 2)
            target = rb_lerp(m.vertices[apex],
                             m.vertices[rim0 + (int)(rt_test_rng_uniform(&rng) * 64)],
                             rt_test_rng_uniform(&rng));
        /* From within 60 degrees of the axis, above or below: there the
         * fan covers the apex and the spokes from the ray's view. */
        rt_vec3 axis = rb_rotate(rb_v(0, 0,
                                      rt_test_rng_uniform(&rng) < 0.5 ? -1 : 1));
        rt_vec3 d = rb_random_unit(&rng);
        while (rb_dot(d, axis) < 0.5)
            d = rb_random_unit(&rng);
        rt_vec3 origin = rb_add(target,
                                rb_scale(d, rt_test_rng_range(&rng, 0.5, 3)));
        rb_hit h;
        r->total++;
        if (!rb_engine_hit(e, (rt_ray){origin, rb_sub(target, origin)}, &h))
            r->failures++;
        else
            r->nans += rb_hit_is_nan(&h);
    }
    rb_engine_free(e);
    rt_scene_destroy(scene);
    rb_mesh_free(&m);
}

/* A tilted grid with integer coordinates (exact in float too) near 1e6,
 * windings alternating; rays from above aimed at shared edges. */
void rb_case_w5(rb_method method, rt_precision precision, rb_result *r)
{
    rb_mesh m = {0};
    rt_vec3 corner = rb_v(1048579, 1000000, 500000);
    rb_mesh_grid(&m, corner, rb_v(1, 0, 1), rb_v(0, 2, 1), 16, 1, 0, GREY);
    rt_vec3 normal = rb_cross(rb_v(1, 0, 1), rb_v(0, 2, 1));
    normal = rb_scale(normal, 1 / rb_length(normal));
    rb_view view = rb_ray_view(1, rb_add(corner, rb_v(0, 0, 100)), SKY);
    view.observer = rb_add(view.observer, corner);
    view.screen_center = rb_add(view.screen_center, corner);
    view.screen_right = rb_add(view.screen_right, corner);
    rt_scene *scene = rb_scene(&m, &view);
    rb_engine *e = rb_engine_create(scene, method, precision);
    rt_test_rng rng = {55};
    rb_shared sh = rb_shared_of(&m);
    for (int i = 0; i < rb_scaled(100000); i++) {
        rt_vec3 target = rb_shared_point(&m, &sh, &rng, 0.2);
        /* Cells are 1 x 2 along (s, t); float's spacing near 1e6 is
         * 1/16: a target within a few of those of the outer border is not
         * one float can aim at (its rounded origin may pass outside), so
         * targets keep half a cell from it. */
        rt_vec3 local = rb_sub(target, corner);
        double s_cell = local.x, t_cell = local.y / 2;
        if (s_cell < 0.5 || s_cell > 15.5 || t_cell < 0.5 || t_cell > 15.5) {
            i--;
            continue;
        }
        rt_vec3 d = rb_random_unit(&rng);
        if (rb_dot(d, normal) < 0.1)
            d = rb_add(d, rb_scale(normal, 1.1 - rb_dot(d, normal)));
        rt_vec3 origin = rb_add(target,
                                rb_scale(d, rt_test_rng_range(&rng, 1, 5)));
        /* An origin float holds exactly: the same ray in both precisions. */
        origin = rb_v((float)origin.x, (float)origin.y, (float)origin.z);
        rb_hit h;
        r->total++;
        if (!rb_engine_hit(e, (rt_ray){origin, rb_sub(target, origin)}, &h))
            r->failures++;
        else
            r->nans += rb_hit_is_nan(&h);
    }
    rb_shared_free(&sh);
    rb_engine_free(e);
    rt_scene_destroy(scene);
    rb_mesh_free(&m);
}

/* ================================================================== */
/* Degenerate and sliver facets                                        */

void rb_case_d1(rb_method method, rt_precision precision, rb_result *r)
{
    /* Collinear in exact binary arithmetic: repeated points, points on an
     * axis, on a diagonal, and far from the origin. */
    static const double triples[][9] = {
        {1, 2, 3, 1, 2, 3, 1, 2, 3},
        {0, 0, 0, 0, 0, 0, 1, 1, 1},
        {1, 2, 3, 2, 4, 6, 3, 6, 9},
        {0.5, 0.25, 0.125, 1.5, 0.75, 0.375, 1, 0.5, 0.25},
        {-1, 0, 0, 1, 0, 0, 0.3, 0, 0},
        {1e15, 1e15, 1e15, 3e15, 3e15, 3e15, 2e15, 2e15, 2e15},
        {1e-9, 2e-9, 0, 3e-9, 6e-9, 0, 2e-9, 4e-9, 0}};
    int n = (int)(sizeof triples / sizeof triples[0]);
    rb_mesh m = {0};
    for (int i = 0; i < n; i++)
        rb_mesh_triangle(&m, rb_v(triples[i][0], triples[i][1], triples[i][2]),
                         rb_v(triples[i][3], triples[i][4], triples[i][5]),
                         rb_v(triples[i][6], triples[i][7], triples[i][8]), 0,
                         GREY);
    rb_view view = rb_ray_view(1, rb_v(0, 0, 3), SKY);
    rt_scene *scene = rb_scene(&m, &view);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    if (method == RB_OURS && (info.live_facet_count != 0 ||
                              info.warning_count != n))
        r->failures += n;
    rb_engine *e = rb_engine_create(scene, method, precision);
    rt_test_rng rng = {11};
    for (int i = 0; i < rb_scaled(70000); i++) {
        const rt_facet_desc *f = &m.facets[i % n];
        rt_vec3 a = m.vertices[f->vertex[0]], b = m.vertices[f->vertex[1]],
                c = m.vertices[f->vertex[2]];
        rt_vec3 target = i % 3 == 0 ? a : rb_lerp(a, i % 3 == 1 ? b : c,
                                                  rt_test_rng_uniform(&rng));
        double size = fmax(rb_length(rb_sub(b, a)), rb_length(rb_sub(c, a)));
        if (size == 0)
            size = 1;
        rt_vec3 origin = rb_add(target, rb_scale(rb_random_unit(&rng), size));
        rb_hit h;
        r->total++;
        if (rb_engine_hit(e, (rt_ray){origin, rb_sub(target, origin)}, &h))
            r->failures++;
    }
    rb_engine_free(e);
    rt_scene_destroy(scene);
    rb_mesh_free(&m);
}

/* A random orthonormal frame (u, v, n). */
static void random_frame(rt_test_rng *rng, rt_vec3 *u, rt_vec3 *v, rt_vec3 *n)
{
    *n = rb_random_unit(rng);
    rt_vec3 t = rb_random_unit(rng);
    *u = rb_cross(*n, t);
    *u = rb_scale(*u, 1 / rb_length(*u));
    *v = rb_cross(*n, *u);
}

/* 16 slivers of the given aspect ratio ("cap": the apex near the long edge;
 * "needle": one edge that short), randomly oriented; rays aimed at interior
 * points must hit their sliver, and the hit point must be where aimed. */
static void slivers(rb_method method, rt_precision precision, rb_result *r,
                    double aspect, int needle)
{
    rb_mesh m = {0};
    rt_test_rng rng = {(uint64_t)(aspect * 7) + (uint64_t)needle};
    rt_vec3 normals[16];
    for (int i = 0; i < 16; i++) {
        rt_vec3 u, v, n;
        random_frame(&rng, &u, &v, &n);
        rt_vec3 at = rb_v(10.0 * (i % 4) + 0.37, 10.0 * (i / 4) - 0.11, 0.29);
        rt_vec3 a = at, b = rb_add(at, u);
        rt_vec3 c = needle ? rb_add(b, rb_scale(v, 1 / aspect))
                           : rb_add(at, rb_add(rb_scale(u, 0.37),
                                               rb_scale(v, 1 / aspect)));
        rb_mesh_triangle(&m, a, b, c, 0, GREY);
        normals[i] = n;
    }
    rb_view view = rb_ray_view(1, rb_v(0, 0, 30), SKY);
    rt_scene *scene = rb_scene(&m, &view);
    rb_engine *e = rb_engine_create(scene, method, precision);
    double tolerance = rb_is_double(precision) ? 1e-9 : 1e-3;
    long misses = 0;
    for (int i = 0; i < rb_scaled(64000); i++) {
        int s = i % 16;
        const rt_facet_desc *f = &m.facets[s];
        rt_vec3 a = m.vertices[f->vertex[0]], b = m.vertices[f->vertex[1]],
                c = m.vertices[f->vertex[2]];
        double wu = rt_test_rng_range(&rng, 0.05, 0.9),
               wv = rt_test_rng_range(&rng, 0.05, 0.95 - wu);
        rt_vec3 target = rb_add(a, rb_add(rb_scale(rb_sub(b, a), wu),
                                          rb_scale(rb_sub(c, a), wv)));
        rt_vec3 d = rb_random_unit(&rng);
        if (fabs(rb_dot(d, normals[s])) < 0.2)
            d = rb_add(d, rb_scale(normals[s], 0.5));
        rt_vec3 origin = rb_add(target, d);
        rb_hit h;
        r->total++;
        if (!rb_engine_hit(e, (rt_ray){origin, rb_sub(target, origin)}, &h)) {
            misses++;
            continue;
        }
        if (rb_hit_is_nan(&h)) {
            r->nans++;
            continue;
        }
        double error = rb_length(rb_sub(h.point, target));
        if (!(error <= tolerance * (1 + rb_length(target))) ||
            h.facet != s)
            r->failures++;
    }
    if (rb_is_double(precision) || method != RB_OURS)
        r->failures += misses;
    else
        snprintf(r->note, sizeof r->note,
                 "%ld misses allowed (the sliver is thinner than "
                 "float's resolution)", misses);
    rb_engine_free(e);
    rt_scene_destroy(scene);
    rb_mesh_free(&m);
}

void rb_case_d2(rb_method m, rt_precision p, rb_result *r) { slivers(m, p, r, 1e8, 0); }
void rb_case_d3(rb_method m, rt_precision p, rb_result *r) { slivers(m, p, r, 1e12, 0); }
void rb_case_d4(rb_method m, rt_precision p, rb_result *r) { slivers(m, p, r, 1e12, 1); }

/* Exact a - b as hi + lo (Knuth's two-sum). */
static void two_diff(double a, double b, double *hi, double *lo)
{
    double s = a - b, bb = s - a;
    *hi = s;
    *lo = (a - (s - bb)) + (-b - bb);
}

/* x1 y2 - x2 y1 for double-double x and y, to about 1e-30 relative. */
static double dd_cross(const double x1[2], const double y2[2],
                       const double x2[2], const double y1[2])
{
    double p = x1[0] * y2[0], pe = fma(x1[0], y2[0], -p);
    double q = x2[0] * y1[0], qe = fma(x2[0], y1[0], -q);
    double small = pe - qe + x1[0] * y2[1] + x1[1] * y2[0] -
                   x2[0] * y1[1] - x2[1] * y1[0];
    return (p - q) + small;
}

/* The unit normal of the facet whose vertices are exactly a, b, c. */
static rt_vec3 exact_normal(rt_vec3 a, rt_vec3 b, rt_vec3 c)
{
    double e[2][3][2];
    two_diff(b.x, a.x, &e[0][0][0], &e[0][0][1]);
    two_diff(b.y, a.y, &e[0][1][0], &e[0][1][1]);
    two_diff(b.z, a.z, &e[0][2][0], &e[0][2][1]);
    two_diff(c.x, a.x, &e[1][0][0], &e[1][0][1]);
    two_diff(c.y, a.y, &e[1][1][0], &e[1][1][1]);
    two_diff(c.z, a.z, &e[1][2][0], &e[1][2][1]);
    rt_vec3 n = rb_v(dd_cross(e[0][1], e[1][2], e[0][2], e[1][1]),
                     dd_cross(e[0][2], e[1][0], e[0][0], e[1][2]),
                     dd_cross(e[0][0], e[1][1], e[0][1], e[1][0]));
    return rb_scale(n, 1 / rb_length(n));
}

/* Normals of 2000 slivers, caps and needles of aspect 1e2 to 1e12. */
void rb_case_d5(rb_method method, rt_precision precision, rb_result *r)
{
    if (!rb_is_double(precision)) {
        rb_not_applicable(r, "normals are computed once, in double, for both");
        return;
    }
    rt_test_rng rng = {505};
    rb_mesh m = {0};
    for (int i = 0; i < rb_scaled(2000); i++) {
        double aspect = pow(10, 2 + (i % 11));
        rt_vec3 u, v, n;
        random_frame(&rng, &u, &v, &n);
        rt_vec3 a = rb_random_in_ball(&rng, 5), b = rb_add(a, u);
        rt_vec3 c = i % 2 ? rb_add(b, rb_scale(v, 1 / aspect))
                          : rb_add(a, rb_add(rb_scale(u, rt_test_rng_range(
                                                            &rng, 0.1, 0.9)),
                                             rb_scale(v, 1 / aspect)));
        rb_mesh_triangle(&m, a, b, c, 0, GREY);
    }
    rb_view view = rb_ray_view(1, rb_v(0, 0, 30), SKY);
    rt_scene *scene = rb_scene(&m, &view);
    double worst = 0;
    for (int i = 0; i < m.facet_count; i++) {
        rt_vec3 a = m.vertices[3 * i], b = m.vertices[3 * i + 1],
                c = m.vertices[3 * i + 2];
        rt_vec3 exact = exact_normal(a, b, c), n;
        if (method == RB_OURS) {
            rt_facet_info info = {.size = sizeof info};
            rt_scene_facet(scene, i, &info);
            n = info.normal;
        } else {
            n = rb_cross(rb_sub(b, a), rb_sub(c, a));
            n = rb_scale(n, 1 / rb_length(n));
        }
        double error = rb_length(rb_sub(n, exact));
        r->total++;
        if (isnan(error))
            r->nans++;
        else if (!(error <= 1e-9))
            r->failures++;
        if (error > worst)
            worst = error;
    }
    snprintf(r->note, sizeof r->note, "largest error %.1e", worst);
    rt_scene_destroy(scene);
    rb_mesh_free(&m);
}

