/*
 * test_ply.c - the PLY reader (docs/formats.md, section PLY): the same
 * mesh written as ASCII and as binary in both byte orders renders byte for
 * byte as its OBJ; polygons are cut as OBJ's are; list types, skipped
 * elements and properties, colours and normals; every header rule with
 * its line and column, a truncated body with its byte offset; a count the
 * file cannot hold refused before anything is allocated for it; the
 * cancellation flag.  Every file is generated here (tests/ply_files.c);
 * names and programs: tests/test_ply_programs.c.
 */
#include <check.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>

#include "formats/reader.h"
#include "ply_files.h"
#include "testutil.h"
#include "raytrace/raytrace.h"

/* ------------------------------------------------------------------ */
/* Checks                                                               */

static void assert_same_render(const rt_scene *a, const rt_scene *b,
                               const char *what)
{
    rt_image x = rt_test_render(a, 3, 1), y = rt_test_render(b, 3, 1);
    ck_assert_msg(rt_test_image_diff(&x, &y, NULL) == 0,
                  "%s: the images differ", what);
    rt_image_release(&x);
    rt_image_release(&y);
}

/* Whether the facets of two scenes are the same corners in the same
 * order. */
static void assert_same_facets(const rt_scene *a, const rt_scene *b)
{
    rt_scene_info ia = rt_test_scene_info(a), ib = rt_test_scene_info(b);
    ck_assert_int_eq(ia.facet_count, ib.facet_count);
    ck_assert_int_eq(ia.vertex_count, ib.vertex_count);
    for (int i = 0; i < ia.facet_count; i++) {
        rt_facet_info fa = {.size = sizeof fa}, fb = {.size = sizeof fb};
        rt_scene_facet(a, i, &fa);
        rt_scene_facet(b, i, &fb);
        for (int j = 0; j < 3; j++)
            ck_assert_int_eq(fa.vertex[j], fb.vertex[j]);
        ck_assert_int_eq(fa.color.r, fb.color.r);
    }
}

/* ------------------------------------------------------------------ */
/* The same mesh in every form                                          */

START_TEST(ply_ascii_and_both_byte_orders_render_as_the_same_obj)
{
    rt_scene *obj;
    rt_error error;
    ck_assert_int_eq(ply_parse_named(ply_mesh_obj, strlen(ply_mesh_obj), "t.obj", NULL,
                                 &obj, &error),
                     RT_OK);
    /* the square and the pentagon are cut: 2 + 1 + 3 facets */
    ck_assert_int_eq(rt_test_scene_info(obj).facet_count, 6);
    for (int format = 0; format < 3; format++) {
        ply_blob b = ply_mesh(format, "uchar", "int", 0);
        rt_scene *ply = ply_load(&b);
        assert_same_facets(ply, obj);
        assert_same_render(ply, obj, ply_format_names[format]);
        ck_assert_int_eq(rt_test_scene_info(ply).warning_count, 0);
        rt_scene_destroy(ply);
        free(b.data);
    }
    rt_scene_destroy(obj);
}
END_TEST

START_TEST(ply_lists_of_any_integer_types_read_the_same_faces)
{
    static const char *const counts[] = {"uchar", "char", "ushort", "int",
                                         "uint8", "int32"};
    static const char *const indices[] = {"int", "uint", "ushort", "short",
                                          "uchar", "uint32"};
    ply_blob first = ply_mesh(1, "uchar", "int", 0);
    rt_scene *expected = ply_load(&first);
    for (int format = 0; format < 3; format++)
        for (size_t i = 0; i < sizeof counts / sizeof counts[0]; i++) {
            ply_blob b = ply_mesh(format, counts[i], indices[i], 0);
            rt_scene *scene = ply_load(&b);
            assert_same_facets(scene, expected);
            rt_scene_destroy(scene);
            free(b.data);
        }
    rt_scene_destroy(expected);
    free(first.data);
}
END_TEST

