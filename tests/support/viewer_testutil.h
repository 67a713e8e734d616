/*
 * viewer_testutil.h - what the viewer's test suites (test_viewer.c,
 * test_viewer_load.c) share: the clock, the threads of the process, and the
 * small scene they edit and reload.
 */
#ifndef VIEWER_TESTUTIL_H
#define VIEWER_TESTUTIL_H

/* Monotonic seconds. */
double viewer_now_seconds(void);

void viewer_sleep_ms(int ms);

/* Threads of this process, from /proc/self/task. */
int viewer_thread_count(void);

/*
 * Threads once those that ended have gone: a joined (or detached and
 * returned) thread may be listed for a moment longer, so this waits up to
 * `seconds` for the count to come down to `expected`, and returns it.
 */
int viewer_settled_thread_count(int expected, double seconds);

/*
 * Threads before a test starts any: after one thread has come and gone,
 * because ThreadSanitizer starts its own helper thread at the first
 * pthread_create, and that one stays.
 */
int viewer_baseline_thread_count(void);

/* Writes a 64x48 scene of two facets with the background `background`
 * ("R, G, B") to `path`. */
void viewer_write_scene(const char *path, const char *background);

#endif /* VIEWER_TESTUTIL_H */
