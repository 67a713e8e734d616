/*
 * raytrace/image.h - RGB8 images, their file formats, and saving them.
 *
 * An rt_image is a view: width, height, a row stride in bytes and a pointer
 * to pixels (3 bytes per pixel, R G B, rows top to bottom).  The caller may
 * point it at memory it owns, or let rt_image_init allocate it.
 *
 * Formats: PPM (Netpbm P3, ASCII, and P6, binary, maxval 255) always; PNG
 * (8-bit RGB, no gamma or colour-space chunk, so viewers show the computed
 * values as they are) when the library was built with libpng
 * (rt_image_format_supported says).  Float images (rt_image_float, linear
 * RGB, 1.0 = white, unclamped: the renderer's colours before rounding) go
 * to PFM always and to OpenEXR in builds with OpenEXR; see below.  Every
 * writer goes to a sink (a
 * callback); the FILE and path variants are thin wrappers.
 *
 * Saving to a path (rt_image_save) never damages
 * what the path names.  The rule, by what the path names once symbolic
 * links are followed to their final target:
 *
 *   - nothing yet, or a regular file: the image is written to a temporary
 *     file in the same folder (".rt-save-XXXXXX"), flushed to the disk and
 *     renamed over the target, so the target is always either the complete
 *     old file or the complete new one.  A new file gets the mode
 *     0666 & ~umask, as cp and compilers give; a replaced file keeps its
 *     permission bits, and its owner and group where the process may set
 *     them.  A regular file with several hard links is written in place
 *     instead, so that the links stay one file: the image is first written
 *     completely to the temporary file, its space reserved in the target,
 *     then copied over it.
 *   - a symbolic link: the rule applies to its final target; the link stays.
 *   - a character or block device, a FIFO or a socket: written directly,
 *     as a stream, never replaced (no temporary file, no rename).
 *   - a descriptor of the calling process named as a file: /dev/fd/N,
 *     /proc/self/fd/N (or /proc/PID/fd/N with its own PID), /dev/stdout and
 *     /dev/stderr (links to /proc/self/fd/1 and 2), bash's >(command): the
 *     bytes are written through descriptor N itself, at its current offset
 *     (at the end when it was opened for appending, as by >>); it is left
 *     open and nothing is reopened, truncated or replaced, so what the
 *     caller wrote before and writes after stays around the image.  A
 *     descriptor that is closed or open only for reading is an error naming
 *     it.  A caller that also writes to N through stdio flushes its stream
 *     first.  Another process's /proc/PID/fd/N is opened again as a stream
 *     (a regular file behind it is rewritten from its start: the offset is
 *     that process's).
 *   - a directory, a missing folder, a folder that cannot be written to: an
 *     error naming the path and the reason; nothing is created.
 *
 * The temporary file is removed on every failure; a stream or descriptor
 * that fails half-way keeps what was written before the failure.
 *
 * Signals are the caller's (rt_save_options).  By default a save neither
 * blocks nor polls any signal and installs no handler: a signal takes its
 * usual effect at once, so a program killed during a save may leave its
 * temporary file behind (the target itself is still either the complete
 * old file or the complete new one).  A program that asks for
 * hold_termination_signals has SIGINT, SIGTERM and SIGHUP (those it does
 * not ignore) blocked in the calling thread while the temporary file
 * exists; if one arrives, the temporary file is removed, the target is
 * left as it was, the signal mask is restored (so the signal then takes
 * its usual effect: a program that keeps the default action ends, killed
 * by it) and the call returns RT_ERR_INTERRUPTED.  Such a program should
 * block those signals in its other threads, or a signal sent to the
 * process may be taken by another thread while a save is under way.
 *
 * Readers accept P3 and P6 with maxval 255 (what the writers produce) from
 * memory or a path.  All functions are thread-safe on distinct images and
 * distinct paths.
 */
#ifndef RAYTRACE_IMAGE_H
#define RAYTRACE_IMAGE_H

#include "raytrace/export.h"

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

/* Fills the caller's `image` with a black width x height image (stride
 * 3 * width) whose pixels it allocates; rt_image_release frees them.  Sides
 * must be in 1..RT_MAX_IMAGE_SIDE.  RT_OK, RT_ERR_ARGUMENT or RT_ERR_NOMEM
 * with the reason in *error (may be NULL); on failure image->pixels is
 * NULL.  Thread-safe on distinct images. */
