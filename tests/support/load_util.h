/*
 * load_util.h - what the suites of a load's costs share
 * (test_load_budgets.c, test_load_warnings.c): a text grown line by line
 * to generate inputs, a scene's info as a value, and the count of its
 * warnings that hold some words.
 */
#ifndef RAYTRACE_TESTS_LOAD_UTIL_H
#define RAYTRACE_TESTS_LOAD_UTIL_H

#include <stddef.h>

#include "raytrace/raytrace.h"

/* A growing text (malloc'd; free data). */
typedef struct load_text {
    char *data;
    size_t length, capacity;
} load_text;

/* Appends printf's output (at most 255 bytes); fails the test when out of
 * memory. */
void load_text_add(load_text *t, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

rt_scene_info load_info(const rt_scene *scene);

/* The warnings of `scene` whose message holds `words`. */
int load_count_warnings(const rt_scene *scene, const char *words);

#endif /* RAYTRACE_TESTS_LOAD_UTIL_H */
