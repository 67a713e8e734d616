/*
 * bench_scenes.h - the scenes the performance benchmark renders besides
 * files: generated meshes of any size.  Every generator is deterministic (a fixed LCG), so a facet count
 * always gives the same scene.
 */
#ifndef RAYTRACE_BENCH_SCENES_H
#define RAYTRACE_BENCH_SCENES_H

#include "raytrace/raytrace.h"

/* A unit sphere of about `facets` triangles (latitude-longitude
 * tessellation), grey, k = 0 everywhere, seen from outside. */
rt_status bench_sphere(int facets, int width, int height, rt_scene **scene,
                       rt_error *error);

/* `facets` random triangles in the cube [-1, 1]^3, random colours, every
 * third one reflective (k = 0.3). */
rt_status bench_soup(int facets, int width, int height, rt_scene **scene,
                     rt_error *error);

#endif /* RAYTRACE_BENCH_SCENES_H */
