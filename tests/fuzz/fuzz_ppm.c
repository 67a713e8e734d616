/*
 * fuzz_ppm.c - libFuzzer harness for the PPM reader from memory.
 *
 * rt_ppm_parse reads the images that rt-bench and the tests compare against;
 * they come from disk, so they are untrusted too.  An accepted image is
 * written back through the sink writer and parsed again: the round trip must
 * give the same pixels.
 *
 * Built only with -DRAYTRACE_FUZZ=ON and clang (tests/fuzz/CMakeLists.txt).
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "raytrace/raytrace.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void require(int condition)
{
    if (!condition)
        abort();
}

typedef struct buffer {
    unsigned char *bytes;
    size_t used, capacity;
} buffer;

static int append(void *user, const void *data, size_t size)
{
    buffer *b = user;
    if (b->used + size > b->capacity) {
        size_t capacity = (b->used + size) * 2;
        unsigned char *bigger = realloc(b->bytes, capacity);
        if (bigger == NULL)
            return 0;
        b->bytes = bigger;
        b->capacity = capacity;
    }
    memcpy(b->bytes + b->used, data, size);
    b->used += size;
    return 1;
}

static void round_trip(const rt_image *image, rt_image_format format)
{
    buffer out = {NULL, 0, 0};
    require(rt_image_write_to(append, &out, image, format, NULL) == RT_OK);
    rt_image again;
    rt_error error;
    require(rt_ppm_parse(out.bytes, out.used, "again", &again, &error) ==
            RT_OK);
    require(again.width == image->width && again.height == image->height);
    for (int y = 0; y < image->height; y++)
        require(memcmp(rt_image_pixel(&again, 0, y),
                       rt_image_pixel(image, 0, y),
                       (size_t)image->width * 3) == 0);
    rt_image_release(&again);
    free(out.bytes);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    unsigned char *copy = malloc(size ? size : 1);
    if (copy == NULL)
        return 0;
    if (size)
        memcpy(copy, data, size);
    rt_image image;
    rt_error error;
    memset(&error, 0x55, sizeof error);
    rt_status status = rt_ppm_parse(copy, size, "fuzz.ppm", &image, &error);
    if (status == RT_OK) {
        require(image.pixels != NULL);
        /* Keep the round trip cheap: large images are only parsed. */
        if ((size_t)image.width * (size_t)image.height <= 4096) {
            round_trip(&image, RT_IMAGE_P6);
            round_trip(&image, RT_IMAGE_P3);
        }
        rt_image_release(&image);
    } else {
        require(image.pixels == NULL);
        require(error.status == status);
        require(memchr(error.message, '\0', sizeof error.message) != NULL);
        require(error.message[0] != '\0');
    }
    free(copy);
    return 0;
}
