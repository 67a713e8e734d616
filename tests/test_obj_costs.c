/*
 * test_obj_costs.c - what hostile OBJ and MTL input costs, as bytes in
 * against facets, warnings and memory out (never time): unknown material
 * names cost their bytes and one warning; a face repeating two corners
 * gives no facet; a convex face of 10^5 corners gives n - 2 facets, cut
 * balanced; a large non-convex face is fanned once the load's budget is
 * spent; what could warn per element warns once with a count; an ignored
 * statement keeps no token; a raised cancel flag stops a load between
 * statements.  Memory is checked under an address-space limit in a child
 * process (skipped under a sanitizer or valgrind, which reserve more than
 * they use).
 */
#include <check.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

/* Serves every library from the text at `user`. */
static rt_status serve(void *user, const char *scene_name,
                       const char *reference, size_t limit,
                       rt_resolved_file *file, rt_error *error)
{
    (void)scene_name, (void)limit, (void)error;
    const rt_test_text *t = user;
    file->data = malloc(t->length + 1);
    memcpy(file->data, t->data, t->length);
    file->length = t->length;
    file->name = strdup(reference);
    file->device = file->inode = 0;
    return RT_OK;
}

static rt_status parse(const rt_test_text *t, const rt_test_text *library,
                       rt_scene **scene, rt_error *error)
{
    rt_load_options options;
    rt_load_options_init(&options);
    options.format = RT_SCENE_FORMAT_OBJ;
    if (library != NULL) {
        options.resolve = serve;
        options.resolve_user = (void *)library;
    }
    return rt_scene_parse(t->data, t->length, "hostile.obj", &options, scene,
                          error);
}

static rt_scene *loaded(const rt_test_text *t, const rt_test_text *library)
{
    rt_scene *scene = NULL;
    rt_error error;
    rt_status status = parse(t, library, &scene, &error);
    ck_assert_msg(status == RT_OK, "%s", error.message);
    return scene;
}

/* A parse of `t` in a child whose address space may grow by `limit`. */
typedef struct bounded {
    const rt_test_text *t;
    size_t limit;
} bounded;

static int parse_bounded(void *arg, char *message, size_t size)
{
    const bounded *b = arg;
    if (!rt_test_limit_address_space(b->limit, message, size))
        return 2;
    rt_scene *scene;
    rt_error error;
    rt_status status = parse(b->t, NULL, &scene, &error);
    snprintf(message, size, "%s", status == RT_OK ? "loaded" : error.message);
    rt_scene_destroy(scene);
    return status != RT_OK;
}

static void loads_within(const rt_test_text *t, size_t limit, const char *what)
{
    if (RT_TEST_UNDER_ASAN || rt_test_under_valgrind()) {
        fprintf(stderr, "test_obj_costs: %s: the address-space limit is "
                        "skipped under a sanitizer or valgrind\n", what);
        return;
    }
    bounded b = {t, limit};
    char message[1024];
    int code = rt_test_in_child(parse_bounded, &b, message, sizeof message);
    ck_assert_msg(code == 0, "%s (%zu bytes) did not load within %zu MB: %s",
                  what, t->length, limit >> 20, message);
}

static const char square[] = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

/* n, or n / 10 under valgrind (RT_TEST_MEMCHECK=1: the same paths, where
 * the sizes make no threshold; the memory limits are skipped there). */
static int sized(int n)
{
    return rt_test_memcheck() ? n / 10 : n;
}

START_TEST(unknown_material_names_cost_their_bytes_and_one_warning)
{
    rt_test_text t = {NULL, 0, 0};
    rt_test_text_add(&t, "%s", square);
    int names = sized(100000);
    for (int i = 0; i < names; i++)
        rt_test_text_add(&t, "usemtl material-%d\n", i);
    rt_test_text_add(&t, "f 1 2 3\n");
    rt_scene *scene = loaded(&t, NULL);
    rt_scene_info info = rt_test_scene_info(scene);
    ck_assert_int_eq(info.facet_count, 1);
    /* One warning for the names, which quotes the first three. */
    ck_assert_int_eq(info.warning_count, 1);
    char expected[256];
    snprintf(expected, sizeof expected,
             "hostile.obj:5:8: warning: materials `material-0`, "
             "`material-1`, `material-2` and %d more are defined in no "
             "material library", names - 3);
    ck_assert_int_eq(rt_test_count_warnings(scene, expected), 1);
    rt_scene_destroy(scene);
    /* 1.9 MB in, 32 MB allowed (the reader before kept a 500-byte
     * material and a 512-byte warning a name: 100 MB). */
    loads_within(&t, 32u << 20, "100,000 unknown names");
    free(t.data);
}
END_TEST

