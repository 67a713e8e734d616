/*
 * ply_files.h - what the PLY suites (tests/test_ply.c,
 * tests/test_ply_programs.c) share: PLY files built in memory, ASCII or
 * binary in either byte order, the test mesh as a PLY and as its OBJ, and
 * the loads and refusals they are checked with.  Compiled into each of
 * those suites (tests/ply.cmake); names start with ply_.
 */
#ifndef RAYTRACE_TEST_PLY_FILES_H
#define RAYTRACE_TEST_PLY_FILES_H

#include <stddef.h>

#include "raytrace/raytrace.h"

/* Bytes being gathered (free `data` when done). */
typedef struct ply_blob {
    unsigned char *data;
    size_t length, capacity;
} ply_blob;

void ply_put(ply_blob *b, const void *bytes, size_t n);
void ply_put_text(ply_blob *b, const char *text);

/* A value of PLY type `type` ("uchar", "int", "float", "int32"...), as
 * text followed by a blank (`ascii`), else binary in the byte order `big`
 * (non-zero: big endian). */
void ply_put_value(ply_blob *b, const char *type, double v, int ascii,
                   int big);

/* The test mesh: a square, a triangle above it, a concave pentagon; as an
 * OBJ, and as a PLY of `format` (0 ASCII, 1 little, 2 big endian), its
 * lists of `count_type` counts and `index_type` indices; `extra` adds
 * properties and elements that must be skipped. */
extern const char ply_mesh_obj[];
extern const char *const ply_format_names[];
ply_blob ply_mesh(int format, const char *count_type, const char *index_type,
                  int extra);

/* Parses `length` bytes named `name` at 48 x 48 with `cancel` (may be
 * NULL); *error zeroed first. */
rt_status ply_parse_named(const void *data, size_t length, const char *name,
                          rt_cancel *cancel, rt_scene **scene,
                          rt_error *error);

/* The scene of b (named t.ply), which must load. */
rt_scene *ply_load(const ply_blob *b);

/* The message of the refusal of `text` (named t.ply), whose status must
 * be `status` (a static buffer). */
const char *ply_refusal(const void *text, size_t length, rt_status status);

#endif /* RAYTRACE_TEST_PLY_FILES_H */
