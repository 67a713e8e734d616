/*
 * obj.h - what the Wavefront OBJ reader's files share (internal): the
 * statements over the one lexer (obj_text.c), the reader's state, the
 * geometry (obj.c) and the material libraries (mtl.c).  What is read
 * and why: docs/formats.md, section OBJ.
 */
#ifndef RAYTRACE_OBJ_H
#define RAYTRACE_OBJ_H

#include <stddef.h>

#include "base/error.h"
#include "formats/lexer.h"
#include "formats/mesh.h"
#include "formats/names.h"
#include "formats/reader.h"
#include "formats/resolve.h"
#include "formats/triangulate.h"
#include "raytrace/scene.h"

#define DEFAULT_GREY RT_MESH_GREY /* Kd of the default material */
#define MAX_KEYWORDS_NOTED 32   /* keywords warned about once each */
#define MAX_NAMES_SHOWN 3       /* names quoted in a summary */
#define MAX_LIBRARY_WARNINGS 4  /* libraries not read, each with its own
                                   message; the others are counted */
/* The cancel flag is polled every this many statements (a statement costs
 * at most a line, a few microseconds; a polygon's own cost is polled by
 * the triangulator). */
#define POLL_STATEMENTS 4096

typedef rt_token token;

/*
 * The statements of an OBJ or MTL text over the lexer (lexer.h): a
 * statement is the tokens of a line up to a `#`, and of the following
 * lines while the last token of a line ends with a backslash (which is
 * removed).  The keyword is kept; the rest is kept only as far as the
 * statement asks (rt__obj_rest), so that a statement that is ignored costs
 * no memory whatever its length.
 */
typedef struct lexer {
    rt_lexer text;              /* the one lexer, line by line */
    token *tokens;              /* tokens[0]: the keyword */
    int count, capacity;        /* tokens kept */
    long total;                 /* tokens of the statement read so far,
                                   kept or not */
    token last;                 /* the last token read */
} lexer;

/* Opens the statements of text[0..length), named `name` in messages
 * (rt__lex_open: the checks of the bytes; RT_ERR_NOMEM for the C
 * locale).  rt__obj_lexer_close releases them. */
rt_status rt__obj_lexer_open(lexer *x, const char *text, size_t length,
                             const char *name, rt_error *error);
void rt__obj_lexer_close(lexer *x);

/* The next statement's keyword into tokens[0] (count 1), skipping what is
 * left of the current one: 1, 0 at the end of the text, -1 out of
 * memory. */
int rt__obj_next_statement(lexer *x);

/* Reads the rest of the statement, keeping at most `most` more tokens
 * (all when negative); x->total counts them all, x->last is the last.
 * 0, or -1 when out of memory. */
int rt__obj_rest(lexer *x, int most);

/* The statement's next token without keeping it: 1, or 0 at its end. */
int rt__obj_token(lexer *x, token *t);

/* Reads `t` as a number by the one rule (rt__number_read). */
rt_status rt__obj_number(const lexer *x, const token *t, double *value);

/* A remark made once with a count: the first one's place and words. */
typedef struct counted {
    int count;
    const char *file;           /* the OBJ's or a library's name */
    int line, column;
    char text[300];
} counted;

/* A material as a library defines it: what its facets get. */
typedef struct material {
    rt_facet_desc look;
} material;

/* Facets [first, end) were read after `usemtl name` named a material that
 * no library read so far defines: they get it if one read later does. */
typedef struct waiting {
    int first, end;
    int name;                   /* id in reader.names */
    int line, column;           /* of the usemtl */
} waiting;

