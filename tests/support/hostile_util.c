/*
 * hostile_util.c - the helpers of the suites of bad input and faults (see
 * hostile_util.h).
 */
#define _GNU_SOURCE 1

#include "hostile_util.h"

#include <dirent.h>
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

const char small_scene[] =
    "0 0 10\n"
    "0 0 5 4 0 5 40 30\n"
    "3\n"
    "-3 -3 0\n"
    "3 -3 0\n"
    "0 3 0\n"
    "1\n"
    "1 2 3 0.25 200 100 50\n"
    "10 20 30\n"
    "0 0 4 255 255 255\n";

/* Valgrind puts its preload libraries in LD_PRELOAD of the program it runs. */
int under_valgrind(void)
{
    const char *preload = getenv("LD_PRELOAD");
    return preload != NULL && strstr(preload, "vgpreload") != NULL;
}

char *make_temp_dir(void)
{
    const char *base = getenv("TMPDIR");
    char pattern[PATH_MAX];
    snprintf(pattern, sizeof pattern, "%s/rt-hostile-XXXXXX",
             base && *base ? base : "/tmp");
    char *dir = strdup(pattern);
    ck_assert_ptr_nonnull(dir);
    ck_assert_msg(mkdtemp(dir) != NULL, "mkdtemp: %s", strerror(errno));
    return dir;
}

char *join(const char *dir, const char *name)
{
    size_t length = strlen(dir) + strlen(name) + 2;
    char *path = malloc(length);
    ck_assert_ptr_nonnull(path);
    snprintf(path, length, "%s/%s", dir, name);
    return path;
}

void write_bytes(const char *path, const void *data, size_t size)
{
    FILE *file = fopen(path, "wb");
    ck_assert_msg(file != NULL, "%s: %s", path, strerror(errno));
    ck_assert_uint_eq(fwrite(data, 1, size, file), size);
    ck_assert_int_eq(fclose(file), 0);
}

/* The names in `dir` other than . and .., sorted, joined by spaces. */
char *list_dir(const char *dir)
{
    DIR *d = opendir(dir);
    ck_assert_msg(d != NULL, "%s: %s", dir, strerror(errno));
    char *names[64];
    int count = 0;
    struct dirent *entry;
    while ((entry = readdir(d)) != NULL) {
        if (!strcmp(entry->d_name, ".") || !strcmp(entry->d_name, ".."))
            continue;
        ck_assert_int_lt(count, 64);
        names[count++] = strdup(entry->d_name);
    }
    closedir(d);
    for (int i = 1; i < count; i++)
        for (int j = i; j > 0 && strcmp(names[j - 1], names[j]) > 0; j--) {
            char *t = names[j];
            names[j] = names[j - 1];
            names[j - 1] = t;
        }
    char *out = calloc(1, 64 * 260);
    ck_assert_ptr_nonnull(out);
    for (int i = 0; i < count; i++) {
        if (i)
            strcat(out, " ");
        strcat(out, names[i]);
        free(names[i]);
    }
    return out;
}

void assert_dir_holds(const char *dir, const char *expected)
{
    char *names = list_dir(dir);
    ck_assert_msg(strcmp(names, expected) == 0,
                  "%s holds `%s`, expected `%s` (a temporary file left "
                  "behind?)", dir, names, expected);
    free(names);
}

/* Removes the files of a flat directory, then the directory. */
void remove_dir(char *dir)
{
    DIR *d = opendir(dir);
    if (d != NULL) {
        struct dirent *entry;
        while ((entry = readdir(d)) != NULL) {
            if (!strcmp(entry->d_name, ".") || !strcmp(entry->d_name, ".."))
                continue;
            char *path = join(dir, entry->d_name);
            if (unlink(path) != 0)
                rmdir(path);
            free(path);
        }
        closedir(d);
    }
    rmdir(dir);
    free(dir);
}

rt_image make_image(int width, int height)
{
    rt_image image;
    ck_assert_int_eq(rt_image_init(&image, width, height, NULL), RT_OK);
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++) {
            unsigned char *p = rt_image_pixel(&image, x, y);
            p[0] = (unsigned char)x;
            p[1] = (unsigned char)y;
            p[2] = (unsigned char)(x ^ y);
        }
    return image;
}

void assert_previous_intact(const char *path)
{
    size_t size;
    char *data = rt_test_read_file(path, &size);
    ck_assert_msg(data != NULL, "%s: the previous file is gone", path);
    ck_assert_msg(size == sizeof previous_ppm - 1 &&
                      memcmp(data, previous_ppm, size) == 0,
                  "%s: the previous file was changed (now %zu bytes)", path,
                  size);
    free(data);
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

int limit_address_space(size_t more, char *message, size_t size)
{
    size_t in_use = address_space_in_use();
    if (in_use == 0) {
        snprintf(message, size, "cannot read /proc/self/statm");
        return 0;
    }
    struct rlimit limit = {in_use + more, in_use + more};
    if (setrlimit(RLIMIT_AS, &limit) != 0) {
        snprintf(message, size, "setrlimit: %s", strerror(errno));
        return 0;
    }
    return 1;
}

int run_in_child(child_fn child, void *arg, char *message,
                        size_t size)
{
    int fds[2];
    ck_assert_int_eq(pipe(fds), 0);
    fflush(NULL);
    pid_t pid = fork();
    ck_assert_int_ge(pid, 0);
    if (pid == 0) {
        close(fds[0]);
        char text[1024] = "";
        int code = child(arg, text, sizeof text);
        if (write(fds[1], text, strlen(text)) < 0)
            code = 99;
        close(fds[1]);
        _exit(code);
    }
    close(fds[1]);
    size_t used = 0;
    ssize_t n;
    while (used + 1 < size &&
           (n = read(fds[0], message + used, size - used - 1)) > 0)
        used += (size_t)n;
    message[used] = '\0';
    close(fds[0]);
    int status;
    ck_assert_int_eq(waitpid(pid, &status, 0), pid);
    if (WIFSIGNALED(status)) {
        snprintf(message, size, "child killed by signal %d",
                 WTERMSIG(status));
        return 128 + WTERMSIG(status);
    }
    return WEXITSTATUS(status);
}

/* Parses `text` and checks the contract of a refusal; returns the status. */
rt_status parse_refused(const char *text, size_t length,
                               rt_error *error)
{
    rt_scene *scene = (rt_scene *)1;
    memset(error, 0, sizeof *error);
    rt_status status = rt_scene_parse(text, length, "hostile.scn", &scene,
                                      error);
    ck_assert_msg(status != RT_OK, "a hostile scene loaded");
    ck_assert_ptr_null(scene);
    ck_assert_int_eq(error->status, status);
    ck_assert_msg(error->message[0] != '\0', "a refusal without a message");
    return status;
}

double now_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}
