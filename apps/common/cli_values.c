/*
 * cli_values.c - the values of command-line options (see cli_values.h).
 * Numbers are read with strtod: the programs never change the locale, so
 * it is the C locale's decimal point.
 */
#include "cli_values.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

int cli_parse_length(const char *text, int positive, double *value)
{
    char *end;
    errno = 0;
    double v = strtod(text, &end);
    if (errno != 0 || end == text || *end != '\0' || !isfinite(v) ||
        (positive ? !(v > 0.0) : !(v >= 0.0)))
        return 0;
    *value = v;
    return 1;
}

int cli_parse_numbers(const char *text, int count_min, int count_max,
                      double *out)
{
    double values[6];
    int n = 0;
    const char *at = text;
    for (;;) {
        char *end;
        errno = 0;
        double v = strtod(at, &end);
        if (errno != 0 || end == at || !isfinite(v) || n == count_max ||
            n == 6)
            return 0;
        values[n++] = v;
        if (*end == '\0')
            break;
        if (*end != ',')
            return 0;
        at = end + 1;
    }
    if (n < count_min)
        return 0;
    for (int i = 0; out != NULL && i < n; i++)
        out[i] = values[i];
    return n;
}

int cli_parse_point(const char *text, rt_vec3 *point)
{
    double v[3];
    if (cli_parse_numbers(text, 3, 3, v) != 3)
        return 0;
    *point = (rt_vec3){v[0], v[1], v[2]};
    return 1;
}

int cli_parse_light(const char *text, rt_light *light)
{
    double v[6] = {0, 0, 0, 255, 255, 255};
    int n = cli_parse_numbers(text, 3, 6, v);
    if (n != 3 && n != 6)
        return 0;
    for (int i = 3; i < 6; i++)
        if (v[i] != floor(v[i]) || v[i] < 0 || v[i] > 255)
            return 0;
    light->position = (rt_vec3){v[0], v[1], v[2]};
    light->color = (rt_rgb8){(unsigned char)v[3], (unsigned char)v[4],
                             (unsigned char)v[5]};
    return 1;
}

int cli_parse_scene_format(const char *text, rt_scene_format *format)
{
    static const struct {
        const char *name;
        rt_scene_format format;
    } names[] = {{"scn", RT_SCENE_FORMAT_SCN},
                 {"nff", RT_SCENE_FORMAT_NFF},
                 {"obj", RT_SCENE_FORMAT_OBJ}};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
        if (strcmp(text, names[i].name) == 0) {
            *format = names[i].format;
            return 1;
        }
    return 0;
}
