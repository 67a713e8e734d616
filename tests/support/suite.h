/*
 * suite.h - how a Check suite of the project runs: its main (one suite, or a
 * suite and a second entry that ctest runs apart), the exit status of a
 * visible skip, and the paths of the project's files and of the course's
 * scenes (../shared).  Part of the support library (tests/support/).
 */
#ifndef RAYTRACE_TEST_SUITE_H
#define RAYTRACE_TEST_SUITE_H

#include <check.h>

/* ctest's SKIP_RETURN_CODE for a check whose input is absent. */
#define RT_TEST_SKIPPED 77

/* Runs `suite` (taking it) and returns EXIT_SUCCESS when no test failed. */
int rt_test_run_suite(Suite *suite);

#define RT_CHECK_MAIN(suite_fn)                                              \
    int main(void) { return rt_test_run_suite(suite_fn()); }

/* The main of a suite with a second ctest entry: `prog` runs main_fn's
 * suite; `prog <entry>` runs entry_fn's, or, when `missing()` gives a
 * reason (its input is absent), prints "<prog>: SKIPPED: <reason>" and
 * exits RT_TEST_SKIPPED, a skip ctest shows (SKIP_RETURN_CODE 77). */
int rt_test_main_with_entry(int argc, char **argv, Suite *(*main_fn)(void),
                            const char *entry, Suite *(*entry_fn)(void),
                            const char *(*missing)(void));

/* The main of a suite whose checks on the course's scenes (../shared) are a
 * ctest entry of their own: `prog` runs main_fn's suite; `prog shared` runs
 * shared_fn's suite, or exits RT_TEST_SKIPPED when ../shared is absent. */
int rt_test_main_with_shared(int argc, char **argv, Suite *(*main_fn)(void),
                             Suite *(*shared_fn)(void));

#define RT_CHECK_MAIN_WITH_SHARED(main_fn, shared_fn)                        \
    int main(int argc, char **argv)                                          \
    {                                                                        \
        return rt_test_main_with_shared(argc, argv, main_fn, shared_fn);     \
    }

/* The main of a suite with a `sources` entry: `prog` runs main_fn's suite;
 * `prog sources` runs sources_fn's, or exits RT_TEST_SKIPPED while the
 * loader lists no files (rt_test_loader_lists_its_files). */
int rt_test_main_with_sources(int argc, char **argv,
                              Suite *(*main_fn)(void),
                              Suite *(*sources_fn)(void));

/* "<source dir>/<relative>" in a static buffer (one at a time). */
const char *rt_test_source_path(const char *relative);

/* "<source dir>/../shared/<relative>", or NULL when ../shared is absent. */
const char *rt_test_shared_path(const char *relative);

#endif /* RAYTRACE_TEST_SUITE_H */
