/*
 * view_scene.c - loading scenes, watching their files and naming the
 * images saved beside them (see view_scene.h).
 */
#include "view_scene.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli_export.h"

/* More numbered saves than anyone keeps: beyond, the folder is full of
 * them and S says so rather than searching on. */
#define MAX_NUMBERED_SAVES 100000

rt_status view_scene_load(const char *path, const rt_load_options *options,
                          rt_scene **scene, rt_error *error)
{
    *scene = NULL;
    return rt_scene_load(path, options, scene, error);
}

int view_scale_side(int side, double scale)
{
    double value = floor((double)side * scale + 0.5);
    if (value < 1.0)
        return 1;
    if (value > (double)RT_MAX_IMAGE_SIDE + 1.0)
        return RT_MAX_IMAGE_SIDE + 1;
    return (int)value;
}

int view_scene_image_path(const char *scene_path, rt_image_format format,
                          char *buffer, size_t size)
{
    char *name = cli_export_default_output(scene_path, format);
    if (name == NULL)
        return 0;
    const char *slash = strrchr(scene_path, '/');
    int folder = slash ? (int)(slash - scene_path + 1) : 0;
    int written = snprintf(buffer, size, "%.*s%s", folder, scene_path, name);
    free(name);
    return written >= 0 && (size_t)written < size;
}

int view_scene_side_path(const char *scene_path, const char *suffix,
                         char *buffer, size_t size)
{
    char image[4096];
    if (!view_scene_image_path(scene_path, RT_IMAGE_P6, image, sizeof image))
        return 0;
    char *dot = strrchr(image, '.');        /* the ".ppm" just added */
    if (dot != NULL)
        *dot = '\0';
    int written = snprintf(buffer, size, "%s%s", image, suffix);
    return written >= 0 && (size_t)written < size;
}

static int claim_failed(rt_error *error, const char *name, const char *why)
{
    if (error) {
        error->status = RT_ERR_IO;
        error->line = 0;
        error->column = 0;
        snprintf(error->message, sizeof error->message, "%s: %s", name, why);
    }
    return 0;
}

int view_save_claim_numbered(const char *path, const char *tag, char *buffer,
                             size_t size, rt_error *error)
{
    /* The number goes before the extension of the last path component. */
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    const char *dot = strrchr(base, '.');
    size_t stem = dot && dot != base ? (size_t)(dot - path) : strlen(path);
    const char *extension = path + stem;
    for (int n = 1; n <= MAX_NUMBERED_SAVES; n++) {
        int written = tag ? snprintf(buffer, size, "%.*s-%s-%d%s", (int)stem,
                                     path, tag, n, extension)
                          : snprintf(buffer, size, "%.*s-%d%s", (int)stem,
                                     path, n, extension);
        if (written < 0 || (size_t)written >= size)
            return claim_failed(error, path, "the name is too long");
        int fd = open(buffer, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            close(fd);
            return 1;
        }
        if (errno != EEXIST)
            return claim_failed(error, buffer, strerror(errno));
    }
    return claim_failed(error, path, "every numbered name is taken");
}

void view_file_stamp_read(const char *path, view_file_stamp *stamp)
{
    struct stat info;
    memset(stamp, 0, sizeof *stamp);
    if (stat(path, &info) != 0)
        return;
    stamp->exists = 1;
    stamp->device = (unsigned long long)info.st_dev;
    stamp->inode = (unsigned long long)info.st_ino;
    stamp->size = (long long)info.st_size;
    stamp->mtime_seconds = (long long)info.st_mtim.tv_sec;
    stamp->mtime_nanoseconds = info.st_mtim.tv_nsec;
}

int view_file_stamp_equal(const view_file_stamp *a, const view_file_stamp *b)
{
    return a->exists == b->exists && a->device == b->device &&
           a->inode == b->inode && a->size == b->size &&
           a->mtime_seconds == b->mtime_seconds &&
           a->mtime_nanoseconds == b->mtime_nanoseconds;
}
