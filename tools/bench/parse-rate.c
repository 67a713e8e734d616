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
 *     FILE BYTES parse SECONDS MB/s load SECONDS MB/s
 * with MB = 10^6 bytes.  --no-build, for a profiler (perf record): the
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

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* The time spent in rt__reader_finish during the current load. */
static double finish_seconds;
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
    double start = now();
    rt_status status = __real_rt__reader_finish(desc, reading, scene, error);
    finish_seconds += now() - start;
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
    double best_parse = 1e300, best_load = 1e300;
    for (int i = 0; i < runs; i++) {
        rt_scene *scene;
        rt_error error;
        finish_seconds = 0;
        double start = now();
        rt_status status = rt_scene_load(argv[1], NULL, &scene, &error);
        double load = now() - start;
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
    }
    double mb = (double)st.st_size / 1e6;
    if (no_build) {
        printf("%s %lld parse %.3f s %.0f MB/s\n", argv[1],
               (long long)st.st_size, best_parse, mb / best_parse);
        return 0;
    }
    printf("%s %lld parse %.3f s %.0f MB/s load %.3f s %.0f MB/s\n", argv[1],
           (long long)st.st_size, best_parse, mb / best_parse, best_load,
           mb / best_load);
    return 0;
}
