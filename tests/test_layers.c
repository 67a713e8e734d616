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
 *   - every folder of src/ is a layer the rules know;
 *   - no source file of src/ or apps/ is over RT_LAYERS_MAX_LINES lines.
 *
 * No include circle is test_layers_circles.c's rule; the tree, the layers
 * and the report are support/source_tree.h's.  Every violation is printed
 * (file:line, what, why) before the test fails, so one run lists them
 * all.  tests/layers.allow lists the violations
 * known while the round that removes them is under way, each with the
 * reason it is to go; a violation it lists is printed as allowed, and an
 * entry that no longer matches a violation fails the test, so the list
 * only shrinks.  Calls by name across layers (the kernel calling the
 * renderer's recorder) are beyond what includes show.
 */
#include <stdio.h>
#include <string.h>

#include "source_tree.h"
#include "testutil.h"

/* The largest source file the layout allows (docs/architecture.md): a file
 * a reader takes in at once; longer ones are split by job. */
#define RT_LAYERS_MAX_LINES 700

/* ------------------------------------------------------------------ */
/* The rules                                                            */

/* Why `from` may not include `to`, or NULL when it may. */
static const char *forbidden(const rt_test_source *from,
                             const rt_test_source *to)
{
    if (from->layer < 0 || to->layer < 0)
        return NULL;        /* an unknown folder: its own test says so */
    const rt_test_layer *a = &rt_test_layers[from->layer],
                        *b = &rt_test_layers[to->layer];
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
    rt_test_tree t = rt_test_tree_read();
    rt_test_report r = rt_test_report_new();
    for (int i = 0; i < t.count; i++) {
        const rt_test_source *s = &t.files[i];
        for (int k = 0; k < s->include_count; k++) {
            const rt_test_include *inc = &s->includes[k];
            char where[600], what[1024], key[1100];
            snprintf(where, sizeof where, "%s:%d", s->path, inc->line);
            if (inc->target < 0) {
                if (inc->is_public)
                    continue;
                snprintf(key, sizeof key, "include %s %s", s->path,
                         inc->spelled);
                snprintf(what, sizeof what, "includes \"%s\", which is no "
                         "file of src/ or include/", inc->spelled);
                rt_test_report_violation(&r, key, where, what);
                continue;
            }
            const rt_test_source *to = &t.files[inc->target];
            const char *why = forbidden(s, to);
            if (why == NULL)
                continue;
            snprintf(key, sizeof key, "include %s %s", s->path, to->path);
            snprintf(what, sizeof what, "includes %s: %s", to->path, why);
            rt_test_report_violation(&r, key, where, what);
        }
    }
    rt_test_report_finish(&r, "include");
    rt_test_tree_free(&t);
}
END_TEST

START_TEST(every_folder_of_src_is_a_layer)
{
    rt_test_tree t = rt_test_tree_read();
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
    for (int l = 0; l < rt_test_layer_count; l++) {
        int files = 0;
        for (int i = 0; i < t.count; i++)
            files += t.files[i].layer == l;
        ck_assert_msg(files > 0, "no file in src/%s", rt_test_layers[l].folder);
    }
    rt_test_tree_free(&t);
}
END_TEST

START_TEST(no_source_file_of_src_or_apps_is_over_700_lines)
{
    rt_test_tree t = rt_test_tree_read();
    rt_test_report r = rt_test_report_new();
    for (int i = 0; i < t.count; i++) {
        if (t.files[i].lines <= RT_LAYERS_MAX_LINES)
            continue;
        char key[600], what[128];
        snprintf(key, sizeof key, "size %s", t.files[i].path);
        snprintf(what, sizeof what, "%ld lines, over %d", t.files[i].lines,
                 RT_LAYERS_MAX_LINES);
        rt_test_report_violation(&r, key, t.files[i].path, what);
    }
    rt_test_report_finish(&r, "size");
    rt_test_tree_free(&t);
}
END_TEST

/* The check itself: a tree with a violation of each kind is seen. */
START_TEST(the_rules_refuse_an_upward_include_and_accept_a_downward_one)
{
    rt_test_tree t = {NULL, 0, 0};
    rt_test_tree_add(&t, "src/base/a.h");
    rt_test_tree_add(&t, "src/scene/b.c");
    rt_test_tree_add(&t, "src/formats/c.c");
    rt_test_tree_add(&t, "src/render/d.c");
    rt_test_tree_add(&t, "src/in104/e.c");
    const rt_test_source *f = t.files;
    ck_assert_ptr_null(forbidden(&f[1], &f[0]));     /* scene -> base */
    ck_assert_ptr_nonnull(forbidden(&f[0], &f[1]));  /* base -> scene */
    ck_assert_ptr_nonnull(forbidden(&f[2], &f[3]));  /* formats -> render */
    ck_assert_ptr_nonnull(forbidden(&f[3], &f[2]));  /* render -> formats */
    ck_assert_ptr_null(forbidden(&f[2], &f[1]));     /* formats -> scene */
    ck_assert_ptr_nonnull(forbidden(&f[4], &f[1]));  /* in104 -> scene */
    ck_assert_ptr_null(forbidden(&f[4], &f[0]));     /* in104 -> base */
    ck_assert_ptr_nonnull(forbidden(&f[0], &f[4]));  /* base -> in104 */
    ck_assert_ptr_nonnull(forbidden(&f[1], &f[4]));  /* scene -> in104 */
    ck_assert_int_eq(rt_test_layer_of("src/tools/x.c"), -1);
    ck_assert_int_eq(rt_test_layer_of("src/kernelx/x.c"), -1);
    rt_test_tree_free(&t);
}
END_TEST

static Suite *layers_suite(void)
{
    Suite *s = suite_create("layers");
    TCase *tree_case = tcase_create("the tree");
    tcase_add_test(tree_case, every_folder_of_src_is_a_layer);
    tcase_add_test(tree_case, no_include_in_src_goes_up_a_layer_or_across);
    tcase_add_test(tree_case, no_source_file_of_src_or_apps_is_over_700_lines);
    suite_add_tcase(s, tree_case);

    TCase *rules = tcase_create("the rules");
    tcase_add_test(
        rules, the_rules_refuse_an_upward_include_and_accept_a_downward_one);
    suite_add_tcase(s, rules);
    return s;
}

RT_CHECK_MAIN(layers_suite)
