/*
 * test_mesh_normals.c - vertex normals, highlights and the up axis of the
 * mesh readers (docs/formats.md, OBJ and PLY): every OBJ face form with
 * `vn`, a vertex copied per (v, vn) pair and shared otherwise, flat faces
 * where a corner has no usable normal, MTL's Ks, Ns and illum as s and p,
 * PLY's nx, ny, nz (ASCII and binary), a file without normals loaded and
 * rendered as it always was, the up axis of the automatic camera and the
 * programs' --up-axis, --check and note.  Expected values are the files'
 * own numbers, normalised by hand.
 */
#include <check.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

static rt_scene *parse(const char *text, size_t length, rt_scene_format format,
                       const rt_load_options *given)
{
    rt_load_options options;
    if (given != NULL)
        options = *given;
    else
        rt_load_options_init(&options);
    options.format = format;
    rt_scene *scene = NULL;
    rt_error error;
    memset(&error, 0, sizeof error);
    rt_status status = rt_scene_parse(text, length, "m", &options, &scene,
                                      &error);
    ck_assert_msg(status == RT_OK, "did not load: %s", error.message);
    return scene;
}

static rt_scene *obj(const char *text)
{
    return parse(text, strlen(text), RT_SCENE_FORMAT_OBJ, NULL);
}

static rt_facet_info facet(const rt_scene *scene, int i)
{
    rt_facet_info f = {.size = sizeof f};
    rt_scene_facet(scene, i, &f);
    return f;
}

static void vec_is(rt_vec3 got, double x, double y, double z)
{
    ck_assert_double_eq_tol(got.x, x, 1e-12);
    ck_assert_double_eq_tol(got.y, y, 1e-12);
    ck_assert_double_eq_tol(got.z, z, 1e-12);
}

/* ------------------------------------------------------------------ */
/* OBJ vn                                                              */

START_TEST(each_face_form_gives_each_corner_its_normal)
{
    static const char *const faces[] = {
        "f 1//1 2//2 3//3\n", "f 1/1/1 2/2/2 3/3/3\n",
        "f -3//-3 -2//-2 -1//-1\n", "f -3/-3/-3 -2/-2/-2 -1/-1/-1\n"};
    for (size_t i = 0; i < sizeof faces / sizeof faces[0]; i++) {
        char text[512];
        snprintf(text, sizeof text,
                 "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                 "vn 0 0 2\nvn 0 3 4\nvn 1 0 0\n%s", faces[i]);
        rt_scene *scene = obj(text);
        rt_scene_info info = rt_test_scene_info(scene);
        ck_assert_int_eq(info.vertex_count, 3);
        ck_assert_int_eq(info.smooth_facet_count, 1);
        ck_assert_int_eq(info.warning_count, 0);
        rt_facet_info f = facet(scene, 0);
        ck_assert_int_eq(f.smooth, 1);
        vec_is(f.vertex_normal[0], 0, 0, 1);
        vec_is(f.vertex_normal[1], 0, 0.6, 0.8);
        vec_is(f.vertex_normal[2], 1, 0, 0);
        vec_is(rt_scene_vertex_normal(scene, 1), 0, 0.6, 0.8);
        rt_scene_destroy(scene);
    }
    /* v and v/vt: no normal, a flat facet */
    rt_scene *scene = obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n"
                          "f 1/1 2/1 3/1\n");
    ck_assert_int_eq(rt_test_scene_info(scene).smooth_facet_count, 0);
    ck_assert_int_eq(rt_test_scene_info(scene).vertex_count, 3);
    rt_scene_destroy(scene);
}
END_TEST

static const char cube[] =
    "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\n"
    "v -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
    "vn 0 0 -1\nvn 0 0 1\nvn 0 -1 0\nvn 0 1 0\nvn -1 0 0\nvn 1 0 0\n"
    "f 1//1 4//1 3//1 2//1\nf 5//2 6//2 7//2 8//2\nf 1//3 2//3 6//3 5//3\n"
    "f 4//4 8//4 7//4 3//4\nf 1//5 5//5 8//5 4//5\nf 2//6 3//6 7//6 6//6\n";

static const char cube_flat[] =
    "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\n"
    "v -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\nf 2 3 7 6\n";

