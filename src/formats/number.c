/*
 * number.c - the one grammar of a number in the scene format
 * (docs/scene-format.md, "Values"): an optional sign, digits with an
 * optional decimal point, an optional exponent, read in the C locale (made
 * here, the one place).  Every reader reads its numbers with
 * rt__number_read (through the lexer, lexer.h); the programs read their
 * command-line numbers with rt_scene_read_number, so that an option
 * accepts and refuses exactly what a scene file would.
 */
#include <ctype.h>
#include <locale.h>
#include <math.h>
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

rt_status rt__number_read(locale_t c_locale, const char *text, size_t length,
                          double *value)
{
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
