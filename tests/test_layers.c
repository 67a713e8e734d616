/*
 * test_layers.c - the layering of docs/architecture.md, checked on the
 * source tree as it is: every `#include "..."` of src/ is read and resolved
 * as the build resolves it (the including file's folder, then src/, then
 * include/, and include/in104 for the course's layer), and
 *
 *   - no file includes a layer above its own: base -> kernel -> scene ->
 *     {formats, render}; formats and render never include each other;
 *   - src/in104 stands apart: it includes only itself, base (the bottom
 *     layer, whose vector maths and fastInvSqrt the course's libutil
 *     shares) and the public headers, and no other layer includes it; the
 *     public API of include/raytrace/ (the generated raytrace/version.h
 *     too) is allowed anywhere;
 *   - no include circle: no file reaches itself through its includes, and
 *     no module (a folder's x.h with its x.c) reaches itself through the
 *     headers its files include;
 *   - every folder of src/ is a layer the rules know;
 *   - no source file of src/ or apps/ is over RT_LAYERS_MAX_LINES lines.
 *
 * Every violation is printed (file:line, what, why) before the test fails,
 * so one run lists them all.  tests/layers.allow lists the violations
 * known while the round that removes them is under way, each with the
 * reason it is to go; a violation it lists is printed as allowed, and an
 * entry that no longer matches a violation fails the test, so the list
 * only shrinks.  Calls by name across layers (the kernel calling the
 * renderer's recorder) are beyond what includes show.
 */
#include <ctype.h>
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "testutil.h"

/* The largest source file the layout allows (docs/architecture.md): a file
 * a reader takes in at once; longer ones are split by job. */
#define RT_LAYERS_MAX_LINES 700

/* The layers of src/, lowest first; formats and render share a rank. */
typedef struct layer {
    const char *folder;     /* under src/ */
    int rank;               /* -1: apart (in104) */
} layer;

static const layer layers[] = {
    {"base", 0},    {"kernel", 1}, {"scene", 2},
    {"formats", 3}, {"render", 3}, {"in104", -1},
};
#define LAYER_COUNT (int)(sizeof layers / sizeof layers[0])

typedef struct include {
    char spelled[256];      /* as written between the quotes */
    int line;
    int target;             /* index into the files, or -1 */
    int is_public;          /* resolved to include/ (or raytrace/...) */
} include;

typedef struct source {
    char path[512];         /* relative to the source tree */
    int layer;              /* index into layers, -1 outside src/ */
    int in_src;
    long lines;
    include *includes;
    int include_count;
} source;

typedef struct tree {
    source *files;
    int count, capacity;
} tree;

/* ------------------------------------------------------------------ */
/* Reading the tree                                                     */

static int is_source(const char *name)
{
    size_t n = strlen(name);
    return n > 2 && name[n - 2] == '.' &&
           (name[n - 1] == 'c' || name[n - 1] == 'h');
}

static int layer_of(const char *path)
{
    if (strncmp(path, "src/", 4) != 0)
        return -1;
    for (int i = 0; i < LAYER_COUNT; i++) {
        size_t n = strlen(layers[i].folder);
        if (strncmp(path + 4, layers[i].folder, n) == 0 &&
            path[4 + n] == '/')
            return i;
    }
    return -1;
}

static void add_file(tree *t, const char *path)
{
    if (t->count == t->capacity) {
        t->capacity = t->capacity ? 2 * t->capacity : 256;
        t->files = realloc(t->files, (size_t)t->capacity * sizeof *t->files);
        ck_assert_ptr_nonnull(t->files);
    }
    source *s = &t->files[t->count++];
    memset(s, 0, sizeof *s);
    snprintf(s->path, sizeof s->path, "%s", path);
    s->in_src = strncmp(path, "src/", 4) == 0;
    s->layer = layer_of(path);
}

/* Adds the .c and .h files under `relative` (a folder), depth first. */
static void walk(tree *t, const char *relative)
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
            add_file(t, path);
    }
    closedir(d);
}

