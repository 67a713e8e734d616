/*
 * accel_scenes.h - what the comparison tests of the accelerators
 * (tests/test_octree.c, tests/test_kdtree.c) share: soups of facets, the
 * distributions a space subdivision handles worst, and the checks that an
 * accelerator gives brute force's images and colours byte for byte.
 * Compiled into each of those suites (tests/octree.cmake,
 * tests/kernel.cmake); names start with accel_.
 */
#ifndef RAYTRACE_TEST_ACCEL_SCENES_H
#define RAYTRACE_TEST_ACCEL_SCENES_H

#include <stddef.h>

#include "kernel/kernel.h"
#include "testutil.h"

/* Facets being gathered into a scene (owned arrays). */
typedef struct accel_soup {
    rt_vec3 *v;
    rt_facet_desc *f;
    int nv, nf, cap;
} accel_soup;

/* Appends the facet a b c of reflection k (a colour of its own). */
void accel_soup_add(accel_soup *s, rt_vec3 a, rt_vec3 b, rt_vec3 c, double k);

/* The scene of `desc`, which holds the soup's arrays; the soup is then
 * emptied (a refused scene fails the test). */
rt_scene *accel_soup_create(const rt_scene_desc *desc, accel_soup *s);

/* The soup seen from `eye` towards `at`, lit from `light`, side x side
 * pixels; the soup is emptied. */
rt_scene *accel_soup_scene(accel_soup *s, rt_vec3 eye, rt_vec3 at,
                           rt_vec3 light, int side);

/* p moved by up to r on each axis. */
rt_vec3 accel_jitter(rt_test_rng *rng, rt_vec3 p, double r);

/* The distributions; `small` non-zero: the reduced sizes of valgrind and
 * AddressSanitizer runs.  Each returns a scene the caller destroys. */
rt_scene *accel_one_spot(rt_test_rng *rng, int small);
rt_scene *accel_spanning(rt_test_rng *rng, int small);
rt_scene *accel_slivers_and_walls(rt_test_rng *rng, int small);
rt_scene *accel_coincident(rt_test_rng *rng, int small);
rt_scene *accel_far_camera(rt_test_rng *rng, int small, int inside);
rt_scene *accel_transparency_lights_lens(rt_test_rng *rng, int small);
rt_scene *accel_at_the_limit(rt_test_rng *rng, int small);

/* An n x n grid of unit squares in z = 0 (integer vertices) under a
 * reflective facet, 8 x 8 pixels. */
rt_scene *accel_grid(int n);

/* Ray i of the grid's test of n: random, grazing the plane, in the plane
 * x = integer, through a vertex (by i mod 4). */
void accel_grid_ray(rt_test_rng *rng, int n, int i, rt_vec3 *origin,
                    rt_vec3 *target);

/* Brute force on one thread against `accel` on 1 and 3 threads, with 1
 * and 4 samples, in double and float (when float can hold the scene):
 * the same bytes, the same rays; width x height or 0 x 0 (the scene's). */
void accel_check_scene(const rt_scene *scene, int width, int height,
                       rt_accel accel, const char *name);

/* accel_check_scene on every .scn of `dir` at most side x side pixels;
 * the number of scenes. */
size_t accel_check_directory(const char *dir, int side, rt_accel accel);

/* The same colour, bit for bit, by brute force and through the kernels'
 * structure (`tree`: the settings that choose it), in double (kd) and
 * float (kf), with the scalar and the fast loops. */
void accel_check_ray(const rt_kernel *kd, const rt_kernel *kf,
                     rt_vec3 origin, rt_vec3 target,
                     const rt_trace_settings *tree);

#endif /* RAYTRACE_TEST_ACCEL_SCENES_H */
