/*
 * nff_shapes.c - the NFF entities that make facets (nff.h): `f`, the
 * material of what follows; `p` and `pp`, polygons, cut by the readers'
 * one triangulator at once (tessellate.c); `s` and `c`, spheres and cones,
 * kept until the whole file is read (nff_cut.c cuts them from the view).
 * The reader checks every point it computes with before the build
 * (coordinates, radii), with the builder's words.
 */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/vecmath.h"
#include "formats/nff.h"

/* Ear clipping is quadratic or worse: non-convex polygons are limited. */
#define MAX_NONCONVEX_VERTICES 1024

/* f r g b Kd Ks Shine T index */
rt_status rt__nff_material(parser *p, const token *f)
{
    rt_status status;
    if (rt__nff_grow((void **)&p->materials, &p->material_capacity,
                     p->material_count, sizeof *p->materials) != 0)
        return rt__nff_out_of_memory(p);
    rt_facet_desc m;
    memset(&m, 0, sizeof m);
    double kd, ks, shine, tr, index;
    token kd_t, ks_t, tr_t, index_t;
    if ((status = rt__nff_color(p, "the colour", &m.color)) != RT_OK ||
        (status = rt__nff_number(p, "`Kd`", &kd, &kd_t)) != RT_OK ||
        (status = rt__nff_number(p, "`Ks`", &ks, &ks_t)) != RT_OK ||
        (status = rt__nff_number(p, "`Shine`", &shine, NULL)) != RT_OK ||
        (status = rt__nff_number(p, "`T`", &tr, &tr_t)) != RT_OK ||
        (status = rt__nff_number(p, "the index of refraction", &index,
                                 &index_t)) != RT_OK)
        return status;
    if (!(kd >= 0))
        return rt__nff_fail(p, RT_ERR_RANGE, &kd_t,
                            "a diffuse weight Kd >= 0");
    if (!(ks >= 0))
        return rt__nff_fail(p, RT_ERR_RANGE, &ks_t,
                            "a specular weight Ks >= 0");
    if (!(tr >= 0))
        return rt__nff_fail(p, RT_ERR_RANGE, &tr_t, "a transmittance T >= 0");
    if (tr > 0 && !(index > 0))
        return rt__nff_fail(p, RT_ERR_RANGE, &index_t,
                            "an index of refraction > 0 for a transmitting "
                            "material (T > 0)");
    (void)f;
    if (ks + tr > 1) {
        char text[200];
        double sum = ks + tr;
        if (isfinite(sum)) {
            snprintf(text, sizeof text,
                     "Ks + T = %g is more than 1 (the model needs k + t <= "
                     "1): both scaled by 1/%g (the first is here)", sum, sum);
        } else {
            /* Both near DBL_MAX: halved first (exactly), so that the sum
             * and the ratios stay finite. */
            snprintf(text, sizeof text,
                     "Ks + T = %g + %g is more than 1 (the model needs k + t "
                     "<= 1): both scaled by 1/(Ks + T) (the first is here)",
                     ks, tr);
            ks *= 0.5;
            tr *= 0.5;
            sum = ks + tr;
        }
        rt__nff_warn_once(p, ONCE_KT, &ks_t, text);
        ks /= sum;
        tr /= sum;
    }
    m.reflection = ks;
    m.transparency = tr <= 1.0 - m.reflection ? tr : 1.0 - m.reflection;
    m.refractive_index = tr > 0 ? index : 1.0;
    m.diffuse = kd;
    m.diffuse_given = 1;
    /* Ks is the mirror weight and the highlight's (both of Whitted's
     * specular terms), Shine the highlight's exponent; without a highlight
     * the exponent stays 1. */
    m.highlight = m.reflection;
    m.highlight_exponent = m.highlight > 0 ? fmax(1.0, shine) : 1.0;
    p->materials[p->material_count++] = m;
    return RT_OK;
}

