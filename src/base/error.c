/*
 * error.c - formatting error reports in the GNU "file:line:column: " form,
 * and showing a name (a path, usually) in them without the control bytes
 * it may hold: a scene file's name comes from whoever named the file.
 */
#include "error.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* The length of the well-formed UTF-8 character at s (1..4 bytes), or 0
 * (RFC 3629: no overlong form, no surrogate, nothing past U+10FFFF). */
static int utf8_length(const unsigned char *s)
{
    unsigned char c = s[0];
    int n;
    unsigned char low = 0x80, high = 0xBF;  /* the second byte's range */
    if (c >= 0xC2 && c <= 0xDF)
        n = 2;
    else if (c >= 0xE0 && c <= 0xEF)
        n = 3, low = c == 0xE0 ? 0xA0 : 0x80, high = c == 0xED ? 0x9F : 0xBF;
    else if (c >= 0xF0 && c <= 0xF4)
        n = 4, low = c == 0xF0 ? 0x90 : 0x80, high = c == 0xF4 ? 0x8F : 0xBF;
    else
        return 0;
    if (s[1] < low || s[1] > high)
        return 0;
    for (int i = 2; i < n; i++)
        if (s[i] < 0x80 || s[i] > 0xBF)
            return 0;
    return n;
}

size_t rt__escape_name(const char *name, char *out, size_t size)
{
    static const char hex[] = "0123456789ABCDEF";
    const unsigned char *s = (const unsigned char *)name;
    size_t used = 0;
    while (*s != '\0') {
        char piece[16];
        size_t n = 0, take = 1;
        int length = *s >= 0x80 ? utf8_length(s) : 1;
        /* U+0080..U+009F, the C1 controls, are C2 80..C2 9F */
        int c1 = length == 2 && s[0] == 0xC2 && s[1] <= 0x9F;
        if (*s == '\\') {
            piece[n++] = '\\';
            piece[n++] = '\\';
        } else if (*s < 0x20 || *s == 0x7F || length == 0 || c1) {
            take = c1 ? 2 : 1;
            for (size_t i = 0; i < take; i++) {
                piece[n++] = '\\';
                piece[n++] = 'x';
                piece[n++] = hex[s[i] >> 4];
                piece[n++] = hex[s[i] & 15];
            }
        } else {
            take = (size_t)length;
            memcpy(piece, s, take);
            n = take;
        }
        if (used + n + 1 > size)
            break;
        memcpy(out + used, piece, n);
        used += n;
        s += take;
    }
    out[used] = '\0';
    return used;
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
