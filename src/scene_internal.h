/*
 * scene_internal.h - what an rt_scene holds (internal).
 *
 * A scene keeps two views of its facets: the records as the file gave them
 * (for accessors and the course's API), and a compact array of the facets
 * that can be hit, with everything the renderer needs precomputed once
 * (vertices, unit normal, the diffuse factor (1 - k) C_S C_F / 255).
 * Zero-area facets are absent from the second array: the renderer never
 * spends a test on them.
 */
#ifndef RAYTRACE_SCENE_INTERNAL_H
#define RAYTRACE_SCENE_INTERNAL_H

#include <stdint.h>

#include "raytrace/scene.h"

/* A facet that can be hit, ready for the renderer. */
typedef struct rt_tri {
    rt_vec3 a, b, c;        /* vertices in file order */
    rt_vec3 normal;         /* unit normal, (b - a) x (c - a) direction */
    double k;               /* reflection coefficient */
    double diffuse[3];      /* (1 - k) * C_S * C_F / 255 per channel */
    int facet;              /* index of the facet record */
} rt_tri;

struct rt_scene {
    char *name;
    rt_camera camera;
    rt_vec3 *vertices;
    int vertex_count;
    rt_facet_info *facets;
    int facet_count;
    rt_warning *warnings;
    int warning_count;
    rt_rgb8 background;
    rt_vec3 light;
    rt_rgb8 light_color;
    rt_tri *tris;           /* the live facets, in file order */
    int tri_count;
    int reflective_count;   /* live facets with k > 0 */
};

/*
 * Builds a scene from a validated description.  `name` (may be NULL) and
 * `facet_lines` (may be NULL) only serve warnings.  On failure returns a
 * status with *error filled and *scene NULL.
 */
rt_status rt__scene_build(const rt_scene_desc *desc, const char *name,
                          const int *facet_lines, rt_scene **scene,
                          rt_error *error);

/*
 * Computes the camera of SPEC.md section 2.  Returns NULL on success, or a
 * phrase saying what is degenerate ("the observer O is the screen centre A").
 */
const char *rt__camera_make(rt_vec3 observer, rt_vec3 a, rt_vec3 b,
                            int width, int height, rt_camera *camera);

/* Exact test: non-zero when the three points are collinear (including
 * coincident), evaluated without rounding error. */
int rt__points_collinear(rt_vec3 a, rt_vec3 b, rt_vec3 c);

#endif /* RAYTRACE_SCENE_INTERNAL_H */
