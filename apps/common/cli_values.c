/*
 * cli_values.c - the values of command-line options (see cli_values.h).
 * Every number goes through the library's rt_scene_read_number, the
 * grammar of the scene files, so that there is one rule for a number
 * whether it comes from a file or from the command line.
 */
#include "cli_values.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define MAX_LIST 6              /* the longest list: a light with colour */

void cli_format_number(double value, char *out, size_t size)
{
    if (value == floor(value) && fabs(value) < 1e15)
        snprintf(out, size, "%.0f", value);
    else
        snprintf(out, size, "%g", value);
}

/* The numbers of a comma-separated list text, count_min..count_max of
 * them (at most MAX_LIST), into out[]; where each starts and how long it
 * is into pieces[] and lengths[].  Returns how many, or 0 when the text is
 * not such a list. */
static int read_list(const char *text, int count_min, int count_max,
                     double *out, const char **pieces, size_t *lengths)
{
    int n = 0;
    for (const char *at = text;;) {
        size_t length = strcspn(at, ",");
        if (n == count_max || n == MAX_LIST ||
            rt_scene_read_number(at, length, &out[n], NULL) != RT_OK)
            return 0;
        pieces[n] = at;
        lengths[n++] = length;
        if (at[length] == '\0')
            break;
        at += length + 1;
    }
    return n >= count_min ? n : 0;
}

/* A range failure of `value` (read from piece[0..length)): expected
 * `what`, written by the caller into problem->expected. */
static cli_read out_of_range(cli_problem *problem, double value,
                             const char *piece, size_t length)
{
    problem->value = value;
    problem->piece = piece;
    problem->piece_length = length;
    return CLI_READ_RANGE;
}

static int is_whole(double v)
{
    return v == floor(v);
}

static int is_square(double n)
{
    double root = floor(sqrt(n) + 0.5);
    return root * root == n;
}

cli_read cli_read_integer(const char *text, double min, double max,
                          int square, int *out, cli_problem *problem)
{
    char low[32], high[32];
    cli_format_number(min, low, sizeof low);
    cli_format_number(max, high, sizeof high);
    snprintf(problem->expected, sizeof problem->expected, "%s in %s..%s",
             square ? "a square (1, 4, 9, 16, ...)" : "an integer", low,
             high);
    double v;
    if (rt_scene_read_number(text, strlen(text), &v, NULL) != RT_OK ||
        !is_whole(v))
        return CLI_READ_SYNTAX;
    if (v < min || v > max)
        return out_of_range(problem, v, text, strlen(text));
    if (square && !is_square(v))
        return CLI_READ_SYNTAX;
    *out = (int)v;
    return CLI_READ_OK;
}

void cli_real_limits(double min, double max, unsigned bounds, char *out,
                     size_t size)
{
    char low[32], high[32];
    int open_min = (bounds & CLI_BOUND_OPEN_MIN) != 0;
    cli_format_number(min, low, sizeof low);
    cli_format_number(max, high, sizeof high);
    if (isinf(max))
        snprintf(out, size, "a number %s %s", open_min ? ">" : ">=", low);
    else
        snprintf(out, size, "a number in %c%s, %s%c", open_min ? '(' : '[',
                 low, high, bounds & CLI_BOUND_CLOSED_MAX ? ']' : ')');
}

cli_read cli_read_real(const char *text, double min, double max,
                       unsigned bounds, double *out, cli_problem *problem)
{
    cli_real_limits(min, max, bounds, problem->expected,
                    sizeof problem->expected);
    double v;
    if (rt_scene_read_number(text, strlen(text), &v, NULL) != RT_OK)
        return CLI_READ_SYNTAX;
    int max_allowed = isinf(max) || (bounds & CLI_BOUND_CLOSED_MAX);
    if (v < min || ((bounds & CLI_BOUND_OPEN_MIN) && v == min) || v > max ||
        (v == max && !max_allowed))
        return out_of_range(problem, v, text, strlen(text));
    *out = v;
    return CLI_READ_OK;
}

cli_read cli_read_point(const char *text, double max_magnitude,
                        rt_vec3 *out, cli_problem *problem)
{
    snprintf(problem->expected, sizeof problem->expected,
             "X,Y,Z (three numbers)");
    double v[MAX_LIST];
    const char *pieces[MAX_LIST];
    size_t lengths[MAX_LIST];
    if (read_list(text, 3, 3, v, pieces, lengths) != 3)
        return CLI_READ_SYNTAX;
    for (int i = 0; i < 3; i++)
        if (fabs(v[i]) > max_magnitude) {
            char bound[32];
            cli_format_number(max_magnitude, bound, sizeof bound);
            snprintf(problem->expected, sizeof problem->expected,
                     "a coordinate of magnitude at most %s (the renderer's "
                     "arithmetic overflows beyond)", bound);
            return out_of_range(problem, v[i], pieces[i], lengths[i]);
        }
    *out = (rt_vec3){v[0], v[1], v[2]};
    return CLI_READ_OK;
}

