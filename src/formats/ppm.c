/*
 * ppm.c - writing and reading PPM images (Netpbm P3 and P6, maxval 255).
 *
 * The writer produces bytes through a sink callback, for rt_image_write_to
 * (image_format.c), whose FILE variant and save to a path (save.c) serve
 * every format.  Readers take
 * exactly what the writers produce plus what other Netpbm tools commonly
 * emit: comments and arbitrary white space in the header.
 */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "base/file.h"
#include "formats.h"
#include "raytrace/image.h"
#include "raytrace/scene.h"

/* P3 lines are at most this long (the Netpbm recommendation). */
#define P3_LINE_MAX 70

static int valid_image(const rt_image *image)
{
    return image != NULL && image->pixels != NULL && image->width > 0 &&
           image->height > 0 && image->stride >= (size_t)image->width * 3;
}

static rt_status write_p3_pixels(rt_write_func write, void *user,
                                 const rt_image *image)
{
    char line[P3_LINE_MAX + 2];
    size_t used = 0;
    for (int y = 0; y < image->height; y++) {
        const unsigned char *row = rt_image_pixel(image, 0, y);
        for (int i = 0; i < image->width * 3; i++) {
            char number[8];
            int n = snprintf(number, sizeof number, "%u", row[i]);
            if (used > 0 && used + 1 + (size_t)n > P3_LINE_MAX) {
                line[used++] = '\n';
                if (!write(user, line, used))
                    return RT_ERR_IO;
                used = 0;
            }
            if (used > 0)
                line[used++] = ' ';
            memcpy(line + used, number, (size_t)n);
            used += (size_t)n;
        }
    }
    line[used++] = '\n';
    return write(user, line, used) ? RT_OK : RT_ERR_IO;
}

rt_status rt__ppm_write_to(rt_write_func write, void *user,
                           const rt_image *image, rt_image_format format)
{
    if (!valid_image(image) || write == NULL)
        return RT_ERR_ARGUMENT;
    if (format != RT_IMAGE_P3 && format != RT_IMAGE_P6)
        return RT_ERR_FORMAT;
    char header[64];
    int n = snprintf(header, sizeof header, "P%d\n%d %d\n255\n", (int)format,
                     image->width, image->height);
    if (!write(user, header, (size_t)n))
        return RT_ERR_IO;
    if (format == RT_IMAGE_P3)
        return write_p3_pixels(write, user, image);
    for (int y = 0; y < image->height; y++)
        if (!write(user, rt_image_pixel(image, 0, y),
                   (size_t)image->width * 3))
            return RT_ERR_IO;
    return RT_OK;
}

/* A cursor over PPM bytes that knows its line and column. */
typedef struct reader {
    const unsigned char *at, *end;
    const char *name;
    int line, column;
} reader;

static void advance(reader *r)
{
    if (*r->at == '\n')
        r->line++, r->column = 1;
    else
        r->column++;
    r->at++;
}

static int is_space(int c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' ||
           c == '\f';
}

/* Skips white space and comments (a comment runs to the end of its line). */
static void skip_blank(reader *r)
{
    while (r->at < r->end) {
        if (*r->at == '#') {
            while (r->at < r->end && *r->at != '\n')
                advance(r);
        } else if (is_space(*r->at)) {
            advance(r);
        } else {
            break;
        }
    }
}

/* A byte for a message: itself when printable, else "\xNN". */
static const char *show_byte(unsigned char c, char buffer[8])
{
    if (c >= 0x20 && c < 0x7f)
        snprintf(buffer, 8, "%c", c);
    else
        snprintf(buffer, 8, "\\x%02X", c);
    return buffer;
}

