/*
 * test_triangulate.c - the readers' polygon triangulator
 * (src/formats/triangulate.c) and NFF's calls into it (tessellate.c):
 * convex polygons give the fan ear clipping gave, triangle for triangle,
 * up to 64 corners and a balanced cut beyond, at no cost to the budget;
 * non-convex ones are cut inside themselves with their winding; no
 * triangle without area is ever emitted; ear clipping stops at its budget
 * and fans the rest; the cancel flag is polled.
 */
#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "formats/tessellate.h"
#include "formats/triangulate.h"
#include "testutil.h"

#define PI 3.14159265358979323846

/* The triangles a call emitted. */
typedef struct triangles {
    int (*corners)[3];
    int count, capacity;
} triangles;

static rt_status collect(void *user, int a, int b, int c)
{
    triangles *t = user;
    if (t->count == t->capacity) {
        t->capacity = t->capacity ? 2 * t->capacity : 64;
        t->corners = realloc(t->corners, (size_t)t->capacity *
                                             sizeof *t->corners);
        ck_assert_ptr_nonnull(t->corners);
    }
    t->corners[t->count][0] = a;
    t->corners[t->count][1] = b;
    t->corners[t->count++][2] = c;
    return RT_OK;
}

static rt_vec3 *regular_polygon(int n, double radius)
{
    rt_vec3 *p = malloc((size_t)n * sizeof *p);
    ck_assert_ptr_nonnull(p);
    for (int i = 0; i < n; i++)
        p[i] = (rt_vec3){radius * cos(2 * PI * i / n),
                         radius * sin(2 * PI * i / n), 0};
    return p;
}

static rt_status cut(const rt_vec3 *p, int n, double budget,
                     const rt_cancel *cancel, triangles *out,
                     rt_tri_result *result, double *work_left)
{
    rt_triangulator t;
    rt__tri_init(&t, budget, cancel);
    memset(out, 0, sizeof *out);
    rt_status status = rt__triangulate(&t, p, NULL, n, collect, out, result);
    if (work_left != NULL)
        *work_left = t.work_left;
    rt__tri_free(&t);
    return status;
}

