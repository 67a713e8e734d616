/*
 * probe.h - what a suite asks about the world it runs in: a build with
 * AddressSanitizer, a run under valgrind, the reduced sizes of .ci/memcheck
 * (RT_TEST_MEMCHECK), python3 with its json module, a loader that lists the
 * files it read.  Part of the support library (tests/support/).
 */
#ifndef RAYTRACE_TEST_PROBE_H
#define RAYTRACE_TEST_PROBE_H

/* RT_TEST_UNDER_ASAN: 1 in a build with AddressSanitizer (which reserves
 * terabytes of address space; the programs the suites start run some 30
 * times slower there), else 0. */
#if defined(__SANITIZE_ADDRESS__)
#define RT_TEST_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RT_TEST_UNDER_ASAN 1
#endif
#endif
#ifndef RT_TEST_UNDER_ASAN
#define RT_TEST_UNDER_ASAN 0
#endif

/* Whether this process runs under valgrind (its preload libraries are in
 * LD_PRELOAD), which reserves far more address space than it uses. */
int rt_test_under_valgrind(void);

/* Whether RT_TEST_MEMCHECK is set to something other than "" or "0": the
 * suites run under valgrind (.ci/memcheck), and the sweeps send fewer rays
 * or build smaller inputs on the same code paths. */
int rt_test_memcheck(void);

/* Whether python3 and its json module are installed. */
int rt_test_have_python_json(void);

/* Whether the loader lists the files a load read (rt_scene_source_at): the
 * OBJ of tests/data/obj and its material library. */
int rt_test_loader_lists_its_files(void);

#endif /* RAYTRACE_TEST_PROBE_H */
