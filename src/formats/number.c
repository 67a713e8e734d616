/*
 * number.c - the one grammar of a number in the scene format
 * (docs/scene-format.md, "Values"): an optional sign, digits with an
 * optional decimal point, an optional exponent, read in the C locale (made
 * here, the one place).  Every reader reads its numbers with
 * rt__number_read (through the lexer, lexer.h); the programs read their
 * command-line numbers with rt_scene_read_number, so that an option
 * accepts and refuses exactly what a scene file would.
 *
 * A number is read as the nearest double (round to nearest, ties to
 * even).  The common case - at most 19 significant digits making a whole
 * number w <= 2^53, and a power of ten 10^q that is itself a double
 * (|q| <= 22, or w 10^(q - 22) still a whole number <= 2^53) - is Clinger's
 * fast path (W. D. Clinger, "How to read floating point numbers
 * accurately", PLDI 1990): w and 10^q are exact, so one IEEE multiply or
 * divide gives the correctly rounded value, read in one pass with no copy.
 * Every other number (more digits, larger powers, underflow, and every
 * refusal) goes to strtod in the C locale, which rounds correctly too: the
 * two give the same double, bit for bit (tests/test_number_fast.c).
 */
#include <ctype.h>
#include <float.h>
#include <locale.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "base/error.h"
#include "formats/lexer.h"

/* The digits of a macro's value, as a string literal. */
#define TEXT_OF(macro) LITERAL(macro)
#define LITERAL(text) #text

int rt__number_syntax(const char *text, size_t length)
{
    const char *c = text, *e = text + length;
    if (c < e && (*c == '+' || *c == '-'))
        c++;
    int digits = 0;
    while (c < e && isdigit((unsigned char)*c))
        c++, digits++;
    if (c < e && *c == '.')
        for (c++; c < e && isdigit((unsigned char)*c); c++)
            digits++;
    if (digits > 0 && c < e && (*c == 'e' || *c == 'E')) {
        c++;
        if (c < e && (*c == '+' || *c == '-'))
            c++;
        int exponent_digits = 0;
        while (c < e && isdigit((unsigned char)*c))
            c++, exponent_digits++;
        if (exponent_digits == 0)
            digits = 0;
    }
    return digits > 0 && c == e;
}

/* "nan", "inf", "infinity" with an optional sign, in any case: refused as
 * out of range (not finite) rather than as text that is no number. */
static int names_a_special_value(const char *text, size_t length)
{
    if (length > 0 && (*text == '+' || *text == '-'))
        text++, length--;
    return length >= 3 && (strncasecmp(text, "nan", 3) == 0 ||
                           strncasecmp(text, "inf", 3) == 0);
}

locale_t rt__c_locale_new(void)
{
    return newlocale(LC_NUMERIC_MASK, "C", (locale_t)0);
}

/* Clinger's fast path needs IEEE double arithmetic, each operation rounded
 * once to a double: not the x87's wider intermediates (FLT_EVAL_METHOD
 * other than 0), nor -ffast-math, which may turn a division into a
 * multiplication by a rounded reciprocal.  Elsewhere every number goes to
 * strtod. */
#if defined(FLT_EVAL_METHOD) && FLT_EVAL_METHOD == 0 && \
    !defined(__FAST_MATH__) && FLT_RADIX == 2 && DBL_MANT_DIG == 53
#define FAST_PATH 1
#else
#define FAST_PATH 0
#endif

