/*
 * test_number_fast.c - the one number rule reads every number as strtod
 * does in the C locale, bit for bit, whichever way it takes
 * (src/formats/number.c: Clinger's fast path where it is exact, strtod
 * otherwise): random decimal strings of many shapes (1 to 25 digits, a
 * point or none, exponents from -330 to 330, signs), shapes that sit on
 * the fast path's edges (w near 2^53, powers of ten near 10^22 and
 * 10^(22 + 15)), hand-picked edges (signed zeros, leading zeros,
 * underflow to subnormals and zero, the largest double, exponents of many
 * digits), and the printed forms of random doubles (%.17g, which must
 * read back to the double itself, %.15g, %.9g, %.7g).  It also checks
 * that the fast path answers the shapes scene files are made of, and
 * declines what it cannot do exactly.
 *
 * Under .ci/memcheck (RT_TEST_MEMCHECK) the random sweeps take 1/100 of
 * their strings, on the same shapes.
 */
#define _POSIX_C_SOURCE 200809L
#include <locale.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "formats/lexer.h"
#include "testutil.h"

/* The random strings of a sweep (divided by 100 under memcheck). */
#define SWEEP 600000

static long sweep_size(void)
{
    return rt_test_memcheck() ? SWEEP / 100 : SWEEP;
}

static uint64_t bits_of(double v)
{
    uint64_t b;
    memcpy(&b, &v, sizeof b);
    return b;
}

/* strtod in the C locale over text[0..length): the reference. */
static double reference(locale_t c, const char *text, size_t length)
{
    char copy[512];
    if (length >= sizeof copy)
        ck_abort_msg("a test number of %zu characters", length);
    memcpy(copy, text, length);
    copy[length] = '\0';
    locale_t previous = uselocale(c);
    double v = strtod(copy, NULL);
    uselocale(previous);
    return v;
}

/*
 * Checks one number of the grammar: rt__number_read gives strtod's double
 * bit for bit (or RT_ERR_RANGE where strtod's is not finite), and the fast
 * path, where it answers, gives it too.  Returns whether the fast path
 * answered.  (Check's ck_assert records every assertion that holds: the
 * sweeps call ck_abort_msg on a failure only, to stay fast.)
 */
static int check_one(locale_t c, const char *text)
{
    size_t length = strlen(text);
    double want = reference(c, text, length), got = 0, fast = 0;
    rt_status status = rt__number_read(c, text, length, &got);
    if (!isfinite(want) && status != RT_ERR_RANGE)
        ck_abort_msg("`%s`: status %d, expected RT_ERR_RANGE", text,
                     (int)status);
    if (isfinite(want) && status != RT_OK)
        ck_abort_msg("`%s`: status %d", text, (int)status);
    if (isfinite(want) && bits_of(got) != bits_of(want))
        ck_abort_msg("`%s`: read %a, strtod %a", text, got, want);
    int answered = rt__number_fast(text, length, &fast);
    if (answered && (!isfinite(want) || bits_of(fast) != bits_of(want)))
        ck_abort_msg("`%s`: fast path %a, strtod %a", text, fast, want);
    return answered;
}

/* Appends n random digits at *at. */
static void digits(rt_test_rng *rng, char **at, int n)
{
    for (int i = 0; i < n; i++)
        *(*at)++ = (char)('0' + rt_test_rng_below(rng, 10));
}

/* A random number of the grammar: a sign or none, `whole` digits, a
 * point with `fraction` digits (point: 0 none, 1 one), an exponent or
 * none. */
static void random_number(rt_test_rng *rng, char *out, int whole,
                          int point, int fraction, int exponent_given,
                          int exponent)
{
    static const char *signs[] = {"", "", "-", "+"};
    char *at = out;
    const char *sign = signs[rt_test_rng_below(rng, 4)];
    at += sprintf(at, "%s", sign);
    digits(rng, &at, whole);
    if (point) {
        *at++ = '.';
        digits(rng, &at, fraction);
    }
    if (exponent_given)
        at += sprintf(at, "%c%s%d", rt_test_rng_below(rng, 2) ? 'e' : 'E',
                      exponent >= 0 && rt_test_rng_below(rng, 2) ? "+" : "",
                      exponent);
    *at = '\0';
}