START_TEST(a_cube_with_a_normal_per_face_has_24_vertices_and_its_geometry)
{
    rt_scene *scene = obj(cube), *flat = obj(cube_flat);
    rt_scene_info info = rt_test_scene_info(scene);
    ck_assert_int_eq(info.vertex_count, 24);
    ck_assert_int_eq(info.facet_count, 12);
    ck_assert_int_eq(info.smooth_facet_count, 12);
    ck_assert_int_eq(rt_test_scene_info(flat).facet_count, 12);
    /* the first 8 are the file's vertices, in order */
    for (int i = 0; i < 8; i++) {
        rt_vec3 a = rt_scene_vertex(scene, i), b = rt_scene_vertex(flat, i);
        ck_assert(a.x == b.x && a.y == b.y && a.z == b.z);
    }
    for (int i = 0; i < 12; i++) {
        rt_facet_info f = facet(scene, i), g = facet(flat, i);
        rt_vec3 n = f.vertex_normal[0];
        for (int j = 0; j < 3; j++) {
            /* the same corners, and every corner the face's normal */
            rt_vec3 a = rt_scene_vertex(scene, f.vertex[j]);
            rt_vec3 b = rt_scene_vertex(flat, g.vertex[j]);
            ck_assert(a.x == b.x && a.y == b.y && a.z == b.z);
            vec_is(f.vertex_normal[j], n.x, n.y, n.z);
        }
        /* the normal is the facet's outward one (the file's winding) */
        rt_vec3 a = rt_scene_vertex(scene, f.vertex[0]);
        ck_assert_double_eq_tol(a.x * n.x + a.y * n.y + a.z * n.z, 1, 1e-12);
    }
    rt_scene_destroy(scene);
    rt_scene_destroy(flat);
}
END_TEST

