/*
 * image.c - allocating and freeing RGB8 images.
 */
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "raytrace/image.h"
#include "raytrace/scene.h"

rt_status rt_image_init(rt_image *image, int width, int height,
                        rt_error *error)
{
    if (image == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "expected an image to fill");
    memset(image, 0, sizeof *image);
    if (width < 1 || height < 1 || width > RT_MAX_IMAGE_SIDE ||
        height > RT_MAX_IMAGE_SIDE)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "an image of %d x %d pixels: each side must be "
                             "in 1..%d", width, height, RT_MAX_IMAGE_SIDE);
    size_t stride = (size_t)width * 3;
    unsigned char *pixels = calloc((size_t)height, stride);
    if (pixels == NULL)
        return rt__error_set(error, RT_ERR_NOMEM, NULL, 0, 0,
                             "out of memory for an image of %d x %d pixels",
                             width, height);
    image->width = width;
    image->height = height;
    image->stride = stride;
    image->pixels = pixels;
    return RT_OK;
}

void rt_image_release(rt_image *image)
{
    if (image == NULL)
        return;
    free(image->pixels);
    memset(image, 0, sizeof *image);
}
