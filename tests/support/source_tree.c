/*
 * source_tree.c - the project's source tree as the layering suites read it
 * (see source_tree.h).
 */
#define _GNU_SOURCE 1       /* program_invocation_short_name */

#include "source_tree.h"

#include <check.h>
#include <ctype.h>
#include <errno.h>
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "suite.h"

const rt_test_layer rt_test_layers[] = {
    {"base", 0},    {"kernel", 1}, {"scene", 2},
    {"formats", 3}, {"render", 3}, {"in104", -1},
};
const int rt_test_layer_count =
    (int)(sizeof rt_test_layers / sizeof rt_test_layers[0]);

/* ------------------------------------------------------------------ */
/* Reading the tree                                                     */

static int is_source(const char *name)
{
    size_t n = strlen(name);
    return n > 2 && name[n - 2] == '.' &&
           (name[n - 1] == 'c' || name[n - 1] == 'h');
}

int rt_test_layer_of(const char *path)
{
    if (strncmp(path, "src/", 4) != 0)
        return -1;
    for (int i = 0; i < rt_test_layer_count; i++) {
        size_t n = strlen(rt_test_layers[i].folder);
        if (strncmp(path + 4, rt_test_layers[i].folder, n) == 0 &&
            path[4 + n] == '/')
            return i;
    }
    return -1;
}

void rt_test_tree_add(rt_test_tree *t, const char *path)
{
    if (t->count == t->capacity) {
        t->capacity = t->capacity ? 2 * t->capacity : 256;
        t->files = realloc(t->files, (size_t)t->capacity * sizeof *t->files);
        ck_assert_ptr_nonnull(t->files);
    }
    rt_test_source *s = &t->files[t->count++];
    memset(s, 0, sizeof *s);
    snprintf(s->path, sizeof s->path, "%s", path);
    s->in_src = strncmp(path, "src/", 4) == 0;
    s->layer = rt_test_layer_of(path);
}

/* Adds the .c and .h files under `relative` (a folder), depth first. */
static void walk(rt_test_tree *t, const char *relative)
{
    DIR *d = opendir(rt_test_source_path(relative));
    ck_assert_msg(d != NULL, "cannot read %s", relative);
    struct dirent *entry;
    while ((entry = readdir(d)) != NULL) {
        if (entry->d_name[0] == '.')
            continue;
        char path[512];
        snprintf(path, sizeof path, "%s/%s", relative, entry->d_name);
        struct stat st;
        ck_assert_int_eq(stat(rt_test_source_path(path), &st), 0);
        if (S_ISDIR(st.st_mode))
            walk(t, path);
        else if (S_ISREG(st.st_mode) && is_source(entry->d_name))
            rt_test_tree_add(t, path);
    }
    closedir(d);
}

static int find_file(const rt_test_tree *t, const char *path)
{
    for (int i = 0; i < t->count; i++)
        if (strcmp(t->files[i].path, path) == 0)
            return i;
    return -1;
}

static int exists(const char *relative)
{
    struct stat st;
    return stat(rt_test_source_path(relative), &st) == 0 &&
           S_ISREG(st.st_mode);
}

/* "a/b/../c" as "a/c" (the spellings of src/ use no "..", but a path is
 * compared as the build would reach it). */
static void normalise(char *path)
{
    char *slot;
    while ((slot = strstr(path, "/../")) != NULL) {
        char *start = slot;
        while (start > path && start[-1] != '/')
            start--;
        memmove(start, slot + 4, strlen(slot + 4) + 1);
    }
}

/* Resolves `spelled`, included from `from`, as the build does. */
static void resolve(const rt_test_tree *t, const rt_test_source *from,
                    rt_test_include *inc)
{
    char folder[512];
    snprintf(folder, sizeof folder, "%s", from->path);
    char *slash = strrchr(folder, '/');
    *slash = '\0';
    const char *roots[4] = {folder, "src", "include", NULL};
    if (from->layer >= 0 && rt_test_layers[from->layer].rank < 0)
        roots[3] = "include/in104";
    inc->target = -1;
    inc->is_public = 0;
    for (int r = 0; r < 4; r++) {
        if (roots[r] == NULL)
            continue;
        char candidate[1024];
        snprintf(candidate, sizeof candidate, "%s/%s", roots[r],
                 inc->spelled);
        normalise(candidate);
        int index = find_file(t, candidate);
        if (index >= 0 && t->files[index].in_src) {
            inc->target = index;
            return;
        }
        if (strncmp(candidate, "include/", 8) == 0 && exists(candidate)) {
            inc->is_public = 1;
            return;
        }
    }
    /* generated into the build tree: raytrace/version.h */
    inc->is_public = strncmp(inc->spelled, "raytrace/", 9) == 0;
}

