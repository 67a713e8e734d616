/*
 * cases_shadows.c - the robustness cases (docs/robustness.md) of contact
 * shadows and acne (S: self-intersection) and lights in, on and grazing
 * facets (L: lights).  Their table is in cases.c.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "robust/cases.h"

/* ================================================================== */
/* Self-intersection: contact shadows and acne                        */

/* A tessellated floor, a slab lifted by 1e-3 of the scene's size, the
 * light above; camera rays from inside the gap to the floor under the slab
 * must find it dark, and rays from above to the open floor must find it
 * lit with the exact N.S. */
static void contact(rb_method method, rt_precision precision, rb_result *r,
                    double scale, rt_vec3 shift)
{
    rb_mesh m = {0};
    double h = 2e-3;
    rb_mesh_grid(&m, rb_v(-1, -1, 0), rb_v(0.25, 0, 0), rb_v(0, 0.25, 0), 8,
                 1, 0, GREY);
    rb_mesh_box(&m, rb_v(-0.5, -0.5, h), rb_v(0.5, 0.5, h + 0.2), 0, RED);
    rb_mesh_transform(&m, scale, shift);
    rt_vec3 light = rb_v(0.2, 0.1, 3);
    rb_view view = rb_ray_view(1, light, SKY);
    rb_view_transform(&view, scale, shift);
    rt_scene *scene = rb_scene(&m, &view);
    rb_engine *e = rb_engine_create(scene, method, precision);
    rt_test_rng rng = {77};
    long leaks = 0, acne = 0;
    for (int i = 0; i < rb_scaled(100000); i++) {
        int under = i % 2;
        rt_vec3 origin, target;
        if (under) {
            origin = rb_v(rt_test_rng_range(&rng, -0.45, 0.45),
                          rt_test_rng_range(&rng, -0.45, 0.45), h / 2);
            target = rb_v(rt_test_rng_range(&rng, -0.4, 0.4),
                          rt_test_rng_range(&rng, -0.4, 0.4), 0);
        } else {
            double x = rt_test_rng_range(&rng, 0.7,
                                         0.98) * (rt_test_rng_uniform(&rng) < 0.5 ? -1 : 1);
            double y = rt_test_rng_range(&rng, -0.98, 0.98);
            if (i % 4 == 0) {
                double s = x;
                x = y, y = s;
            }
            target = rb_v(x, y, 0);
            origin = rb_add(target,
                            rb_v(rt_test_rng_range(&rng, -0.1, 0.1),
                                 rt_test_rng_range(&rng, -0.1, 0.1), 1));
        }
        rt_vec3 to_light = rb_sub(light, target);
        double expected = 200 * to_light.z / rb_length(to_light);
        origin = rb_transform_point(origin, scale, shift);
        target = rb_transform_point(target, scale, shift);
        rt_color c = rb_engine_trace(e, (rt_ray){origin, rb_sub(target, origin)}, 0);
        r->total++;
        if (rb_color_has_nan(c))
            r->nans++;
        else if (under && c.r != 0)
            leaks++;
        else if (!under && !(fabs(c.r - expected) <= 1e-3 * expected))
            acne++;
    }
    r->failures = leaks + acne;
    snprintf(r->note, sizeof r->note, "%ld leaks (under the slab), %ld acne (open floor)",
             leaks, acne);
    rb_engine_free(e);
    rt_scene_destroy(scene);
    rb_mesh_free(&m);
}

void rb_case_s1(rb_method m, rt_precision p, rb_result *r) { contact(m, p, r, 1e-6, rb_v(0, 0, 0)); }
void rb_case_s2(rb_method m, rt_precision p, rb_result *r) { contact(m, p, r, 1e-3, rb_v(0, 0, 0)); }
void rb_case_s3(rb_method m, rt_precision p, rb_result *r) { contact(m, p, r, 1, rb_v(0, 0, 0)); }
void rb_case_s4(rb_method m, rt_precision p, rb_result *r) { contact(m, p, r, 1e3, rb_v(0, 0, 0)); }
void rb_case_s5(rb_method m, rt_precision p, rb_result *r) { contact(m, p, r, 1e6, rb_v(0, 0, 0)); }
void rb_case_s6(rb_method m, rt_precision p, rb_result *r)
{
    if (!rb_is_double(p)) {
        rb_not_applicable(r, "float's step at 1e12 is 65536: no scene of size 2 survives");
        return;
    }
    contact(m, p, r, 1, rb_v(1e12, -1e12, 1e12));
}

/* ================================================================== */
/* Lights                                                              */

/* Rays from above to a floor (optionally tilted); each colour against what
 * the light should give there (`expect` returns it, or -1 for "exactly 0"). */
typedef double (*expect_fn)(rt_vec3 target, rt_vec3 light);

static double expect_zero(rt_vec3 target, rt_vec3 light)
{
    (void)target, (void)light;
    return -1;
}

static double expect_lit_z(rt_vec3 target, rt_vec3 light)
{
    rt_vec3 s = rb_sub(light, target);
    return 200 * s.z / rb_length(s);
}

