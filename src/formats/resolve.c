/*
 * resolve.c - the default resolver of the files a scene names (resolve.h),
 * and names as messages show them; the list of what one load reads is
 * sources.c's.
 *
 * rt_resolve_in_folder takes a name relative to the scene's folder and
 * walks it one component at a time from a descriptor of that folder
 * (openat with O_NOFOLLOW), so that no component is ever looked up outside
 * it: an absolute name or `..` is refused before any look-up, and a
 * symbolic link is followed only when its target, walked the same way,
 * stays inside (an absolute target, or `..` above the folder, is refused
 * unread).  So nothing outside the folder is touched, and a refusal there
 * cannot tell a missing file from an unreadable one.  The last component
 * is checked with fstatat before it is opened (a FIFO, a device or a
 * folder is never opened), opened with O_NONBLOCK | O_NOCTTY, and checked
 * again with fstat on the descriptor, so that a FIFO swapped in between
 * cannot block the load; only then is it read, at most `limit` bytes.
 * Folders on the way must be readable (they are opened O_RDONLY).
 */
#include "formats/resolve.h"

#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "base/error.h"

#define MAX_LINKS 40        /* links followed in one name (Linux's limit) */
#define MAX_DEPTH 64        /* folders below the scene's in one name */
#define MAX_NAME_BYTES 4096 /* a name, and a name with a link's target */

/* ----------------------------------------------------------- names shown */


char *rt__shown_name(const char *name)
{
    size_t size = 4 * strlen(name) + 1;     /* an escape per byte at most */
    char *out = malloc(size);
    if (out != NULL)
        rt__escape_name(name, out, size);
    return out;
}

/* -------------------------------------------------------- the walk */

typedef enum walk_result {
    WALK_OPEN,          /* *fd is the file, a regular one */
    WALK_OUTSIDE,       /* the name leads out of the folder */
    WALK_FAILED,        /* a look-up inside the folder failed: w->error */
    WALK_NOT_REGULAR,   /* a folder, FIFO, device or socket: w->mode */
    WALK_TOO_BIG        /* more than the limit: w->size */
} walk_result;

typedef struct walk {
    int fds[MAX_DEPTH + 1];     /* [0]: the scene's folder */
    int depth;
    char path[MAX_NAME_BYTES + 1];  /* what is left to walk */
    int links;
    int error;
    mode_t mode;
    long long size;
    uint64_t device, inode;     /* of the file opened */
} walk;

/* Replaces the component `name` (a link in the current folder) by its
 * target followed by `rest`. */
static walk_result follow(walk *w, const char *name, const char *rest,
                          char **cursor)
{
    char target[MAX_NAME_BYTES + 1];
    ssize_t n = readlinkat(w->fds[w->depth], name, target, MAX_NAME_BYTES);
    if (n < 0 || ++w->links > MAX_LINKS) {
        w->error = n < 0 ? errno : ELOOP;
        return WALK_FAILED;
    }
    target[n] = '\0';
    if (target[0] == '/')
        return WALK_OUTSIDE;
    size_t rest_length = strlen(rest);
    if ((size_t)n + 1 + rest_length > MAX_NAME_BYTES) {
        w->error = ENAMETOOLONG;
        return WALK_FAILED;
    }
    char joined[MAX_NAME_BYTES + 2];
    memcpy(joined, target, (size_t)n);
    size_t used = (size_t)n;
    if (rest_length > 0)
        joined[used++] = '/';
    memcpy(joined + used, rest, rest_length + 1);
    memcpy(w->path, joined, used + rest_length + 1);
    *cursor = w->path;
    return WALK_OPEN;           /* go on */
}

static walk_result check_regular(walk *w, const struct stat *st,
                                 size_t limit)
{
    w->mode = st->st_mode;
    w->size = (long long)st->st_size;
    if (!S_ISREG(st->st_mode))
        return WALK_NOT_REGULAR;
    return (unsigned long long)st->st_size > limit ? WALK_TOO_BIG : WALK_OPEN;
}

/* The last component: checked by name without following a link, opened
 * without blocking, checked again on the descriptor.  WALK_OPEN with *fd
 * -1 means a link whose target is now w->path, to walk on. */
static walk_result open_last(walk *w, const char *name, const char *rest,
                             size_t limit, int *fd, char **cursor)
{
    struct stat st;
    if (fstatat(w->fds[w->depth], name, &st, AT_SYMLINK_NOFOLLOW) != 0) {
        w->error = errno;
        return WALK_FAILED;
    }
    if (S_ISLNK(st.st_mode))
        return follow(w, name, rest, cursor);
    walk_result result = check_regular(w, &st, limit);
    if (result != WALK_OPEN)
        return result;
    *fd = openat(w->fds[w->depth], name,
                 O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC | O_NOFOLLOW);
    if (*fd < 0 && errno == ELOOP)          /* a link swapped in */
        return follow(w, name, rest, cursor);
    if (*fd < 0 || fstat(*fd, &st) != 0) {
        w->error = errno;
        if (*fd >= 0)
            close(*fd);
        *fd = -1;
        return WALK_FAILED;
    }
    result = check_regular(w, &st, limit);  /* swapped for a FIFO? */
    if (result != WALK_OPEN) {
        close(*fd);
        *fd = -1;
        return result;
    }
    w->device = (uint64_t)st.st_dev;
    w->inode = (uint64_t)st.st_ino;
    return WALK_OPEN;
}

