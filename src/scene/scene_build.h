/*
 * scene_build.h - all a reader needs of the scene layer (internal): the
 * build of a scene from an rt_scene_desc, the one validator of its rules,
 * which reports what it refuses as data (item, index, field: a reader maps
 * that to the token it kept, as SQLite's sqlite3_error_offset does); the
 * warnings a load collects (the reader's, then the builder's); the files a
 * load read; and how often a load polls its cancellation flag.  The
 * readers (src/formats/) reach the scene through this header only, never
 * through scene_internal.h and the kernel behind it.
 */
#ifndef RAYTRACE_SCENE_BUILD_H
#define RAYTRACE_SCENE_BUILD_H

#include <stddef.h>

#include "base/error.h"
#include "raytrace/render.h"
#include "raytrace/scene.h"

/* How many items (records, entities, facets) a reader or the builder
 * handles between two polls of a load's cancellation flag: a few
 * microseconds of work. */
#define RT_LOAD_POLL 4096

/* ---------------------------------------------------------------- notes */

/* How many warnings of one kind (rt__notes_add_kind) are kept as they
 * are; the others of that kind become one warning that counts them and
 * lists their lines.  A file of a million zero-area facets then stores
 * nine warnings, not a million (each is an rt_warning of 520 bytes), and
 * a terminal shows the first few, which say what is wrong. */
#define RT_NOTES_SHOWN_PER_KIND 8

/* The most characters of line numbers a summary lists ("12, 15-20, ..."),
 * within the 512 bytes of a warning. */
#define RT_NOTES_LINES_TEXT 200

/* The lines of the warnings a summary stands for, as ranges. */
typedef struct rt_note_lines {
    char text[RT_NOTES_LINES_TEXT + 1];  /* the closed ranges so far */
    size_t length;
    int start, end;         /* the open range (start 0: none yet) */
    int full;               /* a range did not fit: ", ..." follows */
} rt_note_lines;

/* One kind of warning and what became of its warnings. */
typedef struct rt_note_kind {
    const char *kind;       /* as given (a literal) */
    int kept;               /* warnings stored as they are */
    int more;               /* warnings summarised */
    int summary;            /* index of the summary among the items */
    size_t prefix;          /* length of its "name:line:column: warning: " */
    rt_note_lines lines;
} rt_note_kind;

/* Warnings a reader found (malloc'd array), in the order found. */
typedef struct rt_notes {
    rt_warning *items;
    int count, capacity;
    rt_note_kind *kinds;    /* the kinds seen by rt__notes_add_kind */
    int kind_count, kind_capacity;
    int failed;             /* an item could not be stored (out of memory) */
} rt_notes;

/* Adds "name:line:column: warning: ..." (or "name: warning: ..." when
 * line is 0), the name shown by rt__escape_name. */
void rt__notes_add(rt_notes *notes, const char *name, int line, int column,
                   const char *fmt, ...) RT_PRINTF_LIKE(5, 6);

/*
 * The same for a warning of a kind that may repeat once per line of a
 * file: `kind` (a literal, compared by content) names it in the plural
 * ("zero-area facets").  The first RT_NOTES_SHOWN_PER_KIND of a kind are
 * stored as rt__notes_add stores them; the next one takes a place at its
 * own position for "name:line:column: warning: ... and N more KIND (lines
 * L, L1-L2, ...)", and every later one only counts in it (constant time).
 * The summary's text is written by rt__notes_settle, or in the copy
 * rt__notes_append makes.  A list holds at most RT_NOTES_SHOWN_PER_KIND + 1
 * warnings of each kind.
 */
void rt__notes_add_kind(rt_notes *notes, const char *kind, const char *name,
                        int line, int column, const char *fmt, ...)
    RT_PRINTF_LIKE(6, 7);

/* Writes the text of the summaries of `notes` (see rt__notes_add_kind). */
void rt__notes_settle(rt_notes *notes);

/* Appends copies of the warnings of `from` (may be NULL), its summaries
 * written, as plain warnings (not summarised further). */
void rt__notes_append(rt_notes *notes, const rt_notes *from);

void rt__notes_free(rt_notes *notes);

/* ------------------------------------------------------------- refusals */

/* The rules the builder checks, as "expected %s" words them: readers that
 * check a rule of their own on the same value (a format's 0, a value a
 * reader computes with before the build) use the same words. */
#define RT_RULE_COORDINATE                                                   \
    "a coordinate of magnitude at most 1e152 (the renderer's arithmetic "   \
    "overflows beyond)"
#define RT_RULE_K "a reflection coefficient k in [0, 1]"
#define RT_RULE_T "a transparency t with k + t <= 1"
#define RT_RULE_T_SIGN "a transparency t >= 0"
#define RT_RULE_N "a refractive index n > 0"
#define RT_RULE_D "a diffuse weight d >= 0"
#define RT_RULE_S "a highlight weight s >= 0"
#define RT_RULE_P "a highlight exponent p >= 1"
#define RT_RULE_NORMAL "a finite vertex normal"
#define RT_RULE_APERTURE "an aperture a >= 0"
#define RT_RULE_FOCAL "a focal distance f > 0"
#define RT_RULE_CAMERA "a camera that sees something"
#define RT_RULE_LIGHTS                                                       \
    "at most 64 lights (each one costs every hit a shadow ray)"
