/*
 * formats.h - what the image writers share (internal).
 */
#ifndef RAYTRACE_FORMATS_H
#define RAYTRACE_FORMATS_H

#include "raytrace/image.h"

/* Fills *error for a format this build cannot write (PNG without libpng,
 * or a value that names no format) and returns RT_ERR_FORMAT. */
rt_status rt__image_format_refusal(rt_image_format format, rt_error *error);

#if RAYTRACE_HAVE_PNG
/* Encodes `image` (valid) as an 8-bit RGB PNG to the sink. */
rt_status rt__png_write_to(rt_write_func write, void *context,
                           const rt_image *image, rt_error *error);
#endif

#endif /* RAYTRACE_FORMATS_H */
