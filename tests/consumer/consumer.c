/*
 * consumer.c - the smallest useful client of an installed libraytrace.
 *
 * Built against the installed package (CMake's find_package, or pkg-config),
 * it checks that the headers and the library agree on the version, parses a
 * one-triangle scene from memory, renders it and writes it as P6 to a memory
 * sink: everything a user needs links, nothing touches the disk.
 */
#include <stdio.h>
#include <string.h>

#include <raytrace/raytrace.h>

static const char scene_text[] =
    "0 0 10\n"
    "0 0 5  4 0 5  8 6\n"
    "3\n-6 -4 0\n6 -4 0\n0 5 0\n"
    "1\n1 2 3 0.5 200 100 50\n"
    "20 40 60\n"
    "0.125 0.125 4 255 204 102\n";

typedef struct buffer {
    unsigned char data[512];
    size_t size;
} buffer;

static int append(void *user, const void *data, size_t size)
{
    buffer *out = user;

    if (size > sizeof out->data - out->size)
        return 0;
    memcpy(out->data + out->size, data, size);
    out->size += size;
    return 1;
}

int main(void)
{
    static const char header[] = "P6\n8 6\n255\n";
    rt_scene *scene;
    rt_image image;
    rt_error error;
    rt_status status;
    buffer out = {{0}, 0};

    if (strcmp(rt_version_string(), RT_VERSION_STRING) != 0) {
        fprintf(stderr, "consumer: headers say %s, library says %s\n",
                RT_VERSION_STRING, rt_version_string());
        return 1;
    }
    if (rt_scene_parse(scene_text, sizeof scene_text - 1, "<consumer>", NULL,
                       &scene, &error) != RT_OK) {
        fprintf(stderr, "consumer: %s\n", error.message);
        return 1;
    }
    status = rt_image_init(&image, 8, 6, NULL);
    if (status == RT_OK)
        status = rt_render(scene, NULL, &image, NULL);
    if (status == RT_OK)
        status = rt_image_write_to(append, &out, &image, RT_IMAGE_P6, NULL);
    rt_image_release(&image);
    rt_scene_destroy(scene);
    if (status != RT_OK) {
        fprintf(stderr, "consumer: %s\n", rt_status_string(status));
        return 1;
    }
    if (out.size != sizeof header - 1 + 8 * 6 * 3
        || memcmp(out.data, header, sizeof header - 1) != 0) {
        fprintf(stderr, "consumer: unexpected P6 output (%zu bytes)\n",
                out.size);
        return 1;
    }
    printf("consumer: libraytrace %s rendered 8x6 to %zu bytes of P6\n",
           rt_version_string(), out.size);
    return 0;
}
