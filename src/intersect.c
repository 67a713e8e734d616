/*
 * intersect.c - watertight ray/facet intersection and the brute-force
 * nearest-hit and any-hit queries.
 *
 * The test is the one of Woop, Benthin and Wald, "Watertight Ray/Triangle
 * Intersection", JCGT 2(1), 2013: the ray is mapped to the +z axis by a
 * permutation and a shear, and the facet is tested in 2D by three edge
 * functions.  An edge shared by two facets gets bit-for-bit opposite (or
 * equal) edge functions in both, so a ray through the edge cannot slip
 * between them.  This needs the products rounded as written (no FMA
 * contraction: the library is built with -ffp-contract=off), and an exact
 * sign when an edge function rounds to zero, which the fallback below gives
 * with Kahan's difference of products.
 */
#include <float.h>
#include <math.h>

#include "intersect.h"
#include "vecmath.h"

rt_ray_prep rt__ray_prepare(rt_vec3 origin, rt_vec3 direction)
{
    rt_ray_prep r;
    r.origin = origin;
    r.direction = direction;
    rt_vec3 d = v3_abs(direction);
    r.kz = d.x >= d.y ? (d.x >= d.z ? 0 : 2) : (d.y >= d.z ? 1 : 2);
    r.kx = (r.kz + 1) % 3;
    r.ky = (r.kx + 1) % 3;
    double dz = v3_get(direction, r.kz);
    if (dz < 0.0) {         /* keep the winding of the 2D projection */
        int swap = r.kx;
        r.kx = r.ky;
        r.ky = swap;
    }
    r.sx = v3_get(direction, r.kx) / dz;
    r.sy = v3_get(direction, r.ky) / dz;
    r.sz = 1.0 / dz;
    return r;
}

/* a*b - c*d with an error below 2 ulps, hence with the exact sign. */
static double difference_of_products(double a, double b, double c, double d)
{
    double cd = c * d;
    double error = fma(-c, d, cd);
    return fma(a, b, -cd) + error;
}

/* x*w - y*z, the 2D edge function, with the exact sign when it is zero. */
static double edge(double x, double w, double y, double z)
{
    double e = x * w - y * z;
    if (e == 0.0)
        e = difference_of_products(x, w, y, z);
    return e;
}

int rt__intersect_tri(const rt_ray_prep *ray, const rt_tri *tri, double t_max,
                      rt_tri_hit *hit)
{
    rt_vec3 a = v3_sub(tri->a, ray->origin);
    rt_vec3 b = v3_sub(tri->b, ray->origin);
    rt_vec3 c = v3_sub(tri->c, ray->origin);
    double az = v3_get(a, ray->kz), bz = v3_get(b, ray->kz),
           cz = v3_get(c, ray->kz);
    double ax = v3_get(a, ray->kx) - ray->sx * az;
    double ay = v3_get(a, ray->ky) - ray->sy * az;
    double bx = v3_get(b, ray->kx) - ray->sx * bz;
    double by = v3_get(b, ray->ky) - ray->sy * bz;
    double cx = v3_get(c, ray->kx) - ray->sx * cz;
    double cy = v3_get(c, ray->ky) - ray->sy * cz;

    double u = edge(cx, by, cy, bx);
    double v = edge(ax, cy, ay, cx);
    double w = edge(bx, ay, by, ax);
    if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0))
        return 0;
    double det = u + v + w;
    if (det == 0.0)
        return 0;
    az *= ray->sz;
    bz *= ray->sz;
    cz *= ray->sz;
    double t = (u * az + v * bz + w * cz) / det;
    if (!(t > 0.0 && t < t_max))
        return 0;
    hit->t = t;
    hit->b0 = u / det;
    hit->b1 = v / det;
    hit->b2 = w / det;
    return 1;
}

int rt__nearest_hit(const rt_scene *scene, const rt_ray_prep *ray,
                    double t_max, int skip, rt_tri_hit *hit, uint64_t *tests)
{
    int found = 0;
    rt_tri_hit candidate;
    for (int i = 0; i < scene->tri_count; i++) {
        if (i == skip)
            continue;
        if (rt__intersect_tri(ray, &scene->tris[i], t_max, &candidate)) {
            candidate.tri = i;
            *hit = candidate;
            t_max = candidate.t;    /* strict: equal t keeps the lower index */
            found = 1;
        }
    }
    *tests += (uint64_t)scene->tri_count - (skip >= 0);
    return found;
}

int rt__any_hit(const rt_scene *scene, const rt_ray_prep *ray, double t_max,
                int skip, uint64_t *tests)
{
    rt_tri_hit ignored;
    uint64_t made = 0;
    int found = 0;
    for (int i = 0; i < scene->tri_count && !found; i++) {
        if (i == skip)
            continue;
        made++;
        found = rt__intersect_tri(ray, &scene->tris[i], t_max, &ignored);
    }
    *tests += made;
    return found;
}

/* gamma(n) = n u / (1 - n u), u the unit roundoff: Higham's bound on n
 * successive roundings, as pbrt-v4 uses it. */
static double gamma_bound(int n)
{
    double u = DBL_EPSILON * 0.5;
    return n * u / (1.0 - n * u);
}

rt_vec3 rt__hit_point(const rt_tri *tri, const rt_tri_hit *hit,
                      rt_vec3 *error_bound)
{
    rt_vec3 pa = v3_scale(tri->a, hit->b0);
    rt_vec3 pb = v3_scale(tri->b, hit->b1);
    rt_vec3 pc = v3_scale(tri->c, hit->b2);
    rt_vec3 sum = v3_add(v3_abs(pa), v3_add(v3_abs(pb), v3_abs(pc)));
    *error_bound = v3_scale(sum, gamma_bound(7));
    return v3_add(pa, v3_add(pb, pc));
}

rt_vec3 rt__offset_origin(rt_vec3 point, rt_vec3 error_bound, rt_vec3 normal,
                          rt_vec3 direction)
{
    double distance = v3_dot(v3_abs(normal), error_bound);
    rt_vec3 offset = v3_scale(normal, distance);
    if (v3_dot(direction, normal) < 0.0)
        offset = v3_neg(offset);
    rt_vec3 p = v3_add(point, offset);
    /* Round away from the surface so the addition cannot undo the offset. */
    double *c[3] = {&p.x, &p.y, &p.z};
    double o[3] = {offset.x, offset.y, offset.z};
    for (int i = 0; i < 3; i++) {
        if (o[i] > 0.0)
            *c[i] = nextafter(*c[i], INFINITY);
        else if (o[i] < 0.0)
            *c[i] = nextafter(*c[i], -INFINITY);
    }
    return p;
}
