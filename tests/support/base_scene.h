/*
 * base_scene.h - the `.scn` base scene of the parse suites (test_parse.c,
 * test_parse_accepts.c): ten records, one per line, whose tokens' columns
 * the cases of broken rules name; built with one line replaced, cut short
 * or followed by more, with any line ending; and the check that a loaded
 * scene is exactly it.  Part of the support library (tests/support/), not
 * of testutil.h; its functions fail the test (Check) when they cannot do
 * their job.
 */
#ifndef RAYTRACE_TEST_BASE_SCENE_H
#define RAYTRACE_TEST_BASE_SCENE_H

#include <stddef.h>

#include "raytrace/raytrace.h"

/* rt_test_base_scene's `keep` for every line. */
#define RT_TEST_BASE_ALL -1

/* Builds the base scene into `buffer` with line `replace` (1-based, 0 for
 * none) replaced by `replacement`, only the first `keep` lines (all when
 * keep < 0), then `append` (NULL: nothing); lines end with `eol`. */
void rt_test_base_scene(char *buffer, size_t size, int replace,
                        const char *replacement, int keep,
                        const char *append, const char *eol);

/* Fails the test unless `scene` is the base scene: 2 x 2, three vertices,
 * one facet, its colours, camera and light, no warning. */
void rt_test_assert_base_scene(const rt_scene *scene);

#endif /* RAYTRACE_TEST_BASE_SCENE_H */
