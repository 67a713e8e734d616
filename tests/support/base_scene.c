/*
 * base_scene.c - the base scene of the `.scn` parse suites (see
 * base_scene.h).
 */
#include "base_scene.h"

#include <check.h>
#include <stdio.h>

/* The base scene, one record per line (line numbers in comments).  Columns
 * of its tokens are used by the cases of test_parse.c. */
static const char *const base_lines[] = {
    "0 0 5",                  /* 1  observer */
    "0 0 4 1 0 0 2 2",        /* 2  screen: cols 1 3 5 7 9 11 13 15 */
    "3",                      /* 3  vertex count */
    "-1 -1 0",                /* 4 */
    "1 -1 0",                 /* 5 */
    "0 1 0",                  /* 6 */
    "1",                      /* 7  facet count */
    "1 2 3 0 255 0 0",        /* 8  facet: cols 1 3 5 7 9 13 15 */
    "10 20 30",               /* 9  background: cols 1 4 7 */
    "0 0 10 255 255 255",     /* 10 light: cols 1 3 5 8 12 16 */
};
#define BASE_LINE_COUNT 10

void rt_test_base_scene(char *buffer, size_t size, int replace,
                        const char *replacement, int keep,
                        const char *append, const char *eol)
{
    buffer[0] = '\0';
    size_t used = 0;
    for (int i = 0; i < BASE_LINE_COUNT; i++) {
        if (keep >= 0 && i >= keep)
            break;
        const char *line = i + 1 == replace ? replacement : base_lines[i];
        int n = snprintf(buffer + used, size - used, "%s%s", line, eol);
        ck_assert(n > 0 && (size_t)n < size - used);
        used += (size_t)n;
    }
    if (append) {
        int n = snprintf(buffer + used, size - used, "%s", append);
        ck_assert(n >= 0 && (size_t)n < size - used);
    }
}

void rt_test_assert_base_scene(const rt_scene *scene)
{
    rt_scene_info info = {.size = sizeof info};
    rt_scene_get_info(scene, &info);
    ck_assert_int_eq(info.width, 2);
    ck_assert_int_eq(info.height, 2);
    ck_assert_int_eq(info.vertex_count, 3);
    ck_assert_int_eq(info.facet_count, 1);
    ck_assert_int_eq(info.live_facet_count, 1);
    ck_assert_int_eq(info.warning_count, 0);
    ck_assert_int_eq(info.background.r, 10);
    ck_assert_int_eq(info.background.g, 20);
    ck_assert_int_eq(info.background.b, 30);
    ck_assert_int_eq(info.light_count, 1);
    rt_light light;
    rt_scene_light(scene, 0, &light);
    ck_assert_double_eq(light.position.z, 10.0);
    ck_assert_int_eq(light.color.g, 255);
    ck_assert_double_eq(info.camera.observer.z, 5.0);
    ck_assert_double_eq(info.camera.screen_center.z, 4.0);
    ck_assert_double_eq(info.camera.right.x, 1.0);
    rt_vec3 v = rt_scene_vertex(scene, 0);
    ck_assert_double_eq(v.x, -1.0);
    ck_assert_double_eq(v.y, -1.0);
    ck_assert_double_eq(v.z, 0.0);
    v = rt_scene_vertex(scene, 2);
    ck_assert_double_eq(v.x, 0.0);
    ck_assert_double_eq(v.y, 1.0);
    rt_facet_info facet = {.size = sizeof facet};
    rt_scene_facet(scene, 0, &facet);
    ck_assert_int_eq(facet.vertex[0], 0);
    ck_assert_int_eq(facet.vertex[1], 1);
    ck_assert_int_eq(facet.vertex[2], 2);
    ck_assert_double_eq(facet.reflection, 0.0);
    ck_assert_int_eq(facet.color.r, 255);
    ck_assert_int_eq(facet.color.g, 0);
    ck_assert_int_eq(facet.degenerate, 0);
    /* (b-a)x(c-a) = (2,0,0)x(1,2,0) = (0,0,4): unit (0,0,1), tol 1e-15 */
    ck_assert_double_eq_tol(facet.normal.z, 1.0, 1e-15);
}