typedef struct reader {
    const char *name;           /* the OBJ, for messages */
    rt_error *error;
    const rt_load_options *options;
    rt_files *files;            /* the files the load reads */
    rt_notes notes;
    lexer lex;
    rt_triangulator triangulator;
    long statements;            /* read so far, OBJ and MTL */
    rt_vec3 *vertices;          /* the scene's: the `v` positions, and the
                                   copies a vertex used with another
                                   normal needs (obj_normals.c) */
    int vertex_count, vertex_capacity;
    int obj_vertex_count;       /* `v` statements read so far */
    int texture_count, normal_count;
    /* vertex normals (obj_normals.c): none of these exists before the
     * first `vn`, so a file without normals costs what it always did */
    rt_vec3 *normal_values;     /* each `vn`, unit, or zero when unusable */
    int normal_capacity;
    int *slot;                  /* per vertex: its `vn` (-1 none, -2 not
                                   used yet) */
    int slot_capacity;
    int *position_of;           /* per `v`: where it is in vertices[];
                                   NULL while that is its number */
    int position_capacity;
    struct obj_pair *pairs;     /* (v, vn) -> the copy, open addressing */
    int pair_count, pair_capacity;
    int *corner_normals;        /* per corner of the face being read */
    rt_vec3 *scene_normals;     /* the description's, at the end */
    int corner_normal_capacity;
    rt_facet_desc *facets;
    int *facet_lines;
    int facet_count, facet_capacity;
    int *polygon;               /* the corners of the face being read */
    int polygon_capacity;
    /* materials */
    material *materials;
    int material_count, material_capacity;
    rt_names names;             /* every material name defined or used */
    int *defined;               /* per name: its latest material, or -1 */
    int defined_capacity;
    int current;                /* material of new facets; -1: default */
    waiting *waits;
    int wait_count, wait_capacity;
    int open_wait;              /* the wait new facets join, or -1 */
    /* once-only warnings */
    char keywords[MAX_KEYWORDS_NOTED][16];
    int keyword_count, keywords_overflowed;
    int unread_warned;          /* "libraries are not read" said */
    int libraries_refused;      /* libraries not read so far */
    /* counted warnings, said once at the end */
    counted fanned, over_budget, no_area, few_corners;
    counted self_library, more_refused, bad_values, lowered, no_name;
    counted no_argument, no_library_name;
    counted bad_normal;         /* `vn` of zero length or not finite */
} reader;

void rt__obj_warn(reader *r, const char *file, int line, int column,
          const char *fmt, ...) RT_PRINTF_LIKE(5, 6);

/* Counts a remark, keeping the words of the first. */
void rt__obj_count(counted *c, const char *file, int line, int column,
                const char *fmt, ...) RT_PRINTF_LIKE(5, 6);

/* Says a counted remark (when there was one): the first's words, and how
 * many more there were. */
void rt__obj_say(reader *r, const counted *c);

/* Warns once per keyword: `what` says how it is treated. */
void rt__obj_warn_once(reader *r, const char *file, const token *keyword,
               const char *what);

/* Non-zero the first time `key` (a keyword, or "@something" for other
 * once-only remarks, which no keyword can be) is seen; -1 the first time
 * the list is full. */
int rt__obj_first_time(reader *r, const char *key, size_t length);

rt_status rt__obj_out_of_memory(reader *r);

/* Room for element `count` of *array (*capacity elements of `size` bytes),
 * doubling from `first`: 1; 0 when out of memory; -1 past INT_MAX / 2
 * elements. */
int rt__obj_grow(void **array, int *capacity, int count, size_t size,
                 int first);

/* Polls the cancel flag every POLL_STATEMENTS statements. */
rt_status rt__obj_poll(reader *r);

/* The name a statement gives after its keyword: its tokens from the
 * second on when they stay on one line (names may hold spaces), else the
 * second alone.  Needs rt__obj_rest(x, 1) first. */
void rt__obj_statement_name(const lexer *x, const char **text, size_t *length);

/* obj_normals.c: the vertex normals (docs/formats.md, OBJ, "Vertex
 * normals").  rt__obj_normal reads a `vn`; rt__obj_corners turns the face's
 * corners (polygon[i]: a `v`, 0-based; corner_normals[i]: a `vn` or -1)
 * into positions in vertices[], copying a vertex used with another normal
 * than its first (corners repeating the one before are dropped first, *n
 * their new count); rt__obj_normals gives the scene's array (NULL: none, or
 * out of memory: *failed); rt__obj_free_normals frees what they hold. */
rt_status rt__obj_normal(reader *r);
int rt__obj_vertex_added(reader *r);     /* 1, or 0 out of memory */
rt_status rt__obj_corners(reader *r, int *n);
rt_vec3 *rt__obj_normals(reader *r, int *failed);
void rt__obj_free_normals(reader *r);

/* mtl.c: `mtllib` and `usemtl`, and the materials at the end. */
rt_status rt__obj_read_libraries(reader *r);
rt_status rt__obj_use_material(reader *r);
rt_status rt__obj_finish_materials(reader *r);
void rt__obj_free_materials(reader *r);

#endif /* RAYTRACE_OBJ_H */
