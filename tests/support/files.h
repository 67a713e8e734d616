/*
 * files.h - the files and folders of a test: a fresh folder of its own and
 * its removal, paths in it (a value, a malloc'd string, or one of a few
 * static buffers), whole files read and written, and what a folder holds.
 * Part of the support library (tests/support/).  The functions fail the
 * test (Check) when they cannot do their job, except those that say they
 * are safe in a forked child.
 */
#ifndef RAYTRACE_TEST_FILES_H
#define RAYTRACE_TEST_FILES_H

#include <limits.h>
#include <stddef.h>
#include <stdio.h>

/* A new empty folder of mode 0700 under $TMPDIR (or /tmp), named
 * rt-test-XXXXXX; malloc'd, and freed by rt_test_remove_dir. */
char *rt_test_temp_dir(void);

/* Removes `dir` and everything in it (restoring the permissions a test took
 * away first), then frees `dir`; does what it can (safe in a forked
 * child). */
void rt_test_remove_dir(char *dir);

/* A path as a value, for a test that holds many at a time. */
typedef struct rt_test_path {
    char s[PATH_MAX];
} rt_test_path;

/* "<dir>/<name>" as a value. */
rt_test_path rt_test_path_at(const char *dir, const char *name);

/* "<dir>/<name>", malloc'd. */
char *rt_test_join(const char *dir, const char *name);

/* "<dir>/<name>" in a static buffer, one of eight used in turn: good until
 * eight more calls. */
const char *rt_test_in_dir(const char *dir, const char *name);

/* The whole file at `path`, malloc'd and NUL-terminated (the NUL not
 * counted), its length through *size when not NULL; NULL when it cannot
 * be opened. */
char *rt_test_read_file(const char *path, size_t *size);

/* The rest of `file` from where it stands, read the same way (the file
 * stays open). */
char *rt_test_read_stream(FILE *file, size_t *size);

/* Writes `size` bytes, or the string `text`, to the file at `path`,
 * replacing it. */
void rt_test_write_bytes(const char *path, const void *data, size_t size);
void rt_test_write_file(const char *path, const char *text);

/* Non-zero when the file at `path` holds exactly the `size` bytes `data`.
 * Calls no Check function (safe in a forked child). */
int rt_test_file_holds(const char *path, const void *data, size_t size);

/* The type bits (S_IFREG, S_IFIFO...) of what `path` names, the last
 * component not followed (lstat); 0 when nothing is there. */
unsigned rt_test_file_kind(const char *path);

/* Fails the test unless `path` is a symbolic link whose text is `target`. */
void rt_test_assert_link(const char *path, const char *target);

/* The names in `dir` other than . and .. (hidden ones too), sorted and
 * joined by spaces; malloc'd; NULL when the folder cannot be read.  Calls
 * no Check function (safe in a forked child). */
char *rt_test_dir_names(const char *dir);

/* Fails the test unless `dir` holds exactly `expected` (rt_test_dir_names'
 * form), saying what it holds. */
void rt_test_assert_dir_holds(const char *dir, const char *expected);

#endif /* RAYTRACE_TEST_FILES_H */
