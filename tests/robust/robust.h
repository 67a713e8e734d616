/*
 * robust.h - the numerical-robustness cases of docs/robustness.md, shared by
 * the Check suite (tests/test_robust.c) and the report (robustness-report).
 *
 * Each case builds a stiff or extreme scene, runs one method on it - our
 * renderer or a naive reference - in double or float, and counts what its
 * criterion calls a failure (a ray that falls through a mesh, a speckle of
 * acne, a leak of light, a NaN).  The suites assert that ours fails nowhere;
 * the report prints every method side by side (docs/robustness.md).  The
 * naive renderer lives here, in the tests, never in the library.
 */
#ifndef RAYTRACE_TESTS_ROBUST_H
#define RAYTRACE_TESTS_ROBUST_H

#include <stdint.h>

#include "raytrace/raytrace.h"
#include "rng.h"            /* the support library's generator */

/* ------------------------------------------------------------------ */
/* Methods                                                             */

typedef enum rb_method {
    RB_OURS = 0,        /* libraytrace: watertight test, error-bounded offset */
    RB_NAIVE_MT,        /* Moller-Trumbore, |det| < 1e-5 and t > 1e-5
                           rejected, secondary rays offset by 1e-5 */
    RB_NAIVE_MT_FMA,    /* the same with its products fused (FMA), as a
                           contracting compiler would build it */
    RB_NAIVE_PLANE,     /* the handout's test: the ray meets the plane, then
                           changeCoord through the 2x2 normal equations and
                           isInFacet within 1e-5; offset 1e-5 */
    RB_METHOD_COUNT
} rb_method;

#define RB_NAIVE_EPSILON 1e-5

const char *rb_method_name(rb_method method);

/* An intersector and shader over one scene, of one method and precision. */
typedef struct rb_engine rb_engine;

typedef struct rb_hit {
    double t;
    int facet;          /* index of the facet record */
    rt_vec3 point;
} rb_hit;

rb_engine *rb_engine_create(const rt_scene *scene, rb_method method,
                            rt_precision precision);
void rb_engine_free(rb_engine *engine);
/* Nearest hit for t in (0, inf); 0 when none. */
int rb_engine_hit(const rb_engine *engine, rt_ray ray, rb_hit *hit);
/* The colour of a ray (docs/rendering-model.md), at most `depth`
 * reflections. */
rt_color rb_engine_trace(const rb_engine *engine, rt_ray ray, int depth);
/* Renders the scene's camera view into `image` (the scene's size) with
 * `threads` threads (ours: rt_render; naive: one thread); returns the
 * number of pixels whose real colour is NaN (ours: found by tracing each
 * pixel's primary ray again). */
long rb_engine_render(const rb_engine *engine, int depth, int threads,
                      rt_image *image);

int rb_color_has_nan(rt_color c);

/* The acceleration the cases render with: RT_TEST_ACCEL=octree forces the
 * octree on, =kdtree the kd-tree, =none both off; unset, the library's
 * default (tests/robustness.cmake registers every suite all three ways). */
rt_accel rb_accel(void);

/* ------------------------------------------------------------------ */
/* Scene builders                                                      */

typedef struct rb_mesh {
    rt_vec3 *vertices;
    int vertex_count, vertex_capacity;
    rt_facet_desc *facets;
    int facet_count, facet_capacity;
} rb_mesh;

void rb_mesh_free(rb_mesh *mesh);
int rb_mesh_vertex(rb_mesh *mesh, rt_vec3 p);
int rb_mesh_facet(rb_mesh *mesh, int a, int b, int c, double k, rt_rgb8 color);
/* Appends a triangle with its own three vertices. */
int rb_mesh_triangle(rb_mesh *mesh, rt_vec3 a, rt_vec3 b, rt_vec3 c,
                     double k, rt_rgb8 color);
/* Unit icosahedron subdivided `levels` times, projected on the sphere of
 * radius r about centre: 20 * 4^levels facets sharing edges exactly. */
void rb_mesh_icosphere(rb_mesh *mesh, rt_vec3 centre, double r, int levels,
                       double k, rt_rgb8 color);
/* A grid of n x n cells, two facets each, corner + i u + j v; `alternate`
 * reverses the winding of every other facet and the diagonal direction. */
void rb_mesh_grid(rb_mesh *mesh, rt_vec3 corner, rt_vec3 u, rt_vec3 v,
                  int n, int alternate, double k, rt_rgb8 color);
