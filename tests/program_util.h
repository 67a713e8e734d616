/*
 * program_util.h - running the project's programs as a user does, for the
 * suites of the command line (test_cli.c, test_cli_outputs.c,
 * test_cli_json.c, test_cli_numbers.c, test_explain_terms.c): a fresh
 * folder, files in it, and a program run there with its standard streams
 * captured (or given), its exit status read back.
 */
#ifndef RAYTRACE_TESTS_PROGRAM_UTIL_H
#define RAYTRACE_TESTS_PROGRAM_UTIL_H

#include <stddef.h>
#include <sys/types.h>

#include "testutil.h"

/* A new folder /tmp/rt-test-cli-XXXXXX, malloc'd; remove_dir frees it. */
char *fresh_dir(void);

/* Removes `dir` and everything in it (rm -rf), then frees it. */
void remove_dir(char *dir);

/* dir/name in a static buffer (one of four at a time). */
const char *in_dir(const char *dir, const char *name);

/* Writes `text` to `path`, replacing it. */
void write_text(const char *path, const char *text);

/* What a run of a program gave. */
typedef struct run {
    int code;               /* exit status, or 128 + the signal */
    char *out;              /* standard output (empty when given) */
    size_t out_size;
    char *err;              /* standard error */
} run;

void run_free(run *r);

/* How to start it: NULL fields take the defaults. */
typedef struct run_setup {
    const char *stdin_path;     /* NULL: /dev/null */
    const char *stdout_path;    /* NULL: captured into run.out */
    const char *tmpdir;         /* NULL: TMPDIR as the suite has it */
} run_setup;

/* Runs `program` with `args` (NULL-terminated) in `dir`, standard input
 * from /dev/null, standard output and error captured. */
run run_in(const char *dir, const char *program, const char *const *args);

/* The same, started as `setup` says. */
run run_with(const char *dir, const char *program, const char *const *args,
             const run_setup *setup);

/* A program started with its standard error into a pipe, read as it
 * comes (a test acts when a line appears: the first progress line). */
typedef struct started {
    pid_t pid;
    int err_fd;             /* the pipe's read end */
    char *err;              /* what was read so far, NUL-terminated */
    size_t err_length;
    char out_path[4200];    /* where its standard output goes */
    run_setup setup;
} started;

started start_piped(const char *dir, const char *program,
                    const char *const *args, const run_setup *setup);

/* Reads standard error until a whole line starting with `start` has come:
 * 1, or 0 when the program closed it first. */
int wait_for_line(started *s, const char *start);

/* Reads the rest, waits for the program's end; the run it made. */
run finish_piped(started *s);

/* Whether python3 and its json module are installed. */
int python_has_json(void);

#endif /* RAYTRACE_TESTS_PROGRAM_UTIL_H */