static int current_material(parser *p, const token *at)
{
    if (p->material_count == 0) {
        rt__nff_warn_once(
            p, ONCE_MATERIAL, at,
            "an object before any `f`: white, Kd = 1, Ks = T = 0");
        rt_facet_desc m;
        memset(&m, 0, sizeof m);
        m.color = (rt_rgb8){255, 255, 255};
        m.refractive_index = 1.0;
        m.diffuse = 1.0;
        m.diffuse_given = 1;
        if (rt__nff_grow((void **)&p->materials, &p->material_capacity, 0,
                         sizeof *p->materials) != 0)
            return -1;
        p->materials[p->material_count++] = m;
    }
    return p->material_count - 1;
}

static rt_status add_primitive(parser *p, const primitive *prim)
{
    if (rt__nff_grow((void **)&p->primitives, &p->primitive_capacity,
                     p->primitive_count, sizeof *p->primitives) != 0)
        return rt__nff_out_of_memory(p);
    p->primitives[p->primitive_count++] = *prim;
    return RT_OK;
}

/* A radius: non-zero, and the centre +- it within RT_MAX_COORDINATE. */
static rt_status radius(parser *p, const char *what, rt_vec3 center,
                        int zero_allowed, double *r, token *t)
{
    rt_status status = rt__nff_number(p, what, r, t);
    if (status != RT_OK)
        return status;
    if (!zero_allowed && *r == 0)
        return rt__nff_fail(p, RT_ERR_RANGE, t, "a radius other than 0");
    if (v3_max_abs(center) + fabs(*r) > RT_MAX_COORDINATE)
        return rt__nff_fail(
            p, RT_ERR_RANGE, t,
            "a radius that keeps the surface within coordinates of "
            "magnitude 1e152 (the renderer's arithmetic overflows "
            "beyond)");
    /* The spacing of doubles at the centre: a smaller radius moves no
     * coordinate of it, so no surface is there to cut. */
    double largest = v3_max_abs(center);
    double spacing = nextafter(largest, INFINITY) - largest;
    if (*r != 0 && fabs(*r) < spacing) {
        char expected[200];
        snprintf(expected, sizeof expected,
                 "a radius of at least %g, the spacing of doubles at its "
                 "centre (a smaller surface cannot be represented)",
                 spacing);
        return rt__nff_fail(p, RT_ERR_RANGE, t, expected);
    }
    return RT_OK;
}

static void inside_warning(parser *p, const token *t)
{
    rt__nff_warn_once(
        p, ONCE_INSIDE, t,
        "a negative radius (only the inside visible): the facets are "
        "wound inward, but the model sees facets from both sides");
}

rt_status rt__nff_sphere(parser *p, const token *s)
{
    primitive prim;
    memset(&prim, 0, sizeof prim);
    token r_t;
    rt_status status =
        rt__nff_triple(p, "the sphere's centre", 1, &prim.base, NULL);
    if (status == RT_OK)
        status =
            radius(p, "the sphere's radius", prim.base, 0, &prim.r0, &r_t);
    if (status != RT_OK)
        return status;
    if (prim.r0 < 0) {
        inside_warning(p, &r_t);
        prim.r0 = -prim.r0;
        prim.inward = 1;
    }
    if ((prim.material = current_material(p, s)) < 0)
        return rt__nff_out_of_memory(p);
    prim.line = s->line;
    prim.column = s->column;
    return add_primitive(p, &prim);
}

