/*
 * test_obj.c - the Wavefront OBJ reader (src/formats/obj.c):
 * every index form, relative indices, polygons triangulated by ear clipping
 * (areas and orientations checked against the polygon), materials mapped
 * from the .mtl, warnings for what is ignored, refusals with their line and
 * column.  The automatic camera and the renders are test_obj_view.c's.
 */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

static rt_scene *obj(const char *text)
{
    rt_scene *scene = NULL;
    rt_error error;
    memset(&error, 0, sizeof error);
    rt_status status = rt_test_parse_obj(text, NULL, &scene, &error);
    ck_assert_msg(status == RT_OK, "the OBJ did not load: %s", error.message);
    return scene;
}

/* Refuses `text` with `status`, at (line, column), with a message that
 * holds `words`. */
static void refused(const char *text, rt_status status, int line, int column,
                    const char *words)
{
    rt_scene *scene = (rt_scene *)1;
    rt_error error;
    memset(&error, 0, sizeof error);
    rt_load_options options;
    rt_load_options_init(&options);
    options.format = RT_SCENE_FORMAT_OBJ;
    rt_status got = rt_scene_parse(text, strlen(text), "bad.obj", &options,
                                   &scene, &error);
    ck_assert_msg(got == status, "status %d, expected %d: %s", (int)got,
                  (int)status, error.message);
    ck_assert_ptr_null(scene);
    ck_assert_int_eq(error.line, line);
    ck_assert_int_eq(error.column, column);
    ck_assert_msg(strstr(error.message, words) != NULL,
                  "message `%s` lacks `%s`", error.message, words);
    char prefix[64];
    snprintf(prefix, sizeof prefix, "bad.obj:%d:%d: ", line, column);
    ck_assert_msg(strncmp(error.message, prefix, strlen(prefix)) == 0,
                  "message `%s` does not start with `%s`", error.message,
                  prefix);
}

static void facet_is(const rt_scene *scene, int i, int a, int b, int c)
{
    rt_facet_info f = {.size = sizeof f};
    rt_scene_facet(scene, i, &f);
    ck_assert_msg(f.vertex[0] == a && f.vertex[1] == b && f.vertex[2] == c,
                  "facet %d is (%d, %d, %d), expected (%d, %d, %d)", i,
                  f.vertex[0], f.vertex[1], f.vertex[2], a, b, c);
}

static int facet_count(const rt_scene *scene)
{
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    return info.facet_count;
}

/* ------------------------------------------------------------------ */
/* Index forms                                                          */

