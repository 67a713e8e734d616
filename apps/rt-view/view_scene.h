/*
 * view_scene.h - what rt-view does with files besides rendering them:
 * loading a scene, noticing that its file changed (--watch), and choosing
 * the names `S` saves to so that no save ever replaces an earlier one.
 *
 * The image size is a render option (rt_render_options.width/height), so
 * nothing here copies or rebuilds a scene: --scale only computes a width
 * and height from the scene's (view_scale_side).  Thread-safe.
 */
#ifndef VIEW_SCENE_H
#define VIEW_SCENE_H

#include <stddef.h>

#include "raytrace/raytrace.h"

/* Smallest and largest --scale factors accepted. */
#define VIEW_MIN_SCALE 0.01
#define VIEW_MAX_SCALE 64.0

/* Loads the scene at `path` with the loader's options (NULL: the
 * defaults): rt_scene_load, whose messages are FILE:LINE:COLUMN:
 * MESSAGE.  *scene is NULL on failure. */
rt_status view_scene_load(const char *path, const rt_load_options *options,
                          rt_scene **scene, rt_error *error);

/* `side` pixels times `scale`, rounded to nearest, at least 1 (it may
 * exceed RT_MAX_IMAGE_SIDE: the render then refuses the size). */
int view_scale_side(int side, double scale);

/*
 * The name `S` numbers (view_save_claim_numbered): rt-export's default
 * output for the scene (cli_export_default_output: the file name without
 * its extension, whatever it is, then ".png" for PNG, else ".ppm"), in
 * the scene's folder rather than the current one: "dir/balls-s2.nff" ->
 * "dir/balls-s2.png".  Returns 0 when it does not fit in `size` or
 * memory is short.
 */
int view_scene_image_path(const char *scene_path, rt_image_format format,
                          char *buffer, size_t size);

/* The scene's folder and stem (as view_scene_image_path names them) with
 * `suffix` after them: "dir/balls-s2.nff", "-camera.txt" ->
 * "dir/balls-s2-camera.txt".  Returns 0 when it does not fit in `size` or
 * memory is short. */
int view_scene_side_path(const char *scene_path, const char *suffix,
                         char *buffer, size_t size);

/*
 * Claims the first free numbered name beside `path` ("dir/cubes.png"):
 * "dir/cubes-1.png", "dir/cubes-2.png", ..., or with a `tag`
 * ("partial") "dir/cubes-partial-1.png", ...  A name is claimed by
 * creating it empty and exclusively (O_CREAT | O_EXCL), so two savers never
 * get the same name and an existing file is never a candidate; the caller
 * then writes the image over the empty file (rt_image_save) or removes it.
 * Returns 1 with the name in `buffer`, or 0 with the reason in `error`
 * (the name too long, the folder missing or read-only ...).
 */
int view_save_claim_numbered(const char *path, const char *tag, char *buffer,
                             size_t size, rt_error *error);

/* What --watch compares to notice that a file changed: its identity
 * (device and inode: an editor that saves by renaming gives a new one), its
 * size and its modification time. */
typedef struct view_file_stamp {
    int exists;
    unsigned long long device, inode;
    long long size;
    long long mtime_seconds;
    long mtime_nanoseconds;
} view_file_stamp;

/* Reads the stamp of `path` (exists = 0 when it cannot be stat'ed). */
void view_file_stamp_read(const char *path, view_file_stamp *stamp);

/* Non-zero when the two stamps are the same. */
int view_file_stamp_equal(const view_file_stamp *a, const view_file_stamp *b);

#endif /* VIEW_SCENE_H */
