/*
 * programs.c - running the project's programs (see programs.h).  The child
 * is made with fork and execve: between the two it calls only
 * async-signal-safe functions (the suite may have threads), and a failed
 * chdir or exec comes back through a close-on-exec pipe as its errno.
 */
#define _GNU_SOURCE 1       /* pipe2 */

#include "programs.h"

#include <check.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "files.h"

/* Arguments a test may pass, argv[0] and the NULL not counted. */
#define MAX_ARGS 62

void rt_test_output_free(rt_test_output *output)
{
    free(output->out);
    free(output->err);
    output->out = output->err = NULL;
}

/* environ with TMPDIR set to `tmpdir` (malloc'd array, the strings
 * borrowed but the one it adds, *added). */
static char **environment_with(const char *tmpdir, char **added)
{
    extern char **environ;
    size_t n = 0;
    while (environ[n] != NULL)
        n++;
    char **env = calloc(n + 2, sizeof *env);
    ck_assert_ptr_nonnull(env);
    size_t used = 0;
    for (size_t i = 0; i < n; i++)
        if (strncmp(environ[i], "TMPDIR=", 7) != 0)
            env[used++] = environ[i];
    *added = malloc(strlen(tmpdir) + 8);
    ck_assert_ptr_nonnull(*added);
    strcpy(*added, "TMPDIR=");
    strcat(*added, tmpdir);
    env[used++] = *added;
    env[used] = NULL;
    return env;
}

/* In the child: tells the parent why it cannot go on, and ends. */
static void give_up(int report_fd)
{
    int code = errno;
    if (write(report_fd, &code, sizeof code) < 0)
        code = 0;
    _exit(127);
}

/* In the child: `path` opened with `flags` as descriptor `fd`. */
static void open_as(int fd, const char *path, int flags, int report_fd)
{
    int opened = open(path, flags, 0644);
    if (opened < 0 || dup2(opened, fd) < 0)
        give_up(report_fd);
    if (opened != fd)
        close(opened);
}

static const rt_test_setup no_setup;

static rt_test_process spawn(const char *dir, const char *program,
                             const char *const *args,
                             const rt_test_setup *setup, int piped)
{
    if (setup == NULL)
        setup = &no_setup;
    rt_test_process p;
    memset(&p, 0, sizeof p);
    p.err_fd = -1;
    p.err_piped = piped;
    if (setup->stdout_path == NULL) {
        p.out_file = tmpfile();
        ck_assert_msg(p.out_file != NULL, "tmpfile: %s", strerror(errno));
    }
    int err_pipe[2] = {-1, -1};
    if (piped) {
        ck_assert_int_eq(pipe2(err_pipe, O_CLOEXEC), 0);
    } else {
        p.err_file = tmpfile();
        ck_assert_msg(p.err_file != NULL, "tmpfile: %s", strerror(errno));
    }
    const char *argv[MAX_ARGS + 2];
    int argc = 0;
    argv[argc++] = program;
    for (int i = 0; args[i] != NULL; i++) {
        ck_assert_msg(argc <= MAX_ARGS, "more than %d arguments", MAX_ARGS);
        argv[argc++] = args[i];
    }
    argv[argc] = NULL;
    extern char **environ;
    char *added = NULL;
    char **env = setup->tmpdir ? environment_with(setup->tmpdir, &added)
                               : environ;
    int report[2];
    ck_assert_int_eq(pipe2(report, O_CLOEXEC), 0);
    fflush(NULL);
    p.pid = fork();
    ck_assert_msg(p.pid >= 0, "fork: %s", strerror(errno));
    if (p.pid == 0) {
        close(report[0]);
        if (chdir(dir) != 0)
            give_up(report[1]);
        open_as(0, setup->stdin_path ? setup->stdin_path : "/dev/null",
                O_RDONLY, report[1]);
        if (setup->stdout_path != NULL)
            open_as(1, setup->stdout_path, O_WRONLY | O_CREAT, report[1]);
        else if (dup2(fileno(p.out_file), 1) < 0)
            give_up(report[1]);
        if (dup2(piped ? err_pipe[1] : fileno(p.err_file), 2) < 0)
            give_up(report[1]);
        /* a test runner may ignore these; the program must not inherit
         * that */
        signal(SIGINT, SIG_DFL);
        signal(SIGTERM, SIG_DFL);
        signal(SIGHUP, SIG_DFL);
        signal(SIGPIPE, SIG_DFL);
        if (setup->file_size_limit > 0) {
            signal(SIGXFSZ, SIG_IGN);
            rlim_t bytes = (rlim_t)setup->file_size_limit;
            struct rlimit limit = {bytes, bytes};
            if (setrlimit(RLIMIT_FSIZE, &limit) != 0)
                give_up(report[1]);
        }
        execve(program, (char *const *)argv, env);
        give_up(report[1]);
    }
    close(report[1]);
    if (piped) {
        close(err_pipe[1]);
        p.err_fd = err_pipe[0];
    }
    if (env != environ) {
        free(added);
        free(env);
    }
    int failed = 0;
    ssize_t n;
    while ((n = read(report[0], &failed, sizeof failed)) < 0 &&
           errno == EINTR)
        ;
    close(report[0]);
    if (n > 0) {
        waitpid(p.pid, NULL, 0);
        ck_abort_msg("cannot start %s in %s: %s", program, dir,
                     strerror(failed));
    }
    return p;
}

