/*
 * cli_text.c - names in messages and in JSON strings (see cli_text.h).
 * The UTF-8 decoder follows RFC 3629's table of well-formed sequences
 * (the bounds of the second byte after E0, ED, F0 and F4 exclude overlong
 * forms, surrogates and code points above U+10FFFF); where a sequence
 * breaks off, the bytes read so far are one maximal subpart.
 */
#include "cli_text.h"

#include <string.h>

#include "raytrace/raytrace.h"

#define INVALID (-1L)

const char *cli_printable(const char *text, char *out, size_t size)
{
    size_t used = 0;
    for (const unsigned char *c = (const unsigned char *)text; *c; c++) {
        char piece[8];
        size_t n = 1;
        if (*c < 0x20 || *c == 0x7f)
            n = (size_t)snprintf(piece, sizeof piece, "\\x%02x", *c);
        else
            piece[0] = (char)*c;
        if (used + n + 4 > size) {   /* room for "..." and the NUL */
            if (size >= 4)
                memcpy(out + (used < size - 4 ? used : size - 4), "...", 4);
            else if (size > 0)
                out[0] = '\0';
            return out;
        }
        memcpy(out + used, piece, n);
        used += n;
    }
    if (size > 0)
        out[used] = '\0';
    return out;
}

/* The code point at s (RFC 3629), its length in *length; INVALID with the
 * length of the maximal subpart (at least 1) when the bytes there are not
 * a well-formed sequence. */
static long decode(const unsigned char *s, size_t *length)
{
    unsigned char c = s[0];
    *length = 1;
    if (c < 0x80)
        return c;
    int more;
    long code;
    unsigned char low = 0x80, high = 0xbf; /* the second byte's range */
    if (c >= 0xc2 && c <= 0xdf) {
        more = 1, code = c & 0x1f;
    } else if (c >= 0xe0 && c <= 0xef) {
        more = 2, code = c & 0x0f;
        low = c == 0xe0 ? 0xa0 : 0x80;
        high = c == 0xed ? 0x9f : 0xbf;
    } else if (c >= 0xf0 && c <= 0xf4) {
        more = 3, code = c & 0x07;
        low = c == 0xf0 ? 0x90 : 0x80;
        high = c == 0xf4 ? 0x8f : 0xbf;
    } else {
        return INVALID;     /* a continuation byte, C0, C1, F5..FF */
    }
    for (int i = 1; i <= more; i++) {
        unsigned char next = s[i]; /* the NUL ends a sequence too */
        if (next < (i == 1 ? low : 0x80) || next > (i == 1 ? high : 0xbf))
            return INVALID;
        code = (code << 6) | (next & 0x3f);
        *length = (size_t)i + 1;
    }
    return code;
}

/* Where the escaped string goes: a stream, or a buffer. */
typedef struct sink {
    FILE *file;
    char *buffer;
    size_t size, length;
} sink;

static void emit(sink *k, const char *bytes, size_t n)
{
    if (k->file != NULL) {
        fwrite(bytes, 1, n, k->file);
    } else {
        for (size_t i = 0; i < n; i++)
            if (k->length + i + 1 < k->size)
                k->buffer[k->length + i] = bytes[i];
    }
    k->length += n;
}

static int escaped_code_point(long code)
{
    return code < 0x20 || (code >= 0x7f && code <= 0x9f) || code == 0x2028 ||
           code == 0x2029;
}

static void json_escape(sink *k, const char *text)
{
    emit(k, "\"", 1);
    const unsigned char *c = (const unsigned char *)text;
    while (*c) {
        size_t length;
        long code = decode(c, &length);
        char escape[24];   /* "\\u" and up to 16 hex digits of a long */
        if (code == INVALID) {
            emit(k, "\\ufffd", 6);
        } else if (code == '"' || code == '\\') {
            escape[0] = '\\';
            escape[1] = (char)code;
            emit(k, escape, 2);
        } else if (escaped_code_point(code)) {
            snprintf(escape, sizeof escape, "\\u%04lx", (unsigned long)code);
            emit(k, escape, 6);
        } else {
            emit(k, (const char *)c, length);
        }
        c += length;
    }
    emit(k, "\"", 1);
}

void cli_json_string(FILE *out, const char *text)
{
    sink k = {out, NULL, 0, 0};
    json_escape(&k, text);
}

size_t cli_json_quote(const char *text, char *out, size_t size)
{
    sink k = {NULL, out, size, 0};
    json_escape(&k, text);
    if (size > 0)
        out[k.length < size ? k.length : size - 1] = '\0';
    return k.length;
}

int cli_up_axis_text(const rt_scene *scene, char *out, size_t size)
{
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    static const char *const names[] = {"+y", "+x", "+y", "+z",
                                        "-x", "-y", "-z"};
    const char *axis = info.up_axis >= RT_UP_AUTO && info.up_axis <= RT_UP_NEG_Z
                           ? names[info.up_axis]
                           : "+y";
    switch (info.up_cue) {
    case RT_UP_CUE_NONE:
        break;
    case RT_UP_CUE_DEFAULT:
        snprintf(out, size, "%s up (the default: no comment names one)",
                 axis);
        return 1;
    case RT_UP_CUE_COMMENT:
        snprintf(out, size, "%s up (from the comment on line %d)", axis,
                 info.up_cue_line);
        return 1;
    case RT_UP_CUE_EXPORTER:
        snprintf(out, size,
                 "%s up (the exporter named on line %d writes it so by "
                 "default)", axis, info.up_cue_line);
        return 1;
    case RT_UP_CUE_OPTION:
        snprintf(out, size, "%s up (--up-axis)", axis);
        return 2;
    }
    if (size > 0)
        out[0] = '\0';
    return 0;
}

void cli_print_up_note(FILE *stream, const char *program, const char *name,
                       const rt_scene *scene)
{
    char text[160], shown[512];
    int said = cli_up_axis_text(scene, text, sizeof text);
    if (said)
        fprintf(stream, "%s: %s: note: automatic camera with %s%s\n",
                program, cli_printable(name, shown, sizeof shown), text,
                said == 1 ? "; --up-axis picks another" : "");
}