RT_API rt_status rt_image_init(rt_image *image, int width, int height,
                               rt_error *error);

/* Frees the pixels rt_image_init or rt_ppm_parse allocated and zeroes the
 * view; a zeroed image is a no-op. */
RT_API void rt_image_release(rt_image *image);

/* Pointer to pixel (x, y). */
static inline unsigned char *rt_image_pixel(const rt_image *image, int x,
                                            int y)
{
    return image->pixels + (size_t)y * image->stride + (size_t)x * 3;
}

/* The file formats the library writes (the PPM values are the digit of
 * the magic number, "P3" and "P6"). */
typedef enum rt_image_format {
    RT_IMAGE_P3 = 3,        /* PPM, ASCII (the course's format), lines of
                               at most 70 characters */
    RT_IMAGE_P6 = 6,        /* PPM, binary */
    RT_IMAGE_PNG = 16,      /* PNG, 8-bit RGB; needs a build with libpng */
    RT_IMAGE_PFM = 32,      /* Portable FloatMap, float32 RGB (an
                               rt_image_float only) */
    RT_IMAGE_EXR = 33       /* OpenEXR, FLOAT RGB, ZIP (an rt_image_float
                               only); needs a build with OpenEXR */
} rt_image_format;

/* Non-zero when this build can write `format` (PNG needs libpng).
 * Thread-safe. */
RT_API int rt_image_format_supported(rt_image_format format);

/* The lower-case name of a format ("p3", "p6", "png"); "unknown" for any
 * other value.  Thread-safe. */
RT_API const char *rt_image_format_name(rt_image_format format);

/*
 * The format a path's extension asks for, case-insensitively: ".png" PNG,
 * ".pfm" PFM, ".exr" EXR, ".ppm" and ".pnm" binary P6 (P3 is never chosen by extension: it is asked
 * for by name).  Returns RT_OK, or RT_ERR_FORMAT for any other extension or
 * none (*format untouched) with a message naming the path in *error (may be
 * NULL).  Does not look at the file.  Thread-safe.
 */
RT_API rt_status rt_image_format_from_path(const char *path,
                                           rt_image_format *format,
                                           rt_error *error);

/* Receives `size` bytes of output; returns non-zero on success. */
typedef int (*rt_write_func)(void *user, const void *data, size_t size);

/*
 * Encodes `image` in `format` to the sink.  Returns RT_OK, RT_ERR_ARGUMENT
 * (no image or sink), RT_ERR_FORMAT (a format this build cannot write; the
 * message says why), RT_ERR_IO (the sink returned 0) or RT_ERR_NOMEM.  A
 * NULL `error` is allowed.  Thread-safe on distinct sinks.
 */
RT_API rt_status rt_image_write_to(rt_write_func write, void *user,
                                   const rt_image *image,
                                   rt_image_format format, rt_error *error);

/* The same to a stdio stream, flushed at the end (a full device is an
 * RT_ERR_IO).  The stream is not closed.  Thread-safe on distinct
 * streams. */
RT_API rt_status rt_image_write_file(FILE *file, const rt_image *image,
                                     rt_image_format format, rt_error *error);

/*
 * How a save to a path treats the process (rt_save_options_init sets the
 * defaults; the struct grows by the rule of raytrace/render.h: `size`
 * first, fields beyond it keep their defaults, 0 or a size larger than
 * the library's is refused with RT_ERR_ARGUMENT).
 */
typedef struct rt_save_options {
    size_t size;                    /* sizeof(rt_save_options); set by
                                       rt_save_options_init */
    int hold_termination_signals;   /* non-zero: SIGINT, SIGTERM and SIGHUP
                                       are held while a temporary file
                                       exists, and one that arrives makes
                                       the save return RT_ERR_INTERRUPTED
                                       (the rule at the top of this header);
                                       0 (the default): the signal mask and
                                       the handlers are left alone */
} rt_save_options;

/* Sets size to sizeof(rt_save_options) and the defaults above (no signal
 * held).  NULL: no-op.  Thread-safe. */
RT_API void rt_save_options_init(rt_save_options *options);