rt_status rt__nff_cone(parser *p, const token *c)
{
    primitive prim;
    memset(&prim, 0, sizeof prim);
    prim.cone = 1;
    token r0_t, r1_t, apex_t;
    rt_status status;
    if ((status = rt__nff_triple(p, "the cone's base", 1, &prim.base, NULL)) !=
            RT_OK ||
        (status = radius(p, "the base radius", prim.base, 1, &prim.r0,
                         &r0_t)) != RT_OK ||
        (status = rt__nff_triple(p, "the cone's apex", 1, &prim.apex,
                                 &apex_t)) != RT_OK ||
        (status = radius(p, "the apex radius", prim.apex, 1, &prim.r1,
                         &r1_t)) != RT_OK)
        return status;
    if ((prim.r0 < 0 && prim.r1 > 0) || (prim.r0 > 0 && prim.r1 < 0))
        return rt__nff_fail(p, RT_ERR_RANGE, &r1_t,
                            "an apex radius of the base radius's sign (both "
                            "negative: only the inside visible)");
    if (prim.r0 == 0 && prim.r1 == 0)
        return rt__nff_fail(p, RT_ERR_RANGE, &r1_t,
                            "a radius other than 0 at the base or the apex");
    if (v3_length(v3_sub(prim.apex, prim.base)) == 0)
        return rt__nff_fail(p, RT_ERR_RANGE, &apex_t,
                            "an apex apart from the base");
    if (prim.r0 < 0 || prim.r1 < 0) {
        inside_warning(p, &r0_t);
        prim.r0 = fabs(prim.r0);
        prim.r1 = fabs(prim.r1);
        prim.inward = 1;
    }
    if ((prim.material = current_material(p, c)) < 0)
        return rt__nff_out_of_memory(p);
    prim.line = c->line;
    prim.column = c->column;
    return add_primitive(p, &prim);
}

/* p n, n vertices; pp n, n vertices each with its normal. */
rt_status rt__nff_polygon(parser *p, const token *entity, int patch)
{
    int n;
    token count_t;
    rt_status status =
        rt__nff_integer(p, "the vertex count", 3, INT_MAX, &n, &count_t);
    if (status != RT_OK)
        return status;
    long per_vertex = patch ? 6 : 3;
    if (n > rt__nff_tokens_left(p) / per_vertex) {
        char expected[160];
        snprintf(expected, sizeof expected,
                 "a vertex count of at most %ld (the values left in the "
                 "file)",
                 rt__nff_tokens_left(p) / per_vertex);
        return rt__nff_fail(p, RT_ERR_LIMIT, &count_t, expected);
    }
    if (n > p->point_capacity) {
        /* (a patch's normals after its points, in the same block) */
        rt_vec3 *grown = realloc(p->points, 2 * (size_t)n * sizeof *grown);
        if (grown == NULL)
            return rt__nff_out_of_memory(p);
        p->points = grown;
        p->point_capacity = n;
    }
    rt_vec3 *normals = patch ? p->points + n : NULL;
    for (int i = 0; i < n; i++) {
        if (i % RT_LOAD_POLL == RT_LOAD_POLL - 1 &&
            rt__load_cancelled(p->options))
            return rt__load_cancel(p->error, p->name);
        if ((status = rt__nff_triple(p, "a vertex", 1, &p->points[i], NULL)) !=
            RT_OK)
            return status;
        if (patch) {
            token t;
            if ((status = rt__nff_triple(p, "a vertex normal", 0, &normals[i],
                                         &t)) != RT_OK)
                return status;
            if (normals[i].x == 0 && normals[i].y == 0 && normals[i].z == 0)
                rt__nff_warn_once(
                    p, ONCE_NORMALS, &t,
                    "a zero vertex normal in a `pp` patch: the triangles at "
                    "that corner are flat (the first is here)");
        }
    }
    if (n > MAX_NONCONVEX_VERTICES &&
        !rt__tess_polygon_convex(p->points, n)) {
        char expected[160];
        snprintf(expected, sizeof expected,
                 "a convex polygon, or a non-convex one of at most %d "
                 "vertices", MAX_NONCONVEX_VERTICES);
        return rt__nff_fail(p, RT_ERR_LIMIT, &count_t, expected);
    }
    int m = current_material(p, entity);
    if (m < 0)
        return rt__nff_out_of_memory(p);
    if (p->mesh.facet_count + (double)n - 2 > RT_TESS_MAX_FACETS)
        return rt__nff_fail(p, RT_ERR_LIMIT, &count_t,
                            "at most 16777216 facets in all");
    int irregular = 0;
    if (rt__tess_patch(&p->mesh, p->points, normals, n, &p->materials[m],
                       entity->line, &irregular) != 0)
        return rt__nff_out_of_memory(p);
    if (irregular)
        rt__nff_warn_once(
            p, ONCE_IRREGULAR, entity,
            "a polygon that is not simple (self-intersecting, or "
            "degenerate): cut into triangles corner by corner (the "
            "first is here)");
    return RT_OK;
}
