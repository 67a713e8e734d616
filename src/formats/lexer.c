/*
 * lexer.c - the one lexer of the text formats (lexer.h): the checks of the
 * raw bytes, tokens with their line and column in a stream or line by line
 * (commas and continued lines as a format asks), the end of the text, and
 * a token as a message shows it or as a number.
 *
 * A token costs no memory: it points into the text.  A statement that a
 * reader skips is passed over token by token without keeping any, so a
 * megabyte line costs nothing but the time to read it.
 */
#include "formats/lexer.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "scene/scene_build.h" /* RT_LOAD_POLL */

static const char utf8_bom[] = "\xEF\xBB\xBF";

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

/* The checks of rt__lex_open on the raw bytes (lexer.h), each of which once
 * gave a misleading message deep in a parser ("expected 3 values, found 1"
 * for a UTF-16 file): the message names the real cause. */
static rt_status text_check(const char *text, size_t length, const char *name,
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
    /* memchr finds the rare bytes at memory speed; the line and column of
     * a NUL are counted only when there is one */
    const unsigned char *nul = memchr(b, 0, length);
    if (nul != NULL) {
        int line = 1;
        const unsigned char *line_start = b;
        for (const unsigned char *c = b; c < nul; c++)
            if (*c == '\n') {
                line++;
                line_start = c + 1;
            }
        int column = (int)(nul - line_start) + 1;
        int utf16 = looks_utf16(b, length);
        return rt__error_set(
            error, RT_ERR_FORMAT, name, line, column,
            utf16 ? "expected text, found NUL bytes between ASCII "
                    "characters: the file looks UTF-16 encoded (without "
                    "a byte-order mark); save it as ASCII or UTF-8"
                  : "expected text, found a NUL byte: the file is "
                    "binary, not a scene");
    }
    if (length > 0 && memchr(b, '\n', length) == NULL) {
        /* no LF at all: every CR stands alone */
        size_t cr_alone = 0;
        for (size_t i = 0; i < length; i++)
            cr_alone += b[i] == '\r';
        if (cr_alone > 0)
            return rt__error_set(error, RT_ERR_FORMAT, name, 0, 0,
                                 "the file has old Mac line endings (CR "
                                 "only, %zu of them, no LF): convert them "
                                 "to LF or CRLF", cr_alone);
    }
    return RT_OK;
}

/* What each byte is to the lexer, one table for every format: blanks
 * (space, tab, CR, VT, FF), the newline, `#` and the comma (which ends a
 * token only with RT_LEX_COMMAS: rt_lexer's `stops`). */
enum { BLANK = 1, NEWLINE = 2, HASH = 4, COMMA = 8 };
static const unsigned char byte_class[256] = {
    ['\t'] = BLANK, ['\n'] = NEWLINE, ['\v'] = BLANK, ['\f'] = BLANK,
    ['\r'] = BLANK, [' '] = BLANK,     ['#'] = HASH,    [','] = COMMA};

static int is_blank(unsigned char c)
{
    return byte_class[c] & BLANK;
}

/* RT_LEX_LINES: the cursor at the start of the line at `start`. */
static void begin_line(rt_lexer *lx, const char *start)
{
    lx->at = lx->line_start = start;
    const char *eol = memchr(start, '\n', (size_t)(lx->end - start));
    lx->eol = eol != NULL ? eol : lx->end;
}

rt_status rt__lex_open(rt_lexer *lx, const char *text, size_t length,
                       const char *name, unsigned flags, rt_error *error)
{
    memset(lx, 0, sizeof *lx);
    if (text == NULL)
        text = "";
    rt_status status = text_check(text, length, name, error);
    if (status != RT_OK)
        return status;
    lx->c_locale = rt__c_locale_new();
    if (lx->c_locale == (locale_t)0)
        return rt__error_set(error, RT_ERR_NOMEM, name, 0, 0,
                             "cannot create the C locale");
    lx->start = text;
    lx->end = text + length;
    lx->line = 1;
    lx->flags = flags;
    lx->stops = BLANK | NEWLINE | HASH | (flags & RT_LEX_COMMAS ? COMMA : 0);
    const char *first = text;
    if (length >= 3 && memcmp(text, utf8_bom, 3) == 0)
        first += 3;         /* a UTF-8 byte-order mark: not a column */
    if (flags & RT_LEX_LINES)
        begin_line(lx, first);
    else
        lx->at = lx->line_start = first;
    return RT_OK;
}

