/*
 * clock.h - the tests' monotonic clock, for deadlines and guards (how long a
 * test waits before it fails), never for a pass/fail timing.  Part of the
 * support library (tests/support/).
 */
#ifndef RAYTRACE_TEST_CLOCK_H
#define RAYTRACE_TEST_CLOCK_H

/* Seconds on CLOCK_MONOTONIC. */
double rt_test_now(void);

/* Sleeps `ms` milliseconds. */
void rt_test_sleep_ms(int ms);

#endif /* RAYTRACE_TEST_CLOCK_H */
