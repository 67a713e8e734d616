/*
 * test_lexer.c - the one lexer of the text formats (src/formats/lexer.h):
 * tokens with their line and column in a stream (NFF) and line by line
 * (.scn with its commas, OBJ and MTL with their continued lines), the
 * counts and the end of the text, the checks of the raw bytes, the one
 * number rule, and a token as every message shows it (the escaping rule of
 * names, base/error.h).
 */
#include <string.h>

#include "formats/lexer.h"
#include "testutil.h"

static rt_lexer open_text(const char *text, unsigned flags)
{
    rt_lexer lx;
    rt_error error;
    ck_assert_msg(rt__lex_open(&lx, text, strlen(text), "t", flags,
                               &error) == RT_OK,
                  "%s", error.message);
    return lx;
}

static void assert_token(const rt_token *t, const char *text, int line,
                         int column)
{
    ck_assert_msg(t->length == strlen(text) &&
                      memcmp(t->text, text, t->length) == 0,
                  "token `%.*s`, expected `%s`", (int)t->length, t->text,
                  text);
    ck_assert_int_eq(t->line, line);
    ck_assert_int_eq(t->column, column);
}

START_TEST(a_stream_crosses_lines_and_skips_comments)
{
    /* a byte-order mark is no column; CR is a blank; `#` ends a token */
    rt_lexer lx = open_text("\xEF\xBB\xBFs 1\r\n  # all of it\n\t2#3\n"
                            "  c\n",
                            0);
    rt_token t;
    static const struct {
        const char *text;
        int line, column;
    } want[] = {{"s", 1, 1}, {"1", 1, 3}, {"2", 3, 2}, {"c", 4, 3}};
    for (size_t i = 0; i < sizeof want / sizeof want[0]; i++) {
        ck_assert(rt__lex_next(&lx, &t));
        assert_token(&t, want[i].text, want[i].line, want[i].column);
    }
    ck_assert(!rt__lex_next(&lx, &t));
    ck_assert_int_eq(lx.tokens, 4);
    rt__lex_close(&lx);
}
END_TEST

START_TEST(a_peek_reads_nothing)
{
    rt_lexer lx = open_text("l 1 2 3\n0.5", 0);
    rt_token t, ahead;
    for (int i = 0; i < 4; i++)
        ck_assert(rt__lex_next(&lx, &t));
    ck_assert(rt__lex_peek(&lx, &ahead));
    assert_token(&ahead, "0.5", 2, 1);
    ck_assert_int_eq(lx.tokens, 4);
    ck_assert(rt__lex_next(&lx, &t));
    assert_token(&t, "0.5", 2, 1);
    ck_assert(!rt__lex_peek(&lx, &ahead));
    rt__lex_close(&lx);
}
END_TEST

START_TEST(a_line_is_a_statement_and_commas_are_tokens)
{
    rt_lexer lx = open_text("# header\n\n 0,1 , 2\n   \n3,,4 # z\n",
                            RT_LEX_LINES | RT_LEX_COMMAS);
    rt_token t;
    ck_assert(rt__lex_statement(&lx, &t));
    assert_token(&t, "0", 3, 2);
    const char *rest[] = {",", "1", ",", "2"};
    const int columns[] = {3, 4, 6, 8};
    for (int i = 0; i < 4; i++) {
        ck_assert(rt__lex_next(&lx, &t));
        assert_token(&t, rest[i], 3, columns[i]);
    }
    ck_assert(!rt__lex_next(&lx, &t));
    ck_assert(rt__lex_statement(&lx, &t));
    assert_token(&t, "3", 5, 1);
    ck_assert(rt__lex_next(&lx, &t));
    assert_token(&t, ",", 5, 2);
    ck_assert(rt__lex_next(&lx, &t));
    assert_token(&t, ",", 5, 3);
    ck_assert(!rt__lex_statement(&lx, &t));
    rt__lex_close(&lx);
    /* without RT_LEX_COMMAS a comma is part of a token */
    lx = open_text("1,5 2\n", RT_LEX_LINES);
    ck_assert(rt__lex_statement(&lx, &t));
    assert_token(&t, "1,5", 1, 1);
    rt__lex_close(&lx);
}
END_TEST

START_TEST(a_statement_skips_what_is_left_of_the_last)
{
    rt_lexer lx = open_text("v 1 2 3\nf 1 2 3\n", RT_LEX_LINES);
    rt_token t;
    ck_assert(rt__lex_statement(&lx, &t));
    assert_token(&t, "v", 1, 1);
    ck_assert(rt__lex_statement(&lx, &t));
    assert_token(&t, "f", 2, 1);
    ck_assert_int_eq(lx.tokens, 5);     /* skipped tokens are read */
    rt__lex_close(&lx);
}
END_TEST

