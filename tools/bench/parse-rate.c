/*
 * parse-rate.c - the reading time of a scene file, split in two: the whole
 * load (rt_scene_load: the file read, its checks, the tokens and numbers,
 * the reader's arrays, then the scene build) and the parse alone (all of
 * it but the build).  tools/bench/parse-rate.sh compiles it against a
 * build's static libraytrace.a, linked with -Wl,--wrap=rt__reader_finish:
 * every reader ends with rt__reader_finish (src/formats/reader.h), which
 * applies the options and builds the scene, so the time spent inside it
 * is the build and the rest is the parse.  Nothing of the library changes
 * for the measure; the same source measures any build of the project
 * that has that function.
 *
 *     parse-rate [--no-build] FILE [RUNS]
 *
 * prints, for the least of RUNS (default 3) loads,
 *     FILE BYTES parse SECONDS MB/s load SECONDS MB/s cpu SECONDS MB/s
 * with MB = 10^6 bytes: wall-clock times, and last the parse's processor
 * time (the parse runs on one thread; the build's threads are left out),
 * which others' work on a busy machine changes less.  --no-build, for a profiler (perf record): the
 * build is skipped (the wrapped function refuses the load instead), so
 * the profile is the parse's alone; only the parse is printed.  A
 * benchmark tool, not a test, and not installed.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "formats/reader.h"
#include "raytrace/raytrace.h"

static double clock_seconds(clockid_t id)
{
    struct timespec t;
    clock_gettime(id, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static double now(void)
{
    return clock_seconds(CLOCK_MONOTONIC);
}

/* The process's processor time (all its threads). */
static double cpu(void)
{
    return clock_seconds(CLOCK_PROCESS_CPUTIME_ID);
}

/* The time (and the processor time) spent in rt__reader_finish during
 * the current load. */
static double finish_seconds, finish_cpu;
/* --no-build: rt__reader_finish refuses the load without building. */
static int no_build;

rt_status __real_rt__reader_finish(rt_scene_desc *desc,
                                   const rt_reading *reading,
                                   rt_scene **scene, rt_error *error);
rt_status __wrap_rt__reader_finish(rt_scene_desc *desc,
                                   const rt_reading *reading,
                                   rt_scene **scene, rt_error *error);

rt_status __wrap_rt__reader_finish(rt_scene_desc *desc,
                                   const rt_reading *reading,
                                   rt_scene **scene, rt_error *error)
{
    if (no_build)
        return RT_ERR_CANCELLED;
    double start = now(), start_cpu = cpu();
    rt_status status = __real_rt__reader_finish(desc, reading, scene, error);
    finish_seconds += now() - start;
    finish_cpu += cpu() - start_cpu;
    return status;
}

int main(int argc, char **argv)
{
    if (argc > 1 && strcmp(argv[1], "--no-build") == 0) {
        no_build = 1;
        argv++, argc--;
    }
    if (argc < 2 || argc > 3) {
        fprintf(stderr, "usage: parse-rate [--no-build] FILE [RUNS]\n");
        return 2;
    }
    int runs = argc == 3 ? atoi(argv[2]) : 3;
    struct stat st;
    if (runs < 1 || stat(argv[1], &st) != 0) {
        fprintf(stderr, "parse-rate: cannot read %s\n", argv[1]);
        return 2;
    }
    double best_parse = 1e300, best_load = 1e300, best_cpu = 1e300;
    for (int i = 0; i < runs; i++) {
        rt_scene *scene;
        rt_error error;
        finish_seconds = finish_cpu = 0;
        double start = now(), start_cpu = cpu();
        rt_status status = rt_scene_load(argv[1], NULL, &scene, &error);
        double load = now() - start, parse_cpu = cpu() - start_cpu - finish_cpu;
        if (no_build && status == RT_ERR_CANCELLED)
            status = RT_OK, scene = NULL;
        if (status != RT_OK) {
            fprintf(stderr, "parse-rate: %s\n", error.message);
            return 1;
        }
        rt_scene_destroy(scene);
        if (load - finish_seconds < best_parse)
            best_parse = load - finish_seconds;
        if (load < best_load)
            best_load = load;
        if (parse_cpu < best_cpu)
            best_cpu = parse_cpu;
    }
    double mb = (double)st.st_size / 1e6;
    printf("%s %lld parse %.3f s %.0f MB/s", argv[1], (long long)st.st_size,
           best_parse, mb / best_parse);
    if (!no_build)
        printf(" load %.3f s %.0f MB/s", best_load, mb / best_load);
    printf(" cpu %.3f s %.0f MB/s\n", best_cpu, mb / best_cpu);
    return 0;
}