static void floor_rays(rb_method method, rt_precision precision, rb_result *r,
                       rb_mesh *m, rt_vec3 light, int tilted, expect_fn expect,
                       double tolerance, double extent, int skip_wall)
{
    rb_view view = rb_ray_view(1, tilted ? rb_rotate(light) : light, SKY);
    if (tilted)
        for (int i = 0; i < m->vertex_count; i++)
            m->vertices[i] = rb_rotate(m->vertices[i]);
    rt_scene *scene = rb_scene(m, &view);
    rb_engine *e = rb_engine_create(scene, method, precision);
    /* In the plane up to rounding: the light gives at most what its own
     * rounding (relative 1e-16, float 6e-8) lets through - invisible. */
    double zero_tolerance = rb_is_double(precision) ? 1e-6 : 1e-2;
    rt_test_rng rng = {99};
    for (int i = 0; i < rb_scaled(50000); i++) {
        rt_vec3 target = rb_v(rt_test_rng_range(&rng, -extent, extent),
                              rt_test_rng_range(&rng, -extent, extent), 0);
        if (skip_wall && fabs(target.x) < 0.05)
            target.x = 0.05 + target.x;
        rt_vec3 origin = rb_add(target, rb_v(rt_test_rng_range(&rng, -0.2, 0.2),
                                             rt_test_rng_range(&rng, -0.2,
                                                               0.2), 0.5));
        if (skip_wall && origin.x * target.x <= 0)
            origin.x = target.x;
        double expected = expect(target, light);
        if (tilted)
            target = rb_rotate(target), origin = rb_rotate(origin);
        rt_color c = rb_engine_trace(e, (rt_ray){origin, rb_sub(target, origin)}, 0);
        r->total++;
        if (rb_color_has_nan(c))
            r->nans++;
        else if (expected < 0 ? c.r != 0 && !(tilted && fabs(c.r) < zero_tolerance)
                              : !(fabs(c.r - expected) <= tolerance * expected))
            r->failures++;
    }
    rb_engine_free(e);
    rt_scene_destroy(scene);
}

static void light_in_plane(rb_method method, rt_precision precision,
                           rb_result *r, int tilted)
{
    rb_mesh m = {0};
    rb_mesh_grid(&m, rb_v(-1, -1, 0), rb_v(0.25, 0, 0), rb_v(0, 0.25, 0), 8, 1,
                 0, GREY);
    floor_rays(method, precision, r, &m, rb_v(3, 0.5, 0), tilted, expect_zero,
               0, 0.98, 0);
    rb_mesh_free(&m);
}

void rb_case_l1(rb_method m, rt_precision p, rb_result *r) { light_in_plane(m, p, r, 0); }
void rb_case_l2(rb_method m, rt_precision p, rb_result *r) { light_in_plane(m, p, r, 1); }

/* The light at the apex of a cone of facets opening upwards; the floor
 * below is lit everywhere (the apex ends every shadow segment). */
void rb_case_l3(rb_method method, rt_precision precision, rb_result *r)
{
    rb_mesh m = {0};
    rb_mesh_grid(&m, rb_v(-3, -3, 0), rb_v(0.5, 0, 0), rb_v(0, 0.5, 0), 12, 1,
                 0, GREY);
    rt_vec3 apex = rb_v(0.1, 0.05, 1.0);
    int a = rb_mesh_vertex(&m, apex), rim = m.vertex_count;
    for (int i = 0; i < 16; i++) {
        double t = 2 * RB_PI * i / 16;
        rb_mesh_vertex(&m, rb_v(0.1 + cos(t), 0.05 + sin(t), 2));
    }
    for (int i = 0; i < 16; i++)
        rb_mesh_facet(&m, a, rim + i, rim + (i + 1) % 16, 0, RED);
    floor_rays(method, precision, r, &m, apex, 0, expect_lit_z,
               rb_is_double(precision) ? 1e-9 : 1e-4, 2.5, 0);
    rb_mesh_free(&m);
}

/* The light on a wall (inside one of its facets); the floor on both sides
 * is lit (the wall meets each shadow segment only at its end). */
void rb_case_l4(rb_method method, rt_precision precision, rb_result *r)
{
    rb_mesh m = {0};
    rb_mesh_grid(&m, rb_v(-2, -2, 0), rb_v(0.5, 0, 0), rb_v(0, 0.5, 0), 8, 1,
                 0, GREY);
    rb_mesh_grid(&m, rb_v(0, -2, 0), rb_v(0, 1, 0), rb_v(0, 0, 0.5), 4, 1, 0,
                 BLUE);
    floor_rays(method, precision, r, &m, rb_v(0, 0.3, 0.8), 0, expect_lit_z,
               rb_is_double(precision) ? 1e-9 : 1e-4, 1.95, 1);
    rb_mesh_free(&m);
}

/* A tilted tessellated floor lit at a grazing angle: no acne. */
static void grazing_light(rb_method method, rt_precision precision,
                          rb_result *r, double angle)
{
    rb_mesh m = {0};
    rb_mesh_grid(&m, rb_v(-1, -1, 0), rb_v(0.125, 0, 0), rb_v(0, 0.125, 0), 16,
                 1, 0, GREY);
    rt_vec3 light = rb_v(10 * cos(angle), 0.3, 10 * sin(angle));
    floor_rays(method, precision, r, &m, light, 1, expect_lit_z,
               rb_is_double(precision) ? 1e-2 : 0.5, 0.98, 0);
    rb_mesh_free(&m);
}

void rb_case_l5(rb_method m, rt_precision p, rb_result *r) { grazing_light(m, p, r, 1e-6); }
void rb_case_l6(rb_method m, rt_precision p, rb_result *r)
{
    if (!rb_is_double(p)) {
        rb_not_applicable(r, "1e-12 rad is below float's resolution: the light is in the plane (L2)");
        return;
    }
    grazing_light(m, p, r, 1e-12);
}

