/*
 * intersect.h - ray/facet intersection and brute-force scene queries
 * (internal).
 */
#ifndef RAYTRACE_INTERSECT_H
#define RAYTRACE_INTERSECT_H

#include <stdint.h>

#include "scene_internal.h"

/* A ray prepared for the watertight test: the axis permutation and shear
 * that map its direction onto +z. */
typedef struct rt_ray_prep {
    rt_vec3 origin;
    rt_vec3 direction;
    int kx, ky, kz;
    double sx, sy, sz;
} rt_ray_prep;

/* A hit found by the queries below. */
typedef struct rt_tri_hit {
    double t;
    double b0, b1, b2;      /* barycentric weights of a, b, c */
    int tri;                /* index into scene->tris */
} rt_tri_hit;

/* Prepares a ray; the direction must be finite and non-zero. */
rt_ray_prep rt__ray_prepare(rt_vec3 origin, rt_vec3 direction);

/*
 * The watertight test of Woop, Benthin and Wald (JCGT 2013) on one facet:
 * non-zero when the ray meets it at some t in (0, t_max); fills *hit.
 */
int rt__intersect_tri(const rt_ray_prep *ray, const rt_tri *tri, double t_max,
                      rt_tri_hit *hit);

/* Nearest hit over all live facets except `skip` (-1 for none); ties go to
 * the lowest index.  Adds the number of facet tests to *tests. */
int rt__nearest_hit(const rt_scene *scene, const rt_ray_prep *ray,
                    double t_max, int skip, rt_tri_hit *hit, uint64_t *tests);

/* Non-zero when some live facet except `skip` meets the ray in
 * (0, t_max); stops at the first.  Adds the tests made to *tests. */
int rt__any_hit(const rt_scene *scene, const rt_ray_prep *ray, double t_max,
                int skip, uint64_t *tests);

/*
 * The hit point, computed from barycentric weights, and its rounding-error
 * bound per component (pbrt-v4's bound for this computation).
 */
rt_vec3 rt__hit_point(const rt_tri *tri, const rt_tri_hit *hit,
                      rt_vec3 *error_bound);

/*
 * The origin for a ray leaving the surface at `point` towards `direction`:
 * moved along the normal, to the side `direction` goes, by just more than
 * the point's error bound, so that no rounding can put it behind the surface
 * it leaves at any scale of coordinates (pbrt-v4's OffsetRayOrigin rule).
 */
rt_vec3 rt__offset_origin(rt_vec3 point, rt_vec3 error_bound, rt_vec3 normal,
                          rt_vec3 direction);

#endif /* RAYTRACE_INTERSECT_H */