START_TEST(ply_skips_the_elements_and_properties_it_does_not_read)
{
    ply_blob plain = ply_mesh(0, "uchar", "int", 0);
    rt_scene *expected = ply_load(&plain);
    for (int format = 0; format < 3; format++) {
        ply_blob b = ply_mesh(format, "uchar", "int", 1);
        rt_scene *scene = ply_load(&b);
        assert_same_facets(scene, expected);
        assert_same_render(scene, expected, ply_format_names[format]);
        /* one warning for each skipped element, one for each element's
         * skipped properties */
        ck_assert_int_eq(rt_test_count_warnings(scene, "`material` (2 "
                                                       "items) is not read"),
                         1);
        ck_assert_int_eq(rt_test_count_warnings(scene, "`edge` (1 item) "
                                                       "is not read"),
                         1);
        ck_assert_int_eq(rt_test_count_warnings(
                             scene, "2 properties of the element `vertex` "
                                    "are not read: `confidence`, "
                                    "`intensity`"),
                         1);
        ck_assert_int_eq(rt_test_count_warnings(
                             scene, "1 property of the element `face` is "
                                    "not read: `texcoord`"),
                         1);
        ck_assert_int_eq(rt_test_scene_info(scene).warning_count, 4);
        rt_scene_destroy(scene);
        free(b.data);
    }
    rt_scene_destroy(expected);
    free(plain.data);
}
END_TEST

/* ------------------------------------------------------------------ */
/* Colours and normals                                                  */

#define TRIANGLE_HEADER(vertex_props, face_props)                            \
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"            \
    "property float y\nproperty float z\n" vertex_props                     \
    "element face 1\nproperty list uchar int vertex_indices\n" face_props   \
    "end_header\n"

static rt_rgb8 facet_colour(const char *text)
{
    rt_scene *scene;
    rt_error error;
    ck_assert_msg(ply_parse_named(text, strlen(text), "t.ply", NULL, &scene,
                              &error) == RT_OK,
                  "%s", error.message);
    ck_assert_int_eq(rt_test_scene_info(scene).facet_count, 1);
    rt_facet_info f = {.size = sizeof f};
    rt_scene_facet(scene, 0, &f);
    rt_scene_destroy(scene);
    return f.color;
}

