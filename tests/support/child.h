/*
 * child.h - a job in a forked child of the suite: what changes the process
 * (umask, signal dispositions, rlimits, mount namespaces, an abort) happens
 * there, and the child reports through a pipe and calls no Check function,
 * so that the suites also hold under CK_FORK=no (valgrind).  A job may also
 * be a helper the test talks to (a FIFO's reader, a socket's listener).
 * Part of the support library (tests/support/).
 */
#ifndef RAYTRACE_TEST_CHILD_H
#define RAYTRACE_TEST_CHILD_H

#include <stddef.h>
#include <sys/types.h>

/*
 * A job: runs in the child and returns its exit status; it may leave a line
 * for the parent in `note` (`size` bytes).  It never calls Check (under
 * CK_FORK=no a failing assertion there would go on running the suite in
 * the child).
 */
typedef int (*rt_test_job)(void *arg, char *note, size_t size);

/* The user and group "nobody" on Debian and most systems: what a job that
 * runs as root becomes to lose its privileges. */
#define RT_TEST_NOBODY 65534

typedef struct rt_test_child {
    pid_t pid;              /* -1 when fork or pipe failed */
    int note_fd;            /* the read end of the note's pipe */
} rt_test_child;

/* Starts `job(arg)` in a forked child; pid -1 (errno set) when it cannot.
 * Calls no Check function: a job may start children of its own. */
rt_test_child rt_test_child_start(rt_test_job job, void *arg);

/* The same, with the child's standard error into the note's pipe too (what
 * an assert or abort prints comes back in the note). */
rt_test_child rt_test_child_start_with_stderr(rt_test_job job, void *arg);

/* Reads the child's note (NUL-terminated into `note`) and reaps it;
 * returns its wait status (WIFEXITED, WTERMSIG...), -1 when it cannot be
 * reaped.  Calls no Check function. */
int rt_test_child_finish(rt_test_child *child, char *note, size_t size);

/* A wait status as one number: the exit code, or 128 + the signal. */
int rt_test_exit_code(int wait_status);

/* Runs `job` to its end in a child: its exit code, or 128 + the signal
 * that ended it (its note then says which).  Fails the test when it cannot
 * fork. */
int rt_test_in_child(rt_test_job job, void *arg, char *note, size_t size);

/* In a job: writes the note and returns `code`. */
int rt_test_say(int code, char *note, size_t size, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

/* In a job: limits the address space to what is in use plus `more` bytes
 * (RLIMIT_AS).  0, with `note` saying why, when it cannot.  Meaningless
 * under a sanitizer or valgrind, which reserve far more than they use. */
int rt_test_limit_address_space(size_t more, char *note, size_t size);

/* A job that copies a stream into the file `to`: from the path `from`
 * (opened for reading, as a FIFO's reader does) or from the descriptor
 * `from_fd`; `also_close` is a descriptor the copier must not keep (a
 * pipe's write end, a listening socket), or -1.  Gives up after a minute
 * (ten under valgrind): a save that never comes. */
typedef struct rt_test_copy {
    const char *from;
    int from_fd;
    int also_close;
    const char *to;
} rt_test_copy;
int rt_test_copy_job(void *copy, char *note, size_t size);

#endif /* RAYTRACE_TEST_CHILD_H */