/* Counts the lines of a file and, in src/, reads its includes. */
static void read_file(rt_test_tree *t, int index)
{
    rt_test_source *s = &t->files[index];
    FILE *file = fopen(rt_test_source_path(s->path), "r");
    ck_assert_msg(file != NULL, "cannot read %s", s->path);
    char line[4096];
    int number = 0, capacity = 0;
    while (fgets(line, sizeof line, file) != NULL) {
        size_t n = strlen(line);
        if (n > 0 && line[n - 1] == '\n')
            number++;
        else if (!feof(file))
            continue;       /* the rest of a long line */
        else
            number++;
        if (!s->in_src)
            continue;
        const char *p = line;
        while (*p == ' ' || *p == '\t')
            p++;
        if (*p != '#')
            continue;
        p++;
        while (*p == ' ' || *p == '\t')
            p++;
        if (strncmp(p, "include", 7) != 0)
            continue;
        p += 7;
        while (*p == ' ' || *p == '\t')
            p++;
        const char *end = *p == '"' ? strchr(p + 1, '"') : NULL;
        if (end == NULL)
            continue;       /* <system> headers */
        if (s->include_count == capacity) {
            capacity = capacity ? 2 * capacity : 16;
            s->includes = realloc(s->includes,
                                  (size_t)capacity * sizeof *s->includes);
            ck_assert_ptr_nonnull(s->includes);
        }
        rt_test_include *inc = &s->includes[s->include_count++];
        memset(inc, 0, sizeof *inc);
        snprintf(inc->spelled, sizeof inc->spelled, "%.*s",
                 (int)(end - p - 1), p + 1);
        inc->line = number;
    }
    fclose(file);
    s->lines = number;
}

rt_test_tree rt_test_tree_read(void)
{
    rt_test_tree t = {NULL, 0, 0};
    walk(&t, "src");
    walk(&t, "apps");
    for (int i = 0; i < t.count; i++)
        read_file(&t, i);
    for (int i = 0; i < t.count; i++)
        for (int k = 0; k < t.files[i].include_count; k++)
            resolve(&t, &t.files[i], &t.files[i].includes[k]);
    return t;
}

void rt_test_tree_free(rt_test_tree *t)
{
    for (int i = 0; i < t->count; i++)
        free(t->files[i].includes);
    free(t->files);
}

/* ------------------------------------------------------------------ */
/* The allow-list and the report                                        */


/* tests/layers.allow: one key a line ("include <file> <target>", "circle
 * <file> <file>...", "module <module> <module>...", "size <file>"), then
 * anything after a '#'. */
static rt_test_allow_list read_allow_list(void)
{
    rt_test_allow_list a = {NULL, NULL, 0};
    FILE *file = fopen(rt_test_source_path("tests/layers.allow"), "r");
    ck_assert_msg(file != NULL, "cannot read tests/layers.allow");
    char line[2048];
    while (fgets(line, sizeof line, file) != NULL) {
        char *hash = strchr(line, '#');
        if (hash != NULL)
            *hash = '\0';
        char *end = line + strlen(line);
        while (end > line && isspace((unsigned char)end[-1]))
            *--end = '\0';
        char *start = line;
        while (isspace((unsigned char)*start))
            start++;
        if (*start == '\0')
            continue;
        a.keys = realloc(a.keys, (size_t)(a.count + 1) * sizeof *a.keys);
        a.used = realloc(a.used, (size_t)(a.count + 1) * sizeof *a.used);
        ck_assert(a.keys != NULL && a.used != NULL);
        /* one space between words, as the keys are made */
        char *out = a.keys[a.count];
        size_t used = 0;
        for (char *p = start; *p && used + 1 < sizeof a.keys[0]; p++)
            if (!isspace((unsigned char)*p) ||
                (used > 0 && out[used - 1] != ' '))
                out[used++] = isspace((unsigned char)*p) ? ' ' : *p;
        out[used] = '\0';
        a.used[a.count++] = 0;
    }
    fclose(file);
    return a;
}

static void free_allow_list(rt_test_allow_list *a)
{
    free(a->keys);
    free(a->used);
}


/* Prints one violation (`where`: file:line) and counts it, unless the
 * allow-list has `key`. */
void rt_test_report_violation(rt_test_report *r, const char *key,
                              const char *where, const char *what)
{
    for (int i = 0; i < r->allowed.count; i++)
        if (strcmp(r->allowed.keys[i], key) == 0) {
            r->allowed.used[i] = 1;
            r->allowed_seen++;
            printf("%s: allowed (tests/layers.allow): %s: %s\n",
                   program_invocation_short_name, where, what);
            return;
        }
    printf("%s: VIOLATION: %s: %s\n", program_invocation_short_name, where,
           what);
    if (r->violations++ == 0)
        snprintf(r->first, sizeof r->first, "%s: %s", where, what);
}

/* Fails the test when a violation was not allowed, or when an entry of
 * the allow-list of kind `kind` matched nothing. */
void rt_test_report_finish(rt_test_report *r, const char *kind)
{
    int stale = 0;
    size_t n = strlen(kind);
    for (int i = 0; i < r->allowed.count; i++)
        if (!r->allowed.used[i] && strncmp(r->allowed.keys[i], kind, n) == 0 &&
            r->allowed.keys[i][n] == ' ') {
            printf("%s: STALE: tests/layers.allow lists `%s`, "
                   "which is no longer a violation: remove it\n",
                   program_invocation_short_name, r->allowed.keys[i]);
            stale++;
        }
    printf("%s: %s: %d violations, %d allowed, %d stale entries\n",
           program_invocation_short_name, kind, r->violations,
           r->allowed_seen, stale);
    fflush(stdout);
    ck_assert_msg(r->violations == 0, "%d violations; the first: %s",
                  r->violations, r->first);
    ck_assert_msg(stale == 0, "%d entries of tests/layers.allow match no "
                  "violation (printed above): remove them", stale);
    free_allow_list(&r->allowed);
}

rt_test_report rt_test_report_new(void)
{
    rt_test_report r;
    memset(&r, 0, sizeof r);
    r.allowed = read_allow_list();
    return r;
}
