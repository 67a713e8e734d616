/*
 * program_util.c - running the project's programs (see program_util.h).
 */
#include "program_util.h"

#include <check.h>
#include <errno.h>
#include <fcntl.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

char *fresh_dir(void)
{
    char *dir = strdup("/tmp/rt-test-cli-XXXXXX");
    ck_assert_ptr_nonnull(dir);
    ck_assert_ptr_nonnull(mkdtemp(dir));
    return dir;
}

void remove_dir(char *dir)
{
    char command[4200];
    snprintf(command, sizeof command, "chmod -R u+rwx '%s' 2>/dev/null; "
             "rm -rf '%s'", dir, dir);
    ck_assert_int_eq(system(command), 0);
    free(dir);
}

const char *in_dir(const char *dir, const char *name)
{
    static char paths[4][4096];
    static int next;
    char *path = paths[next++ % 4];
    snprintf(path, sizeof paths[0], "%s/%s", dir, name);
    return path;
}

void run_free(run *r)
{
    free(r->out);
    free(r->err);
}

run run_in(const char *dir, const char *program, const char *const *args)
{
    return run_with(dir, program, args, NULL);
}

/* environ with TMPDIR set to `tmpdir` (malloc'd array, strings borrowed
 * but the one it adds). */
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
    *added = NULL;
    if (tmpdir != NULL) {
        *added = malloc(strlen(tmpdir) + 8);
        ck_assert_ptr_nonnull(*added);
        sprintf(*added, "TMPDIR=%s", tmpdir);
        env[used++] = *added;
    }
    env[used] = NULL;
    return env;
}

/* Starts `program` as `setup` says; standard error into the file
 * err_path, or into a new pipe whose read end goes to *err_fd when
 * err_path is NULL.  Returns its pid. */
static pid_t spawn(const char *dir, const char *program,
                   const char *const *args, const run_setup *setup,
                   const char *out_path, const char *err_path, int *err_fd)
{
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(
        &actions, 0, setup->stdin_path ? setup->stdin_path : "/dev/null",
        O_RDONLY, 0);
    posix_spawn_file_actions_addopen(
        &actions, 1, setup->stdout_path ? setup->stdout_path : out_path,
        O_WRONLY | O_CREAT | (setup->stdout_path ? 0 : O_TRUNC), 0644);
    int pipe_ends[2] = {-1, -1};
    if (err_path != NULL) {
        posix_spawn_file_actions_addopen(&actions, 2, err_path,
                                         O_WRONLY | O_CREAT | O_TRUNC, 0644);
    } else {
        ck_assert_int_eq(pipe(pipe_ends), 0);
        posix_spawn_file_actions_adddup2(&actions, pipe_ends[1], 2);
        posix_spawn_file_actions_addclose(&actions, pipe_ends[0]);
        posix_spawn_file_actions_addclose(&actions, pipe_ends[1]);
    }
    char *argv[32];
    int argc = 0;
    argv[argc++] = (char *)program;
    for (int i = 0; args[i] != NULL && argc < 31; i++)
        argv[argc++] = (char *)args[i];
    argv[argc] = NULL;
    extern char **environ;
    char *added = NULL;
    char **env = setup->tmpdir ? environment_with(setup->tmpdir, &added)
                               : environ;
    char cwd[4096];
    ck_assert_ptr_nonnull(getcwd(cwd, sizeof cwd));
    ck_assert_int_eq(chdir(dir), 0);
    pid_t pid;
    int failed = posix_spawn(&pid, program, &actions, NULL, argv, env);
    ck_assert_int_eq(chdir(cwd), 0);
    posix_spawn_file_actions_destroy(&actions);
    if (env != environ) {
        free(added);
        free(env);
    }
    if (err_path == NULL) {
        close(pipe_ends[1]);
        *err_fd = pipe_ends[0];
    }
    ck_assert_msg(failed == 0, "cannot start %s: %s", program,
                  strerror(failed));
    return pid;
}

