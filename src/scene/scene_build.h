/*
 * scene_build.h - all a reader needs of the scene layer (internal): the
 * build of a scene from an rt_scene_desc, the warnings a load collects
 * (the reader's, then the builder's), the files a load read, and how often
 * a load polls its cancellation flag.  The readers (src/formats/) reach
 * the scene through this header only, never through scene_internal.h and
 * the kernel behind it.
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

/* ---------------------------------------------------------------- build */

/*
 * Builds a scene from a description, the one validator of the rules the
 * renderer relies on (raytrace/scene.h, rt_scene_desc).  `name` (may be
 * NULL) and `facet_lines` (may be NULL) only serve warnings; `notes` (may
 * be NULL) are the reader's own warnings, listed before the builder's;
 * `cancel` (may be NULL) is polled (RT_ERR_CANCELLED).  On failure returns
 * a status with *error filled and *scene NULL.
 */
rt_status rt__scene_build(const rt_scene_desc *desc, const char *name,
                          const int *facet_lines, const rt_notes *notes,
                          const rt_cancel *cancel, rt_scene **scene,
                          rt_error *error);

/* Gives `scene` the files its load read: `sources` (an array of `count`,
 * from malloc, each name from malloc), which the scene frees; a list it
 * held before is freed. */
void rt__scene_take_sources(rt_scene *scene, rt_scene_source *sources,
                            int count);

#endif /* RAYTRACE_SCENE_BUILD_H */
