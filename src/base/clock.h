/*
 * clock.h - the one clock the library times its work with (internal):
 * seconds on the monotonic clock, for durations only (the octree's build,
 * a render's wall-clock time), never for dates.
 */
#ifndef RAYTRACE_CLOCK_H
#define RAYTRACE_CLOCK_H

#include <time.h>

/* Seconds since an unspecified start on CLOCK_MONOTONIC: the difference of
 * two readings is the time between them, unaffected by changes to the
 * system's date.  Thread-safe. */
static inline double rt__clock_seconds(void)
{
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (double)now.tv_sec + (double)now.tv_nsec * 1e-9;
}

#endif /* RAYTRACE_CLOCK_H */