static int find_file(const tree *t, const char *path)
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
static void resolve(const tree *t, const source *from, include *inc)
{
    char folder[512];
    snprintf(folder, sizeof folder, "%s", from->path);
    char *slash = strrchr(folder, '/');
    *slash = '\0';
    const char *roots[4] = {folder, "src", "include", NULL};
    if (from->layer >= 0 && layers[from->layer].rank < 0)
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
static void read_file(tree *t, int index)
{
    source *s = &t->files[index];
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
        include *inc = &s->includes[s->include_count++];
        memset(inc, 0, sizeof *inc);
        snprintf(inc->spelled, sizeof inc->spelled, "%.*s",
                 (int)(end - p - 1), p + 1);
        inc->line = number;
    }
    fclose(file);
    s->lines = number;
}

static tree read_tree(void)
{
    tree t = {NULL, 0, 0};
    walk(&t, "src");
    walk(&t, "apps");
    for (int i = 0; i < t.count; i++)
        read_file(&t, i);
    for (int i = 0; i < t.count; i++)
        for (int k = 0; k < t.files[i].include_count; k++)
            resolve(&t, &t.files[i], &t.files[i].includes[k]);
    return t;
}

static void free_tree(tree *t)
{
    for (int i = 0; i < t->count; i++)
        free(t->files[i].includes);
    free(t->files);
}

/* ------------------------------------------------------------------ */
/* The allow-list and the report                                        */

typedef struct allow_list {
    char (*keys)[1024];
    int *used;
    int count;
} allow_list;

/* tests/layers.allow: one key a line ("include <file> <target>", "circle
 * <file> <file>...", "module <module> <module>...", "size <file>"), then
 * anything after a '#'. */
