/*
 * reader.h - what every scene reader shares (internal): the checks of the
 * raw bytes before parsing (size, encoding, line endings) and the list of
 * warnings a reader hands to the scene builder.
 */
#ifndef RAYTRACE_READER_H
#define RAYTRACE_READER_H

#include <stddef.h>

#include "error.h"
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

/* Warnings a reader found (malloc'd array), in the order found. */
typedef struct rt_notes {
    rt_warning *items;
    int count, capacity;
    int failed;             /* an item could not be stored (out of memory) */
} rt_notes;

/* Adds "name:line:column: warning: ..." (or "name: warning: ..." when
 * line is 0). */
void rt__notes_add(rt_notes *notes, const char *name, int line, int column,
                   const char *fmt, ...) RT_PRINTF_LIKE(5, 6);

void rt__notes_free(rt_notes *notes);

/* The longest number a reader takes, in characters (a longer one is
 * refused: no double needs more, and the copy for strtod stays on the
 * stack). */
#define RT__MAX_NUMBER_LENGTH 256

/* Whether text[0..length) is a number of the scene format's grammar:
 * [+-] digits [. digits] [(e|E) [+-] digits], at least one digit before
 * the exponent (number.c; rt_scene_read_number reads one). */
int rt__number_syntax(const char *text, size_t length);

#endif /* RAYTRACE_READER_H */