rt_test_process rt_test_start(const char *dir, const char *program,
                              const char *const *args,
                              const rt_test_setup *setup)
{
    return spawn(dir, program, args, setup, 0);
}

rt_test_process rt_test_start_piped(const char *dir, const char *program,
                                    const char *const *args,
                                    const rt_test_setup *setup)
{
    return spawn(dir, program, args, setup, 1);
}

/* Appends what one read(2) of the pipe gives to p->err; 0 at its end. */
static int read_some(rt_test_process *p)
{
    char chunk[4096];
    ssize_t n;
    do
        n = read(p->err_fd, chunk, sizeof chunk);
    while (n < 0 && errno == EINTR);
    ck_assert_int_ge(n, 0);
    if (n == 0)
        return 0;
    char *grown = realloc(p->err, p->err_length + (size_t)n + 1);
    ck_assert_ptr_nonnull(grown);
    memcpy(grown + p->err_length, chunk, (size_t)n);
    p->err = grown;
    p->err_length += (size_t)n;
    p->err[p->err_length] = '\0';
    return 1;
}

int rt_test_wait_for_line(rt_test_process *process, const char *start)
{
    ck_assert_msg(process->err_piped, "standard error is not piped");
    for (;;) {
        for (const char *at = process->err; at != NULL && *at;) {
            const char *end = strchr(at, '\n');
            if (end == NULL)
                break;
            if (strncmp(at, start, strlen(start)) == 0)
                return 1;
            at = end + 1;
        }
        if (!read_some(process))
            return 0;
    }
}

int rt_test_running(rt_test_process *process)
{
    if (process->reaped)
        return 0;
    pid_t got = waitpid(process->pid, &process->status, WNOHANG);
    ck_assert_int_ge(got, 0);
    process->reaped = got == process->pid;
    return !process->reaped;
}

double rt_test_cpu_seconds(const rt_test_process *process)
{
    char path[64];
    snprintf(path, sizeof path, "/proc/%d/stat", (int)process->pid);
    FILE *file = fopen(path, "r");
    unsigned long user = 0, system = 0;
    if (file != NULL) {
        /* fields 14 and 15; the name (2) is in parentheses */
        char line[1024];
        if (fgets(line, sizeof line, file)) {
            char *p = strrchr(line, ')');
            if (p == NULL ||
                sscanf(p + 2, "%*c %*d %*d %*d %*d %*d %*u %*u %*u "
                              "%*u %*u %lu %lu", &user, &system) != 2)
                user = system = 0;
        }
        fclose(file);
    }
    return (double)(user + system) / (double)sysconf(_SC_CLK_TCK);
}

/* All a captured stream held, malloc'd and NUL-terminated; closes it. */
static char *read_back(FILE *file, size_t *size)
{
    ck_assert_int_eq(fseek(file, 0, SEEK_SET), 0);
    char *data = rt_test_read_stream(file, size);
    fclose(file);
    return data;
}

rt_test_output rt_test_finish(rt_test_process *process)
{
    rt_test_output r;
    memset(&r, 0, sizeof r);
    if (process->err_piped) {
        while (read_some(process))
            continue;
        close(process->err_fd);
        process->err_fd = -1;
    }
    if (!process->reaped) {
        pid_t got;
        while ((got = waitpid(process->pid, &process->status, 0)) < 0 &&
               errno == EINTR)
            ;
        ck_assert_int_eq(got, process->pid);
        process->reaped = 1;
    }
    int status = process->status;
    r.code = WIFSIGNALED(status) ? 128 + WTERMSIG(status)
                                 : WEXITSTATUS(status);
    if (process->out_file != NULL) {
        r.out = read_back(process->out_file, &r.out_size);
    } else {
        r.out = strdup("");
        ck_assert_ptr_nonnull(r.out);
    }
    if (process->err_piped) {
        r.err = process->err ? process->err : strdup("");
        ck_assert_ptr_nonnull(r.err);
    } else {
        r.err = read_back(process->err_file, NULL);
    }
    process->out_file = process->err_file = NULL;
    process->err = NULL;
    return r;
}

rt_test_output rt_test_run_with(const char *dir, const char *program,
                                const char *const *args,
                                const rt_test_setup *setup)
{
    rt_test_process p = rt_test_start(dir, program, args, setup);
    return rt_test_finish(&p);
}

rt_test_output rt_test_run(const char *dir, const char *program,
                           const char *const *args)
{
    return rt_test_run_with(dir, program, args, NULL);
}
