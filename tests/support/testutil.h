/*
 * testutil.h - the support library of the test suites (tests/support/, the
 * static library raytrace_test_support every suite links), in one include:
 *
 *   suite.h     a suite's main, visible skips (77), the project's paths
 *   probe.h     AddressSanitizer, valgrind, RT_TEST_MEMCHECK, python3
 *   files.h     temporary folders, paths, whole files, folder listings
 *   programs.h  the project's programs run as a user runs them
 *   child.h     jobs in forked children (safe under CK_FORK=no)
 *   clock.h     a monotonic clock for deadlines and guards
 *   threads.h   the threads of this process
 *   rng.h       the one random number generator (splitmix64)
 *   scenes.h    scenes as text, loads and refusals, info and warnings
 *   images.h    renders, image differences, patterns, encoded bytes
 *
 * Every name it exports starts with rt_test_ (RT_TEST_ for macros), so a
 * suite's own static helpers never collide with it.
 */
#ifndef RAYTRACE_TESTUTIL_H
#define RAYTRACE_TESTUTIL_H

#include <check.h>

#include "raytrace/raytrace.h"

#include "child.h"
#include "clock.h"
#include "files.h"
#include "images.h"
#include "probe.h"
#include "programs.h"
#include "rng.h"
#include "scenes.h"
#include "suite.h"
#include "threads.h"

#endif /* RAYTRACE_TESTUTIL_H */