START_TEST(a_face_repeating_two_corners_gives_no_facet_and_one_warning)
{
    rt_test_text t = {NULL, 0, 0};
    rt_test_text_add(&t, "%sv 2 0 0\nf", square);
    for (int i = 0; i < sized(200000); i++)
        rt_test_text_add(&t, " %d", 1 + i % 2);
    rt_test_text_add(&t, "\nf 1 3 1 3 1 3\nf 1 2 5 2\n");
    rt_scene *scene = loaded(&t, NULL);
    rt_scene_info info = rt_test_scene_info(scene);
    ck_assert_int_eq(info.facet_count, 0);
    ck_assert_int_eq(info.warning_count, 2);   /* the faces, the picture */
    ck_assert_int_eq(rt_test_count_warnings(scene,
                                            "hostile.obj:6:1: warning: this "
                                          "face has no area"),
                     1);
    ck_assert_int_eq(rt_test_count_warnings(scene, "(and 2 more like it)"), 1);
    ck_assert_int_eq(rt_test_count_warnings(scene, "no face to draw"), 1);
    rt_scene_destroy(scene);
    free(t.data);
}
END_TEST

START_TEST(a_convex_face_of_100000_corners_gives_n_minus_2_facets_cut_balanced)
{
    int n = sized(100000);
    rt_test_text t = {NULL, 0, 0};
    /* Written with 9 decimals, as a program would: not convex to the last
     * bit, convex to a billionth. */
    for (int i = 0; i < n; i++)
        rt_test_text_add(&t, "v %.9f %.9f 0\n", cos(6.283185307179586 * i / n),
            sin(6.283185307179586 * i / n));
    rt_test_text_add(&t, "f");
    for (int i = 1; i <= n; i++)
        rt_test_text_add(&t, " %d", i);
    rt_test_text_add(&t, "\n");
    rt_scene *scene = loaded(&t, NULL);
    rt_scene_info info = rt_test_scene_info(scene);
    ck_assert_int_le(info.facet_count, n - 2);
    ck_assert_int_gt(info.facet_count, n / 2);
    ck_assert_int_eq(info.live_facet_count, info.facet_count);
    ck_assert_int_eq(info.warning_count, 0);
    int *uses = calloc((size_t)n, sizeof *uses), most = 0;
    ck_assert_ptr_nonnull(uses);
    for (int i = 0; i < info.facet_count; i++) {
        rt_facet_info f = {.size = sizeof f};
        rt_scene_facet(scene, i, &f);
        ck_assert(f.normal.z > 0);      /* the face's winding */
        for (int k = 0; k < 3; k++)
            if (++uses[f.vertex[k]] > most)
                most = uses[f.vertex[k]];
    }
    /* A fan would meet n - 2 facets at one corner. */
    ck_assert_int_le(most, 36);
    free(uses);
    rt_scene_destroy(scene);
    free(t.data);
}
END_TEST

START_TEST(a_large_non_convex_face_is_fanned_once_the_budget_is_spent)
{
    /* A comb of 15,000 teeth: ear clipping would test about n^2 / 4 =
     * 9e8 corners; the budget of its 0.9 MB is 2^25 + 256 per byte. */
    int teeth = 15000;
    rt_test_text t = {NULL, 0, 0};
    rt_test_text_add(&t, "v %d 0 0\n", 2 * teeth);
    for (int k = teeth - 1; k >= 0; k--)
        rt_test_text_add(&t, "v %d 6 0\nv %d 6 0\nv %d 1 0\nv %d 1 0\n",
                         2 * k + 2,
            2 * k + 1, 2 * k + 1, 2 * k);
    rt_test_text_add(&t, "v 0 0 0\nf");
    int n = 4 * teeth + 2;
    for (int i = 1; i <= n; i++)
        rt_test_text_add(&t, " %d", i);
    rt_test_text_add(&t, "\n");
    rt_scene *scene = loaded(&t, NULL);
    rt_scene_info info = rt_test_scene_info(scene);
    ck_assert_int_le(info.facet_count, n - 2);
    ck_assert_int_gt(info.facet_count, n / 2);
    ck_assert_int_eq(info.live_facet_count, info.facet_count);
    ck_assert_int_eq(rt_test_count_warnings(scene,
                                            "budget for cutting non-convex "
                                          "polygons"),
                     1);
    rt_scene_destroy(scene);
    free(t.data);
}
END_TEST

