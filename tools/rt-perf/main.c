/*
 * rt-perf - the speed benchmark of docs/performance.md.
 *
 * Renders a fixed list of scenes - the project's cubes and mirror scenes at
 * 400x400 and 1920x1080, the SPD scenes at 400x400, and generated meshes (a
 * tessellated sphere and a random soup of about 1,000 to 1,000,000 facets) -
 * with nine renderer settings in the same run: brute force with the plain
 * scalar loops and with the fast kernel, in double and in float, the fast
 * kernel on one thread and on all; and the octree on one thread
 * and on all.  Entries marked octree-only (the biggest meshes at 400x400,
 * where brute force would take hours) run the octree settings alone.
 * Each is timed as the median of N renders (default 5, the settings taking
 * turns so that a change of load affects them alike); the program prints
 * Markdown tables of Mrays/s, G ray-facet tests/s and the ratios, and checks
 * that every setting of one precision gives the same image, byte for byte.
 * A last table is the per-ray budget of the fast kernel on one thread: rays
 * by kind, tests per ray, nanoseconds per ray and, where the kernel lets a
 * process read the hardware counters (Linux perf_event_open), cycles and
 * instructions per ray; elsewhere those columns say n/a (use
 * `valgrind --tool=callgrind` for instruction counts then).
 *
 * A program, not a test: it takes minutes.  Run it on an idle machine.
 */
#if defined(__linux__) && !defined(_DEFAULT_SOURCE)
#define _DEFAULT_SOURCE     /* syscall(), for perf_event_open */
#endif
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#if defined(__linux__)
#include <linux/perf_event.h>
#include <sys/ioctl.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

#include "bench_scenes.h"
#include "cli_clock.h"
#include "raytrace/raytrace.h"

#define MAX_RUNS 101

typedef enum { FROM_FILE, SPHERE, SOUP } scene_kind;

typedef struct entry {
    const char *name;
    scene_kind kind;
    const char *path;       /* FROM_FILE: relative to its directory */
    int shared;             /* FROM_FILE: in the SPD directory */
    int facets;             /* generated scenes */
    int width, height;
    int octree_only;        /* too big for brute force at this size (2: and
                               run only when --only names it) */
} entry;

/* Image sizes keep the scalar renders of the big scenes to seconds. */
static const entry entries[] = {
    {"cubes", FROM_FILE, "scenes/cubes.scn", 0, 0, 400, 400, 0},
    {"cubes", FROM_FILE, "scenes/cubes.scn", 0, 0, 1920, 1080, 0},
    {"mirror", FROM_FILE, "scenes/mirror.scn", 0, 0, 400, 400, 0},
    {"mirror", FROM_FILE, "scenes/mirror.scn", 0, 0, 1920, 1080, 0},
    {"tetra-s2", FROM_FILE, "tetra-s2.scn", 1, 0, 400, 400, 0},
    {"tetra-s4", FROM_FILE, "tetra-s4.scn", 1, 0, 400, 400, 0},
    {"teapot-s2", FROM_FILE, "teapot-s2.scn", 1, 0, 400, 400, 0},
    {"mount-s2", FROM_FILE, "mount-s2.scn", 1, 0, 400, 400, 0},
    {"tetra-s6", FROM_FILE, "tetra-s6.scn", 1, 0, 400, 400, 0},
    {"gears-s2", FROM_FILE, "gears-s2.scn", 1, 0, 400, 400, 0},
    {"balls-s2", FROM_FILE, "balls-s2.scn", 1, 0, 400, 400, 0},
    {"sphere-1k", SPHERE, NULL, 0, 1000, 256, 256, 0},
    {"sphere-10k", SPHERE, NULL, 0, 10000, 128, 128, 0},
    {"sphere-100k", SPHERE, NULL, 0, 100000, 64, 64, 0},
    {"sphere-1M", SPHERE, NULL, 0, 1000000, 32, 32, 0},
    {"soup-1k", SOUP, NULL, 0, 1000, 256, 256, 0},
    {"soup-10k", SOUP, NULL, 0, 10000, 128, 128, 0},
    {"soup-100k", SOUP, NULL, 0, 100000, 64, 64, 0},
    {"soup-1M", SOUP, NULL, 0, 1000000, 32, 32, 0},
    {"sphere-100k", SPHERE, NULL, 0, 100000, 400, 400, 1},
    {"sphere-1M", SPHERE, NULL, 0, 1000000, 400, 400, 1},
    {"soup-1M", SOUP, NULL, 0, 1000000, 400, 400, 1},
    {"big-sphere-5M", SPHERE, NULL, 0, 5000000, 400, 400, 2},
};
#define ENTRY_COUNT ((int)(sizeof entries / sizeof entries[0]))