START_TEST(a_smooth_octahedron_shares_its_vertices)
{
    rt_scene *scene = obj(
        "v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n"
        "vn 1 0 0\nvn -1 0 0\nvn 0 1 0\nvn 0 -1 0\nvn 0 0 1\nvn 0 0 -1\n"
        "f 1//1 3//3 5//5\nf 3//3 2//2 5//5\nf 2//2 4//4 5//5\n"
        "f 4//4 1//1 5//5\nf 3//3 1//1 6//6\nf 2//2 3//3 6//6\n"
        "f 4//4 2//2 6//6\nf 1//1 4//4 6//6\n");
    rt_scene_info info = rt_test_scene_info(scene);
    ck_assert_int_eq(info.vertex_count, 6);
    ck_assert_int_eq(info.smooth_facet_count, 8);
    for (int i = 0; i < 6; i++) {
        rt_vec3 v = rt_scene_vertex(scene, i);
        vec_is(rt_scene_vertex_normal(scene, i), v.x, v.y, v.z);
    }
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(a_face_with_a_corner_without_normal_is_flat_and_cut_alike)
{
    /* the quad's last corner has no normal: both its facets are flat, and
     * a vertex used with a normal and without is copied */
    rt_scene *scene = obj("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\n"
                          "f 1//1 2//1 3//1 4\nf 1//1 2//1 3//1\n");
    rt_scene_info info = rt_test_scene_info(scene);
    ck_assert_int_eq(info.facet_count, 3);
    ck_assert_int_eq(info.smooth_facet_count, 1);
    ck_assert_int_eq(info.vertex_count, 7); /* 1, 2, 3 copied */
    ck_assert_int_eq(facet(scene, 0).smooth, 0);
    ck_assert_int_eq(facet(scene, 2).smooth, 1);
    rt_scene_destroy(scene);
    /* a polygon cut into triangles: each corner keeps its normal */
    scene = obj("v 0 0 0\nv 2 0 0\nv 2 2 0\nv 1 1 0\nv 0 2 0\n"
                "vn 1 0 1\nvn 0 1 1\nvn 0 0 1\nvn 1 1 1\nvn -1 0 1\n"
                "f 1//1 2//2 3//3 4//4 5//5\n");
    info = rt_test_scene_info(scene);
    ck_assert_int_eq(info.vertex_count, 5);
    ck_assert_int_eq(info.smooth_facet_count, info.facet_count);
    ck_assert_int_eq(info.facet_count, 3);
    for (int i = 0; i < info.facet_count; i++) {
        rt_facet_info f = facet(scene, i);
        for (int j = 0; j < 3; j++) {
            rt_vec3 v = rt_scene_vertex(scene, f.vertex[j]);
            /* vn k belongs to v k: recognise it by its position */
            rt_vec3 expected[] = {{1, 0, 1}, {0, 1, 1}, {0, 0, 1},
                                  {1, 1, 1}, {-1, 0, 1}};
            rt_vec3 at[] = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {1, 1, 0},
                            {0, 2, 0}};
            for (int k = 0; k < 5; k++)
                if (v.x == at[k].x && v.y == at[k].y) {
                    rt_vec3 e = expected[k];
                    double l = sqrt(e.x * e.x + e.y * e.y + e.z * e.z);
                    vec_is(f.vertex_normal[j], e.x / l, e.y / l, e.z / l);
                }
        }
    }
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(faces_read_before_a_vn_keep_their_vertices_flat)
{
    /* (the second face repeats the first's positions: the builder leaves
     * it out of the live facets, but its record is smooth) */
    rt_scene *scene = obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nvn 0 0 1\n"
                          "f 1//1 2//1 3//1\nv 5 5 5\nf 1//1 2//1 -1//1\n");
    rt_scene_info info = rt_test_scene_info(scene);
    ck_assert_int_eq(info.facet_count, 3);
    ck_assert_int_eq(info.smooth_facet_count, 1);
    ck_assert_int_eq(facet(scene, 1).smooth, 1);
    ck_assert_int_eq(facet(scene, 2).smooth, 1);
    /* 3 copies for the second face; the new `v` keeps its place (3) and
     * takes -1 = itself: the third face's third corner is (5, 5, 5) */
    ck_assert_int_eq(info.vertex_count, 7);
    rt_facet_info f = facet(scene, 2);
    rt_vec3 c = rt_scene_vertex(scene, f.vertex[2]);
    vec_is(c, 5, 5, 5);
    ck_assert_int_eq(facet(scene, 0).smooth, 0);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(zero_and_non_finite_normals_warn_once_and_their_faces_are_flat)
{
    rt_scene *scene = obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 0\nvn nan 0 1\n"
                          "vn 0 0 1e400\nvn 0 0 1\nv 0 0 1\n"
                          "f 1//1 2//4 3//4\nf 1//2 2//4 4//4\n"
                          "f 1//3 4//4 3//4\n");
    rt_scene_info info = rt_test_scene_info(scene);
    ck_assert_int_eq(info.smooth_facet_count, 0);
    ck_assert_int_eq(info.vertex_count, 4);
    ck_assert_int_eq(info.warning_count, 1);
    ck_assert_int_eq(rt_test_count_warnings(scene, "m:4:1: warning: this "
                                                   "vertex normal has zero "
                                                   "length"), 1);
    ck_assert_int_eq(rt_test_count_warnings(scene, "(and 2 more like it)"),
                     1);
    rt_scene_destroy(scene);
}
END_TEST

/* What a file without normals gave before: its vertices, all of them, in
 * its order, and the faces' indices as written. */
START_TEST(a_file_without_normals_gives_its_own_vertices_and_same_render)
{
    static const char plain[] =
        "v 0 0 0\nv 9 9 9\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 3 4 5\nf -5 -3 -1\n";
    static const char unused_vn[] =
        "vn 0 0 1\nv 0 0 0\nv 9 9 9\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 3 4 5\n"
        "vn 0 1 0\nf -5 -3 -1\n";
    rt_scene *a = obj(plain), *b = obj(unused_vn);
    rt_scene_info ia = rt_test_scene_info(a), ib = rt_test_scene_info(b);
    ck_assert_int_eq(ia.vertex_count, 5);
    ck_assert_int_eq(ib.vertex_count, 5);
    ck_assert_int_eq(ia.facet_count, 3);
    ck_assert_int_eq(ib.facet_count, 3);
    ck_assert_int_eq(ib.smooth_facet_count, 0);
    const double x[] = {0, 9, 1, 1, 0};
    for (int i = 0; i < 5; i++) {
        ck_assert(rt_scene_vertex(a, i).x == x[i]);
        ck_assert(rt_scene_vertex(b, i).x == x[i]);
        vec_is(rt_scene_vertex_normal(b, i), 0, 0, 0);
    }
    for (int i = 0; i < 3; i++) {
        rt_facet_info f = facet(a, i), g = facet(b, i);
        ck_assert(memcmp(f.vertex, g.vertex, sizeof f.vertex) == 0);
        ck_assert(f.vertex[0] != 1 && f.vertex[1] != 1 && f.vertex[2] != 1);
    }
    /* at 160x120: the scene's own 512x512 takes seconds under the
     * sanitizers and valgrind */
    rt_render_options o;
    rt_render_options_init(&o);
    o.width = 160;
    o.height = 120;
    rt_image ra = rt_test_render_with(a, &o), rb = rt_test_render_with(b, &o);
    rt_test_assert_same_image(&ra, &rb, "without-normals");
    rt_image_release(&ra);
    rt_image_release(&rb);
    rt_scene_destroy(a);
    rt_scene_destroy(b);
}
END_TEST

