/*
 * test_memory.c - what a scene holds, and what a big load costs
 * (docs/performance.md, "Memory"): facets alike share one entry of the
 * scene's table of materials and read back as given; a facet record is
 * compact (its normal computed, not stored); the page-mapped arrays of a
 * kd-tree build keep their contents as they grow; and rt-export's
 * --stats reports the process's peak memory per facet, as text and as
 * JSON.
 */
#include <check.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/exact.h"
#include "base/pages.h"
#include "scene/scene_internal.h"
#include "testutil.h"

/* A .scn of an n x n grid of cells, two facets each, whose facets take
 * material (i % kinds) of three: grey, red mirror, glass. */
static char *grid_scene(int n, int kinds)
{
    rt_test_text t = {0};
    rt_test_text_add(&t, "0.5,0.5,3\n0.5,0.5,2,1.5,0.5,2,64,64\n%d\n",
                     (n + 1) * (n + 1));
    for (int j = 0; j <= n; j++)
        for (int i = 0; i <= n; i++)
            rt_test_text_add(&t, "%g,%g,0\n", (double)i / n, (double)j / n);
    rt_test_text_add(&t, "%d\n", 2 * n * n);
    /* a, b, c, k, R, G, B [, t [, n]] */
    static const char *const materials[] = {"0,128,128,128",
                                            "0.5,255,0,0",
                                            "0,200,200,255,0.5,1.5"};
    int facet = 0;
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            /* indices count from 1 */
            int a = j * (n + 1) + i + 1, b = a + 1, c = a + n + 1, d = c + 1;
            rt_test_text_add(&t, "%d,%d,%d,%s\n", a, b, d,
                             materials[facet++ % kinds]);
            rt_test_text_add(&t, "%d,%d,%d,%s\n", a, d, c,
                             materials[facet++ % kinds]);
        }
    rt_test_text_add(&t, "0,0,0\n0.5,0.5,5,255,255,255\n");
    return t.data;
}

START_TEST(a_mesh_in_one_material_stores_one_material)
{
    char *text = grid_scene(40, 1);
    rt_scene *scene = rt_test_scene_from_string(text);
    ck_assert_ptr_nonnull(scene);
    ck_assert_int_eq(scene->facet_count, 3200);
    ck_assert_int_eq(scene->materials.count, 1);
    /* a record is its corners, material, line and kind: 24 bytes, and
     * the scene's own records (vertices included) under 40 a facet */
    ck_assert_uint_eq(sizeof(rt_facet_record), 24);
    ck_assert_uint_lt(rt__scene_bytes(scene),
                      40 * (size_t)scene->facet_count + 4096);
    rt_scene_destroy(scene);
    free(text);
}
END_TEST

START_TEST(facets_alike_share_a_material_and_read_back_as_given)
{
    char *text = grid_scene(8, 3);
    rt_scene *scene = rt_test_scene_from_string(text);
    ck_assert_ptr_nonnull(scene);
    ck_assert_int_eq(scene->materials.count, 3);
    for (int i = 0; i < scene->facet_count; i++) {
        rt_facet_info f = {.size = sizeof f};
        rt_scene_facet(scene, i, &f);
        ck_assert_int_eq(scene->facets[i].material, i % 3);
        switch (i % 3) {
        case 0:
            ck_assert_int_eq(f.color.r, 128);
            ck_assert_double_eq(f.reflection, 0.0);
            ck_assert_double_eq(f.diffuse, 1.0);
            break;
        case 1:
            ck_assert_int_eq(f.color.g, 0);
            ck_assert_double_eq(f.reflection, 0.5);
            ck_assert_double_eq(f.diffuse, 0.5);
            break;
        default:
            ck_assert_double_eq(f.transparency, 0.5);
            ck_assert_double_eq(f.refractive_index, 1.5);
            break;
        }
        /* the normal, not stored, is the builder's own */
        rt_vec3 a = rt_scene_vertex(scene, f.vertex[0]),
                b = rt_scene_vertex(scene, f.vertex[1]),
                c = rt_scene_vertex(scene, f.vertex[2]);
        rt_vec3 n = rt__facet_normal(a, b, c);
        ck_assert(memcmp(&n, &f.normal, sizeof n) == 0);
        ck_assert_double_eq(f.normal.z, 1.0);
        ck_assert_int_eq(f.line, 4 + 81 + i + 1);
    }
    rt_scene_destroy(scene);
    free(text);
}
END_TEST

