/*
 * test_ply.c - the PLY reader (docs/formats.md, section PLY): the same
 * mesh written as ASCII and as binary in both byte orders renders byte for
 * byte as its OBJ; polygons are cut as OBJ's are; list types, skipped
 * elements and properties, colours and normals; every header rule with
 * its line and column, a truncated body with its byte offset; a count the
 * file cannot hold refused before anything is allocated for it; the
 * cancellation flag; an unknown extension refused with the formats listed,
 * in the library and the programs; rt-convert's .scn rendering as the PLY
 * does.  Every file is generated here.
 */
#include <check.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>

#include "formats/reader.h"
#include "testutil.h"
#include "raytrace/raytrace.h"

/* ------------------------------------------------------------------ */
/* Files                                                                */

typedef struct blob {
    unsigned char *data;
    size_t length, capacity;
} blob;

static void put(blob *b, const void *bytes, size_t n)
{
    if (b->length + n > b->capacity) {
        b->capacity = 2 * (b->length + n) + 64;
        b->data = realloc(b->data, b->capacity);
        ck_assert_ptr_nonnull(b->data);
    }
    memcpy(b->data + b->length, bytes, n);
    b->length += n;
}

static void put_text(blob *b, const char *text)
{
    put(b, text, strlen(text));
}

/* A value of PLY type `type` ("uchar", "int", "float"...), binary in the
 * byte order `big`, or as text followed by `separator`. */
static void put_value(blob *b, const char *type, double v, int ascii,
                      int big)
{
    if (ascii) {
        char text[64];
        snprintf(text, sizeof text, "%.17g ", v);
        put_text(b, text);
        return;
    }
    unsigned char bytes[8];
    size_t n;
    if (strcmp(type, "uint8") == 0 || strcmp(type, "int8") == 0)
        type = "uchar";
    if (strcmp(type, "uint32") == 0 || strcmp(type, "int32") == 0)
        type = "int";
    if (strcmp(type, "uchar") == 0 || strcmp(type, "char") == 0) {
        bytes[0] = (unsigned char)(int)v;
        n = 1;
    } else if (strcmp(type, "ushort") == 0 || strcmp(type, "short") == 0) {
        unsigned short s = (unsigned short)(int)v;
        memcpy(bytes, &s, 2);
        n = 2;
    } else if (strcmp(type, "int") == 0 || strcmp(type, "uint") == 0) {
        unsigned u = (unsigned)(long long)v;
        memcpy(bytes, &u, 4);
        n = 4;
    } else if (strcmp(type, "float") == 0) {
        float f = (float)v;
        memcpy(bytes, &f, 4);
        n = 4;
    } else {
        memcpy(bytes, &v, 8);
        n = 8;
    }
    static const unsigned short one = 1;
    int little = *(const unsigned char *)&one == 1;
    if (big == little)
        for (size_t i = 0; i < n / 2; i++) {
            unsigned char t = bytes[i];
            bytes[i] = bytes[n - 1 - i];
            bytes[n - 1 - i] = t;
        }
    put(b, bytes, n);
}

/* The test mesh: a square, a triangle above it, a concave pentagon. */
static const double mesh_vertices[][3] = {
    {0, 0, 0},        {1, 0, 0},     {1, 1, 0},       {0, 1, 0},
    {0.5, 0.5, 0.75}, {1.5, 0, 0.25}, {2, 1, 0.125},  {1.75, 0.5, 0.25}};
static const int mesh_faces[][6] = {{4, 0, 1, 2, 3},
                                    {3, 0, 1, 4},
                                    {5, 1, 5, 6, 7, 2}};
#define MESH_VERTICES 8
#define MESH_FACES 3

static const char mesh_obj[] =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 0.75\nv 1.5 0 0.25\n"
    "v 2 1 0.125\nv 1.75 0.5 0.25\nf 1 2 3 4\nf 1 2 5\nf 2 6 7 8 3\n";

static const char *const format_names[] = {"ascii", "binary_little_endian",
                                           "binary_big_endian"};

/* The mesh as a PLY of `format` (0 ASCII, 1 little, 2 big endian), its
 * lists of `count_type` counts and `index_type` indices; `extra` adds
 * properties and elements that must be skipped. */