START_TEST(a_backslash_at_the_end_of_a_line_continues_the_statement)
{
    unsigned obj = RT_LEX_LINES | RT_LEX_CONTINUATION;
    rt_lexer lx = open_text("f 1 2\\\n  3 \\ # more\n4\n\\\n\nv 0\n", obj);
    rt_token t;
    ck_assert(rt__lex_statement(&lx, &t));
    assert_token(&t, "f", 1, 1);
    ck_assert(rt__lex_next(&lx, &t));
    assert_token(&t, "1", 1, 3);
    ck_assert(rt__lex_next(&lx, &t));
    assert_token(&t, "2", 1, 5);        /* the backslash is removed */
    ck_assert(rt__lex_next(&lx, &t));
    assert_token(&t, "3", 2, 3);        /* a lone backslash is no token */
    ck_assert(rt__lex_next(&lx, &t));
    assert_token(&t, "4", 3, 1);
    ck_assert(!rt__lex_next(&lx, &t));
    /* a line of one backslash, then a blank line: an empty statement,
     * passed over */
    ck_assert(rt__lex_statement(&lx, &t));
    assert_token(&t, "v", 6, 1);
    rt__lex_close(&lx);
    /* a backslash inside a line is part of its token */
    lx = open_text("mtllib a\\ b.mtl\n", obj);
    ck_assert(rt__lex_statement(&lx, &t));
    ck_assert(rt__lex_next(&lx, &t));
    assert_token(&t, "a\\", 1, 8);
    rt__lex_close(&lx);
}
END_TEST

START_TEST(counts_and_the_end_of_the_text)
{
    rt_lexer lx = open_text("a b\n\n# c\nd\n", RT_LEX_LINES);
    ck_assert_int_eq(rt__lex_count(&lx, 1, NULL), 2);
    rt_lexer stream = open_text("a b\n\n# c\nd\n", 0);
    ck_assert_int_eq(rt__lex_count(&stream, 0, NULL), 3);
    ck_assert_int_eq(stream.tokens, 0);     /* the lexer stays where it is */
    int line, column;
    rt__lex_end(&lx, &line, &column);
    ck_assert_int_eq(line, 5);
    ck_assert_int_eq(column, 1);
    rt__lex_close(&lx);
    rt__lex_close(&stream);
    lx = open_text("\xEF\xBB\xBF" "ab", 0);
    rt__lex_end(&lx, &line, &column);
    ck_assert_int_eq(line, 1);
    ck_assert_int_eq(column, 3);
    rt__lex_close(&lx);
    /* a raised flag stops a count */
    rt_cancel *cancel;
    ck_assert_int_eq(rt_cancel_create(&cancel, NULL), RT_OK);
    rt_cancel_request(cancel);
    lx = open_text("a b c", 0);
    ck_assert_int_eq(rt__lex_count(&lx, 0, cancel), -1);
    rt__lex_close(&lx);
    rt_cancel_destroy(cancel);
}
END_TEST

/* The count of rt__lex_count, by reading: the statements, or the tokens
 * rt__lex_next gives, from where `from` stands. */
static long count_by_reading(const rt_lexer *from, int statements)
{
    rt_lexer lx = *from;
    rt_token t;
    long count = 0;
    while (statements ? rt__lex_statement(&lx, &t) : rt__lex_next(&lx, &t))
        count++;
    return count;
}

