/*
 * save_target.h - what a path given to the save names (internal): the
 * final target once symbolic links are followed one by one, and whether it
 * is a new or regular file, a multiply linked one, a stream, a socket, a
 * folder or a descriptor of this process (save_target.c).  save.c writes
 * by what this says, following the rule of raytrace/image.h.
 */
#ifndef RAYTRACE_SAVE_TARGET_H
#define RAYTRACE_SAVE_TARGET_H

#include <sys/stat.h>

#include "raytrace/status.h"

/* What the destination is, once links are followed. */
typedef enum rt_target_kind {
    RT__TARGET_ABSENT,      /* nothing there yet */
    RT__TARGET_REGULAR,
    RT__TARGET_LINKED,      /* a regular file with several hard links */
    RT__TARGET_STREAM,      /* device, FIFO, or another process's
                               descriptor through /proc */
    RT__TARGET_SOCKET,
    RT__TARGET_DIRECTORY,
    RT__TARGET_DESCRIPTOR   /* a descriptor of this process, open for
                               writing: written through it */
} rt_target_kind;

typedef struct rt_save_target {
    char *path;             /* the final target (malloc'd; the caller frees
                               it, even on failure) */
    rt_target_kind kind;
    struct stat st;         /* of the target, when it exists */
    int fd;                 /* RT__TARGET_DESCRIPTOR: the descriptor */
} rt_save_target;

/* Follows `path` to what it finally names and says what that is in *t.
 * RT_OK; RT_ERR_IO for a folder, a loop of links, a link that cannot be
 * read, a descriptor closed or open for reading only, or a stat that
 * fails, with the message naming `path` and calling the bytes `noun`;
 * RT_ERR_NOMEM.  A missing file (or a missing or non-folder parent) is
 * RT__TARGET_ABSENT: the temporary file's creation tells the folder's
 * problem. */
rt_status rt__save_resolve(const char *path, rt_save_target *t,
                           const char *noun, rt_error *error);

/* The folder part of `path` with its slash ("dir/"), or "" (malloc'd;
 * NULL when out of memory). */
char *rt__save_folder_of(const char *path);

/* "WHAT: reason" for errno `saved`, as RT_ERR_IO naming `path`. */
rt_status rt__save_io_error(rt_error *error, const char *path, int saved,
                            const char *what);

/* "cannot write the NOUN: reason" for errno `saved`, as RT_ERR_IO naming
 * `path`. */
rt_status rt__save_write_error(rt_error *error, const char *path, int saved,
                               const char *noun);

#endif /* RAYTRACE_SAVE_TARGET_H */