/* The settings, in the order of the tables; the octree's last. */
typedef struct setting {
    const char *name;
    rt_precision precision;
    rt_kernel_choice kernel;
    int threads;            /* 0: all */
    rt_accel accel;
} setting;

static const setting settings[] = {
    {"scalar double", RT_PRECISION_DOUBLE, RT_KERNEL_SCALAR, 1, RT_ACCEL_NONE},
    {"fast double 1t", RT_PRECISION_DOUBLE, RT_KERNEL_AUTO, 1, RT_ACCEL_NONE},
    {"fast double all", RT_PRECISION_DOUBLE, RT_KERNEL_AUTO, 0, RT_ACCEL_NONE},
    {"scalar float", RT_PRECISION_FLOAT, RT_KERNEL_SCALAR, 1, RT_ACCEL_NONE},
    {"fast float 1t", RT_PRECISION_FLOAT, RT_KERNEL_AUTO, 1, RT_ACCEL_NONE},
    {"fast float all", RT_PRECISION_FLOAT, RT_KERNEL_AUTO, 0, RT_ACCEL_NONE},
    {"octree double 1t", RT_PRECISION_DOUBLE, RT_KERNEL_AUTO, 1,
     RT_ACCEL_OCTREE},
    {"octree double all", RT_PRECISION_DOUBLE, RT_KERNEL_AUTO, 0,
     RT_ACCEL_OCTREE},
    {"octree float all", RT_PRECISION_FLOAT, RT_KERNEL_AUTO, 0,
     RT_ACCEL_OCTREE},
};
#define SETTING_COUNT 9
#define FIRST_OCTREE 6

typedef struct result {
    double times[MAX_RUNS];
    double cycles[MAX_RUNS], instructions[MAX_RUNS];    /* < 0: no counter */
    double seconds;         /* median */
    double median_cycles, median_instructions;
    rt_render_stats stats;  /* of the last run */
} result;

static int compare_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static rt_status make_scene(const entry *e, const char *shared_dir,
                            rt_scene **scene, rt_error *error)
{
    if (e->kind == SPHERE)
        return bench_sphere(e->facets, e->width, e->height, scene, error);
    if (e->kind == SOUP)
        return bench_soup(e->facets, e->width, e->height, scene, error);
    char path[8192];
    int length = snprintf(path, sizeof path, "%s/%s",
                          e->shared ? shared_dir : RT_SOURCE_DIR, e->path);
    if (length < 0 || (size_t)length >= sizeof path)
        return RT_ERR_ARGUMENT;
    /* Rendered at the entry's size through the render options. */
    return rt_scene_load(path, NULL, scene, error);
}

/* A hardware counter of this process's threads (those it starts later
 * included), or -1 where the kernel does not give one. */
static int counter_open(uint64_t config)
{
#if defined(__linux__)
    struct perf_event_attr attr;
    memset(&attr, 0, sizeof attr);
    attr.size = sizeof attr;
    attr.type = PERF_TYPE_HARDWARE;
    attr.config = config;
    attr.disabled = 1;
    attr.inherit = 1;
    attr.exclude_kernel = 1;
    attr.exclude_hv = 1;
    return (int)syscall(SYS_perf_event_open, &attr, 0, -1, -1, 0);
#else
    (void)config;
    return -1;
#endif
}

static void counter_start(int fd)
{
#if defined(__linux__)
    if (fd >= 0) {
        ioctl(fd, PERF_EVENT_IOC_RESET, 0);
        ioctl(fd, PERF_EVENT_IOC_ENABLE, 0);
    }
#else
    (void)fd;
#endif
}

/* The count since counter_start, or -1. */
static double counter_stop(int fd)
{
#if defined(__linux__)
    uint64_t value;
    if (fd >= 0) {
        ioctl(fd, PERF_EVENT_IOC_DISABLE, 0);
        if (read(fd, &value, sizeof value) == (ssize_t)sizeof value)
            return (double)value;
    }
#else
    (void)fd;
#endif
    return -1.0;
}

/* Renders once with setting *s and adds the time to r->times; 0 on
 * failure. */
