/*
 * file.c - reading a whole file into memory.
 */
#include "file.h"

#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "raytrace/scene.h"

/* Reads all of `file`, or, when `text`, stops after the chunk that holds
 * a NUL byte or takes the size past RT_MAX_SCENE_BYTES. */
static rt_status read_all(const char *path, int text, char **data,
                          size_t *length, rt_error *error)
{
    *data = NULL;
    *length = 0;
    FILE *file = fopen(path, "rb");
    if (file == NULL)
        return rt__error_set(error, RT_ERR_IO, path, 0, 0, "cannot open: %s",
                             strerror(errno));
    size_t capacity = 1 << 16, used = 0;
    char *buffer = malloc(capacity);
    while (buffer != NULL) {
        size_t got = fread(buffer + used, 1, capacity - used - 1, file);
        used += got;
        if (used < capacity - 1)
            break;
        if (text && (used > RT_MAX_SCENE_BYTES ||
                     memchr(buffer + used - got, 0, got) != NULL))
            break;          /* the text check names the reason */
        char *bigger = capacity <= SIZE_MAX / 2 ? realloc(buffer, capacity * 2)
                                                : NULL;
        if (bigger == NULL)
            free(buffer);
        buffer = bigger;
        capacity *= 2;
    }
    int failed = ferror(file);
    int saved = errno;
    fclose(file);
    if (buffer == NULL)
        return rt__error_set(error, RT_ERR_NOMEM, path, 0, 0,
                             "out of memory reading the file");
    if (failed) {
        free(buffer);
        return rt__error_set(error, RT_ERR_IO, path, 0, 0, "cannot read: %s",
                             strerror(saved));
    }
    buffer[used] = '\0';
    *data = buffer;
    *length = used;
    return RT_OK;
}

rt_status rt__read_file(const char *path, char **data, size_t *length,
                        rt_error *error)
{
    return read_all(path, 0, data, length, error);
}

rt_status rt__read_text_file(const char *path, char **data, size_t *length,
                             rt_error *error)
{
    return read_all(path, 1, data, length, error);
}