/* The powers of ten that are doubles exactly (5^22 < 2^53 <= 5^23). */
static const double exact_powers[] = {
    1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
    1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
#define MAX_EXACT_POWER 22
/* 2^53: every whole number up to it is a double. */
#define MAX_EXACT_WHOLE ((uint64_t)1 << 53)
/* The most significant digits summed in 64 bits (10^19 < 2^64). */
#define MAX_FAST_DIGITS 19
/* An exponent's digits are summed up to this, then only checked: no
 * number of at most 256 characters needs a larger one for its value
 * (strtod is asked beyond the fast path's 10^(22 + 15) anyway). */
#define EXPONENT_CAP 100000

/* Adds the digits from c on to *w (which wraps past MAX_FAST_DIGITS of
 * them: the caller then leaves it), the leading zeros first skipped when
 * `leading` (they change nothing); returns the first byte that is no
 * digit, and counts the digits added in *significant. */
static const char *sum_digits(const char *c, const char *e, int leading,
                              uint64_t *w, long *significant)
{
    if (leading)
        while (c < e && *c == '0')
            c++;
    const char *first = c;
    uint64_t sum = *w;
    for (unsigned d; c < e && (d = (unsigned)(*c - '0')) < 10; c++)
        sum = 10 * sum + d;
    *w = sum;
    *significant += c - first;
    return c;
}

int rt__number_fast(const char *text, size_t length, double *value)
{
#if FAST_PATH
    if (length > RT__MAX_NUMBER_LENGTH)
        return 0;
    const char *c = text, *e = text + length;
    int negative = 0;
    if (c < e && (*c == '+' || *c == '-'))
        negative = *c++ == '-';
    uint64_t w = 0;
    long significant = 0;       /* the digits of w */
    const char *first = c;
    c = sum_digits(c, e, 1, &w, &significant);
    long q = 0;                 /* the power of ten of w */
    int any = c > first;        /* a digit before the exponent */
    if (c < e && *c == '.') {
        const char *fraction = c + 1;
        c = sum_digits(fraction, e, significant == 0, &w, &significant);
        q = -(long)(c - fraction);
        any |= c > fraction;
    }
    if (!any || significant > MAX_FAST_DIGITS)
        return 0;
    if (c < e && (*c == 'e' || *c == 'E')) {
        c++;
        int minus = 0;
        if (c < e && (*c == '+' || *c == '-'))
            minus = *c++ == '-';
        const char *digits = c;
        long exponent = 0;
        for (; c < e && (unsigned)(*c - '0') < 10; c++)
            if (exponent < EXPONENT_CAP)
                exponent = 10 * exponent + (*c - '0');
        if (c == digits)
            return 0;
        q += minus ? -exponent : exponent;
    }
    if (c != e)
        return 0;
    if (w == 0) {               /* whatever the exponent: a signed zero */
        *value = negative ? -0.0 : 0.0;
        return 1;
    }
    if (w > MAX_EXACT_WHOLE)
        return 0;
    if (q > MAX_EXACT_POWER) {
        /* w 10^(q - 22) may still be a whole number of at most 2^53:
         * then the value is it times 10^22, one rounding again. */
        for (; q > MAX_EXACT_POWER; q--) {
            if (w > MAX_EXACT_WHOLE / 10)
                return 0;
            w *= 10;
        }
    }
    if (q < -MAX_EXACT_POWER)
        return 0;
    /* the sign first: a negative value is rounded as itself */
    double v = negative ? -(double)w : (double)w;
    *value = q >= 0 ? v * exact_powers[q] : v / exact_powers[-q];
    return 1;
#else
    (void)text, (void)length, (void)value;
    return 0;
#endif
}

rt_status rt__number_read(locale_t c_locale, const char *text, size_t length,
                          double *value)
{
    if (rt__number_fast(text, length, value))
        return RT_OK;
    if (!rt__number_syntax(text, length))
        return names_a_special_value(text, length) ? RT_ERR_RANGE
                                                   : RT_ERR_SYNTAX;
    if (length > RT__MAX_NUMBER_LENGTH)
        return RT_ERR_LIMIT;
    char copy[RT__MAX_NUMBER_LENGTH + 1];
    memcpy(copy, text, length);
    copy[length] = '\0';
    /* the C locale's decimal point whatever the caller's locale */
    locale_t previous = uselocale(c_locale);
    double v = strtod(copy, NULL);
    uselocale(previous);
    /* an underflow is no error: a subnormal (or zero) is the nearest
     * double */
    if (!isfinite(v))
        return RT_ERR_RANGE;
    *value = v;
    return RT_OK;
}

const char *rt__number_expected(rt_status status)
{
    switch (status) {
    case RT_ERR_RANGE:
        return "a finite number";
    case RT_ERR_LIMIT:
        return "a number of at most " TEXT_OF(RT__MAX_NUMBER_LENGTH)
               " characters";
    default:
        return "a number";
    }
}

rt_status rt_scene_read_number(const char *text, size_t length,
                               double *value, rt_error *error)
{
    if (text == NULL || value == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "expected a text and a place for its value");
    locale_t c_locale = rt__c_locale_new();
    if (c_locale == (locale_t)0)
        return rt__error_set(error, RT_ERR_NOMEM, NULL, 0, 0,
                             "cannot create the C locale");
    rt_status status = rt__number_read(c_locale, text, length, value);
    freelocale(c_locale);
    if (status == RT_OK)
        return RT_OK;
    char shown[RT_TOKEN_SHOWN_SIZE];
    /* a number of the grammar beyond a double's range */
    const char *beyond = status == RT_ERR_RANGE &&
                                 rt__number_syntax(text, length)
                             ? " (beyond a double's range)"
                             : "";
    return rt__error_set(error, status, NULL, 0, 0,
                         "expected %s, found `%s`%s",
                         rt__number_expected(status),
                         rt__show_token(text, length, shown), beyond);
}