static int measure_once(const rt_scene *scene, const setting *s,
                        rt_image *image, result *r, int run)
{
    rt_render_options options;
    rt_render_options_init(&options);
    options.precision = s->precision;
    options.kernel = s->kernel;
    options.threads = s->threads;
    options.accel = s->accel;
    r->stats.size = sizeof r->stats;
    options.stats = &r->stats;
    options.width = image->width;
    options.height = image->height;
    int cycles = counter_open(PERF_COUNT_HW_CPU_CYCLES);
    int instructions = counter_open(PERF_COUNT_HW_INSTRUCTIONS);
    counter_start(cycles);
    counter_start(instructions);
    double start = cli_clock_seconds();
    rt_status status = rt_render(scene, &options, image, NULL);
    r->times[run] = cli_seconds_since(start);
    r->cycles[run] = counter_stop(cycles);
    r->instructions[run] = counter_stop(instructions);
#if defined(__linux__)
    if (cycles >= 0)
        close(cycles);
    if (instructions >= 0)
        close(instructions);
#endif
    if (status != RT_OK) {
        fprintf(stderr, "\nrt-perf: %s: %s\n", s->name,
                rt_status_string(status));
        return 0;
    }
    return 1;
}

static int same_pixels(const rt_image *a, const rt_image *b)
{
    for (int y = 0; y < a->height; y++)
        if (memcmp(rt_image_pixel(a, 0, y), rt_image_pixel(b, 0, y),
                   (size_t)a->width * 3) != 0)
            return 0;
    return 1;
}

static void usage(void)
{
    fprintf(stderr,
            "usage: rt-perf [--runs N] [--only NAME] [--spd DIR]\n"
            "  --runs N    renders per setting, the median is kept "
            "(default 5)\n"
            "  --only NAME only the scenes whose name starts with NAME\n"
            "              (big-sphere-5M, 5,000,000 facets, runs only so)\n"
            "  --spd DIR   the SPD scenes (default %s/spd-scenes)\n"
            "  --no-scalar leave out the scalar settings (minutes on the "
            "big scenes)\n",
            RT_SHARED_DIR);
}

