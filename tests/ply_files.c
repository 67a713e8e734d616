/*
 * ply_files.c - PLY files built in memory for the PLY suites, and their
 * loads (ply_files.h).
 */
#include "ply_files.h"

#include <check.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void ply_put(ply_blob *b, const void *bytes, size_t n)
{
    if (b->length + n > b->capacity) {
        b->capacity = 2 * (b->length + n) + 64;
        b->data = realloc(b->data, b->capacity);
        ck_assert_ptr_nonnull(b->data);
    }
    memcpy(b->data + b->length, bytes, n);
    b->length += n;
}

void ply_put_text(ply_blob *b, const char *text)
{
    ply_put(b, text, strlen(text));
}

/* A value of PLY type `type` ("uchar", "int", "float"...), binary in the
 * byte order `big`, or as text followed by `separator`. */
void ply_put_value(ply_blob *b, const char *type, double v, int ascii,
                      int big)
{
    if (ascii) {
        char text[64];
        snprintf(text, sizeof text, "%.17g ", v);
        ply_put_text(b, text);
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
    ply_put(b, bytes, n);
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

const char ply_mesh_obj[] =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 0.75\nv 1.5 0 0.25\n"
    "v 2 1 0.125\nv 1.75 0.5 0.25\nf 1 2 3 4\nf 1 2 5\nf 2 6 7 8 3\n";

const char *const ply_format_names[] = {"ascii", "binary_little_endian",
                                           "binary_big_endian"};

/* The mesh as a PLY of `format` (0 ASCII, 1 little, 2 big endian), its
 * lists of `count_type` counts and `index_type` indices; `extra` adds
 * properties and elements that must be skipped. */
ply_blob ply_mesh(int format, const char *count_type,
                     const char *index_type, int extra)
{
    ply_blob b = {0};
    char line[256];
    int ascii = format == 0, big = format == 2;
    snprintf(line, sizeof line, "ply\nformat %s 1.0\ncomment test mesh\n",
             ply_format_names[format]);
    ply_put_text(&b, line);
    if (extra)
        ply_put_text(&b, "element material 2\nproperty uchar ambient\n"
                     "property list uchar float weights\n");
    snprintf(line, sizeof line, "element vertex %d\nproperty float x\n",
             MESH_VERTICES);
    ply_put_text(&b, line);
    if (extra)
        ply_put_text(&b, "property float confidence\n");
    ply_put_text(&b, "property float y\nproperty float z\n");
    if (extra)
        ply_put_text(&b, "property uchar intensity\n");
    snprintf(line, sizeof line, "element face %d\n", MESH_FACES);
    ply_put_text(&b, line);
    if (extra)
        ply_put_text(&b, "property list uchar float texcoord\n");
    snprintf(line, sizeof line, "property list %s %s vertex_indices\n",
             count_type, index_type);
    ply_put_text(&b, line);
    if (extra)
        ply_put_text(&b, "element edge 1\nproperty int vertex1\n"
                     "property int vertex2\n");
    ply_put_text(&b, "end_header\n");
    if (extra)
        for (int i = 0; i < 2; i++) {
            ply_put_value(&b, "uchar", 7, ascii, big);
            ply_put_value(&b, "uchar", 2, ascii, big);
            ply_put_value(&b, "float", 0.5, ascii, big);
            ply_put_value(&b, "float", 0.25, ascii, big);
            if (ascii)
                ply_put_text(&b, "\n");
        }
    for (int i = 0; i < MESH_VERTICES; i++) {
        ply_put_value(&b, "float", mesh_vertices[i][0], ascii, big);
        if (extra)
            ply_put_value(&b, "float", 0.9, ascii, big);
        ply_put_value(&b, "float", mesh_vertices[i][1], ascii, big);
        ply_put_value(&b, "float", mesh_vertices[i][2], ascii, big);
        if (extra)
            ply_put_value(&b, "uchar", 200, ascii, big);
        if (ascii)
            ply_put_text(&b, "\n");
    }
    for (int i = 0; i < MESH_FACES; i++) {
        if (extra) {
            ply_put_value(&b, "uchar", 2, ascii, big);
            ply_put_value(&b, "float", 0.5, ascii, big);
            ply_put_value(&b, "float", 0.5, ascii, big);
        }
        ply_put_value(&b, count_type, mesh_faces[i][0], ascii, big);
        for (int j = 1; j <= mesh_faces[i][0]; j++)
            ply_put_value(&b, index_type, mesh_faces[i][j], ascii, big);
        if (ascii)
            ply_put_text(&b, "\n");
    }
    if (extra) {
        ply_put_value(&b, "int", 0, ascii, big);
        ply_put_value(&b, "int", 1, ascii, big);
        if (ascii)
            ply_put_text(&b, "\n");
    }
    return b;
}

rt_status ply_parse_named(const void *data, size_t length,
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

rt_scene *ply_load(const ply_blob *b)
{
    rt_scene *scene;
    rt_error error;
    rt_status status = ply_parse_named(b->data, b->length, "t.ply", NULL, &scene,
                                   &error);
    ck_assert_msg(status == RT_OK, "%s", error.message);
    return scene;
}

/* The message of the refusal of `text` (a PLY named t.ply), whose status
 * must be `status`. */
const char *ply_refusal(const void *text, size_t length, rt_status status)
{
    static rt_error error;
    rt_scene *scene;
    rt_status got = ply_parse_named(text, length, "t.ply", NULL, &scene, &error);
    ck_assert_msg(got == status, "status %s, expected %s: %s",
                  rt_status_string(got), rt_status_string(status),
                  error.message);
    ck_assert_ptr_null(scene);
    return error.message;
}