void rt__lex_close(rt_lexer *lx)
{
    if (lx->c_locale != (locale_t)0)
        freelocale(lx->c_locale);
    lx->c_locale = (locale_t)0;
}

/* The token that starts at lx->at (not a blank, '#' or a line's end). */
static void take_token(rt_lexer *lx, const char *limit, rt_token *t)
{
    const char *s = lx->at, *c = s + 1;
    unsigned stops = lx->stops;
    if (!(byte_class[(unsigned char)*s] & stops & COMMA))
        while (c < limit && !(byte_class[(unsigned char)*c] & stops))
            c++;
    lx->at = c;
    *t = (rt_token){s, (size_t)(c - s), lx->line,
                    (int)(s - lx->line_start) + 1};
}

/* The next token of a stream (newlines are blanks). */
static int stream_next(rt_lexer *lx, rt_token *t)
{
    const char *c = lx->at;
    for (;;) {
        while (c < lx->end && (byte_class[(unsigned char)*c] &
                               (BLANK | NEWLINE))) {
            if (*c == '\n') {
                lx->line++;
                lx->line_start = c + 1;
            }
            c++;
        }
        if (c < lx->end && *c == '#') {
            while (c < lx->end && *c != '\n')
                c++;
            continue;
        }
        break;
    }
    lx->at = c;
    if (c == lx->end)
        return 0;
    take_token(lx, lx->end, t);
    lx->tokens++;
    return 1;
}

/* The next token of the open statement, line by line. */
static int line_next(rt_lexer *lx, rt_token *t)
{
    if (!lx->open)
        return 0;
    for (;;) {
        while (lx->at < lx->eol && is_blank((unsigned char)*lx->at))
            lx->at++;
        if (lx->at == lx->eol || *lx->at == '#') {
            int more = lx->continues;
            lx->continues = 0;
            if (lx->eol == lx->end) {
                lx->at = lx->end;
                lx->open = 0;
                return 0;
            }
            begin_line(lx, lx->eol + 1);
            lx->line++;
            if (!more) {
                lx->open = 0;
                return 0;
            }
            continue;
        }
        take_token(lx, lx->eol, t);
        if (lx->flags & RT_LEX_CONTINUATION) {
            const char *c = lx->at;
            while (c < lx->eol && is_blank((unsigned char)*c))
                c++;
            if ((c == lx->eol || *c == '#') &&
                t->text[t->length - 1] == '\\') {
                lx->continues = 1;  /* the last token of a continued line */
                if (--t->length == 0)
                    continue;
            }
        }
        lx->tokens++;
        return 1;
    }
}

int rt__lex_next(rt_lexer *lx, rt_token *t)
{
    return lx->flags & RT_LEX_LINES ? line_next(lx, t) : stream_next(lx, t);
}

int rt__lex_peek(const rt_lexer *lx, rt_token *t)
{
    rt_lexer ahead = *lx;
    return rt__lex_next(&ahead, t);
}

int rt__lex_statement(rt_lexer *lx, rt_token *first)
{
    rt_token t;
    while (lx->open && line_next(lx, &t))
        ;                           /* what the last statement left */
    while (lx->at < lx->end || lx->open) {
        lx->open = 1;
        if (line_next(lx, first))
            return 1;
    }
    return 0;
}

/* Whether the count is to poll `cancel` at `count` (lexer.h). */
static int poll_now(long count, const rt_cancel *cancel)
{
    return count % (16 * RT_LOAD_POLL) == 0 && cancel != NULL &&
           rt_cancel_requested(cancel);
}

