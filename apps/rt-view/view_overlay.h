/*
 * view_overlay.h - what rt-view draws over the picture when a pixel is
 * clicked: the rays of that pixel's tree projected through the camera.
 *
 * A world point X is shown where the line from the observer O to X crosses
 * the screen plane, in the image's pixel coordinates: the inverse of
 * docs/rendering-model.md's P = A + ((2x - w)/w)·AB + ((h - 2y)/w)·AC, so
 * the camera ray of pixel (i, j) projects to (i + 1/2, j + 1/2).  A segment
 * is clipped to the half-space in front of the observer before it is
 * projected.  Also the window-to-image mapping of the letterboxed picture
 * (view_window.c draws it scaled to fit and centred).
 *
 * Pure arithmetic, no SDL: every function is thread-safe.
 */
#ifndef VIEW_OVERLAY_H
#define VIEW_OVERLAY_H

#include "raytrace/raytrace.h"

/* The kinds of ray the overlay draws, each with its colour
 * (view_ray_color). */
typedef enum view_ray_kind {
    VIEW_RAY_CAMERA,        /* white */
    VIEW_RAY_SHADOW,        /* yellow: a shadow ray that reaches its light */
    VIEW_RAY_REFLECTED,     /* cyan */
    VIEW_RAY_REFRACTED,     /* magenta */
    VIEW_RAY_BLOCKED        /* red: a shadow ray, up to its blocker */
} view_ray_kind;

/* One ray to draw: from `from` to `to` (a hit, a light, a blocker, or far
 * along a ray that hits nothing); `mark` non-zero marks `to` (a hit). */
typedef struct view_segment {
    view_ray_kind kind;
    rt_vec3 from, to;
    int mark;
} view_segment;

/* The camera and the image a projection maps to: the render's full size
 * (width x height) and the region's top-left corner, since the image shown
 * holds only the region. */
typedef struct view_projection {
    rt_camera camera;
    int width, height;          /* the full image's */
    int x0, y0;                 /* the region's corner (0, 0 without) */
    double focal_distance;      /* the lens's f (view_project_camera_ray) */
} view_projection;

/* The projection of `scene` rendered with `options` (size, region, the
 * camera when options->camera sets one, the focal distance). */
void view_projection_init(view_projection *projection, const rt_scene *scene,
                          const rt_render_options *options);

/* The image coordinates (x, y) (pixel (i, j) covers [i, i+1) x [j, j+1))
 * of `point`; 0 when it is not in front of the observer. */
int view_project_point(const view_projection *projection, rt_vec3 point,
                       double *x, double *y);

/* Projects the part of segment a-b in front of the observer: out = {x0,
 * y0, x1, y1} in image coordinates, x0 y0 for a's end.  0 when none of it
 * is in front. */
int view_project_segment(const view_projection *projection, rt_vec3 a,
                         rt_vec3 b, double out[4]);

/*
 * The image point a camera ray of the render was cast through: where the
 * pinhole ray it belongs to crosses the screen, in image coordinates (the
 * sample's position in its pixel: (i + 1/2, j + 1/2) for one sample).  A
 * pinhole ray leaves the observer, so any point of it projects there; a
 * thin-lens ray leaves a point of the lens towards the point where that
 * pinhole ray reaches the focal distance (docs/rendering-model.md), and
 * that point is projected.  0 when the ray does not go forwards.
 */
int view_project_camera_ray(const view_projection *projection,
                            rt_vec3 origin, rt_vec3 direction, double *x,
                            double *y);

/* The overlay colour of a kind of ray. */
void view_ray_color(view_ray_kind kind, unsigned char rgb[3]);

/* Where the picture of an image_width x image_height image goes in an
 * out_width x out_height output: scaled to fit, centred (rect = {x, y, w,
 * h}). */
void view_letterbox(int image_width, int image_height, int out_width,
                    int out_height, int rect[4]);

/* The image pixel under output point (x, y) for that letterbox: 1 with
 * (*i, *j), or 0 when the point is outside the picture.  (The pixel's
 * fractional point is *i + f, f in [0, 1): view_navigation.c finds it from
 * the window points showing the same pixel.) */
int view_output_to_pixel(int image_width, int image_height, int out_width,
                         int out_height, double x, double y, int *i, int *j);

#endif /* VIEW_OVERLAY_H */
