/*
 * rt-export - render a `.scn` scene to a PPM image, headless.
 *
 * A thin command-line client of libraytrace: parse the arguments, load the
 * scene, render it on all cores with a progress line on a terminal, save the
 * image atomically, print the path.  Exit status: 0 success, 1 bad input or
 * a failed write, 2 bad usage.
 */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "raytrace/raytrace.h"

#define EXIT_BAD_INPUT 1
#define EXIT_USAGE 2

static const char usage[] =
    "usage: rt-export SCENE.scn [-o OUT] [--format p3|p6] [--depth N]\n"
    "                 [--threads N] [--precision double|float] [--fast-sqrt]\n"
    "                 [--samples N] [--sampling regular|stratified]\n"
    "                 [--kernel auto|scalar] [--accel auto|none|octree]\n"
    "                 [--check] [--stats] [--quiet]\n"
    "\n"
    "Renders SCENE.scn (a scene of triangles lit by one point light) to a\n"
    "PPM image and prints the path it wrote.\n"
    "\n"
    "  -o, --output OUT  where to write the image (default: the scene's name\n"
    "                    with .ppm, in the current directory)\n"
    "  --format p3|p6    ASCII P3 (the course's format) or binary P6\n"
    "                    (default p6)\n"
    "  --depth N         reflections followed after a primary ray (default 5)\n"
    "  --threads N       rendering threads; 0 = one per core (default 0)\n"
    "  --precision P     arithmetic of the renderer: double (the reference,\n"
    "                    default) or float (faster, less accurate)\n"
    "  --fast-sqrt       normalise vectors with the handout's fastInvSqrt\n"
    "  --samples N       rays per pixel, a square (1, 4, 9, ...; default 1:\n"
    "                    one ray through the pixel's centre)\n"
    "  --sampling S      regular (grid centres, default) or stratified\n"
    "  --kernel K        auto (default: the fastest loops this processor\n"
    "                    runs) or scalar (one facet at a time); the image\n"
    "                    is the same\n"
    "  --accel A         auto (default: an octree from 300 facets on), none\n"
    "                    (every ray tests every facet) or octree; the\n"
    "                    image is the same\n"
    "  --check           validate the scene and print what it holds; do not\n"
    "                    render\n"
    "  --stats           print the work done (rays, tests, time) on stderr\n"
    "  -q, --quiet       no progress line\n"
    "  -h, --help        this help\n"
    "  --version         the version\n"
    "\n"
    "Exit status: 0 success, 1 bad scene or failed write, 2 bad usage.\n";

typedef struct arguments {
    const char *scene;
    const char *output;
    rt_ppm_format format;
    int depth;
    int threads;
    rt_precision precision;
    int fast_sqrt;
    int samples;
    rt_sampling sampling;
    rt_kernel_choice kernel;
    rt_accel accel;
    int check;
    int stats;
    int quiet;
} arguments;

static int usage_error(const char *fmt, const char *value)
{
    fprintf(stderr, "rt-export: ");
    fprintf(stderr, fmt, value);
    fprintf(stderr, "\nTry 'rt-export --help'.\n");
    return EXIT_USAGE;
}

static int parse_int(const char *text, int min, int max, int *value)
{
    char *end;
    errno = 0;
    long v = strtol(text, &end, 10);
    if (errno != 0 || end == text || *end != '\0' || v < min || v > max)
        return 0;
    *value = (int)v;
    return 1;
}