static blob mesh_ply(int format, const char *count_type,
                     const char *index_type, int extra)
{
    blob b = {0};
    char line[256];
    int ascii = format == 0, big = format == 2;
    snprintf(line, sizeof line, "ply\nformat %s 1.0\ncomment test mesh\n",
             format_names[format]);
    put_text(&b, line);
    if (extra)
        put_text(&b, "element material 2\nproperty uchar ambient\n"
                     "property list uchar float weights\n");
    snprintf(line, sizeof line, "element vertex %d\nproperty float x\n",
             MESH_VERTICES);
    put_text(&b, line);
    if (extra)
        put_text(&b, "property float confidence\n");
    put_text(&b, "property float y\nproperty float z\n");
    if (extra)
        put_text(&b, "property uchar intensity\n");
    snprintf(line, sizeof line, "element face %d\n", MESH_FACES);
    put_text(&b, line);
    if (extra)
        put_text(&b, "property list uchar float texcoord\n");
    snprintf(line, sizeof line, "property list %s %s vertex_indices\n",
             count_type, index_type);
    put_text(&b, line);
    if (extra)
        put_text(&b, "element edge 1\nproperty int vertex1\n"
                     "property int vertex2\n");
    put_text(&b, "end_header\n");
    if (extra)
        for (int i = 0; i < 2; i++) {
            put_value(&b, "uchar", 7, ascii, big);
            put_value(&b, "uchar", 2, ascii, big);
            put_value(&b, "float", 0.5, ascii, big);
            put_value(&b, "float", 0.25, ascii, big);
            if (ascii)
                put_text(&b, "\n");
        }
    for (int i = 0; i < MESH_VERTICES; i++) {
        put_value(&b, "float", mesh_vertices[i][0], ascii, big);
        if (extra)
            put_value(&b, "float", 0.9, ascii, big);
        put_value(&b, "float", mesh_vertices[i][1], ascii, big);
        put_value(&b, "float", mesh_vertices[i][2], ascii, big);
        if (extra)
            put_value(&b, "uchar", 200, ascii, big);
        if (ascii)
            put_text(&b, "\n");
    }
    for (int i = 0; i < MESH_FACES; i++) {
        if (extra) {
            put_value(&b, "uchar", 2, ascii, big);
            put_value(&b, "float", 0.5, ascii, big);
            put_value(&b, "float", 0.5, ascii, big);
        }
        put_value(&b, count_type, mesh_faces[i][0], ascii, big);
        for (int j = 1; j <= mesh_faces[i][0]; j++)
            put_value(&b, index_type, mesh_faces[i][j], ascii, big);
        if (ascii)
            put_text(&b, "\n");
    }
    if (extra) {
        put_value(&b, "int", 0, ascii, big);
        put_value(&b, "int", 1, ascii, big);
        if (ascii)
            put_text(&b, "\n");
    }
    return b;
}

static rt_status parse_named(const void *data, size_t length,
                             const char *name, rt_cancel *cancel,
                             rt_scene **scene, rt_error *error)
{
    rt_load_options options;
    rt_load_options_init(&options);
    options.width = options.height = 48;
    options.cancel = cancel;
    memset(error, 0, sizeof *error);
    *scene = NULL;
    return rt_scene_parse(data, length, name, &options, scene, error);
}

static rt_scene *load_ply(const blob *b)
{
    rt_scene *scene;
    rt_error error;
    rt_status status = parse_named(b->data, b->length, "t.ply", NULL, &scene,
                                   &error);
    ck_assert_msg(status == RT_OK, "%s", error.message);
    return scene;
}

/* The message of the refusal of `text` (a PLY named t.ply), whose status
 * must be `status`. */