START_TEST(a_count_is_what_reading_one_by_one_finds)
{
    /* rt__lex_count finds the lines that hold a token, or the starts of
     * tokens, without cutting them: random texts of the bytes that matter
     * to the lexer, in every grammar, from the start and from a cursor
     * within a statement */
    static const char alphabet[] = " \t\r\v\f\n\n#,,ab1\\";
    static const unsigned grammars[] = {
        0, RT_LEX_COMMAS, RT_LEX_LINES, RT_LEX_LINES | RT_LEX_COMMAS,
        RT_LEX_LINES | RT_LEX_CONTINUATION};
    rt_test_rng rng = {41};
    char text[64];
    for (int i = 0; i < 4000; i++) {
        int n = rt_test_rng_below(&rng, (int)sizeof text);
        for (int k = 0; k < n; k++)
            text[k] = alphabet[rt_test_rng_below(&rng,
                                                 (int)sizeof alphabet - 1)];
        text[n] = '\0';
        if (n > 0 && text[n - 1] == '\r')
            text[n - 1] = 'a';  /* CR alone at the end: old Mac endings */
        for (size_t g = 0; g < sizeof grammars / sizeof grammars[0]; g++) {
            rt_lexer lx;
            rt_error error;
            if (rt__lex_open(&lx, text, (size_t)n, "t", grammars[g],
                             &error) != RT_OK)
                continue;       /* CR without any LF: refused */
            for (int step = 0; step < 3; step++) {
                /* statements: of a grammar of lines only */
                int kinds = grammars[g] & RT_LEX_LINES ? 2 : 1;
                for (int statements = 0; statements < kinds; statements++)
                    if (rt__lex_count(&lx, statements, NULL) !=
                        count_by_reading(&lx, statements))
                        ck_abort_msg("grammar %u, step %d: %ld %s counted, "
                                     "%ld read, in `%s`", grammars[g], step,
                                     rt__lex_count(&lx, statements, NULL),
                                     statements ? "statements" : "tokens",
                                     count_by_reading(&lx, statements),
                                     text);
                rt_token t;         /* on: into a statement, then past it */
                if (grammars[g] & RT_LEX_LINES)
                    step == 0 ? rt__lex_statement(&lx, &t)
                              : rt__lex_next(&lx, &t);
                else
                    rt__lex_next(&lx, &t);
            }
            rt__lex_close(&lx);
        }
    }
}
END_TEST

