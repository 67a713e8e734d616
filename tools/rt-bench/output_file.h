/*
 * output_file.h - writing a report file so that it is never left half
 * written: the text goes to a temporary file in the destination's directory,
 * which replaces the destination only once it is complete and on disk.
 */
#ifndef RAYTRACE_BENCH_OUTPUT_FILE_H
#define RAYTRACE_BENCH_OUTPUT_FILE_H

#include <stdio.h>

typedef struct output_file {
    FILE *file;             /* write here */
    char *temp_path;
    const char *path;
} output_file;

/* Opens a temporary file beside `path`; 0 (and errno) on failure. */
int output_file_open(output_file *out, const char *path);

/* With ok non-zero: flushes, syncs and renames the temporary file over the
 * destination, returning non-zero on success.  With ok zero, or on any
 * failure: removes the temporary file and leaves the destination as it
 * was, returning 0 with errno saying why. */
int output_file_close(output_file *out, int ok);

#endif /* RAYTRACE_BENCH_OUTPUT_FILE_H */
