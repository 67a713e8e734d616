/*
 * obj_text.c - the text side of the OBJ and MTL readers (obj.h): the
 * statements over the one lexer (lexer.h), numbers, and the warnings,
 * those said once and those counted.
 *
 * A statement is read a token at a time, keeping only what it asks for:
 * the keyword always, the rest up to a count the statement's reader
 * gives.  A statement that is ignored (an unknown keyword, `l`, an MTL
 * line before any `newmtl`) is skipped without keeping a token, so a
 * megabyte line costs no memory; a face reads its corners one by one.
 */
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "formats/obj.h"

/* ------------------------------------------------------------ statements */

rt_status rt__obj_lexer_open(lexer *x, const char *text, size_t length,
                             const char *name, rt_error *error)
{
    memset(x, 0, sizeof *x);
    return rt__lex_open(&x->text, text, length, name,
                        RT_LEX_LINES | RT_LEX_CONTINUATION, error);
}

void rt__obj_lexer_close(lexer *x)
{
    rt__lex_close(&x->text);
    free(x->tokens);
    x->tokens = NULL;
}

/* The next token of the open statement, counted: 1, or 0 at its end. */
static int next_token(lexer *x, token *t)
{
    if (!rt__lex_next(&x->text, t))
        return 0;
    x->total++;
    x->last = *t;
    return 1;
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
    x->count = 0;
    x->total = 0;
    if (!rt__lex_statement(&x->text, &t))
        return 0;
    x->total = 1;
    x->last = t;
    return keep(x, &t) ? 1 : -1;
}

int rt__obj_rest(lexer *x, int most)
{
    token t;
    while (next_token(x, &t))
        if ((most < 0 || x->count <= most) && !keep(x, &t))
            return -1;
    return 0;
}

int rt__obj_token(lexer *x, token *t)
{
    return next_token(x, t);
}

void rt__obj_statement_name(const lexer *x, const char **text, size_t *length)
{
    const token *a = &x->tokens[1], *b = &x->last;
    *text = a->text;
    *length = a->line == b->line ? (size_t)(b->text + b->length - a->text)
                                 : a->length;
}

rt_status rt__obj_number(const lexer *x, const token *t, double *value)
{
    return rt__lex_number(&x->text, t, value);
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
    char buffer[RT_TOKEN_SHOWN_SIZE];
    int first = rt__obj_first_time(r, keyword->text, keyword->length);
    if (first > 0)
        rt__obj_warn(r, file, keyword->line, keyword->column,
                     "`%s` statements %s (said once)",
                     rt__token_shown(keyword, buffer), what);
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
