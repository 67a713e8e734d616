/*
 * test_explain_terms.c - an explanation names each term as the rendering
 * model does (docs/rendering-model.md): under a total internal reflection
 * the renderer casts one mirror ray, of weight k + t, for both k C_R and
 * t C_T (C_T is then the mirror ray's colour); on a facet with k = 0 that
 * ray is the t C_T term, and rt-export's --explain (text and JSON) and
 * rt-view's click (view_explain.c) must say so, not "reflection k C_R".
 *
 * The scene: a glass facet (k = 0, t = 1, n = 1.5) seen from behind at 60
 * degrees from its normal.  Leaving glass, eta = n = 1.5 and
 * q = 1 - eta^2 (1 - cos^2 60) = 1 - 2.25 x 0.75 = -0.6875 < 0: the ray is
 * totally reflected, and its mirror ray meets nothing, so it brings back
 * the background (10, 20, 30) times k + t = 1.  With k = 0.25, t = 0.75 the
 * terms are 0.25 and 0.75 of it.  For every hit of every scene, the three
 * terms add up to what the hit carries.  (rt-view's text is rt-export's,
 * from one formatter: tests/test_explain_same.c compares them whole.)
 */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli_explain.h"
#include "testutil.h"
#if RT_TEST_HAVE_VIEWER
#include "view_explain.h"
#endif

/* The facet's record is the scene's line 9; `k` and `t` its weights. */
static void write_tir_scene(const char *path, const char *k, const char *t)
{
    char text[1024];
    snprintf(text, sizeof text,
             "# a glass facet seen from behind at 60 degrees\n"
             "0, 0, 5\n"
             "0, 0, 4,  0.1, 0, 4,  9, 9\n"
             "3\n"
             "-2, -2, -3.464101615137754\n"
             "2, -2, 3.464101615137754\n"
             "0, 3, 0\n"
             "1\n"
             "1, 3, 2, %s, 200, 200, 200, %s, 1.5\n"
             "10, 20, 30\n"
             "0, 0, 10, 255, 255, 255\n",
             k, t);
    rt_test_write_file(path, text);
}

/* rt-export --explain 4,4 (the ray through the facet's point at the
 * origin) of the scene, with `extra` (NULL or --explain-json). */
static char *explain(const char *dir, const char *extra)
{
    const char *args[] = {"tir.scn", "--explain", "4,4", extra, NULL};
    rt_test_output r = rt_test_run(dir, RT_EXPORT_PATH, args);
    ck_assert_msg(r.code == 0, "%s", r.err);
    char *out = strdup(r.out);
    rt_test_output_free(&r);
    return out;
}