static const char *refusal(const void *text, size_t length, rt_status status)
{
    static rt_error error;
    rt_scene *scene;
    rt_status got = parse_named(text, length, "t.ply", NULL, &scene, &error);
    ck_assert_msg(got == status, "status %s, expected %s: %s",
                  rt_status_string(got), rt_status_string(status),
                  error.message);
    ck_assert_ptr_null(scene);
    return error.message;
}

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
    ck_assert_int_eq(parse_named(mesh_obj, strlen(mesh_obj), "t.obj", NULL,
                                 &obj, &error),
                     RT_OK);
    /* the square and the pentagon are cut: 2 + 1 + 3 facets */
    ck_assert_int_eq(rt_test_scene_info(obj).facet_count, 6);
    for (int format = 0; format < 3; format++) {
        blob b = mesh_ply(format, "uchar", "int", 0);
        rt_scene *ply = load_ply(&b);
        assert_same_facets(ply, obj);
        assert_same_render(ply, obj, format_names[format]);
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
    blob first = mesh_ply(1, "uchar", "int", 0);
    rt_scene *expected = load_ply(&first);
    for (int format = 0; format < 3; format++)
        for (size_t i = 0; i < sizeof counts / sizeof counts[0]; i++) {
            blob b = mesh_ply(format, counts[i], indices[i], 0);
            rt_scene *scene = load_ply(&b);
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
    blob plain = mesh_ply(0, "uchar", "int", 0);
    rt_scene *expected = load_ply(&plain);
    for (int format = 0; format < 3; format++) {
        blob b = mesh_ply(format, "uchar", "int", 1);
        rt_scene *scene = load_ply(&b);
        assert_same_facets(scene, expected);
        assert_same_render(scene, expected, format_names[format]);
        /* one warning for each skipped element, one for each element's
         * skipped properties */
        ck_assert_int_eq(rt_test_count_warnings(scene, "`material` (2 "
                                                       "items) is not read"),
                         1);
        ck_assert_int_eq(rt_test_count_warnings(scene, "`edge` (1 items) "
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
    ck_assert_msg(parse_named(text, strlen(text), "t.ply", NULL, &scene,
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

START_TEST(ply_normals_are_read_and_ignored_with_one_warning)
{
    static const char text[] = TRIANGLE_HEADER(
        "property float nx\nproperty float ny\nproperty float nz\n", "")
        "0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n";
    rt_scene *scene;
    rt_error error;
    ck_assert_int_eq(parse_named(text, strlen(text), "t.ply", NULL, &scene,
                                 &error),
                     RT_OK);
    ck_assert_int_eq(rt_test_scene_info(scene).warning_count, 1);
    ck_assert_int_eq(rt_test_count_warnings(scene, "the vertex normals (nx, "
                                                   "ny, nz) are ignored"),
                     1);
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
        ck_assert_str_eq(refusal(cases[i].text, strlen(cases[i].text),
                                 cases[i].status),
                         cases[i].message);
}
END_TEST

START_TEST(ply_a_header_without_end_in_binary_data_says_so)
{
    static const char text[] = "ply\nformat binary_little_endian 1.0\n"
                               "element vertex 1\n\0\0\0\1";
    ck_assert_str_eq(refusal(text, sizeof text - 1, RT_ERR_SYNTAX),
                     "t.ply:4:1: expected `end_header`, found a NUL byte "
                     "(binary data)");
}
END_TEST

START_TEST(ply_a_truncated_binary_body_gives_its_byte_offset)
{
    /* A claim the bytes left cannot hold is refused at the element's
     * declaration: 8 vertices of 12 bytes in 50 bytes. */
    blob b = mesh_ply(1, "uchar", "int", 0);
    size_t header = (size_t)(strstr((char *)b.data, "end_header\n") -
                             (char *)b.data) + 11;
    ck_assert_str_eq(refusal(b.data, header + 50, RT_ERR_SYNTAX),
                     "t.ply:4:9: expected a count the file can hold, found "
                     "8 items of `vertex` in 50 bytes left of the file");
    /* Lists longer than their least: 3 faces of 13 bytes at least, 51 in
     * all; 45 bytes hold the first two faces, not the third's 5 corners. */
    char expected[200];
    snprintf(expected, sizeof expected,
             "t.ply: byte %zu: expected the count of the vertices of face 2, "
             "which the rest of the file can hold, found 5",
             header + 96 + 17 + 13);
    ck_assert_str_eq(refusal(b.data, header + 96 + 45, RT_ERR_SYNTAX),
                     expected);
    free(b.data);
    /* A value past the end: a quad's 17 bytes, then its flags byte. */
    blob q = {0};
    put_text(&q, "ply\nformat binary_little_endian 1.0\nelement vertex 4\n"
                 "property float x\nproperty float y\nproperty float z\n"
                 "element face 1\nproperty list uchar int vertex_indices\n"
                 "property uchar flags\nend_header\n");
    header = q.length;
    for (int i = 0; i < 12; i++)
        put_value(&q, "float", i == 3 || i == 7 || i == 10 ? 1 : 0, 0, 0);
    put_value(&q, "uchar", 4, 0, 0);
    for (int i = 0; i < 4; i++)
        put_value(&q, "int", i, 0, 0);
    snprintf(expected, sizeof expected,
             "t.ply: byte %zu: expected the property `flags` (uchar) of "
             "face 0, found the end of the file", header + 48 + 17);
    ck_assert_str_eq(refusal(q.data, q.length, RT_ERR_SYNTAX), expected);
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
         "t.ply:7:9: expected a count the file can hold, found 1 items of "
         "`face` in 0 bytes left of the file"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char text[512];
        snprintf(text, sizeof text, "%s%s", TRIANGLE_HEADER("", ""),
                 cases[i].body);
        ck_assert_str_eq(refusal(text, strlen(text), cases[i].status),
                         cases[i].message);
    }
}
END_TEST

START_TEST(ply_an_index_out_of_range_in_binary_gives_its_byte)
{
    blob b = {0};
    put_text(&b, "ply\nformat binary_big_endian 1.0\nelement vertex 3\n"
                 "property double x\nproperty double y\nproperty double z\n"
                 "element face 1\nproperty list uchar uint vertex_indices\n"
                 "end_header\n");
    size_t header = b.length;
    for (int i = 0; i < 9; i++)
        put_value(&b, "double", i == 3 || i == 7, 0, 1);
    put_value(&b, "uchar", 3, 0, 1);
    put_value(&b, "uint", 0, 0, 1);
    put_value(&b, "uint", 7, 0, 1);
    put_value(&b, "uint", 1, 0, 1);
    char expected[200];
    snprintf(expected, sizeof expected,
             "t.ply: byte %zu: expected a vertex index in 0..2 for face 0, "
             "found 7", header + 72 + 1 + 4);
    ck_assert_str_eq(refusal(b.data, b.length, RT_ERR_RANGE), expected);
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
    ck_assert_int_eq(parse_named(copy, strlen(copy), "t.ply", NULL, &scene,
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
    ck_assert_str_eq(refusal(binary, sizeof binary - 1, RT_ERR_SYNTAX),
                     "t.ply:3:9: expected a count the file can hold, found "
                     "1000000000 items of `vertex` in 12 bytes left of the "
                     "file");
    static const char faces[] = "ply\nformat binary_little_endian 1.0\n"
                                "element vertex 0\nproperty float x\n"
                                "property float y\nproperty float z\n"
                                "element face 900000000\nproperty list "
                                "uchar int vertex_indices\nend_header\n"
                                "0123456789abcdef";
    ck_assert_str_eq(refusal(faces, sizeof faces - 1, RT_ERR_SYNTAX),
                     "t.ply:7:9: expected a count the file can hold, found "
                     "900000000 items of `face` in 16 bytes left of the "
                     "file");
    /* ASCII: 2 bytes a value at least; 3 values a vertex */
    static const char ascii[] = "ply\nformat ascii 1.0\nelement vertex 3\n"
                                "property float x\nproperty float y\n"
                                "property float z\nend_header\n"
                                "0 0 0\n0 0 0\n0 0 0";
    ck_assert_int_eq(refusal(ascii, sizeof ascii - 2, RT_ERR_SYNTAX)[0], 't');
    rt_scene *scene;
    rt_error error;
    ck_assert_int_eq(parse_named(ascii, sizeof ascii - 1, "t.ply", NULL,
                                 &scene, &error),
                     RT_OK);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(ply_a_raised_flag_cancels_the_load)
{
    rt_cancel *cancel;
    ck_assert_int_eq(rt_cancel_create(&cancel, NULL), RT_OK);
    blob b = mesh_ply(1, "uchar", "int", 0);
    rt_scene *scene;
    rt_error error;
    rt_cancel_request(cancel);
    ck_assert_int_eq(parse_named(b.data, b.length, "t.ply", cancel, &scene,
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
    ck_assert_int_eq(parse_named(t.data, t.length, "t.ply", cancel, &scene,
                                 &error),
                     RT_OK);
    ck_assert_int_eq(rt_test_scene_info(scene).facet_count, 0);
    rt_scene_destroy(scene);
    free(t.data);
    free(b.data);
    rt_cancel_destroy(cancel);
}
END_TEST

/* ------------------------------------------------------------------ */
/* Names and programs                                                   */

START_TEST(an_unknown_extension_is_refused_with_the_formats_listed)
{
    rt_scene *scene;
    rt_error error;
    static const char scn[] = "0 0 10\n0 0 5 4 0 5 8 8\n0\n0\n0 0 0\n"
                              "0 0 4 255 255 255\n";
    char *dir = rt_test_temp_dir();
    rt_test_path txt = rt_test_path_at(dir, "scene.txt");
    rt_test_path bare = rt_test_path_at(dir, "scene");
    rt_test_write_file(txt.s, scn);
    rt_test_write_file(bare.s, scn);
    ck_assert_int_eq(rt_scene_load(txt.s, NULL, &scene, &error),
                     RT_ERR_FORMAT);
    ck_assert_msg(strstr(error.message, "/scene.txt: cannot tell the scene "
                                        "format: expected the extension "
                                        ".scn, .nff, .obj or .ply (or give "
                                        "the format: --input-format)") !=
                      NULL,
                  "%s", error.message);
    /* a file without an extension is read as .scn, as it always was; so is
     * text in memory whatever its name (a label there) */
    ck_assert_int_eq(rt_scene_load(bare.s, NULL, &scene, &error), RT_OK);
    rt_scene_destroy(scene);
    ck_assert_int_eq(parse_named(scn, strlen(scn), "scene 1.5 (text)", NULL,
                                 &scene, &error),
                     RT_OK);
    rt_scene_destroy(scene);
    rt_scene_format format;
    ck_assert_int_eq(rt_scene_format_from_path("a/b.PLY", &format, NULL),
                     RT_OK);
    ck_assert_int_eq(format, RT_SCENE_FORMAT_PLY);
    ck_assert_str_eq(rt_scene_format_name(RT_SCENE_FORMAT_PLY), "ply");
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(rt_export_renders_a_ply_as_its_conversion_to_scn)
{
    char *dir = rt_test_temp_dir();
    blob b = mesh_ply(2, "uchar", "int", 1);
    rt_test_write_bytes(rt_test_in_dir(dir, "m.ply"), b.data, b.length);
    rt_test_write_file(rt_test_in_dir(dir, "m.txt"), mesh_obj);
    const char *convert[] = {"m.ply", "m.scn", NULL};
    rt_test_output out = rt_test_run(dir, RT_CONVERT_PATH, convert);
    ck_assert_msg(out.code == 0, "%s", out.err);
    rt_test_output_free(&out);
    const char *direct[] = {"m.ply", "-o", "a.ppm", NULL};
    const char *converted[] = {"m.scn", "-o", "b.ppm", NULL};
    out = rt_test_run(dir, RT_EXPORT_PATH, direct);
    ck_assert_msg(out.code == 0, "%s", out.err);
    rt_test_output_free(&out);
    out = rt_test_run(dir, RT_EXPORT_PATH, converted);
    ck_assert_msg(out.code == 0, "%s", out.err);
    rt_test_output_free(&out);
    size_t na, nb;
    char *a = rt_test_read_file(rt_test_in_dir(dir, "a.ppm"), &na);
    char *c = rt_test_read_file(rt_test_in_dir(dir, "b.ppm"), &nb);
    ck_assert_uint_eq(na, nb);
    ck_assert_uint_gt(na, 100);
    ck_assert_int_eq(memcmp(a, c, na), 0);
    free(a);
    free(c);
    /* an unknown extension: both programs list the formats */
    const char *unknown_export[] = {"m.txt", "-o", "c.ppm", NULL};
    const char *unknown_convert[] = {"m.txt", "c.scn", NULL};
    const char *programs[] = {RT_EXPORT_PATH, RT_CONVERT_PATH};
    const char *const *args[] = {unknown_export, unknown_convert};
    for (int i = 0; i < 2; i++) {
        out = rt_test_run(dir, programs[i], args[i]);
        ck_assert_int_eq(out.code, 1);
        ck_assert_msg(strstr(out.err, "m.txt: cannot tell the scene format: "
                                      "expected the extension .scn, .nff, "
                                      ".obj or .ply") != NULL,
                      "%s", out.err);
        rt_test_output_free(&out);
    }
    /* --input-format reads it anyway */
    const char *forced[] = {"--input-format", "obj", "m.txt", "-o", "c.ppm",
                            NULL};
    out = rt_test_run(dir, RT_EXPORT_PATH, forced);
    ck_assert_msg(out.code == 0, "%s", out.err);
    rt_test_output_free(&out);
    free(b.data);
    rt_test_remove_dir(dir);
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
    tcase_add_test(t, ply_normals_are_read_and_ignored_with_one_warning);
    tcase_add_test(t, ply_header_errors_give_their_line_and_column);
    tcase_add_test(t, ply_a_header_without_end_in_binary_data_says_so);
    tcase_add_test(t, ply_a_truncated_binary_body_gives_its_byte_offset);
    tcase_add_test(t, ply_ascii_body_errors_give_their_line_and_column);
    tcase_add_test(t, ply_an_index_out_of_range_in_binary_gives_its_byte);
    tcase_add_test(t, ply_degenerate_faces_are_left_out_with_counted_warnings);
    tcase_add_test(t,
                   ply_a_count_the_file_cannot_hold_is_refused_without_allocating);
    tcase_add_test(t, ply_a_raised_flag_cancels_the_load);
    tcase_add_test(t, an_unknown_extension_is_refused_with_the_formats_listed);
    tcase_add_test(t, rt_export_renders_a_ply_as_its_conversion_to_scn);
    suite_add_tcase(s, t);
    return s;
}

RT_CHECK_MAIN(ply_suite)
