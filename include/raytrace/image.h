/*
 * raytrace/image.h - RGB8 images and the PPM format.
 *
 * An rt_image is a view: width, height, a row stride in bytes and a pointer
 * to pixels (3 bytes per pixel, R G B, rows top to bottom).  The caller may
 * point it at memory it owns, or let rt_image_create allocate it.
 *
 * PPM writers go to a sink (a callback), to a FILE, or to a path; the path
 * variant writes a temporary file in the destination directory, flushes it
 * and renames it over the destination, so the file at `path` is either the
 * old one or the complete new one, never a partial image.  Readers accept P3
 * and P6 with maxval 255 (what the writers produce) from memory or a path.
 * All functions are thread-safe on distinct images.
 */
#ifndef RAYTRACE_IMAGE_H
#define RAYTRACE_IMAGE_H

#include <stddef.h>
#include <stdio.h>

#include "raytrace/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct rt_image {
    int width;
    int height;
    size_t stride;          /* bytes from one row to the next, >= 3 * width */
    unsigned char *pixels;
} rt_image;

typedef enum rt_ppm_format {
    RT_PPM_P3 = 3,          /* ASCII, lines of at most 70 characters */
    RT_PPM_P6 = 6           /* binary */
} rt_ppm_format;

/* Allocates a black width x height image with stride 3 * width.  Sides must
 * be in 1..RT_MAX_IMAGE_SIDE.  On failure image->pixels is NULL. */
rt_status rt_image_create(rt_image *image, int width, int height);

/* Frees what rt_image_create allocated and zeroes the view; a zeroed image
 * is a no-op. */
void rt_image_destroy(rt_image *image);

/* Pointer to pixel (x, y). */
static inline unsigned char *rt_image_pixel(const rt_image *image, int x,
                                            int y)
{
    return image->pixels + (size_t)y * image->stride + (size_t)x * 3;
}

/* Receives `size` bytes of output; returns non-zero on success. */
typedef int (*rt_write_func)(void *context, const void *data, size_t size);

rt_status rt_ppm_write_to(rt_write_func write, void *context,
                          const rt_image *image, rt_ppm_format format);
rt_status rt_ppm_write_file(FILE *file, const rt_image *image,
                            rt_ppm_format format);

/* Atomic save (see above).  Errors name the path and the reason. */
rt_status rt_ppm_save(const char *path, const rt_image *image,
                      rt_ppm_format format, rt_error *error);

/* Parses a P3 or P6 image from memory into a new image (free it with
 * rt_image_destroy).  `name` is used in messages ("<memory>" when NULL). */
rt_status rt_ppm_parse(const void *data, size_t length, const char *name,
                       rt_image *image, rt_error *error);
rt_status rt_ppm_load(const char *path, rt_image *image, rt_error *error);

#ifdef __cplusplus
}
#endif

#endif /* RAYTRACE_IMAGE_H */
