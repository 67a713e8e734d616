/*
 * error.h - filling an rt_error, and showing names and tokens in messages
 * (internal).
 */
#ifndef RAYTRACE_ERROR_H
#define RAYTRACE_ERROR_H

#include <assert.h>
#include <stddef.h>

#include "raytrace/status.h"

#if defined(__GNUC__)
#define RT_PRINTF_LIKE(f, a) __attribute__((format(printf, f, a)))
#else
#define RT_PRINTF_LIKE(f, a)
#endif

/*
 * Sets *error (when not NULL) to status at (line, column) with a message
 * formatted by fmt; the message is prefixed with "name:line:column: " when
 * line > 0, with "name: " when line == 0 and name != NULL, the name shown
 * by rt__escape_name.  Returns status.
 */
rt_status rt__error_set(rt_error *error, rt_status status, const char *name,
                        int line, int column, const char *fmt, ...)
    RT_PRINTF_LIKE(6, 7);

/*
 * A precondition of a function that cannot return a status (an accessor's
 * index, a query's scene): a programmer's error when false (STYLE.md), so
 * assert() stops a debug build there; with NDEBUG the expression is still
 * the condition, and the caller returns its documented zero value instead
 * of reading out of bounds.  `condition` is evaluated twice in debug
 * builds: give it no side effects.
 */
#define RT__EXPECT(condition) (assert(condition), (condition))

/*
 * Writes `name` (NUL-terminated) into out[0..size) as messages show it, so
 * that a file's name cannot drive the terminal it is printed on: a
 * backslash becomes `\\`; a control byte (0x00-0x1F), DEL (0x7F), a byte
 * that is not part of well-formed UTF-8, and the UTF-8 encoding of a C1
 * control (U+0080-U+009F) become `\xNN`, byte by byte; other characters,
 * UTF-8 included, stay as they are.  Stops before an escape or a character
 * that would not fit whole; out is always NUL-terminated (size > 0).
 * Returns the length written.  Thread-safe.
 */
size_t rt__escape_name(const char *name, char *out, size_t size);

/* The most bytes of a token that a message quotes: a longer token is cut
 * (before a character that would straddle the limit) and "..." follows. */
#define RT_TOKEN_SHOWN_BYTES 40

/* Room for a token as shown: each byte may become four characters, then
 * "..." and the NUL. */
#define RT_TOKEN_SHOWN_SIZE (4 * RT_TOKEN_SHOWN_BYTES + 4)

/*
 * Writes text[0..length) (any bytes, no NUL needed) into `out` as every
 * message quotes a token of a file: its first RT_TOKEN_SHOWN_BYTES bytes
 * escaped by rt__escape_name's rule, then "..." when the token is longer.
 * Returns out.  Thread-safe.
 */
const char *rt__show_token(const char *text, size_t length,
                           char out[RT_TOKEN_SHOWN_SIZE]);

#endif /* RAYTRACE_ERROR_H */
