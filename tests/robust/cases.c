/*
 * cases.c - the stiff and extreme cases of docs/robustness.md: their table
 * (id, group, setup, criterion, run function) and the helpers the case
 * files share (robust/cases.h).
 *
 * A case builds its scene, runs one method in one precision and counts
 * failures by its criterion.  Ray-level cases ask the engine for hits or
 * colours of rays chosen to be hard (aimed exactly at shared edges, grazing,
 * in a facet's plane); image-level cases render the scene's camera view and
 * compare images.  Scenes and rays come from a fixed generator, so every run
 * measures the same inputs.  The cases themselves are in one file per
 * family: cases_watertight.c (W, D), cases_invariance.c (T, Q, X),
 * cases_shadows.c (S, L), cases_camera.c (C, R), cases_special.c (V),
 * cases_glass.c (G).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "robust/cases.h"

void rb_not_applicable(rb_result *r, const char *why)
{
    r->applicable = 0;
    snprintf(r->note, sizeof r->note, "%s", why);
}

/* A view for ray-level cases: a valid camera far above, the light given. */
rb_view rb_ray_view(double scale, rt_vec3 light, rt_rgb8 background)
{
    rb_view v = {rb_v(0, 0, 50 * scale), rb_v(0, 0, 49 * scale),
                 rb_v(scale, 0, 49 * scale), 16, 16, light, WHITE,
                 background};
    return v;
}

int rb_is_double(rt_precision p) { return p == RT_PRECISION_DOUBLE; }

rt_vec3 rb_random_in_ball(rt_test_rng *rng, double radius)
{
    for (;;) {
        rt_vec3 p = rb_v(rt_test_rng_range(rng, -1, 1),
                         rt_test_rng_range(rng, -1, 1),
                         rt_test_rng_range(rng, -1, 1));
        if (rb_dot(p, p) <= 1)
            return rb_scale(p, radius);
    }
}

rt_vec3 rb_random_unit(rt_test_rng *rng)
{
    rt_vec3 p = rb_random_in_ball(rng, 1);
    while (rb_length(p) < 1e-3)
        p = rb_random_in_ball(rng, 1);
    return rb_scale(p, 1 / rb_length(p));
}

static int compare_edges(const void *a, const void *b)
{
    const int *x = a, *y = b;
    return x[0] != y[0] ? (x[0] > y[0]) - (x[0] < y[0])
                        : (x[1] > y[1]) - (x[1] < y[1]);
}

rb_shared rb_shared_of(const rb_mesh *m)
{
    rb_shared sh = {0};
    int n = 3 * m->facet_count;
    int (*all)[2] = malloc(sizeof *all * (size_t)(n + 1));
    for (int i = 0; i < m->facet_count; i++)
        for (int e = 0; e < 3; e++) {
            int a = m->facets[i].vertex[e], b = m->facets[i].vertex[(e + 1) % 3];
            all[3 * i + e][0] = a < b ? a : b;
            all[3 * i + e][1] = a < b ? b : a;
        }
    qsort(all, (size_t)n, sizeof *all, compare_edges);
    sh.edges = malloc(sizeof *sh.edges * (size_t)(n + 1));
    char *boundary = calloc((size_t)m->vertex_count + 1, 1);
    char *used = calloc((size_t)m->vertex_count + 1, 1);
    for (int i = 0; i < n;) {
        int j = i;
        while (j < n && compare_edges(all[i], all[j]) == 0)
            j++;
        used[all[i][0]] = used[all[i][1]] = 1;
        if (j - i >= 2) {
            sh.edges[sh.edge_count][0] = all[i][0];
            sh.edges[sh.edge_count++][1] = all[i][1];
        } else {
            boundary[all[i][0]] = boundary[all[i][1]] = 1;
        }
        i = j;
    }
    sh.vertices = malloc(sizeof *sh.vertices * (size_t)(m->vertex_count + 1));
    for (int v = 0; v < m->vertex_count; v++)
        if (used[v] && !boundary[v])
            sh.vertices[sh.vertex_count++] = v;
    free(all);
    free(boundary);
    free(used);
    return sh;
}

void rb_shared_free(rb_shared *sh)
{
    free(sh->edges);
    free(sh->vertices);
}

/* A point on an edge shared by two facets, or (with probability
 * vertex_share) a vertex inside the mesh. */
rt_vec3 rb_shared_point(const rb_mesh *m, const rb_shared *sh, rt_test_rng *rng,
                            double vertex_share)
{
    if (sh->vertex_count > 0 && rt_test_rng_uniform(rng) < vertex_share)
        return m->vertices[sh->vertices[(int)(rt_test_rng_uniform(rng) * sh->vertex_count)]];
    const int *e = sh->edges[(int)(rt_test_rng_uniform(rng) * sh->edge_count)];
    return rb_lerp(m->vertices[e[0]], m->vertices[e[1]],
                   rt_test_rng_uniform(rng));
}

int rb_hit_is_nan(const rb_hit *h)
{
    return isnan(h->t) || isnan(h->point.x) || isnan(h->point.y) ||
           isnan(h->point.z);
}