START_TEST(page_mapped_arrays_keep_their_contents_as_they_grow)
{
    uint32_t *a = NULL;
    size_t capacity = 0;
    void *p = NULL;
    for (uint32_t i = 0; i < 3000000; i++) {
        if (i == capacity) {
            size_t before = capacity;
            p = a;
            ck_assert(rt__pages_grow(&p, &capacity, (size_t)i + 1,
                                     sizeof *a));
            ck_assert_uint_ge(capacity, 2 * before);
            a = p;
        }
        a[i] = i * 2654435761u;
    }
    uint32_t wrong = 0;
    for (uint32_t i = 0; i < 3000000; i++)
        wrong += a[i] != i * 2654435761u;
    ck_assert_uint_eq(wrong, 0);
    /* growing to what it holds changes nothing */
    size_t held = capacity;
    ck_assert(rt__pages_grow(&p, &capacity, held, sizeof *a));
    ck_assert_uint_eq(capacity, held);
    ck_assert_ptr_eq(p, a);
    rt__pages_free(a, capacity, sizeof *a);
    rt__pages_free(NULL, 0, sizeof *a);
}
END_TEST

/* The number after `key` in `text`; -1 when absent. */
static double number_after(const char *text, const char *key)
{
    const char *at = strstr(text, key);
    return at != NULL ? strtod(at + strlen(key), NULL) : -1;
}

START_TEST(stats_report_the_peak_memory_per_facet)
{
    char *dir = rt_test_temp_dir();
    char *text = grid_scene(20, 2);
    char *scene = rt_test_join(dir, "grid.scn");
    rt_test_write_file(scene, text);
    free(scene);
    const char *const as_text[] = {"grid.scn", "-o", "a.ppm", "--stats",
                                   NULL};
    rt_test_output r = rt_test_run(dir, RT_EXPORT_PATH, as_text);
    ck_assert_int_eq(r.code, 0);
    /* "memory: peak X MB (Y bytes per facet of 800), Z MB by the end of
     * the load": Y is X over the facets, Z at most X */
    double peak = number_after(r.err, "memory: peak ");
    double per_facet = number_after(r.err, " MB (");
    double load = number_after(r.err, "facet of 800), ");
    ck_assert_msg(peak > 0 && load > 0 && load <= peak, "%s", r.err);
    /* both printed to one decimal: MB to 0.05e6 bytes */
    ck_assert_double_le(fabs(per_facet - peak * 1e6 / 800),
                        0.1 + 0.05e6 / 800);
    rt_test_output_free(&r);
    const char *const as_json[] = {"grid.scn", "-o", "b.ppm",
                                   "--stats=json", NULL};
    r = rt_test_run(dir, RT_EXPORT_PATH, as_json);
    ck_assert_int_eq(r.code, 0);
    double bytes = number_after(r.err, "\"memory\":{\"peak_bytes\":");
    ck_assert_msg(bytes > 1e6, "%s", r.err);
    ck_assert_double_eq(number_after(r.err, "\"facets\":"), 800);
    ck_assert_double_le(
        fabs(number_after(r.err, "\"peak_bytes_per_facet\":") - bytes / 800),
        1e-3 * bytes / 800);
    rt_test_output_free(&r);
    free(text);
    rt_test_remove_dir(dir);
}
END_TEST

static Suite *memory_suite(void)
{
    Suite *s = suite_create("memory");
    TCase *c = tcase_create("records");
    tcase_add_test(c, a_mesh_in_one_material_stores_one_material);
    tcase_add_test(c, facets_alike_share_a_material_and_read_back_as_given);
    tcase_add_test(c, page_mapped_arrays_keep_their_contents_as_they_grow);
    suite_add_tcase(s, c);
    c = tcase_create("stats");
    tcase_set_timeout(c, 60);
    tcase_add_test(c, stats_report_the_peak_memory_per_facet);
    suite_add_tcase(s, c);
    return s;
}

RT_CHECK_MAIN(memory_suite)
