/*
 * cli_values.h - reading the values of the programs' command-line options
 * (whole numbers, numbers, points, lights, sizes, regions, pixels), shared
 * by every program of apps/ through cli.c so that all of them accept and
 * refuse exactly the same text.
 *
 * Every number follows the scene format's grammar (rt_scene_read_number:
 * decimal, an optional exponent, no hexadecimal, no `nan` or `inf`, a
 * subnormal taken as it is) and its rules: a count or a pixel is a whole
 * number (`200`, `200.` and `200.0` are the same), a camera point stays
 * within RT_MAX_COORDINATE, a colour component is a whole number in
 * 0..255.  A reader says how a value failed, so that the message can be
 * worded for it: text that is not of the value's form is quoted as typed;
 * a value of the right form outside its limits is given as a number, with
 * the bound it broke (cli.c words the messages).
 */
#ifndef RAYTRACE_CLI_VALUES_H
#define RAYTRACE_CLI_VALUES_H

#include <stddef.h>

#include "raytrace/raytrace.h"

/* What reading a value found. */
typedef enum cli_read {
    CLI_READ_OK = 0,    /* stored */
    CLI_READ_SYNTAX,    /* not of the value's form: "found 'TEXT'" */
    CLI_READ_RANGE      /* of its form, outside its limits: "found VALUE" */
} cli_read;

/* Why a value was refused, for the message. */
typedef struct cli_problem {
    char expected[160];     /* "an integer in 0..1000000", "X1 in 0..16384" */
    double value;           /* CLI_READ_RANGE: the number found */
    const char *piece;      /* CLI_READ_RANGE: the text it was read from */
    size_t piece_length;    /* (a part of the option's value) */
} cli_problem;

/* A bound or a value as a message shows it: "%g", except that a whole
 * number below 1e15 in magnitude is written out in full (2147483647, not
 * 2.14748e+09), so that a message never shows a rounded value. */
void cli_format_number(double value, char *out, size_t size);

/* An integer in min..max (a square of one when `square`), e.g. --depth;
 * `2.0` and `2e1` are integers. */
cli_read cli_read_integer(const char *text, double min, double max,
                          int square, int *out, cli_problem *problem);

/* Which ends of a real's interval are in it, for cli_read_real: by
 * default min is and a finite max is not ([min, max): --fov's 180 is no
 * field of view); an infinite max always stands for "no upper limit". */
enum {
    CLI_BOUND_OPEN_MIN = 1 << 0,    /* min itself is refused: (min, ... */
    CLI_BOUND_CLOSED_MAX = 1 << 1   /* max itself is accepted: ..., max] */
};

/* A number in the interval from min to max whose ends `bounds` (0 or
 * CLI_BOUND_... flags) says, e.g. --aperture (>= 0), --fov (in (0, 180)),
 * rt-view's --scale (in [0.01, 64]). */
cli_read cli_read_real(const char *text, double min, double max,
                       unsigned bounds, double *out, cli_problem *problem);

/* The words of cli_read_real's limits: "a number >= 0", "a number > 0",
 * "a number in (0, 180)", "a number in [0.01, 64]". */
void cli_real_limits(double min, double max, unsigned bounds, char *out,
                     size_t size);

/* "X,Y,Z": three numbers of magnitude at most `max_magnitude` (infinite:
 * any finite number), e.g. --look-from. */
cli_read cli_read_point(const char *text, double max_magnitude,
                        rt_vec3 *out, cli_problem *problem);

/* A light "X,Y,Z" (white) or "X,Y,Z,R,G,B" (whole numbers 0..255). */
cli_read cli_read_light(const char *text, rt_light *out,
                        cli_problem *problem);

/* "WxH" (or "WXH"), each side a whole number in 1..max. */
cli_read cli_read_size(const char *text, int max, int *width, int *height,
                       cli_problem *problem);

/* "X0,Y0,X1,Y1": whole numbers in 0..max with X0 < X1 and Y0 < Y1. */
cli_read cli_read_region(const char *text, int max, rt_region *region,
                         cli_problem *problem);

/* "X,Y": two whole numbers in 0..max-1. */
cli_read cli_read_pixel(const char *text, int max, int *x, int *y,
                        cli_problem *problem);

#endif /* RAYTRACE_CLI_VALUES_H */