#define RT_RULE_A_LIGHT "at least one light"

/* What part of a description a refusal names. */
typedef enum rt_item {
    RT_ITEM_NONE,           /* the description as a whole (its arrays) */
    RT_ITEM_IMAGE,          /* width, height */
    RT_ITEM_CAMERA,         /* observer, screen_center, screen_right */
    RT_ITEM_LENS,           /* aperture, focal_distance */
    RT_ITEM_VERTEX,         /* vertices[index] */
    RT_ITEM_FACET,          /* facets[index] */
    RT_ITEM_LIGHT           /* lights[index] (0 with RT_FIELD_NONE when
                               there are none) */
} rt_item;

/* Which field of the item. */
typedef enum rt_field {
    RT_FIELD_NONE,          /* the item itself (a light past the limit,
                               or no light) */
    RT_FIELD_WIDTH,
    RT_FIELD_HEIGHT,
    RT_FIELD_OBSERVER,
    RT_FIELD_SCREEN_CENTER,
    RT_FIELD_SCREEN_RIGHT,
    RT_FIELD_APERTURE,
    RT_FIELD_FOCAL_DISTANCE,
    RT_FIELD_POSITION,      /* a vertex's or a light's */
    RT_FIELD_CORNER,        /* a facet's vertex index (part: which) */
    RT_FIELD_K,
    RT_FIELD_T,
    RT_FIELD_N,
    RT_FIELD_D,
    RT_FIELD_S,
    RT_FIELD_P,
    RT_FIELD_NORMAL         /* a vertex's normal (part: coordinate) */
} rt_field;

/* What the builder refused, as data (rt__scene_build); its words are also
 * in the rt_error, without a position. */
typedef struct rt_refusal {
    rt_status status;       /* RT_OK: nothing refused (or not the
                               description: memory, cancellation) */
    rt_item item;
    int index;              /* the vertex, facet or light; 0 otherwise */
    rt_field field;
    int part;               /* the coordinate (0 x, 1 y, 2 z) or the corner
                               (0..2); 0 otherwise */
    const char *expected;   /* the rule broken, an RT_RULE_ phrase */
    char found[96];         /* what stands instead when no token of a file
                               says it ("that the observer O is the screen
                               centre A", "light 65"); "": the token */
} rt_refusal;

/* ---------------------------------------------------------------- build */

/*
 * Builds a scene from a description, the one validator of the rules the
 * renderer relies on (raytrace/scene.h, rt_scene_desc).  `name` (may be
 * NULL) and `facet_lines` (may be NULL) only serve warnings; `notes` (may
 * be NULL) are the reader's own warnings, listed before the builder's;
 * `cancel` (may be NULL) is polled (RT_ERR_CANCELLED).  On failure returns
 * a status with *error filled ("name: " before its words when `name` is
 * given) and *scene NULL; when the description broke a rule, *refusal
 * (may be NULL) says which, else its status is RT_OK.  The rules are
 * checked in the order a file states them (the camera's points, the lens,
 * the camera, the vertices, the facets, the lights), so that the first
 * refused is the first a reader met.
 */
rt_status rt__scene_build(const rt_scene_desc *desc, const char *name,
                          const int *facet_lines, const rt_notes *notes,
                          const rt_cancel *cancel, rt_scene **scene,
                          rt_error *error, rt_refusal *refusal);

/* What frees a description's arrays during a build (rt_reading). */
typedef struct rt_scene_release {
    void (*release)(void *user);    /* may be NULL */
    void *user;
} rt_scene_release;

/* rt__scene_build, calling release->release(release->user) (release and
 * its function may be NULL) once the scene's records are made, before
 * its kernel: `desc` and `facet_lines` are not read after that call.  The
 * call is made on success only up to that point; on a failure before it,
 * the description is left to its owner. */
rt_status rt__scene_build_releasing(const rt_scene_desc *desc,
                                    const char *name, const int *facet_lines,
                                    const rt_notes *notes,
                                    const rt_cancel *cancel,
                                    const rt_scene_release *release,
                                    rt_scene **scene, rt_error *error,
                                    rt_refusal *refusal);

/* The checks of rt__scene_build alone: RT_OK, or the refusal as
 * rt__scene_build reports it (nothing is built). */
rt_status rt__scene_check(const rt_scene_desc *desc, const char *name,
                          rt_error *error, rt_refusal *refusal);

/* Gives `scene` the files its load read: `sources` (an array of `count`,
 * from malloc, each name from malloc), which the scene frees; a list it
 * held before is freed. */
void rt__scene_take_sources(rt_scene *scene, rt_scene_source *sources,
                            int count);

#endif /* RAYTRACE_SCENE_BUILD_H */
