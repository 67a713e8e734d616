/*
 * float_image.c - linear float images: allocating them, the Portable
 * FloatMap writer (little-endian float32 RGB, rows bottom to top as the
 * format wants), the dispatch to the OpenEXR writer (exr.c, in builds with
 * OpenEXR) and the save, through the same atomic machinery as the 8-bit
 * images (save.c).
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "formats/formats.h"
#include "raytrace/scene.h"

rt_status rt_image_float_init(rt_image_float *image, int width, int height,
                              rt_error *error)
{
    if (image == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "expected an image to fill");
    memset(image, 0, sizeof *image);
    if (width < 1 || height < 1 || width > RT_MAX_IMAGE_SIDE ||
        height > RT_MAX_IMAGE_SIDE)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "a float image of %d x %d pixels: each side "
                             "must be in 1..%d", width, height,
                             RT_MAX_IMAGE_SIDE);
    size_t stride = (size_t)width * 3;
    float *pixels = calloc((size_t)height * stride, sizeof *pixels);
    if (pixels == NULL)
        return rt__error_set(error, RT_ERR_NOMEM, NULL, 0, 0,
                             "out of memory for a float image of %d x %d "
                             "pixels", width, height);
    image->width = width;
    image->height = height;
    image->stride = stride;
    image->pixels = pixels;
    return RT_OK;
}

void rt_image_float_release(rt_image_float *image)
{
    if (image == NULL)
        return;
    free(image->pixels);
    memset(image, 0, sizeof *image);
}

static int valid_float_image(const rt_image_float *image)
{
    return image != NULL && image->pixels != NULL && image->width > 0 &&
           image->height > 0 && image->stride >= (size_t)image->width * 3;
}

/* The four bytes of `value`, little-endian whatever the machine. */
static void put_le_float(unsigned char *out, float value)
{
    uint32_t bits;
    memcpy(&bits, &value, sizeof bits);
    out[0] = (unsigned char)bits;
    out[1] = (unsigned char)(bits >> 8);
    out[2] = (unsigned char)(bits >> 16);
    out[3] = (unsigned char)(bits >> 24);
}

static rt_status pfm_write_to(rt_write_func write, void *user,
                              const rt_image_float *image)
{
    char header[64];
    int n = snprintf(header, sizeof header, "PF\n%d %d\n-1.0\n",
                     image->width, image->height);
    if (!write(user, header, (size_t)n))
        return RT_ERR_IO;
    size_t row_bytes = (size_t)image->width * 12;
    unsigned char *row = malloc(row_bytes);
    if (row == NULL)
        return RT_ERR_NOMEM;
    rt_status status = RT_OK;
    for (int y = image->height - 1; y >= 0 && status == RT_OK; y--) {
        const float *p = rt_image_float_pixel(image, 0, y);
        for (size_t i = 0; i < (size_t)image->width * 3; i++)
            put_le_float(&row[4 * i], p[i]);
        if (!write(user, row, row_bytes))
            status = RT_ERR_IO;
    }
    free(row);
    return status;
}

rt_status rt_image_float_write_to(rt_write_func write, void *user,
                                  const rt_image_float *image,
                                  rt_image_format format, rt_error *error)
{
    if (format != RT_IMAGE_PFM && format != RT_IMAGE_EXR)
        return rt__error_set(error, RT_ERR_FORMAT, NULL, 0, 0,
                             "cannot write a float image as %s: expected "
                             "pfm or exr", rt_image_format_name(format));
    if (!rt_image_format_supported(format))
        return rt__image_format_refusal(format, error);
    if (write == NULL || !valid_float_image(image))
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "expected a float image and a sink");
#if RAYTRACE_HAVE_EXR
    if (format == RT_IMAGE_EXR)
        return rt__exr_write_to(write, user, image, error);
#endif
    rt_status status = pfm_write_to(write, user, image);
    if (status != RT_OK)
        return rt__error_set(error, status, NULL, 0, 0,
                             "cannot write the image: %s",
                             rt_status_string(status));
    return RT_OK;
}

/* What rt_image_float_save hands the save: an image and its format. */
typedef struct float_bytes {
    const rt_image_float *image;
    rt_image_format format;
} float_bytes;

static rt_status produce_float(rt_write_func write, void *user,
                               const void *what, rt_error *error)
{
    const float_bytes *b = what;
    return rt_image_float_write_to(write, user, b->image, b->format, error);
}

rt_status rt_image_float_save(const char *path, const rt_image_float *image,
                              rt_image_format format,
                              const rt_save_options *options,
                              rt_error *error)
{
    if (path == NULL || path[0] == '\0' || !valid_float_image(image))
        return rt__error_set(error, RT_ERR_ARGUMENT, path, 0, 0,
                             "expected a path and a float image");
    if (format != RT_IMAGE_PFM && format != RT_IMAGE_EXR)
        return rt__error_set(error, RT_ERR_FORMAT, path, 0, 0,
                             "cannot write a float image as %s: expected "
                             "pfm or exr", rt_image_format_name(format));
    if (!rt_image_format_supported(format))
        return rt__image_format_refusal(format, error);
    float_bytes bytes = {image, format};
    rt_producer producer = {produce_float, &bytes, "image"};
    return rt__save(path, &producer, options, error);
}