/* Returns -1 to go on, or an exit status. */
static int parse_arguments(int argc, char **argv, arguments *a)
{
    *a = (arguments){.format = RT_PPM_P6, .depth = RT_DEFAULT_DEPTH,
                     .samples = 1};
    for (int i = 1; i < argc; i++) {
        const char *arg = argv[i];
        const char *value = i + 1 < argc ? argv[i + 1] : NULL;
        int takes_value = !strcmp(arg, "-o") || !strcmp(arg, "--output") ||
                          !strcmp(arg, "--format") ||
                          !strcmp(arg, "--depth") ||
                          !strcmp(arg, "--threads") ||
                          !strcmp(arg, "--precision") ||
                          !strcmp(arg, "--samples") ||
                          !strcmp(arg, "--sampling") ||
                          !strcmp(arg, "--kernel") ||
                          !strcmp(arg, "--accel");
        if (takes_value && value == NULL)
            return usage_error("option '%s' needs a value", arg);
        if (!strcmp(arg, "-h") || !strcmp(arg, "--help")) {
            fputs(usage, stdout);
            return EXIT_SUCCESS;
        } else if (!strcmp(arg, "--version")) {
            printf("rt-export (libraytrace) %s\n", rt_version_string());
            return EXIT_SUCCESS;
        } else if (!strcmp(arg, "-o") || !strcmp(arg, "--output")) {
            a->output = value;
        } else if (!strcmp(arg, "--format")) {
            if (!strcmp(value, "p3") || !strcmp(value, "P3"))
                a->format = RT_PPM_P3;
            else if (!strcmp(value, "p6") || !strcmp(value, "P6"))
                a->format = RT_PPM_P6;
            else
                return usage_error("expected p3 or p6 after --format, "
                                   "found '%s'", value);
        } else if (!strcmp(arg, "--depth")) {
            if (!parse_int(value, 0, 1000000, &a->depth))
                return usage_error("expected a depth in 0..1000000, "
                                   "found '%s'", value);
        } else if (!strcmp(arg, "--threads")) {
            if (!parse_int(value, 0, 1024, &a->threads))
                return usage_error("expected a thread count in 0..1024, "
                                   "found '%s'", value);
        } else if (!strcmp(arg, "--precision")) {
            if (!strcmp(value, "double"))
                a->precision = RT_PRECISION_DOUBLE;
            else if (!strcmp(value, "float"))
                a->precision = RT_PRECISION_FLOAT;
            else
                return usage_error("expected double or float after "
                                   "--precision, found '%s'", value);
        } else if (!strcmp(arg, "--fast-sqrt")) {
            a->fast_sqrt = 1;
        } else if (!strcmp(arg, "--samples")) {
            int root = 1;
            if (!parse_int(value, 1, 1024, &a->samples))
                return usage_error("expected a sample count in 1..1024, "
                                   "found '%s'", value);
            while (root * root < a->samples)
                root++;
            if (root * root != a->samples)
                return usage_error("expected a square sample count (1, 4, "
                                   "9, 16, ...), found '%s'", value);
        } else if (!strcmp(arg, "--sampling")) {
            if (!strcmp(value, "regular"))
                a->sampling = RT_SAMPLING_REGULAR;
            else if (!strcmp(value, "stratified"))
                a->sampling = RT_SAMPLING_STRATIFIED;
            else
                return usage_error("expected regular or stratified after "
                                   "--sampling, found '%s'", value);
        } else if (!strcmp(arg, "--kernel")) {
            if (!strcmp(value, "auto"))
                a->kernel = RT_KERNEL_AUTO;
            else if (!strcmp(value, "scalar"))
                a->kernel = RT_KERNEL_SCALAR;
            else
                return usage_error("expected auto or scalar after --kernel, "
                                   "found '%s'", value);
        } else if (!strcmp(arg, "--accel")) {
            if (!strcmp(value, "auto"))
                a->accel = RT_ACCEL_AUTO;
            else if (!strcmp(value, "none"))
                a->accel = RT_ACCEL_NONE;
            else if (!strcmp(value, "octree"))
                a->accel = RT_ACCEL_OCTREE;
            else
                return usage_error("expected auto, none or octree after "
                                   "--accel, found '%s'", value);
        } else if (!strcmp(arg, "--check")) {
            a->check = 1;
        } else if (!strcmp(arg, "--stats")) {
            a->stats = 1;
        } else if (!strcmp(arg, "-q") || !strcmp(arg, "--quiet")) {
            a->quiet = 1;
        } else if (arg[0] == '-' && arg[1] != '\0') {
            return usage_error("unknown option '%s'", arg);
        } else if (a->scene == NULL) {
            a->scene = arg;
        } else {
            return usage_error("expected one scene, found a second: '%s'",
                               arg);
        }
        i += takes_value;
    }
    if (a->scene == NULL)
        return usage_error("%s", "expected a scene file");
    return -1;
}

