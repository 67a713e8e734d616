/*
 * test_layers_circles.c - no include circle in src/ (docs/architecture.md):
 * no file reaches itself through its includes, and no module (a folder's
 * x.h with its x.c) reaches itself through the headers its files include.
 * Each circle is printed with the includes (file:line) that make it before
 * the test fails; tests/layers.allow may list one ("circle <file>...",
 * "module <module>...") while it is being removed, and an entry that
 * matches nothing fails the test.  The tree and the report are
 * support/source_tree.h's; the other rules are test_layers.c's.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "source_tree.h"
#include "testutil.h"

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
    const rt_test_source *s = &((const rt_test_tree *)graph)->files[node];
    if (k >= s->include_count)
        return -2;
    return s->includes[k].target;
}

/* A module: a folder's x.h with its x.c (a lone file is its own). */
typedef struct modules {
    const rt_test_tree *t;
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

static void report_circles(rt_test_report *r, int n, const int *component,
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
        rt_test_report_violation(r, key, where, what);
    }
}

/* Writes "file:line includes target; ..." for each include of `t` inside
 * component `c`: between two files of it, or (with `of`, which maps a file
 * to its module) between files of two of its modules. */
static void describe_includes(const rt_test_tree *t, const int *of,
                              const int *component, int c, char *out,
                              size_t size)
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
    return ((const rt_test_tree *)graph)->files[node].path;
}

START_TEST(no_file_of_src_reaches_itself_through_its_includes)
{
    rt_test_tree t = rt_test_tree_read();
    rt_test_report r = rt_test_report_new();
    int *component = malloc((size_t)(t.count + 1) * sizeof *component);
    ck_assert_ptr_nonnull(component);
    int count = components(&t, t.count, file_edge, component);
    report_circles(&r, t.count, component, count, file_edge, &t, file_name,
                   describe_files, "circle");
    free(component);
    rt_test_report_finish(&r, "circle");
    rt_test_tree_free(&t);
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
    rt_test_tree t = rt_test_tree_read();
    rt_test_report r = rt_test_report_new();
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
    rt_test_report_finish(&r, "module");
    rt_test_tree_free(&t);
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

static Suite *layers_circles_suite(void)
{
    Suite *s = suite_create("layers_circles");
    TCase *tree_case = tcase_create("the tree");
    tcase_add_test(tree_case,
                   no_file_of_src_reaches_itself_through_its_includes);
    tcase_add_test(
        tree_case,
        no_module_of_src_reaches_itself_through_the_headers_it_includes);
    suite_add_tcase(s, tree_case);

    TCase *rules = tcase_create("the rules");
    tcase_add_test(rules,
                   a_circle_of_two_files_is_one_component_and_a_chain_is_none);
    suite_add_tcase(s, rules);
    return s;
}

RT_CHECK_MAIN(layers_circles_suite)