START_TEST(ply_a_facet_takes_the_mean_of_its_corners_colours)
{
    /* (255 + 0 + 2) / 3 = 85.67 -> 86, the same for green; (0 + 0 + 101)
     * / 3 = 33.67 -> 34; (0 + 0 + 100) / 3 = 33.33 -> 33 (rounded to the
     * nearest) */
    rt_rgb8 c = facet_colour(TRIANGLE_HEADER(
        "property uchar red\nproperty uchar green\nproperty uchar blue\n", "")
        "0 0 0 255 0 0\n1 0 0 0 255 0\n0 1 0 2 2 101\n3 0 1 2\n");
    ck_assert_int_eq(c.r, 86);
    ck_assert_int_eq(c.g, 86);
    ck_assert_int_eq(c.b, 34);
    c = facet_colour(TRIANGLE_HEADER(
        "property uchar red\nproperty uchar green\nproperty uchar blue\n", "")
        "0 0 0 0 0 0\n1 0 0 0 0 0\n0 1 0 1 1 100\n3 0 1 2\n");
    ck_assert_int_eq(c.r, 0);
    ck_assert_int_eq(c.b, 33);
    /* floating colours are 0..1 */
    c = facet_colour(TRIANGLE_HEADER(
        "property float red\nproperty float green\nproperty float blue\n", "")
        "0 0 0 1 0 0.5\n1 0 0 1 0 0.5\n0 1 0 1 0 0.5\n3 0 1 2\n");
    ck_assert_int_eq(c.r, 255);
    ck_assert_int_eq(c.g, 0);
    ck_assert_int_eq(c.b, 128);
    /* a face's own colour wins over its corners' */
    c = facet_colour(TRIANGLE_HEADER(
        "property uchar red\nproperty uchar green\nproperty uchar blue\n",
        "property uchar red\nproperty uchar green\nproperty uchar blue\n")
        "0 0 0 255 0 0\n1 0 0 0 255 0\n0 1 0 1 1 100\n3 0 1 2 9 8 7\n");
    ck_assert_int_eq(c.r, 9);
    ck_assert_int_eq(c.g, 8);
    ck_assert_int_eq(c.b, 7);
    /* without colours, OBJ's default grey */
    c = facet_colour(TRIANGLE_HEADER("", "")
                     "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    ck_assert_int_eq(c.r, 204);
    ck_assert_int_eq(c.g, 204);
    ck_assert_int_eq(c.b, 204);
}
END_TEST

START_TEST(ply_normals_are_the_vertices_normals_without_a_warning)
{
    static const char text[] = TRIANGLE_HEADER(
        "property float nx\nproperty float ny\nproperty float nz\n", "")
        "0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n";
    rt_scene *scene;
    rt_error error;
    ck_assert_int_eq(ply_parse_named(text, strlen(text), "t.ply", NULL, &scene,
                                 &error),
                     RT_OK);
    ck_assert_int_eq(rt_test_scene_info(scene).warning_count, 0);
    ck_assert_int_eq(rt_test_scene_info(scene).smooth_facet_count, 1);
    rt_scene_destroy(scene);
}
END_TEST

/* ------------------------------------------------------------------ */
/* Refusals and warnings with their places                              */

START_TEST(ply_header_errors_give_their_line_and_column)
{
    static const struct {
        const char *text;
        rt_status status;
        const char *message;
    } cases[] = {
        {"plx\n", RT_ERR_FORMAT,
         "t.ply:1:1: expected `ply` (the first line of a PLY file), found "
         "`plx`"},
        {"", RT_ERR_FORMAT,
         "t.ply:1:1: expected `ply` (the first line of a PLY file), found "
         "the end of the file"},
        {"ply\nformat ascii 2.0\n", RT_ERR_FORMAT,
         "t.ply:2:14: expected the version `1.0`, found `2.0`"},
        {"ply\nformat binary 1.0\n", RT_ERR_FORMAT,
         "t.ply:2:8: expected `ascii`, `binary_little_endian` or "
         "`binary_big_endian`, found `binary`"},
        {"ply\nformat ascii 1.0\nelement vertex 3\nproperty foo x\n",
         RT_ERR_SYNTAX,
         "t.ply:4:10: expected a property type (char, uchar, short, ushort, "
         "int, uint, float, double, int8, uint8, int16, uint16, int32, "
         "uint32, float32 or float64) or `list`, found `foo`"},
        {"ply\nformat ascii 1.0\nproperty float x\n", RT_ERR_SYNTAX,
         "t.ply:3:1: expected an `element` line before its properties, "
         "found `property`"},
        {"ply\nformat ascii 1.0\nelement vertex\n", RT_ERR_SYNTAX,
         "t.ply:3:15: expected the element's count, found the end of the "
         "line"},
        {"ply\nformat ascii 1.0\nelement vertex -3\n", RT_ERR_SYNTAX,
         "t.ply:3:16: expected the element's count (a whole number), found "
         "`-3`"},
        {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
         "property float x\n",
         RT_ERR_SYNTAX,
         "t.ply:5:16: expected a property name not declared before in its "
         "element, found `x`"},
        {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
         "property float y\nend_header\n",
         RT_ERR_SYNTAX,
         "t.ply:3:9: expected the properties `x`, `y` and `z` of the element "
         "`vertex`, found no `z`"},
        {"ply\nformat ascii 1.0\nelement face 1\nproperty int "
         "vertex_indices\n",
         RT_ERR_SYNTAX,
         "t.ply:4:14: expected the vertex indices as a list (`property list "
         "uchar int vertex_indices`), found `vertex_indices`"},
        {"ply\nformat ascii 1.0\nelement face 1\nproperty list float int "
         "vertex_indices\n",
         RT_ERR_SYNTAX,
         "t.ply:4:15: expected an integer type for the list's count, found "
         "`float`"},
        {"ply\nformat ascii 1.0\nelement face 1\nproperty list uchar float "
         "vertex_indices\n",
         RT_ERR_SYNTAX,
         "t.ply:4:27: expected vertex indices of an integer type, found "
         "`vertex_indices`"},
        {"ply\nformat ascii 1.0\nelement face 0\nelement vertex 0\n",
         RT_ERR_SYNTAX,
         "t.ply:4:9: expected the element `vertex` before the element "
         "`face` (the faces refer to the vertices), found `vertex`"},
        {"ply\nformat ascii 1.0\nelement face 1\nend_header\n",
         RT_ERR_SYNTAX,
         "t.ply:3:9: expected a list `vertex_indices` in the element `face`, "
         "found none"},
        {"ply\nelement vertex 0\nend_header\n", RT_ERR_SYNTAX,
         "t.ply:3:1: expected a `format` line before `end_header`, found "
         "`end_header`"},
        {"ply\nformat ascii 1.0\nvertex 3\n", RT_ERR_SYNTAX,
         "t.ply:3:1: expected a header line (`format`, `comment`, "
         "`obj_info`, `element`, `property` or `end_header`), found "
         "`vertex`"},
        {"ply\nformat ascii 1.0\nelement vertex 3\n", RT_ERR_SYNTAX,
         "t.ply:4:1: expected `end_header`, found the end of the file"},
        {"ply\nformat ascii 1.0\nelement vertex 3000000000\n", RT_ERR_LIMIT,
         "t.ply:3:16: expected a count of at most 1073741823, found "
         "`3000000000`"},
        {"ply\nformat ascii 1.0\nformat ascii 1.0\n", RT_ERR_SYNTAX,
         "t.ply:3:1: expected one `format` line, and this is a second, "
         "found `format`"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
        ck_assert_str_eq(ply_refusal(cases[i].text, strlen(cases[i].text),
                                 cases[i].status),
                         cases[i].message);
}
END_TEST

START_TEST(ply_a_header_without_end_in_binary_data_says_so)
{
    static const char text[] = "ply\nformat binary_little_endian 1.0\n"
                               "element vertex 1\n\0\0\0\1";
    ck_assert_str_eq(ply_refusal(text, sizeof text - 1, RT_ERR_SYNTAX),
                     "t.ply:4:1: expected `end_header`, found a NUL byte "
                     "(binary data)");
}
END_TEST

START_TEST(ply_a_truncated_binary_body_gives_its_byte_offset)
{
    /* A claim the bytes left cannot hold is refused at the element's
     * declaration: 8 vertices of 12 bytes in 50 bytes. */
    ply_blob b = ply_mesh(1, "uchar", "int", 0);
    size_t header = (size_t)(strstr((char *)b.data, "end_header\n") -
                             (char *)b.data) + 11;
    ck_assert_str_eq(ply_refusal(b.data, header + 50, RT_ERR_SYNTAX),
                     "t.ply:4:9: expected a count the file can hold, found "
                     "8 items of `vertex` in 50 bytes left of the file");
    /* Lists longer than their least: 3 faces of 13 bytes at least, 51 in
     * all; 45 bytes hold the first two faces, not the third's 5 corners. */
    char expected[200];
    snprintf(expected, sizeof expected,
             "t.ply: byte %zu: expected the count of the vertices of face 2, "
             "which the rest of the file can hold, found 5",
             header + 96 + 17 + 13);
    ck_assert_str_eq(ply_refusal(b.data, header + 96 + 45, RT_ERR_SYNTAX),
                     expected);
    free(b.data);
    /* A value past the end: a quad's 17 bytes, then its flags byte. */
    ply_blob q = {0};
    ply_put_text(&q, "ply\nformat binary_little_endian 1.0\nelement vertex 4\n"
                 "property float x\nproperty float y\nproperty float z\n"
                 "element face 1\nproperty list uchar int vertex_indices\n"
                 "property uchar flags\nend_header\n");
    header = q.length;
    for (int i = 0; i < 12; i++)
        ply_put_value(&q, "float", i == 3 || i == 7 || i == 10 ? 1 : 0, 0, 0);
    ply_put_value(&q, "uchar", 4, 0, 0);
    for (int i = 0; i < 4; i++)
        ply_put_value(&q, "int", i, 0, 0);
    snprintf(expected, sizeof expected,
             "t.ply: byte %zu: expected the property `flags` (uchar) of "
             "face 0, found the end of the file", header + 48 + 17);
    ck_assert_str_eq(ply_refusal(q.data, q.length, RT_ERR_SYNTAX), expected);
    free(q.data);
}
END_TEST

START_TEST(ply_ascii_body_errors_give_their_line_and_column)
{
    static const struct {
        const char *body;
        rt_status status;
        const char *message;
    } cases[] = {
        {"0 0 0\n1 0\n0 1 0\n3 0 1 2\n", RT_ERR_SYNTAX,
         "t.ply:11:4: expected the property `z` (float) of vertex 1, found "
         "the end of the line"},
        {"0 0 0\n1 0 0\n0 1 0\n3 0 1 2 5\n", RT_ERR_SYNTAX,
         "t.ply:13:9: expected the end of the line of face 0, found `5`"},
        {"0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", RT_ERR_RANGE,
         "t.ply:13:7: expected a vertex index in 0..2 for face 0, found "
         "`3`"},
        {"0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n", RT_ERR_RANGE,
         "t.ply:13:7: expected a vertex index in 0..2 for face 0, found "
         "`-1`"},
        {"0 0 0\n1 0 0\n0 1 0\n256 0 1 2\n", RT_ERR_RANGE,
         "t.ply:13:1: expected a whole number in 0..255 for the property "
         "`vertex_indices` (uchar) of face 0, found `256`"},
        {"0 0 0\n1 0 0\n0 1 0\n3 0 1 1.5\n", RT_ERR_RANGE,
         "t.ply:13:7: expected a whole number in -2147483648..2147483647 for "
         "the property `vertex_indices` (int) of face 0, found `1.5`"},
        /* (blanks so that the bytes left can hold the face's claim) */
        {"0 0 0\n1 0 0\n0 1 0\n2 0 1    \n", RT_ERR_SYNTAX,
         "t.ply:13:1: expected at least 3 vertices for face 0, found `2`"},
        {"0 0 0\n1 0 1e200\n0 1 0\n3 0 1 2\n", RT_ERR_RANGE,
         "t.ply:11:5: expected a coordinate of magnitude at most 1e152 (the "
         "renderer's arithmetic overflows beyond) for the property `z` "
         "(float) of vertex 1, found `1e200`"},
        {"0 0 x\n1 0 0\n0 1 0\n3 0 1 2\n", RT_ERR_SYNTAX,
         "t.ply:10:5: expected a number for the property `z` (float) of "
         "vertex 0, found `x`"},
        {"0 0 0\n1 0 0\n0 1 0\n", RT_ERR_SYNTAX,
         "t.ply:7:9: expected a count the file can hold, found 1 item of "
         "`face` in 0 bytes left of the file"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char text[512];
        snprintf(text, sizeof text, "%s%s", TRIANGLE_HEADER("", ""),
                 cases[i].body);
        ck_assert_str_eq(ply_refusal(text, strlen(text), cases[i].status),
                         cases[i].message);
    }
}
END_TEST

START_TEST(ply_an_index_out_of_range_in_binary_gives_its_byte)
{
    ply_blob b = {0};
    ply_put_text(&b, "ply\nformat binary_big_endian 1.0\nelement vertex 3\n"
                 "property double x\nproperty double y\nproperty double z\n"
                 "element face 1\nproperty list uchar uint vertex_indices\n"
                 "end_header\n");
    size_t header = b.length;
    for (int i = 0; i < 9; i++)
        ply_put_value(&b, "double", i == 3 || i == 7, 0, 1);
    ply_put_value(&b, "uchar", 3, 0, 1);
    ply_put_value(&b, "uint", 0, 0, 1);
    ply_put_value(&b, "uint", 7, 0, 1);
    ply_put_value(&b, "uint", 1, 0, 1);
    char expected[200];
    snprintf(expected, sizeof expected,
             "t.ply: byte %zu: expected a vertex index in 0..2 for face 0, "
             "found 7", header + 72 + 1 + 4);
    ck_assert_str_eq(ply_refusal(b.data, b.length, RT_ERR_RANGE), expected);
    free(b.data);
}
END_TEST

START_TEST(ply_degenerate_faces_are_left_out_with_counted_warnings)
{
    static const char text[] = TRIANGLE_HEADER("", "")
        "0 0 0\n1 0 0\n2 0 0\n"
        "3 0 1 2\n3 0 1 2\n3 0 0 1\n";
    /* the header declares 1 face; declare 3 */
    char copy[sizeof text + 8];
    snprintf(copy, sizeof copy, "%s", text);
    char *count = strstr(copy, "element face 1");
    count[13] = '3';
    rt_scene *scene;
    rt_error error;
    ck_assert_int_eq(ply_parse_named(copy, strlen(copy), "t.ply", NULL, &scene,
                                 &error),
                     RT_OK);
    ck_assert_int_eq(rt_test_scene_info(scene).facet_count, 0);
    ck_assert_int_eq(rt_test_count_warnings(
                         scene, "t.ply:13:1: warning: face 0: this face has "
                                "no area (its corners are on a line) and is "
                                "left out (and 1 more like it)"),
                     1);
    ck_assert_int_eq(rt_test_count_warnings(
                         scene, "t.ply:15:1: warning: face 2: this face has "
                                "fewer than 3 distinct corners"),
                     1);
    ck_assert_int_eq(rt_test_count_warnings(scene, "no face to draw"), 1);
    rt_scene_destroy(scene);
}
END_TEST

/* ------------------------------------------------------------------ */
/* Budgets and cancellation                                             */

START_TEST(ply_a_count_the_file_cannot_hold_is_refused_without_allocating)
{
    /* With the address space limited to 256 MiB, a reader that sized its
     * arrays from the claimed counts (a billion vertices: 24 GB) would
     * report RT_ERR_NOMEM; the claim is refused from the file's size. */
#if RT_TEST_UNDER_ASAN
    printf("NOTE %s: built with AddressSanitizer, address space not "
           "limited\n", __func__);
#else
    if (!rt_test_under_valgrind()) {
        struct rlimit limit = {256UL << 20, 256UL << 20};
        if (setrlimit(RLIMIT_AS, &limit) != 0)
            printf("NOTE: setrlimit failed (%s); checking the status only\n",
                   strerror(errno));
    }
#endif
    static const char binary[] = "ply\nformat binary_little_endian 1.0\n"
                                 "element vertex 1000000000\nproperty float "
                                 "x\nproperty float y\nproperty float z\n"
                                 "end_header\n0123456789ab";
    ck_assert_str_eq(ply_refusal(binary, sizeof binary - 1, RT_ERR_SYNTAX),
                     "t.ply:3:9: expected a count the file can hold, found "
                     "1000000000 items of `vertex` in 12 bytes left of the "
                     "file");
    static const char faces[] = "ply\nformat binary_little_endian 1.0\n"
                                "element vertex 0\nproperty float x\n"
                                "property float y\nproperty float z\n"
                                "element face 900000000\nproperty list "
                                "uchar int vertex_indices\nend_header\n"
                                "0123456789abcdef";
    ck_assert_str_eq(ply_refusal(faces, sizeof faces - 1, RT_ERR_SYNTAX),
                     "t.ply:7:9: expected a count the file can hold, found "
                     "900000000 items of `face` in 16 bytes left of the "
                     "file");
    /* ASCII: 2 bytes a value at least; 3 values a vertex */
    static const char ascii[] = "ply\nformat ascii 1.0\nelement vertex 3\n"
                                "property float x\nproperty float y\n"
                                "property float z\nend_header\n"
                                "0 0 0\n0 0 0\n0 0 0";
    ck_assert_int_eq(ply_refusal(ascii, sizeof ascii - 2, RT_ERR_SYNTAX)[0], 't');
    rt_scene *scene;
    rt_error error;
    ck_assert_int_eq(ply_parse_named(ascii, sizeof ascii - 1, "t.ply", NULL,
                                 &scene, &error),
                     RT_OK);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(ply_a_raised_flag_cancels_the_load)
{
    rt_cancel *cancel;
    ck_assert_int_eq(rt_cancel_create(&cancel, NULL), RT_OK);
    ply_blob b = ply_mesh(1, "uchar", "int", 0);
    rt_scene *scene;
    rt_error error;
    rt_cancel_request(cancel);
    ck_assert_int_eq(ply_parse_named(b.data, b.length, "t.ply", cancel, &scene,
                                 &error),
                     RT_ERR_CANCELLED);
    ck_assert_ptr_null(scene);
    ck_assert_str_eq(error.message, "t.ply: the load was cancelled");
    /* A flag raised during the read (the reader called past the loader,
     * which looks at the flag first): 20 000 items of an element that is
     * skipped, the flag polled every RT_LOAD_POLL of them. */
    rt_test_text t = {0};
    rt_test_text_add(&t, "ply\nformat ascii 1.0\nelement edge 20000\n"
                         "property int a\nend_header\n");
    for (int i = 0; i < 20000; i++)
        rt_test_text_add(&t, "%d\n", i);
    rt_load_options options;
    rt_load_options_init(&options);
    options.cancel = cancel;
    ck_assert_int_eq(rt__ply_parse(t.data, t.length, "t.ply", &options,
                                   &scene, &error),
                     RT_ERR_CANCELLED);
    ck_assert_str_eq(error.message, "t.ply: the load was cancelled");
    rt_cancel_reset(cancel);
    ck_assert_int_eq(ply_parse_named(t.data, t.length, "t.ply", cancel, &scene,
                                 &error),
                     RT_OK);
    ck_assert_int_eq(rt_test_scene_info(scene).facet_count, 0);
    rt_scene_destroy(scene);
    free(t.data);
    free(b.data);
    rt_cancel_destroy(cancel);
}
END_TEST

static Suite *ply_suite(void)
{
    Suite *s = suite_create("ply");
    TCase *t = tcase_create("ply");
    tcase_set_timeout(t, 120);
    tcase_add_test(t, ply_ascii_and_both_byte_orders_render_as_the_same_obj);
    tcase_add_test(t, ply_lists_of_any_integer_types_read_the_same_faces);
    tcase_add_test(t, ply_skips_the_elements_and_properties_it_does_not_read);
    tcase_add_test(t, ply_a_facet_takes_the_mean_of_its_corners_colours);
    tcase_add_test(t, ply_normals_are_the_vertices_normals_without_a_warning);
    tcase_add_test(t, ply_header_errors_give_their_line_and_column);
    tcase_add_test(t, ply_a_header_without_end_in_binary_data_says_so);
    tcase_add_test(t, ply_a_truncated_binary_body_gives_its_byte_offset);
    tcase_add_test(t, ply_ascii_body_errors_give_their_line_and_column);
    tcase_add_test(t, ply_an_index_out_of_range_in_binary_gives_its_byte);
    tcase_add_test(t, ply_degenerate_faces_are_left_out_with_counted_warnings);
    tcase_add_test(t,
                   ply_a_count_the_file_cannot_hold_is_refused_without_allocating);
    tcase_add_test(t, ply_a_raised_flag_cancels_the_load);
    suite_add_tcase(s, t);
    return s;
}

RT_CHECK_MAIN(ply_suite)