static allow_list read_allow_list(void)
{
    allow_list a = {NULL, NULL, 0};
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

static void free_allow_list(allow_list *a)
{
    free(a->keys);
    free(a->used);
}

typedef struct report {
    allow_list allowed;
    int violations;         /* not allowed */
    int allowed_seen;
    char first[1024];
} report;

/* Prints one violation (`where`: file:line) and counts it, unless the
 * allow-list has `key`. */
static void violation(report *r, const char *key, const char *where,
                      const char *what)
{
    for (int i = 0; i < r->allowed.count; i++)
        if (strcmp(r->allowed.keys[i], key) == 0) {
            r->allowed.used[i] = 1;
            r->allowed_seen++;
            printf("test_layers: allowed (tests/layers.allow): %s: %s\n",
                   where, what);
            return;
        }
    printf("test_layers: VIOLATION: %s: %s\n", where, what);
    if (r->violations++ == 0)
        snprintf(r->first, sizeof r->first, "%s: %s", where, what);
}

/* Fails the test when a violation was not allowed, or when an entry of
 * the allow-list of kind `kind` matched nothing. */
static void finish(report *r, const char *kind)
{
    int stale = 0;
    size_t n = strlen(kind);
    for (int i = 0; i < r->allowed.count; i++)
        if (!r->allowed.used[i] && strncmp(r->allowed.keys[i], kind, n) == 0 &&
            r->allowed.keys[i][n] == ' ') {
            printf("test_layers: STALE: tests/layers.allow lists `%s`, "
                   "which is no longer a violation: remove it\n",
                   r->allowed.keys[i]);
            stale++;
        }
    printf("test_layers: %s: %d violations, %d allowed, %d stale entries\n",
           kind, r->violations, r->allowed_seen, stale);
    fflush(stdout);
    ck_assert_msg(r->violations == 0, "%d violations; the first: %s",
                  r->violations, r->first);
    ck_assert_msg(stale == 0, "%d entries of tests/layers.allow match no "
                  "violation (printed above): remove them", stale);
    free_allow_list(&r->allowed);
}

static report new_report(void)
{
    report r;
    memset(&r, 0, sizeof r);
    r.allowed = read_allow_list();
    return r;
}

/* ------------------------------------------------------------------ */
/* The rules                                                            */

/* Why `from` may not include `to`, or NULL when it may. */
static const char *forbidden(const source *from, const source *to)
{
    if (from->layer < 0 || to->layer < 0)
        return NULL;        /* an unknown folder: its own test says so */
    const layer *a = &layers[from->layer], *b = &layers[to->layer];
    if (a == b)
        return NULL;
    if (a->rank < 0 && b->rank == 0)
        return NULL;        /* in104 over base */
    if (a->rank < 0 || b->rank < 0)
        return "src/in104 stands apart: it uses only base and the public "
               "API, and no layer uses it";
    if (b->rank > a->rank)
        return "an include up the layers (base -> kernel -> scene -> "
               "{formats, render})";
    if (b->rank == a->rank)
        return "formats and render never include each other";
    return NULL;
}

START_TEST(no_include_in_src_goes_up_a_layer_or_across)
{
    tree t = read_tree();
    report r = new_report();
    for (int i = 0; i < t.count; i++) {
        const source *s = &t.files[i];
        for (int k = 0; k < s->include_count; k++) {
            const include *inc = &s->includes[k];
            char where[600], what[1024], key[1024];
            snprintf(where, sizeof where, "%s:%d", s->path, inc->line);
            if (inc->target < 0) {
                if (inc->is_public)
                    continue;
                snprintf(key, sizeof key, "include %s %s", s->path,
                         inc->spelled);
                snprintf(what, sizeof what, "includes \"%s\", which is no "
                         "file of src/ or include/", inc->spelled);
                violation(&r, key, where, what);
                continue;
            }
            const source *to = &t.files[inc->target];
            const char *why = forbidden(s, to);
            if (why == NULL)
                continue;
            snprintf(key, sizeof key, "include %s %s", s->path, to->path);
            snprintf(what, sizeof what, "includes %s: %s", to->path, why);
            violation(&r, key, where, what);
        }
    }
    finish(&r, "include");
    free_tree(&t);
}
END_TEST

START_TEST(every_folder_of_src_is_a_layer)
{
    tree t = read_tree();
    int unknown = 0;
    for (int i = 0; i < t.count; i++)
        if (t.files[i].in_src && t.files[i].layer < 0) {
            printf("test_layers: VIOLATION: %s: in no layer the rules know "
                   "(src/base, kernel, scene, formats, render, in104)\n",
                   t.files[i].path);
            unknown++;
        }
    ck_assert_msg(unknown == 0, "%d files of src/ are in no known layer",
                  unknown);
    /* the walk saw the tree: every layer has files */
    for (int l = 0; l < LAYER_COUNT; l++) {
        int files = 0;
        for (int i = 0; i < t.count; i++)
            files += t.files[i].layer == l;
        ck_assert_msg(files > 0, "no file in src/%s", layers[l].folder);
    }
    free_tree(&t);
}
END_TEST

/* Tarjan's strongly connected components over `n` nodes whose edges are
 * given by `edges(node, k)` (-1 ends a node's list); component[i] says
 * which component node i is in, and the number of components is
 * returned. */
typedef int (*edge_fn)(const void *graph, int node, int k);

typedef struct scc_state {
    const void *graph;
    edge_fn edges;
    int *index, *low, *on_stack, *stack, *component;
    int next, top, count;
} scc_state;

static void strong_connect(scc_state *s, int v)
{
    s->index[v] = s->low[v] = s->next++;
    s->stack[s->top++] = v;
    s->on_stack[v] = 1;
    for (int k = 0;; k++) {
        int w = s->edges(s->graph, v, k);
        if (w == -2)
            break;
        if (w < 0)
            continue;
        if (s->index[w] < 0) {
            strong_connect(s, w);
            if (s->low[w] < s->low[v])
                s->low[v] = s->low[w];
        } else if (s->on_stack[w] && s->index[w] < s->low[v]) {
            s->low[v] = s->index[w];
        }
    }
    if (s->low[v] == s->index[v]) {
        int w;
        do {
            w = s->stack[--s->top];
            s->on_stack[w] = 0;
            s->component[w] = s->count;
        } while (w != v);
        s->count++;
    }
}

static int components(const void *graph, int n, edge_fn edges,
                      int *component)
{
    scc_state s = {graph, edges, NULL, NULL, NULL, NULL, component, 0, 0, 0};
    s.index = malloc((size_t)(n + 1) * sizeof *s.index);
    s.low = malloc((size_t)(n + 1) * sizeof *s.low);
    s.on_stack = calloc((size_t)n + 1, sizeof *s.on_stack);
    s.stack = malloc((size_t)(n + 1) * sizeof *s.stack);
    ck_assert(s.index && s.low && s.on_stack && s.stack);
    for (int i = 0; i < n; i++)
        s.index[i] = -1;
    for (int i = 0; i < n; i++)
        if (s.index[i] < 0)
            strong_connect(&s, i);
    free(s.index);
    free(s.low);
    free(s.on_stack);
    free(s.stack);
    return s.count;
}

/* File k's k-th include target in src/ (-1: none there; -2: the end). */
static int file_edge(const void *graph, int node, int k)
{
    const source *s = &((const tree *)graph)->files[node];
    if (k >= s->include_count)
        return -2;
    return s->includes[k].target;
}

/* A module: a folder's x.h with its x.c (a lone file is its own). */
typedef struct modules {
    const tree *t;
    int *module_of;         /* file -> module */
    int count;
    int (*edges)[2];        /* module -> module, with a file of each */
    int edge_count;
} modules;

static int module_edge(const void *graph, int node, int k)
{
    const modules *m = graph;
    for (int e = 0, seen = 0; e < m->edge_count; e++)
        if (m->edges[e][0] == node && seen++ == k)
            return m->edges[e][1];
    return -2;
}

/* The name of a file's module: its path without the extension. */
static void module_name(const char *path, char *out, size_t size)
{
    snprintf(out, size, "%s", path);
    char *dot = strrchr(out, '.');
    if (dot != NULL)
        *dot = '\0';
}

/* Reports each component of more than one node (or with a self-loop):
 * `name(i)` names node i, `describe` writes the includes (file:line) that
 * make the circle. */
typedef void (*describe_fn)(const void *graph, const int *component,
                            int c, char *out, size_t size);

static void report_circles(report *r, int n, const int *component,
                           int count, edge_fn edges, const void *graph,
                           const char *(*name)(const void *, int),
                           describe_fn describe, const char *kind)
{
    for (int c = 0; c < count; c++) {
        int members = 0, self = 0;
        for (int i = 0; i < n; i++)
            if (component[i] == c) {
                members++;
                for (int k = 0;; k++) {
                    int w = edges(graph, i, k);
                    if (w == -2)
                        break;
                    self |= w == i;
                }
            }
        if (members < 2 && !self)
            continue;
        char key[1024], what[1024] = "";
        snprintf(key, sizeof key, "%s", kind);
        size_t used = strlen(key), wused = 0;
        /* the members in path order, as the key lists them */
        const char *names[256];
        int count_names = 0;
        for (int i = 0; i < n && count_names < 256; i++)
            if (component[i] == c)
                names[count_names++] = name(graph, i);
        for (int a = 1; a < count_names; a++)
            for (int b = a; b > 0 && strcmp(names[b - 1], names[b]) > 0; b--) {
                const char *x = names[b];
                names[b] = names[b - 1];
                names[b - 1] = x;
            }
        for (int i = 0; i < count_names; i++) {
            used += (size_t)snprintf(key + used, sizeof key - used, " %s",
                                     names[i]);
            wused += (size_t)snprintf(what + wused, sizeof what - wused,
                                      "%s%s", i ? " -> " : "", names[i]);
            if (used >= sizeof key || wused >= sizeof what)
                break;
        }
        wused = strlen(what);
        if (wused + 8 < sizeof what) {
            strcat(what, " (");
            describe(graph, component, c, what + wused + 2,
                     sizeof what - wused - 3);
            strcat(what, ")");
        }
        char where[128];
        snprintf(where, sizeof where, "%s circle of %d",
                 strcmp(kind, "circle") == 0 ? "include" : "module", members);
        violation(r, key, where, what);
    }
}

/* Appends "file:line includes target; " for each include of `t`'s files
 * for which `inside(file, target)` holds. */
static void describe_includes(const tree *t, const int *of,
                              const int *component,
                              int c, char *out, size_t size)
{
    size_t used = 0;
    out[0] = '\0';
    for (int i = 0; i < t->count; i++) {
        if (component[of ? of[i] : i] != c)
            continue;
        for (int k = 0; k < t->files[i].include_count; k++) {
            int target = t->files[i].includes[k].target;
            if (target < 0 || component[of ? of[target] : target] != c ||
                (of && of[target] == of[i]))
                continue;
            int n = snprintf(out + used, size - used, "%s%s:%d includes %s",
                             used ? "; " : "", t->files[i].path,
                             t->files[i].includes[k].line,
                             t->files[target].path);
            if (n < 0 || (size_t)n >= size - used)
                return;
            used += (size_t)n;
        }
    }
}

static void describe_files(const void *graph, const int *component, int c,
                           char *out, size_t size)
{
    describe_includes(graph, NULL, component, c, out, size);
}

static const char *file_name(const void *graph, int node)
{
    return ((const tree *)graph)->files[node].path;
}

START_TEST(no_file_of_src_reaches_itself_through_its_includes)
{
    tree t = read_tree();
    report r = new_report();
    int *component = malloc((size_t)(t.count + 1) * sizeof *component);
    ck_assert_ptr_nonnull(component);
    int count = components(&t, t.count, file_edge, component);
    report_circles(&r, t.count, component, count, file_edge, &t, file_name,
                   describe_files, "circle");
    free(component);
    finish(&r, "circle");
    free_tree(&t);
}
END_TEST

static char module_names[1024][512];

static const char *module_label(const void *graph, int node)
{
    (void)graph;
    return module_names[node];
}

static void describe_modules(const void *graph, const int *component, int c,
                             char *out, size_t size)
{
    const modules *m = graph;
    describe_includes(m->t, m->module_of, component, c, out, size);
}

START_TEST(no_module_of_src_reaches_itself_through_the_headers_it_includes)
{
    tree t = read_tree();
    report r = new_report();
    modules m = {&t, malloc((size_t)(t.count + 1) * sizeof(int)), 0, NULL,
                 0};
    ck_assert_ptr_nonnull(m.module_of);
    for (int i = 0; i < t.count; i++) {
        char name[512];
        module_name(t.files[i].path, name, sizeof name);
        int found = -1;
        for (int j = 0; j < m.count; j++)
            if (strcmp(module_names[j], name) == 0)
                found = j;
        if (found < 0) {
            ck_assert_int_lt(m.count, 1024);
            snprintf(module_names[m.count], sizeof module_names[0], "%s",
                     name);
            found = m.count++;
        }
        m.module_of[i] = found;
    }
    for (int i = 0; i < t.count; i++)
        for (int k = 0; k < t.files[i].include_count; k++) {
            int target = t.files[i].includes[k].target;
            if (target < 0 || m.module_of[target] == m.module_of[i])
                continue;
            m.edges = realloc(m.edges, (size_t)(m.edge_count + 1) *
                                           sizeof *m.edges);
            ck_assert_ptr_nonnull(m.edges);
            m.edges[m.edge_count][0] = m.module_of[i];
            m.edges[m.edge_count++][1] = m.module_of[target];
        }
    int *component = malloc((size_t)(m.count + 1) * sizeof *component);
    ck_assert_ptr_nonnull(component);
    int count = components(&m, m.count, module_edge, component);
    report_circles(&r, m.count, component, count, module_edge, &m,
                   module_label, describe_modules, "module");
    free(component);
    free(m.edges);
    free(m.module_of);
    finish(&r, "module");
    free_tree(&t);
}
END_TEST

START_TEST(no_source_file_of_src_or_apps_is_over_700_lines)
{
    tree t = read_tree();
    report r = new_report();
    for (int i = 0; i < t.count; i++) {
        if (t.files[i].lines <= RT_LAYERS_MAX_LINES)
            continue;
        char key[600], what[128];
        snprintf(key, sizeof key, "size %s", t.files[i].path);
        snprintf(what, sizeof what, "%ld lines, over %d", t.files[i].lines,
                 RT_LAYERS_MAX_LINES);
        violation(&r, key, t.files[i].path, what);
    }
    finish(&r, "size");
    free_tree(&t);
}
END_TEST

/* The check itself: a tree with a violation of each kind is seen. */
START_TEST(the_rules_refuse_an_upward_include_and_accept_a_downward_one)
{
    tree t = {NULL, 0, 0};
    add_file(&t, "src/base/a.h");
    add_file(&t, "src/scene/b.c");
    add_file(&t, "src/formats/c.c");
    add_file(&t, "src/render/d.c");
    add_file(&t, "src/in104/e.c");
    const source *f = t.files;
    ck_assert_ptr_null(forbidden(&f[1], &f[0]));     /* scene -> base */
    ck_assert_ptr_nonnull(forbidden(&f[0], &f[1]));  /* base -> scene */
    ck_assert_ptr_nonnull(forbidden(&f[2], &f[3]));  /* formats -> render */
    ck_assert_ptr_nonnull(forbidden(&f[3], &f[2]));  /* render -> formats */
    ck_assert_ptr_null(forbidden(&f[2], &f[1]));     /* formats -> scene */
    ck_assert_ptr_nonnull(forbidden(&f[4], &f[1]));  /* in104 -> scene */
    ck_assert_ptr_null(forbidden(&f[4], &f[0]));     /* in104 -> base */
    ck_assert_ptr_nonnull(forbidden(&f[0], &f[4]));  /* base -> in104 */
    ck_assert_ptr_nonnull(forbidden(&f[1], &f[4]));  /* scene -> in104 */
    ck_assert_int_eq(layer_of("src/tools/x.c"), -1);
    ck_assert_int_eq(layer_of("src/kernelx/x.c"), -1);
    free_tree(&t);
}
END_TEST

/* Two files that include each other make one circle of two. */
typedef struct toy {
    int edges[3][3];        /* per node, -2 terminated */
} toy;

static int toy_edge(const void *graph, int node, int k)
{
    return ((const toy *)graph)->edges[node][k];
}

START_TEST(a_circle_of_two_files_is_one_component_and_a_chain_is_none)
{
    toy circle = {{{1, -2, 0}, {0, -2, 0}, {0, -2, 0}}};
    int component[3];
    ck_assert_int_eq(components(&circle, 3, toy_edge, component), 2);
    ck_assert_int_eq(component[0], component[1]);
    ck_assert_int_ne(component[0], component[2]);
    toy chain = {{{1, -2, 0}, {2, -2, 0}, {-2, 0, 0}}};
    ck_assert_int_eq(components(&chain, 3, toy_edge, component), 3);
}
END_TEST

static Suite *layers_suite(void)
{
    Suite *s = suite_create("layers");
    TCase *tree_case = tcase_create("the tree");
    tcase_add_test(tree_case, every_folder_of_src_is_a_layer);
    tcase_add_test(tree_case, no_include_in_src_goes_up_a_layer_or_across);
    tcase_add_test(tree_case,
                   no_file_of_src_reaches_itself_through_its_includes);
    tcase_add_test(
        tree_case,
        no_module_of_src_reaches_itself_through_the_headers_it_includes);
    tcase_add_test(tree_case, no_source_file_of_src_or_apps_is_over_700_lines);
    suite_add_tcase(s, tree_case);

    TCase *rules = tcase_create("the rules");
    tcase_add_test(
        rules, the_rules_refuse_an_upward_include_and_accept_a_downward_one);
    tcase_add_test(rules,
                   a_circle_of_two_files_is_one_component_and_a_chain_is_none);
    suite_add_tcase(s, rules);
    return s;
}

RT_CHECK_MAIN(layers_suite)
