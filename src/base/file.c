/*
 * file.c - reading a whole file into memory, and the extension of a path.
 */
#include "file.h"

#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "error.h"
#include "raytrace/scene.h"

/* How read_descriptor stops. */
enum {
    READ_ALL,           /* at the end */
    READ_TEXT,          /* after the chunk that holds a NUL byte or takes
                           the size past RT_MAX_SCENE_BYTES */
    READ_BOUNDED        /* after the chunk past RT_MAX_SCENE_BYTES */
};

/* Reads all of `fd`, stopping as `mode` says; `size_hint` (the size of a
 * regular file, else 0) sizes the first buffer.  Returns 0, or the
 * errno of a failed read (with *buffer still owned and filled), or -1
 * when out of memory (*buffer NULL). */
static int read_descriptor(int fd, int mode, size_t size_hint, char **out,
                           size_t *length)
{
    size_t capacity = 1 << 16, used = 0, checked = 0;
    /* A file's size known: one buffer, and one read more to see its end
     * (PLY bodies, read at memory speed). */
    if (mode == READ_BOUNDED && size_hint >= capacity &&
        size_hint <= RT_MAX_SCENE_BYTES)
        capacity = size_hint + 2;
    char *buffer = malloc(capacity);
    int failure = 0;
    while (buffer != NULL) {
        if (used == capacity - 1) {
            if (mode != READ_ALL &&
                (used > RT_MAX_SCENE_BYTES ||
                 (mode == READ_TEXT &&
                  memchr(buffer + checked, 0, used - checked) != NULL)))
                break;      /* the reader's check names the reason */
            checked = used;
            char *bigger = capacity <= SIZE_MAX / 2
                               ? realloc(buffer, capacity * 2)
                               : NULL;
            if (bigger == NULL)
                free(buffer);
            buffer = bigger;
            capacity *= 2;
            continue;
        }
        ssize_t got = read(fd, buffer + used, capacity - 1 - used);
        if (got < 0 && errno == EINTR)
            continue;
        if (got < 0)
            failure = errno;
        if (got <= 0)
            break;
        used += (size_t)got;
    }
    *out = buffer;
    if (buffer == NULL)
        return -1;
    buffer[used] = '\0';
    *length = used;
    return failure;
}

static rt_status read_all(const char *path, int mode, char **data,
                          size_t *length, rt_file_identity *identity,
                          rt_error *error)
{
    *data = NULL;
    *length = 0;
    if (identity != NULL)
        *identity = (rt_file_identity){0, 0};
    int fd = open(path, O_RDONLY | O_NOCTTY | O_CLOEXEC);
    if (fd < 0)
        return rt__error_set(error, RT_ERR_IO, path, 0, 0, "cannot open: %s",
                             strerror(errno));
    struct stat st;
    size_t size_hint = 0;
    if (fstat(fd, &st) == 0 && S_ISREG(st.st_mode)) {
        if (identity != NULL)
            *identity = (rt_file_identity){(uint64_t)st.st_dev,
                                           (uint64_t)st.st_ino};
        size_hint = st.st_size > 0 ? (size_t)st.st_size : 0;
    }
    char *buffer;
    int failure = read_descriptor(fd, mode, size_hint, &buffer, length);
    close(fd);
    if (failure < 0)
        return rt__error_set(error, RT_ERR_NOMEM, path, 0, 0,
                             "out of memory reading the file");
    if (failure > 0) {
        free(buffer);
        *length = 0;
        return rt__error_set(error, RT_ERR_IO, path, 0, 0, "cannot read: %s",
                             strerror(failure));
    }
    *data = buffer;
    return RT_OK;
}

rt_status rt__read_file(const char *path, char **data, size_t *length,
                        rt_error *error)
{
    return read_all(path, READ_ALL, data, length, NULL, error);
}

rt_status rt__read_text_file(const char *path, char **data, size_t *length,
                             rt_error *error)
{
    return read_all(path, READ_TEXT, data, length, NULL, error);
}

rt_status rt__read_text_file_identified(const char *path, char **data,
                                        size_t *length,
                                        rt_file_identity *identity,
                                        rt_error *error)
{
    return read_all(path, READ_TEXT, data, length, identity, error);
}

rt_status rt__read_scene_file_identified(const char *path, int text,
                                         char **data, size_t *length,
                                         rt_file_identity *identity,
                                         rt_error *error)
{
    return read_all(path, text ? READ_TEXT : READ_BOUNDED, data, length,
                    identity, error);
}

const char *rt__path_extension(const char *path)
{
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    const char *dot = strrchr(base, '.');
    return dot != NULL && dot != base ? dot : NULL;
}
