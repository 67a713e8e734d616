/*
 * child.c - jobs in forked children (see child.h).
 */
#include "child.h"

#include <check.h>
#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "probe.h"

static rt_test_child start(rt_test_job job, void *arg, int with_stderr)
{
    rt_test_child c = {-1, -1};
    int fds[2];
    if (pipe(fds) != 0)
        return c;
    fflush(NULL);
    c.pid = fork();
    if (c.pid == 0) {
        close(fds[0]);
        if (with_stderr)
            dup2(fds[1], 2);
        char note[1024] = "";
        int code = job(arg, note, sizeof note);
        if (write(fds[1], note, strlen(note)) < 0)
            code = 99;
        _exit(code);
    }
    int saved = errno;
    close(fds[1]);
    c.note_fd = fds[0];
    if (c.pid < 0) {
        close(fds[0]);
        c.note_fd = -1;
        errno = saved;
    }
    return c;
}

rt_test_child rt_test_child_start(rt_test_job job, void *arg)
{
    return start(job, arg, 0);
}

rt_test_child rt_test_child_start_with_stderr(rt_test_job job, void *arg)
{
    return start(job, arg, 1);
}

int rt_test_child_finish(rt_test_child *child, char *note, size_t size)
{
    size_t used = 0;
    ssize_t n;
    while (used + 1 < size &&
           ((n = read(child->note_fd, note + used, size - used - 1)) > 0 ||
            (n < 0 && errno == EINTR)))
        if (n > 0)
            used += (size_t)n;
    note[used] = '\0';
    close(child->note_fd);
    child->note_fd = -1;
    int status = -1;
    while (waitpid(child->pid, &status, 0) < 0 && errno == EINTR)
        ;
    return status;
}

int rt_test_exit_code(int wait_status)
{
    return WIFSIGNALED(wait_status) ? 128 + WTERMSIG(wait_status)
                                    : WEXITSTATUS(wait_status);
}

int rt_test_in_child(rt_test_job job, void *arg, char *note, size_t size)
{
    rt_test_child c = rt_test_child_start(job, arg);
    ck_assert_msg(c.pid > 0, "fork: %s", strerror(errno));
    int status = rt_test_child_finish(&c, note, size);
    if (WIFSIGNALED(status))
        snprintf(note, size, "child killed by signal %d", WTERMSIG(status));
    return rt_test_exit_code(status);
}

int rt_test_say(int code, char *note, size_t size, const char *format, ...)
{
    va_list args;
    va_start(args, format);
    vsnprintf(note, size, format, args);
    va_end(args);
    return code;
}

static size_t address_space_in_use(void)
{
    FILE *file = fopen("/proc/self/statm", "r");
    unsigned long pages = 0;
    if (file != NULL) {
        if (fscanf(file, "%lu", &pages) != 1)
            pages = 0;
        fclose(file);
    }
    return (size_t)pages * (size_t)sysconf(_SC_PAGESIZE);
}

int rt_test_limit_address_space(size_t more, char *note, size_t size)
{
    size_t in_use = address_space_in_use();
    if (in_use == 0)
        return rt_test_say(0, note, size, "cannot read /proc/self/statm");
    struct rlimit limit = {in_use + more, in_use + more};
    if (setrlimit(RLIMIT_AS, &limit) != 0)
        return rt_test_say(0, note, size, "setrlimit: %s", strerror(errno));
    return 1;
}

int rt_test_copy_job(void *arg, char *note, size_t size)
{
    const rt_test_copy *a = arg;
    alarm(rt_test_memcheck() ? 600 : 60);   /* a save that never comes */
    if (a->also_close >= 0)
        close(a->also_close);
    int in = a->from ? open(a->from, O_RDONLY) : a->from_fd;
    int out = open(a->to, O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (in < 0 || out < 0)
        return rt_test_say(1, note, size, "copier: cannot open: %s",
                           strerror(errno));
    char chunk[16384];
    ssize_t n;
    while ((n = read(in, chunk, sizeof chunk)) > 0)
        if (write(out, chunk, (size_t)n) != n)
            return rt_test_say(1, note, size, "copier: write: %s",
                               strerror(errno));
    if (n < 0)
        return rt_test_say(1, note, size, "copier: read: %s",
                           strerror(errno));
    return close(out) == 0 ? 0
                           : rt_test_say(1, note, size,
                                         "copier: close failed");
}
