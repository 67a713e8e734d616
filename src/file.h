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

/* The same for a text file (a scene): reading stops early at a chunk
 * holding a NUL byte or past RT_MAX_SCENE_BYTES, so that /dev/zero or a
 * huge binary file costs a chunk, not the memory; rt__text_check then
 * names the reason. */
rt_status rt__read_text_file(const char *path, char **data, size_t *length,
                             rt_error *error);

#endif /* RAYTRACE_FILE_H */