int main(int argc, char **argv)
{
    int runs = 5, skip_scalar = 0;
    const char *only = NULL;
    char spd[4096];
    snprintf(spd, sizeof spd, "%s/spd-scenes", RT_SHARED_DIR);
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--runs") && i + 1 < argc) {
            runs = atoi(argv[++i]);
        } else if (!strcmp(argv[i], "--only") && i + 1 < argc) {
            only = argv[++i];
        } else if (!strcmp(argv[i], "--no-scalar")) {
            skip_scalar = 1;
        } else if (!strcmp(argv[i], "--spd") && i + 1 < argc) {
            snprintf(spd, sizeof spd, "%s", argv[++i]);
        } else {
            usage();
            return 2;
        }
    }
    if (runs < 1 || runs > MAX_RUNS) {
        usage();
        return 2;
    }

    static result results[ENTRY_COUNT][SETTING_COUNT];
    static int done[ENTRY_COUNT], identical[ENTRY_COUNT], facets[ENTRY_COUNT];
    int failures = 0;
    for (int e = 0; e < ENTRY_COUNT; e++) {
        const entry *en = &entries[e];
        if (only != NULL && strncmp(en->name, only, strlen(only)) != 0)
            continue;
        if (en->octree_only == 2 && only == NULL)
            continue;
        rt_scene *scene;
        rt_error error;
        if (make_scene(en, spd, &scene, &error) != RT_OK) {
            fprintf(stderr, "rt-perf: %s: %s (skipped)\n", en->name,
                    error.message);
            continue;
        }
        rt_scene_info info = {.size = sizeof info};
        rt_scene_get_info(scene, &info);
        facets[e] = info.live_facet_count;
        rt_image images[SETTING_COUNT] = {{0}};
        int ok = 1, first = en->octree_only ? FIRST_OCTREE : 0;
        for (int s = first; s < SETTING_COUNT && ok; s++)
            ok = rt_image_init(&images[s], en->width, en->height,
                               NULL) == RT_OK;
        /* round robin, so that a change of load on the machine hits every
         * setting alike */
        for (int run = 0; run < runs && ok; run++) {
            fprintf(stderr, "\r%-12s %4dx%-4d run %d of %d ", en->name,
                    en->width, en->height, run + 1, runs);
            for (int s = first; s < SETTING_COUNT && ok; s++)
                if (!skip_scalar || settings[s].kernel != RT_KERNEL_SCALAR)
                    ok = measure_once(scene, &settings[s], &images[s],
                                      &results[e][s], run);
        }
        for (int s = first; s < SETTING_COUNT && ok; s++) {
            result *r = &results[e][s];
            qsort(r->times, (size_t)runs, sizeof r->times[0], compare_double);
            r->seconds = r->times[runs / 2];
            qsort(r->cycles, (size_t)runs, sizeof r->cycles[0],
                  compare_double);
            r->median_cycles = r->cycles[runs / 2];
            qsort(r->instructions, (size_t)runs, sizeof r->instructions[0],
                  compare_double);
            r->median_instructions = r->instructions[runs / 2];
        }
        if (ok) {
            done[e] = 1;
            identical[e] =
                en->octree_only
                    ? same_pixels(&images[6], &images[7])
                    : same_pixels(&images[1], &images[2]) &&
                          same_pixels(&images[4], &images[5]) &&
                          same_pixels(&images[1], &images[6]) &&
                          same_pixels(&images[1], &images[7]) &&
                          same_pixels(&images[4], &images[8]) &&
                          (skip_scalar ||
                           (same_pixels(&images[0], &images[1]) &&
                            same_pixels(&images[3], &images[4])));
            failures += !identical[e];
        } else {
            fprintf(stderr, "\nrt-perf: %s: rendering failed\n", en->name);
            failures++;
        }
        for (int s = 0; s < SETTING_COUNT; s++)
            rt_image_release(&images[s]);
        rt_scene_destroy(scene);
    }
    fprintf(stderr, "\r%60s\r", "");

    printf("Median of %d renders.  Rates: Mrays/s (all rays: camera, shadow, "
           "reflection) / G ray-facet tests/s.\n\n", runs);
    printf("| scene | facets | image |");
    for (int s = 0; s < SETTING_COUNT; s++)
        printf(" %s |", settings[s].name);
    printf("\n|---|--:|--:|");
    for (int s = 0; s < SETTING_COUNT; s++)
        printf("--:|");
    printf("\n");
    for (int e = 0; e < ENTRY_COUNT; e++) {
        if (!done[e])
            continue;
        printf("| %s | %d | %dx%d |", entries[e].name, facets[e],
               entries[e].width, entries[e].height);
        for (int s = 0; s < SETTING_COUNT; s++) {
            const result *r = &results[e][s];
            if ((entries[e].octree_only && s < FIRST_OCTREE) ||
                (skip_scalar && settings[s].kernel == RT_KERNEL_SCALAR))
                printf(" - |");
            else
                printf(" %.2f / %.3f |",
                       rt_render_stats_rays(&r->stats) / r->seconds * 1e-6,
                       r->stats.ray_facet_tests / r->seconds * 1e-9);
        }
        printf("\n");
    }

    printf("\nRatios of render times (higher is faster); `same image`: the "
           "three settings of each precision gave identical bytes.\n\n");
    printf("| scene | image | fast/scalar double (1 thread) | "
           "fast float/scalar double (1 thread) | fast/scalar float "
           "(1 thread) | all/1 thread double | all/1 thread float | "
           "same image |\n|---|--:|--:|--:|--:|--:|--:|:-:|\n");
    for (int e = 0; e < ENTRY_COUNT && !skip_scalar; e++) {
        if (!done[e] || entries[e].octree_only)
            continue;
        const result *r = results[e];
        printf("| %s | %dx%d | %.1f | %.1f | %.1f | %.2f | %.2f | %s |\n",
               entries[e].name, entries[e].width, entries[e].height,
               r[0].seconds / r[1].seconds, r[0].seconds / r[4].seconds,
               r[3].seconds / r[4].seconds, r[1].seconds / r[2].seconds,
               r[4].seconds / r[5].seconds, identical[e] ? "yes" : "NO");
    }

    printf("\nThe octree: render times in seconds (median), its "
           "speed-up over the fast brute-force kernel, and its own numbers "
           "(double).  Per query: leaves visited and facets tested, against "
           "the live facets brute force tests.\n\n"
           "| scene | facets | image | brute double 1t | octree double 1t | "
           "speed-up 1t | brute double all | octree double all | speed-up "
           "all | octree float all | build | references/facet | bytes/facet "
           "| leaves/query | tests/query | same image |\n"
           "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|:-:|"
           "\n");
    for (int e = 0; e < ENTRY_COUNT; e++) {
        if (!done[e])
            continue;
        const result *r = results[e];
        const rt_render_stats *st = &r[7].stats;
        double queries = st->accel_queries ? (double)st->accel_queries : 1;
        int brute = !entries[e].octree_only;
        char b1[32] = "-", ba[32] = "-", x1[32] = "-", xa[32] = "-";
        if (brute) {
            snprintf(b1, sizeof b1, "%.3f", r[1].seconds);
            snprintf(ba, sizeof ba, "%.3f", r[2].seconds);
            snprintf(x1, sizeof x1, "%.1f", r[1].seconds / r[6].seconds);
            snprintf(xa, sizeof xa, "%.1f", r[2].seconds / r[7].seconds);
        }
        printf("| %s | %d | %dx%d | %s | %.3f | %s | %s | %.3f | %s | %.3f | "
               "%.3f s | %.2f | %.0f | %.2f | %.1f | %s |\n",
               entries[e].name, facets[e], entries[e].width,
               entries[e].height, b1, r[6].seconds, x1, ba, r[7].seconds, xa,
               r[8].seconds, st->accel_build_seconds,
               facets[e] ? (double)st->accel_references / facets[e] : 0.0,
               facets[e] ? (double)st->accel_bytes / facets[e] : 0.0,
               st->accel_leaves_visited / queries,
               st->accel_facet_tests / queries, identical[e] ? "yes" : "NO");
    }

    printf("\nWork per render (double, fast kernel; the scalar loops cast the "
           "same rays).  Skipped: rays the scene analysis left out (no "
           "shadow ray where N.S <= 0 or k = 1, no reflection from k = 0).\n\n"
           "| scene | image | camera rays | shadow rays | shadow skipped | "
           "reflection rays | reflection skipped | tests | tests skipped |\n"
           "|---|--:|--:|--:|--:|--:|--:|--:|--:|\n");
    for (int e = 0; e < ENTRY_COUNT; e++) {
        if (!done[e] || entries[e].octree_only)
            continue;
        const rt_render_stats *st = &results[e][1].stats;
        printf("| %s | %dx%d | %llu | %llu | %llu | %llu | %llu | %llu | "
               "%llu |\n",
               entries[e].name, entries[e].width, entries[e].height,
               (unsigned long long)st->camera_rays,
               (unsigned long long)st->shadow_rays,
               (unsigned long long)st->shadow_rays_skipped,
               (unsigned long long)st->reflection_rays,
               (unsigned long long)st->reflection_rays_skipped,
               (unsigned long long)st->ray_facet_tests,
               (unsigned long long)st->ray_facet_tests_skipped);
    }

    printf("\nPer-ray budget (double, fast kernel, 1 thread, medians): rays "
           "by kind per camera ray, ray-facet tests per ray, time and, where "
           "the hardware counters can be read, cycles and instructions per "
           "ray (all kinds together) and per test.\n\n"
           "| scene | image | shadow/camera | reflection/camera | tests/ray | "
           "ns/ray | cycles/ray | instructions/ray | cycles/test |\n"
           "|---|--:|--:|--:|--:|--:|--:|--:|--:|\n");
    for (int e = 0; e < ENTRY_COUNT; e++) {
        if (!done[e] || entries[e].octree_only)
            continue;
        const result *r = &results[e][1];
        const rt_render_stats *st = &r->stats;
        double n = (double)rt_render_stats_rays(st);
        double camera = (double)st->camera_rays;
        char cycles[32] = "n/a", instructions[32] = "n/a", per_test[32] = "n/a";
        if (r->median_cycles >= 0) {
            snprintf(cycles, sizeof cycles, "%.0f", r->median_cycles / n);
            snprintf(per_test, sizeof per_test, "%.1f",
                     r->median_cycles / (double)st->ray_facet_tests);
        }
        if (r->median_instructions >= 0)
            snprintf(instructions, sizeof instructions, "%.0f",
                     r->median_instructions / n);
        printf("| %s | %dx%d | %.3f | %.3f | %.1f | %.1f | %s | %s | %s |\n",
               entries[e].name, entries[e].width, entries[e].height,
               st->shadow_rays / camera, st->reflection_rays / camera,
               (double)st->ray_facet_tests / n, r->seconds / n * 1e9, cycles,
               instructions, per_test);
    }
    return failures ? 1 : 0;
}
