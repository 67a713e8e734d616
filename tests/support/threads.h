/*
 * threads.h - the threads of this process, to check that what a test
 * started has ended (a render's workers, a viewer's loader).  Part of the
 * support library (tests/support/).
 */
#ifndef RAYTRACE_TEST_THREADS_H
#define RAYTRACE_TEST_THREADS_H

/* Threads of this process, from /proc/self/task. */
int rt_test_thread_count(void);

/*
 * Threads once those that ended have gone: a joined (or detached and
 * returned) thread may be listed for a moment longer, so this waits up to
 * `seconds` for the count to come down to `expected`, and returns it.
 */
int rt_test_settled_thread_count(int expected, double seconds);

/*
 * Threads before a test starts any: after one thread has come and gone,
 * because ThreadSanitizer starts its own helper thread at the first
 * pthread_create, and that one stays.
 */
int rt_test_baseline_thread_count(void);

#endif /* RAYTRACE_TEST_THREADS_H */
