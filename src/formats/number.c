/*
 * number.c - the one grammar of a number in the scene format
 * (docs/scene-format.md, "Values"): an optional sign, digits with an
 * optional decimal point, an optional exponent, read in the C locale.  The
 * .scn reader checks its tokens with rt__number_syntax; the programs read
 * their command-line numbers with rt_scene_read_number, so that an option
 * accepts and refuses exactly what a scene file would.
 */
#include <ctype.h>
#include <locale.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "base/error.h"
#include "formats/reader.h"

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

/* text[0..length) as a message shows it: at most 40 characters, a byte
 * that is not printable ASCII as '?', then "..." when cut. */
static const char *show(const char *text, size_t length, char *out,
                        size_t size)
{
    size_t n = length < 40 ? length : 40;
    if (n > size - 4)
        n = size - 4;
    for (size_t i = 0; i < n; i++) {
        unsigned char c = (unsigned char)text[i];
        out[i] = c >= 0x20 && c < 0x7f ? (char)c : '?';
    }
    strcpy(out + n, length > n ? "..." : "");
    return out;
}

rt_status rt_scene_read_number(const char *text, size_t length,
                               double *value, rt_error *error)
{
    if (text == NULL || value == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "expected a text and a place for its value");
    char shown[48];
    if (!rt__number_syntax(text, length)) {
        int special = names_a_special_value(text, length);
        return rt__error_set(error, special ? RT_ERR_RANGE : RT_ERR_SYNTAX,
                             NULL, 0, 0, "expected %s, found `%s`",
                             special ? "a finite number" : "a number",
                             show(text, length, shown, sizeof shown));
    }
    if (length > RT__MAX_NUMBER_LENGTH)
        return rt__error_set(error, RT_ERR_LIMIT, NULL, 0, 0,
                             "expected a number of at most %d characters, "
                             "found `%s`", RT__MAX_NUMBER_LENGTH,
                             show(text, length, shown, sizeof shown));
    char copy[RT__MAX_NUMBER_LENGTH + 1];
    memcpy(copy, text, length);
    copy[length] = '\0';
    /* the C locale's decimal point whatever the caller's locale */
    locale_t c_locale = newlocale(LC_NUMERIC_MASK, "C", (locale_t)0);
    if (c_locale == (locale_t)0)
        return rt__error_set(error, RT_ERR_NOMEM, NULL, 0, 0,
                             "out of memory for the C locale");
    locale_t previous = uselocale(c_locale);
    double v = strtod(copy, NULL);
    uselocale(previous);
    freelocale(c_locale);
    /* an underflow is no error: a subnormal (or zero) is the nearest
     * double, as the readers take it */
    if (!isfinite(v))
        return rt__error_set(error, RT_ERR_RANGE, NULL, 0, 0,
                             "expected a finite number, found `%s` (beyond "
                             "a double's range)",
                             show(text, length, shown, sizeof shown));
    *value = v;
    return RT_OK;
}
