/*
 * reader.h - what every scene reader shares (internal): the checks of the
 * raw bytes before parsing (size, encoding, line endings), the list of
 * warnings a reader hands to the scene builder, and the poll of a load's
 * cancellation flag.
 */
#ifndef RAYTRACE_READER_H
#define RAYTRACE_READER_H

#include <stddef.h>

#include "base/error.h"
#include "raytrace/scene.h"

/*
 * Refuses, with a message that names the cause, input no reader can take:
 * more than RT_MAX_SCENE_BYTES; UTF-16 or UTF-32 text (by its byte-order
 * mark, or by NUL bytes between ASCII characters); other binary data (a
 * NUL byte; its line and column are given); old Mac line endings (CR
 * without LF).  A UTF-8 byte-order mark, LF and CRLF are accepted.
 */
rt_status rt__text_check(const char *text, size_t length, const char *name,
                         rt_error *error);

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

/* Non-zero when `options` (may be NULL) carries a cancellation flag that
 * is raised.  Cheap (one atomic load), but readers poll it every
 * RT_LOAD_POLL items only. */
int rt__load_cancelled(const rt_load_options *options);

/* How many items (records, entities, facets) a reader handles between
 * two polls of the flag: a few microseconds of work. */
#define RT_LOAD_POLL 4096

/* Fills *error for a cancelled load of `name` and returns
 * RT_ERR_CANCELLED. */
rt_status rt__load_cancel(rt_error *error, const char *name);

/* The longest number a reader takes, in characters (a longer one is
 * refused: no double needs more, and the copy for strtod stays on the
 * stack). */
#define RT__MAX_NUMBER_LENGTH 256

/* Whether text[0..length) is a number of the scene format's grammar:
 * [+-] digits [. digits] [(e|E) [+-] digits], at least one digit before
 * the exponent (number.c; rt_scene_read_number reads one). */
int rt__number_syntax(const char *text, size_t length);

#endif /* RAYTRACE_READER_H */
