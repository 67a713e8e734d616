/*
 * programs.h - running the project's programs as a user does: in a folder,
 * with standard input from a file (or /dev/null), standard output and error
 * captured (or standard output to a file the test names), the termination
 * signals and SIGPIPE at their default action, and the exit status read
 * back; or started, watched while it runs (its standard error line by
 * line, its CPU time) and finished later.  Captured streams go to
 * unlinked temporary files, so a run adds nothing to the folder it runs
 * in.  Part of the support library (tests/support/); every function fails
 * the test (Check) when it cannot do its job.
 */
#ifndef RAYTRACE_TEST_PROGRAMS_H
#define RAYTRACE_TEST_PROGRAMS_H

#include <stdio.h>
#include <sys/types.h>

/* How to start a program; NULL and 0 fields take the defaults. */
typedef struct rt_test_setup {
    const char *stdin_path;     /* NULL: /dev/null */
    const char *stdout_path;    /* NULL: captured into rt_test_output.out;
                                   else opened for writing, created (0644)
                                   but not truncated */
    const char *tmpdir;         /* NULL: TMPDIR as the suite has it */
    long long file_size_limit;  /* > 0: RLIMIT_FSIZE, in bytes, with
                                   SIGXFSZ ignored (a write past it fails
                                   with EFBIG) */
} rt_test_setup;

/* What a run of a program gave. */
typedef struct rt_test_output {
    int code;               /* exit status, or 128 + the signal */
    char *out;              /* standard output ("" when given a file) */
    size_t out_size;
    char *err;              /* standard error, NUL-terminated */
} rt_test_output;

void rt_test_output_free(rt_test_output *output);

/* Runs `program` with `args` (NULL-terminated, without argv[0]) in `dir`
 * to its end, as the defaults of rt_test_setup say. */
rt_test_output rt_test_run(const char *dir, const char *program,
                           const char *const *args);

/* The same, started as `setup` says (NULL: the defaults). */
rt_test_output rt_test_run_with(const char *dir, const char *program,
                                const char *const *args,
                                const rt_test_setup *setup);

/* A program started and not yet finished. */
typedef struct rt_test_process {
    pid_t pid;
    char *err;              /* piped: what was read so far, NUL-terminated
                               (NULL before anything came) */
    size_t err_length;
    int err_piped;          /* standard error into a pipe read as it comes */
    FILE *out_file, *err_file;  /* the captured streams, or NULL */
    int err_fd;             /* the pipe's read end, when piped */
    int status, reaped;     /* its wait status, once rt_test_running saw it
                               end */
} rt_test_process;

/* Starts `program` as `setup` says (NULL: the defaults); finish it with
 * rt_test_finish. */
rt_test_process rt_test_start(const char *dir, const char *program,
                              const char *const *args,
                              const rt_test_setup *setup);

/* The same with standard error into a pipe, read as it comes
 * (rt_test_wait_for_line: a test acts when a line appears). */
rt_test_process rt_test_start_piped(const char *dir, const char *program,
                                    const char *const *args,
                                    const rt_test_setup *setup);

/* Reads standard error (piped) until a whole line starting with `start`
 * has come: 1, or 0 when the program closed it first. */
int rt_test_wait_for_line(rt_test_process *process, const char *start);

/* 1 while the program runs; 0 once it has ended (it is then reaped, and
 * rt_test_finish gives its status). */
int rt_test_running(rt_test_process *process);

/* The CPU time (user + system) the program has used so far, from
 * /proc/<pid>/stat; 0 when it cannot be read. */
double rt_test_cpu_seconds(const rt_test_process *process);

/* Waits for the program's end (reading the rest of a piped standard
 * error) and gives what it did. */
rt_test_output rt_test_finish(rt_test_process *process);

#endif /* RAYTRACE_TEST_PROGRAMS_H */
