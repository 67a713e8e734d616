/*
 * file.h - reading a whole file into memory, and the extension of a path
 * (internal).
 */
#ifndef RAYTRACE_FILE_H
#define RAYTRACE_FILE_H

#include <stddef.h>
#include <stdint.h>

#include "raytrace/status.h"

/* What names a file read: its device and inode when it is a regular file,
 * 0 and 0 otherwise (a FIFO, a terminal, a device). */
typedef struct rt_file_identity {
    uint64_t device, inode;
} rt_file_identity;

/* Reads the file at `path` into a new NUL-terminated buffer (*data, to be
 * freed with free) of *length bytes.  The file is opened without becoming
 * the controlling terminal, and what was read is the descriptor's (fstat
 * on it, not on the name).  Errors name the path. */
rt_status rt__read_file(const char *path, char **data, size_t *length,
                        rt_error *error);

/* The same for a text file (a scene): reading stops early at a chunk
 * holding a NUL byte or past RT_MAX_SCENE_BYTES, so that /dev/zero or a
 * huge binary file costs a chunk, not the memory; the lexer's checks
 * (formats/lexer.h) then name the reason.  FIFOs and terminals are read to their end (a user
 * may name `<(cat x.scn)`).  *identity (may be NULL) receives what the
 * descriptor read was. */
rt_status rt__read_text_file(const char *path, char **data, size_t *length,
                             rt_error *error);
rt_status rt__read_text_file_identified(const char *path, char **data,
                                        size_t *length,
                                        rt_file_identity *identity,
                                        rt_error *error);

/* The same with the choice: `text` non-zero reads as
 * rt__read_text_file_identified; zero reads binary data (NUL bytes and
 * all) but stops as early past RT_MAX_SCENE_BYTES (a PLY's body). */
rt_status rt__read_scene_file_identified(const char *path, int text,
                                         char **data, size_t *length,
                                         rt_file_identity *identity,
                                         rt_error *error);

/* The extension of the last component of `path`, its dot included
 * (".scn"), or NULL when it has none (no dot, or only a leading one, as in
 * ".profile"). */
const char *rt__path_extension(const char *path);

#endif /* RAYTRACE_FILE_H */
