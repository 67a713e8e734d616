/*
 * ply_values.c - the values of a PLY body (ply.h): binary ones read with
 * memcpy and a byte swap when the body's order is not the machine's, ASCII
 * ones one token at a time through the lexer, each line an item, numbers by
 * the one rule (rt__lex_number) and whole numbers checked against their
 * type's range; and the messages that name a value's place, its byte
 * (binary) or its line and column (ASCII).
 */
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "formats/ply.h"

size_t rt__ply_offset(const reader *r)
{
    return (size_t)((const char *)r->at - r->text);
}

/* Refuses the last value read: "name:line:column: expected ..., found
 * `token`" (ASCII), "name: byte N: expected ..., found VALUE" (binary). */
rt_status rt__ply_refuse_value(reader *r, rt_status status, double found,
                               const char *fmt, ...)
{
    char expected[RT_ERROR_MESSAGE_SIZE];
    va_list args;
    va_start(args, fmt);
    vsnprintf(expected, sizeof expected, fmt, args);
    va_end(args);
    if (r->h.format == PLY_ASCII)
        return rt__token_refuse(r->error, status, r->name, &r->last, "%s",
                                expected);
    return rt__error_set(r->error, status, r->name, 0, 0,
                         "byte %zu: expected %s, found %.17g", r->last_at,
                         expected, found);
}

/* The bytes of the body left to read. */
size_t rt__ply_bytes_left(const reader *r)
{
    if (r->h.format != PLY_ASCII)
        return (size_t)(r->end - r->at);
    const char *from = r->has_pending ? r->pending.text : r->lex.at;
    return (size_t)(r->lex.end - from);
}

/* "the property `y` of vertex 3" */
const char *rt__ply_what(const place *w, char *out, size_t size)
{
    char property[RT_TOKEN_SHOWN_SIZE], element[RT_TOKEN_SHOWN_SIZE];
    snprintf(
        out, size, "the property `%s` (%s) of %s %lld",
        rt__token_shown(&w->property->name, property),
        rt__ply_type_name(w->property->count_type != PLY_NONE && !w->in_list
                              ? w->property->count_type
                              : w->property->type),
        rt__token_shown(&w->element->name, element), w->item);
    return out;
}

/* ------------------------------------------------------------ binary */

static rt_status binary_value(reader *r, ply_type type, const place *w,
                              double *value)
{
    int size = rt__ply_type_size(type);
    if (r->end - r->at < size) {
        char shown[RT_ERROR_MESSAGE_SIZE];
        return rt__error_set(r->error, RT_ERR_SYNTAX, r->name, 0, 0,
                             "byte %zu: expected %s, found the end of the "
                             "file",
                             rt__ply_offset(r),
                             rt__ply_what(w, shown, sizeof shown));
    }
    *value = ply_load(r->at, type, r->swap);
    r->last_at = rt__ply_offset(r);
    r->at += size;
    return RT_OK;
}

/* ------------------------------------------------------------- ASCII */

/* The next value of the item's line (the first opens the line). */
static rt_status ascii_value(reader *r, ply_type type, const place *w,
                             int first, double *value)
{
    rt_token t;
    char shown[RT_ERROR_MESSAGE_SIZE];
    int got;
    if (first && r->has_pending) {
        t = r->pending, got = 1, r->has_pending = 0;
    } else {
        got =
            first ? rt__lex_statement(&r->lex, &t) : rt__lex_next(&r->lex, &t);
    }
    if (!got) {
        int line, column;
        if (first) {
            rt__lex_end(&r->lex, &line, &column);
        } else {
            line = r->last.line;
            column = r->last.column + (int)r->last.length;
        }
        return rt__error_set(r->error, RT_ERR_SYNTAX, r->name, line, column,
                             "expected %s, found the end of the %s",
                             rt__ply_what(w, shown, sizeof shown),
                             first ? "file" : "line");
    }
    if (first)
        r->line = t.line;
    r->last = t;
    rt_status status = rt__lex_number(&r->lex, &t, value);
    if (status != RT_OK)
        return rt__token_refuse(r->error, status, r->name, &t, "%s for %s",
                                rt__number_expected(status),
                                rt__ply_what(w, shown, sizeof shown));
    if (type != PLY_FLOAT32 && type != PLY_FLOAT64) {
        static const double low[] = {0, -128, 0, -32768, 0, -2147483648.0, 0};
        static const double high[] = {0,     127,          255,         32767,
                                      65535, 2147483647.0, 4294967295.0};
        if (*value != floor(*value) || *value < low[type] ||
            *value > high[type])
            return rt__ply_refuse_value(
                r, RT_ERR_RANGE, *value, "a whole number in %.0f..%.0f for %s",
                low[type], high[type], rt__ply_what(w, shown, sizeof shown));
    }
    return RT_OK;
}

/* The end of an ASCII item's line. */
rt_status rt__ply_line_end(reader *r, const ply_element *e, long long item)
{
    rt_token t;
    char shown[RT_TOKEN_SHOWN_SIZE];
    if (rt__lex_next(&r->lex, &t))
        return rt__token_refuse(r->error, RT_ERR_SYNTAX, r->name, &t,
                                "the end of the line of %s %lld",
                                rt__token_shown(&e->name, shown), item);
    return RT_OK;
}

/* ---------------------------------------------------------------- items */

rt_status rt__ply_value(reader *r, ply_type type, const place *w, int first,
                        double *v)
{
    return r->h.format == PLY_ASCII ? ascii_value(r, type, w, first, v)
                                    : binary_value(r, type, w, v);
}
