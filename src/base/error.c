/*
 * error.c - formatting error reports in the GNU "file:line:column: " form,
 * and showing names (a path, usually) and tokens in them without the
 * control bytes they may hold: a scene file's name comes from whoever named
 * the file, and its tokens from whoever wrote it.  Names and tokens follow
 * one escaping rule.
 */
#include "error.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* The length of the well-formed UTF-8 character at s, of `left` bytes at
 * most (1..4), or 0 (RFC 3629: no overlong form, no surrogate, nothing
 * past U+10FFFF). */
static size_t utf8_length(const unsigned char *s, size_t left)
{
    unsigned char c = s[0];
    size_t n;
    unsigned char low = 0x80, high = 0xBF;  /* the second byte's range */
    if (c >= 0xC2 && c <= 0xDF)
        n = 2;
    else if (c >= 0xE0 && c <= 0xEF)
        n = 3, low = c == 0xE0 ? 0xA0 : 0x80, high = c == 0xED ? 0x9F : 0xBF;
    else if (c >= 0xF0 && c <= 0xF4)
        n = 4, low = c == 0xF0 ? 0x90 : 0x80, high = c == 0xF4 ? 0x8F : 0xBF;
    else
        return 0;
    if (left < n || s[1] < low || s[1] > high)
        return 0;
    for (size_t i = 2; i < n; i++)
        if (s[i] < 0x80 || s[i] > 0xBF)
            return 0;
    return n;
}

/*
 * The one escaping rule of messages: writes the character at s (of `left`
 * bytes at most) as a message shows it into piece[0..16) and returns its
 * length there; *take is set to the bytes of s it stands for.
 */
static size_t escape_piece(const unsigned char *s, size_t left, char *piece,
                           size_t *take)
{
    static const char hex[] = "0123456789ABCDEF";
    size_t n = 0;
    size_t length = *s >= 0x80 ? utf8_length(s, left) : 1;
    /* U+0080..U+009F, the C1 controls, are C2 80..C2 9F */
    int c1 = length == 2 && s[0] == 0xC2 && s[1] <= 0x9F;
    *take = 1;
    if (*s == '\\') {
        piece[n++] = '\\';
        piece[n++] = '\\';
    } else if (*s < 0x20 || *s == 0x7F || length == 0 || c1) {
        *take = c1 ? 2 : 1;
        for (size_t i = 0; i < *take; i++) {
            piece[n++] = '\\';
            piece[n++] = 'x';
            piece[n++] = hex[s[i] >> 4];
            piece[n++] = hex[s[i] & 15];
        }
    } else {
        *take = length;
        memcpy(piece, s, length);
        n = length;
    }
    return n;
}

/* Escapes text[0..length) into out[0..size) (size > 0, NUL-terminated),
 * taking no more than `most` bytes of the text and no character that would
 * not fit whole; returns the bytes of the text taken. */
static size_t escape(const char *text, size_t length, size_t most, char *out,
                     size_t size, size_t *used_out)
{
    const unsigned char *s = (const unsigned char *)text;
    size_t used = 0, taken = 0;
    while (taken < length) {
        char piece[16];
        size_t take;
        size_t n = escape_piece(s + taken, length - taken, piece, &take);
        if (taken + take > most || used + n + 1 > size)
            break;
        memcpy(out + used, piece, n);
        used += n;
        taken += take;
    }
    out[used] = '\0';
    *used_out = used;
    return taken;
}

size_t rt__escape_name(const char *name, char *out, size_t size)
{
    size_t used;
    size_t length = strlen(name);
    escape(name, length, length, out, size, &used);
    return used;
}

const char *rt__show_token(const char *text, size_t length,
                           char out[RT_TOKEN_SHOWN_SIZE])
{
    size_t used;
    size_t taken = escape(text, length, RT_TOKEN_SHOWN_BYTES, out,
                          RT_TOKEN_SHOWN_SIZE - 3, &used);
    if (taken < length)
        memcpy(out + used, "...", 4);
    return out;
}

rt_status rt__error_set(rt_error *error, rt_status status, const char *name,
                        int line, int column, const char *fmt, ...)
{
    if (error == NULL)
        return status;
    error->status = status;
    error->line = line;
    error->column = column;
    size_t size = sizeof error->message;
    size_t used = 0;
    if (name != NULL) {
        used = rt__escape_name(name, error->message, size);
        int more = line > 0 ? snprintf(error->message + used, size - used,
                                       ":%d:%d: ", line, column)
                            : snprintf(error->message + used, size - used,
                                       ": ");
        if (more < 0 || (size_t)more >= size - used)
            used = 0;   /* no room for the message: the message alone */
        else
            used += (size_t)more;
    }
    va_list args;
    va_start(args, fmt);
    vsnprintf(error->message + used, size - used, fmt, args);
    va_end(args);
    return status;
}
