/*
 * exr.c - the OpenEXR writer, through OpenEXR's C API (openexr.h, the
 * OpenEXRCore library): one scanline part of FLOAT channels B, G, R (the
 * order EXR sorts them in), ZIP compression.  The library seeks back to
 * write its table of chunk offsets, so the file is built in memory and
 * then handed to the sink at once.
 */
#include <openexr.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "formats/formats.h"

/* The file in memory: bytes written at any offset. */
typedef struct memory_file {
    unsigned char *data;
    size_t size, capacity;
    int failed;
} memory_file;

static int64_t memory_write(exr_const_context_t context, void *user,
                            const void *buffer, uint64_t size,
                            uint64_t offset,
                            exr_stream_error_func_ptr_t error_callback)
{
    (void)context;
    (void)error_callback;
    memory_file *m = user;
    if (offset + size > m->capacity) {
        size_t capacity = m->capacity ? m->capacity : 65536;
        while (capacity < offset + size)
            capacity *= 2;
        unsigned char *data = realloc(m->data, capacity);
        if (data == NULL) {
            m->failed = 1;
            return -1;
        }
        m->data = data;
        m->capacity = capacity;
    }
    if (offset > m->size)
        memset(m->data + m->size, 0, offset - m->size);
    memcpy(m->data + offset, buffer, size);
    if (offset + size > m->size)
        m->size = offset + size;
    return (int64_t)size;
}

static void quiet(exr_const_context_t context, exr_result_t code,
                  const char *message)
{
    (void)context;
    (void)code;
    (void)message;
}

static exr_result_t write_chunks(exr_context_t context,
                                 const rt_image_float *image)
{
    int32_t lines = 0;
    exr_result_t r = exr_get_scanlines_per_chunk(context, 0, &lines);
    if (r != EXR_ERR_SUCCESS)
        return r;
    size_t row_bytes = (size_t)image->width * sizeof(float);
    float *planar = malloc(row_bytes * 3 * (size_t)lines);
    if (planar == NULL)
        return EXR_ERR_OUT_OF_MEMORY;
    exr_encode_pipeline_t encoder;
    int started = 0;
    for (int y = 0; y < image->height && r == EXR_ERR_SUCCESS; y += lines) {
        exr_chunk_info_t chunk;
        r = exr_write_scanline_chunk_info(context, 0, y, &chunk);
        if (r != EXR_ERR_SUCCESS)
            break;
        int first = !started;
        r = started ? exr_encoding_update(context, 0, &chunk, &encoder)
                    : exr_encoding_initialize(context, 0, &chunk, &encoder);
        if (r != EXR_ERR_SUCCESS)
            break;
        started = 1;
        int height = chunk.height;
        /* the channels in the order the header sorted them: B, G, R */
        for (int c = 0; c < encoder.channel_count; c++) {
            int source = encoder.channels[c].channel_name[0] == 'R'   ? 0
                         : encoder.channels[c].channel_name[0] == 'G' ? 1
                                                                      : 2;
            float *plane = planar + (size_t)c * image->width * height;
            for (int row = 0; row < height; row++) {
                const float *p = rt_image_float_pixel(image, 0, y + row);
                for (int x = 0; x < image->width; x++)
                    plane[(size_t)row * image->width + x] = p[3 * x + source];
            }
            encoder.channels[c].encode_from_ptr = (const uint8_t *)plane;
            encoder.channels[c].user_pixel_stride = sizeof(float);
            encoder.channels[c].user_line_stride = (int32_t)row_bytes;
            encoder.channels[c].user_data_type = EXR_PIXEL_FLOAT;
            encoder.channels[c].user_bytes_per_element = sizeof(float);
        }
        if (first)
            r = exr_encoding_choose_default_routines(context, 0, &encoder);
        if (r == EXR_ERR_SUCCESS)
            r = exr_encoding_run(context, 0, &encoder);
    }
    if (started)
        exr_encoding_destroy(context, &encoder);
    free(planar);
    return r;
}

static exr_result_t write_exr(memory_file *m, const rt_image_float *image)
{
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.user_data = m;
    init.write_fn = memory_write;
    init.error_handler_fn = quiet;
    exr_context_t context = NULL;
    exr_result_t r = exr_start_write(&context, "<memory>",
                                     EXR_WRITE_FILE_DIRECTLY, &init);
    if (r != EXR_ERR_SUCCESS)
        return r;
    int part = 0;
    r = exr_add_part(context, "image", EXR_STORAGE_SCANLINE, &part);
    if (r == EXR_ERR_SUCCESS)
        r = exr_initialize_required_attr_simple(context, part, image->width,
                                                image->height,
                                                EXR_COMPRESSION_ZIP);
    static const char *const names[] = {"R", "G", "B"};
    for (int c = 0; c < 3 && r == EXR_ERR_SUCCESS; c++)
        r = exr_add_channel(context, part, names[c], EXR_PIXEL_FLOAT,
                            EXR_PERCEPTUALLY_LOGARITHMIC, 1, 1);
    if (r == EXR_ERR_SUCCESS)
        r = exr_write_header(context);
    if (r == EXR_ERR_SUCCESS)
        r = write_chunks(context, image);
    exr_result_t finished = exr_finish(&context);
    return r != EXR_ERR_SUCCESS ? r : finished;
}

rt_status rt__exr_write_to(rt_write_func write, void *user,
                           const rt_image_float *image, rt_error *error)
{
    memory_file m = {0};
    exr_result_t r = write_exr(&m, image);
    rt_status status = RT_OK;
    if (r != EXR_ERR_SUCCESS)
        status = rt__error_set(error, m.failed || r == EXR_ERR_OUT_OF_MEMORY
                                          ? RT_ERR_NOMEM
                                          : RT_ERR_IO,
                               NULL, 0, 0, "cannot encode the EXR: %s",
                               exr_get_error_code_as_string(r));
    else if (!write(user, m.data, m.size))
        status = rt__error_set(error, RT_ERR_IO, NULL, 0, 0,
                               "cannot write the image: %s",
                               rt_status_string(RT_ERR_IO));
    free(m.data);
    return status;
}
