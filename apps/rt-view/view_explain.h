/*
 * view_explain.h - what rt-view shows of one clicked pixel: its ray tree
 * from the library (rt_explain_pixel, same render options as the picture),
 * turned into the segments the overlay draws and the text rt-export
 * --explain prints for the same pixel, word for word (the one formatter,
 * apps/common/cli_explain.h).
 *
 * A pixel of several samples is explained whole (its text: every sample,
 * as rt-export --explain X,Y prints it) but drawn one sample at a time:
 * the sample whose point in the pixel is nearest the click, then the
 * others in turn (view_explanation_show_sample).  Each sample's point is
 * where its camera ray was cast through the screen, read back from the
 * library's own rays (view_project_camera_ray), so the choice follows the
 * sampling, regular or stratified, and the lens, without knowing them.
 *
 * Shadow rays are drawn yellow to their light, or red up to the facet that
 * blocks them (found again with rt_scene_nearest_hit, as the tree names
 * only the facet); rays that hit nothing are drawn far along their
 * direction.  Shadow rays the renderer did not cast (N.S <= 0) are not
 * drawn, but their line in the text says why.
 *
 * Threading: reads the scene only; each explanation belongs to one thread.
 */
#ifndef VIEW_EXPLAIN_H
#define VIEW_EXPLAIN_H

#include <stddef.h>

#include "raytrace/explain.h"
#include "raytrace/raytrace.h"
#include "view_overlay.h"

typedef struct view_explanation {
    int x, y;                   /* the pixel, in the shown image */
    int samples;                /* the render's samples a pixel (1, 4 ...) */
    double (*points)[2];        /* each sample's point, image coordinates
                                   (pixel (x, y) covers [x, x+1) x [y, y+1)):
                                   points[k] for sample k */
    char *text;                 /* rt-export --explain's text for the pixel:
                                   every sample */
    rt_color value;             /* the pixel's value before rounding */

    /* The sample drawn (with one sample: the pixel): */
    int sample;                 /* its index, 0..samples-1 */
    view_segment *segments;     /* what the overlay draws: its rays only */
    int segment_count;
    char *sample_text;          /* the same formatter's text for its tree
                                   alone (rt_explain_pixel of that sample);
                                   `text` itself with one sample */
    rt_color sample_value;      /* its colour (`value` with one sample) */
    rt_ray_node first;          /* its camera ray */

    /* The window's text panel, the app's to fill: */
    char *panel;                /* view_explanation_panel's text; NULL:
                                   none yet (show_sample drops it) */
    int panel_columns, panel_rows;  /* the size it was made for */
} view_explanation;

/*
 * Explains the pixel under point (px, py) of the image rendered with
 * `options` (image coordinates as above, in that image: a region's own),
 * and chooses the sample drawn: the one whose point is nearest (px, py),
 * the lowest index among equally near ones.  `name` is the scene as the
 * text names it (rt-export's operand: the path as given).  RT_OK with *out
 * filled (release it), else the library's status and reason in *error
 * (which may be NULL), *out empty.
 */
rt_status view_explain_point(const rt_scene *scene,
                             const rt_render_options *options,
                             const char *name, double px, double py,
                             view_explanation *out, rt_error *error);

/* view_explain_point at the centre of pixel (x, y). */
rt_status view_explain_pixel(const rt_scene *scene,
                             const rt_render_options *options,
                             const char *name, int x, int y,
                             view_explanation *out, rt_error *error);

/*
 * Draws sample `sample` (0..samples-1) of the explained pixel instead:
 * its tree from the library, with the options and name the explanation
 * was made with.  RT_OK, else the status and reason in *error (may be
 * NULL) and the explanation as it was.
 */
rt_status view_explanation_show_sample(const rt_scene *scene,
                                       const rt_render_options *options,
                                       const char *name,
                                       view_explanation *explanation,
                                       int sample, rt_error *error);

/* The sample whose point is nearest image point (px, py); the lowest
 * index among equally near ones. */
int view_explanation_nearest_sample(const view_explanation *explanation,
                                    double px, double py);

/*
 * What the window's text panel shows of an explanation, in a new string
 * (NULL when out of memory): the lines of `sample_text` from the camera
 * ray's hit on, word for word, under a line of rt-view's naming the pixel.
 * Left out: the formula line every explanation starts with and the camera
 * ray's own line (the overlay draws that ray as the clicked point); with
 * several samples also the formatter's "sample K:" and value lines, in
 * place of which rt-view's lines give the pixel's bytes (the mean of its
 * samples), the sample drawn ("sample K of N", K from 0 as in rt-export's
 * "sample K:") and the keys that change it.  When that does not fit in
 * `rows` rows of `columns` characters (words wrapped as the panel wraps
 * them), the first lines that fit and a last one saying how many more
 * lines are on standard output.
 */
char *view_explanation_panel(const view_explanation *explanation,
                             int columns, int rows);

/* The rows `text` takes wrapped at `columns` characters: each line's words
 * (runs without a space) go on a row while they fit, a word longer than
 * a row on rows of their own. */
int view_text_rows(const char *text, int columns);

/* Frees what an explanation holds; an empty one is a no-op. */
void view_explanation_release(view_explanation *explanation);

#endif /* VIEW_EXPLAIN_H */
