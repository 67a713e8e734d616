/*
 * suite.c - the mains of the suites and the paths of the project's files
 * (see suite.h).
 */
#include "suite.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "probe.h"

int rt_test_run_suite(Suite *suite)
{
    SRunner *runner = srunner_create(suite);
    srunner_run_all(runner, CK_NORMAL);
    int failed = srunner_ntests_failed(runner);
    srunner_free(runner);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

int rt_test_main_with_entry(int argc, char **argv, Suite *(*main_fn)(void),
                            const char *entry, Suite *(*entry_fn)(void),
                            const char *(*missing)(void))
{
    if (argc > 1 && strcmp(argv[1], entry) == 0) {
        const char *why = missing();
        if (why != NULL) {
            printf("%s: SKIPPED: %s\n", argv[0], why);
            return RT_TEST_SKIPPED;
        }
        return rt_test_run_suite(entry_fn());
    }
    return rt_test_run_suite(main_fn());
}

static const char *shared_missing(void)
{
    return rt_test_shared_path("") == NULL
               ? "../shared is absent, the course's scenes are not checked"
               : NULL;
}

int rt_test_main_with_shared(int argc, char **argv, Suite *(*main_fn)(void),
                             Suite *(*shared_fn)(void))
{
    return rt_test_main_with_entry(argc, argv, main_fn, "shared", shared_fn,
                                   shared_missing);
}

static const char *sources_missing(void)
{
    return rt_test_loader_lists_its_files()
               ? NULL
               : "the loader does not list the files a load read yet "
                 "(rt_scene_source_count is 0); the material-library cases "
                 "are not checked";
}

int rt_test_main_with_sources(int argc, char **argv,
                              Suite *(*main_fn)(void),
                              Suite *(*sources_fn)(void))
{
    return rt_test_main_with_entry(argc, argv, main_fn, "sources",
                                   sources_fn, sources_missing);
}

const char *rt_test_source_path(const char *relative)
{
    static char buffer[4096];
    snprintf(buffer, sizeof buffer, "%s/%s", RT_SOURCE_DIR, relative);
    return buffer;
}

const char *rt_test_shared_path(const char *relative)
{
    static char buffer[4096];
    struct stat st;
    if (stat(RT_SHARED_DIR, &st) != 0 || !S_ISDIR(st.st_mode))
        return NULL;
    snprintf(buffer, sizeof buffer, "%s/%s", RT_SHARED_DIR, relative);
    return buffer;
}