/*
 * Saves `image` in `format` at `path` following the rule at the top of this
 * header, with `options` (NULL: the defaults).  Returns RT_OK; RT_ERR_IO
 * with a message naming the path and the reason ("is a directory", "the
 * folder ... does not exist", "Permission denied", "No space left on
 * device" ...); RT_ERR_FORMAT; RT_ERR_NOMEM; RT_ERR_INTERRUPTED (only when
 * the options hold the termination signals: one arrived, nothing was
 * changed); or RT_ERR_ARGUMENT (no path or image, or options of a bad
 * size).  Thread-safe on distinct paths.
 */
RT_API rt_status rt_image_save(const char *path, const rt_image *image,
                               rt_image_format format,
                               const rt_save_options *options,
                               rt_error *error);

/*
 * Checks, without rendering anything, that rt_image_save could write at
 * `path`: the folder exists and takes a new file (a file is created in it
 * and removed at once), or the device opens for writing, or the FIFO or
 * socket may be written to, or the descriptor is open for writing (its
 * offset untouched); a directory is refused.  Leaves nothing behind.
 * `options` are those the save will have (NULL: the defaults): when they
 * hold the termination signals, so does the check while its probe file
 * exists.  Returns RT_OK or what rt_image_save would return, with the same
 * messages.  Programs call it before a long render so that a bad output
 * fails in milliseconds.  Thread-safe.
 */
RT_API rt_status rt_image_save_check(const char *path,
                                     const rt_save_options *options,
                                     rt_error *error);

/*
 * Float images: linear RGB, unclamped, 1.0 = white (a channel of the
 * model's 0..255 scale divided by 255; docs/saving-images.md).  A view like
 * rt_image: `stride` counts floats from one row to the next, >= 3 * width,
 * rows top to bottom.  rt_render fills one through
 * rt_render_options.linear.  Only the float formats (RT_IMAGE_PFM,
 * RT_IMAGE_EXR) take them, and only float images take those formats
 * (RT_ERR_FORMAT otherwise).  Thread-safe on distinct images and paths.
 */
typedef struct rt_image_float {
    int width;
    int height;
    size_t stride;          /* floats from one row to the next */
    float *pixels;
} rt_image_float;

/* As rt_image_init: a zero (black) image of width x height floats RGB,
 * stride 3 * width; free it with rt_image_float_release (a zeroed image
 * is a no-op there). */
RT_API rt_status rt_image_float_init(rt_image_float *image, int width,
                                     int height, rt_error *error);
RT_API void rt_image_float_release(rt_image_float *image);

/* Pointer to pixel (x, y), three floats R G B. */
static inline float *rt_image_float_pixel(const rt_image_float *image, int x,
                                          int y)
{
    return image->pixels + (size_t)y * image->stride + (size_t)x * 3;
}

/*
 * Encodes `image` as PFM ("PF", width and height, scale -1.0 for little
 * endian, then the rows bottom to top, as the format wants) or EXR to the
 * sink.  Same statuses as rt_image_write_to; RT_ERR_FORMAT for a format
 * that is not a float one, or EXR in a build without OpenEXR.
 * Thread-safe on distinct sinks.
 */
RT_API rt_status rt_image_float_write_to(rt_write_func write, void *user,
                                         const rt_image_float *image,
                                         rt_image_format format,
                                         rt_error *error);

/* Saves a float image at `path` by the rule at the top of this header
 * (the same temporary file and rename, statuses and messages as
 * rt_image_save).  Thread-safe on distinct paths. */
RT_API rt_status rt_image_float_save(const char *path,
                                     const rt_image_float *image,
                                     rt_image_format format,
                                     const rt_save_options *options,
                                     rt_error *error);

/* Parses a P3 or P6 image from `length` bytes at `data` into a new image
 * (free it with rt_image_release).  `name` is used in messages ("<memory>"
 * when NULL).  RT_ERR_ARGUMENT for a NULL `data` or `image`; the reader's
 * status (RT_ERR_FORMAT, RT_ERR_SYNTAX, RT_ERR_RANGE, RT_ERR_NOMEM) with the
 * position in the message for bad bytes; *image is zeroed on failure.
 * rt_ppm_load reads the file at `path` first (RT_ERR_ARGUMENT for a NULL
 * path; RT_ERR_IO when it cannot be read).  Thread-safe. */
RT_API rt_status rt_ppm_parse(const void *data, size_t length,
                              const char *name, rt_image *image,
                              rt_error *error);
RT_API rt_status rt_ppm_load(const char *path, rt_image *image,
                             rt_error *error);

#ifdef __cplusplus
}
#endif

#endif /* RAYTRACE_IMAGE_H */
