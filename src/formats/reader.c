/*
 * reader.c - the checks every scene reader makes on its raw bytes, and the
 * warnings readers collect.  The checks exist because each of these inputs
 * once produced a misleading message deep in a parser ("expected 3 values,
 * found 1" for a UTF-16 file): the message must name the real cause.
 */
#include "formats/reader.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The encoding a byte-order mark announces, or NULL. */
static const char *bom_encoding(const unsigned char *b, size_t n)
{
    if (n >= 4 && b[0] == 0xFF && b[1] == 0xFE && b[2] == 0 && b[3] == 0)
        return "UTF-32 (little-endian)";
    if (n >= 4 && b[0] == 0 && b[1] == 0 && b[2] == 0xFE && b[3] == 0xFF)
        return "UTF-32 (big-endian)";
    if (n >= 2 && b[0] == 0xFF && b[1] == 0xFE)
        return "UTF-16 (little-endian)";
    if (n >= 2 && b[0] == 0xFE && b[1] == 0xFF)
        return "UTF-16 (big-endian)";
    return NULL;
}

/* ASCII text in UTF-16 without a byte-order mark: its first characters
 * alternate with NUL bytes (every other byte NUL, the others printable). */
static int looks_utf16(const unsigned char *b, size_t n)
{
    if (n < 8)
        return 0;
    for (int zero_at = 0; zero_at < 2; zero_at++) {
        int fits = 1;
        for (size_t i = 0; i < 8 && fits; i++) {
            int want_zero = (int)(i % 2) == zero_at;
            fits = want_zero ? b[i] == 0
                             : (b[i] >= 0x20 && b[i] < 0x7f) || b[i] == '\n' ||
                                   b[i] == '\r' || b[i] == '\t';
        }
        if (fits)
            return 1;
    }
    return 0;
}

rt_status rt__text_check(const char *text, size_t length, const char *name,
                         rt_error *error)
{
    const unsigned char *b = (const unsigned char *)text;
    if (length > RT_MAX_SCENE_BYTES)
        return rt__error_set(error, RT_ERR_LIMIT, name, 0, 0,
                             "expected a scene of at most %zu bytes, found "
                             "%zu bytes", RT_MAX_SCENE_BYTES, length);
    const char *encoding = bom_encoding(b, length);
    if (encoding != NULL)
        return rt__error_set(error, RT_ERR_FORMAT, name, 0, 0,
                             "the file is encoded in %s (it starts with that "
                             "byte-order mark): save it as ASCII or UTF-8",
                             encoding);
    int line = 1, column = 1;
    size_t cr_alone = 0, lf = 0;
    for (size_t i = 0; i < length; i++) {
        if (b[i] == 0) {
            int utf16 = looks_utf16(b, length);
            return rt__error_set(
                error, RT_ERR_FORMAT, name, line, column,
                utf16 ? "expected text, found NUL bytes between ASCII "
                        "characters: the file looks UTF-16 encoded (without "
                        "a byte-order mark); save it as ASCII or UTF-8"
                      : "expected text, found a NUL byte: the file is "
                        "binary, not a scene");
        }
        if (b[i] == '\n') {
            lf++;
            line++;
            column = 1;
        } else {
            cr_alone += b[i] == '\r' && (i + 1 == length || b[i + 1] != '\n');
            column++;
        }
    }
    if (cr_alone > 0 && lf == 0)
        return rt__error_set(error, RT_ERR_FORMAT, name, 0, 0,
                             "the file has old Mac line endings (CR only, "
                             "%zu of them, no LF): convert them to LF or "
                             "CRLF", cr_alone);
    return RT_OK;
}

void rt__notes_add(rt_notes *notes, const char *name, int line, int column,
                   const char *fmt, ...)
{
    if (notes->count == notes->capacity) {
        int bigger = notes->capacity ? 2 * notes->capacity : 8;
        rt_warning *grown = realloc(notes->items,
                                    (size_t)bigger * sizeof *grown);
        if (grown == NULL) {
            notes->failed = 1;
            return;
        }
        notes->items = grown;
        notes->capacity = bigger;
    }
    rt_warning *w = &notes->items[notes->count++];
    w->line = line;
    w->column = line > 0 ? column : 0;
    const char *shown = name ? name : "<memory>";
    int used = line > 0 ? snprintf(w->message, sizeof w->message,
                                   "%s:%d:%d: warning: ", shown, line, column)
                        : snprintf(w->message, sizeof w->message,
                                   "%s: warning: ", shown);
    if (used < 0 || (size_t)used >= sizeof w->message)
        used = 0;
    va_list args;
    va_start(args, fmt);
    vsnprintf(w->message + used, sizeof w->message - (size_t)used, fmt, args);
    va_end(args);
}

void rt__notes_free(rt_notes *notes)
{
    free(notes->items);
    memset(notes, 0, sizeof *notes);
}
