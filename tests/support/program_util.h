/*
 * program_util.h - running the project's programs as a user does, for the
 * suites of the command line (test_cli.c, test_cli_outputs.c,
 * test_json_output.c, test_cli_numbers.c, test_explain_terms.c,
 * test_viewer_outputs.c): a fresh folder, files in it, a program run there
 * with its standard streams captured (or given) and its exit status read
 * back, and the main of a suite whose checks wait for the loader's list of
 * the files it read.
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

/* Whether the loader lists the files a load read (rt_scene_source_at):
 * the OBJ of tests/data/obj and its material library. */
int loader_lists_its_files(void);

/* The main of a suite with a `sources` entry: `prog` runs main_fn's
 * suite; `prog sources` runs sources_fn's, or exits RT_TEST_SKIPPED (with
 * a line naming `prog`) while the loader lists no files. */
int main_with_sources(int argc, char **argv, Suite *(*main_fn)(void),
                      Suite *(*sources_fn)(void), const char *prog);

/* Whether python3 and its json module are installed. */
int python_has_json(void);

#endif /* RAYTRACE_TESTS_PROGRAM_UTIL_H */
