/*
 * scenes.h - scenes for the tests: two small scenes as text, a scene held
 * in a C string loaded or refused (with the contract of a refusal
 * checked), the scene the viewer's suites edit and reload, a text grown
 * line by line to generate inputs, and a scene's info and warnings.  Part
 * of the support library (tests/support/); the functions fail the test
 * (Check) when they cannot do their job.
 */
#ifndef RAYTRACE_TEST_SCENES_H
#define RAYTRACE_TEST_SCENES_H

#include <stddef.h>

#include "raytrace/raytrace.h"

/* A scene of one facet, 40 x 30 pixels, every record on its own line, the
 * numbers separated by spaces. */
extern const char rt_test_small_scene[];

/* One facet filling the middle of a 40 x 30 image, one light, no warning,
 * no source file; the numbers separated by commas. */
extern const char rt_test_centred_facet_scene[];

/* Parses a scene held in a C string; fails the test with the loader's
 * message if it does not load. */
rt_scene *rt_test_scene_from_string(const char *text);

/* Loads the project's file `relative` (scenes/cubes.scn...); fails the
 * test, naming it, if it does not load. */
rt_scene *rt_test_load_source_scene(const char *relative);

/* Parses an OBJ held in a C string with `given` (NULL: the defaults), its
 * format set to OBJ; no name, so no .mtl is read unless the options'
 * resolver serves one.  The loader's status. */
rt_status rt_test_parse_obj(const char *text, const rt_load_options *given,
                            rt_scene **scene, rt_error *error);

/* Parses `text` (named hostile.scn), which must be refused: no scene, the
 * error's status the one returned, a message; returns the status. */
rt_status rt_test_parse_refused(const char *text, size_t length,
                                rt_error *error);

/* Writes a 64 x 48 scene of two facets with the background `background`
 * ("R, G, B") to `path` (the viewer's suites edit and reload it). */
void rt_test_write_two_facet_scene(const char *path, const char *background);

/* A scene's info as a value. */
rt_scene_info rt_test_scene_info(const rt_scene *scene);

/* The warnings of `scene` whose message holds `words`. */
int rt_test_count_warnings(const rt_scene *scene, const char *words);

/* A growing text, NUL-terminated once anything was added (zeroed to
 * start; free `data` when done). */
typedef struct rt_test_text {
    char *data;
    size_t length, capacity;
} rt_test_text;

/* Appends printf's output, of any length. */
void rt_test_text_add(rt_test_text *text, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

#endif /* RAYTRACE_TEST_SCENES_H */