/* Twice the signed area in the xy plane. */
static double area2(rt_vec3 a, rt_vec3 b, rt_vec3 c)
{
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

static double polygon_area2(const rt_vec3 *p, int n)
{
    double sum = 0;
    for (int i = 0, j = n - 1; i < n; j = i++)
        sum += p[j].x * p[i].y - p[i].x * p[j].y;
    return sum;
}

static int inside_polygon(const rt_vec3 *p, int n, double x, double y)
{
    int in = 0;
    for (int i = 0, j = n - 1; i < n; j = i++)
        if ((p[i].y > y) != (p[j].y > y) &&
            x < (p[j].x - p[i].x) * (y - p[i].y) / (p[j].y - p[i].y) + p[i].x)
            in = !in;
    return in;
}

/* Every triangle wound as the polygon, inside it (checked up to 1000
 * corners: the test is quadratic), the areas adding up. */
static void covers_exactly(const rt_vec3 *p, int n, const triangles *t)
{
    double total = 0, whole = polygon_area2(p, n);
    for (int i = 0; i < t->count; i++) {
        rt_vec3 a = p[t->corners[i][0]], b = p[t->corners[i][1]],
                c = p[t->corners[i][2]];
        double area = area2(a, b, c);
        ck_assert_msg(area * whole > 0, "triangle %d is wound against the "
                                        "polygon or has no area", i);
        ck_assert_msg(n > 1000 || inside_polygon(p, n, (a.x + b.x + c.x) / 3,
                                                 (a.y + b.y + c.y) / 3),
                      "triangle %d lies outside the polygon", i);
        total += area;
    }
    ck_assert_msg(fabs(total - whole) <= 1e-9 * fabs(whole),
                  "the triangles cover %.17g, the polygon %.17g", total,
                  whole);
}

START_TEST(convex_polygons_of_up_to_64_corners_are_the_fan_ear_clipping_gave)
{
    for (int n = 3; n <= RT_TRI_FAN_MAX_CORNERS; n++) {
        rt_vec3 *p = regular_polygon(n, 1);
        triangles t;
        rt_tri_result r;
        ck_assert_int_eq(cut(p, n, 0, NULL, &t, &r, NULL), RT_OK);
        ck_assert_int_eq(t.count, n - 2);
        for (int i = 0; i + 3 < n; i++) {
            ck_assert_int_eq(t.corners[i][0], n - 1);
            ck_assert_int_eq(t.corners[i][1], i);
            ck_assert_int_eq(t.corners[i][2], i + 1);
        }
        ck_assert_int_eq(t.corners[n - 3][0], n - 3);
        ck_assert_int_eq(t.corners[n - 3][1], n - 2);
        ck_assert_int_eq(t.corners[n - 3][2], n - 1);
        free(t.corners);
        free(p);
    }
}
END_TEST

START_TEST(a_large_convex_polygon_is_cut_balanced_at_no_cost_to_the_budget)
{
    int n = 100000;
    rt_vec3 *p = regular_polygon(n, 1e3);
    triangles t;
    rt_tri_result r;
    /* A budget of 0: a convex polygon spends none of it. */
    ck_assert_int_eq(cut(p, n, 0, NULL, &t, &r, NULL), RT_OK);
    ck_assert_int_eq(t.count, n - 2);
    ck_assert_int_eq(r.dropped, 0);
    ck_assert(!r.over_budget && !r.crossing);
    covers_exactly(p, n, &t);
    /* No fan: a corner is in at most two triangles a level of the
     * recursion (a fan puts n - 2 at one corner). */
    int *uses = calloc((size_t)n, sizeof *uses), most = 0;
    ck_assert_ptr_nonnull(uses);
    for (int i = 0; i < t.count; i++)
        for (int k = 0; k < 3; k++)
            if (++uses[t.corners[i][k]] > most)
                most = uses[t.corners[i][k]];
    ck_assert_int_le(most, 2 * 17 + 2);
    /* Short and local: the facets' bounding boxes add up to a few times
     * the polygon's (a ray meets O(1) of them); a fan's add up to about
     * n / 4 times. */
    double boxes = 0;
    for (int i = 0; i < t.count; i++) {
        double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
        for (int k = 0; k < 3; k++) {
            rt_vec3 q = p[t.corners[i][k]];
            lo[0] = fmin(lo[0], q.x), hi[0] = fmax(hi[0], q.x);
            lo[1] = fmin(lo[1], q.y), hi[1] = fmax(hi[1], q.y);
        }
        boxes += (hi[0] - lo[0]) * (hi[1] - lo[1]);
    }
    double polygon_box = 2e3 * 2e3;
    ck_assert_msg(boxes <= 4 * polygon_box, "the boxes add up to %g times "
                                            "the polygon's",
                  boxes / polygon_box);
    free(uses);
    free(t.corners);
    free(p);
}
END_TEST

/* An L, a 20-tooth comb and a star, each also wound the other way. */
static int shapes(int which, rt_vec3 *p)
{
    int n = 0;
    if (which == 0) {
        static const double l[6][2] = {{0, 0}, {2, 0}, {2, 1},
                                       {1, 1}, {1, 2}, {0, 2}};
        for (n = 0; n < 6; n++)
            p[n] = (rt_vec3){l[n][0], l[n][1], 0};
    } else if (which == 1) {
        p[n++] = (rt_vec3){40, 0, 0};
        for (int k = 19; k >= 0; k--) {
            p[n++] = (rt_vec3){2 * k + 2, 6, 0};
            p[n++] = (rt_vec3){2 * k + 1, 6, 0};
            p[n++] = (rt_vec3){2 * k + 1, 1, 0};
            p[n++] = (rt_vec3){2 * k, 1, 0};
        }
        p[n++] = (rt_vec3){0, 0, 0};
    } else {
        for (n = 0; n < 10; n++) {
            double angle = PI * (0.5 + n / 5.0), radius = n % 2 ? 0.4 : 1.0;
            p[n] = (rt_vec3){radius * cos(angle), radius * sin(angle), 0};
        }
    }
    return n;
}

START_TEST(a_convex_polygon_written_with_rounded_coordinates_is_still_cut_in_o_n)
{
    /* 10^5 corners on a circle, rounded to 6 decimals (as exporters write
     * them): dents of up to about 1e-6 turn corners slightly right; with
     * no budget it must still be cut balanced, not given up on. */
    int n = 100000;
    rt_vec3 *p = regular_polygon(n, 1);
    for (int i = 0; i < n; i++) {
        p[i].x = round(p[i].x * 1e6) / 1e6;
        p[i].y = round(p[i].y * 1e6) / 1e6;
    }
    triangles t;
    rt_tri_result r;
    ck_assert_int_eq(cut(p, n, 0, NULL, &t, &r, NULL), RT_OK);
    ck_assert(!r.over_budget && !r.crossing);
    ck_assert_int_eq(r.facets + r.dropped, n - 2);
    ck_assert_int_gt(r.facets, n / 2);
    free(t.corners);
    free(p);
}
END_TEST

START_TEST(non_convex_polygons_are_cut_inside_themselves_with_their_winding)
{
    rt_vec3 p[100], q[100];
    for (int which = 0; which < 3; which++) {
        int n = shapes(which, p);
        for (int reversed = 0; reversed < 2; reversed++) {
            for (int i = 0; i < n; i++)
                q[i] = reversed ? p[n - 1 - i] : p[i];
            triangles t;
            rt_tri_result r;
            ck_assert_int_eq(cut(q, n, 1e9, NULL, &t, &r, NULL), RT_OK);
            ck_assert_int_eq(t.count, n - 2);
            ck_assert(!r.over_budget && !r.crossing);
            covers_exactly(q, n, &t);
            free(t.corners);
        }
    }
}
END_TEST

START_TEST(polygons_without_area_give_no_triangle)
{
    /* Two corners repeated (`f 1 2 1 2 ...`), and corners on a line. */
    int n = 100000;
    rt_vec3 *p = malloc((size_t)n * sizeof *p);
    ck_assert_ptr_nonnull(p);
    for (int i = 0; i < n; i++)
        p[i] = (rt_vec3){i % 2, 0, 0};
    triangles t;
    rt_tri_result r;
    ck_assert_int_eq(cut(p, n, 0, NULL, &t, &r, NULL), RT_OK);
    ck_assert_int_eq(t.count, 0);
    ck_assert_int_eq(r.facets, 0);
    ck_assert_int_eq(r.dropped, n - 2);
    for (int i = 0; i < n; i++)
        p[i] = (rt_vec3){i < n / 2 ? i : n - i, 2.0 * (i < n / 2 ? i : n - i),
                         -1.0 * (i < n / 2 ? i : n - i)};
    ck_assert_int_eq(cut(p, n, 0, NULL, &t, &r, NULL), RT_OK);
    ck_assert_int_eq(t.count, 0);
    free(p);
}
END_TEST

START_TEST(ear_clipping_stops_at_its_budget_and_fans_the_rest)
{
    rt_vec3 p[100];
    int n = shapes(1, p);
    /* Enough for the first flags (about n r / 2), not for the clipping. */
    double budget = 2000;
    triangles t;
    rt_tri_result r;
    double left;
    ck_assert_int_eq(cut(p, n, budget, NULL, &t, &r, &left), RT_OK);
    ck_assert(r.over_budget);
    ck_assert_int_eq(r.facets + r.dropped, n - 2);
    /* What the budget allows, plus at most one step beyond it: a search
     * for an ear (n corners) and three ear tests (n corners each). */
    ck_assert_msg(left >= -4.0 * n, "overspent by %g", -left);
    free(t.corners);
    /* No budget at all: cut balanced at once, from the first corner. */
    ck_assert_int_eq(cut(p, n, 0, NULL, &t, &r, &left), RT_OK);
    ck_assert(r.over_budget);
    ck_assert_int_eq(t.corners[0][0], 0);
    ck_assert(left == 0);
    free(t.corners);
}
END_TEST

START_TEST(a_raised_cancel_flag_stops_a_large_polygon)
{
    int n = 200000;
    rt_vec3 *p = regular_polygon(n, 1);
    rt_cancel *cancel;
    ck_assert_int_eq(rt_cancel_create(&cancel, NULL), RT_OK);
    rt_cancel_request(cancel);
    triangles t;
    rt_tri_result r;
    ck_assert_int_eq(cut(p, n, 0, cancel, &t, &r, NULL), RT_ERR_CANCELLED);
    ck_assert_int_lt(t.count, n - 2);
    free(t.corners);
    rt_cancel_destroy(cancel);
    free(p);
}
END_TEST

START_TEST(nff_polygons_keep_their_fan_from_the_first_corner)
{
    rt_vec3 p[5] = {{0, 0, 0}, {2, 0, 0}, {3, 0, 1}, {1, 0, 2}, {-1, 0, 1}};
    rt_tess_mesh mesh;
    memset(&mesh, 0, sizeof mesh);
    rt_facet_desc look;
    memset(&look, 0, sizeof look);
    int irregular = 0;
    ck_assert_int_eq(rt__tess_polygon(&mesh, p, 5, &look, 7, &irregular), 0);
    ck_assert_int_eq(irregular, 0);
    ck_assert_int_eq(mesh.vertex_count, 5);
    ck_assert_int_eq(mesh.facet_count, 3);
    for (int i = 0; i < 3; i++) {
        ck_assert_int_eq(mesh.facets[i].vertex[0], 0);
        ck_assert_int_eq(mesh.facets[i].vertex[1], i + 1);
        ck_assert_int_eq(mesh.facets[i].vertex[2], i + 2);
        ck_assert_int_eq(mesh.facet_lines[i], 7);
    }
    ck_assert(rt__tess_polygon_convex(p, 5));
    /* A triangle without area: its vertices, no facet, irregular. */
    rt_vec3 line[3] = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
    ck_assert_int_eq(rt__tess_polygon(&mesh, line, 3, &look, 8, &irregular),
                     0);
    ck_assert_int_eq(irregular, 1);
    ck_assert_int_eq(mesh.vertex_count, 8);
    ck_assert_int_eq(mesh.facet_count, 3);
    rt__tess_mesh_free(&mesh);
    rt_vec3 star[10];
    shapes(2, star);
    ck_assert(!rt__tess_polygon_convex(star, 10));
}
END_TEST

static Suite *triangulate_suite(void)
{
    Suite *s = suite_create("triangulate");
    TCase *c = tcase_create("triangulate");
    tcase_set_timeout(c, 120);
    tcase_add_test(
        c, convex_polygons_of_up_to_64_corners_are_the_fan_ear_clipping_gave);
    tcase_add_test(
        c, a_large_convex_polygon_is_cut_balanced_at_no_cost_to_the_budget);
    tcase_add_test(
        c,
        a_convex_polygon_written_with_rounded_coordinates_is_still_cut_in_o_n);
    tcase_add_test(
        c, non_convex_polygons_are_cut_inside_themselves_with_their_winding);
    tcase_add_test(c, polygons_without_area_give_no_triangle);
    tcase_add_test(c, ear_clipping_stops_at_its_budget_and_fans_the_rest);
    tcase_add_test(c, a_raised_cancel_flag_stops_a_large_polygon);
    tcase_add_test(c, nff_polygons_keep_their_fan_from_the_first_corner);
    suite_add_tcase(s, c);
    return s;
}

RT_CHECK_MAIN(triangulate_suite)
