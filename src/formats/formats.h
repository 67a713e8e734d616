/*
 * formats.h - what the image writers share (internal).
 */
#ifndef RAYTRACE_FORMATS_H
#define RAYTRACE_FORMATS_H

#include "raytrace/image.h"
#include "raytrace/scene.h"

/* Fills *error for a format this build cannot write (PNG without libpng,
 * or a value that names no format) and returns RT_ERR_FORMAT. */
rt_status rt__image_format_refusal(rt_image_format format, rt_error *error);

/* Bytes to save: `produce` writes `what` to the sink and returns a status
 * (filling *error on failure). */
typedef struct rt_producer {
    rt_status (*produce)(rt_write_func write, void *user, const void *what,
                         rt_error *error);
    const void *what;
    const char *noun;       /* what messages call it: "image", "scene" */
} rt_producer;

/* Writes what `producer` produces at `path` by the rule of
 * raytrace/image.h (atomic replacement, streams written directly, links
 * followed), with `options` (NULL: the defaults; a bad size is
 * RT_ERR_ARGUMENT) saying whether the termination signals are held.
 * Errors name `path`. */
rt_status rt__save(const char *path, const rt_producer *producer,
                   const rt_save_options *options, rt_error *error);

/* Encodes `image` as PPM (RT_IMAGE_P3 or RT_IMAGE_P6) to the sink: RT_OK
 * or the bare status (the callers write the message). */
rt_status rt__ppm_write_to(rt_write_func write, void *user,
                           const rt_image *image, rt_image_format format);

#if RAYTRACE_HAVE_EXR
/* Encodes `image` (valid) as a scanline OpenEXR of FLOAT R, G, B with ZIP
 * compression to the sink (built in memory, then written at once). */
rt_status rt__exr_write_to(rt_write_func write, void *user,
                           const rt_image_float *image, rt_error *error);
#endif

#if RAYTRACE_HAVE_PNG
/* Encodes `image` (valid) as an 8-bit RGB PNG to the sink. */
rt_status rt__png_write_to(rt_write_func write, void *user,
                           const rt_image *image, rt_error *error);
#endif

#endif /* RAYTRACE_FORMATS_H */
