/*
 * spec.h - scenes as data for the kernel suites (test_packets*.c): a
 * camera, vertices, facets and lights held in a fixed-size value, built by
 * a few calls (a triangle, a quad, a box, a light, an aim) and written as
 * .scn text at any scale; and the fast kernel against the scalar loops on
 * such a scene (RT_KERNEL_AUTO on one and two threads against
 * RT_KERNEL_SCALAR on one, in double and float, at 1 sample, 4 regular and
 * 4 stratified), every mismatch printed and counted before the test fails.
 *
 * Part of the support library (tests/support/) but not of testutil.h:
 * include it where it is used, for its short vector helpers (vec, add,
 * sub, mul, cross, length, unit) are static inline here, not exported.
 * The functions fail the test (Check) when they cannot do their job.
 */
#ifndef RAYTRACE_TEST_SPEC_H
#define RAYTRACE_TEST_SPEC_H

#include <math.h>

#include "raytrace/raytrace.h"

/* What a spec holds at most: a case beyond a kernel's limits (64 facets,
 * 8 lights) still fits. */
#define RT_TEST_SPEC_MAX_VERTICES 256
#define RT_TEST_SPEC_MAX_FACETS 80
#define RT_TEST_SPEC_MAX_LIGHTS 12

typedef struct rt_test_spec_facet_t {
    int v[3];               /* 0-based */
    double k;
    int color[3];
} rt_test_spec_facet_t;

typedef struct rt_test_spec_light_t {
    rt_vec3 p;
    int color[3];
} rt_test_spec_light_t;

/* A scene: the camera (eye, screen centre a, its right edge's middle b),
 * the image size, the geometry, the background and the lights. */
typedef struct rt_test_spec {
    rt_vec3 eye, a, b;
    int width, height;
    int nv, nf, nl;
    rt_vec3 v[RT_TEST_SPEC_MAX_VERTICES];
    rt_test_spec_facet_t f[RT_TEST_SPEC_MAX_FACETS];
    int background[3];
    rt_test_spec_light_t l[RT_TEST_SPEC_MAX_LIGHTS];
} rt_test_spec;

static inline rt_vec3 vec(double x, double y, double z)
{
    return (rt_vec3){x, y, z};
}
static inline rt_vec3 add(rt_vec3 a, rt_vec3 b)
{
    return vec(a.x + b.x, a.y + b.y, a.z + b.z);
}
static inline rt_vec3 sub(rt_vec3 a, rt_vec3 b)
{
    return vec(a.x - b.x, a.y - b.y, a.z - b.z);
}
static inline rt_vec3 mul(rt_vec3 a, double s)
{
    return vec(a.x * s, a.y * s, a.z * s);
}
static inline rt_vec3 cross(rt_vec3 a, rt_vec3 b)
{
    return vec(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z,
               a.x * b.y - a.y * b.x);
}
static inline double length(rt_vec3 a)
{
    return sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
}
static inline rt_vec3 unit(rt_vec3 a) { return mul(a, 1.0 / length(a)); }

/* A new empty spec (calloc'd; free it): 24 x 18, a dark blue background. */
rt_test_spec *rt_test_spec_new(void);

/* Appends a vertex; its index. */
int rt_test_spec_vertex(rt_test_spec *s, rt_vec3 p);
/* Appends the facet a, b, c (0-based vertex indices). */
void rt_test_spec_facet(rt_test_spec *s, int a, int b, int c, double k,
                        int r, int g, int bl);
/* A facet with its own three vertices. */
void rt_test_spec_triangle(rt_test_spec *s, rt_vec3 a, rt_vec3 b, rt_vec3 c,
                           double k, int r, int g, int bl);
/* The square a, b, c, d (in order round it) as two facets. */
void rt_test_spec_quad(rt_test_spec *s, rt_vec3 a, rt_vec3 b, rt_vec3 c,
                       rt_vec3 d, double k, int r, int g, int bl);
/* A closed box [lo, hi] of 12 facets wound outwards. */
void rt_test_spec_box(rt_test_spec *s, rt_vec3 lo, rt_vec3 hi, double k,
                      int r, int g, int b);
void rt_test_spec_light(rt_test_spec *s, rt_vec3 p, int r, int g, int b);
/* The camera at `eye` looking along `direction` (A = eye + direction, as
 * given: an exact diagonal stays exact), the screen's half-width
 * `half_width` |direction|, right-handed with `up` roughly up. */
void rt_test_spec_aim(rt_test_spec *s, rt_vec3 eye, rt_vec3 direction,
                      rt_vec3 up, double half_width);

/* The .scn text of *s with every coordinate (camera, vertices, lights)
 * multiplied by `scale`; malloc'd. */
char *rt_test_spec_text(const rt_test_spec *s, double scale);

/* The precisions a check renders in. */
#define RT_TEST_DOUBLE_ONLY 1u
#define RT_TEST_FLOAT_ONLY 2u
#define RT_TEST_BOTH_PRECISIONS 3u

/* Starts a test's count of cases, renders, mismatches and skips. */
void rt_test_kernels_reset(void);

/* Fails the test when it found a mismatch; prints what it checked. */
void rt_test_kernels_finish(const char *test);

/* Renders `scene` with `base` (precision, kernel, threads, samples and
 * sampling set here) in `precisions` and the three samplings: the scalar
 * loops on one thread, the fast kernel on one and two threads, which must
 * give the same bytes and cast the same shadow and reflected rays.  A
 * precision the scene cannot be rendered in (float's range) is skipped,
 * and said so. */
void rt_test_kernels_check(const char *name, const rt_scene *scene,
                           const rt_render_options *base,
                           unsigned precisions);

/* Loads *s at `scale` and checks it; when the loader refuses the scene,
 * fails the test unless `may_refuse`, in which case the case is skipped
 * and said so.  `base` NULL: the default options. */
void rt_test_spec_check(const char *name, const rt_test_spec *s,
                        double scale, const rt_render_options *base,
                        unsigned precisions, int may_refuse);

/* The pieces of a check, for a test that renders its own way: one render
 * (counted), the comparison of two (a mismatch counted and printed), a
 * case counted, a case skipped (counted, and printed with `why`). */
rt_image rt_test_kernels_render(const rt_scene *scene,
                                const rt_render_options *options,
                                const char *what);
void rt_test_kernels_compare(const rt_image *ref, const rt_image *got,
                             const rt_render_options *options,
                             const char *what);
void rt_test_kernels_count_case(void);
void rt_test_kernels_skip(const char *what, const char *why);

#endif /* RAYTRACE_TEST_SPEC_H */
