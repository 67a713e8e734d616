/*
 * file.h - reading a whole file into memory (internal).
 */
#ifndef RAYTRACE_FILE_H
#define RAYTRACE_FILE_H

#include <stddef.h>

#include "raytrace/status.h"

/* Reads the file at `path` into a new NUL-terminated buffer (*data, to be
 * freed with free) of *length bytes.  Errors name the path. */
rt_status rt__read_file(const char *path, char **data, size_t *length,
                        rt_error *error);

#endif /* RAYTRACE_FILE_H */
