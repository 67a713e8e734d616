/*
 * image_format.c - choosing an image format and writing an image in it:
 * the dispatch between the PPM writers (ppm.c) and the PNG writer (png.c,
 * present only in builds with libpng).
 */
#include <ctype.h>
#include <stdio.h>
#include <string.h>

#include "base/error.h"
#include "base/file.h"
#include "formats/formats.h"

int rt_image_format_supported(rt_image_format format)
{
    switch (format) {
    case RT_IMAGE_P3:
    case RT_IMAGE_P6:
        return 1;
    case RT_IMAGE_PNG:
        return RAYTRACE_HAVE_PNG;
    case RT_IMAGE_PFM:
        return 1;
    case RT_IMAGE_EXR:
        return RAYTRACE_HAVE_EXR;
    }
    return 0;
}

const char *rt_image_format_name(rt_image_format format)
{
    switch (format) {
    case RT_IMAGE_P3:
        return "p3";
    case RT_IMAGE_P6:
        return "p6";
    case RT_IMAGE_PNG:
        return "png";
    case RT_IMAGE_PFM:
        return "pfm";
    case RT_IMAGE_EXR:
        return "exr";
    }
    return "unknown";
}

/* Non-zero when `extension` (with its dot) equals `wanted`, ignoring
 * case. */
static int extension_is(const char *extension, const char *wanted)
{
    for (; *extension && *wanted; extension++, wanted++)
        if (tolower((unsigned char)*extension) != *wanted)
            return 0;
    return *extension == '\0' && *wanted == '\0';
}

rt_status rt_image_format_from_path(const char *path, rt_image_format *format,
                                    rt_error *error)
{
    if (path == NULL || format == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "expected a path and a format to fill");
    const char *dot = rt__path_extension(path);
    if (dot != NULL && extension_is(dot, ".png"))
        *format = RT_IMAGE_PNG;
    else if (dot != NULL && extension_is(dot, ".pfm"))
        *format = RT_IMAGE_PFM;
    else if (dot != NULL && extension_is(dot, ".exr"))
        *format = RT_IMAGE_EXR;
    else if (dot != NULL &&
             (extension_is(dot, ".ppm") || extension_is(dot, ".pnm")))
        *format = RT_IMAGE_P6;
    else
        return rt__error_set(error, RT_ERR_FORMAT, path, 0, 0,
                             "cannot tell the image format: expected the "
                             "extension .png, .ppm, .pnm, .pfm or .exr");
    return RT_OK;
}

rt_status rt__image_format_refusal(rt_image_format format, rt_error *error)
{
    if (format == RT_IMAGE_PNG)
        return rt__error_set(error, RT_ERR_FORMAT, NULL, 0, 0,
                             "cannot write PNG: this build of libraytrace "
                             "has no PNG support (it was built without "
                             "libpng)");
    if (format == RT_IMAGE_EXR)
        return rt__error_set(error, RT_ERR_FORMAT, NULL, 0, 0,
                             "cannot write EXR: this build of libraytrace "
                             "has no OpenEXR support (configure with "
                             "-DRAYTRACE_EXR=ON and libopenexr-dev)");
    return rt__error_set(error, RT_ERR_FORMAT, NULL, 0, 0,
                         "cannot write images in format %d: expected p3, "
                         "p6, png, pfm or exr", (int)format);
}

rt_status rt_image_write_to(rt_write_func write, void *user,
                            const rt_image *image, rt_image_format format,
                            rt_error *error)
{
    if (!rt_image_format_supported(format))
        return rt__image_format_refusal(format, error);
    if (write == NULL || image == NULL || image->pixels == NULL ||
        image->width < 1 || image->height < 1 ||
        image->stride < (size_t)image->width * 3)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "expected an image and a sink");
    if (format == RT_IMAGE_PFM || format == RT_IMAGE_EXR)
        return rt__error_set(error, RT_ERR_FORMAT, NULL, 0, 0,
                             "cannot write an 8-bit image as %s, a float "
                             "format: write an rt_image_float "
                             "(rt_image_float_save)",
                             rt_image_format_name(format));
#if RAYTRACE_HAVE_PNG
    if (format == RT_IMAGE_PNG)
        return rt__png_write_to(write, user, image, error);
#endif
    rt_status status = rt__ppm_write_to(write, user, image, format);
    if (status != RT_OK)
        return rt__error_set(error, status, NULL, 0, 0,
                             "cannot write the image: %s",
                             rt_status_string(status));
    return RT_OK;
}

static int write_to_file(void *user, const void *data, size_t size)
{
    return fwrite(data, 1, size, (FILE *)user) == size;
}

rt_status rt_image_write_file(FILE *file, const rt_image *image,
                              rt_image_format format, rt_error *error)
{
    if (file == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "expected a stream");
    rt_status status = rt_image_write_to(write_to_file, file, image, format,
                                         error);
    /* A full device shows up only when the buffer is flushed. */
    if (status == RT_OK && (fflush(file) != 0 || ferror(file)))
        status = rt__error_set(error, RT_ERR_IO, NULL, 0, 0,
                               "cannot write the image: %s",
                               "input/output error");
    return status;
}
