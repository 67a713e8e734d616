/*
 * cases.h - what the files of the robustness cases share (cases.c and
 * cases_*.c, one per family of docs/robustness.md): the colours, the
 * helpers of the ray-level cases (a view, random points and directions,
 * the edges a mesh shares), the helpers of the image cases, and the run
 * function of every case, which the table in cases.c lists.  Internal to
 * the robustness library: robust.h is what the suite and the report see.
 */
#ifndef RAYTRACE_TESTS_ROBUST_CASES_H
#define RAYTRACE_TESTS_ROBUST_CASES_H

#include "rng.h"
#include "robust/robust.h"

#define RB_PI 3.14159265358979323846

/* The colours of the cases' facets, lights and backgrounds. */
#define WHITE ((rt_rgb8){255, 255, 255})
#define GREY ((rt_rgb8){200, 200, 200})
#define RED ((rt_rgb8){220, 60, 50})
#define GREEN ((rt_rgb8){60, 200, 80})
#define BLUE ((rt_rgb8){50, 80, 220})
#define SKY ((rt_rgb8){40, 60, 120})

/* Marks `r` as not applying to this method or precision, saying why. */
void rb_not_applicable(rb_result *r, const char *why);
/* A view for ray-level cases: a valid camera far above, the light given. */
rb_view rb_ray_view(double scale, rt_vec3 light, rt_rgb8 background);
int rb_is_double(rt_precision p);
/* Uniform in the ball of `radius` about the origin; on the unit sphere. */
rt_vec3 rb_random_in_ball(rt_test_rng *rng, double radius);
rt_vec3 rb_random_unit(rt_test_rng *rng);

/* The edges two facets share, and the vertices all of whose edges are
 * shared (the inside of a mesh): where rays are aimed. */
typedef struct rb_shared {
    int (*edges)[2];
    int edge_count;
    int *vertices;
    int vertex_count;
} rb_shared;

rb_shared rb_shared_of(const rb_mesh *m);
void rb_shared_free(rb_shared *sh);
/* A point on an edge shared by two facets, or (with probability
 * vertex_share) a vertex inside the mesh. */
rt_vec3 rb_shared_point(const rb_mesh *m, const rb_shared *sh,
                        rt_test_rng *rng, double vertex_share);
/* Whether the hit's t or point is NaN. */
int rb_hit_is_nan(const rb_hit *h);

/* The image cases' scene (cases_invariance.c): a reflective floor, a slab
 * lifted by 1e-3 of its size, a sphere, a mirror wall; 64 x 64. */
void rb_invariance_scene(rb_mesh *m, rb_view *v);
/* The mesh and view scaled and moved, rendered by `method` (pixels NULL,
 * *nans -1, when the scene is refused); *nans: its NaN pixels. */
rt_image rb_render_view(const rb_mesh *base, const rb_view *base_view,
                        double scale, rt_vec3 shift, rb_method method,
                        rt_precision precision, long *nans);
/* Pixels that differ (all of them when either image is missing). */
long rb_count_differing(const rt_image *a, const rt_image *b);

/* The cases, by family: rb_case_w1 runs W1, and so on. */
typedef void rb_case_fn(rb_method method, rt_precision precision,
                        rb_result *r);
rb_case_fn rb_case_w1, rb_case_w2, rb_case_w3, rb_case_w4, rb_case_w5;
rb_case_fn rb_case_d1, rb_case_d2, rb_case_d3, rb_case_d4, rb_case_d5;
rb_case_fn rb_case_t1, rb_case_t2, rb_case_t3, rb_case_t4, rb_case_t5;
rb_case_fn rb_case_s1, rb_case_s2, rb_case_s3, rb_case_s4, rb_case_s5,
           rb_case_s6;
rb_case_fn rb_case_l1, rb_case_l2, rb_case_l3, rb_case_l4, rb_case_l5,
           rb_case_l6;
rb_case_fn rb_case_c1, rb_case_c2, rb_case_c3;
rb_case_fn rb_case_r1, rb_case_r2;
rb_case_fn rb_case_v1, rb_case_v2, rb_case_v3, rb_case_v4, rb_case_v5;
rb_case_fn rb_case_q1, rb_case_q2;
rb_case_fn rb_case_g1, rb_case_g2, rb_case_g3, rb_case_g4;
rb_case_fn rb_case_x1, rb_case_x2;

#endif /* RAYTRACE_TESTS_ROBUST_CASES_H */