START_TEST(warnings_that_could_repeat_per_element_are_said_once_with_a_count)
{
    rt_test_text t = {NULL, 0, 0}, library = {NULL, 0, 0};
    /* Per round: a face without area (vertex 5 is on the line of 1 and 2),
     * one with a single corner, `usemtl` and `mtllib` without a name; in
     * the library, a colour and an index that cannot be used. */
    rt_test_text_add(&t, "mtllib m.mtl\n%sv 2 0 0\n", square);
    rt_test_text_add(&library, "newmtl a\n");
    for (int i = 0; i < 10000; i++) {
        rt_test_text_add(&t, "f 1 2 5\nf 3 3 3\nusemtl\nmtllib\n");
        rt_test_text_add(&library, "Kd x\nNi -1\n");
    }
    rt_test_text_add(&t, "usemtl a\nf 1 2 3\n");
    rt_scene *scene = loaded(&t, &library);
    rt_scene_info info = rt_test_scene_info(scene);
    ck_assert_int_eq(info.facet_count, 1);
    ck_assert_int_eq(info.warning_count, 5);
    ck_assert_int_eq(rt_test_count_warnings(scene, "has no area"), 1);
    ck_assert_int_eq(rt_test_count_warnings(scene,
                                            "fewer than 3 distinct corners"),
                     1);
    ck_assert_int_eq(rt_test_count_warnings(scene, "without a file name"), 1);
    ck_assert_int_eq(rt_test_count_warnings(scene,
                                            "m.mtl:2:4: warning: expected a "
                                          "number, found `x`"),
                     1);
    ck_assert_int_eq(rt_test_count_warnings(scene, "(and 9999 more like it)"),
                     4);
    ck_assert_int_eq(rt_test_count_warnings(scene, "(and 19999 more like it)"),
                     1);
    rt_scene_destroy(scene);
    free(t.data);
    free(library.data);
}
END_TEST

START_TEST(an_ignored_statement_keeps_no_token)
{
    /* 4 MB of `l` corners, and as much of an unknown statement: 2 million
     * tokens each, 48 MB if they were kept. */
    rt_test_text t = {NULL, 0, 0};
    rt_test_text_add(&t, "%sl", square);
    for (int i = 0; i < sized(2000000); i++)
        rt_test_text_add(&t, " 1");
    rt_test_text_add(&t, "\ncurv");
    for (int i = 0; i < sized(2000000); i++)
        rt_test_text_add(&t, " 2");
    rt_test_text_add(&t, "\nf 1 2 3\n");
    rt_scene *scene = loaded(&t, NULL);
    ck_assert_int_eq(rt_test_scene_info(scene).facet_count, 1);
    ck_assert_int_eq(rt_test_scene_info(scene).warning_count, 2);
    rt_scene_destroy(scene);
    loads_within(&t, 16u << 20, "8 MB of ignored statements");
    free(t.data);
}
END_TEST

/* A resolver that raises the load's cancel flag when it is asked. */
static rt_status raise_flag(void *user, const char *scene_name,
                            const char *reference, size_t limit,
                            rt_resolved_file *file, rt_error *error)
{
    (void)scene_name, (void)limit, (void)file;
    rt_cancel_request(user);
    error->status = RT_ERR_IO;
    snprintf(error->message, sizeof error->message,
             "`%s` is not read: the flag is raised instead", reference);
    return RT_ERR_IO;
}

START_TEST(a_cancel_flag_raised_during_a_load_stops_it_between_statements)
{
    rt_test_text t = {NULL, 0, 0};
    rt_test_text_add(&t, "mtllib m.mtl\n");
    for (int i = 0; i < 100000; i++)
        rt_test_text_add(&t, "v %d 0 0\n", i);
    rt_cancel *cancel;
    ck_assert_int_eq(rt_cancel_create(&cancel, NULL), RT_OK);
    rt_load_options options;
    rt_load_options_init(&options);
    options.format = RT_SCENE_FORMAT_OBJ;
    options.cancel = cancel;
    options.resolve = raise_flag;
    options.resolve_user = cancel;
    rt_scene *scene = (rt_scene *)1;
    rt_error error;
    ck_assert_int_eq(
        rt_scene_parse(t.data, t.length, "c.obj", &options, &scene, &error),
        RT_ERR_CANCELLED);
    ck_assert_ptr_null(scene);
    ck_assert_ptr_nonnull(strstr(error.message, "c.obj: the load was "
                                                "cancelled"));
    rt_cancel_destroy(cancel);
    free(t.data);
}
END_TEST

static Suite *obj_costs_suite(void)
{
    Suite *s = suite_create("obj_costs");
    TCase *c = tcase_create("costs");
    tcase_set_timeout(c, 300);
    tcase_add_test(c, unknown_material_names_cost_their_bytes_and_one_warning);
    tcase_add_test(c,
                   a_face_repeating_two_corners_gives_no_facet_and_one_warning);
    tcase_add_test(
        c,
        a_convex_face_of_100000_corners_gives_n_minus_2_facets_cut_balanced);
    tcase_add_test(c,
                   a_large_non_convex_face_is_fanned_once_the_budget_is_spent);
    tcase_add_test(
        c, warnings_that_could_repeat_per_element_are_said_once_with_a_count);
    tcase_add_test(c, an_ignored_statement_keeps_no_token);
    tcase_add_test(
        c, a_cancel_flag_raised_during_a_load_stops_it_between_statements);
    suite_add_tcase(s, c);
    return s;
}

RT_CHECK_MAIN(obj_costs_suite)