START_TEST(random_decimals_read_as_strtod_reads_them)
{
    locale_t c = rt__c_locale_new();
    ck_assert(c != (locale_t)0);
    rt_test_rng rng = {29};
    char text[128];
    long n = sweep_size(), fast = 0;
    for (long i = 0; i < n; i++) {
        int total = 1 + rt_test_rng_below(&rng, 25);  /* 1..25 digits */
        int point = rt_test_rng_below(&rng, 3) > 0;
        int whole = point ? rt_test_rng_below(&rng, total + 1) : total;
        int exponent_given = rt_test_rng_below(&rng, 3) > 0;
        int exponent = rt_test_rng_below(&rng, 661) - 330;
        random_number(&rng, text, whole, point, total - whole,
                      exponent_given, exponent);
        fast += check_one(c, text);
    }
    /* the shapes near the fast path: about a third of them take it */
    ck_assert_msg(fast > n / 20, "the fast path answered %ld of %ld", fast,
                  n);
    ck_assert_msg(fast < n, "the fast path answered all %ld", n);
    freelocale(c);
}
END_TEST

START_TEST(numbers_on_the_fast_paths_edges_read_as_strtod_reads_them)
{
    locale_t c = rt__c_locale_new();
    ck_assert(c != (locale_t)0);
    rt_test_rng rng = {2953};
    char text[128];
    long n = sweep_size(), fast = 0;
    const uint64_t two53 = (uint64_t)1 << 53;
    for (long i = 0; i < n; i++) {
        char *at = text;
        if (rt_test_rng_below(&rng, 2)) {
            /* w within 1000 of 2^53, its point anywhere, q near +-22 and
             * near 22 + 15 */
            uint64_t w = two53 - 1000 + (uint64_t)rt_test_rng_below(&rng, 2001);
            char number[32];
            int length = sprintf(number, "%llu", (unsigned long long)w);
            int cut = rt_test_rng_below(&rng, length + 1);
            at += sprintf(at, "%s%.*s.%s", rt_test_rng_below(&rng, 2) ? "-"
                                                                      : "",
                          cut, number, number + cut);
            sprintf(at, "e%d", rt_test_rng_below(&rng, 100) - 40);
        } else {
            /* 1 to 19 digits (with zeros at either end), q in -30..45 */
            int zeros = rt_test_rng_below(&rng, 4);
            for (int z = 0; z < zeros; z++)
                *at++ = '0';
            digits(&rng, &at, 1 + rt_test_rng_below(&rng, 19));
            zeros = rt_test_rng_below(&rng, 4);
            for (int z = 0; z < zeros; z++)
                *at++ = '0';
            sprintf(at, "e%d", rt_test_rng_below(&rng, 76) - 30);
        }
        fast += check_one(c, text);
    }
    ck_assert_msg(fast > n / 4, "the fast path answered %ld of %ld", fast,
                  n);
    freelocale(c);
}
END_TEST