/* An axis-aligned box, 12 facets. */
void rb_mesh_box(rb_mesh *mesh, rt_vec3 lo, rt_vec3 hi, double k,
                 rt_rgb8 color);
/* p * scale + shift for every vertex. */
void rb_mesh_transform(rb_mesh *mesh, double scale, rt_vec3 shift);
/* An existing vertex with exactly these coordinates, or a new one. */
int rb_mesh_vertex_shared(rb_mesh *mesh, rt_vec3 p);
/* Appends the quad p0 p1 p2 p3 as two facets sharing the diagonal p0-p2;
 * a corner equal to an existing vertex reuses it (quads that meet share
 * vertices); returns the first facet. */
int rb_mesh_quad(rb_mesh *mesh, rt_vec3 p0, rt_vec3 p1, rt_vec3 p2,
                 rt_vec3 p3, double k, rt_rgb8 color);
/* Reverses the winding of facets [first, mesh->facet_count) whose winding
 * normal (b - a) x (c - a) points towards `inside` (a point inside a
 * convex mesh): afterwards they wind counter-clockwise seen from outside,
 * as docs/rendering-model.md asks of transparent facets. */
void rb_mesh_orient_outward(rb_mesh *mesh, int first, rt_vec3 inside);
/* Makes facets [first, mesh->facet_count) glass: k = 0, transparency t,
 * index n, diffuse weight 0 (given). */
void rb_mesh_glass(rb_mesh *mesh, int first, double t, double n);

/* Everything else a scene needs around a mesh. */
typedef struct rb_view {
    rt_vec3 observer, screen_center, screen_right;
    int width, height;
    rt_vec3 light;
    rt_rgb8 light_color, background;
} rb_view;

rt_vec3 rb_transform_point(rt_vec3 p, double scale, rt_vec3 shift);
void rb_view_transform(rb_view *view, double scale, rt_vec3 shift);
/* rt_scene_create over mesh and view; NULL (with the message on stderr)
 * when it is refused. */
rt_scene *rb_scene(const rb_mesh *mesh, const rb_view *view);
/* The same with further lights, already placed. */
rt_scene *rb_scene_lights(const rb_mesh *mesh, const rb_view *view,
                          const rt_light *further, int further_count);

/* ------------------------------------------------------------------ */
/* Helpers                                                             */

/* How many rays a case sends where it would send n: n, or n / 100 (at
 * least 20) when RT_TEST_MEMCHECK is set, so that the suites also run under
 * valgrind within CI's time (.ci/memcheck). */
int rb_scaled(int n);

static inline rt_vec3 rb_v(double x, double y, double z)
{
    return (rt_vec3){x, y, z};
}
rt_vec3 rb_add(rt_vec3 a, rt_vec3 b);
rt_vec3 rb_sub(rt_vec3 a, rt_vec3 b);
rt_vec3 rb_scale(rt_vec3 a, double s);
double rb_dot(rt_vec3 a, rt_vec3 b);
rt_vec3 rb_cross(rt_vec3 a, rt_vec3 b);
double rb_length(rt_vec3 a);
rt_vec3 rb_lerp(rt_vec3 a, rt_vec3 b, double s);
/* A fixed rotation with no axis-aligned direction, applied to p. */
rt_vec3 rb_rotate(rt_vec3 p);

/* ------------------------------------------------------------------ */
/* Cases                                                               */

typedef struct rb_result {
    long total;         /* what was counted: rays, pixels, inputs */
    long failures;      /* what the criterion calls a failure */
    long nans;          /* NaN in an output (a colour, a t, a point) */
    int applicable;     /* 0: this method or precision does not apply */
    char note[256];     /* why not, or what else was measured */
} rb_result;

typedef void (*rb_run)(rb_method method, rt_precision precision,
                       rb_result *result);

typedef struct rb_case {
    const char *id;         /* "W1" */
    const char *group;      /* "watertightness" */
    const char *setup;      /* what the case is, one sentence */
    const char *criterion;  /* what counts as a failure */
    rb_run run;
} rb_case;

extern const rb_case rb_cases[];
extern const int rb_case_count;

const rb_case *rb_case_find(const char *id);
/* Runs one case; result->applicable says whether it applied. */
void rb_case_run(const rb_case *c, rb_method method, rt_precision precision,
                 rb_result *result);

#endif /* RAYTRACE_TESTS_ROBUST_H */
