/*
 * test_in104_geometry.c - the handout's geometric functions (intersection.h
 * of the in104 layer): createFacet, computeIntersection, changeCoord and
 * isInFacet, on docs/in104.md's examples, on boundaries (vertices,
 * edges, EPSILON on both sides), on the cases without an answer (parallel
 * rays, zero-area facets) and on badly conditioned input (slivers of aspect
 * ratio 1e12, scenes at 1e-6 and 1e6).
 */
#include <math.h>

#include "geometry.h"
#include "intersection.h"
#include "testutil.h"

/* Tolerance for results that are exact up to a few roundings. */
#define TIGHT 1e-12

static point pt(double x, double y, double z)
{
    point p = {x, y, z};
    return p;
}

static point add(point a, point b)
{
    return pt(a.x + b.x, a.y + b.y, a.z + b.z);
}

static point sub(point a, point b)
{
    return pt(a.x - b.x, a.y - b.y, a.z - b.z);
}

static point scale(point a, double s)
{
    return pt(a.x * s, a.y * s, a.z * s);
}

static double dot(point a, point b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

static point cross(point a, point b)
{
    return pt(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z,
              a.x * b.y - a.y * b.x);
}

static double norm(point a)
{
    return sqrt(dot(a, a));
}

static point unit(point a)
{
    return scale(a, 1.0 / norm(a));
}

static ray make_ray(point o, point v)
{
    ray r = {o, v};
    return r;
}

static void assert_point_near(point got, point expected, double tolerance)
{
    ck_assert_double_eq_tol(got.x, expected.x, tolerance);
    ck_assert_double_eq_tol(got.y, expected.y, tolerance);
    ck_assert_double_eq_tol(got.z, expected.z, tolerance);
}

static void assert_point_eq(point got, point expected)
{
    ck_assert_double_eq(got.x, expected.x);
    ck_assert_double_eq(got.y, expected.y);
    ck_assert_double_eq(got.z, expected.z);
}

static void assert_no_point(point p)
{
    ck_assert(isnan(p.x) && isnan(p.y) && isnan(p.z));
}

/* The facet of the handout's intersection example (docs/in104.md). */
static facet spec_facet(void)
{
    return createFacet(pt(-1, -1, 1), pt(1, -1, -1), pt(0, 1, 1));
}

/* The triangle of the handout's isInFacet example (docs/in104.md). */
static facet spec_triangle(void)
{
    return createFacet(pt(0, 0, 0), pt(0, 1, 0), pt(1, 0, 0));
}

/* A deterministic pseudo-random number in [-1, 1). */
static double random_unit(unsigned *state)
{
    *state = *state * 1664525u + 1013904223u;
    return (double)(*state >> 8) / (double)(1u << 23) - 1.0;
}

/* The unit vector in the plane of f, perpendicular to the edge from -> to,
 * pointing away from the triangle. */
static point outward(facet f, point from, point to, point opposite)
{
    point m = unit(cross(sub(to, from), f.n));
    return dot(m, sub(opposite, from)) > 0 ? scale(m, -1) : m;
}

/* ---- createFacet -------------------------------------------------------- */

START_TEST(create_facet_gives_the_unit_normal_of_the_spec_example)
{
    /* (b - a) x (c - a) = (2, 0, -2) x (1, 2, 0) = (4, -2, 4), length 6 */
    assert_point_near(spec_facet().n, pt(2.0 / 3, -1.0 / 3, 2.0 / 3), TIGHT);
}
END_TEST

START_TEST(create_facet_sets_k_zero_and_black_and_keeps_the_vertices)
{
    facet f = spec_facet();
    ck_assert_double_eq(f.k, 0.0);
    ck_assert(f.cp.r == 0 && f.cp.g == 0 && f.cp.b == 0);
    assert_point_eq(f.a, pt(-1, -1, 1));
    assert_point_eq(f.b, pt(1, -1, -1));
    assert_point_eq(f.c, pt(0, 1, 1));
}
END_TEST

START_TEST(create_facet_normal_follows_the_winding)
{
    facet f = createFacet(pt(0, 0, 0), pt(1, 0, 0), pt(0, 1, 0));
    facet g = createFacet(pt(0, 0, 0), pt(0, 1, 0), pt(1, 0, 0));
    assert_point_eq(f.n, pt(0, 0, 1));
    assert_point_eq(g.n, pt(0, 0, -1));
}
END_TEST

START_TEST(create_facet_normal_is_unit_at_tiny_and_huge_scales)
{
    static const double scales[] = {1e-300, 1e-150, 1e-6, 1, 1e6, 1e150};
    for (size_t i = 0; i < sizeof scales / sizeof scales[0]; i++) {
        double s = scales[i];
        facet f = createFacet(pt(-s, -s, s), pt(s, -s, -s), pt(0, s, s));
        assert_point_near(f.n, pt(2.0 / 3, -1.0 / 3, 2.0 / 3), TIGHT);
    }
}
END_TEST

START_TEST(create_facet_of_collinear_or_equal_points_has_zero_normal)
{
    facet line = createFacet(pt(0, 0, 0), pt(1, 1, 1), pt(3, 3, 3));
    facet equal = createFacet(pt(1, 2, 3), pt(1, 2, 3), pt(0, 0, 1));
    facet point3 = createFacet(pt(1, 2, 3), pt(1, 2, 3), pt(1, 2, 3));
    assert_point_eq(line.n, pt(0, 0, 0));
    assert_point_eq(equal.n, pt(0, 0, 0));
    assert_point_eq(point3.n, pt(0, 0, 0));
    ck_assert(!isnan(line.n.x) && !isnan(point3.n.x));
}
END_TEST

/*
 * A sliver with exact coordinates: a = 0, b = 2g, c = g + (0, h, 0) with
 * h = 2^-42 and g a point of norm about 2 whose coordinates use all 42
 * fractional bits.  Its height is about h, its length about 4: aspect ratio
 * about 1.5e13.  Naive cross products of its edges round away most of the
 * normal (the products are ~1 and cancel to ~1e-13), so only a careful
 * implementation passes the tests below.
 */
static const double SLIVER_H = 0x1p-42;

static point sliver_g(void)
{
    return pt(ldexp(3456789012345.0, -42), ldexp(2109876543211.0, -42),
              ldexp(4012345678901.0, -42));
}

static facet sliver(void)
{
    point g = sliver_g();
    return createFacet(pt(0, 0, 0), scale(g, 2), add(g, pt(0, SLIVER_H, 0)));
}

START_TEST(create_facet_of_a_sliver_has_an_accurate_normal)
{
    /* 2g x (g + h.y) = 2h (g x y) = 2h (-g.z, 0, g.x) */
    point g = sliver_g();
    assert_point_near(sliver().n, unit(pt(-g.z, 0, g.x)), TIGHT);
}
END_TEST

/* ---- computeIntersection ------------------------------------------------ */

START_TEST(compute_intersection_gives_the_spec_example)
{
    point p = computeIntersection(make_ray(pt(0, 0, 0), pt(1, 3, 2)),
                                  spec_facet());
    assert_point_near(p, pt(1.0 / 3, 1, 2.0 / 3), TIGHT);
}
END_TEST

START_TEST(compute_intersection_does_not_depend_on_the_direction_length)
{
    static const double lengths[] = {1e-200, 1e-8, 0.001, 7, 1e8, 1e200};
    for (size_t i = 0; i < sizeof lengths / sizeof lengths[0]; i++) {
        ray r = make_ray(pt(0, 0, 0), scale(pt(1, 3, 2), lengths[i]));
        assert_point_near(computeIntersection(r, spec_facet()),
                          pt(1.0 / 3, 1, 2.0 / 3), TIGHT);
    }
}
END_TEST

START_TEST(compute_intersection_returns_points_behind_the_origin)
{
    /* The line, not the half-line: the opposite direction, and an origin
     * beyond the plane, give the same point. */
    point expected = pt(1.0 / 3, 1, 2.0 / 3);
    ray backwards = make_ray(pt(0, 0, 0), pt(-1, -3, -2));
    ray beyond = make_ray(pt(1, 3, 2), pt(1, 3, 2));
    assert_point_near(computeIntersection(backwards, spec_facet()), expected,
                      TIGHT);
    assert_point_near(computeIntersection(beyond, spec_facet()), expected,
                      TIGHT);
}
END_TEST

START_TEST(compute_intersection_returns_the_origin_when_it_is_on_the_plane)
{
    facet f = createFacet(pt(0, 0, 2), pt(1, 0, 2), pt(0, 1, 2));
    point p = computeIntersection(make_ray(pt(5, -3, 2), pt(1, 1, 1)), f);
    assert_point_eq(p, pt(5, -3, 2));
}
END_TEST

START_TEST(compute_intersection_of_a_parallel_ray_is_nan)
{
    facet f = createFacet(pt(0, 0, 2), pt(1, 0, 2), pt(0, 1, 2));
    point p = computeIntersection(make_ray(pt(0, 0, 0), pt(1, 2, 0)), f);
    assert_no_point(p);
    ck_assert(!isInFacet(p, f));
    /* parallel to the tilted plane of the spec's facet: v . (2,-1,2) = 0 */
    assert_no_point(computeIntersection(make_ray(pt(0, 0, 0), pt(1, 2, 0)),
                                        spec_facet()));
}
END_TEST

START_TEST(compute_intersection_of_a_ray_in_the_plane_is_nan)
{
    facet f = createFacet(pt(0, 0, 2), pt(1, 0, 2), pt(0, 1, 2));
    assert_no_point(computeIntersection(make_ray(pt(0.2, 0.2, 2),
                                                 pt(1, 0, 0)), f));
}
END_TEST

START_TEST(compute_intersection_without_direction_or_area_is_nan)
{
    facet flat = createFacet(pt(0, 0, 0), pt(1, 1, 1), pt(2, 2, 2));
    assert_no_point(computeIntersection(make_ray(pt(1, 0, 0), pt(0, 0, 0)),
                                        spec_facet()));
    assert_no_point(computeIntersection(make_ray(pt(1, 0, 0), pt(0, 0, 1)),
                                        flat));
    assert_no_point(computeIntersection(
        make_ray(pt(NAN, 0, 0), pt(1, 3, 2)), spec_facet()));
}
END_TEST

START_TEST(compute_intersection_of_a_nearly_parallel_ray_is_finite_or_nan)
{
    facet f = createFacet(pt(0, 0, 1), pt(1, 0, 1), pt(0, 1, 1));
    point p = computeIntersection(make_ray(pt(0, 0, 0), pt(1, 0, 1e-12)), f);
    assert_point_near(p, pt(1e12, 0, 1), 1e-3);
    /* so close to parallel that the point overflows */
    assert_no_point(computeIntersection(
        make_ray(pt(0, 0, 0), pt(1, 0, 1e-320)), f));
}
END_TEST

START_TEST(compute_intersection_ignores_the_stored_normal)
{
    facet f = spec_facet();
    f.n = pt(0, 0, 0);                  /* a facet built by hand */
    assert_point_near(computeIntersection(make_ray(pt(0, 0, 0), pt(1, 3, 2)),
                                          f),
                      pt(1.0 / 3, 1, 2.0 / 3), TIGHT);
}
END_TEST

START_TEST(compute_intersection_lands_on_the_plane_and_the_line)
{
    unsigned state = 12345;
    for (int i = 0; i < 1000; i++) {
        point a = pt(random_unit(&state), random_unit(&state),
                     random_unit(&state));
        point b = pt(random_unit(&state), random_unit(&state),
                     random_unit(&state));
        point c = pt(random_unit(&state), random_unit(&state),
                     random_unit(&state));
        point o = scale(pt(random_unit(&state), random_unit(&state),
                           random_unit(&state)), 5);
        point v = pt(random_unit(&state), random_unit(&state),
                     random_unit(&state));
        facet f = createFacet(a, b, c);
        point p = computeIntersection(make_ray(o, v), f);
        /* near-parallel draws put p far away: judge relative to |p - o| */
        double size = fmax(1.0, norm(sub(p, o)));
        ck_assert_double_le(fabs(dot(sub(p, a), f.n)), 1e-13 * size);
        ck_assert_double_le(norm(cross(sub(p, o), unit(v))), 1e-13 * size);
    }
}
END_TEST

START_TEST(compute_intersection_is_accurate_far_from_the_origin)
{
    /* The spec's example moved to 1e6 and scaled by 1e3. */
    point shift = pt(1e6, -2e6, 3e6);
    facet f = createFacet(add(shift, pt(-1e3, -1e3, 1e3)),
                          add(shift, pt(1e3, -1e3, -1e3)),
                          add(shift, pt(0, 1e3, 1e3)));
    point p = computeIntersection(make_ray(shift, pt(1, 3, 2)), f);
    assert_point_near(p, add(shift, pt(1e3 / 3, 1e3, 2e3 / 3)), 1e-8);
}
END_TEST

/* ---- changeCoord -------------------------------------------------------- */

START_TEST(change_coord_recovers_u_v_w)
{
    facet f = createFacet(pt(1, 0, 0), pt(3, 1, 0), pt(1, 2, 1));
    static const double uvw[][3] = {
        {0.25, 0.5, -0.75}, {0, 0, 0}, {1, 0, 0}, {-2, 3, 10}, {0.5, 0.5, 0}};
    for (size_t i = 0; i < sizeof uvw / sizeof uvw[0]; i++) {
        point p = add(add(f.a, scale(sub(f.b, f.a), uvw[i][0])),
                      add(scale(sub(f.c, f.a), uvw[i][1]),
                          scale(f.n, uvw[i][2])));
        assert_point_near(changeCoord(p, f),
                          pt(uvw[i][0], uvw[i][1], uvw[i][2]), TIGHT);
    }
}
END_TEST

START_TEST(change_coord_maps_the_vertices_to_the_unit_frame)
{
    facet f = spec_facet();
    assert_point_near(changeCoord(f.a, f), pt(0, 0, 0), TIGHT);
    assert_point_near(changeCoord(f.b, f), pt(1, 0, 0), TIGHT);
    assert_point_near(changeCoord(f.c, f), pt(0, 1, 0), TIGHT);
}
END_TEST

START_TEST(change_coord_w_is_the_signed_distance_to_the_plane)
{
    facet f = createFacet(pt(0, 0, 0), pt(2, 0, 0), pt(0, 4, 0));
    assert_point_near(changeCoord(pt(1, 1, 3), f), pt(0.5, 0.25, 3), TIGHT);
    assert_point_near(changeCoord(pt(1, 1, -3), f), pt(0.5, 0.25, -3),
                      TIGHT);
}
END_TEST

START_TEST(change_coord_is_accurate_on_a_sliver_of_aspect_1e12)
{
    point g = sliver_g();
    facet f = sliver();
    /* (1/4) b + (1/2) c and (3/4) b - (1/2) c, both exact */
    assert_point_near(changeCoord(add(g, pt(0, SLIVER_H / 2, 0)), f),
                      pt(0.25, 0.5, 0), TIGHT);
    assert_point_near(changeCoord(sub(g, pt(0, SLIVER_H / 2, 0)), f),
                      pt(0.75, -0.5, 0), TIGHT);
    assert_point_near(changeCoord(f.c, f), pt(0, 1, 0), TIGHT);
}
END_TEST

START_TEST(change_coord_works_at_small_and_large_scales)
{
    static const double scales[] = {1e-150, 1e-6, 1e6, 1e150};
    for (size_t i = 0; i < sizeof scales / sizeof scales[0]; i++) {
        double s = scales[i];
        facet f = createFacet(pt(0, 0, 0), pt(2 * s, 0, 0), pt(0, 4 * s, 0));
        point q = changeCoord(pt(s, s, 3 * s), f);
        ck_assert_double_eq_tol(q.x, 0.5, TIGHT);
        ck_assert_double_eq_tol(q.y, 0.25, TIGHT);
        ck_assert_double_eq_tol(q.z / s, 3, TIGHT);
    }
}
END_TEST

START_TEST(change_coord_of_a_zero_area_facet_is_nan)
{
    facet line = createFacet(pt(0, 0, 0), pt(1, 1, 1), pt(3, 3, 3));
    facet dot3 = createFacet(pt(1, 1, 1), pt(1, 1, 1), pt(1, 1, 1));
    assert_no_point(changeCoord(pt(1, 1, 1), line));
    assert_no_point(changeCoord(pt(1, 1, 1), dot3));
}
END_TEST

/* ---- isInFacet ---------------------------------------------------------- */

START_TEST(is_in_facet_gives_the_spec_examples)
{
    ck_assert(isInFacet(pt(0.5, 0.5, 0), spec_triangle()));
    ck_assert(!isInFacet(pt(-0.5, -0.5, 0), spec_triangle()));
}
END_TEST

START_TEST(is_in_facet_accepts_inner_points_vertices_and_edges)
{
    facet f = spec_triangle();
    ck_assert(isInFacet(pt(0.25, 0.25, 0), f));
    ck_assert(isInFacet(pt(1e-9, 1e-9, 0), f));
    ck_assert(isInFacet(f.a, f));
    ck_assert(isInFacet(f.b, f));
    ck_assert(isInFacet(f.c, f));
    ck_assert(isInFacet(pt(0, 0.3, 0), f));
    ck_assert(isInFacet(pt(0.7, 0, 0), f));
    ck_assert(isInFacet(pt(0.3, 0.7, 0), f));
}
END_TEST

START_TEST(is_in_facet_accepts_points_less_than_epsilon_outside)
{
    facet f = spec_triangle();
    ck_assert(isInFacet(pt(-0.5 * EPSILON, 0.5, 0), f));
    ck_assert(isInFacet(pt(0.5, -0.9 * EPSILON, 0), f));
    /* beyond the long edge x + y = 1, at distance 0.9 EPSILON */
    double d = 0.9 * EPSILON / sqrt(2.0);
    ck_assert(isInFacet(pt(0.5 + d, 0.5 + d, 0), f));
    /* beyond a vertex, diagonally: distance 0.99 EPSILON */
    d = 0.99 * EPSILON / sqrt(2.0);
    ck_assert(isInFacet(pt(-d, -d, 0), f));
    ck_assert(isInFacet(pt(1 + 0.9 * EPSILON, 0, 0), f));
}
END_TEST

START_TEST(is_in_facet_rejects_points_more_than_epsilon_outside)
{
    facet f = spec_triangle();
    ck_assert(!isInFacet(pt(-1.1 * EPSILON, 0.5, 0), f));
    ck_assert(!isInFacet(pt(-2 * EPSILON, 0.5, 0), f));
    ck_assert(!isInFacet(pt(0.5, -2 * EPSILON, 0), f));
    double d = 1.1 * EPSILON / sqrt(2.0);
    ck_assert(!isInFacet(pt(0.5 + d, 0.5 + d, 0), f));
    /* beyond the vertex (0, 0), diagonally, at 1.1 EPSILON: each coordinate
     * is less than EPSILON outside, the distance is not */
    ck_assert(!isInFacet(pt(-d, -d, 0), f));
    ck_assert(!isInFacet(pt(1 + 1.1 * EPSILON, 0, 0), f));
    ck_assert(!isInFacet(pt(0.6, 0.6, 0), f));
}
END_TEST

START_TEST(is_in_facet_judges_the_distance_off_the_plane_too)
{
    facet f = spec_triangle();
    ck_assert(isInFacet(pt(0.2, 0.2, 0.5 * EPSILON), f));
    ck_assert(isInFacet(pt(0.2, 0.2, -0.5 * EPSILON), f));
    ck_assert(!isInFacet(pt(0.2, 0.2, 2 * EPSILON), f));
    ck_assert(!isInFacet(pt(0.2, 0.2, 1), f));
}
END_TEST

START_TEST(is_in_facet_at_epsilon_in_a_tilted_plane)
{
    facet f = createFacet(pt(1, 2, -1), pt(4, 0.5, 2), pt(-2, 3, 5));
    point corners[3] = {f.a, f.b, f.c};
    for (int i = 0; i < 3; i++) {
        point from = corners[i], to = corners[(i + 1) % 3];
        point opposite = corners[(i + 2) % 3];
        point m = outward(f, from, to, opposite);
        point middle = scale(add(from, to), 0.5);
        ck_assert(isInFacet(middle, f));
        ck_assert(isInFacet(add(middle, scale(m, 0.5 * EPSILON)), f));
        ck_assert(!isInFacet(add(middle, scale(m, 2 * EPSILON)), f));
        ck_assert(isInFacet(from, f));
    }
}
END_TEST

START_TEST(is_in_facet_does_not_depend_on_the_winding)
{
    facet f = createFacet(pt(0, 0, 0), pt(1, 0, 0), pt(0, 1, 0));
    facet g = createFacet(pt(0, 0, 0), pt(0, 1, 0), pt(1, 0, 0));
    point probes[] = {pt(0.2, 0.2, 0), pt(0.5, 0.5, 0), pt(-2 * EPSILON, 0.5, 0),
                      pt(0.6, 0.6, 0), pt(0.5 * EPSILON, 0.5, 0)};
    for (size_t i = 0; i < sizeof probes / sizeof probes[0]; i++)
        ck_assert_int_eq(!isInFacet(probes[i], f), !isInFacet(probes[i], g));
}
END_TEST

START_TEST(is_in_facet_of_a_zero_area_facet_is_zero)
{
    facet line = createFacet(pt(0, 0, 0), pt(1, 1, 1), pt(3, 3, 3));
    ck_assert(!isInFacet(pt(1, 1, 1), line));
    ck_assert(!isInFacet(pt(0, 0, 0), line));
}
END_TEST

START_TEST(is_in_facet_of_nan_or_infinite_points_is_zero)
{
    facet f = spec_triangle();
    ck_assert(!isInFacet(pt(NAN, 0.1, 0), f));
    ck_assert(!isInFacet(pt(0.1, 0.1, NAN), f));
    ck_assert(!isInFacet(pt(INFINITY, 0, 0), f));
    ck_assert(!isInFacet(pt(0.1, 0.1, -INFINITY), f));
}
END_TEST

START_TEST(is_in_facet_on_a_sliver_of_aspect_1e12)
{
    point g = sliver_g();
    facet f = sliver();
    ck_assert(isInFacet(add(g, pt(0, SLIVER_H / 2, 0)), f));
    ck_assert(isInFacet(g, f));                 /* on the long edge */
    ck_assert(isInFacet(f.c, f));
    /* in the plane, away from the long edge, on either side: the sliver is
     * 1e-13 thick, so EPSILON is measured from its edges */
    point m = outward(f, f.a, f.b, f.c);
    ck_assert(isInFacet(add(g, scale(m, 0.5 * EPSILON)), f));
    ck_assert(!isInFacet(add(g, scale(m, 2 * EPSILON)), f));
    ck_assert(isInFacet(sub(g, scale(m, 0.5 * EPSILON)), f));
    ck_assert(!isInFacet(sub(g, scale(m, 2 * EPSILON)), f));
    /* beyond its ends, along the long edge */
    point along = unit(g);
    ck_assert(isInFacet(sub(f.a, scale(along, 0.5 * EPSILON)), f));
    ck_assert(!isInFacet(sub(f.a, scale(along, 2 * EPSILON)), f));
    ck_assert(!isInFacet(add(f.b, scale(along, 2 * EPSILON)), f));
    /* off the plane */
    ck_assert(isInFacet(add(g, scale(f.n, 0.5 * EPSILON)), f));
    ck_assert(!isInFacet(add(g, scale(f.n, 2 * EPSILON)), f));
}
END_TEST

/* Random triangles (some of them slivers) and points at a known distance:
 * inside at 0.5 EPSILON off the plane, or 0.5 / 2 EPSILON straight out of an
 * edge, in the plane. */
START_TEST(is_in_facet_at_epsilon_on_random_triangles)
{
    unsigned state = 2024;
    for (int i = 0; i < 2000; i++) {
        point a = pt(random_unit(&state), random_unit(&state),
                     random_unit(&state));
        point b = pt(random_unit(&state), random_unit(&state),
                     random_unit(&state));
        point c = pt(random_unit(&state), random_unit(&state),
                     random_unit(&state));
        if (i % 2 == 1) {               /* a sliver: c near the line ab */
            double thin = ldexp(1.0, -10 - i % 31);
            c = add(add(a, scale(sub(b, a), 0.5 + 0.4 * random_unit(&state))),
                    scale(c, thin));
        }
        facet f = createFacet(a, b, c);
        double u = 0.5 * (1 + random_unit(&state));
        double v = (1 - u) * 0.5 * (1 + random_unit(&state));
        point inner = add(a, add(scale(sub(b, a), u), scale(sub(c, a), v)));
        ck_assert(isInFacet(inner, f));
        ck_assert(isInFacet(add(inner, scale(f.n, 0.5 * EPSILON)), f));
        ck_assert(!isInFacet(add(inner, scale(f.n, 2 * EPSILON)), f));

        point corners[3] = {a, b, c};
        int e = i % 3;
        point from = corners[e], to = corners[(e + 1) % 3];
        point m = outward(f, from, to, corners[(e + 2) % 3]);
        double t = 0.5 * (1 + random_unit(&state));
        point on_edge = add(from, scale(sub(to, from), t));
        ck_assert(isInFacet(add(on_edge, scale(m, 0.5 * EPSILON)), f));
        ck_assert_msg(!isInFacet(add(on_edge, scale(m, 2 * EPSILON)), f),
                      "triangle %d, edge %d", i, e);
    }
}
END_TEST

START_TEST(is_in_facet_uses_epsilon_as_an_absolute_length)
{
    /* EPSILON is in scene units (the handout's choice): a triangle of size
     * 1e6 has the same 1e-5 margin as one of size 1. */
    facet big = createFacet(pt(0, 0, 0), pt(0, 1e6, 0), pt(1e6, 0, 0));
    ck_assert(isInFacet(pt(-0.5 * EPSILON, 5e5, 0), big));
    ck_assert(!isInFacet(pt(-2 * EPSILON, 5e5, 0), big));
}
END_TEST

START_TEST(is_in_facet_after_compute_intersection)
{
    facet f = spec_facet();
    /* The spec's example meets the plane outside the triangle:
     * (1/3, 1, 2/3) = a + (1/6)(b - a) + 1.(c - a), u + v = 7/6. */
    point p = computeIntersection(make_ray(pt(0, 0, 0), pt(1, 3, 2)), f);
    ck_assert(!isInFacet(p, f));
    assert_point_near(changeCoord(p, f), pt(1.0 / 6, 1, 0), TIGHT);
    /* A ray towards the centroid (0, -1/3, 1/3) hits it, inside. */
    p = computeIntersection(make_ray(pt(0, 0, 0), pt(0, -1, 1)), f);
    assert_point_near(p, pt(0, -1.0 / 3, 1.0 / 3), TIGHT);
    ck_assert(isInFacet(p, f));
}
END_TEST

static Suite *in104_geometry_suite(void)
{
    Suite *suite = suite_create("in104_geometry");
    TCase *facets = tcase_create("createFacet");
    tcase_add_test(facets, create_facet_gives_the_unit_normal_of_the_spec_example);
    tcase_add_test(facets, create_facet_sets_k_zero_and_black_and_keeps_the_vertices);
    tcase_add_test(facets, create_facet_normal_follows_the_winding);
    tcase_add_test(facets, create_facet_normal_is_unit_at_tiny_and_huge_scales);
    tcase_add_test(facets, create_facet_of_collinear_or_equal_points_has_zero_normal);
    tcase_add_test(facets, create_facet_of_a_sliver_has_an_accurate_normal);
    suite_add_tcase(suite, facets);

    TCase *hits = tcase_create("computeIntersection");
    tcase_add_test(hits, compute_intersection_gives_the_spec_example);
    tcase_add_test(hits, compute_intersection_does_not_depend_on_the_direction_length);
    tcase_add_test(hits, compute_intersection_returns_points_behind_the_origin);
    tcase_add_test(hits, compute_intersection_returns_the_origin_when_it_is_on_the_plane);
    tcase_add_test(hits, compute_intersection_of_a_parallel_ray_is_nan);
    tcase_add_test(hits, compute_intersection_of_a_ray_in_the_plane_is_nan);
    tcase_add_test(hits, compute_intersection_without_direction_or_area_is_nan);
    tcase_add_test(hits, compute_intersection_of_a_nearly_parallel_ray_is_finite_or_nan);
    tcase_add_test(hits, compute_intersection_ignores_the_stored_normal);
    tcase_add_test(hits, compute_intersection_lands_on_the_plane_and_the_line);
    tcase_add_test(hits, compute_intersection_is_accurate_far_from_the_origin);
    suite_add_tcase(suite, hits);

    TCase *frames = tcase_create("changeCoord");
    tcase_add_test(frames, change_coord_recovers_u_v_w);
    tcase_add_test(frames, change_coord_maps_the_vertices_to_the_unit_frame);
    tcase_add_test(frames, change_coord_w_is_the_signed_distance_to_the_plane);
    tcase_add_test(frames, change_coord_is_accurate_on_a_sliver_of_aspect_1e12);
    tcase_add_test(frames, change_coord_works_at_small_and_large_scales);
    tcase_add_test(frames, change_coord_of_a_zero_area_facet_is_nan);
    suite_add_tcase(suite, frames);

    TCase *inside = tcase_create("isInFacet");
    tcase_add_test(inside, is_in_facet_gives_the_spec_examples);
    tcase_add_test(inside, is_in_facet_accepts_inner_points_vertices_and_edges);
    tcase_add_test(inside, is_in_facet_accepts_points_less_than_epsilon_outside);
    tcase_add_test(inside, is_in_facet_rejects_points_more_than_epsilon_outside);
    tcase_add_test(inside, is_in_facet_judges_the_distance_off_the_plane_too);
    tcase_add_test(inside, is_in_facet_at_epsilon_in_a_tilted_plane);
    tcase_add_test(inside, is_in_facet_does_not_depend_on_the_winding);
    tcase_add_test(inside, is_in_facet_of_a_zero_area_facet_is_zero);
    tcase_add_test(inside, is_in_facet_of_nan_or_infinite_points_is_zero);
    tcase_add_test(inside, is_in_facet_on_a_sliver_of_aspect_1e12);
    tcase_add_test(inside, is_in_facet_at_epsilon_on_random_triangles);
    tcase_add_test(inside, is_in_facet_uses_epsilon_as_an_absolute_length);
    tcase_add_test(inside, is_in_facet_after_compute_intersection);
    suite_add_tcase(suite, inside);
    return suite;
}

RT_CHECK_MAIN(in104_geometry_suite)