START_TEST(hand_picked_edges_read_as_strtod_reads_them)
{
    static const char *cases[] = {
        "0", "-0", "+0", "0e5", "-0e5", "-0e-5", "0.0", "-0.000", "0.",
        ".0", "-.0e0", "000", "00000123", "000.000", "007.5000",
        "0.000000000000000000001", "-0.000000000000000000001",
        "0.0000000000000000000000000000000000000001", "1e-400", "-1e-400",
        "1e-324", "2.4703282292062327e-324", "2.4703282292062328e-324",
        "4.9406564584124654e-324", "5e-324", "1e-320", "-1e-310",
        "2.2250738585072011e-308", "2.2250738585072014e-308",
        "2.2250738585072012e-308", "1e308", "1.7976931348623157e308",
        "1.7976931348623158e308", "1.7976931348623159e308", "1.8e308",
        "1e309", "-1e309", "9007199254740991", "9007199254740992",
        "9007199254740993", "9007199254740994", "9007199254740995",
        "-9007199254740993", "9007199254740992e22", "9007199254740993e22",
        "9007199254740992e-22", "9007199254740993e-22", "1e22", "1e23",
        "1e-22", "1e-23", "1e37", "1e38", "1e15e", "123456789012345678e20",
        "900719925474099e22", "900719925474099e23", "90071992547409e24",
        "1e0000000000000000000000000001", "1e-0000000000000000000000000400",
        "1e99999999999999999999", "-1e99999999999999999999",
        "1e-99999999999999999999", "-1e-99999999999999999999",
        "0e99999999999999999999", "-0e-99999999999999999999", ".5", "5.",
        "-.5e1", "+.5E+1", "1E5", "1e+5", "1e-5", "9999999999999999999",
        "99999999999999999999", "18446744073709551615",
        "18446744073709551616", "0.1", "0.2", "0.3", "0.30000000000000004",
        "3.141592653589793", "2.718281828459045", "1.0000000000000002",
        "0.9999999999999999", "4503599627370496.5", "4503599627370497.5",
        "1.00000000000000011102230246251565404236316680908203125",
        "1.00000000000000011102230246251565404236316680908203124",
        "1.00000000000000011102230246251565404236316680908203126",
        "7.2057594037927933e16", "123.456e-2", "1000000000000000000000000",
        "0.0000000000000000000000000000000000000000000001e46",
    };
    locale_t c = rt__c_locale_new();
    ck_assert(c != (locale_t)0);
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        /* "1e15e" is no number: the fast path declines it */
        if (strcmp(cases[i], "1e15e") == 0) {
            double v;
            ck_assert(!rt__number_fast(cases[i], strlen(cases[i]), &v));
            ck_assert_int_eq(rt__number_read(c, cases[i], strlen(cases[i]),
                                             &v),
                             RT_ERR_SYNTAX);
            continue;
        }
        check_one(c, cases[i]);
    }
    /* the sign of zero survives either way */
    double v;
    ck_assert_int_eq(rt__number_read(c, "-0", 2, &v), RT_OK);
    ck_assert(v == 0 && signbit(v));
    ck_assert_int_eq(rt__number_read(c, "-0e400", 6, &v), RT_OK);
    ck_assert(v == 0 && signbit(v));
    ck_assert_int_eq(rt__number_read(c, "-1e-400", 7, &v), RT_OK);
    ck_assert(v == 0 && signbit(v));
    ck_assert_int_eq(rt__number_read(c, "0e5", 3, &v), RT_OK);
    ck_assert(v == 0 && !signbit(v));
    freelocale(c);
}
END_TEST

START_TEST(printed_doubles_read_back_as_strtod_reads_them)
{
    locale_t c = rt__c_locale_new();
    ck_assert(c != (locale_t)0);
    rt_test_rng rng = {1990};
    char text[64];
    static const char *formats[] = {"%.17g", "%.15g", "%.9g", "%.7g"};
    long n = sweep_size() / 2;
    for (long i = 0; i < n; i++) {
        double d;
        if (i % 2) {
            /* any finite double, subnormals included */
            uint64_t b = rt_test_rng_next(&rng);
            memcpy(&d, &b, sizeof d);
            if (!isfinite(d))
                continue;
        } else {
            /* the scale of scene coordinates */
            d = rt_test_rng_range(&rng, -1, 1) *
                pow(10, rt_test_rng_below(&rng, 13) - 6);
        }
        for (int f = 0; f < 4; f++) {
            snprintf(text, sizeof text, formats[f], d);
            check_one(c, text);
            double back = 0;
            if (f == 0 &&       /* 17 digits name the double itself */
                (rt__number_read(c, text, strlen(text), &back) != RT_OK ||
                 bits_of(back) != bits_of(d)))
                ck_abort_msg("`%s` read back as %a, not %a", text, back, d);
        }
    }
    freelocale(c);
}
END_TEST

