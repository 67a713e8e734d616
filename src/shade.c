/*
 * shade.c - the colour of a ray: SPEC.md section 3.
 *
 *     C = k C_R + E (1 - k) (N.S) C_S C_F / 255
 *
 * The recursion on C_R is unrolled into a loop: the colour is the sum over
 * the bounces of each hit's own term weighted by the product of the k met
 * before it, so any depth runs in constant stack.  Work that cannot change
 * the result is left out, exactly: no shadow ray where N.S <= 0 or k = 1,
 * no reflected ray from a facet with k = 0.
 */
#include "shade.h"

#include <math.h>

#include "intersect.h"
#include "vecmath.h"

/* The lit term E (N.S) (1 - k) C_S C_F / 255 of a hit, added to *color
 * with weight `weight`. */
static void add_direct_light(const rt_scene *scene, const rt_tri *tri,
                             rt_vec3 point, rt_vec3 error_bound,
                             rt_vec3 normal, int tri_index, double weight,
                             rt_color *color, rt_counters *counters)
{
    rt_vec3 to_light = v3_sub(scene->light, point);
    double facing = v3_dot(normal, to_light);
    if (tri->k == 1.0 || !(facing > 0.0)) {
        counters->shadow_rays_skipped++;
        return;
    }
    rt_vec3 origin = rt__offset_origin(point, error_bound, normal, to_light);
    rt_vec3 segment = v3_sub(scene->light, origin);
    rt_ray_prep shadow = rt__ray_prepare(origin, segment);
    counters->shadow_rays++;
    if (rt__any_hit(scene, &shadow, 1.0, tri_index, &counters->tests))
        return;
    double n_dot_s = v3_dot(normal, v3_normalize(to_light));
    double w = weight * n_dot_s;
    color->r += w * tri->diffuse[0];
    color->g += w * tri->diffuse[1];
    color->b += w * tri->diffuse[2];
}

rt_color rt__trace(const rt_scene *scene, rt_vec3 origin, rt_vec3 direction,
                   int max_depth, rt_counters *counters)
{
    rt_color color = {0.0, 0.0, 0.0};
    double weight = 1.0;
    int skip = -1;
    rt_vec3 incoming = v3_normalize(direction);
    for (int bounce = 0;; bounce++) {
        rt_ray_prep ray = rt__ray_prepare(origin, incoming);
        rt_tri_hit hit;
        if (!rt__nearest_hit(scene, &ray, INFINITY, skip, &hit,
                             &counters->tests)) {
            color.r += weight * scene->background.r;
            color.g += weight * scene->background.g;
            color.b += weight * scene->background.b;
            break;
        }
        const rt_tri *tri = &scene->tris[hit.tri];
        rt_vec3 error_bound;
        rt_vec3 point = rt__hit_point(tri, &hit, &error_bound);
        rt_vec3 normal = tri->normal;   /* two-sided: face the ray */
        if (v3_dot(normal, incoming) > 0.0)
            normal = v3_neg(normal);
        add_direct_light(scene, tri, point, error_bound, normal, hit.tri,
                         weight, &color, counters);
        if (tri->k == 0.0) {
            counters->reflection_rays_skipped += bounce < max_depth;
            break;
        }
        if (bounce >= max_depth)
            break;          /* a reflection past the limit is black */
        weight *= tri->k;
        rt_vec3 reflected = v3_sub(
            incoming, v3_scale(normal, 2.0 * v3_dot(incoming, normal)));
        origin = rt__offset_origin(point, error_bound, normal, reflected);
        incoming = v3_normalize(reflected);
        skip = hit.tri;
        counters->reflection_rays++;
    }
    return color;
}
