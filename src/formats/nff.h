/*
 * nff.h - what the NFF reader's files share (internal): the reader's state,
 * the values of the stream (nff.c), the entities that become facets
 * (nff_shapes.c) and the cut of spheres and cones from the view
 * (nff_cut.c).  What each entity becomes: docs/formats.md, section NFF.
 */
#ifndef RAYTRACE_NFF_H
#define RAYTRACE_NFF_H

#include <stddef.h>

#include "base/error.h"
#include "formats/lexer.h"
#include "formats/reader.h"
#include "formats/tessellate.h"
#include "scene/scene_build.h"

typedef rt_token token;

/* One warning of each kind per file. */
enum {
    ONCE_HITHER, ONCE_NORMALS, ONCE_INSIDE, ONCE_COLOR,
    ONCE_KT, ONCE_MATERIAL, ONCE_IRREGULAR, ONCE_ASPECT, ONCE_VIEW,
    ONCE_COUNT
};

/* A sphere (apex unused) or cone, tessellated at the end. */
typedef struct primitive {
    int cone;
    rt_vec3 base, apex;
    double r0, r1;          /* >= 0 */
    int inward;
    int material;           /* index into the materials */
    int line, column;
} primitive;

typedef struct nff_light {
    rt_vec3 position;
    rt_rgb8 color;
    int colored;
    token at;               /* its `l`, for the builder's refusals */
} nff_light;

typedef struct parser {
    rt_lexer lex;           /* NFF is a stream of tokens */
    const char *name;
    const rt_load_options *options;
    long polls;             /* items handled, for the cancellation poll */
    long token_count;       /* the tokens of the file */
    rt_error *error;
    rt_notes notes;
    int once[ONCE_COUNT];
    /* what the file says */
    int has_view;
    rt_vec3 from, at_point, up;
    double angle;
    rt_vec3 observer, screen_center, screen_right;  /* its frame */
    int width, height;
    rt_rgb8 background;
    nff_light *lights;
    int light_count, light_capacity;
    rt_facet_desc *materials;
    int material_count, material_capacity;
    primitive *primitives;
    int primitive_count, primitive_capacity;
    rt_vec3 *points;        /* a polygon's vertices, then a patch's
                               normals (room for 2 point_capacity) */
    int point_capacity;
    rt_tess_mesh mesh;
} parser;

/* ------------------------------------------------------ values (nff.c) */

/* Non-zero when the load is cancelled, looked at on the first item and
 * every RT_LOAD_POLL items after it. */
int rt__nff_poll_cancel(parser *p);

/* The tokens of the file not read yet; its size in bytes. */
long rt__nff_tokens_left(const parser *p);
size_t rt__nff_file_bytes(const parser *p);

/* "name:line:column: expected EXPECTED, found `token`". */
rt_status rt__nff_fail(parser *p, rt_status status, const token *t,
                       const char *expected);
rt_status rt__nff_out_of_memory(parser *p);

/* The next token as a finite number, a whole number in [min, max], or
 * three numbers (`bounded`: each within RT_MAX_COORDINATE); `what` names
 * it in messages ("the sphere's radius"); *where (may be NULL) gets the
 * token (the first of three). */
rt_status rt__nff_number(parser *p, const char *what, double *value,
                         token *where);
rt_status rt__nff_integer(parser *p, const char *what, long min, long max,
                          int *value, token *where);
rt_status rt__nff_triple(parser *p, const char *what, int bounded,
                         rt_vec3 *out, token *where);

/* An NFF colour (three components in [0, 1], clamped with a warning). */
rt_status rt__nff_color(parser *p, const char *what, rt_rgb8 *out);

/* The warning of kind `kind` (ONCE_), at `at`, the first time only. */
void rt__nff_warn_once(parser *p, int kind, const token *at,
                       const char *text);

/* Room for element `count` of *array, doubling from 16: 0, or -1 when out
 * of memory or past INT_MAX / 2 elements. */
int rt__nff_grow(void **array, int *capacity, int count, size_t size);

/* -------------------------------------------------- entities (nff_shapes.c)
 * `f` (a material), `s`, `c`, `p` and `pp`, the entity's keyword given. */
rt_status rt__nff_material(parser *p, const token *f);
rt_status rt__nff_sphere(parser *p, const token *s);
rt_status rt__nff_cone(parser *p, const token *c);
rt_status rt__nff_polygon(parser *p, const token *entity, int patch);

/* ---------------------------------------------------------- nff_cut.c */

/* Cuts every sphere and cone into the mesh, by the tolerance `option`
 * (--tessellate), or from the view when it is 0. */
rt_status rt__nff_tessellate(parser *p, double option);

#endif /* RAYTRACE_NFF_H */