/* The statements from the start of a line on when no line continues
 * another: the lines that hold a token, found without cutting tokens
 * (the first byte that is no blank is neither `#` nor the line's end). */
static long count_lines(const rt_lexer *lx, const rt_cancel *cancel)
{
    const char *c = lx->at, *end = lx->end;
    long count = 0;
    if (poll_now(count, cancel))
        return -1;
    while (c < end) {
        while (c < end && is_blank((unsigned char)*c))
            c++;
        if (c < end && *c != '\n' && *c != '#' && poll_now(++count, cancel))
            return -1;
        const char *eol = memchr(c, '\n', (size_t)(end - c));
        if (eol == NULL)
            break;
        c = eol + 1;
    }
    return count;
}

/* The tokens of a stream from the cursor on, cut as stream_next cuts
 * them without making them. */
static long count_tokens(const rt_lexer *lx, const rt_cancel *cancel)
{
    const char *c = lx->at, *end = lx->end;
    unsigned stops = lx->stops;
    long count = 0;
    if (poll_now(count, cancel))
        return -1;
    while (c < end) {
        unsigned kind = byte_class[(unsigned char)*c];
        if (kind & (BLANK | NEWLINE)) {
            c++;
        } else if (kind & HASH) {
            const char *eol = memchr(c, '\n', (size_t)(end - c));
            c = eol != NULL ? eol : end;
        } else {
            if (poll_now(++count, cancel))
                return -1;
            c++;
            if (!(kind & stops & COMMA))
                while (c < end && !(byte_class[(unsigned char)*c] & stops))
                    c++;
        }
    }
    return count;
}

long rt__lex_count(const rt_lexer *from, int statements,
                   const rt_cancel *cancel)
{
    if (!(from->flags & RT_LEX_LINES) && !statements)
        return count_tokens(from, cancel);
    if ((from->flags & RT_LEX_LINES) && statements &&
        !(from->flags & RT_LEX_CONTINUATION) && !from->open &&
        from->at == from->line_start)
        return count_lines(from, cancel);
    rt_lexer lx = *from;
    rt_token t;
    for (long count = 0;; count++) {
        if (poll_now(count, cancel))
            return -1;
        if (!(statements ? rt__lex_statement(&lx, &t) : rt__lex_next(&lx, &t)))
            return count;
    }
}

void rt__lex_end(const rt_lexer *lx, int *line, int *column)
{
    const char *text = lx->start, *last = lx->end;
    while (last > text && last[-1] != '\n')
        last--;
    if (last == text && lx->end - text >= 3 && memcmp(text, utf8_bom, 3) == 0)
        last += 3;
    int newlines = 0;
    for (const char *c = text; c < lx->end; c++)
        newlines += *c == '\n';
    *line = newlines + 1;
    *column = (int)(lx->end - last) + 1;
}

rt_status rt__lex_number(const rt_lexer *lx, const rt_token *t,
                         double *value)
{
    return rt__number_read(lx->c_locale, t->text, t->length, value);
}

int rt__token_is(const rt_token *t, const char *word)
{
    size_t n = strlen(word);
    return t->length == n && memcmp(t->text, word, n) == 0;
}

const char *rt__token_shown(const rt_token *t, char out[RT_TOKEN_SHOWN_SIZE])
{
    return rt__show_token(t->text, t->length, out);
}

rt_status rt__token_refuse(rt_error *error, rt_status status,
                           const char *name, const rt_token *t,
                           const char *fmt, ...)
{
    char expected[RT_ERROR_MESSAGE_SIZE], shown[RT_TOKEN_SHOWN_SIZE];
    va_list args;
    va_start(args, fmt);
    vsnprintf(expected, sizeof expected, fmt, args);
    va_end(args);
    return rt__error_set(error, status, name, t->line, t->column,
                         "expected %s, found `%s`", expected,
                         rt__token_shown(t, shown));
}
