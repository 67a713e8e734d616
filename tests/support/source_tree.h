/*
 * source_tree.h - the project's source tree as the layering suites read it
 * (test_layers.c, test_layers_circles.c): every .c and .h of src/ and
 * apps/ with its line count and, in src/, its `#include "..."` lines
 * resolved as the build resolves them (the file's folder, src/, include/,
 * and include/in104 for the course's layer); the layers of
 * docs/architecture.md; and the report of violations against the
 * allow-list tests/layers.allow.  Part of the support library
 * (tests/support/), not of testutil.h; its functions fail the test
 * (Check) when they cannot do their job.
 */
#ifndef RAYTRACE_TEST_SOURCE_TREE_H
#define RAYTRACE_TEST_SOURCE_TREE_H

/* A layer of src/: its folder and its rank, lowest first (base 0, kernel
 * 1, scene 2, formats and render 3, in104 -1: apart). */
typedef struct rt_test_layer {
    const char *folder;     /* under src/ */
    int rank;               /* -1: apart (in104) */
} rt_test_layer;

typedef struct rt_test_include {
    char spelled[256];      /* as written between the quotes */
    int line;
    int target;             /* index into the files, or -1 */
    int is_public;          /* resolved to include/ (or raytrace/...) */
} rt_test_include;

typedef struct rt_test_source {
    char path[512];         /* relative to the source tree */
    int layer;              /* index into layers, -1 outside src/ */
    int in_src;
    long lines;
    rt_test_include *includes;
    int include_count;
} rt_test_source;

typedef struct rt_test_tree {
    rt_test_source *files;
    int count, capacity;
} rt_test_tree;

typedef struct rt_test_allow_list {
    char (*keys)[1024];
    int *used;
    int count;
} rt_test_allow_list;

typedef struct rt_test_report {
    rt_test_allow_list allowed;
    int violations;         /* not allowed */
    int allowed_seen;
    char first[1024];
} rt_test_report;

extern const rt_test_layer rt_test_layers[];
extern const int rt_test_layer_count;

/* The index in rt_test_layers of the layer `path` (relative to the source
 * tree) is in, or -1 outside src/'s layers. */
int rt_test_layer_of(const char *path);

/* Every .c and .h of src/ and apps/, read and resolved; free with
 * rt_test_tree_free. */
rt_test_tree rt_test_tree_read(void);
/* Appends a file to `t`, by its path, without reading it. */
void rt_test_tree_add(rt_test_tree *t, const char *path);
void rt_test_tree_free(rt_test_tree *t);

/* A report of violations, with tests/layers.allow read: one key a line
 * ("include <file> <target>", "circle <file>...", "module <module>...",
 * "size <file>"), then anything after a '#'. */
rt_test_report rt_test_report_new(void);

/* Prints one violation (`where`: file:line) and counts it, unless the
 * allow-list has `key`, in which case it is printed as allowed. */
void rt_test_report_violation(rt_test_report *r, const char *key,
                              const char *where, const char *what);

/* Fails the test when a violation was not allowed, or when an entry of the
 * allow-list of kind `kind` (its first word) matched nothing; frees the
 * allow-list. */
void rt_test_report_finish(rt_test_report *r, const char *kind);

#endif /* RAYTRACE_TEST_SOURCE_TREE_H */
