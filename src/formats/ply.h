/*
 * ply.h - what the PLY reader's files share (internal): the header as
 * read (ply_header.c: the format, the elements and their properties, each
 * property's part in the model), the reader's state (ply.c: the body,
 * ASCII or binary, into the mesh) and its values (ply_values.c).  What is
 * read and why: docs/formats.md, section PLY; the budgets:
 * docs/robustness-input.md.
 */
#ifndef RAYTRACE_PLY_H
#define RAYTRACE_PLY_H

#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "base/error.h"
#include "formats/lexer.h"
#include "formats/mesh.h"
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

static inline uint16_t ply_swap16(uint16_t v)
{
    return (uint16_t)(v << 8 | v >> 8);
}

static inline uint32_t ply_swap32(uint32_t v)
{
    return v << 24 | (v & 0xff00u) << 8 | (v >> 8 & 0xff00u) | v >> 24;
}

static inline uint64_t ply_swap64(uint64_t v)
{
    return (uint64_t)ply_swap32((uint32_t)v) << 32 |
           ply_swap32((uint32_t)(v >> 32));
}

/* The value of `type` at p, its bytes swapped when `swap` (the body's
 * byte order is not the machine's): one memcpy, no alignment needed. */
static inline double ply_load(const unsigned char *p, ply_type type,
                              int swap)
{
    switch (type) {
    case PLY_INT8:
        return (int8_t)p[0];
    case PLY_UINT8:
        return p[0];
    case PLY_INT16:
    case PLY_UINT16: {
        uint16_t u;
        memcpy(&u, p, 2);
        u = swap ? ply_swap16(u) : u;
        return type == PLY_INT16 ? (double)(int16_t)u : (double)u;
    }
    case PLY_INT32:
    case PLY_UINT32:
    case PLY_FLOAT32: {
        uint32_t u;
        memcpy(&u, p, 4);
        u = swap ? ply_swap32(u) : u;
        if (type == PLY_FLOAT32) {
            float f;
            memcpy(&f, &u, 4);
            return f;
        }
        return type == PLY_INT32 ? (double)(int32_t)u : (double)u;
    }
    case PLY_FLOAT64: {
        uint64_t u;
        memcpy(&u, p, 8);
        u = swap ? ply_swap64(u) : u;
        double d;
        memcpy(&d, &u, 8);
        return d;
    }
    case PLY_NONE:
        break;
    }
    return 0;
}

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

/* ---------------------------------------------------------------- reader
 * ply.c's state, which ply_values.c reads values for. */

/* Where a remark about faces is first made, and how many there were. */
typedef struct counted {
    int count;
    int line;           /* ASCII: the face's line; binary: 0 */
    long long face;     /* the face's index */
} counted;

typedef struct reader {
    const char *name;
    rt_error *error;
    const rt_load_options *options;
    const char *text;
    size_t length;
    ply_header h;
    rt_notes notes;
    rt_triangulator triangulator;
    long long items;            /* read so far, for the cancel poll */
    /* the model */
    rt_vec3 *vertices;
    int vertex_count;
    unsigned char *colours;     /* 3 a vertex, when the vertices have them */
    rt_vec3 *normals;           /* when the vertices have nx, ny, nz */
    rt_facet_desc *facets;
    int *facet_lines;           /* ASCII only: each facet's line */
    int facet_count, facet_capacity;
    int *polygon;               /* the corners of the face being read */
    int polygon_capacity;
    rt_facet_desc look;         /* the default material */
    rt_rgb8 face_colour;        /* of the face being read, when faces have
                                   colours */
    int line;                   /* ASCII: the line of the item read */
    counted outcomes[RT_FACE_CROSSING + 1];
    counted clamped;            /* colours outside their range */
    /* binary */
    const unsigned char *at, *end;
    int swap;                   /* the body's byte order is not ours */
    /* ASCII */
    rt_lexer lex;
    rt_token pending;           /* the first token of the next line */
    int has_pending;
    rt_token last;              /* the last value read (ASCII) */
    size_t last_at;             /* the byte of the last value (binary) */
} reader;

/* What a value being read is, for messages. */
typedef struct place {
    const ply_element *element;
    const ply_property *property;
    long long item;
    int in_list;        /* the value is one of a list's items */
} place;

/* The next value, of `type`, at the place `w` names: binary, the next
 * bytes; ASCII, the next token of the item's line (`first`: the first of a
 * new line).  RT_OK, or the refusal: the end of the file (or line), no
 * number, not a whole number in the type's range. */
rt_status rt__ply_value(reader *r, ply_type type, const place *w, int first,
                        double *value);

/* ASCII: refuses a token left on the line of item `item` of `e`. */
rt_status rt__ply_line_end(reader *r, const ply_element *e, long long item);

/* Refuses the last value read: "name:line:column: expected ..., found
 * `token`" (ASCII), "name: byte N: expected ..., found VALUE" (binary). */
rt_status rt__ply_refuse_value(reader *r, rt_status status, double found,
                               const char *fmt, ...) RT_PRINTF_LIKE(4, 5);

/* The bytes of the body left to read; the byte the cursor is at. */
size_t rt__ply_bytes_left(const reader *r);
size_t rt__ply_offset(const reader *r);

/* "the property `y` (float) of vertex 3", into out[size]. */
const char *rt__ply_what(const place *w, char *out, size_t size);

#endif /* RAYTRACE_PLY_H */
