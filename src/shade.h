/*
 * shade.h - the colour of a ray (internal).
 */
#ifndef RAYTRACE_SHADE_H
#define RAYTRACE_SHADE_H

#include <stdint.h>

#include "raytrace/render.h"
#include "scene_internal.h"

/* Work counters of one thread; summed into rt_render_stats at the end. */
typedef struct rt_counters {
    uint64_t shadow_rays;
    uint64_t reflection_rays;
    uint64_t tests;
    uint64_t shadow_rays_skipped;
    uint64_t reflection_rays_skipped;
} rt_counters;

/* SPEC.md section 3 for one ray with a non-zero finite direction. */
rt_color rt__trace(const rt_scene *scene, rt_vec3 origin, rt_vec3 direction,
                   int max_depth, rt_counters *counters);

#endif /* RAYTRACE_SHADE_H */