/* ================================================================== */
/* The table                                                           */

const rb_case rb_cases[] = {
    {"W1", "watertightness", "Closed icosphere (320 facets), radius 1e-3; 100,000 rays from inside aimed at shared edges (70%) and vertices (30%)", "a ray that hits nothing", rb_case_w1},
    {"W2", "watertightness", "The same sphere at radius 1",
     "a ray that hits nothing", rb_case_w2},
    {"W3", "watertightness", "The same sphere at radius 1e3",
     "a ray that hits nothing", rb_case_w3},
    {"W4", "watertightness", "Cone of 64 thin facets around one apex; 50,000 rays from all around aimed at the apex and along the spokes", "a ray that hits nothing", rb_case_w4},
    {"W5", "watertightness", "Tilted 16x16 grid near (1e6, 1e6, 5e5), integer vertices, windings alternating; 100,000 rays from above aimed at shared edges and vertices", "a ray that hits nothing", rb_case_w5},
    {"D1", "degenerate facets", "Seven zero-area facets (repeated and exactly collinear vertices, at 1e-9 to 1e15); 70,000 rays aimed at their segments", "any hit (zero-area facets are never hit); ours also: live count 0 and one warning each", rb_case_d1},
    {"D2", "degenerate facets", "16 randomly oriented cap slivers (apex 1e-8 from the long edge: aspect 1e8); 64,000 rays aimed at interior points", "a miss, a hit on another facet, or a hit point farther than 1e-9 (float 1e-3) times (1 + the distance of p from the origin) from the aim", rb_case_d2},
    {"D3", "degenerate facets", "The same with aspect 1e12", "as D2 (float: misses allowed, documented refusal)", rb_case_d3},
    {"D4", "degenerate facets", "16 needles (one edge 1e-12 long, aspect 1e12); 64,000 rays at interior points", "as D2", rb_case_d4},
    {"D5", "degenerate facets", "Normals of 2,000 caps and needles of aspect 1e2 to 1e12, random orientation", "normal farther than 1e-9 from the exact normal of the binary vertices", rb_case_d5},
    {"T1", "invariance", "Floor, slab lifted 1e-3 of the size, sphere, mirrors (64x64, depth 5) translated by (1e6, -1e6, 1e6), against the original", "more than 0.1% of pixels differ, or a differing pixel not on a crease, silhouette or shadow edge", rb_case_t1},
    {"T2", "invariance", "The same scene scaled by 1e-6", "as T1", rb_case_t2},
    {"T3", "invariance", "The same scene scaled by 1e6", "as T1", rb_case_t3},
    {"T4", "invariance", "The same scene scaled by 1e-150 (float: 1e-15)", "as T1", rb_case_t4},
    {"T5", "invariance", "The same scene scaled by 1e150 (float: 1e15)",
     "as T1", rb_case_t5},
    {"S1", "self-intersection", "Tessellated floor, slab box lifted 2e-3 over it (1e-3 of the size), light above; all scaled by 1e-6; 50,000 rays from the gap to the floor under the slab, 50,000 from above to the open floor", "under the slab: any light (a leak); open floor: N.S off by more than 1e-3 (acne)", rb_case_s1},
    {"S2", "self-intersection", "The same at scale 1e-3", "as S1", rb_case_s2},
    {"S3", "self-intersection", "The same at scale 1", "as S1", rb_case_s3},
    {"S4", "self-intersection", "The same at scale 1e3", "as S1", rb_case_s4},
    {"S5", "self-intersection", "The same at scale 1e6", "as S1", rb_case_s5},
    {"S6", "self-intersection", "The same at scale 1, translated to (1e12, -1e12, 1e12)", "as S1", rb_case_s6},
    {"L1", "lights", "Light in the plane of a floor (z = 0, 128 facets); 50,000 rays from above", "any light on the floor (the real colour must be exactly 0)", rb_case_l1},
    {"L2", "lights", "The same, floor and light rotated (the light is in the plane up to rounding)", "a colour above 1e-6 (float: 1e-2; both invisible, continuity with L1)", rb_case_l2},
    {"L3", "lights", "Light exactly at the apex vertex of a cone of 16 facets above a floor; 50,000 rays to the floor", "a floor point not lit with the exact N.S (1e-9; float 1e-4)", rb_case_l3},
    {"L4", "lights", "Light on a wall (inside one of its facets), floor on both sides; 50,000 rays to the floor", "as L3 (a facet through the light does not shadow)", rb_case_l4},
    {"L5", "lights", "Tilted 16x16 floor, light 1e-6 rad above its plane; 50,000 rays from above", "N.S off by more than 1% (float 50%): acne", rb_case_l5},
    {"L6", "lights", "The same at 1e-12 rad", "as L5", rb_case_l6},
    {"C1", "camera", "Observer on the floor (on a shared vertex, then inside a facet) looking along it; 64x64 camera rays and 20,000 random rays, twice", "a camera ray that hits a floor facet (only possible at t = 0)", rb_case_c1},
    {"C2", "camera", "100,000 rays lying in the floor's plane, through it", "any hit; any NaN colour", rb_case_c2},
    {"C3", "camera", "Rays grazing a tilted 16x16 floor at 1e-12 rad (float: 1e-4), aimed at shared edges and vertices; 100,000", "a ray that hits nothing", rb_case_c3},
    {"R1", "recursion", "Two facing mirrors (k = 1), 4x4 image, depth 100,000 (and 10,000)", "a pixel not black, reflection count not exactly 16 x depth, a crash", rb_case_r1},
    {"R2", "recursion", "Closed box of mirrors (k = 1, white background); 3,000 rays from inside at face points at least 1% of a facet from its edges, 1000 bounces", "a ray that escapes (any colour)", rb_case_r2},
    {"V1", "special values", "Scene files with nan, inf, -INF, infinity, 1e400, -1e309 in vertices, camera, light, k; rt_scene_create with NaN and infinities", "an input accepted", rb_case_v1},
    {"V2", "special values", "Rays at a sphere with directions scaled by 1e-300 to 1e300 (float 1e-30 to 1e30); NaN, infinite and zero rays", "a different facet, or t times the direction's length off by 1e-5; a hit or NaN colour for a non-ray", rb_case_v2},
    {"V3", "special values", "The T1 scene with the light at 1e200 along a direction (beyond float's range), against the light at 1e30", "a pixel that differs (float: a refusal by rt_render is the decided result)", rb_case_v3},
    {"V4", "special values", "200 facets 3 units wide near 1e8 (float's step there is 8: they collapse in float); 30,000 rays, a 64x64 render", "a NaN (hit, colour or pixel)", rb_case_v4},
    {"V5", "special values", "The T1 scene at subnormal scale 1e-310 (float: 1e-40)", "a NaN pixel (refusal is allowed)", rb_case_v5},
    {"Q1", "coincident facets", "Tilted floor whose 128 facets are each listed twice, same vertex order, red then blue; 50,000 rays", "a hit on the second copy", rb_case_q1},
    {"Q2", "coincident facets", "The same with the second copy's vertices rotated once, twice, reversed", "a hit on the second copy", rb_case_q2},
    {"G1", "transparency", "Glass slab (two parallel faces 1 apart, 2,000 wide; n = 1.5, t = 0.9, k = d = 0) over a white floor lit from under the slab; scales 1e-6, 1e-3, 1, 1e3, 1e6; 2,000 rays per scale, incidence uniform to 80 degrees and grazing from 80 to 89.9 degrees, built backwards from a floor point through the analytic lateral shift sin(theta - theta_t)/cos(theta_t)", "a colour off 0.81 x 255 N.S at that floor point by more than the rounding tolerance (stuck, leaking, re-hitting the facet it leaves, not displaced as Snell says)", rb_case_g1},
    {"G2", "transparency", "Right-angle glass prism (closed, 8 facets, rotated) over a lit floor, 5 scales; 2,000 rays per scale entering the top face, half within 0.3 rad of the incidence whose internal angle at the hypotenuse is asin(1/n) (down to 1e-6 rad from it; float 1e-3)", "a colour off the analytic path's: beyond the critical angle totally reflected (then out of the side, to the background), below it refracted out of the hypotenuse to the floor", rb_case_g2},
    {"G3", "transparency", "Closed glass cube (12 facets, 8 shared vertices, rotated) over a lit floor, 5 scales; 3,000 rays per scale aimed exactly at shared edges: face diagonals from any entering direction (40%), cube edges entering both faces (30%), diagonals at normal incidence leaving through the opposite diagonal (30%)", "a colour off the analytic path's (either face's at a cube edge): a ray that passes between two facets, stops or leaks shows the background or the floor with the wrong weight", rb_case_g3},
    {"G4", "transparency", "A light inside a closed glass cube, a second light outside, 5 scales; 2,000 rays per scale: half from inside the cube to a plate inside it, half from outside to the floor outside", "a point inside not lit by exactly the inside light's N.S, or a point outside lit by it (shadow rays are blocked by glass), or outside not lit by the outside light exactly where the cube does not shadow it", rb_case_g4},
    {"X1", "determinism", "Three stiff scenes (unit, 1e-6, translated 1e6) rendered with 1, 2, 3, 8 threads", "a pixel that differs from the 1-thread scalar image", rb_case_x1},
    {"X2", "determinism", "The same rendered with the AVX2 and scalar loops", "a pixel that differs", rb_case_x2},
};

const int rb_case_count = (int)(sizeof rb_cases / sizeof rb_cases[0]);

const rb_case *rb_case_find(const char *id)
{
    for (int i = 0; i < rb_case_count; i++)
        if (strcmp(rb_cases[i].id, id) == 0)
            return &rb_cases[i];
    return NULL;
}

void rb_case_run(const rb_case *c, rb_method method, rt_precision precision,
                 rb_result *result)
{
    memset(result, 0, sizeof *result);
    result->applicable = 1;
    c->run(method, precision, result);
}