START_TEST(each_index_form_names_the_same_vertices)
{
    static const char *const faces[] = {
        "f 1 2 3", "f 1/1 2/2 3/3", "f 1//1 2//1 3//1", "f 1/1/1 2/2/1 3/3/1",
        "f -3/-3/-1 -2/-2/-1 -1/-1/-1", "f 1/-3 2/-2//-1 3//1"};
    int expected_ok[] = {1, 1, 1, 1, 1, 0};
    for (size_t i = 0; i < sizeof faces / sizeof faces[0]; i++) {
        char text[256];
        snprintf(text, sizeof text,
                 "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                 "vn 0 0 1\n%s\n", faces[i]);
        rt_scene *scene = NULL;
        rt_error error;
        rt_status status = rt_test_parse_obj(text, NULL, &scene, &error);
        if (!expected_ok[i]) {
            ck_assert_int_eq(status, RT_ERR_SYNTAX);
            continue;
        }
        ck_assert_msg(status == RT_OK, "`%s`: %s", faces[i], error.message);
        ck_assert_int_eq(facet_count(scene), 1);
        facet_is(scene, 0, 0, 1, 2);
        rt_scene_destroy(scene);
    }
}
END_TEST

START_TEST(negative_indices_count_back_from_the_last_vertex_read)
{
    rt_scene *scene = obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n"
                          "v 0 0 1\nv 1 0 1\nv 0 1 1\nf -3 -2 -1\n"
                          "f -6 2 -1\n");
    ck_assert_int_eq(facet_count(scene), 3);
    facet_is(scene, 0, 0, 1, 2);
    facet_is(scene, 1, 3, 4, 5);
    facet_is(scene, 2, 0, 1, 5);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(a_statement_continues_after_a_backslash_and_comments_end_lines)
{
    rt_scene *scene = obj("# a comment\nv 0 0 0 # the origin\nv 1 \\\n 0 0\n"
                          "v 0 1 0\nv 1 1 0\nf 1 2 \\\r\n4 \\\n 3\n");
    ck_assert_int_eq(facet_count(scene), 2);
    rt_vec3 p = rt_scene_vertex(scene, 1);
    ck_assert(p.x == 1 && p.y == 0 && p.z == 0);
    rt_scene_destroy(scene);
}
END_TEST

/* ------------------------------------------------------------------ */
/* Triangulation                                                        */

static double tri_area(rt_vec3 a, rt_vec3 b, rt_vec3 c, rt_vec3 normal)
{
    rt_vec3 ab = {b.x - a.x, b.y - a.y, b.z - a.z};
    rt_vec3 ac = {c.x - a.x, c.y - a.y, c.z - a.z};
    rt_vec3 n = {ab.y * ac.z - ab.z * ac.y, ab.z * ac.x - ab.x * ac.z,
                 ab.x * ac.y - ab.y * ac.x};
    return 0.5 * (n.x * normal.x + n.y * normal.y + n.z * normal.z);
}

/* Non-zero when the 2D point (x, y) is inside the polygon (even-odd). */
static int inside_polygon(const double (*p)[2], int n, double x, double y)
{
    int in = 0;
    for (int i = 0, j = n - 1; i < n; j = i++)
        if ((p[i][1] > y) != (p[j][1] > y) &&
            x < (p[j][0] - p[i][0]) * (y - p[i][1]) / (p[j][1] - p[i][1]) +
                    p[i][0])
            in = !in;
    return in;
}

/*
 * Writes the 2D polygon p as one face in the plane
 * spanned by the orthonormal e1, e2 (through `origin`), loads it, and
 * checks that its facets are n - 2, all wound like the polygon (their
 * signed areas around e1 x e2 have the polygon's sign), with areas adding
 * up to the polygon's, each centroid inside the polygon.
 */
static void check_polygon(const double (*p)[2], int n, rt_vec3 origin,
                          rt_vec3 e1, rt_vec3 e2)
{
    char *text = malloc((size_t)n * 100 + 64);
    ck_assert_ptr_nonnull(text);
    size_t used = 0;
    for (int i = 0; i < n; i++)
        used += (size_t)sprintf(
            text + used, "v %.17g %.17g %.17g\n",
            origin.x + p[i][0] * e1.x + p[i][1] * e2.x,
            origin.y + p[i][0] * e1.y + p[i][1] * e2.y,
            origin.z + p[i][0] * e1.z + p[i][1] * e2.z);
    used += (size_t)sprintf(text + used, "f");
    for (int i = 0; i < n; i++)
        used += (size_t)sprintf(text + used, " %d", i + 1);
    sprintf(text + used, "\n");
    rt_scene *scene = obj(text);
    free(text);
    rt_vec3 normal = {e1.y * e2.z - e1.z * e2.y, e1.z * e2.x - e1.x * e2.z,
                      e1.x * e2.y - e1.y * e2.x};
    double polygon_area = 0;
    for (int i = 0, j = n - 1; i < n; j = i++)
        polygon_area += 0.5 * (p[j][0] * p[i][1] - p[i][0] * p[j][1]);
    ck_assert_int_eq(facet_count(scene), n - 2);
    double total = 0;
    for (int i = 0; i < n - 2; i++) {
        rt_facet_info f = {.size = sizeof f};
        rt_scene_facet(scene, i, &f);
        ck_assert(!f.degenerate);
        rt_vec3 a = rt_scene_vertex(scene, f.vertex[0]),
                b = rt_scene_vertex(scene, f.vertex[1]),
                c = rt_scene_vertex(scene, f.vertex[2]);
        double area = tri_area(a, b, c, normal);
        ck_assert_msg(area * polygon_area > 0,
                      "facet %d is wound against the polygon", i);
        total += area;
        /* The centroid, back in the polygon's plane coordinates. */
        double cx = 0, cy = 0;
        for (int k = 0; k < 3; k++) {
            cx += p[f.vertex[k]][0] / 3;
            cy += p[f.vertex[k]][1] / 3;
        }
        ck_assert_msg(inside_polygon(p, n, cx, cy),
                      "facet %d lies outside the polygon", i);
    }
    ck_assert_msg(fabs(total - polygon_area) <= 1e-9 * fabs(polygon_area),
                  "the facets cover %.17g, the polygon %.17g", total,
                  polygon_area);
    ck_assert_int_eq(rt_test_count_warnings(scene, "fan"), 0);
    rt_scene_destroy(scene);
}

START_TEST(an_l_shaped_hexagon_is_cut_into_four_facets_inside_it)
{
    static const double l[6][2] = {{0, 0}, {2, 0}, {2, 1},
                                   {1, 1}, {1, 2}, {0, 2}};
    check_polygon(l, 6, (rt_vec3){0, 0, 0}, (rt_vec3){1, 0, 0},
                  (rt_vec3){0, 1, 0});
    /* The same with the reflex corner first (a fan from it would do, from
     * the next one it would not). */
    static const double l2[6][2] = {{1, 1}, {1, 2}, {0, 2},
                                    {0, 0}, {2, 0}, {2, 1}};
    check_polygon(l2, 6, (rt_vec3){0, 0, 0}, (rt_vec3){1, 0, 0},
                  (rt_vec3){0, 1, 0});
}
END_TEST

START_TEST(a_star_in_a_tilted_plane_far_from_the_origin_is_cut_inside_it)
{
    double star[10][2];
    for (int i = 0; i < 10; i++) {
        double angle = 3.14159265358979323846 * (0.5 + i / 5.0);
        double radius = i % 2 ? 0.4 : 1.0;
        star[i][0] = radius * cos(angle);
        star[i][1] = radius * sin(angle);
    }
    double s = 1 / sqrt(2.0), t = 1 / sqrt(3.0);
    check_polygon((const double (*)[2])star, 10, (rt_vec3){1e4, -3e3, 7e2},
                  (rt_vec3){s, s, 0}, (rt_vec3){-t, t, t});
    /* Wound the other way: the facets follow the file's winding. */
    double reversed[10][2];
    for (int i = 0; i < 10; i++) {
        reversed[i][0] = star[9 - i][0];
        reversed[i][1] = star[9 - i][1];
    }
    check_polygon((const double (*)[2])reversed, 10,
                  (rt_vec3){-5, 2, 9}, (rt_vec3){s, -s, 0},
                  (rt_vec3){0, 0, -1});
}
END_TEST

START_TEST(a_comb_of_many_teeth_is_cut_inside_it)
{
    /* A comb: 20 teeth of width 1 and height 5 on a bar of height 1. */
    double comb[84][2];
    int n = 0;
    comb[n][0] = 40, comb[n++][1] = 0;
    for (int k = 19; k >= 0; k--) {
        double x = 2 * k;
        comb[n][0] = x + 2, comb[n++][1] = 6;
        comb[n][0] = x + 1, comb[n++][1] = 6;
        comb[n][0] = x + 1, comb[n++][1] = 1;
        comb[n][0] = x, comb[n++][1] = 1;
    }
    comb[n][0] = 0, comb[n++][1] = 0;
    check_polygon((const double (*)[2])comb, n, (rt_vec3){0, 0, 0},
                  (rt_vec3){1, 0, 0}, (rt_vec3){0, 0, 1});
}
END_TEST

START_TEST(a_polygon_that_crosses_itself_is_fanned_with_a_warning)
{
    rt_scene *scene = obj("v 0 0 0\nv 1 1 0\nv 1 0 0\nv 0 1 0\n"
                          "f 1 2 3 4\n");
    ck_assert_int_eq(facet_count(scene), 2);
    ck_assert_int_eq(rt_test_count_warnings(scene, "triangulated as a fan"), 1);
    ck_assert_int_eq(rt_test_count_warnings(scene, ":5:1: warning"), 1);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(corners_on_a_straight_line_and_repeated_corners_add_no_facet)
{
    /* A square with a corner in the middle of each side, and one repeated. */
    rt_scene *scene = obj("v 0 0 0\nv 1 0 0\nv 2 0 0\nv 2 1 0\nv 2 2 0\n"
                          "v 1 2 0\nv 0 2 0\nv 0 1 0\n"
                          "f 1 2 2 3 4 5 6 7 8\n");
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    ck_assert_int_eq(info.live_facet_count, info.facet_count);
    double total = 0;
    for (int i = 0; i < info.facet_count; i++) {
        rt_facet_info f = {.size = sizeof f};
        rt_scene_facet(scene, i, &f);
        total += tri_area(rt_scene_vertex(scene, f.vertex[0]),
                          rt_scene_vertex(scene, f.vertex[1]),
                          rt_scene_vertex(scene, f.vertex[2]),
                          (rt_vec3){0, 0, 1});
    }
    ck_assert_double_eq_tol(total, 4.0, 1e-12);
    ck_assert_int_eq(info.warning_count, 0);
    rt_scene_destroy(scene);
}
END_TEST

/* ------------------------------------------------------------------ */
/* Materials                                                            */

static void material_is(const rt_scene *scene, int facet, int r, int g,
                        int b, double k, double t, double n, double d)
{
    rt_facet_info f = {.size = sizeof f};
    rt_scene_facet(scene, facet, &f);
    ck_assert_msg(f.color.r == r && f.color.g == g && f.color.b == b,
                  "facet %d: colour (%d, %d, %d), expected (%d, %d, %d)",
                  facet, f.color.r, f.color.g, f.color.b, r, g, b);
    ck_assert_double_eq_tol(f.reflection, k, 1e-12);
    ck_assert_double_eq_tol(f.transparency, t, 1e-12);
    ck_assert_double_eq_tol(f.refractive_index, n, 1e-12);
    ck_assert_double_eq_tol(f.diffuse, d, 1e-12);
}

START_TEST(materials_map_kd_ks_with_illum_d_tr_and_ni)
{
    rt_scene *scene = rt_test_load_source_scene("tests/data/obj/materials.obj");
    ck_assert_int_eq(facet_count(scene), 14);
    /* Kd 1 0 0, illum 1: colour only. */
    material_is(scene, 0, 255, 0, 0, 0, 0, 1, 1);
    /* illum 3 (mirror), Ks 0.8 0.7 0.6: k = max(Ks). */
    material_is(scene, 2, 51, 51, 51, 0.8, 0, 1, 0.2);
    /* d 0.25 (dissolve), Ni 1.5, illum 7 without Ks: t = 0.75. */
    material_is(scene, 4, 128, 128, 255, 0, 0.75, 1.5, 0.25);
    /* Tr 0.4, Ni 1.33, no illum. */
    material_is(scene, 6, 0, 255, 0, 0, 0.4, 1.33, 0.6);
    /* illum 5, Ks 0.9, d 0.5: k + t > 1, so k is lowered to 1 - t. */
    material_is(scene, 8, 204, 204, 204, 0.5, 0.5, 1, 0);
    ck_assert_int_eq(rt_test_count_warnings(scene, "`mirror_glass`"), 1);
    /* illum 2 with Ks: a highlight (s = max(Ks), p = Ns), no mirror. */
    material_is(scene, 10, 128, 128, 128, 0, 0, 1, 1);
    rt_facet_info h = {.size = sizeof h};
    rt_scene_facet(scene, 10, &h);
    ck_assert_double_eq_tol(h.highlight, 0.5, 1e-12);
    ck_assert_double_eq_tol(h.highlight_exponent, 96, 1e-12);
    /* A material no library defines: the default grey, with a warning. */
    material_is(scene, 12, 204, 204, 204, 0, 0, 1, 1);
    ck_assert_int_eq(rt_test_count_warnings(scene,
                                            "material `nowhere` is defined "
                                          "in no material library"), 1);
    ck_assert_int_eq(rt_test_count_warnings(scene,
                                            "materials.obj:20:8: warning"), 1);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(a_missing_material_library_is_a_warning_and_the_mesh_is_grey)
{
    rt_scene *scene =
        rt_test_load_source_scene("tests/data/obj/missing-mtl.obj");
    ck_assert_int_eq(facet_count(scene), 1);
    material_is(scene, 0, 204, 204, 204, 0, 0, 1, 1);
    ck_assert_int_eq(rt_test_count_warnings(scene, "material library "
                                          "`no-such-library.mtl` is not "
                                          "read"),
                     1);
    ck_assert_int_eq(rt_test_count_warnings(scene,
                                            "missing-mtl.obj:2:8: warning"),
                     1);
    ck_assert_int_eq(rt_test_count_warnings(scene, "material `red`"), 1);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(library_names_with_spaces_are_read_whole_or_escaped)
{
    rt_scene *scene =
        rt_test_load_source_scene("tests/data/obj/spaced-library.obj");
    material_is(scene, 0, 0, 0, 255, 0, 0, 1, 1);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    ck_assert_int_eq(info.warning_count, 0);
    rt_scene_destroy(scene);
    scene = rt_test_load_source_scene("tests/data/obj/escaped-library.obj");
    material_is(scene, 0, 0, 0, 255, 0, 0, 1, 1);
    rt_scene_get_info(scene, &info);
    ck_assert_int_eq(info.warning_count, 1);
    ck_assert_int_eq(rt_test_count_warnings(scene,
                                            "escaped-library.obj:2:8: warning: "
                                          "material library `missing.mtl` "
                                          "is not read"), 1);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(an_obj_from_memory_without_a_resolver_reads_no_library)
{
    rt_scene *scene = obj("mtllib x.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                          "f 1 2 3\n");
    ck_assert_int_eq(rt_test_count_warnings(scene, "without a resolver"), 1);
    rt_scene_destroy(scene);
}
END_TEST

/* ------------------------------------------------------------------ */
/* What is ignored                                                      */

START_TEST(unknown_statements_lines_and_points_warn_once_each)
{
    rt_scene *scene = obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvn 0 0 1\n"
                          "vp 0.5\nvp 0.5\ncstype bezier\nl 1 2\nl 2 3\n"
                          "p 1\no thing\ng a b\ns off\nf 1 2 3\n");
    ck_assert_int_eq(facet_count(scene), 1);
    ck_assert_int_eq(rt_test_count_warnings(scene, "`vp` statements are not "
                                          "understood"), 1);
    ck_assert_int_eq(rt_test_count_warnings(scene, "`cstype`"), 1);
    ck_assert_int_eq(rt_test_count_warnings(scene, "`l` statements"), 1);
    ck_assert_int_eq(rt_test_count_warnings(scene, "`p` statements"), 1);
    /* normals are read (test_mesh_normals.c): no warning */
    ck_assert_int_eq(rt_test_count_warnings(scene, "vertex normals"), 0);
    ck_assert_int_eq(rt_test_count_warnings(scene, "<memory>:6:1: warning"), 1);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    ck_assert_int_eq(info.warning_count, 4);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(a_file_without_faces_loads_with_a_warning)
{
    rt_scene *scene = obj("v 0 0 0\nv 1 0 0\nl 1 2\n");
    ck_assert_int_eq(facet_count(scene), 0);
    ck_assert_int_eq(rt_test_count_warnings(scene,
                                            "<memory>: warning: the file has "
                                          "no face to draw"), 1);
    rt_scene_destroy(scene);
    scene = obj("");
    ck_assert_int_eq(rt_test_count_warnings(scene, "no face to draw"), 1);
    rt_scene_destroy(scene);
}
END_TEST

/* ------------------------------------------------------------------ */
/* Refusals                                                             */

START_TEST(a_face_index_out_of_range_or_zero_is_refused_at_its_column)
{
    const char *tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    char text[256];
    snprintf(text, sizeof text, "%sf 1 2 4\n", tri);
    refused(text, RT_ERR_RANGE, 4, 7, "a vertex index in 1..3 or -3..-1");
    snprintf(text, sizeof text, "%sf 1 0 2\n", tri);
    refused(text, RT_ERR_RANGE, 4, 5, "found `0`");
    snprintf(text, sizeof text, "%sf 1 2 -4\n", tri);
    refused(text, RT_ERR_RANGE, 4, 7, "found `-4`");
    snprintf(text, sizeof text, "%svt 0 0\nf 1/1 2/0 3/1\n", tri);
    refused(text, RT_ERR_RANGE, 5, 9, "a texture coordinate index in 1..1");
    snprintf(text, sizeof text, "%svn 0 0 1\nf 1//1 2//1 3//0\n", tri);
    refused(text, RT_ERR_RANGE, 5, 16, "a normal index in 1..1");
    refused("f 1 2 3\n", RT_ERR_RANGE, 1, 3, "before any vertex");
}
END_TEST

START_TEST(texture_and_normal_indices_out_of_range_warn_once_each)
{
    /* Exporters leave vt and vn out and keep the references (the reader
     * uses neither): the mesh renders, with one warning for each kind. */
    rt_scene *scene = obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\n"
                          "f 1/2/1 2/9/1 3/-2/4\nf 3/1 2/5 1/1\n");
    ck_assert_int_eq(facet_count(scene), 2);
    ck_assert_int_eq(rt_test_count_warnings(scene, "<memory>:5:5: warning: `2` "
                                          "refers to no texture coordinate"),
                     1);
    ck_assert_int_eq(rt_test_count_warnings(scene, "<memory>:5:7: warning: `1` "
                                          "refers to no normal"),
                     1);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    ck_assert_int_eq(info.warning_count, 2);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(a_face_with_fewer_than_three_vertices_is_refused)
{
    refused("v 0 0 0\nv 1 0 0\nf 1 2\n", RT_ERR_SYNTAX, 3, 6,
            "expected at least 3 vertices for the face, found 2");
    refused("v 0 0 0\nf\n", RT_ERR_SYNTAX, 2, 2, "found 0");
}
END_TEST

START_TEST(malformed_face_vertices_and_numbers_are_refused_with_the_token)
{
    const char *tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n";
    char text[256];
    snprintf(text, sizeof text, "%sf 1/1/1/1 2 3\n", tri);
    refused(text, RT_ERR_SYNTAX, 6, 3, "found `1/1/1/1`");
    snprintf(text, sizeof text, "%sf 1/ 2 3\n", tri);
    refused(text, RT_ERR_SYNTAX, 6, 3, "`v//vn` or `v/vt/vn`");
    snprintf(text, sizeof text, "%sf 1 2.5 3\n", tri);
    refused(text, RT_ERR_SYNTAX, 6, 6, "found `2.5`");
    snprintf(text, sizeof text, "%sf a 2 3\n", tri);
    refused(text, RT_ERR_SYNTAX, 6, 3, "found `a`");
    refused("v 0 0 0\nv 1 0x1 0\n", RT_ERR_SYNTAX, 2, 5,
            "expected a number, found `0x1`");
    refused("v 0 0 0\nv 1 1,5 0\n", RT_ERR_SYNTAX, 2, 5, "found `1,5`");
    refused("v 1 nan 0\n", RT_ERR_RANGE, 1, 5, "a finite number, found `nan`");
    refused("v 1 1e999 0\n", RT_ERR_RANGE, 1, 5, "a finite number");
    refused("v 1 2\n", RT_ERR_SYNTAX, 1, 6,
            "expected 3 coordinates for the vertex");
    refused("vn 1 2\n", RT_ERR_SYNTAX, 1, 7, "expected 3 values for `vn`");
}
END_TEST

START_TEST(coordinates_beyond_1e152_are_refused_at_their_position)
{
    refused("v 0 0 0\n  v 0 -2e152 0\n", RT_ERR_RANGE, 2, 7,
            "a coordinate of magnitude at most 1e152");
}
END_TEST

START_TEST(binary_and_utf16_input_are_refused_by_the_shared_checks)
{
    rt_scene *scene = (rt_scene *)1;
    rt_error error;
    rt_load_options options;
    rt_load_options_init(&options);
    options.format = RT_SCENE_FORMAT_OBJ;
    static const char utf16[] = "\xFF\xFEv\0 \0001\0";
    ck_assert_int_eq(rt_scene_parse(utf16, sizeof utf16 - 1, "u.obj", &options,
                                    &scene, &error),
                     RT_ERR_FORMAT);
    ck_assert_ptr_null(scene);
    ck_assert_ptr_nonnull(strstr(error.message, "UTF-16"));
    static const char mac[] = "v 0 0 0\rv 1 0 0\r";
    ck_assert_int_eq(
        rt_scene_parse(mac, sizeof mac - 1, "m.obj", &options, &scene, &error),
        RT_ERR_FORMAT);
    ck_assert_ptr_nonnull(strstr(error.message, "old Mac line endings"));
}
END_TEST

static Suite *obj_suite(void)
{
    Suite *s = suite_create("obj");
    TCase *c = tcase_create("reading");
    tcase_add_test(c, each_index_form_names_the_same_vertices);
    tcase_add_test(c, negative_indices_count_back_from_the_last_vertex_read);
    tcase_add_test(
        c, a_statement_continues_after_a_backslash_and_comments_end_lines);
    tcase_add_test(c, unknown_statements_lines_and_points_warn_once_each);
    tcase_add_test(c, a_file_without_faces_loads_with_a_warning);
    suite_add_tcase(s, c);

    c = tcase_create("triangulation");
    tcase_add_test(c, an_l_shaped_hexagon_is_cut_into_four_facets_inside_it);
    tcase_add_test(
        c, a_star_in_a_tilted_plane_far_from_the_origin_is_cut_inside_it);
    tcase_add_test(c, a_comb_of_many_teeth_is_cut_inside_it);
    tcase_add_test(c, a_polygon_that_crosses_itself_is_fanned_with_a_warning);
    tcase_add_test(
        c, corners_on_a_straight_line_and_repeated_corners_add_no_facet);
    suite_add_tcase(s, c);

    c = tcase_create("materials");
    tcase_add_test(c, materials_map_kd_ks_with_illum_d_tr_and_ni);
    tcase_add_test(
        c, a_missing_material_library_is_a_warning_and_the_mesh_is_grey);
    tcase_add_test(c, library_names_with_spaces_are_read_whole_or_escaped);
    tcase_add_test(c, an_obj_from_memory_without_a_resolver_reads_no_library);
    suite_add_tcase(s, c);

    c = tcase_create("refusals");
    tcase_add_test(c,
                   a_face_index_out_of_range_or_zero_is_refused_at_its_column);
    tcase_add_test(c, texture_and_normal_indices_out_of_range_warn_once_each);
    tcase_add_test(c, a_face_with_fewer_than_three_vertices_is_refused);
    tcase_add_test(
        c, malformed_face_vertices_and_numbers_are_refused_with_the_token);
    tcase_add_test(c, coordinates_beyond_1e152_are_refused_at_their_position);
    tcase_add_test(c,
                   binary_and_utf16_input_are_refused_by_the_shared_checks);
    suite_add_tcase(s, c);

    return s;
}

RT_CHECK_MAIN(obj_suite)