/* ------------------------------------------------------------------ */
/* MTL                                                                 */

START_TEST(mtl_ks_ns_and_illum_give_the_highlight)
{
    rt_scene *scene =
        rt_test_load_source_scene("tests/data/obj/highlights.obj");
    ck_assert_int_eq(rt_test_scene_info(scene).facet_count, 5);
    ck_assert_int_eq(rt_test_scene_info(scene).warning_count, 0);
    /* plastic: s = max(Ks) = 0.6, p = Ns = 50, no mirror */
    rt_facet_info f = facet(scene, 0);
    ck_assert_double_eq_tol(f.highlight, 0.6, 1e-12);
    ck_assert_double_eq_tol(f.highlight_exponent, 50, 1e-12);
    ck_assert_double_eq_tol(f.reflection, 0, 1e-12);
    /* illum 1: no highlight */
    ck_assert_double_eq_tol(facet(scene, 1).highlight, 0, 1e-12);
    /* no illum (2), Ns below 1: p = 1 */
    f = facet(scene, 2);
    ck_assert_double_eq_tol(f.highlight, 0.3, 1e-12);
    ck_assert_double_eq_tol(f.highlight_exponent, 1, 1e-12);
    /* illum 3: the mirror as before (k = max(Ks)) and the highlight */
    f = facet(scene, 3);
    ck_assert_double_eq_tol(f.reflection, 0.7, 1e-12);
    ck_assert_double_eq_tol(f.highlight, 0.7, 1e-12);
    ck_assert_double_eq_tol(f.highlight_exponent, 200, 1e-12);
    /* Ks without Ns: p = 1 */
    f = facet(scene, 4);
    ck_assert_double_eq_tol(f.highlight, 0.5, 1e-12);
    ck_assert_double_eq_tol(f.highlight_exponent, 1, 1e-12);
    ck_assert_int_eq(rt_test_scene_info(scene).highlight_facet_count, 4);
    rt_scene_destroy(scene);
}
END_TEST

/* ------------------------------------------------------------------ */
/* PLY                                                                 */

#define PLY_HEAD(format)                                                     \
    "ply\nformat " format " 1.0\nelement vertex 3\nproperty float x\n"       \
    "property float y\nproperty float z\nproperty float nx\n"               \
    "property float ny\nproperty float nz\nelement face 1\n"                \
    "property list uchar int vertex_indices\nend_header\n"

