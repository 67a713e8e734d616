/*
 * hostile_util.h - what the suites of bad input and faults share
 * (test_hostile_input.c, test_hostile_time.c, test_hostile_writes.c,
 * test_hostile_export.c): a small valid scene, temporary directories and
 * their listing, a recognisable "previous" file, and a way to run a check
 * in a forked child, so that the tests also hold under CK_FORK=no
 * (valgrind).
 */
#ifndef RAYTRACE_TESTS_HOSTILE_UTIL_H
#define RAYTRACE_TESTS_HOSTILE_UTIL_H

#include <stddef.h>

#include "testutil.h"

/* A scene of one facet, 40 x 30 pixels, every record on its own line. */
extern const char small_scene[];

/* A PPM file that is recognisably "the previous one". */
static const char previous_ppm[] = "P3\n1 1\n255\n1 2 3\n";

/* Whether the suite runs under valgrind (its preload in LD_PRELOAD). */
int under_valgrind(void);

/* A new directory under $TMPDIR (or /tmp), malloc'd; remove_dir frees it. */
char *make_temp_dir(void);
/* "<dir>/<name>", malloc'd. */
char *join(const char *dir, const char *name);
void write_bytes(const char *path, const void *data, size_t size);
/* The names in `dir` other than . and .., sorted, joined by spaces. */
char *list_dir(const char *dir);
/* Fails the test unless `dir` holds exactly `expected` (list_dir's form). */
void assert_dir_holds(const char *dir, const char *expected);
/* Removes the files of a flat directory, then the directory; frees `dir`. */
void remove_dir(char *dir);

/* A width x height image of a recognisable pattern. */
rt_image make_image(int width, int height);
/* Fails the test unless `path` still holds previous_ppm. */
void assert_previous_intact(const char *path);

/*
 * Runs `child(arg, message, size)` in a forked process and returns its exit
 * status (0: success; otherwise `message` says what went wrong).  What the
 * child reports travels through a pipe, so no Check call happens there.
 */
typedef int (*child_fn)(void *arg, char *message, size_t size);
int run_in_child(child_fn child, void *arg, char *message, size_t size);

/* In a child of run_in_child: limits the address space to what is in use
 * plus `more` bytes (RLIMIT_AS).  0, with `message` saying why, when it
 * cannot.  Meaningless under a sanitizer or valgrind, which reserve far
 * more than they use. */
int limit_address_space(size_t more, char *message, size_t size);

/* Parses `text` and checks the contract of a refusal; returns the status. */
rt_status parse_refused(const char *text, size_t length, rt_error *error);

/* A monotonic clock, in seconds. */
double now_seconds(void);

#endif /* RAYTRACE_TESTS_HOSTILE_UTIL_H */
