/*
 * files.c - the files and folders of a test (see files.h).
 */
#include "files.h"

#include <check.h>
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

char *rt_test_temp_dir(void)
{
    const char *base = getenv("TMPDIR");
    char *dir = rt_test_join(base && *base ? base : "/tmp",
                             "rt-test-XXXXXX");
    ck_assert_msg(mkdtemp(dir) != NULL, "mkdtemp: %s", strerror(errno));
    return dir;
}

/* Removes what `path` names, a folder with all it holds. */
static void remove_tree(const char *path)
{
    struct stat st;
    if (lstat(path, &st) != 0)
        return;
    if (!S_ISDIR(st.st_mode)) {
        unlink(path);
        return;
    }
    chmod(path, 0700);
    DIR *d = opendir(path);
    if (d != NULL) {
        struct dirent *entry;
        while ((entry = readdir(d)) != NULL) {
            if (!strcmp(entry->d_name, ".") || !strcmp(entry->d_name, ".."))
                continue;
            rt_test_path inner;
            int n = snprintf(inner.s, sizeof inner.s, "%s/%s", path,
                             entry->d_name);
            if (n > 0 && (size_t)n < sizeof inner.s)
                remove_tree(inner.s);
        }
        closedir(d);
    }
    rmdir(path);
}

void rt_test_remove_dir(char *dir)
{
    if (dir != NULL)
        remove_tree(dir);
    free(dir);
}

rt_test_path rt_test_path_at(const char *dir, const char *name)
{
    rt_test_path p;
    int n = snprintf(p.s, sizeof p.s, "%s/%s", dir, name);
    ck_assert(n > 0 && (size_t)n < sizeof p.s);
    return p;
}

char *rt_test_join(const char *dir, const char *name)
{
    size_t length = strlen(dir) + strlen(name) + 2;
    char *path = malloc(length);
    ck_assert_ptr_nonnull(path);
    snprintf(path, length, "%s/%s", dir, name);
    return path;
}

const char *rt_test_in_dir(const char *dir, const char *name)
{
    static rt_test_path paths[8];
    static unsigned next;
    rt_test_path *p = &paths[next++ % 8];
    *p = rt_test_path_at(dir, name);
    return p->s;
}

char *rt_test_read_file(const char *path, size_t *size)
{
    FILE *file = fopen(path, "rb");
    if (file == NULL)
        return NULL;
    char *data = rt_test_read_stream(file, size);
    fclose(file);
    return data;
}

char *rt_test_read_stream(FILE *file, size_t *size)
{
    size_t capacity = 1 << 16, used = 0;
    char *data = malloc(capacity + 1);
    ck_assert_ptr_nonnull(data);
    size_t n;
    while ((n = fread(data + used, 1, capacity - used, file)) > 0) {
        used += n;
        if (used == capacity) {
            capacity *= 2;
            data = realloc(data, capacity + 1);
            ck_assert_ptr_nonnull(data);
        }
    }
    data[used] = '\0';
    if (size != NULL)
        *size = used;
    return data;
}

void rt_test_write_bytes(const char *path, const void *data, size_t size)
{
    FILE *file = fopen(path, "wb");
    ck_assert_msg(file != NULL, "cannot write %s: %s", path,
                  strerror(errno));
    ck_assert_uint_eq(fwrite(data, 1, size, file), size);
    ck_assert_int_eq(fclose(file), 0);
}

void rt_test_write_file(const char *path, const char *text)
{
    rt_test_write_bytes(path, text, strlen(text));
}

int rt_test_file_holds(const char *path, const void *data, size_t size)
{
    int fd = open(path, O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return 0;
    const unsigned char *expected = data;
    unsigned char chunk[65536];
    size_t seen = 0;
    int same = 1;
    ssize_t n;
    while (same && (n = read(fd, chunk, sizeof chunk)) > 0) {
        same = seen + (size_t)n <= size &&
               memcmp(chunk, expected + seen, (size_t)n) == 0;
        seen += (size_t)n;
    }
    close(fd);
    return same && seen == size;
}

unsigned rt_test_file_kind(const char *path)
{
    struct stat st;
    return lstat(path, &st) == 0 ? (unsigned)(st.st_mode & S_IFMT) : 0;
}

void rt_test_assert_link(const char *path, const char *target)
{
    char text[PATH_MAX];
    ssize_t n = readlink(path, text, sizeof text - 1);
    ck_assert_msg(n >= 0, "%s is no longer a symbolic link", path);
    text[n] = '\0';
    ck_assert_msg(strcmp(text, target) == 0,
                  "%s now points at `%s`, was `%s`", path, text, target);
}

static int by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

char *rt_test_dir_names(const char *dir)
{
    DIR *d = opendir(dir);
    if (d == NULL)
        return NULL;
    char **names = NULL, *out = NULL;
    size_t count = 0, capacity = 0, length = 1;
    int failed = 0;
    struct dirent *entry;
    while (!failed && (entry = readdir(d)) != NULL) {
        if (!strcmp(entry->d_name, ".") || !strcmp(entry->d_name, ".."))
            continue;
        if (count == capacity) {
            capacity = capacity ? 2 * capacity : 16;
            char **grown = realloc(names, capacity * sizeof *names);
            failed = grown == NULL;
            if (failed)
                break;
            names = grown;
        }
        names[count] = strdup(entry->d_name);
        failed = names[count] == NULL;
        if (!failed)
            length += strlen(names[count++]) + 1;
    }
    closedir(d);
    if (count > 0)
        qsort(names, count, sizeof *names, by_name);
    if (!failed)
        out = malloc(length);
    if (out != NULL)
        out[0] = '\0';
    for (size_t i = 0; i < count; i++) {
        if (out != NULL) {
            if (i)
                strcat(out, " ");
            strcat(out, names[i]);
        }
        free(names[i]);
    }
    free(names);
    return out;
}

void rt_test_assert_dir_holds(const char *dir, const char *expected)
{
    char *names = rt_test_dir_names(dir);
    ck_assert_msg(names != NULL, "%s cannot be read: %s", dir,
                  strerror(errno));
    ck_assert_msg(strcmp(names, expected) == 0,
                  "%s holds `%s`, expected `%s` (a temporary file left, or "
                  "something created or replaced?)", dir, names, expected);
    free(names);
}
