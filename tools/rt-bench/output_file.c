/*
 * output_file.c - report files written atomically (see output_file.h).
 */
#include "output_file.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

int output_file_open(output_file *out, const char *path)
{
    static const char pattern[] = ".rt-bench-XXXXXX";
    const char *slash = strrchr(path, '/');
    size_t dir_length = slash ? (size_t)(slash - path) + 1 : 0;
    out->file = NULL;
    out->path = path;
    out->temp_path = malloc(dir_length + sizeof pattern);
    if (out->temp_path == NULL)
        return 0;
    memcpy(out->temp_path, path, dir_length);
    memcpy(out->temp_path + dir_length, pattern, sizeof pattern);
    int fd = mkstemp(out->temp_path);
    if (fd >= 0) {
        fchmod(fd, 0644);
        out->file = fdopen(fd, "w");
        if (out->file == NULL) {
            close(fd);
            unlink(out->temp_path);
        }
    }
    if (out->file == NULL) {
        free(out->temp_path);
        out->temp_path = NULL;
        return 0;
    }
    return 1;
}

int output_file_close(output_file *out, int ok)
{
    if (out->file == NULL)
        return 0;
    int saved = errno;
    if (ok && (fflush(out->file) != 0 || ferror(out->file) ||
               fsync(fileno(out->file)) != 0))
        ok = 0, saved = errno;
    if (fclose(out->file) != 0 && ok)
        ok = 0, saved = errno;
    if (ok && rename(out->temp_path, out->path) != 0)
        ok = 0, saved = errno;
    if (!ok)
        unlink(out->temp_path);
    errno = saved;      /* the reason, for the caller's message */
    free(out->temp_path);
    out->file = NULL;
    out->temp_path = NULL;
    return ok;
}