START_TEST(explain_names_a_total_internal_reflection_the_t_ct_term)
{
    char *dir = rt_test_temp_dir();
    write_tir_scene(rt_test_in_dir(dir, "tir.scn"), "0", "1");
    char *text = explain(dir, NULL);
    ck_assert_msg(strstr(text, "hits facet 0 (line 9) at t 5, point (0, 0, "
                               "0), normal as used (-0.866025, -0, 0.5); "
                               "k 0, t 1, d 0\n"), "%s", text);
    ck_assert_msg(strstr(text, "\n    totally reflected ray (weight 1) "
                               "from "), "%s", text);
    ck_assert_msg(strstr(text, "terms: direct light 0 0 0 + reflection k C_R "
                               "0 0 0 + refraction t C_T 10 20 30 = 10 20 30 "
                               "(total internal reflection: C_T is the "
                               "colour of the mirror ray, which carries "
                               "k C_R + t C_T)\n"), "%s", text);
    ck_assert_ptr_null(strstr(text, "    reflected ray"));
    ck_assert_msg(strstr(text, "pixel value 10 20 30 -> bytes 10 20 30\n"),
                  "%s", text);
    free(text);
    char *json = explain(dir, "--explain-json");
    /* the camera ray's hit: its terms; its mirror ray: marked */
    ck_assert_msg(strstr(json, "\"direct\":[0,0,0],\"reflection\":[0,0,0],"
                               "\"refraction\":[10,20,30]"), "%s", json);
    ck_assert_msg(strstr(json, "\"kind\":\"reflected\",\"parent\":0,"), "%s",
                  json);
    ck_assert_msg(strstr(json, "\"total_internal_reflection\":true"), "%s",
                  json);
    free(json);
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(explain_splits_the_mirror_ray_k_to_t_when_both_are_there)
{
    char *dir = rt_test_temp_dir();
    write_tir_scene(rt_test_in_dir(dir, "tir.scn"), "0.25", "0.75");
    char *text = explain(dir, NULL);
    ck_assert_msg(strstr(text, "terms: direct light 0 0 0 + reflection k C_R "
                               "2.5 5 7.5 + refraction t C_T 7.5 15 22.5 = "
                               "10 20 30 (total internal reflection"),
                  "%s", text);
    free(text);
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(explain_of_an_opaque_mirror_is_unchanged)
{
    char *dir = rt_test_temp_dir();
    char scene[4096];
    snprintf(scene, sizeof scene, "%s",
             rt_test_source_path("scenes/cubes.scn"));
    const char *args[] = {scene, "--explain", "269,172", NULL};
    rt_test_output r = rt_test_run(dir, RT_EXPORT_PATH, args);
    ck_assert_int_eq(r.code, 0);
    /* docs/teaching.md's example, line for line */
    ck_assert_msg(strstr(r.out, "    reflected ray (weight 0.5) from "),
                  "%s", r.out);
    ck_assert_msg(strstr(r.out, "    terms: direct light 0 0 0 + reflection "
                                "k C_R 5 5 5 + refraction t C_T 0 0 0 = 5 5 "
                                "5\n"), "%s", r.out);
    ck_assert_ptr_null(strstr(r.out, "totally"));
    rt_test_output_free(&r);
    const char *json[] = {scene, "--explain", "269,172", "--explain-json",
                          NULL};
    r = rt_test_run(dir, RT_EXPORT_PATH, json);
    ck_assert_int_eq(r.code, 0);
    ck_assert_ptr_nonnull(strstr(r.out, "\"total_internal_reflection\":"
                                        "false"));
    ck_assert_ptr_null(strstr(r.out, "\"total_internal_reflection\":true"));
    rt_test_output_free(&r);
    rt_test_remove_dir(dir);
}
END_TEST

/* Every hit of every pixel of a sample of each scene: the three terms add
 * up to what the hit carries; returns how many total internal reflections
 * were met. */
static int check_terms(const char *path, int step)
{
    rt_scene *scene;
    rt_error error;
    ck_assert_msg(rt_scene_load(path, NULL, &scene, &error) == RT_OK, "%s",
                  error.message);
    rt_render_options options;
    rt_render_options_init(&options);
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    int total = 0;
    for (int y = 0; y < info.height; y += step)
        for (int x = 0; x < info.width; x += step) {
            rt_ray_tree *tree;
            ck_assert_int_eq(rt_explain_pixel(scene, &options, x, y, -1,
                                              &tree, &error), RT_OK);
            size_t count;
            const rt_ray_node *n = rt_ray_tree_nodes(tree, &count);
            for (size_t i = 0; i < count; i++) {
                if (!n[i].hit || n[i].kind == RT_RAY_SHADOW)
                    continue;
                rt_color d, r, t;
                total += cli_explain_terms(n, count, i, &d, &r, &t);
                double sums[3] = {d.r + r.r + t.r, d.g + r.g + t.g,
                                  d.b + r.b + t.b};
                double want[3] = {n[i].subtotal.r, n[i].subtotal.g,
                                  n[i].subtotal.b};
                for (int c = 0; c < 3; c++)
                    ck_assert_msg(fabs(sums[c] - want[c]) <=
                                      1e-12 * (1 + fabs(want[c])),
                                  "%s pixel %d,%d ray %zu: terms %.17g, "
                                  "carries %.17g", path, x, y, i, sums[c],
                                  want[c]);
                if (n[i].transparency == 0)
                    ck_assert(t.r == 0 && t.g == 0 && t.b == 0);
                if (n[i].reflection == 0)
                    ck_assert(r.r == 0 && r.g == 0 && r.b == 0);
            }
            rt_ray_tree_destroy(tree);
        }
    rt_scene_destroy(scene);
    return total;
}

START_TEST(terms_add_up_to_what_each_hit_carries)
{
    char *dir = rt_test_temp_dir();
    write_tir_scene(rt_test_in_dir(dir, "tir.scn"), "0", "1");
    ck_assert_int_gt(check_terms(rt_test_in_dir(dir, "tir.scn"), 1), 0);
    static const char *const scenes[] = {"scenes/cubes.scn",
                                         "scenes/mirror.scn",
                                         "scenes/glass.scn"};
    for (size_t i = 0; i < sizeof scenes / sizeof *scenes; i++) {
        char path[4096];
        snprintf(path, sizeof path, "%s", rt_test_source_path(scenes[i]));
        int total = check_terms(path, 23);
        /* the slab's side faces keep rays in (scenes/glass.scn says) */
        if (strstr(scenes[i], "glass"))
            ck_assert_int_gt(total, 0);
        else
            ck_assert_int_eq(total, 0);
    }
    rt_test_remove_dir(dir);
}
END_TEST

#if RT_TEST_HAVE_VIEWER
START_TEST(viewer_names_a_total_internal_reflection_the_t_ct_term)
{
    char *dir = rt_test_temp_dir();
    write_tir_scene(rt_test_in_dir(dir, "tir.scn"), "0", "1");
    rt_scene *scene;
    rt_error error;
    ck_assert_int_eq(
        rt_scene_load(rt_test_in_dir(dir, "tir.scn"), NULL, &scene, &error),
        RT_OK);
    rt_render_options options;
    rt_render_options_init(&options);
    view_explanation e;
    ck_assert_int_eq(view_explain_pixel(scene, &options, "tir.scn", 4, 4, &e,
                                        &error), RT_OK);
    ck_assert_msg(strstr(e.text, "\n    totally reflected ray (weight 1) "
                                 "from "), "%s", e.text);
    ck_assert_msg(strstr(e.text, "refraction t C_T 10 20 30 = 10 20 30 "
                                 "(total internal reflection"), "%s", e.text);
    ck_assert_ptr_null(strstr(e.text, "    reflected ray"));
    view_explanation_release(&e);
    rt_scene_destroy(scene);
    rt_test_remove_dir(dir);
}
END_TEST
#endif

static Suite *terms_suite(void)
{
    Suite *s = suite_create("explain_terms");
    TCase *c = tcase_create("terms");
    tcase_set_timeout(c, 120);
    tcase_add_test(c, explain_names_a_total_internal_reflection_the_t_ct_term);
    tcase_add_test(c, explain_splits_the_mirror_ray_k_to_t_when_both_are_there);
    tcase_add_test(c, explain_of_an_opaque_mirror_is_unchanged);
    tcase_add_test(c, terms_add_up_to_what_each_hit_carries);
#if RT_TEST_HAVE_VIEWER
    tcase_add_test(c, viewer_names_a_total_internal_reflection_the_t_ct_term);
#endif
    suite_add_tcase(s, c);
    return s;
}

RT_CHECK_MAIN(terms_suite)
