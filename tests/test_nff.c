/*
 * test_nff.c - the NFF reader (src/formats/nff.c) and the tessellation of
 * its spheres, cones and polygons (src/formats/tessellate.c).  Every
 * expectation is computed by hand from the entity's definition in
 * ../shared/formats/NFF.TXT and the mapping of docs/formats.md; the three
 * SPD scenes of ../shared/formats load (a visible skip without ../shared).
 */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "formats/tessellate.h"
#include "testutil.h"

#define PI 3.14159265358979323846

/* A view with every parameter, 100x100 pixels, then `body`. */
#define VIEW                                                                 \
    "v\nfrom 0 -10 0\nat 0 0 0\nup 0 0 1\nangle 45\nhither 1\n"              \
    "resolution 100 100\nl 0 -10 10\n"

static rt_status parse_nff(const char *text, double tolerance,
                           rt_scene **scene, rt_error *error)
{
    rt_load_options options;
    rt_load_options_init(&options);
    options.format = RT_SCENE_FORMAT_NFF;
    options.tessellation = tolerance;
    memset(error, 0, sizeof *error);
    return rt_scene_parse(text, strlen(text), "t.nff", &options, scene, error);
}

static rt_scene *load_nff(const char *text, double tolerance)
{
    rt_scene *scene;
    rt_error error;
    rt_status status = parse_nff(text, tolerance, &scene, &error);
    ck_assert_msg(status == RT_OK, "%s", error.message);
    return scene;
}

static rt_vec3 sub(rt_vec3 a, rt_vec3 b)
{
    return (rt_vec3){a.x - b.x, a.y - b.y, a.z - b.z};
}