START_TEST(ply_normals_ascii_and_binary_are_the_vertices_normals)
{
    static const char ascii[] = PLY_HEAD("ascii")
        "0 0 0 0 0 2\n1 0 0 0 3 4\n0 1 0 0 0 0\n3 0 1 2\n";
    rt_scene *scene = parse(ascii, strlen(ascii), RT_SCENE_FORMAT_PLY, NULL);
    rt_scene_info info = rt_test_scene_info(scene);
    ck_assert_int_eq(info.warning_count, 0);
    vec_is(rt_scene_vertex_normal(scene, 0), 0, 0, 1);
    vec_is(rt_scene_vertex_normal(scene, 1), 0, 0.6, 0.8);
    vec_is(rt_scene_vertex_normal(scene, 2), 0, 0, 0); /* zero: none */
    ck_assert_int_eq(info.smooth_facet_count, 0);
    rt_scene_destroy(scene);

    const uint16_t one = 1;
    int little = *(const unsigned char *)&one == 1;
    const char *head = little ? PLY_HEAD("binary_little_endian")
                              : PLY_HEAD("binary_big_endian");
    float v[3][6] = {{0, 0, 0, 0, 0, 2}, {1, 0, 0, 0, 3, 4},
                     {0, 1, 0, 1, 0, 0}};
    unsigned char bytes[512];
    size_t n = strlen(head);
    memcpy(bytes, head, n);
    memcpy(bytes + n, v, sizeof v);
    n += sizeof v;
    bytes[n++] = 3;
    for (int32_t i = 0; i < 3; i++, n += 4)
        memcpy(bytes + n, &i, 4);
    scene = parse((const char *)bytes, n, RT_SCENE_FORMAT_PLY, NULL);
    info = rt_test_scene_info(scene);
    ck_assert_int_eq(info.warning_count, 0);
    ck_assert_int_eq(info.smooth_facet_count, 1);
    rt_facet_info f = facet(scene, 0);
    vec_is(f.vertex_normal[1], 0, 0.6, 0.8);
    vec_is(f.vertex_normal[2], 1, 0, 0);
    rt_scene_destroy(scene);
    /* a NaN normal: none, with a warning */
    v[1][4] = NAN;
    memcpy(bytes + strlen(head), v, sizeof v);
    scene = parse((const char *)bytes, n, RT_SCENE_FORMAT_PLY, NULL);
    ck_assert_int_eq(rt_test_scene_info(scene).smooth_facet_count, 0);
    ck_assert_int_eq(rt_test_count_warnings(scene, "vertex 1: its normal is "
                                                   "not finite"), 1);
    vec_is(rt_scene_vertex_normal(scene, 1), 0, 0, 0);
    rt_scene_destroy(scene);
}
END_TEST

/* ------------------------------------------------------------------ */
/* The up axis                                                          */

static rt_scene_info up_of(const char *text, rt_scene_format format,
                           rt_up_axis option)
{
    rt_load_options options;
    rt_load_options_init(&options);
    options.up_axis = option;
    rt_scene *scene = parse(text, strlen(text), format, &options);
    rt_scene_info info = rt_test_scene_info(scene);
    rt_scene_destroy(scene);
    return info;
}

#define TRIANGLE_OBJ "v 0 0 0\nv 1 0 0\nv 0 0 1\nf 1 2 3\n"
#define TRIANGLE_PLY(comment)                                               \
    "ply\nformat ascii 1.0\n" comment "element vertex 3\n"                 \
    "property float x\nproperty float y\nproperty float z\n"               \
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n" \
    "0 0 0\n1 0 0\n0 0 1\n3 0 1 2\n"

