/*
 * save_target.c - where a save writes: the path given to rt__save followed
 * to what it finally names (rt__save_resolve).  Symbolic links are followed
 * here, link by link, so that the temporary file lands beside the final
 * target and the rename replaces the target, not the link; a path inside
 * /proc is left to the kernel, whose links are not paths; a descriptor of
 * this process named as a file (/dev/fd/N, /proc/self/fd/N, /dev/stdout,
 * what bash's >(...) passes) is found by its folder, once canonical, being
 * the process's table of descriptors, and checked open for writing.
 * What each kind of target is written as is save.c's (raytrace/image.h
 * states the rule).
 */
/* realpath is X/Open's, beyond the _POSIX_C_SOURCE every target is built
 * with (cmake/RaytraceWarnings.cmake). */
#define _XOPEN_SOURCE 700

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "base/error.h"
#include "formats/save_target.h"

/* Links followed before giving up, as the kernel's own limit (ELOOP). */
#define MAX_LINKS 40

static char *copy_string(const char *s, size_t length)
{
    char *copy = malloc(length + 1);
    if (copy != NULL) {
        memcpy(copy, s, length);
        copy[length] = '\0';
    }
    return copy;
}

char *rt__save_folder_of(const char *path)
{
    const char *slash = strrchr(path, '/');
    return copy_string(path, slash ? (size_t)(slash - path) + 1 : 0);
}

/* A link's target, read relative to the link's folder (malloc'd). */
static char *follow(const char *link, rt_status *status)
{
    size_t capacity = 256;
    for (;;) {
        char *target = malloc(capacity);
        if (target == NULL)
            return *status = RT_ERR_NOMEM, NULL;
        ssize_t n = readlink(link, target, capacity);
        if (n < 0) {
            free(target);
            return *status = RT_ERR_IO, NULL;
        }
        if ((size_t)n < capacity) {
            target[n] = '\0';
            if (target[0] == '/')
                return target;
            char *folder = rt__save_folder_of(link);
            char *joined = folder ? malloc(strlen(folder) + (size_t)n + 1)
                                  : NULL;
            if (joined != NULL) {
                strcpy(joined, folder);
                strcat(joined, target);
            }
            free(folder);
            free(target);
            return joined ? joined : (*status = RT_ERR_NOMEM, NULL);
        }
        free(target);
        if (capacity > (size_t)SSIZE_MAX / 2)
            return *status = RT_ERR_IO, errno = ENAMETOOLONG, NULL;
        capacity *= 2;
    }
}

/* A path inside /proc names an open descriptor (/dev/stdout leads there);
 * its links are the kernel's, not paths to follow by hand. */
static int in_proc(const char *path)
{
    return strncmp(path, "/proc/", 6) == 0;
}

rt_status rt__save_io_error(rt_error *error, const char *path, int saved,
                            const char *what)
{
    return rt__error_set(error, RT_ERR_IO, path, 0, 0, "%s: %s", what,
                         strerror(saved));
}

rt_status rt__save_write_error(rt_error *error, const char *path, int saved,
                               const char *noun)
{
    return rt__error_set(error, RT_ERR_IO, path, 0, 0,
                         "cannot write the %s: %s", noun, strerror(saved));
}

/* The canonical name of folder `folder` ("" for the current one), or NULL
 * (malloc'd). */
static char *real_folder(const char *folder)
{
    return realpath(folder[0] ? folder : ".", NULL);
}

/* Non-zero when `real` (a canonical folder) is this process's table of
 * descriptors: /proc/PID/fd, or a thread's /proc/PID/task/TID/fd. */
static int own_descriptor_table(const char *real)
{
    char *own = realpath("/proc/self", NULL);
    int same = 0;
    if (own != NULL) {
        size_t n = strlen(own);
        const char *rest = strncmp(real, own, n) == 0 ? real + n : NULL;
        if (rest != NULL && strncmp(rest, "/task/", 6) == 0) {
            rest += 6;
            if (*rest < '0' || *rest > '9')
                rest = NULL;
            while (rest != NULL && *rest >= '0' && *rest <= '9')
                rest++;
        }
        same = rest != NULL && strcmp(rest, "/fd") == 0;
        free(own);
    }
    return same;
}

/*
 * Non-zero, with *fd set, when `path` names a descriptor of this process:
 * its last part is a number and its folder is the process's table of
 * descriptors once canonical (/dev/fd/N and /proc/self/fd/N lead there, and
 * /dev/stdout is a link to /proc/self/fd/1).  Another process's table
 * (/proc/PID/fd/N) is not: its descriptors are not this process's to write
 * through.
 */
