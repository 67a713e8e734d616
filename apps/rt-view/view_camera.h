/*
 * view_camera.h - the arithmetic of rt-view's camera moves, on the
 * library's rt_look (a view as rt-export's --look-from, --look-at, --up
 * and --fov give it): orbiting round the look-at point, panning in the
 * screen plane, dollying towards the look-at point, flying, the field of
 * view, aiming at a picked point, and the camera written as rt-export
 * options and as the camera records of a .scn file.
 *
 * Every move changes an rt_look only; the caller makes the camera of the
 * result with rt_scene_look (which refuses a look it cannot use, and then
 * the previous one stays).  The look-at point is the target: orbits turn
 * about it and dollies approach it, and the screen plane passes through it
 * (rt_scene_look puts the screen centre A there), so a pan moves what lies
 * at the target's depth exactly with the cursor.
 *
 * "World up" is the axis orbits keep vertical: the file's camera's up
 * snapped to the nearest axis, or the up axis of the automatic camera of
 * an OBJ or PLY file (rt_scene_info.up_axis).  An orbit makes the look's
 * up the world up (no roll); the other moves keep the look's up.
 *
 * Pure arithmetic on values, no SDL, no state: every function is
 * thread-safe (those taking a scene only read it).
 */
#ifndef VIEW_CAMERA_H
#define VIEW_CAMERA_H

#include <stddef.h>

#include "raytrace/raytrace.h"

/* The field of view a move may give, in degrees (both included). */
#define VIEW_CAMERA_MIN_FOV 1.0
#define VIEW_CAMERA_MAX_FOV 170.0

/* How close to the world up (or down) an orbit may tilt the view, in
 * degrees: the poles themselves have no turntable "right". */
#define VIEW_CAMERA_POLE_DEGREES 1.0

/* The nearest and farthest a dolly brings the observer to the target, in
 * units of the scene's extent (view_camera_extent): never onto it. */
#define VIEW_CAMERA_MIN_DISTANCE 1e-4
#define VIEW_CAMERA_MAX_DISTANCE 1e4

/* The world up of `scene` (a unit axis): for an OBJ or PLY file (its
 * info's up_axis set) that axis, else the file's camera's up half-height
 * AC snapped to the nearest of +-x, +-y, +-z. */
rt_vec3 view_camera_world_up(const rt_scene *scene);

/* The scene's extent: the diagonal of the bounding box of its vertices,
 * or |AO| of its camera when that is zero (no vertices, or one point). */
double view_camera_extent(const rt_scene *scene);

/* The look of the file's camera (rt_camera_get_look of the scene's
 * camera) with its target moved along the axis of view to what the axis
 * meets (the nearest hit of the ray from O through A), else to the point
 * of the axis nearest the middle of the vertices' bounding box when that
 * is in front of O, else left at A: where the first move starts from, the
 * direction of view and the field of view those of the file. */
rt_look view_camera_file_look(const rt_scene *scene);

/*
 * Orbits look_from round look_at: `yaw` radians about `world_up` (unit;
 * positive moves the observer towards the image's right), then `pitch`
 * radians about the view's right (positive raises it towards world_up),
 * the elevation clamped VIEW_CAMERA_POLE_DEGREES short of the poles.  The
 * distance to look_at is kept; look->up becomes world_up.  A view along
 * world_up takes its horizontal from look->up (the image's up).
 */
void view_camera_orbit(rt_look *look, rt_vec3 world_up, double yaw,
                       double pitch);

/*
 * Pans: moves look_from and look_at together in the screen plane of
 * `camera` (the look's camera, as rt_scene_look made it) so that what lies
 * at the target's depth moves (dx, dy) pixels (right, down) on an image
 * `width` pixels wide (the render's full width, > 0).
 */
void view_camera_pan(rt_look *look, const rt_camera *camera, int width,
                     double dx, double dy);

/*
 * Dollies: look_from moves along the line to look_at so that the distance
 * is multiplied by `factor` (> 0; < 1 comes closer), kept within
 * [min_distance, max_distance]; the direction of view does not change.
 */
void view_camera_dolly(rt_look *look, double factor, double min_distance,
                       double max_distance);

/*
 * Flies: moves look_from and look_at by the same vector, `forward` scene
 * units along the direction of view, `right` along the camera's right
 * half-width AB and `rise` along `world_up` (unit).
 */
void view_camera_fly(rt_look *look, const rt_camera *camera,
                     rt_vec3 world_up, double forward, double right,
                     double rise);

/* `fov` clamped to [VIEW_CAMERA_MIN_FOV, VIEW_CAMERA_MAX_FOV] (NaN gives
 * the minimum). */
double view_camera_clamp_fov(double fov);

/*
 * Aims at `target`: look_from stays, look_at becomes `target` (which then
 * projects to the image centre, and becomes what orbits turn about), the
 * up `world_up`.  A target within VIEW_CAMERA_POLE_DEGREES of straight
 * above or below moves look_from round it, at its distance, to that
 * limit.  Returns 0, the look untouched, when target is look_from.
 */
int view_camera_aim(rt_look *look, rt_vec3 world_up, rt_vec3 target);

/*
 * The nearest surface under pixel (i, j) (column, row from the top) of a
 * width x height render by `camera` (its own size is ignored): the hit of
 * that pixel's camera ray (rt_camera_ray, rt_scene_nearest_hit).  Returns
 * 1 with the point in *point, 0 when the ray meets nothing.
 */
int view_camera_pick(const rt_scene *scene, const rt_camera *camera,
                     int width, int height, int i, int j, rt_vec3 *point);

/*
 * The text `C` prints and writes: `look` (NULL: the file's own camera) as
 * rt-export's options "--look-from X,Y,Z --look-at X,Y,Z --up X,Y,Z --fov
 * F" on one line, and as the two camera records a .scn file starts with
 * (the observer "O"; the screen "A, B, w, h[, a, f]", with B the point
 * rt_scene_look returns and a, f the lens when the camera has one or a
 * focal distance other than |AO|), every number with %.17g so that each
 * reads back to the same bits; lines starting with '#' say what they are.
 * For the file's camera it says that no options are needed.  `name`
 * names the scene in the first comment.  Returns RT_OK; RT_ERR_ARGUMENT
 * (rt_scene_look's reason in *error, may be NULL) for a look it refuses;
 * RT_ERR_LIMIT when the text does not fit in `size` bytes.
 */
rt_status view_camera_describe(const rt_scene *scene, const char *name,
                               const rt_look *look, char *buffer,
                               size_t size, rt_error *error);

#endif /* VIEW_CAMERA_H */
