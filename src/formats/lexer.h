/*
 * lexer.h - the one lexer of the text formats (internal): `.scn`, NFF, OBJ
 * and MTL read their bytes through it.  It checks the bytes before anything
 * is read (size, encoding, line endings), cuts them into tokens that know
 * their line and column, reads numbers by the scene format's one rule in
 * the C locale, and shows a token in a message by the one escaping rule of
 * names and tokens (base/error.h).  Each format keeps its own grammar as
 * flags and a thin layer over it: what separates values, whether a line
 * ends a statement, whether a backslash continues one.
 *
 * Every format shares: blanks are space, tab, CR, VT and FF; `#` starts a
 * comment that runs to the end of the line, inside a token too; a UTF-8
 * byte-order mark at the start is skipped and is no column; lines and
 * columns count from 1, columns in bytes.
 */
#ifndef RAYTRACE_LEXER_H
#define RAYTRACE_LEXER_H

#include <locale.h>
#include <stddef.h>

#include "base/error.h"
#include "raytrace/render.h"
#include "raytrace/scene.h"

/* A token: `length` bytes at `text` (inside the text read, no NUL after
 * it), the line and column of its first byte. */
typedef struct rt_token {
    const char *text;
    size_t length;
    int line, column;
} rt_token;

/* The grammar's choices (rt__lex_open's flags). */
enum {
    /* A line ends a statement (.scn, OBJ, MTL); without it the text is
     * one stream of tokens, and newlines are blanks (NFF). */
    RT_LEX_LINES = 1,
    /* A comma is a token of its own, one byte long, and ends the token
     * before it (.scn: values are separated by blanks and/or one comma). */
    RT_LEX_COMMAS = 2,
    /* With RT_LEX_LINES: a statement whose line's last token ends with a
     * backslash goes on on the next line; the backslash is no part of the
     * token, and a token that was only a backslash is none (OBJ, MTL). */
    RT_LEX_CONTINUATION = 4
};

/* The lexer's cursor over a text (a value: a copy reads on from where the
 * original stood, as rt__lex_peek and rt__lex_count do). */
typedef struct rt_lexer {
    const char *start;          /* the text as given (a byte-order mark
                                   included) */
    const char *at, *end;       /* the next byte to read; the text's end */
    const char *line_start;     /* the start of the line of `at` */
    const char *eol;            /* RT_LEX_LINES: the end of that line */
    int line;                   /* the line of `at` */
    unsigned flags;
    unsigned stops;             /* the classes of bytes that end a token */
    int open;                   /* RT_LEX_LINES: inside a statement */
    int continues;              /* the line's last token ended with '\' */
    long tokens;                /* tokens read so far */
    locale_t c_locale;          /* for numbers */
} rt_lexer;

/*
 * Starts a lexer over text[0..length) (text may be NULL when length is 0)
 * with the grammar's `flags`.  Refuses first, with a message that names
 * the cause and `name` (the file, for messages), input no reader can take:
 * more than RT_MAX_SCENE_BYTES (RT_ERR_LIMIT); UTF-16 or UTF-32 text (by
 * its byte-order mark, or by NUL bytes between ASCII characters); other
 * binary data (a NUL byte; its line and column are given); old Mac line
 * endings (CR without LF) (RT_ERR_FORMAT).  A UTF-8 byte-order mark, LF and
 * CRLF are accepted.  RT_ERR_NOMEM when the C locale cannot be made.
 * On success rt__lex_close releases the lexer; on failure there is nothing
 * to release.
 */
rt_status rt__lex_open(rt_lexer *lexer, const char *text, size_t length,
                       const char *name, unsigned flags, rt_error *error);
void rt__lex_close(rt_lexer *lexer);

/*
 * The next token: of the open statement with RT_LEX_LINES (0 at its end,
 * the cursor then at the start of the next line), of the stream without
 * (0 at the end of the text).
 */
int rt__lex_next(rt_lexer *lexer, rt_token *token);