static int descriptor_named(const char *path, int *fd)
{
    const char *slash = strrchr(path, '/');
    const char *digits = slash ? slash + 1 : path;
    int number = 0;
    if (*digits == '\0')
        return 0;
    for (const char *c = digits; *c; c++) {
        if (*c < '0' || *c > '9' || number > (INT_MAX - (*c - '0')) / 10)
            return 0;
        number = number * 10 + (*c - '0');
    }
    char *folder = copy_string(path, (size_t)(digits - path));
    char *real = folder ? real_folder(folder) : NULL;
    int own = real != NULL && own_descriptor_table(real);
    free(real);
    free(folder);
    if (own)
        *fd = number;
    return own;
}

/* Checks that descriptor d->fd is open for writing and not a folder, and
 * fills d->st. */
static rt_status check_descriptor(const char *path, rt_save_target *d,
                                  const char *noun, rt_error *error)
{
    int flags = fcntl(d->fd, F_GETFL);
    if (flags < 0)
        return rt__error_set(error, RT_ERR_IO, path, 0, 0,
                             "cannot write the %s: descriptor %d is not "
                             "open", noun, d->fd);
    int mode = flags & O_ACCMODE;
#ifdef O_PATH
    if (flags & O_PATH)
        mode = O_RDONLY;
#endif
    if (fstat(d->fd, &d->st) != 0)
        return rt__save_write_error(error, path, errno, noun);
    if (S_ISDIR(d->st.st_mode))
        return rt__error_set(error, RT_ERR_IO, path, 0, 0,
                             "cannot write the %s: is a directory", noun);
    if (mode != O_WRONLY && mode != O_RDWR)
        return rt__error_set(error, RT_ERR_IO, path, 0, 0,
                             "cannot write the %s: descriptor %d is open "
                             "for reading only", noun, d->fd);
    return RT_OK;
}

rt_status rt__save_resolve(const char *path, rt_save_target *d,
                           const char *noun, rt_error *error)
{
    memset(d, 0, sizeof *d);
    char *current = copy_string(path, strlen(path));
    if (current == NULL)
        return rt__error_set(error, RT_ERR_NOMEM, path, 0, 0,
                             "out of memory");
    for (int links = 0;; links++) {
        if (descriptor_named(current, &d->fd)) {
            d->path = current;
            d->kind = RT__TARGET_DESCRIPTOR;
            return check_descriptor(path, d, noun, error);
        }
        if (in_proc(current)) {
            /* Let the kernel follow its own links: stat the whole path. */
            free(current);
            d->path = copy_string(path, strlen(path));
            if (d->path == NULL)
                return rt__error_set(error, RT_ERR_NOMEM, path, 0, 0,
                                     "out of memory");
            if (stat(path, &d->st) != 0) {
                int saved = errno;
                if (saved == ENOENT || saved == ENOTDIR) {
                    /* a new file in a real folder reached through
                     * /proc */
                    d->kind = RT__TARGET_ABSENT;
                    return RT_OK;
                }
                free(d->path);
                d->path = NULL;
                return rt__save_write_error(error, path, saved, noun);
            }
            if (S_ISDIR(d->st.st_mode))
                return rt__error_set(error, RT_ERR_IO, path, 0, 0,
                                     "cannot write the %s: is a "
                                     "directory", noun);
            d->kind = RT__TARGET_STREAM;
            return RT_OK;
        }
        if (lstat(current, &d->st) != 0) {
            int saved = errno;
            /* A missing or non-folder parent is told by the temporary
             * file's creation, which names the folder. */
            if (saved != ENOENT && saved != ENOTDIR) {
                free(current);
                return rt__save_write_error(error, path, saved, noun);
            }
            d->kind = RT__TARGET_ABSENT;
            break;
        }
        if (!S_ISLNK(d->st.st_mode)) {
            mode_t m = d->st.st_mode;
            d->kind = S_ISDIR(m)    ? RT__TARGET_DIRECTORY
                      : S_ISSOCK(m) ? RT__TARGET_SOCKET
                      : S_ISREG(m)  ? (d->st.st_nlink > 1 ? RT__TARGET_LINKED
                                                          : RT__TARGET_REGULAR)
                                    : RT__TARGET_STREAM;
            break;
        }
        if (links == MAX_LINKS) {
            free(current);
            return rt__save_write_error(error, path, ELOOP, noun);
        }
        rt_status status = RT_OK;
        char *next = follow(current, &status);
        int saved = errno;
        free(current);
        if (next == NULL)
            return status == RT_ERR_NOMEM
                       ? rt__error_set(error, status, path, 0, 0,
                                       "out of memory")
                       : rt__save_io_error(error, path, saved,
                                  "cannot follow the symbolic link");
        current = next;
    }
    d->path = current;
    if (d->kind == RT__TARGET_DIRECTORY)
        return rt__error_set(error, RT_ERR_IO, path, 0, 0,
                             "cannot write the %s: is a directory", noun);
    return RT_OK;
}
