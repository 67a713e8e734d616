/*
 * program_util.c - running the project's programs (see program_util.h).
 */
#include "program_util.h"

#include <check.h>
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

void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "wb");
    ck_assert_msg(f != NULL, "cannot write %s", path);
    ck_assert_int_eq(fputs(text, f) >= 0, 1);
    ck_assert_int_eq(fclose(f), 0);
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

run run_with(const char *dir, const char *program, const char *const *args,
             const run_setup *setup)
{
    run_setup none = {NULL, NULL, NULL};
    if (setup == NULL)
        setup = &none;
    char out_path[4200], err_path[4200];
    snprintf(out_path, sizeof out_path, "%s/..out", dir);
    snprintf(err_path, sizeof err_path, "%s/..err", dir);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(
        &actions, 0, setup->stdin_path ? setup->stdin_path : "/dev/null",
        O_RDONLY, 0);
    posix_spawn_file_actions_addopen(
        &actions, 1, setup->stdout_path ? setup->stdout_path : out_path,
        O_WRONLY | O_CREAT | (setup->stdout_path ? 0 : O_TRUNC), 0644);
    posix_spawn_file_actions_addopen(&actions, 2, err_path,
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
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
    ck_assert_msg(failed == 0, "cannot start %s: %s", program,
                  strerror(failed));
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
    r.err = rt_test_read_file(err_path, NULL);
    unlink(err_path);
    ck_assert_ptr_nonnull(r.out);
    ck_assert_ptr_nonnull(r.err);
    return r;
}

int python_has_json(void)
{
    return system("python3 -c 'import json' >/dev/null 2>&1") == 0;
}