START_TEST(the_up_axis_comes_from_a_comment_an_exporter_or_the_option)
{
    static const struct {
        const char *text;
        rt_scene_format format;
        rt_up_axis option, axis;
        rt_up_cue cue;
        int line;
    } cases[] = {
        {TRIANGLE_OBJ, RT_SCENE_FORMAT_OBJ, RT_UP_AUTO, RT_UP_Y,
         RT_UP_CUE_DEFAULT, 0},
        {"# made by hand\n# Z-up\n" TRIANGLE_OBJ, RT_SCENE_FORMAT_OBJ,
         RT_UP_AUTO, RT_UP_Z, RT_UP_CUE_COMMENT, 2},
        {"# up axis: -X\n" TRIANGLE_OBJ, RT_SCENE_FORMAT_OBJ, RT_UP_AUTO,
         RT_UP_NEG_X, RT_UP_CUE_COMMENT, 1},
        {"#up=+z\n" TRIANGLE_OBJ, RT_SCENE_FORMAT_OBJ, RT_UP_AUTO, RT_UP_Z,
         RT_UP_CUE_COMMENT, 1},
        /* words that hold "up" name no axis */
        {"# setup x: update y, upper z, up to you\n" TRIANGLE_OBJ,
         RT_SCENE_FORMAT_OBJ, RT_UP_AUTO, RT_UP_Y, RT_UP_CUE_DEFAULT, 0},
        {"# Blender v2.80 (sub 74) OBJ File\n" TRIANGLE_OBJ,
         RT_SCENE_FORMAT_OBJ, RT_UP_AUTO, RT_UP_Y, RT_UP_CUE_EXPORTER, 1},
        {"# Blender 4.0\n# Z up\n" TRIANGLE_OBJ, RT_SCENE_FORMAT_OBJ,
         RT_UP_AUTO, RT_UP_Z, RT_UP_CUE_COMMENT, 2},
        {"# Z-up\n" TRIANGLE_OBJ, RT_SCENE_FORMAT_OBJ, RT_UP_NEG_Y,
         RT_UP_NEG_Y, RT_UP_CUE_OPTION, 0},
        {TRIANGLE_PLY("comment Created by Blender 3.6.0\n"),
         RT_SCENE_FORMAT_PLY, RT_UP_AUTO, RT_UP_Z, RT_UP_CUE_EXPORTER, 3},
        {TRIANGLE_PLY("comment y up\n"), RT_SCENE_FORMAT_PLY, RT_UP_AUTO,
         RT_UP_Y, RT_UP_CUE_COMMENT, 3},
        {TRIANGLE_PLY(""), RT_SCENE_FORMAT_PLY, RT_UP_AUTO, RT_UP_Y,
         RT_UP_CUE_DEFAULT, 0},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        rt_scene_info info = up_of(cases[i].text, cases[i].format,
                                   cases[i].option);
        ck_assert_msg(info.up_axis == cases[i].axis &&
                          info.up_cue == cases[i].cue &&
                          info.up_cue_line == cases[i].line,
                      "case %zu: axis %d cue %d line %d", i,
                      (int)info.up_axis, (int)info.up_cue, info.up_cue_line);
        /* the image's up is the model's */
        rt_vec3 u = info.camera.up;
        double sign = cases[i].axis > RT_UP_Z ? -1 : 1, axis[3] = {0, 0, 0};
        axis[(cases[i].axis - 1) % 3] = sign;
        rt_vec3 e = {axis[0], axis[1], axis[2]};
        double along = (u.x * e.x + u.y * e.y + u.z * e.z) /
                       sqrt(u.x * u.x + u.y * u.y + u.z * u.z);
        ck_assert_msg(along > 0.8, "case %zu: the image's up leans %g", i,
                      along);
    }
    /* a .scn has its own camera */
    rt_scene *scene = rt_test_load_source_scene("scenes/cubes.scn");
    ck_assert_int_eq(rt_test_scene_info(scene).up_cue, RT_UP_CUE_NONE);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(the_default_up_gives_the_camera_of_every_earlier_release)
{
    /* +y given and +y by default: the same camera, bit for bit */
    rt_scene_info a = up_of(TRIANGLE_OBJ, RT_SCENE_FORMAT_OBJ, RT_UP_AUTO);
    rt_scene_info b = up_of(TRIANGLE_OBJ, RT_SCENE_FORMAT_OBJ, RT_UP_Y);
    /* field by field: the struct has padding, which nothing sets */
    const rt_camera *ca = &a.camera, *cb = &b.camera;
    ck_assert(memcmp(&ca->observer, &cb->observer, sizeof ca->observer) == 0 &&
              memcmp(&ca->screen_center, &cb->screen_center,
                     sizeof ca->screen_center) == 0 &&
              memcmp(&ca->right, &cb->right, sizeof ca->right) == 0 &&
              memcmp(&ca->up, &cb->up, sizeof ca->up) == 0 &&
              ca->width == cb->width && ca->height == cb->height &&
              ca->b_was_projected == cb->b_was_projected &&
              memcmp(&ca->aperture, &cb->aperture, sizeof ca->aperture) == 0 &&
              memcmp(&ca->focal_distance, &cb->focal_distance,
                     sizeof ca->focal_distance) == 0);
    /* the view from (0.5, 0.5, 1): observer to the right, above, in front */
    rt_vec3 d = {a.camera.observer.x - a.camera.screen_center.x,
                 a.camera.observer.y - a.camera.screen_center.y,
                 a.camera.observer.z - a.camera.screen_center.z};
    ck_assert_double_eq_tol(d.x / d.z, 0.5, 1e-9);
    ck_assert_double_eq_tol(d.y / d.z, 0.5, 1e-9);
    /* +z up: from the right (+x), above (+z), in front (-y) */
    rt_scene_info z = up_of(TRIANGLE_OBJ, RT_SCENE_FORMAT_OBJ, RT_UP_Z);
    d = (rt_vec3){z.camera.observer.x - z.camera.screen_center.x,
                  z.camera.observer.y - z.camera.screen_center.y,
                  z.camera.observer.z - z.camera.screen_center.z};
    ck_assert_double_eq_tol(d.x / -d.y, 0.5, 1e-9);
    ck_assert_double_eq_tol(d.z / -d.y, 0.5, 1e-9);
}
END_TEST

/* ------------------------------------------------------------------ */
/* The programs                                                         */

START_TEST(programs_take_up_axis_and_say_which_up_they_took)
{
    char *dir = rt_test_temp_dir();
    rt_test_write_file(rt_test_in_dir(dir, "m.obj"), "# Z-up\n" TRIANGLE_OBJ);
    const char *check[] = {"m.obj", "--check", NULL};
    rt_test_output out = rt_test_run(dir, RT_EXPORT_PATH, check);
    ck_assert_msg(out.code == 0, "%s", out.err);
    ck_assert_msg(strstr(out.out, "  up axis    +z up (from the comment on "
                                  "line 1)") != NULL, "%s", out.out);
    rt_test_output_free(&out);
    const char *given[] = {"m.obj", "--check", "--up-axis", "-x", NULL};
    out = rt_test_run(dir, RT_EXPORT_PATH, given);
    ck_assert_msg(out.code == 0, "%s", out.err);
    ck_assert_msg(strstr(out.out, "up axis    -x up (--up-axis)") != NULL,
                  "%s", out.out);
    rt_test_output_free(&out);
    const char *render[] = {"m.obj", "-o", "m.ppm", "--size", "8x8", NULL};
    out = rt_test_run(dir, RT_EXPORT_PATH, render);
    ck_assert_msg(out.code == 0, "%s", out.err);
    ck_assert_str_eq(out.err, "rt-export: m.obj: note: automatic camera with "
                              "+z up (from the comment on line 1); "
                              "--up-axis picks another\n");
    rt_test_output_free(&out);
    const char *quiet[] = {"m.obj", "-q", "-o", "m.ppm", "--size", "8x8",
                           NULL};
    out = rt_test_run(dir, RT_EXPORT_PATH, quiet);
    ck_assert_str_eq(out.err, "");
    rt_test_output_free(&out);
    const char *bad[] = {"m.obj", "--up-axis", "w", NULL};
    out = rt_test_run(dir, RT_EXPORT_PATH, bad);
    ck_assert_int_eq(out.code, 2);
    ck_assert_msg(strstr(out.err, "up-axis") != NULL, "%s", out.err);
    rt_test_output_free(&out);
    const char *convert[] = {"m.obj", "m.scn", "--up-axis", "y", NULL};
    out = rt_test_run(dir, RT_CONVERT_PATH, convert);
    ck_assert_msg(out.code == 0, "%s", out.err);
    ck_assert_msg(strstr(out.err, "+y up (--up-axis)") != NULL, "%s",
                  out.err);
    rt_test_output_free(&out);
    rt_test_remove_dir(dir);
}
END_TEST

static Suite *mesh_normals_suite(void)
{
    Suite *s = suite_create("mesh_normals");
    TCase *c = tcase_create("obj");
    tcase_add_test(c, each_face_form_gives_each_corner_its_normal);
    tcase_add_test(
        c, a_cube_with_a_normal_per_face_has_24_vertices_and_its_geometry);
    tcase_add_test(c, a_smooth_octahedron_shares_its_vertices);
    tcase_add_test(c,
                   a_face_with_a_corner_without_normal_is_flat_and_cut_alike);
    tcase_add_test(c, faces_read_before_a_vn_keep_their_vertices_flat);
    tcase_add_test(
        c, zero_and_non_finite_normals_warn_once_and_their_faces_are_flat);
    tcase_add_test(
        c, a_file_without_normals_gives_its_own_vertices_and_same_render);
    tcase_add_test(c, mtl_ks_ns_and_illum_give_the_highlight);
    tcase_set_timeout(c, 60);
    suite_add_tcase(s, c);
    c = tcase_create("ply");
    tcase_add_test(c, ply_normals_ascii_and_binary_are_the_vertices_normals);
    suite_add_tcase(s, c);
    c = tcase_create("up");
    tcase_add_test(c,
                   the_up_axis_comes_from_a_comment_an_exporter_or_the_option);
    tcase_add_test(c, the_default_up_gives_the_camera_of_every_earlier_release);
    tcase_add_test(c, programs_take_up_axis_and_say_which_up_they_took);
    tcase_set_timeout(c, 60);
    suite_add_tcase(s, c);
    return s;
}

RT_CHECK_MAIN(mesh_normals_suite)
