/*
 * view_scene.h - what rt-view does with scene files besides rendering them:
 * loading one at a chosen resolution, and naming the image saved beside it.
 *
 * Scaling rebuilds the scene through the public builder (rt_scene_create)
 * with the same camera, geometry and light and a width and height
 * multiplied by the factor: the picture is the same, with more or fewer
 * pixels.  A factor of 1 keeps the loaded scene untouched, so the viewer's
 * image is then exactly rt-export's.  Thread-safe.
 */
#ifndef VIEW_SCENE_H
#define VIEW_SCENE_H

#include <stddef.h>

#include "raytrace/raytrace.h"

/* Smallest and largest --scale factors accepted. */
#define VIEW_MIN_SCALE 0.01
#define VIEW_MAX_SCALE 64.0

/*
 * Loads the scene at `path` and renders it at `scale` times its size
 * (rounded, at least 1 pixel).  Errors are rt_scene_load's, or
 * RT_ERR_LIMIT / RT_ERR_ARGUMENT with a message naming the path when the
 * scaled size is out of range.  *scene is NULL on failure.
 */
rt_status view_scene_load(const char *path, double scale, rt_scene **scene,
                          rt_error *error);

/* The same with the loader's options (format, tessellation, view, lights;
 * NULL: the defaults). */
rt_status view_scene_load_with(const char *path, double scale,
                               const rt_load_options *options,
                               rt_scene **scene, rt_error *error);

/* The same scene at `scale` times its size, as a new scene. */
rt_status view_scene_rescale(const rt_scene *scene, const char *name,
                             double scale, rt_scene **scaled,
                             rt_error *error);

/*
 * Where `S` saves the image of `scene_path`: the same directory and name
 * with `extension` (".png", ".ppm") instead of `.scn` (appended when the
 * name has another extension or none).  Returns 0 when it does not fit in
 * `size`.
 */
int view_scene_image_path(const char *scene_path, const char *extension,
                          char *buffer, size_t size);

#endif /* VIEW_SCENE_H */
