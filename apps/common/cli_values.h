/*
 * cli_values.h - reading the values of the programs' command-line options
 * (lengths, lists of numbers, lights, scene formats), shared by rt-export
 * and rt-view so that both accept and refuse exactly the same text.
 */
#ifndef RAYTRACE_CLI_VALUES_H
#define RAYTRACE_CLI_VALUES_H

#include "raytrace/raytrace.h"

/* A finite number: > 0 when `positive`, else >= 0.  Returns 1 on success
 * (then *value is set), 0 otherwise. */
int cli_parse_length(const char *text, int positive, double *value);

/* `count_min` to `count_max` (at most 6) finite numbers separated by
 * commas, into out[0..n) (x, y, z of an rt_vec3 are consecutive doubles);
 * returns n, or 0 when the text is not such a list. */
int cli_parse_numbers(const char *text, int count_min, int count_max,
                      double *out);

/* A point or vector "x,y,z". */
int cli_parse_point(const char *text, rt_vec3 *point);

/* A light "x,y,z" (white) or "x,y,z,r,g,b" (whole numbers 0..255). */
int cli_parse_light(const char *text, rt_light *light);

/* "scn", "nff" or "obj". */
int cli_parse_scene_format(const char *text, rt_scene_format *format);

#endif /* RAYTRACE_CLI_VALUES_H */
