/*
 * png.c - writing PNG images with libpng (built only when the build found
 * libpng; see RAYTRACE_PNG in src/CMakeLists.txt).
 *
 * The image is written as it is: 8-bit RGB, no interlacing, and no gAMA,
 * cHRM, sRGB or iCCP chunk, so a viewer shows the computed values without a
 * colour transformation (the same bytes a P6 file holds).  libpng reports
 * errors by longjmp; everything this file allocates is released before the
 * setjmp point can be reached again.
 */
#include <png.h>
#include <setjmp.h>
#include <stdio.h>
#include <string.h>

#include "base/error.h"
#include "formats/formats.h"

typedef struct png_sink {
    rt_write_func write;
    void *user;
    int failed;             /* the sink refused bytes */
    char message[128];      /* libpng's own message, if it stopped */
} png_sink;

static void on_write(png_structp png, png_bytep data, size_t size)
{
    png_sink *s = png_get_io_ptr(png);
    if (!s->write(s->user, data, size)) {
        s->failed = 1;
        png_error(png, "the sink refused the bytes");
    }
}

static void on_flush(png_structp png)
{
    (void)png;              /* the sink has no flush: the caller flushes */
}

static void on_error(png_structp png, png_const_charp message)
{
    png_sink *s = png_get_error_ptr(png);
    snprintf(s->message, sizeof s->message, "%s", message);
    png_longjmp(png, 1);
}

static void on_warning(png_structp png, png_const_charp message)
{
    (void)png;
    (void)message;          /* nothing this writer does warrants one */
}

rt_status rt__png_write_to(rt_write_func write, void *user,
                           const rt_image *image, rt_error *error)
{
    png_sink sink = {write, user, 0, ""};
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &sink,
                                              on_error, on_warning);
    if (png == NULL)
        return rt__error_set(error, RT_ERR_NOMEM, NULL, 0, 0,
                             "out of memory starting the PNG encoder");
    png_infop info = png_create_info_struct(png);
    if (info == NULL) {
        png_destroy_write_struct(&png, NULL);
        return rt__error_set(error, RT_ERR_NOMEM, NULL, 0, 0,
                             "out of memory starting the PNG encoder");
    }
    /* Nothing below allocates outside png and info, which the error path
     * frees: no local variable changes after setjmp. */
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        if (sink.failed)
            return rt__error_set(error, RT_ERR_IO, NULL, 0, 0,
                                 "cannot write the image: the output "
                                 "refused the bytes");
        return rt__error_set(error, RT_ERR_IO, NULL, 0, 0,
                             "cannot encode the PNG image: %s",
                             sink.message);
    }
    png_set_write_fn(png, &sink, on_write, on_flush);
    png_set_IHDR(png, info, (png_uint_32)image->width,
                 (png_uint_32)image->height, 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < image->height; y++)
        png_write_row(png, rt_image_pixel(image, 0, y));
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    return RT_OK;
}