/* The next token without reading it: 1, or 0 as rt__lex_next. */
int rt__lex_peek(const rt_lexer *lexer, rt_token *token);

/*
 * RT_LEX_LINES: skips what is left of the open statement and opens the
 * next one that holds a token (lines with nothing but blanks and comments
 * are passed over), its first token into *first: 1, or 0 at the end of
 * the text.
 */
int rt__lex_statement(rt_lexer *lexer, rt_token *first);

/* The tokens (statements when `statements` is non-zero) from the cursor
 * to the end of the text, the lexer left where it is; -1 when `cancel`
 * (may be NULL) is raised meanwhile (it is polled every
 * 16 * RT_LOAD_POLL). */
long rt__lex_count(const rt_lexer *lexer, int statements,
                   const rt_cancel *cancel);

/* The line and column just past the last byte of the text, for
 * "unexpected end of file". */
void rt__lex_end(const rt_lexer *lexer, int *line, int *column);

/* Reads `token` as a number by the one rule (rt__number_read). */
rt_status rt__lex_number(const rt_lexer *lexer, const rt_token *token,
                         double *value);

/* Whether the token is `word`, byte for byte. */
int rt__token_is(const rt_token *token, const char *word);

/* The token as messages quote it (rt__show_token). */
const char *rt__token_shown(const rt_token *token,
                            char out[RT_TOKEN_SHOWN_SIZE]);

/*
 * Fills *error with "name:line:column: expected WHAT, found `TOKEN`" at
 * the token's position, WHAT formatted from `fmt`, and returns `status`.
 */
rt_status rt__token_refuse(rt_error *error, rt_status status,
                           const char *name, const rt_token *token,
                           const char *fmt, ...) RT_PRINTF_LIKE(5, 6);

/* ---------------------------------------------------------------- numbers
 * number.c: the one grammar of a number in the scene format
 * (docs/scene-format.md, "Values"), which every reader and the programs'
 * command lines (rt_scene_read_number) follow. */

/* The longest number read, in characters (a longer one is refused: no
 * double needs more, and the copy for strtod stays on the stack). */
#define RT__MAX_NUMBER_LENGTH 256

/* Whether text[0..length) is a number of the grammar:
 * [+-] digits [. digits] [(e|E) [+-] digits], at least one digit before
 * the exponent. */
int rt__number_syntax(const char *text, size_t length);

/* The C locale, for reading numbers whatever the process's locale: the
 * one place it is made; (locale_t)0 when out of memory.  freelocale
 * releases it. */
locale_t rt__c_locale_new(void);

/*
 * Reads text[0..length) as a number of the grammar, in `c_locale`
 * (rt__c_locale_new), into *value: RT_OK; RT_ERR_SYNTAX for text that is
 * no number of the grammar; RT_ERR_RANGE for a name of a special value
 * (nan, inf, infinity with a sign or not, in any case) or a number beyond
 * a double's range; RT_ERR_LIMIT for a number longer than
 * RT__MAX_NUMBER_LENGTH.  An underflow is no error (the nearest double).
 * Fills no message: rt__number_expected says what was expected.
 */
rt_status rt__number_read(locale_t c_locale, const char *text, size_t length,
                          double *value);

/*
 * Clinger's fast path of rt__number_read: 1 with *value set when
 * text[0..length) is a number of the grammar, of at most
 * RT__MAX_NUMBER_LENGTH characters, whose value it computes exactly
 * rounded in one IEEE operation (at most 19 significant digits making a
 * whole number w <= 2^53, times or over an exact power of ten); 0 for
 * everything else, which rt__number_read gives to strtod.  Where it
 * answers, its double is strtod's, bit for bit.  Reads no locale,
 * allocates nothing, thread-safe.
 */
int rt__number_fast(const char *text, size_t length, double *value);

/* What a message says was expected instead, for a status of
 * rt__number_read: "a number", "a finite number", "a number of at most
 * 256 characters". */
const char *rt__number_expected(rt_status status);

#endif /* RAYTRACE_LEXER_H */