START_TEST(the_lexer_refuses_bytes_no_reader_can_take)
{
    static const struct {
        const char *text;
        size_t length;
        rt_status status;
        int line, column;
        const char *words;
    } cases[] = {
        {"1 2\n3\0", 6, RT_ERR_FORMAT, 2, 2, "found a NUL byte"},
        {"\xFF\xFE" "1\0", 4, RT_ERR_FORMAT, 0, 0, "UTF-16 (little-endian)"},
        {"1 2 3\r4 5 6\r", 12, RT_ERR_FORMAT, 0, 0, "old Mac line endings"},
        {"0\0 \0" "0\0 \0", 8, RT_ERR_FORMAT, 1, 2, "looks UTF-16"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        rt_lexer lx;
        rt_error error;
        ck_assert_int_eq(rt__lex_open(&lx, cases[i].text, cases[i].length,
                                      "b.scn", 0, &error),
                         cases[i].status);
        ck_assert_int_eq(error.line, cases[i].line);
        ck_assert_int_eq(error.column, cases[i].column);
        ck_assert_msg(strstr(error.message, cases[i].words) != NULL, "%s",
                      error.message);
    }
    /* the size is checked before a byte is read */
    rt_lexer lx;
    rt_error error;
    ck_assert_int_eq(rt__lex_open(&lx, "x", RT_MAX_SCENE_BYTES + 1, "big",
                                  0, &error),
                     RT_ERR_LIMIT);
}
END_TEST

START_TEST(numbers_follow_the_one_rule)
{
    rt_lexer lx = open_text("", 0);
    static const struct {
        const char *text;
        rt_status status;
        double value;
    } cases[] = {
        {"1.5", RT_OK, 1.5},     {"-.25", RT_OK, -0.25},
        {"2.", RT_OK, 2.0},      {"+1e3", RT_OK, 1000.0},
        {"1e-400", RT_OK, 0.0},  {"1,5", RT_ERR_SYNTAX, 0},
        {"0x10", RT_ERR_SYNTAX, 0}, {"1e", RT_ERR_SYNTAX, 0},
        {".", RT_ERR_SYNTAX, 0}, {"nan", RT_ERR_RANGE, 0},
        {"-Infinity", RT_ERR_RANGE, 0}, {"1e999", RT_ERR_RANGE, 0},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        rt_token t = {cases[i].text, strlen(cases[i].text), 1, 1};
        double v = -7;
        ck_assert_int_eq(rt__lex_number(&lx, &t, &v), cases[i].status);
        if (cases[i].status == RT_OK)
            ck_assert_double_eq(v, cases[i].value);
    }
    char digits[RT__MAX_NUMBER_LENGTH + 2];
    memset(digits, '1', sizeof digits);
    rt_token t = {digits, RT__MAX_NUMBER_LENGTH, 1, 1};
    double v;
    ck_assert_int_eq(rt__lex_number(&lx, &t, &v), RT_OK);
    digits[0] = '0';
    digits[1] = '.';
    t.length = RT__MAX_NUMBER_LENGTH;
    ck_assert_int_eq(rt__lex_number(&lx, &t, &v), RT_OK);
    t.length = RT__MAX_NUMBER_LENGTH + 1;
    ck_assert_int_eq(rt__lex_number(&lx, &t, &v), RT_ERR_LIMIT);
    ck_assert_str_eq(rt__number_expected(RT_ERR_LIMIT),
                     "a number of at most 256 characters");
    ck_assert_str_eq(rt__number_expected(RT_ERR_RANGE), "a finite number");
    ck_assert_str_eq(rt__number_expected(RT_ERR_SYNTAX), "a number");
    rt__lex_close(&lx);
}
END_TEST

START_TEST(a_token_is_shown_as_names_are)
{
    char out[RT_TOKEN_SHOWN_SIZE], name[64];
    static const char *const texts[] = {
        "plain", "caf\xC3\xA9", "bell\x07", "esc\x1B[2J", "back\\slash",
        "bad\xFF", "c1\xC2\x9B"};
    static const char *const shown[] = {
        "plain", "caf\xC3\xA9", "bell\\x07", "esc\\x1B[2J", "back\\\\slash",
        "bad\\xFF", "c1\\xC2\\x9B"};
    for (size_t i = 0; i < sizeof texts / sizeof texts[0]; i++) {
        ck_assert_str_eq(rt__show_token(texts[i], strlen(texts[i]), out),
                         shown[i]);
        rt__escape_name(texts[i], name, sizeof name);
        ck_assert_str_eq(name, out);
    }
    /* 40 bytes, then "..."; a character never cut in two */
    char long_token[50];
    memset(long_token, 'a', sizeof long_token);
    ck_assert_uint_eq(strlen(rt__show_token(long_token, 41, out)), 43);
    ck_assert_str_eq(out + 40, "...");
    ck_assert_uint_eq(strlen(rt__show_token(long_token, 40, out)), 40);
    memcpy(long_token + 39, "\xC3\xA9", 2);
    rt__show_token(long_token, 45, out);
    ck_assert_uint_eq(strlen(out), 42);
    ck_assert_str_eq(out + 39, "...");
    /* every byte escaped still fits */
    char controls[RT_TOKEN_SHOWN_BYTES + 5];
    memset(controls, 1, sizeof controls);
    rt__show_token(controls, sizeof controls, out);
    ck_assert_uint_eq(strlen(out), 4 * RT_TOKEN_SHOWN_BYTES + 3);
}
END_TEST

START_TEST(a_refusal_names_the_token_where_it_stands)
{
    rt_error error;
    rt_token t = {"x\x1b", 2, 3, 7};
    ck_assert_int_eq(rt__token_refuse(&error, RT_ERR_SYNTAX, "f.scn", &t,
                                      "%d values", 3),
                     RT_ERR_SYNTAX);
    ck_assert_str_eq(error.message,
                     "f.scn:3:7: expected 3 values, found `x\\x1B`");
    ck_assert_int_eq(error.line, 3);
    ck_assert_int_eq(error.column, 7);
    ck_assert(rt__token_is(&(rt_token){"usemtl", 6, 1, 1}, "usemtl"));
    ck_assert(!rt__token_is(&(rt_token){"usemtl", 6, 1, 1}, "use"));
}
END_TEST

static Suite *lexer_suite(void)
{
    Suite *s = suite_create("lexer");
    TCase *tc = tcase_create("tokens");
    tcase_add_test(tc, a_stream_crosses_lines_and_skips_comments);
    tcase_add_test(tc, a_peek_reads_nothing);
    tcase_add_test(tc, a_line_is_a_statement_and_commas_are_tokens);
    tcase_add_test(tc, a_statement_skips_what_is_left_of_the_last);
    tcase_add_test(tc,
                   a_backslash_at_the_end_of_a_line_continues_the_statement);
    tcase_add_test(tc, counts_and_the_end_of_the_text);
    tcase_add_test(tc, a_count_is_what_reading_one_by_one_finds);
    suite_add_tcase(s, tc);
    tc = tcase_create("bytes");
    tcase_add_test(tc, the_lexer_refuses_bytes_no_reader_can_take);
    tcase_add_test(tc, numbers_follow_the_one_rule);
    tcase_add_test(tc, a_token_is_shown_as_names_are);
    tcase_add_test(tc, a_refusal_names_the_token_where_it_stands);
    suite_add_tcase(s, tc);
    return s;
}

RT_CHECK_MAIN(lexer_suite)
