/*
 * view_explain.h - what rt-view shows of one clicked pixel: its ray tree
 * from the library (rt_explain_pixel, same render options as the picture),
 * turned into the segments the overlay draws and the text rt-export
 * --explain prints for the same pixel, word for word (the one formatter,
 * apps/common/cli_explain.h).
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
    view_segment *segments;     /* what the overlay draws */
    int segment_count;
    char *text;                 /* rt-export --explain's text */
    rt_color value;             /* the pixel's value before rounding */
    rt_ray_node first;          /* the tree's first ray (a camera ray) */
} view_explanation;

/*
 * Explains pixel (x, y) of the image rendered with `options` (x, y in that
 * image: a region's own coordinates), `name` the scene as the text names
 * it (rt-export's operand: the path as given).  RT_OK with *out filled
 * (release it), else the library's status and reason in *error (which may
 * be NULL), *out empty.
 */
rt_status view_explain_pixel(const rt_scene *scene,
                             const rt_render_options *options,
                             const char *name, int x, int y,
                             view_explanation *out, rt_error *error);

/* Frees what an explanation holds; an empty one is a no-op. */
void view_explanation_release(view_explanation *explanation);

#endif /* VIEW_EXPLAIN_H */
