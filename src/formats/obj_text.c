/*
 * obj_text.c - the text side of the OBJ and MTL readers (obj.h): the
 * statement lexer, tokens and numbers, and the warnings, those said once
 * and those counted.
 *
 * The lexer reads a token at a time and keeps only what a statement asks
 * for: the keyword always, the rest up to a count the statement's reader
 * gives.  A statement that is ignored (an unknown keyword, `l`, an MTL
 * line before any `newmtl`) is skipped without keeping a token, so a
 * megabyte line costs no memory; a face reads its corners one by one.
 */
#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "formats/obj.h"

/* ---------------------------------------------------------------- lexing */

static int is_space(int c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

/* Moves the cursor to the start of line `start`. */
static void begin_line(lexer *x, const char *start)
{
    x->at = x->line_start = start;
    const char *eol = memchr(start, '\n', (size_t)(x->end - start));
    x->eol = eol != NULL ? eol : x->end;
}

void rt__obj_lexer_start(lexer *x, const char *text, size_t length)
{
    memset(x, 0, sizeof *x);
    x->end = text + length;
    x->line = 1;
    if (length >= 3 && memcmp(text, "\xEF\xBB\xBF", 3) == 0)
        text += 3;          /* a UTF-8 byte-order mark: not a column */
    begin_line(x, text);
}

/* The next token of the open statement: 1, or 0 at its end (the cursor is
 * then at the start of the next line). */
static int next_token(lexer *x, token *t)
{
    for (;;) {
        while (x->at < x->eol && is_space((unsigned char)*x->at))
            x->at++;
        if (x->at == x->eol || *x->at == '#') {
            int more = x->continues;
            x->continues = 0;
            if (x->eol == x->end) {
                x->at = x->end;
                x->open = 0;
                return 0;
            }
            begin_line(x, x->eol + 1);
            x->line++;
            if (!more) {
                x->open = 0;
                return 0;
            }
            continue;
        }
        const char *s = x->at;
        while (x->at < x->eol && !is_space((unsigned char)*x->at) &&
               *x->at != '#')
            x->at++;
        *t = (token){s, (size_t)(x->at - s), x->line,
                     (int)(s - x->line_start) + 1};
        const char *c = x->at;
        while (c < x->eol && is_space((unsigned char)*c))
            c++;
        if ((c == x->eol || *c == '#') && t->text[t->length - 1] == '\\') {
            x->continues = 1;       /* the last token of a continued line */
            if (--t->length == 0)
                continue;
        }
        x->total++;
        x->last = *t;
        return 1;
    }
}

static int keep(lexer *x, const token *t)
{
    if (rt__obj_grow((void **)&x->tokens, &x->capacity, x->count,
                     sizeof *x->tokens, 16) <= 0)
        return 0;
    x->tokens[x->count++] = *t;
    return 1;
}

int rt__obj_next_statement(lexer *x)
{
    token t;
    while (x->open && next_token(x, &t))
        ;                           /* what the last statement left */
    x->count = 0;
    x->total = 0;
    while (x->at < x->end || x->open) {
        x->open = 1;
        if (next_token(x, &t))
            return keep(x, &t) ? 1 : -1;
    }
    return 0;
}

int rt__obj_rest(lexer *x, int most)
{
    token t;
    while (x->open && next_token(x, &t))
        if ((most < 0 || x->count <= most) && !keep(x, &t))
            return -1;
    return 0;
}

int rt__obj_token(lexer *x, token *t)
{
    return x->open && next_token(x, t);
}

int rt__obj_token_is(const token *t, const char *word)
{
    size_t n = strlen(word);
    return t->length == n && memcmp(t->text, word, n) == 0;
}

const char *rt__obj_shown(const token *t, char buffer[MAX_TOKEN_SHOWN + 4])
{
    size_t n = t->length < MAX_TOKEN_SHOWN ? t->length : MAX_TOKEN_SHOWN;
    for (size_t i = 0; i < n; i++)
        buffer[i] = isprint((unsigned char)t->text[i]) ? t->text[i] : '?';
    strcpy(buffer + n, t->length > n ? "..." : "");
    return buffer;
}

void rt__obj_statement_name(const lexer *x, const char **text, size_t *length)
{
    const token *a = &x->tokens[1], *b = &x->last;
    *text = a->text;
    *length = a->line == b->line ? (size_t)(b->text + b->length - a->text)
                                 : a->length;
}

/* ---------------------------------------------------------------- numbers */

int rt__obj_decimal(locale_t c_locale, const token *t, double *value)
{
    char copy[128];
    if (t->length == 0 || t->length >= sizeof copy)
        return 1;
    int digits = 0;
    for (size_t i = 0; i < t->length; i++) {
        char c = t->text[i];
        if (isdigit((unsigned char)c))
            digits++;
        else if (!strchr("+-.eE", c))
            return 1;
        copy[i] = c;
    }
    copy[t->length] = '\0';
    if (digits == 0)
        return 1;
    char *stop;
    locale_t previous = uselocale(c_locale);
    errno = 0;
    double v = strtod(copy, &stop);
    uselocale(previous);
    if (*stop != '\0' || (copy[0] == '.' && !isdigit((unsigned char)copy[1])))
        return 1;
    if (!isfinite(v))
        return 2;
    *value = v;
    return 0;
}

/* --------------------------------------------------------------- warnings */

void rt__obj_warn(reader *r, const char *file, int line, int column,
                  const char *fmt, ...)
{
    char message[RT_ERROR_MESSAGE_SIZE];
    va_list args;
    va_start(args, fmt);
    vsnprintf(message, sizeof message, fmt, args);
    va_end(args);
    rt__notes_add(&r->notes, file, line, column, "%s", message);
}

void rt__obj_count(counted *c, const char *file, int line, int column,
                   const char *fmt, ...)
{
    if (c->count++ > 0)
        return;
    c->file = file;
    c->line = line;
    c->column = column;
    va_list args;
    va_start(args, fmt);
    vsnprintf(c->text, sizeof c->text, fmt, args);
    va_end(args);
}

void rt__obj_say(reader *r, const counted *c)
{
    if (c->count == 1)
        rt__obj_warn(r, c->file, c->line, c->column, "%s", c->text);
    else if (c->count > 1)
        rt__obj_warn(r, c->file, c->line, c->column,
                     "%s (and %d more like it)", c->text, c->count - 1);
}

int rt__obj_first_time(reader *r, const char *key, size_t length)
{
    if (length >= sizeof r->keywords[0])
        length = sizeof r->keywords[0] - 1;
    for (int i = 0; i < r->keyword_count; i++)
        if (strlen(r->keywords[i]) == length &&
            memcmp(r->keywords[i], key, length) == 0)
            return 0;
    if (r->keyword_count == MAX_KEYWORDS_NOTED) {
        int first = !r->keywords_overflowed;
        r->keywords_overflowed = 1;
        return first ? -1 : 0;
    }
    memcpy(r->keywords[r->keyword_count], key, length);
    r->keywords[r->keyword_count++][length] = '\0';
    return 1;
}

void rt__obj_warn_once(reader *r, const char *file, const token *keyword,
                       const char *what)
{
    char buffer[MAX_TOKEN_SHOWN + 4];
    int first = rt__obj_first_time(r, keyword->text, keyword->length);
    if (first > 0)
        rt__obj_warn(r, file, keyword->line, keyword->column,
                     "`%s` statements %s (said once)",
                     rt__obj_shown(keyword, buffer), what);
    else if (first < 0)
        rt__obj_warn(r, file, keyword->line, keyword->column,
                     "more kinds of statements than are listed are ignored");
}

int rt__obj_grow(void **array, int *capacity, int count, size_t size,
                 int first)
{
    if (count < *capacity)
        return 1;
    if (*capacity > INT_MAX / 2)
        return -1;
    int bigger = *capacity ? 2 * *capacity : first;
    void *grown = realloc(*array, (size_t)bigger * size);
    if (grown == NULL)
        return 0;
    *array = grown;
    *capacity = bigger;
    return 1;
}

rt_status rt__obj_out_of_memory(reader *r)
{
    return rt__error_set(r->error, RT_ERR_NOMEM, r->name, 0, 0,
                         "out of memory");
}

rt_status rt__obj_poll(reader *r)
{
    if (++r->statements % POLL_STATEMENTS != 0 ||
        r->options->cancel == NULL ||
        !rt_cancel_requested(r->options->cancel))
        return RT_OK;
    return rt__error_set(r->error, RT_ERR_CANCELLED, r->name, 0, 0,
                         "the load was cancelled");
}