/* Walks `reference` from the folder w->fds[0]; on WALK_OPEN *fd is open. */
static walk_result walk_to(walk *w, const char *reference, size_t limit,
                           int *fd)
{
    *fd = -1;
    size_t length = strlen(reference);
    if (reference[0] == '/')
        return WALK_OUTSIDE;
    for (const char *c = reference; (c = strstr(c, "..")) != NULL; c += 2)
        if ((c == reference || c[-1] == '/') && (c[2] == '/' || c[2] == '\0'))
            return WALK_OUTSIDE;    /* no `..` in the name itself */
    if (length > MAX_NAME_BYTES) {
        w->error = ENAMETOOLONG;
        return WALK_FAILED;
    }
    memcpy(w->path, reference, length + 1);
    char *cursor = w->path;
    for (;;) {
        while (*cursor == '/')
            cursor++;
        if (*cursor == '\0') {          /* the name ends with a folder */
            w->mode = S_IFDIR;
            return WALK_NOT_REGULAR;
        }
        char *name = cursor, *end = strchr(cursor, '/');
        int last = end == NULL;
        cursor = last ? name + strlen(name) : end + 1;
        if (!last)
            *end = '\0';
        if (strcmp(name, ".") == 0)
            continue;
        if (strcmp(name, "..") == 0) {
            if (w->depth == 0)
                return WALK_OUTSIDE;
            close(w->fds[w->depth--]);
            continue;
        }
        walk_result result;
        if (last) {
            result = open_last(w, name, cursor, limit, fd, &cursor);
            if (result != WALK_OPEN || *fd >= 0)
                return result;
            continue;                   /* a link: its target next */
        }
        int next = openat(w->fds[w->depth], name,
                          O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
        if (next < 0) {
            int error = errno;
            struct stat st;
            if (fstatat(w->fds[w->depth], name, &st, AT_SYMLINK_NOFOLLOW) ==
                    0 &&
                S_ISLNK(st.st_mode)) {
                result = follow(w, name, cursor, &cursor);
                if (result != WALK_OPEN)
                    return result;
                continue;
            }
            w->error = error;
            return WALK_FAILED;
        }
        if (w->depth == MAX_DEPTH) {
            close(next);
            w->error = ENAMETOOLONG;
            return WALK_FAILED;
        }
        w->fds[++w->depth] = next;
    }
}

/* Reads at most limit + 1 bytes of the regular file `fd`: 1 and the bytes,
 * 0 with *error (errno, or 0 when out of memory), or -1 when it holds more
 * than `limit`. */
static int read_regular(int fd, long long size, size_t limit, char **data,
                        size_t *length, int *error)
{
    size_t capacity = (size_t)size + 1, used = 0;
    char *buffer = malloc(capacity + 1);
    if (buffer == NULL) {
        *error = 0;
        return 0;
    }
    for (;;) {
        if (used == capacity) {
            if (used > limit) {
                free(buffer);
                return -1;
            }
            size_t bigger = capacity * 2 > limit + 1 ? limit + 1
                                                     : capacity * 2;
            char *grown = realloc(buffer, bigger + 1);
            if (grown == NULL) {
                free(buffer);
                *error = 0;
                return 0;
            }
            buffer = grown;
            capacity = bigger;
        }
        ssize_t got = read(fd, buffer + used, capacity - used);
        if (got < 0 && errno == EINTR)
            continue;
        if (got < 0) {
            *error = errno;
            free(buffer);
            return 0;
        }
        if (got == 0)
            break;
        used += (size_t)got;
    }
    if (used > limit) {
        free(buffer);
        return -1;
    }
    buffer[used] = '\0';
    *data = buffer;
    *length = used;
    return 1;
}

/* "folder/" of the scene (its name up to its last slash), or "". */
static size_t folder_prefix(const char *scene_name)
{
    const char *slash = scene_name ? strrchr(scene_name, '/') : NULL;
    return slash ? (size_t)(slash - scene_name) + 1 : 0;
}

static const char *kind_of(mode_t mode)
{
    return S_ISDIR(mode)    ? "a folder"
           : S_ISFIFO(mode) ? "a FIFO"
           : S_ISCHR(mode)  ? "a character device"
           : S_ISBLK(mode)  ? "a block device"
           : S_ISSOCK(mode) ? "a socket"
                            : "not a regular file";
}

/* The one message of a refusal; it names the reference and quotes no
 * file: outside the folder nothing was looked up, so it cannot tell a
 * missing file from an unreadable one. */
static rt_status refusal(walk_result result, const walk *w, const char *shown,
                         size_t limit, rt_error *error)
{
    switch (result) {
    case WALK_OUTSIDE:
        return rt__error_set(
            error, RT_ERR_IO, NULL, 0, 0,
            "`%s` is not read: a file a scene names must lie in the scene's "
            "folder (a relative name, without `..`, through no symbolic "
            "link that leads out of it)", shown);
    case WALK_NOT_REGULAR:
        return rt__error_set(error, RT_ERR_IO, NULL, 0, 0,
                             "`%s` is not read: it is %s, not a regular "
                             "file", shown, kind_of(w->mode));
    case WALK_TOO_BIG:
        return rt__error_set(error, RT_ERR_LIMIT, NULL, 0, 0,
                             "`%s` is not read: it holds more than the %zu "
                             "bytes the scene may still read", shown, limit);
    case WALK_FAILED:
        if (w->fds[0] < 0)
            return rt__error_set(error, RT_ERR_IO, NULL, 0, 0,
                                 "`%s` is not read: the scene's folder "
                                 "cannot be opened (%s)", shown,
                                 strerror(w->error));
        return rt__error_set(error, RT_ERR_IO, NULL, 0, 0,
                             "`%s` is not read: %s", shown,
                             strerror(w->error));
    case WALK_OPEN:
        break;
    }
    return RT_OK;
}

/* The folder of the scene (its name up to its last slash; "." without
 * one), for open. */
static char *folder_of(const char *scene_name)
{
    size_t prefix = folder_prefix(scene_name);
    char *folder = malloc(prefix + 2);
    if (folder == NULL)
        return NULL;
    if (prefix == 0)
        memcpy(folder, ".", 2);
    else if (prefix == 1)
        memcpy(folder, "/", 2);
    else
        memcpy(folder, scene_name, prefix - 1), folder[prefix - 1] = '\0';
    return folder;
}

/* The name of a file found: the scene's folder as the scene was named,
 * then the reference (raw bytes: messages escape it, rt__escape_name). */
static char *found_name(const char *scene_name, const char *reference)
{
    size_t prefix = folder_prefix(scene_name), n = strlen(reference);
    char *full = malloc(prefix + n + 1);
    if (full == NULL)
        return NULL;
    if (prefix > 0)
        memcpy(full, scene_name, prefix);
    memcpy(full + prefix, reference, n + 1);
    return full;
}

rt_status rt_resolve_in_folder(void *user, const char *scene_name,
                               const char *reference, size_t limit,
                               rt_resolved_file *file, rt_error *error)
{
    (void)user;
    if (reference == NULL || file == NULL)
        return rt__error_set(error, RT_ERR_ARGUMENT, NULL, 0, 0,
                             "expected a name and a file to fill");
    char *folder = folder_of(scene_name);
    char *shown = rt__shown_name(reference);
    walk w;
    memset(&w, 0, sizeof w);
    w.fds[0] = folder ? open(folder, O_RDONLY | O_DIRECTORY | O_CLOEXEC) : -1;
    w.error = errno;
    free(folder);
    if (folder == NULL || shown == NULL) {
        free(shown);
        if (w.fds[0] >= 0)
            close(w.fds[0]);
        return rt__error_set(error, RT_ERR_NOMEM, NULL, 0, 0,
                             "out of memory");
    }
    walk_result result = WALK_FAILED;
    int fd = -1;
    if (w.fds[0] >= 0)
        result = reference[0] == '\0' ? WALK_OUTSIDE
                                      : walk_to(&w, reference, limit, &fd);
    for (int i = 0; i <= w.depth; i++)
        if (w.fds[i] >= 0)
            close(w.fds[i]);
    char *data = NULL;
    size_t length = 0;
    if (result == WALK_OPEN) {
        int got = read_regular(fd, w.size, limit, &data, &length, &w.error);
        close(fd);
        if (got == 0 && w.error == 0) {
            free(shown);
            return rt__error_set(error, RT_ERR_NOMEM, NULL, 0, 0,
                                 "out of memory");
        }
        result = got > 0 ? WALK_OPEN : got < 0 ? WALK_TOO_BIG : WALK_FAILED;
    }
    rt_status status = refusal(result, &w, shown, limit, error);
    free(shown);
    if (status == RT_OK && (file->name = found_name(scene_name, reference)) ==
                               NULL)
        status = rt__error_set(error, RT_ERR_NOMEM, NULL, 0, 0,
                               "out of memory");
    if (status != RT_OK) {
        free(data);
        return status;
    }
    file->data = data;
    file->length = length;
    file->device = w.device;
    file->inode = w.inode;
    return RT_OK;
}
