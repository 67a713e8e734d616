/*
 * framing.h - the one framing of a view (internal): an eye, the point it
 * looks at, an up direction and a horizontal field of view become the
 * rendering model's camera, the observer O, the screen centre A and the
 * screen's right edge B (docs/rendering-model.md).  The loader's
 * --look-from/--look-at/--up/--fov, NFF's `v` and the OBJ reader's
 * automatic camera all frame their view here.
 */
#ifndef RAYTRACE_FRAMING_H
#define RAYTRACE_FRAMING_H

#include "raytrace/vec3.h"

/* A view to frame. */
typedef struct rt_view {
    rt_vec3 from;           /* the eye: O */
    rt_vec3 at;             /* the point looked at: A */
    rt_vec3 up;             /* up in the image (any length, not along the
                               view) */
    double fov;             /* the horizontal field of view, in degrees */
    int width;              /* the image's width in pixels (for centres) */
    int centres;            /* non-zero: fov spans the centres of the first
                               and last columns (NFF), not the screen's
                               edges */
} rt_view;

/* What keeps a view from being framed (rt__frame_view). */
typedef enum rt_frame_problem {
    RT_FRAME_OK,
    RT_FRAME_FOV,           /* fov is not in (0, 180) degrees */
    RT_FRAME_SAME_POINT,    /* `at` is `from` (or too far from it) */
    RT_FRAME_UP_ALONG_VIEW  /* up is along the direction of view */
} rt_frame_problem;

/* tan(fov / 2) for a field of view of `fov` degrees: the half width of
 * the screen at a distance of 1. */
double rt__frame_tan_half(double fov);

/*
 * The screen's right edge of a view looking along `look` (from the eye
 * towards `at`, of any length) with `up`: B = at + half_width
 * unit(look x up), the right half of the screen at `at`, half_width wide.
 */
rt_vec3 rt__frame_right(rt_vec3 at, rt_vec3 look, rt_vec3 up,
                        double half_width);

/*
 * Frames `view`: O = from, A = at and B = rt__frame_right(A, A - O, up,
 * |AO| rt__frame_tan_half(fov)), the half width divided by 1 - 1/width with
 * `centres` (so that the angle spans the first and last columns'
 * centres).  Returns RT_FRAME_OK with *observer, *screen_center and
 * *screen_right set, or what is wrong (nothing set).
 */
rt_frame_problem rt__frame_view(const rt_view *view, rt_vec3 *observer,
                                rt_vec3 *screen_center,
                                rt_vec3 *screen_right);

#endif /* RAYTRACE_FRAMING_H */
