/*
 * cli_clock.h - the one clock of the programs (apps/) and the research
 * tools (tools/): the seconds of CLOCK_MONOTONIC as a double, for the
 * times the programs report (load, render, write, the progress line, a
 * band's busy time) and the tools measure.  A monotonic clock never jumps
 * when the system time is set; its origin is arbitrary, so only the
 * difference of two readings means anything.  At the uptimes of real
 * machines a double resolves it to well under a microsecond.
 *
 * Header-only (two static inline functions) so that a tool built without
 * the programs' library (tools/rt-perf, with RAYTRACE_BENCH alone) uses the
 * same clock.  The library times its renders with its own clock
 * (src/base/), which is not API.  Thread-safe.
 */
#ifndef RAYTRACE_CLI_CLOCK_H
#define RAYTRACE_CLI_CLOCK_H

#include <time.h>

/* Now, in seconds from the clock's arbitrary origin. */
static inline double cli_clock_seconds(void)
{
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (double)now.tv_sec + (double)now.tv_nsec * 1e-9;
}

/* The seconds elapsed since `start`, a reading of cli_clock_seconds. */
static inline double cli_seconds_since(double start)
{
    return cli_clock_seconds() - start;
}

#endif /* RAYTRACE_CLI_CLOCK_H */
