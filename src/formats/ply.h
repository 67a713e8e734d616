/*
 * ply.h - what the PLY reader's files share (internal): the header as
 * read (ply_header.c: the format, the elements and their properties, each
 * property's part in the model) and the reader's state (ply.c: the body,
 * ASCII or binary, into the mesh).  What is read and why: docs/formats.md,
 * section PLY; the budgets: docs/robustness-input.md.
 */
#ifndef RAYTRACE_PLY_H
#define RAYTRACE_PLY_H

#include <stddef.h>

#include "base/error.h"
#include "formats/lexer.h"
#include "formats/reader.h"
#include "formats/triangulate.h"
#include "raytrace/scene.h"
#include "scene/scene_build.h"

/* The longest header read, in bytes: a header is a few lines of
 * declarations and comments; beyond this a file is no PLY a program
 * wrote, and the search for `end_header` stops. */
#define RT_PLY_MAX_HEADER_BYTES (1 << 20)
/* The most elements and properties (all elements together) a header
 * declares: a mesh has two elements of a few properties; the cap bounds
 * the header's memory (about 64 bytes a property). */
#define RT_PLY_MAX_ELEMENTS 64
#define RT_PLY_MAX_PROPERTIES 1024
/* The fewest bytes an ASCII value takes: a digit and a separator.  A
 * count of the header claims at most this many bytes a value of the
 * body, so no array sized from a count holds more than the file. */
#define RT_PLY_ASCII_VALUE_BYTES 2

/* The body's encoding. */
typedef enum ply_format {
    PLY_ASCII,
    PLY_BINARY_LE,
    PLY_BINARY_BE
} ply_format;

/* The types of a value; ply_type_size gives their sizes in bytes. */
typedef enum ply_type {
    PLY_NONE,
    PLY_INT8,
    PLY_UINT8,
    PLY_INT16,
    PLY_UINT16,
    PLY_INT32,
    PLY_UINT32,
    PLY_FLOAT32,
    PLY_FLOAT64
} ply_type;

/* What a property is to the model. */
typedef enum ply_role {
    ROLE_NONE,                  /* skipped */
    ROLE_X, ROLE_Y, ROLE_Z,     /* a vertex's position */
    ROLE_NX, ROLE_NY, ROLE_NZ,  /* a vertex's normal */
    ROLE_RED, ROLE_GREEN, ROLE_BLUE, /* a vertex's or a face's colour */
    ROLE_CORNERS                /* a face's list of vertex indices */
} ply_role;

typedef struct ply_property {
    ply_type type;              /* of the value, or of a list's items */
    ply_type count_type;        /* PLY_NONE: not a list */
    ply_role role;
    rt_token name;              /* in the header, for messages */
} ply_property;

/* What an element is to the model. */
typedef enum ply_kind {
    KIND_OTHER,                 /* skipped */
    KIND_VERTEX,
    KIND_FACE
} ply_kind;

typedef struct ply_element {
    rt_token name;
    long long count;            /* as the header claims it */
    ply_kind kind;
    int first, properties;      /* its properties in ply_header.property */
    long record;                /* binary: bytes an item takes, lists
                                   excepted (the fewest it can take) */
    int lists;                  /* how many of its properties are lists */
} ply_element;

typedef struct ply_header {
    ply_format format;
    ply_element element[RT_PLY_MAX_ELEMENTS];
    int element_count;
    ply_property *property;     /* all elements', in order */
    int property_count;
    size_t length;              /* bytes up to the body */
    int end_line;               /* the line of `end_header` */
    int has_normals;            /* the vertices have nx, ny and nz */
    int vertex_colours;         /* the vertices have red, green, blue */
    int face_colours;           /* the faces have red, green, blue */
} ply_header;

/* The size in bytes of a value of `type`. */
int rt__ply_type_size(ply_type type);

/* The name of `type` as headers write it ("uchar"). */
const char *rt__ply_type_name(ply_type type);

/*
 * Reads the header at the start of text[0..length) into *h: RT_OK, or
 * the refusal of the first broken rule in *error ("name:line:column:
 * expected ..., found `token`"), warnings (ignored elements and
 * properties) into `notes`.  rt__ply_header_free releases h->property
 * whatever the outcome.
 */
rt_status rt__ply_header_read(const char *text, size_t length,
                              const char *name, ply_header *h,
                              rt_notes *notes, rt_error *error);
void rt__ply_header_free(ply_header *h);

#endif /* RAYTRACE_PLY_H */