/* Waits for `pid` and reads back what it wrote. */
static run collect(pid_t pid, const run_setup *setup, const char *out_path)
{
    int status;
    ck_assert_int_eq(waitpid(pid, &status, 0), pid);
    run r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status)
                               : 128 + WTERMSIG(status);
    if (setup->stdout_path == NULL) {
        r.out = rt_test_read_file(out_path, &r.out_size);
        unlink(out_path);
    } else {
        r.out = strdup("");
        r.out_size = 0;
    }
    ck_assert_ptr_nonnull(r.out);
    r.err = NULL;
    return r;
}

static const run_setup no_setup = {NULL, NULL, NULL};

run run_with(const char *dir, const char *program, const char *const *args,
             const run_setup *setup)
{
    if (setup == NULL)
        setup = &no_setup;
    char out_path[4200], err_path[4200];
    snprintf(out_path, sizeof out_path, "%s/..out", dir);
    snprintf(err_path, sizeof err_path, "%s/..err", dir);
    pid_t pid = spawn(dir, program, args, setup, out_path, err_path, NULL);
    run r = collect(pid, setup, out_path);
    r.err = rt_test_read_file(err_path, NULL);
    unlink(err_path);
    ck_assert_ptr_nonnull(r.err);
    return r;
}

started start_piped(const char *dir, const char *program,
                    const char *const *args, const run_setup *setup)
{
    if (setup == NULL)
        setup = &no_setup;
    started s = {0, -1, NULL, 0, {0}};
    s.setup = *setup;
    snprintf(s.out_path, sizeof s.out_path, "%s/..out", dir);
    s.pid = spawn(dir, program, args, setup, s.out_path, NULL, &s.err_fd);
    return s;
}

/* Appends what one read(2) of the pipe gives to s->err; 0 at its end. */
static int read_some(started *s)
{
    char chunk[4096];
    ssize_t n;
    do
        n = read(s->err_fd, chunk, sizeof chunk);
    while (n < 0 && errno == EINTR);
    ck_assert_int_ge(n, 0);
    if (n == 0)
        return 0;
    char *grown = realloc(s->err, s->err_length + (size_t)n + 1);
    ck_assert_ptr_nonnull(grown);
    memcpy(grown + s->err_length, chunk, (size_t)n);
    s->err = grown;
    s->err_length += (size_t)n;
    s->err[s->err_length] = '\0';
    return 1;
}

int wait_for_line(started *s, const char *start)
{
    for (;;) {
        for (const char *at = s->err; at != NULL && *at;) {
            const char *end = strchr(at, '\n');
            if (end == NULL)
                break;
            if (strncmp(at, start, strlen(start)) == 0)
                return 1;
            at = end + 1;
        }
        if (!read_some(s))
            return 0;
    }
}

run finish_piped(started *s)
{
    while (read_some(s))
        continue;
    close(s->err_fd);
    run r = collect(s->pid, &s->setup, s->out_path);
    r.err = s->err ? s->err : strdup("");
    ck_assert_ptr_nonnull(r.err);
    return r;
}

int loader_lists_its_files(void)
{
    rt_scene *scene;
    if (rt_scene_load_with(rt_test_source_path("tests/data/obj/cube.obj"),
                           NULL, &scene, NULL) != RT_OK)
        return 0;
    int count = rt_scene_source_count(scene);
    rt_scene_destroy(scene);
    return count >= 2;
}

int main_with_sources(int argc, char **argv, Suite *(*main_fn)(void),
                      Suite *(*sources_fn)(void), const char *prog)
{
    if (argc > 1 && strcmp(argv[1], "sources") == 0) {
        if (!loader_lists_its_files()) {
            fprintf(stderr, "%s: the loader does not list the files a load "
                            "read yet (rt_scene_source_count is 0); the "
                            "material-library cases are not checked\n",
                    prog);
            return RT_TEST_SKIPPED;
        }
        return rt_test_run_suite(sources_fn());
    }
    return rt_test_run_suite(main_fn());
}

int python_has_json(void)
{
    return system("python3 -c 'import json' >/dev/null 2>&1") == 0;
}