/* "dir/name.scn" -> "name.ppm" (in the current directory). */
static char *default_output(const char *scene)
{
    const char *base = strrchr(scene, '/');
    base = base ? base + 1 : scene;
    const char *dot = strrchr(base, '.');
    size_t length = dot && dot != base ? (size_t)(dot - base) : strlen(base);
    char *out = malloc(length + 5);
    if (out != NULL) {
        memcpy(out, base, length);
        memcpy(out + length, ".ppm", 5);
    }
    return out;
}

static void print_check(const char *path, const rt_scene *scene)
{
    rt_scene_info info;
    rt_scene_get_info(scene, &info);
    printf("%s: valid scene\n", path);
    printf("  image      %d x %d\n", info.width, info.height);
    printf("  vertices   %d\n", info.vertex_count);
    printf("  facets     %d (%d can be hit, %d reflective)\n",
           info.facet_count, info.live_facet_count,
           info.reflective_facet_count);
    printf("  camera     O (%g, %g, %g), A (%g, %g, %g)%s\n",
           info.camera.observer.x, info.camera.observer.y,
           info.camera.observer.z, info.camera.screen_center.x,
           info.camera.screen_center.y, info.camera.screen_center.z,
           info.camera.b_was_projected
               ? ", B projected onto the screen plane"
               : "");
    printf("  light      (%g, %g, %g), colour %d %d %d\n",
           info.light_position.x, info.light_position.y,
           info.light_position.z, info.light_color.r, info.light_color.g,
           info.light_color.b);
    printf("  background %d %d %d\n", info.background.r, info.background.g,
           info.background.b);
    printf("  warnings   %d\n", info.warning_count);
    for (int i = 0; i < info.warning_count; i++)
        printf("  %s\n", rt_scene_warning(scene, i)->message);
}

/* Progress on a terminal: a line rewritten in place, shown only once a
 * render has taken more than half a second. */
typedef struct progress {
    const char *name;
    int rows, done;
    struct timespec start, last;
    int shown;
} progress;

static double seconds_since(const struct timespec *t)
{
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (double)(now.tv_sec - t->tv_sec) + (now.tv_nsec - t->tv_nsec) * 1e-9;
}

static int on_row(void *user, int row)
{
    (void)row;
    progress *p = user;
    p->done++;
    double elapsed = seconds_since(&p->start);
    if (elapsed < 0.5 || (p->shown && seconds_since(&p->last) < 0.1 &&
                          p->done < p->rows))
        return 1;
    clock_gettime(CLOCK_MONOTONIC, &p->last);
    fprintf(stderr, "\rrendering %s: %3d%% (%.1f s)", p->name,
            (int)(100.0 * p->done / p->rows), elapsed);
    fflush(stderr);
    p->shown = 1;
    return 1;
}

/* The work of a render and where the time went, on stderr. */
static void print_stats(const rt_render_stats *s, double load_seconds,
                        double write_seconds, const arguments *a)
{
    double tests_per_second = s->seconds > 0 ? s->ray_facet_tests / s->seconds
                                             : 0.0;
    unsigned long long cast = s->camera_rays + s->shadow_rays +
                              s->reflection_rays;
    fprintf(stderr,
            "rays: %llu camera, %llu shadow, %llu reflection (%llu in all)\n"
            "skipped by the scene analysis: %llu shadow rays "
            "(N.S <= 0 or k = 1), %llu reflection rays (k = 0)\n"
            "ray-facet tests: %llu (%.3g per second); %llu more without the "
            "analysis and early exits\n"
            "time: load %.3f s, render %.3f s (%s threads, %s kernel, %s), "
            "write %.3f s\n",
            (unsigned long long)s->camera_rays,
            (unsigned long long)s->shadow_rays,
            (unsigned long long)s->reflection_rays, cast,
            (unsigned long long)s->shadow_rays_skipped,
            (unsigned long long)s->reflection_rays_skipped,
            (unsigned long long)s->ray_facet_tests, tests_per_second,
            (unsigned long long)s->ray_facet_tests_skipped, load_seconds,
            s->seconds, a->threads == 0 ? "all" : "the given",
            a->kernel == RT_KERNEL_SCALAR ? "scalar" : "fast",
            a->precision == RT_PRECISION_FLOAT ? "float" : "double",
            write_seconds);
    if (!s->accel_used)
        return;
    uint64_t queries = s->accel_queries ? s->accel_queries : 1;
    fprintf(stderr,
            "octree: built in %.3f s; %llu leaves, depth %d, %.2f references "
            "per facet (+%llu slivers in every ray's list), %.1f MB\n"
            "octree per query: %.2f leaves visited, %.2f facets tested "
            "(brute force: %llu); %llu queries left to brute force\n",
            s->accel_build_seconds, (unsigned long long)s->accel_leaves,
            s->accel_depth,
            s->accel_facets > 0
                ? (double)s->accel_references / (double)s->accel_facets
                : 0.0,
            (unsigned long long)s->accel_always, s->accel_bytes / 1e6,
            (double)s->accel_leaves_visited / queries,
            (double)s->accel_facet_tests / queries,
            (unsigned long long)s->accel_facets,
            (unsigned long long)s->accel_fallbacks);
}