/* Reads a decimal integer in [min, max] into *value; `what` names it. */
static rt_status read_uint(reader *r, long min, long max, const char *what,
                           long *value, rt_error *error)
{
    skip_blank(r);
    int line = r->line, column = r->column;
    if (r->at >= r->end)
        return rt__error_set(error, RT_ERR_SYNTAX, r->name, line, column,
                             "expected %s, found the end of the file", what);
    long v = 0;
    int digits = 0;
    while (r->at < r->end && *r->at >= '0' && *r->at <= '9') {
        if (v <= max)
            v = v * 10 + (*r->at - '0');
        digits++;
        advance(r);
    }
    if (digits == 0 || (r->at < r->end && !is_space(*r->at) && *r->at != '#')) {
        char shown[8];
        return rt__error_set(error, RT_ERR_SYNTAX, r->name, r->line,
                             r->column, "expected %s, found `%s`", what,
                             show_byte(*r->at, shown));
    }
    if (v < min || v > max)
        return rt__error_set(error, RT_ERR_RANGE, r->name, line, column,
                             "expected %s in %ld..%ld, found %s", what, min,
                             max, v > max ? "a larger number" : "0");
    *value = v;
    return RT_OK;
}

rt_status rt_ppm_parse(const void *data, size_t length, const char *name,
                       rt_image *image, rt_error *error)
{
    if (image == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, name, 0, 0,
                             "expected an image to fill");
    memset(image, 0, sizeof *image);
    if (data == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, name, 0, 0,
                             "expected the bytes of an image");
    reader r = {data, (const unsigned char *)data + length,
                name ? name : "<memory>", 1, 1};
    if (length < 2 || r.at[0] != 'P' || (r.at[1] != '3' && r.at[1] != '6'))
        return rt__error_set(error, RT_ERR_FORMAT, r.name, 1, 1,
                             "expected `P3` or `P6` at the start of the file");
    int binary = r.at[1] == '6';
    advance(&r);
    advance(&r);
    long width, height, maxval;
    rt_status status;
    if ((status = read_uint(&r, 1, RT_MAX_IMAGE_SIDE, "the width", &width,
                            error)) != RT_OK ||
        (status = read_uint(&r, 1, RT_MAX_IMAGE_SIDE, "the height", &height,
                            error)) != RT_OK ||
        (status = read_uint(&r, 1, 65535, "the maximum value", &maxval,
                            error)) != RT_OK)
        return status;
    if (maxval != 255)
        return rt__error_set(error, RT_ERR_FORMAT, r.name, r.line, r.column,
                             "expected a maximum value of 255, found %ld",
                             maxval);
    size_t bytes = (size_t)width * (size_t)height * 3;
    if (binary) {
        /* Exactly one white-space byte separates the header from pixels. */
        if (r.at >= r.end || !is_space(*r.at))
            return rt__error_set(error, RT_ERR_SYNTAX, r.name, r.line,
                                 r.column,
                                 "expected white space after the header");
        advance(&r);
        if ((size_t)(r.end - r.at) < bytes)
            return rt__error_set(error, RT_ERR_SYNTAX, r.name, r.line,
                                 r.column,
                                 "expected %zu bytes of pixels, found %zu",
                                 bytes, (size_t)(r.end - r.at));
    } else if ((size_t)(r.end - r.at) / 2 < bytes) {
        /* Each P3 value takes at least a digit and a separator: refuse a
         * header that promises more than the file can hold, before
         * allocating for it. */
        return rt__error_set(error, RT_ERR_SYNTAX, r.name, r.line, r.column,
                             "expected %zu pixel values, found a file too "
                             "short to hold them", bytes);
    }
    status = rt_image_init(image, (int)width, (int)height, NULL);
    if (status != RT_OK)
        return rt__error_set(error, status, r.name, 0, 0, "out of memory");
    if (binary) {
        memcpy(image->pixels, r.at, bytes);
        return RT_OK;
    }
    for (size_t i = 0; i < bytes; i++) {
        long v;
        if ((status = read_uint(&r, 0, 255, "a pixel value", &v, error)) !=
            RT_OK) {
            rt_image_release(image);
            return status;
        }
        image->pixels[i] = (unsigned char)v;
    }
    return RT_OK;
}

rt_status rt_ppm_load(const char *path, rt_image *image, rt_error *error)
{
    char *data;
    size_t length;
    if (image == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, path, 0, 0,
                             "expected an image to fill");
    memset(image, 0, sizeof *image);
    if (path == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "expected a path");
    rt_status status = rt__read_file(path, &data, &length, error);
    if (status != RT_OK)
        return status;
    status = rt_ppm_parse(data, length, path, image, error);
    free(data);
    return status;
}