cli_read cli_read_light(const char *text, rt_light *out,
                        cli_problem *problem)
{
    snprintf(problem->expected, sizeof problem->expected,
             "X,Y,Z or X,Y,Z,R,G,B (colour 0..255)");
    double v[MAX_LIST] = {0, 0, 0, 255, 255, 255};
    const char *pieces[MAX_LIST];
    size_t lengths[MAX_LIST];
    int n = read_list(text, 3, 6, v, pieces, lengths);
    if (n != 3 && n != 6)
        return CLI_READ_SYNTAX;
    for (int i = 3; i < n; i++) {
        if (!is_whole(v[i]))
            return CLI_READ_SYNTAX;
        if (v[i] < 0 || v[i] > 255) {
            snprintf(problem->expected, sizeof problem->expected,
                     "a colour component in 0..255");
            return out_of_range(problem, v[i], pieces[i], lengths[i]);
        }
    }
    out->position = (rt_vec3){v[0], v[1], v[2]};
    out->color = (rt_rgb8){(unsigned char)v[3], (unsigned char)v[4],
                           (unsigned char)v[5]};
    return CLI_READ_OK;
}

/* pieces[0..count) as whole numbers each in min..max, named names[i] in a
 * range message; CLI_READ_SYNTAX when one is not whole. */
static cli_read wholes_in(const double *v, const char *const *pieces,
                          const size_t *lengths, int count, double min,
                          double max, const char *const *names,
                          cli_problem *problem)
{
    for (int i = 0; i < count; i++)
        if (!is_whole(v[i]))
            return CLI_READ_SYNTAX;
    for (int i = 0; i < count; i++)
        if (v[i] < min || v[i] > max) {
            char low[32], high[32];
            cli_format_number(min, low, sizeof low);
            cli_format_number(max, high, sizeof high);
            snprintf(problem->expected, sizeof problem->expected,
                     "%s in %s..%s", names[i], low, high);
            return out_of_range(problem, v[i], pieces[i], lengths[i]);
        }
    return CLI_READ_OK;
}

cli_read cli_read_size(const char *text, int max, int *width, int *height,
                       cli_problem *problem)
{
    snprintf(problem->expected, sizeof problem->expected,
             "WIDTHxHEIGHT, each in 1..%d", max);
    static const char *const names[] = {"a width", "a height"};
    size_t first = strcspn(text, "xX");
    if (text[first] == '\0')
        return CLI_READ_SYNTAX;
    const char *pieces[2] = {text, text + first + 1};
    size_t lengths[2] = {first, strlen(text + first + 1)};
    double v[2];
    for (int i = 0; i < 2; i++)
        if (rt_scene_read_number(pieces[i], lengths[i], &v[i], NULL) != RT_OK)
            return CLI_READ_SYNTAX;
    cli_read read = wholes_in(v, pieces, lengths, 2, 1, max, names,
                              problem);
    if (read != CLI_READ_OK)
        return read;
    *width = (int)v[0];
    *height = (int)v[1];
    return CLI_READ_OK;
}

cli_read cli_read_region(const char *text, int max, rt_region *region,
                         cli_problem *problem)
{
    snprintf(problem->expected, sizeof problem->expected,
             "X0,Y0,X1,Y1, whole numbers with X0 < X1 and Y0 < Y1");
    static const char *const names[] = {"X0", "Y0", "X1", "Y1"};
    double v[MAX_LIST];
    const char *pieces[MAX_LIST];
    size_t lengths[MAX_LIST];
    if (read_list(text, 4, 4, v, pieces, lengths) != 4)
        return CLI_READ_SYNTAX;
    cli_read read = wholes_in(v, pieces, lengths, 4, 0, max, names,
                              problem);
    if (read != CLI_READ_OK)
        return read;
    if (v[0] >= v[2] || v[1] >= v[3])
        return CLI_READ_SYNTAX;
    *region = (rt_region){(int)v[0], (int)v[1], (int)v[2], (int)v[3]};
    return CLI_READ_OK;
}

cli_read cli_read_pixel(const char *text, int max, int *x, int *y,
                        cli_problem *problem)
{
    snprintf(problem->expected, sizeof problem->expected,
             "X,Y, two whole numbers (a pixel of the image, 0,0 top left)");
    static const char *const names[] = {"X", "Y"};
    double v[MAX_LIST];
    const char *pieces[MAX_LIST];
    size_t lengths[MAX_LIST];
    if (read_list(text, 2, 2, v, pieces, lengths) != 2)
        return CLI_READ_SYNTAX;
    cli_read read = wholes_in(v, pieces, lengths, 2, 0, max - 1, names,
                              problem);
    if (read != CLI_READ_OK)
        return read;
    *x = (int)v[0];
    *y = (int)v[1];
    return CLI_READ_OK;
}