static double dot(rt_vec3 a, rt_vec3 b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

static rt_vec3 cross(rt_vec3 a, rt_vec3 b)
{
    return (rt_vec3){a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z,
                     a.x * b.y - a.y * b.x};
}

static double length(rt_vec3 a)
{
    return sqrt(dot(a, a));
}

static void corners(const rt_scene *scene, int i, rt_vec3 p[3])
{
    rt_facet_info f = {.size = sizeof f};
    rt_scene_facet(scene, i, &f);
    for (int j = 0; j < 3; j++)
        p[j] = rt_scene_vertex(scene, f.vertex[j]);
}

/* (b - a) x (c - a) of facet i. */
static rt_vec3 winding(const rt_scene *scene, int i)
{
    rt_vec3 p[3];
    corners(scene, i, p);
    return cross(sub(p[1], p[0]), sub(p[2], p[0]));
}

/* The largest distance, along the radius, between the sphere of radius r
 * around c and the facets, sampled on a barycentric grid of each facet. */
static double sphere_gap(const rt_scene *scene, rt_vec3 c, double r)
{
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    double worst = 0;
    const int steps = 12;
    for (int i = 0; i < info.facet_count; i++) {
        rt_vec3 p[3];
        corners(scene, i, p);
        for (int a = 0; a <= steps; a++)
            for (int b = 0; a + b <= steps; b++) {
                double u = (double)a / steps, v = (double)b / steps;
                double w = 1 - u - v;
                rt_vec3 q = {u * p[0].x + v * p[1].x + w * p[2].x,
                             u * p[0].y + v * p[1].y + w * p[2].y,
                             u * p[0].z + v * p[1].z + w * p[2].z};
                double gap = r - length(sub(q, c));
                if (gap > worst)
                    worst = gap;
            }
    }
    return worst;
}

/* ------------------------------------------------------------------ */

START_TEST(a_circle_gets_the_fewest_segments_within_the_tolerance)
{
    /* 1 - cos(pi/7) = 0.0990 <= 0.1 < 1 - cos(pi/6) = 0.1340 */
    ck_assert_int_eq(rt__tess_circle_segments(0.1), 7);
    /* 1 - cos(pi/n) <= 0.01: pi/n <= acos(0.99) = 0.14153, n = 23 */
    ck_assert_int_eq(rt__tess_circle_segments(0.01), 23);
    /* tolerance 0.5: pi/3 gives exactly 0.5, and never fewer than 3 */
    ck_assert_int_eq(rt__tess_circle_segments(0.5), 3);
    ck_assert_int_eq(rt__tess_circle_segments(0.9), 3);
    ck_assert_int_eq(rt__tess_circle_segments(0), 0);
    ck_assert_int_eq(rt__tess_circle_segments(1), 0);
    const double tols[] = {0.1, 0.03, 0.01, 0.003, 0.001, 1e-4};
    for (size_t i = 0; i < sizeof tols / sizeof tols[0]; i++) {
        int n = rt__tess_circle_segments(tols[i]);
        ck_assert(1 - cos(PI / n) <= tols[i]);
        ck_assert(1 - cos(PI / (n - 1)) > tols[i]);
    }
}
END_TEST

START_TEST(a_sphere_gets_the_fewest_bands_within_the_tolerance)
{
    const double tols[] = {0.3, 0.1, 0.03, 0.01, 0.003, 0.001};
    for (size_t i = 0; i < sizeof tols / sizeof tols[0]; i++) {
        int bands = rt__tess_sphere_bands(tols[i]);
        ck_assert_int_ge(bands, 2);
        ck_assert(rt__tess_sphere_deviation(bands) <= tols[i]);
        if (bands > 2)
            ck_assert(rt__tess_sphere_deviation(bands - 1) > tols[i]);
    }
    /* two bands: the octahedron, whose faces are 1 - 1/sqrt(3) from the
     * unit sphere at their centres */
    ck_assert_double_eq_tol(rt__tess_sphere_deviation(2), 1 - 1 / sqrt(3.0),
                            1e-12);
    ck_assert_int_eq(rt__tess_sphere_bands(1e-12), 0);
}
END_TEST

START_TEST(a_sphere_has_its_facets_on_it_within_the_tolerance_wound_outward)
{
    const double tols[] = {0.1, 0.01, 0.001};
    for (size_t k = 0; k < sizeof tols / sizeof tols[0]; k++) {
        rt_scene *scene = load_nff(VIEW "f 1 0 0 1 0 0 0 0\ns 1 2 3 0.5\n",
                                   tols[k]);
        rt_scene_info info = {.size = sizeof info};
        rt_scene_get_info(scene, &info);
        int bands = rt__tess_sphere_bands(tols[k]);
        ck_assert_int_eq(info.facet_count, 4 * bands * (bands - 1));
        ck_assert_int_eq(info.vertex_count, 2 * bands * (bands - 1) + 2);
        rt_vec3 c = {1, 2, 3};
        for (int i = 0; i < info.vertex_count; i++)
            ck_assert_double_eq_tol(length(sub(rt_scene_vertex(scene, i), c)),
                                    0.5, 1e-12);
        for (int i = 0; i < info.facet_count; i++) {
            rt_vec3 p[3];
            corners(scene, i, p);
            rt_vec3 centroid = {(p[0].x + p[1].x + p[2].x) / 3 - c.x,
                                (p[0].y + p[1].y + p[2].y) / 3 - c.y,
                                (p[0].z + p[1].z + p[2].z) / 3 - c.z};
            ck_assert(dot(winding(scene, i), centroid) > 0);
        }
        double gap = sphere_gap(scene, c, 0.5);
        ck_assert_msg(gap <= tols[k] * 0.5 * (1 + 1e-9), "gap %g", gap);
        /* and not far below: the fewest bands were chosen */
        ck_assert_msg(gap > tols[k] * 0.5 * 0.3, "gap %g", gap);
        rt_scene_destroy(scene);
    }
}
END_TEST

START_TEST(a_negative_radius_winds_the_sphere_inward_with_a_warning)
{
    rt_scene *scene = load_nff(VIEW "s 0 0 0 -1\n", 0.1);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    for (int i = 0; i < info.facet_count; i++) {
        rt_vec3 p[3];
        corners(scene, i, p);
        ck_assert(dot(winding(scene, i), p[0]) < 0);
    }
    ck_assert_int_eq(rt_test_count_warnings(scene, "negative radius"), 1);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(a_cylinder_is_open_with_two_facets_a_segment_wound_outward)
{
    /* tolerance 0.1: 7 segments (above); the cylinder along x, radius 2 */
    rt_scene *scene = load_nff(VIEW "c 0 0 0 2 3 0 0 2\n", 0.1);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    ck_assert_int_eq(info.facet_count, 14);
    ck_assert_int_eq(info.vertex_count, 14);
    for (int i = 0; i < info.vertex_count; i++) {
        rt_vec3 v = rt_scene_vertex(scene, i);
        ck_assert(v.x == 0 || v.x == 3);
        ck_assert_double_eq_tol(hypot(v.y, v.z), 2, 1e-12);
    }
    for (int i = 0; i < info.facet_count; i++) {
        rt_vec3 p[3];
        corners(scene, i, p);
        rt_vec3 radial = {0, p[0].y + p[1].y + p[2].y,
                          p[0].z + p[1].z + p[2].z};
        ck_assert(dot(winding(scene, i), radial) > 0);
        /* the facet's plane is 2 cos(pi/7) from the axis: deviation
         * 2 (1 - cos(pi/7)) <= 0.1 * 2 */
        rt_vec3 n = winding(scene, i);
        double d = dot(n, p[0]) / length(n);
        ck_assert_double_eq_tol(d, 2 * cos(PI / 7), 1e-9);
    }
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(a_cone_to_a_point_has_one_facet_a_segment)
{
    rt_scene *scene = load_nff(VIEW "c 0 0 0 1 0 0 2 0\n", 0.1);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    ck_assert_int_eq(info.facet_count, 7);
    /* 7 points of the base circle, and the apex once a segment (each
     * copy with its own normal: tessellate.h) */
    ck_assert_int_eq(info.vertex_count, 14);
    for (int i = 0; i < info.facet_count; i++) {
        rt_vec3 p[3];
        corners(scene, i, p);
        rt_vec3 radial = {p[0].x + p[1].x + p[2].x,
                          p[0].y + p[1].y + p[2].y, 0};
        ck_assert(dot(winding(scene, i), radial) > 0);
    }
    for (int i = 0; i < info.vertex_count; i++) {
        rt_vec3 v = rt_scene_vertex(scene, i);
        ck_assert(v.z == 0 || (v.x == 0 && v.y == 0 && v.z == 2));
    }
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(the_view_maps_to_the_screen_with_the_angle_between_pixel_centres)
{
    rt_scene *scene = load_nff("v\nfrom 0 -10 0\nat 0 0 0\nup 0 0.5 2\n"
                               "angle 90\nhither 0.5\nresolution 11 11\n"
                               "l 1 2 3\np 3\n0 0 0\n1 0 0\n0 0 1\n",
                               0);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    const rt_camera *c = &info.camera;
    ck_assert_int_eq(c->width, 11);
    ck_assert_int_eq(c->height, 11);
    ck_assert(c->observer.y == -10 && c->observer.x == 0);
    ck_assert(length(c->screen_center) == 0);
    /* |AB| = |AO| tan(45 deg) / (1 - 1/11) = 11, to the right (+x) */
    ck_assert_double_eq_tol(c->right.x, 11, 1e-12);
    ck_assert_double_eq_tol(c->right.y, 0, 1e-12);
    ck_assert_double_eq_tol(c->right.z, 0, 1e-12);
    /* up is +z (the file's up, made perpendicular), |AC| = |AB| */
    ck_assert_double_eq_tol(c->up.z, 11, 1e-12);
    /* the centre of the first column is 45 degrees left of the axis */
    rt_ray ray = rt_camera_ray(c, 0, 5);
    ck_assert_double_eq_tol(ray.direction.x / ray.direction.y, -1, 1e-12);
    ray = rt_camera_ray(c, 5, 0);
    ck_assert_double_eq_tol(ray.direction.z / ray.direction.y, 1, 1e-12);
    ck_assert_int_eq(rt_test_count_warnings(scene, "hither"), 1);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(colours_and_materials_map_to_the_model)
{
    rt_scene *scene = load_nff(VIEW "b 0.5 0 1\n"
                               "f 0.2 0.4 0.6 0.7 0.2 30 0.5 1.3\n"
                               "p 3\n0 0 0\n1 0 0\n0 0 1\n"
                               "f 1 1 1 2 0.25 5 0 0\n"
                               "p 3\n0 0 0\n1 0 0\n0 0 1\n",
                               0);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    /* 0.5 * 255 = 127.5, rounded to 128 */
    ck_assert_int_eq(info.background.r, 128);
    ck_assert_int_eq(info.background.g, 0);
    ck_assert_int_eq(info.background.b, 255);
    rt_facet_info f = {.size = sizeof f};
    rt_scene_facet(scene, 0, &f);
    ck_assert_int_eq(f.color.r, 51);
    ck_assert_int_eq(f.color.g, 102);
    ck_assert_int_eq(f.color.b, 153);
    ck_assert(f.diffuse == 0.7 && f.reflection == 0.2 &&
              f.transparency == 0.5 && f.refractive_index == 1.3);
    /* Kd above 1 stays (the model needs only d >= 0); T = 0: n = 1 */
    rt_scene_facet(scene, 1, &f);
    ck_assert(f.diffuse == 2 && f.reflection == 0.25 && f.transparency == 0 &&
              f.refractive_index == 1);
    /* Ks is also the highlight's weight, Shine its exponent */
    rt_scene_facet(scene, 0, &f);
    ck_assert(f.highlight == 0.2 && f.highlight_exponent == 30);
    rt_scene_facet(scene, 1, &f);
    ck_assert(f.highlight == 0.25 && f.highlight_exponent == 5);
    ck_assert_int_eq(rt_test_count_warnings(scene, "Shine"), 0);
    ck_assert_int_eq(rt_test_count_warnings(scene, "highlight"), 0);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(ks_plus_t_above_one_is_scaled_down_with_a_warning)
{
    rt_scene *scene = load_nff(VIEW "f 1 1 1 0 0.6 1 0.9 1.5\n"
                               "p 3\n0 0 0\n1 0 0\n0 0 1\n",
                               0);
    rt_facet_info f = {.size = sizeof f};
    rt_scene_facet(scene, 0, &f);
    ck_assert_double_eq_tol(f.reflection, 0.4, 1e-12);
    ck_assert_double_eq_tol(f.transparency, 0.6, 1e-12);
    ck_assert(f.reflection + f.transparency <= 1);
    ck_assert_int_eq(rt_test_count_warnings(scene, "Ks + T = 1.5"), 1);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(lights_without_colour_share_one_white_light)
{
    rt_scene *scene = load_nff(VIEW "l 1 2 3\nl 4 5 6 0.2 0.4 1\n"
                               "p 3\n0 0 0\n1 0 0\n0 0 1\n",
                               0);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    ck_assert_int_eq(info.light_count, 3);
    rt_light l;
    /* three lights: 255 / sqrt(3) = 147.2 */
    rt_scene_light(scene, 0, &l);
    ck_assert(l.position.z == 10);
    ck_assert_int_eq(l.color.r, 147);
    rt_scene_light(scene, 1, &l);
    ck_assert(l.position.x == 1 && l.position.y == 2 && l.position.z == 3);
    ck_assert_int_eq(l.color.g, 147);
    rt_scene_light(scene, 2, &l);
    ck_assert_int_eq(l.color.r, 51);
    ck_assert_int_eq(l.color.g, 102);
    ck_assert_int_eq(l.color.b, 255);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(a_file_without_light_gets_a_white_light_at_the_eye)
{
    /* and without `hither` (NFF before 2.7) */
    rt_scene *scene = load_nff("v from 1 2 3 at 0 0 0 up 0 0 1 angle 30 "
                               "resolution 8 8\n"
                               "p 3 0 0 0 1 0 0 0 0 1\n",
                               0);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    ck_assert_int_eq(info.light_count, 1);
    rt_light light;
    rt_scene_light(scene, 0, &light);
    ck_assert(light.position.x == 1 && light.position.y == 2 &&
              light.position.z == 3);
    ck_assert_int_eq(light.color.r, 255);
    ck_assert_int_eq(rt_test_count_warnings(scene, "no light"), 1);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(a_convex_polygon_is_a_fan_that_keeps_its_winding)
{
    rt_scene *scene = load_nff(VIEW "p 5\n0 0 0\n2 0 0\n3 0 1\n1 0 2\n"
                               "-1 0 1\n",
                               0);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    ck_assert_int_eq(info.facet_count, 3);
    for (int i = 0; i < 3; i++) {
        rt_facet_info f = {.size = sizeof f};
        rt_scene_facet(scene, i, &f);
        ck_assert_int_eq(f.vertex[0], 0);
        /* counter-clockwise seen from -y: normal -y */
        ck_assert(winding(scene, i).y < 0);
    }
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(a_non_convex_polygon_is_cut_into_ears_covering_its_area)
{
    /* an L of area 3 in the z = 1 plane, counter-clockwise from +z, its
     * reflex corner at (1, 1) */
    rt_scene *scene = load_nff(VIEW "p 6\n0 0 1\n2 0 1\n2 1 1\n1 1 1\n"
                               "1 2 1\n0 2 1\n",
                               0);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    ck_assert_int_eq(info.facet_count, 4);
    double area = 0;
    for (int i = 0; i < 4; i++) {
        rt_vec3 n = winding(scene, i);
        ck_assert(n.z > 0);
        area += n.z / 2;
    }
    ck_assert_double_eq_tol(area, 3, 1e-12);
    /* no facet covers the notch (1.5, 1.5) */
    rt_ray ray = {{1.5, 1.5, 5}, {0, 0, -1}};
    rt_hit hit;
    ck_assert(!rt_scene_nearest_hit(scene, ray, INFINITY, &hit));
    ray.origin = (rt_vec3){0.5, 1.5, 5};
    ck_assert(rt_scene_nearest_hit(scene, ray, INFINITY, &hit));
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(a_patch_gives_its_triangles_the_normals_of_its_corners)
{
    /* a square cut into two triangles, a normal of its own at each corner
     * (given unnormalised: the scene holds them normalised) */
    static const double corner[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1},
                                        {0, 0, 1}};
    static const double given[4][3] = {{0, -2, 0}, {1, -1, 0}, {1, -1, 1},
                                       {0, -3, 4}};
    rt_scene *scene = load_nff(VIEW "pp 4\n0 0 0 0 -2 0\n1 0 0 1 -1 0\n"
                               "1 0 1 1 -1 1\n0 0 1 0 -3 4\n",
                               0);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    ck_assert_int_eq(info.facet_count, 2);
    ck_assert_int_eq(info.smooth_facet_count, 2);
    ck_assert_int_eq(rt_test_count_warnings(scene, "normal"), 0);
    for (int i = 0; i < info.facet_count; i++) {
        rt_facet_info f = {.size = sizeof f};
        rt_scene_facet(scene, i, &f);
        ck_assert(f.smooth);
        for (int j = 0; j < 3; j++) {
            rt_vec3 v = rt_scene_vertex(scene, f.vertex[j]);
            int k = 0;
            while (k < 4 && !(v.x == corner[k][0] && v.y == corner[k][1] &&
                              v.z == corner[k][2]))
                k++;
            ck_assert_int_lt(k, 4);
            rt_vec3 g = {given[k][0], given[k][1], given[k][2]};
            double l = length(g);
            rt_vec3 n = f.vertex_normal[j];
            ck_assert_double_eq_tol(n.x, g.x / l, 1e-15);
            ck_assert_double_eq_tol(n.y, g.y / l, 1e-15);
            ck_assert_double_eq_tol(n.z, g.z / l, 1e-15);
        }
    }
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(a_zero_patch_normal_leaves_its_triangles_flat_with_one_warning)
{
    rt_scene *scene = load_nff(VIEW "pp 3\n0 0 0 0 0 0\n1 0 0 0 -1 0\n"
                               "0 0 1 0 -1 0\n"
                               "pp 3\n0 1 0 0 -1 0\n1 1 0 0 -1 0\n"
                               "0 1 1 0 0 0\n"
                               "pp 3\n0 2 0 0 -1 0\n1 2 0 0 -1 0\n"
                               "0 2 1 0 -1 0\n",
                               0);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    ck_assert_int_eq(info.facet_count, 3);
    ck_assert_int_eq(info.smooth_facet_count, 1);
    ck_assert_int_eq(rt_test_count_warnings(scene, "zero vertex normal"), 1);
    rt_scene_destroy(scene);
}
END_TEST

/* The unit point of the sphere's ring i, meridian j, as tessellate.h
 * defines the mesh (bands bands, 2 bands meridians). */
static rt_vec3 sphere_point(int bands, int i, int j)
{
    if (i == 0)
        return (rt_vec3){0, 0, 1};
    if (i == bands)
        return (rt_vec3){0, 0, -1};
    double theta = PI * i / bands, phi = PI * j / bands;
    return (rt_vec3){sin(theta) * cos(phi), sin(theta) * sin(phi),
                     cos(theta)};
}

START_TEST(a_sphere_has_its_exact_normal_at_each_vertex_and_the_same_points)
{
    const double tol = 0.01;
    const double c[3] = {1, 2, 3}, r = 0.5;
    for (int inward = 0; inward < 2; inward++) {
        rt_scene *scene = load_nff(inward ? VIEW "s 1 2 3 -0.5\n"
                                          : VIEW "s 1 2 3 0.5\n",
                                   tol);
        rt_scene_info info = {.size = sizeof info};
        rt_scene_get_info(scene, &info);
        int bands = rt__tess_sphere_bands(tol);
        ck_assert_int_eq(info.smooth_facet_count, info.facet_count);
        /* the north pole, the rings from the north, the south pole */
        int v = 0;
        for (int i = 0; i <= bands; i++)
            for (int j = 0; j < (i == 0 || i == bands ? 1 : 2 * bands);
                 j++, v++) {
                rt_vec3 u = sphere_point(bands, i, j);
                rt_vec3 p = rt_scene_vertex(scene, v);
                /* the points as before the normals, to the bit */
                ck_assert(p.x == c[0] + u.x * r && p.y == c[1] + u.y * r &&
                          p.z == c[2] + u.z * r);
                rt_vec3 n = rt_scene_vertex_normal(scene, v);
                double side = inward ? -1 : 1;
                ck_assert_double_eq_tol(n.x, side * u.x, 1e-15);
                ck_assert_double_eq_tol(n.y, side * u.y, 1e-15);
                ck_assert_double_eq_tol(n.z, side * u.z, 1e-15);
            }
        ck_assert_int_eq(v, info.vertex_count);
        /* facing as the facets are wound */
        for (int i = 0; i < info.facet_count; i++) {
            rt_facet_info f = {.size = sizeof f};
            rt_scene_facet(scene, i, &f);
            ck_assert(dot(winding(scene, i), f.vertex_normal[0]) > 0);
        }
        rt_scene_destroy(scene);
    }
}
END_TEST

START_TEST(a_cone_has_the_exact_normal_of_its_side_at_each_vertex)
{
    /* radius 2 at z = 0 to radius 1 at z = 3 (tolerance 0.1: 7 segments):
     * the side's normal is normalise(3 rho + (2 - 1) z); a cone to a
     * point (radius 1 to 0 over 2): normalise(2 rho + z), its apex once a
     * segment with the normal at the segment's middle */
    static const char *const cones[] = {"c 0 0 0 2 0 0 3 1\n",
                                        "c 0 0 0 1 0 0 2 0\n"};
    static const double height[] = {3, 2}, narrowing[] = {1, 1};
    for (int k = 0; k < 2; k++) {
        char text[512];
        snprintf(text, sizeof text, VIEW "%s", cones[k]);
        rt_scene *scene = load_nff(text, 0.1);
        rt_scene_info info = {.size = sizeof info};
        rt_scene_get_info(scene, &info);
        ck_assert_int_eq(info.smooth_facet_count, info.facet_count);
        double l = hypot(height[k], narrowing[k]);
        for (int i = 0; i < info.facet_count; i++) {
            rt_facet_info f = {.size = sizeof f};
            rt_scene_facet(scene, i, &f);
            rt_vec3 p[3];
            corners(scene, i, p);
            for (int j = 0; j < 3; j++) {
                rt_vec3 n = f.vertex_normal[j];
                ck_assert_double_eq_tol(n.z, narrowing[k] / l, 1e-15);
                ck_assert_double_eq_tol(hypot(n.x, n.y), height[k] / l,
                                        1e-15);
                if (p[j].x != 0 || p[j].y != 0) {
                    /* radial: along the point's own direction */
                    double rho = hypot(p[j].x, p[j].y);
                    ck_assert_double_eq_tol(n.x, height[k] / l * p[j].x / rho,
                                            1e-14);
                    ck_assert_double_eq_tol(n.y, height[k] / l * p[j].y / rho,
                                            1e-14);
                }
            }
            ck_assert(dot(winding(scene, i), f.vertex_normal[0]) > 0);
        }
        rt_scene_destroy(scene);
    }
}
END_TEST

START_TEST(polygons_and_materials_without_ks_carry_no_normal_or_highlight)
{
    /* What rendered flat before vertex normals and highlights still has
     * neither: the renderer then takes the path it took before (the
     * model's rule, docs/rendering-model.md). */
    rt_scene *scene = load_nff(VIEW "f 1 0.5 0 0.8 0 40 0 1\n"
                               "p 4\n0 0 0\n1 0 0\n1 0 1\n0 0 1\n"
                               "p 3\n0 1 0\n1 1 0\n0 1 1\n",
                               0);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    ck_assert_int_eq(info.facet_count, 3);
    ck_assert_int_eq(info.smooth_facet_count, 0);
    ck_assert_int_eq(info.highlight_facet_count, 0);
    for (int i = 0; i < info.vertex_count; i++) {
        rt_vec3 n = rt_scene_vertex_normal(scene, i);
        ck_assert(n.x == 0 && n.y == 0 && n.z == 0);
    }
    for (int i = 0; i < info.facet_count; i++) {
        rt_facet_info f = {.size = sizeof f};
        rt_scene_facet(scene, i, &f);
        ck_assert(f.highlight == 0 && f.highlight_exponent == 1);
    }
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(comments_crlf_and_values_across_lines_are_read)
{
    rt_scene *scene = load_nff("# a comment\r\nv\r\nfrom 0 -10 0 # eye\r\n"
                               "at 0 0 0\r\nup 0 0 1\r\nangle 45\r\n"
                               "hither 1\r\nresolution 10 10\r\n"
                               "c 0 0 0 1\r\n0 0 1 1\r\n"
                               "c 0 0 2 1 0 0 3 1\r\n",
                               0.1);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    ck_assert_int_eq(info.facet_count, 28);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(the_default_tolerance_follows_the_resolution)
{
    rt_scene *small = load_nff("v from 0 -10 0 at 0 0 0 up 0 0 1 angle 45 "
                               "hither 1 resolution 64 64\ns 0 0 0 1\n",
                               0);
    rt_scene *large = load_nff("v from 0 -10 0 at 0 0 0 up 0 0 1 angle 45 "
                               "hither 1 resolution 512 512\ns 0 0 0 1\n",
                               0);
    rt_scene_info a = {.size = sizeof a}, b = {.size = sizeof b};
    rt_scene_get_info(small, &a);
    rt_scene_get_info(large, &b);
    ck_assert_int_lt(a.facet_count, b.facet_count);
    /* 512 pixels: the sphere's radius is 512/2 / (9 tan 22.5) = 68.7 px;
     * facets 5 px across: tolerance 1 - cos(5 / (sqrt(2) 68.7)) = 1.3e-3 */
    double tol = 1 - cos(5 / (sqrt(2.0) * (256 / (9 * tan(PI / 8)))));
    int bands = rt__tess_sphere_bands(tol);
    ck_assert_int_eq(b.facet_count, 4 * bands * (bands - 1));
    rt_scene_destroy(small);
    rt_scene_destroy(large);
}
END_TEST

/* ------------------------------------------------------------------ */
/* Refusals                                                             */

typedef struct refusal {
    const char *text;
    double tolerance;
    rt_status status;
    int line, column;
    const char *message;
} refusal;

START_TEST(every_refusal_names_its_line_column_and_cause)
{
    static const refusal cases[] = {
        {VIEW "q 1 2 3\n", 0, RT_ERR_SYNTAX, 9, 1,
         "t.nff:9:1: expected an entity (v, b, l, f, c, s, p or pp), "
         "found `q`"},
        {VIEW "s 0 0 0 x\n", 0, RT_ERR_SYNTAX, 9, 9,
         "expected a number for the sphere's radius, found `x`"},
        {VIEW "s 0 0 0 0\n", 0, RT_ERR_RANGE, 9, 9,
         "expected a radius other than 0, found `0`"},
        {VIEW "s 0 nan 0 1\n", 0, RT_ERR_RANGE, 9, 5,
         "expected a finite number for the sphere's centre (y)"},
        {VIEW "s 2e152 0 0 1\n", 0, RT_ERR_RANGE, 9, 3,
         "expected a coordinate of magnitude at most 1e152"},
        {VIEW "s 1e152 0 0 1e151\n", 0, RT_ERR_RANGE, 9, 13,
         "expected a radius that keeps the surface within"},
        {VIEW "s 0 0\n", 0, RT_ERR_SYNTAX, 10, 1,
         "unexpected end of file: expected a number for the sphere's "
         "centre (z)"},
        {VIEW "p 5\n0 0 0\n1 0 0\n1 1 0\n", 0, RT_ERR_LIMIT, 9, 3,
         "expected a vertex count of at most 3 (the values left in the "
         "file), found `5`"},
        {VIEW "pp 2\n0 0 0 0 0 1\n1 0 0 0 0 1\n", 0, RT_ERR_RANGE, 9, 4,
         "expected the vertex count (a whole number in 3..2147483647), "
         "found `2`"},
        {VIEW "p 3.5\n", 0, RT_ERR_SYNTAX, 9, 3, "whole number"},
        {VIEW "f 1 1 1 -1 0 0 0 0\n", 0, RT_ERR_RANGE, 9, 9,
         "expected a diffuse weight Kd >= 0, found `-1`"},
        {VIEW "f 1 1 1 1 0 0 -0.5 0\n", 0, RT_ERR_RANGE, 9, 15,
         "expected a transmittance T >= 0, found `-0.5`"},
        {VIEW "f 1 1 1 0 0 0 0.5 0\n", 0, RT_ERR_RANGE, 9, 19,
         "expected an index of refraction > 0 for a transmitting material"},
        {VIEW "c 0 0 0 1 0 0 1 -1\n", 0, RT_ERR_RANGE, 9, 17,
         "expected an apex radius of the base radius's sign"},
        {VIEW "c 0 0 0 1 0 0 0 1\n", 0, RT_ERR_RANGE, 9, 11,
         "expected an apex apart from the base"},
        {VIEW "c 0 0 0 0 0 0 1 0\n", 0, RT_ERR_RANGE, 9, 17,
         "expected a radius other than 0 at the base or the apex"},
        {"v\nfrom 0 0 0\nat 0 0 0\nup 0 0 1\nangle 45\nhither 1\n"
         "resolution 8 8\n", 0, RT_ERR_CAMERA, 3, 4,
         "expected `at` apart from `from`"},
        {"v\nfrom 0 -1 0\nat 0 0 0\nup 0 2 0\nangle 45\nhither 1\n"
         "resolution 8 8\n", 0, RT_ERR_CAMERA, 4, 4,
         "expected an `up` vector not along the view"},
        {"v\nfrom 0 -1 0\nat 0 0 0\nup 0 0 1\nangle 180\nhither 1\n"
         "resolution 8 8\n", 0, RT_ERR_RANGE, 5, 7,
         "expected an angle in (0, 180) degrees, found `180`"},
        {"v\nfrom 0 -1 0\nat 0 0 0\nup 0 0 1\nangle 45\nyon 1\n", 0,
         RT_ERR_SYNTAX, 6, 1, "expected `hither` or `resolution`, found `yon`"},
        {"v\nfrom 0 -1 0\nat 0 0 0\nup 0 0 1\nangle 45\nhither 1\nres 1\n",
         0, RT_ERR_SYNTAX, 7, 1, "expected `resolution`, found `res`"},
        {"v\nfrom 0 -1 0\nat 0 0 0\nup 0 0 1\nangle 45\nhither 1\n"
         "resolution 0 8\n", 0, RT_ERR_RANGE, 7, 12,
         "expected the image width (a whole number in 1..16384)"},
        {"s 0 0 0 1\n", 0, RT_ERR_CAMERA, 2, 1,
         "expected a viewpoint `v` (from, at, up, angle, hither, "
         "resolution), found none in the file"},
        {"v\rfrom 0 -1 0\rat 0 0 0\r", 0, RT_ERR_FORMAT, 0, 0,
         "old Mac line endings"},
        {"\xFF\xFEv\0", 0, RT_ERR_FORMAT, 0, 0, "UTF-16"},
        {VIEW "s 0 0 0 1\n", 1.5, RT_ERR_ARGUMENT, 0, 0,
         "expected a tessellation tolerance in (0, 1), found 1.5"},
        {VIEW "s 0 0 0 1\n", 1e-9, RT_ERR_LIMIT, 9, 1,
         "expected at most 1051488 facets in all for a file of 91 bytes "
         "(1048576 + 32 a byte, at most 16777216), found that this sphere "
         "brings them to more than 16777216: give a larger tessellation "
         "tolerance (--tessellate) (now 1e-09 for this sphere)"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        rt_scene *scene = (rt_scene *)1;
        rt_error error;
        rt_status status = parse_nff(cases[i].text, cases[i].tolerance,
                                     &scene, &error);
        ck_assert_msg(status == cases[i].status, "case %zu: %d %s", i,
                      (int)status, error.message);
        ck_assert_ptr_null(scene);
        ck_assert_msg(error.line == cases[i].line &&
                          error.column == cases[i].column,
                      "case %zu: at %d:%d, %s", i, error.line, error.column,
                      error.message);
        ck_assert_msg(strstr(error.message, cases[i].message) != NULL,
                      "case %zu: %s", i, error.message);
    }
}
END_TEST

START_TEST(the_loader_picks_nff_by_extension)
{
    const char *text = VIEW "s 0 0 0 1\n";
    rt_scene *scene;
    rt_error error;
    ck_assert_int_eq(
        rt_scene_parse(text, strlen(text), "ball.NFF", NULL, &scene, &error),
        RT_OK);
    rt_scene_destroy(scene);
}
END_TEST

/* ------------------------------------------------------------------ */
/* The SPD scenes of ../shared/formats                                  */

static rt_scene *load_shared(const char *file)
{
    char relative[64];
    snprintf(relative, sizeof relative, "formats/%s", file);
    const char *path = rt_test_shared_path(relative);
    ck_assert_ptr_nonnull(path);
    rt_scene *scene;
    rt_error error;
    rt_status status = rt_scene_load(path, NULL, &scene, &error);
    ck_assert_msg(status == RT_OK, "%s", error.message);
    return scene;
}

START_TEST(the_spd_scenes_of_shared_load)
{
    rt_scene *scene = load_shared("tetra-s2.nff");
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    /* 4 tetrahedra of 4 triangles */
    ck_assert_int_eq(info.facet_count, 16);
    ck_assert_int_eq(info.width, 512);
    ck_assert_int_eq(info.background.r, 20);    /* 0.078 * 255 = 19.9 */
    ck_assert_int_eq(info.background.g, 92);    /* 0.361 * 255 = 92.1 */
    ck_assert_int_eq(info.background.b, 192);   /* 0.753 * 255 = 192.0 */
    rt_scene_destroy(scene);

    scene = load_shared("mount-s2.nff");
    rt_scene_get_info(scene, &info);
    /* 4 glass spheres: k = 0.1, t = 0.9, n = 1.5 */
    ck_assert_int_gt(info.transparent_facet_count, 0);
    ck_assert_int_eq(info.light_count, 1);
    rt_scene_destroy(scene);

    scene = load_shared("rings-s2.nff");
    rt_scene_get_info(scene, &info);
    ck_assert_int_eq(info.light_count, 3);
    ck_assert_int_gt(info.facet_count, 150 * 8);
    rt_scene_destroy(scene);
}
END_TEST

static Suite *nff_suite(void)
{
    Suite *s = suite_create("nff");
    TCase *c = tcase_create("tessellation");
    tcase_set_timeout(c, 60);
    tcase_add_test(c, a_circle_gets_the_fewest_segments_within_the_tolerance);
    tcase_add_test(c, a_sphere_gets_the_fewest_bands_within_the_tolerance);
    tcase_add_test(c,
                   a_sphere_has_its_facets_on_it_within_the_tolerance_wound_outward);
    tcase_add_test(c, a_negative_radius_winds_the_sphere_inward_with_a_warning);
    tcase_add_test(c, a_cylinder_is_open_with_two_facets_a_segment_wound_outward);
    tcase_add_test(c, a_cone_to_a_point_has_one_facet_a_segment);
    tcase_add_test(c, a_convex_polygon_is_a_fan_that_keeps_its_winding);
    tcase_add_test(c, a_non_convex_polygon_is_cut_into_ears_covering_its_area);
    tcase_add_test(c, the_default_tolerance_follows_the_resolution);
    suite_add_tcase(s, c);
    c = tcase_create("entities");
    tcase_add_test(c, the_view_maps_to_the_screen_with_the_angle_between_pixel_centres);
    tcase_add_test(c, colours_and_materials_map_to_the_model);
    tcase_add_test(c, ks_plus_t_above_one_is_scaled_down_with_a_warning);
    tcase_add_test(c, lights_without_colour_share_one_white_light);
    tcase_add_test(c, a_file_without_light_gets_a_white_light_at_the_eye);
    tcase_add_test(c, a_patch_gives_its_triangles_the_normals_of_its_corners);
    tcase_add_test(c,
                   a_zero_patch_normal_leaves_its_triangles_flat_with_one_warning);
    tcase_add_test(c,
                   a_sphere_has_its_exact_normal_at_each_vertex_and_the_same_points);
    tcase_add_test(c, a_cone_has_the_exact_normal_of_its_side_at_each_vertex);
    tcase_add_test(c,
                   polygons_and_materials_without_ks_carry_no_normal_or_highlight);
    tcase_add_test(c, comments_crlf_and_values_across_lines_are_read);
    tcase_add_test(c, the_loader_picks_nff_by_extension);
    suite_add_tcase(s, c);
    c = tcase_create("refusals");
    tcase_add_test(c, every_refusal_names_its_line_column_and_cause);
    suite_add_tcase(s, c);
    return s;
}

/* The course's NFF scenes: their own ctest entry, skipped when absent. */
static Suite *nff_shared_suite(void)
{
    Suite *s = suite_create("nff-shared");
    TCase *c = tcase_create("shared");
    tcase_set_timeout(c, 60);
    tcase_add_test(c, the_spd_scenes_of_shared_load);
    suite_add_tcase(s, c);
    return s;
}

RT_CHECK_MAIN_WITH_SHARED(nff_suite, nff_shared_suite)