START_TEST(the_fast_path_answers_the_numbers_scene_files_hold)
{
    rt_test_rng rng = {708};
    char text[64];
    double v;
    long n = sweep_size() / 10;
    for (long i = 0; i < n; i++) {
        /* coordinates as exporters print them, whole numbers (indices,
         * colours), and 15 digits of the unit scale */
        double d = rt_test_rng_range(&rng, -1000, 1000);
        static const char *formats[] = {"%.7g", "%.9g", "%.6f", "%.15g"};
        snprintf(text, sizeof text, formats[i % 4], d);
        if (!rt__number_fast(text, strlen(text), &v))
            ck_abort_msg("the fast path declined `%s`", text);
        snprintf(text, sizeof text, "%d", rt_test_rng_below(&rng, 1 << 30));
        if (!rt__number_fast(text, strlen(text), &v))
            ck_abort_msg("the fast path declined `%s`", text);
    }
}
END_TEST

START_TEST(the_fast_path_declines_what_strtod_must_read)
{
    /* each of these needs more than one exact operation, or is no
     * number: rt__number_read takes the slow way, with its refusals */
    static const char *declined[] = {
        "9007199254740993", "12345678901234567890", "1e23x", "1e-23",
        "1e400", "4.9e-324", "1.7976931348623157e308", "", "-", ".", "e5",
        "1e", "1e+", "0x10", "nan", "inf", "1,5", " 1", "1 ", "1..2",
        "9007199254740993e-5", "1e38"};
    double v;
    for (size_t i = 0; i < sizeof declined / sizeof declined[0]; i++)
        ck_assert_msg(!rt__number_fast(declined[i], strlen(declined[i]), &v),
                      "the fast path answered `%s`", declined[i]);
    /* the length limit stands before any value: 257 characters, a
     * number the fast path could otherwise read (1 and 255 zeros after
     * the point, then 1) */
    char longest[RT__MAX_NUMBER_LENGTH + 2];
    longest[0] = '1';
    longest[1] = '.';
    memset(longest + 2, '0', RT__MAX_NUMBER_LENGTH - 2);
    longest[RT__MAX_NUMBER_LENGTH] = '1';
    longest[RT__MAX_NUMBER_LENGTH + 1] = '\0';
    ck_assert(!rt__number_fast(longest, RT__MAX_NUMBER_LENGTH + 1, &v));
    locale_t c = rt__c_locale_new();
    ck_assert(c != (locale_t)0);
    ck_assert_int_eq(rt__number_read(c, longest, RT__MAX_NUMBER_LENGTH + 1,
                                     &v),
                     RT_ERR_LIMIT);
    /* 256 characters are read (trailing zeros: past 19 digits, strtod) */
    ck_assert_int_eq(rt__number_read(c, longest, RT__MAX_NUMBER_LENGTH, &v),
                     RT_OK);
    ck_assert(v == 1.0);
    longest[3] = '5';   /* 1.05000...: 20 significant digits at most */
    ck_assert(!rt__number_fast(longest, RT__MAX_NUMBER_LENGTH, &v));
    ck_assert(rt__number_fast(longest, 4, &v) && v == 1.05);
    freelocale(c);
}
END_TEST

static Suite *number_fast_suite(void)
{
    Suite *s = suite_create("number_fast");
    TCase *tc = tcase_create("strtod");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, random_decimals_read_as_strtod_reads_them);
    tcase_add_test(tc,
                   numbers_on_the_fast_paths_edges_read_as_strtod_reads_them);
    tcase_add_test(tc, hand_picked_edges_read_as_strtod_reads_them);
    tcase_add_test(tc, printed_doubles_read_back_as_strtod_reads_them);
    suite_add_tcase(s, tc);
    tc = tcase_create("fast path");
    tcase_add_test(tc, the_fast_path_answers_the_numbers_scene_files_hold);
    tcase_add_test(tc, the_fast_path_declines_what_strtod_must_read);
    suite_add_tcase(s, tc);
    return s;
}

RT_CHECK_MAIN(number_fast_suite)