static int same_file(const char *a, const char *b)
{
    struct stat sa, sb;
    return stat(a, &sa) == 0 && stat(b, &sb) == 0 && sa.st_dev == sb.st_dev &&
           sa.st_ino == sb.st_ino;
}

int main(int argc, char **argv)
{
    arguments a;
    int code = parse_arguments(argc, argv, &a);
    if (code >= 0)
        return code;

    rt_scene *scene;
    rt_error error;
    struct timespec load_start;
    clock_gettime(CLOCK_MONOTONIC, &load_start);
    if (rt_scene_load(a.scene, &scene, &error) != RT_OK) {
        fprintf(stderr, "rt-export: %s\n", error.message);
        return EXIT_BAD_INPUT;
    }
    if (a.check) {
        print_check(a.scene, scene);
        rt_scene_free(scene);
        return EXIT_SUCCESS;
    }
    double load_seconds = seconds_since(&load_start);
    rt_scene_info info;
    rt_scene_get_info(scene, &info);
    for (int i = 0; i < info.warning_count; i++)
        fprintf(stderr, "rt-export: %s\n", rt_scene_warning(scene, i)->message);

    char *output = a.output ? NULL : default_output(a.scene);
    const char *path = a.output ? a.output : output;
    rt_image image = {0};
    code = EXIT_BAD_INPUT;
    if (path == NULL || rt_image_create(&image, info.width, info.height)) {
        fprintf(stderr, "rt-export: out of memory\n");
        goto done;
    }
    if (same_file(path, a.scene)) {
        fprintf(stderr, "rt-export: %s: refusing to write the image over "
                        "the scene it was rendered from\n", path);
        goto done;
    }

    progress p = {.name = a.scene, .rows = info.height};
    clock_gettime(CLOCK_MONOTONIC, &p.start);
    rt_render_stats stats;
    rt_render_options options;
    rt_render_options_init(&options);
    options.max_depth = a.depth;
    options.threads = a.threads;
    options.precision = a.precision;
    options.fast_inv_sqrt = a.fast_sqrt;
    options.samples = a.samples;
    options.sampling = a.sampling;
    options.kernel = a.kernel;
    options.accel = a.accel;
    options.stats = &stats;
    if (!a.quiet && isatty(STDERR_FILENO)) {
        options.on_row = on_row;
        options.user = &p;
    }
    rt_status status = rt_render(scene, &options, &image);
    if (p.shown)
        fprintf(stderr, "\n");
    if (status != RT_OK) {
        fprintf(stderr, "rt-export: %s: rendering failed: %s\n", a.scene,
                rt_status_string(status));
        goto done;
    }
    struct timespec write_start;
    clock_gettime(CLOCK_MONOTONIC, &write_start);
    if (rt_ppm_save(path, &image, a.format, &error) != RT_OK) {
        fprintf(stderr, "rt-export: %s\n", error.message);
        goto done;
    }
    if (a.stats)
        print_stats(&stats, load_seconds, seconds_since(&write_start), &a);
    printf("%s\n", path);
    code = EXIT_SUCCESS;
done:
    rt_image_destroy(&image);
    free(output);
    rt_scene_free(scene);
    return code;
}
